//! A loop of region booleans to profile (`valgrind --tool=callgrind` or `perf record`):
//! the 200 quadratic triangle pairs of `benches/region.rs`, or the 8 + 8 cubic stars.
//!
//! `cargo build --release -p blossom --example region_profile`, then
//! `target/release/examples/region_profile triangles 100` (passes over the pairs),
//! `target/release/examples/region_profile fresh 100` (the same, each triangle's region built
//! from its nodes inside the timed loop: construction and first boolean) or
//! `target/release/examples/region_profile stars 10000`. Prints the time per boolean.
//! `target/release/examples/region_profile circle 200`: issue 45's degenerate placement, a
//! square and a 4-cubic circle whose joins lie on the square's edges, against the same circle
//! moved off them, the union's time and report for each.
//! `target/release/examples/region_profile board 1`: boards of k x k squares (half of them,
//! touching at corners) united with the board moved by one square, and simplified, for
//! k = 10, 20, 40, 60: the work estimate (`boolean_work`) against the run.

use blossom::region::{
    boolean, boolean_work, simplify, triangle_intersection, BooleanOp, FillRule, Region,
};
use blossom::Bezier;
use std::time::Instant;

#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/region_peers/src/shapes.rs"]
#[allow(dead_code)]
mod shapes;

/// A region of one loop of curves of doubles.
fn loop_region(curves: Vec<Vec<[f64; 2]>>) -> Region {
    let curves = curves.into_iter().map(|c| Bezier::new(c).expect("points"));
    Region::from_f64(vec![curves.collect()], FillRule::NonZero).expect("a loop")
}

/// The square [-1, 1]^2 and the unit circle of four cubics centred at `centre`: its joins
/// (±1, 0), (0, ±1) lie on the square's edges when the centre is the origin.
fn square_and_circle(centre: [f64; 2]) -> (Region, Region) {
    let c = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let square = loop_region((0..4).map(|i| vec![c[i], c[(i + 1) % 4]]).collect());
    let k = 0.5522847498307936;
    let p = |x: f64, y: f64| [centre[0] + x, centre[1] + y];
    let circle = loop_region(vec![
        vec![p(1.0, 0.0), p(1.0, k), p(k, 1.0), p(0.0, 1.0)],
        vec![p(0.0, 1.0), p(-k, 1.0), p(-1.0, k), p(-1.0, 0.0)],
        vec![p(-1.0, 0.0), p(-1.0, -k), p(-k, -1.0), p(0.0, -1.0)],
        vec![p(0.0, -1.0), p(k, -1.0), p(1.0, -k), p(1.0, 0.0)],
    ]);
    (square, circle)
}

/// Half of a k x k board of unit squares (those with i + j even), moved by `dx`.
fn board(k: usize, dx: f64) -> Region {
    let mut loops = Vec::new();
    for i in 0..k {
        for j in (0..k).filter(|j| (i + j) % 2 == 0) {
            let (x, y) = (i as f64 + dx, j as f64);
            let c = [[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]];
            let sides = (0..4).map(|m| Bezier::new(vec![c[m], c[(m + 1) % 4]]).expect("side"));
            loops.push(sides.collect());
        }
    }
    Region::from_f64(loops, FillRule::NonZero).expect("squares")
}

/// The work estimate against the run on boards (module doc).
fn boards() {
    for k in [10, 20, 40, 60] {
        let (a, b) = (board(k, 0.0), board(k, 1.0));
        let empty = Region::empty(FillRule::NonZero);
        let (union_work, simplify_work) = (boolean_work(&a, &b), boolean_work(&a, &empty));
        let start = Instant::now();
        std::hint::black_box(boolean(&a, &b, BooleanOp::Union).expect("answered"));
        let union = start.elapsed().as_secs_f64();
        let start = Instant::now();
        std::hint::black_box(simplify(&a).expect("answered"));
        let simplified = start.elapsed().as_secs_f64();
        println!(
            "board {k} x {k}: union estimate {:.3} s, run {union:.4} s ({:.1}x); simplify estimate {:.3} s, run {simplified:.4} s ({:.1}x)",
            union_work as f64 * 1e-9,
            union_work as f64 * 1e-9 / union,
            simplify_work as f64 * 1e-9,
            simplify_work as f64 * 1e-9 / simplified,
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map_or("triangles", String::as_str);
    let passes: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100);
    if what == "board" {
        boards();
        return;
    }
    if what == "circle" {
        for (name, centre) in [
            ("joins on the edges", [0.0, 0.0]),
            ("general position", [0.1234, 0.0567]),
        ] {
            let (square, circle) = square_and_circle(centre);
            let report = *boolean(&square, &circle, BooleanOp::Union)
                .expect("answered")
                .report();
            let start = Instant::now();
            for _ in 0..passes {
                std::hint::black_box(
                    boolean(&square, &circle, BooleanOp::Union).expect("answered"),
                );
            }
            let each = start.elapsed().as_secs_f64() / passes as f64;
            println!("circle, {name}: {:.1} us per union; {report:?}", each * 1e6);
        }
        return;
    }
    let pairs: Vec<(Region, Region, BooleanOp)> = if what == "stars" {
        let [a, b] = shapes::star_pair();
        let region = |curves: &[shapes::Cubic]| {
            let curves = curves
                .iter()
                .map(|c| Bezier::new(c.to_vec()).expect("4 points"));
            Region::from_f64(vec![curves.collect()], FillRule::NonZero).expect("a loop")
        };
        vec![(region(&a), region(&b), BooleanOp::Intersection)]
    } else {
        let triangle =
            |t: &shapes::Triangle| Region::triangle_f64(2, t.to_vec()).expect("six nodes");
        shapes::triangle_pairs(200)
            .iter()
            .map(|[t1, t2]| (triangle(t1), triangle(t2), BooleanOp::Intersection))
            .collect()
    };
    if what == "fresh" {
        let nodes = shapes::triangle_pairs(200);
        let start = Instant::now();
        let mut loops = 0;
        for _ in 0..passes {
            for [t1, t2] in &nodes {
                let a = Region::triangle_f64(2, t1.to_vec()).expect("six nodes");
                let b = Region::triangle_f64(2, t2.to_vec()).expect("six nodes");
                loops += triangle_intersection(&a, &b).expect("answered").loops.len();
            }
        }
        let each = start.elapsed().as_secs_f64() / (passes * nodes.len()) as f64;
        println!(
            "fresh triangles: {:.3} us per boolean ({loops} loops)",
            each * 1e6
        );
        return;
    }
    if std::env::var_os("BLOSSOM_REPORT").is_some() {
        // How the first booleans were decided (which contacts took exact arithmetic).
        for (a, b, op) in pairs.iter().take(3) {
            println!("{:?}", boolean(a, b, *op).expect("answered").report());
        }
    }
    let start = Instant::now();
    let mut loops = 0;
    for _ in 0..passes {
        for (a, b, op) in &pairs {
            let r = if what == "stars" {
                boolean(a, b, *op)
            } else {
                triangle_intersection(a, b)
            };
            loops += r.expect("answered").loops.len();
        }
    }
    let each = start.elapsed().as_secs_f64() / (passes * pairs.len()) as f64;
    println!("{what}: {:.3} us per boolean ({loops} loops)", each * 1e6);
}
