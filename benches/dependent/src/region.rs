//! The certified booleans timed from a dependent crate: the 200 quadratic triangle pairs and
//! the 8 + 8 cubic stars of `benches/region_peers/src/shapes.rs`, regions built once (as a
//! user keeps them), then passes of `triangle_intersection` / `boolean` over all of them, every
//! answer consumed (its loop count and area bounds summed), median of 21 passes; and the first
//! boolean on regions built from the nodes inside the timed pass.

use blossom::region::{boolean, triangle_intersection, BooleanOp, Region};
use std::hint::black_box;
use std::time::Instant;

#[path = "../../region_peers/src/shapes.rs"]
#[allow(dead_code)]
mod shapes;

const PASSES: usize = 21;

/// The median over `PASSES` of `pass`, in nanoseconds per item over `items` items.
fn median_ns(items: usize, mut pass: impl FnMut() -> f64) -> f64 {
    let mut times: Vec<f64> = (0..PASSES)
        .map(|_| {
            let start = Instant::now();
            black_box(pass());
            start.elapsed().as_nanos() as f64 / items as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[PASSES / 2]
}

fn consumed(r: &blossom::region::RegionResult) -> f64 {
    r.loops.len() as f64 + r.area[0] + r.area[1]
}

pub fn region_booleans() {
    let pairs = shapes::triangle_pairs(200);
    let triangle = |t: &shapes::Triangle| Region::triangle_f64(2, t.to_vec()).expect("six nodes");
    let kept: Vec<(Region, Region)> = pairs
        .iter()
        .map(|[a, b]| (triangle(a), triangle(b)))
        .collect();
    let warm = median_ns(kept.len(), || {
        kept.iter()
            .map(|(a, b)| consumed(&triangle_intersection(a, b).expect("answered")))
            .sum()
    });
    let fresh = median_ns(pairs.len(), || {
        pairs
            .iter()
            .map(|[a, b]| {
                consumed(&triangle_intersection(&triangle(a), &triangle(b)).expect("answered"))
            })
            .sum()
    });
    let [a, b] = shapes::star_pair();
    let (a, b) = (shapes::region_of(&a), shapes::region_of(&b));
    let star = |op| median_ns(1, || consumed(&boolean(&a, &b, op).expect("answered")));
    let (inter, union) = (star(BooleanOp::Intersection), star(BooleanOp::Union));
    println!("certified booleans, median of {PASSES} passes, ns per boolean:");
    println!("| 200 quadratic triangle pairs, regions kept | built from nodes in the pass | 8+8 cubic stars, intersection | union |");
    println!("|---|---|---|---|");
    println!("| {warm:.1} | {fresh:.1} | {inter:.1} | {union:.1} |");
}
