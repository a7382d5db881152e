//! The planar cubic's restriction as an outside harness times it (issue 47): 10^5 random
//! cubics built by `BezierCurve::new` from nested vectors (control points uniform in
//! [0, 1)^2), each restricted to its own random sub-interval of [0, 1], the answer's
//! `coordinates()` summed; against lyon's `split_range` on the same cubics, its answer's
//! coordinates summed. Three ways of consuming the answers, each timed for both libraries:
//!
//! * `summed`: each answer summed as it comes;
//! * `black_box`: each answer passed through `std::hint::black_box` first (kept in memory, as
//!   when it is handed to code the optimiser cannot see), then summed;
//! * `collected`: the answers collected into a vector (one per form, allocated once and reused
//!   from pass to pass, so that the allocator's page faults stay out of the figure), then
//!   summed.
//!
//! The six take turns pass after pass (the order rotating); the fastest of 21 passes (the
//! least disturbed on a shared machine) is printed in nanoseconds per curve with the ratio to
//! lyon's in the same way.
//! `cargo run --release --bin consume`; `consume FORM PASSES` (FORM 0..=5 in the order above,
//! lyon then blossom) runs one form PASSES times and nothing else, for callgrind:
//! `count.sh`'s difference of 10 and 0 passes over 10^6 curves gives instructions per curve.

use blossom::BezierCurve;
use blossom_dependent_bench::Rng;
use lyon_geom::{point, CubicBezierSegment};
use std::hint::black_box;
use std::time::Instant;

const CURVES: usize = 100_000;
const PASSES: usize = 21;

/// One timed pass of a form: its answers consumed into one number.
type Pass<'a> = Box<dyn FnMut() -> f64 + 'a>;

fn lyon_sum(s: &CubicBezierSegment<f64>) -> f64 {
    s.from.x + s.from.y + s.ctrl1.x + s.ctrl1.y + s.ctrl2.x + s.ctrl2.y + s.to.x + s.to.y
}

fn main() {
    let mut rng = Rng(47);
    let nodes: Vec<Vec<Vec<f64>>> = (0..CURVES)
        .map(|_| (0..4).map(|_| vec![rng.next(), rng.next()]).collect())
        .collect();
    let ranges: Vec<std::ops::Range<f64>> = (0..CURVES)
        .map(|_| {
            let a = 0.05 + 0.4 * rng.next();
            a..a + 0.1 + 0.4 * rng.next()
        })
        .collect();
    let curves: Vec<BezierCurve<f64>> = nodes
        .iter()
        .map(|n| BezierCurve::new(n.clone()).expect("a cubic"))
        .collect();
    let lyons: Vec<CubicBezierSegment<f64>> = nodes
        .iter()
        .map(|n| CubicBezierSegment {
            from: point(n[0][0], n[0][1]),
            ctrl1: point(n[1][0], n[1][1]),
            ctrl2: point(n[2][0], n[2][1]),
            to: point(n[3][0], n[3][1]),
        })
        .collect();
    let pairs = || curves.iter().zip(ranges.iter().cloned());
    let lyon_pairs = || lyons.iter().zip(ranges.iter().cloned());
    let mut lyon_parts = Vec::with_capacity(CURVES);
    let mut parts = Vec::with_capacity(CURVES);
    let mut forms: [(&str, Pass); 6] = [
        (
            "lyon summed",
            Box::new(|| lyon_pairs().map(|(c, r)| lyon_sum(&c.split_range(r))).sum()),
        ),
        (
            "blossom summed",
            Box::new(|| {
                pairs()
                    .map(|(c, r)| c.subsegment(r).coordinates().iter().sum::<f64>())
                    .sum()
            }),
        ),
        (
            "lyon black_box",
            Box::new(|| {
                lyon_pairs()
                    .map(|(c, r)| lyon_sum(&black_box(c.split_range(r))))
                    .sum()
            }),
        ),
        (
            "blossom black_box",
            Box::new(|| {
                pairs()
                    .map(|(c, r)| black_box(c.subsegment(r)).coordinates().iter().sum::<f64>())
                    .sum()
            }),
        ),
        (
            "lyon collected",
            Box::new(|| {
                lyon_parts.clear();
                lyon_parts.extend(lyon_pairs().map(|(c, r)| c.split_range(r)));
                lyon_parts.iter().map(lyon_sum).sum()
            }),
        ),
        (
            "blossom collected",
            Box::new(|| {
                parts.clear();
                parts.extend(pairs().map(|(c, r)| c.subsegment(r)));
                parts
                    .iter()
                    .map(|p| p.coordinates().iter().sum::<f64>())
                    .sum()
            }),
        ),
    ];
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a number"))
        .collect();
    if let [form, passes] = args[..] {
        let acc: f64 = (0..passes).map(|_| (forms[form].1)()).sum();
        println!("{acc}");
        return;
    }
    // The two libraries' sums agree.
    let want = (forms[0].1)();
    let got = (forms[1].1)();
    assert!(
        (want - got).abs() <= 1e-9 * want.abs(),
        "{want} against {got}"
    );
    let mut times = vec![Vec::new(); forms.len()];
    for pass in 0..PASSES {
        for k in 0..forms.len() {
            let i = (k + pass) % forms.len();
            let start = Instant::now();
            black_box((forms[i].1)());
            times[i].push(start.elapsed().as_nanos() as f64 / CURVES as f64);
        }
    }
    let median: Vec<f64> = times
        .into_iter()
        .map(|t| t.into_iter().fold(f64::INFINITY, f64::min))
        .collect();
    println!("planar cubic, 10^5 curves, ns per curve (ratio to lyon consumed the same way):");
    println!("| consumed | lyon | BezierCurve::subsegment |");
    println!("|---|---|---|");
    for (k, way) in ["summed", "black_box", "collected"].iter().enumerate() {
        let (lyon, ours) = (median[2 * k], median[2 * k + 1]);
        println!("| {way} | {lyon:.2} | {ours:.2} ({:.2}) |", ours / lyon);
    }
}
