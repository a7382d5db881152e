//! Curve-curve intersection timed from a dependent crate (issue 40): 10^4 random planar cubic
//! pairs, every control point uniform in [0, 1)^2 (the benches' SplitMix64, seed 26, the pairs
//! of `benches/intersect.rs`), each pass intersecting all of them one after another with every
//! answer consumed (its count and parameters summed). The certified forms and lyon's
//! `cubic_intersections_t` take turns pass after pass (so that a change of load meets all of
//! them alike); the median pass of each is reported in nanoseconds per pair with its ratio to
//! lyon's, all in one run.
//!
//! * `intersect_curves_f64_rounded`: the certified answer as a user calls it (the float
//!   filter, the exact path where the filter does not decide);
//! * `certified_crossings_f64`: the float filter alone (`None` when undecided).
//!
//! Before timing, the three are held to the same number of intersections on every pair (lyon
//! is not certified: a pair where it differs is counted and printed, not fatal).

use std::hint::black_box;
use std::time::Instant;

use crate::lyon;

type Cubic = [[f64; 2]; 4];

const PAIRS: usize = 10_000;
const SEED: u64 = 26;
const PASSES: usize = 21;

/// One pass of the certified answer: the number of intersections plus the sum of their
/// parameters.
fn rounded_pass(pairs: &[(Cubic, Cubic)]) -> f64 {
    let mut acc = 0.0;
    for (p, q) in pairs {
        let found = blossom::intersect_curves_f64_rounded(p, q).expect("finite control points");
        acc += found.points.len() as f64;
        for x in &found.points {
            acc += x.s + x.t;
        }
    }
    acc
}

/// One pass of the float filter alone (an undecided pair counts 0.5).
fn filter_pass(pairs: &[(Cubic, Cubic)]) -> f64 {
    let mut acc = 0.0;
    for (p, q) in pairs {
        match blossom::certified_crossings_f64(p, q) {
            Some(found) => {
                acc += found.len() as f64;
                for x in &found {
                    acc += x.s + x.t;
                }
            }
            None => acc += 0.5,
        }
    }
    acc
}

/// One pass of lyon's intersections.
fn lyon_pass(
    segments: &[(
        lyon_geom::CubicBezierSegment<f64>,
        lyon_geom::CubicBezierSegment<f64>,
    )],
) -> f64 {
    let mut acc = 0.0;
    for (p, q) in segments {
        let found = p.cubic_intersections_t(q);
        acc += found.len() as f64;
        for (s, t) in &found {
            acc += s + t;
        }
    }
    acc
}

/// Nanoseconds per pair of one pass.
fn timed(pass: impl FnOnce() -> f64) -> f64 {
    let start = Instant::now();
    black_box(pass());
    start.elapsed().as_nanos() as f64 / PAIRS as f64
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

pub fn intersection_peers() {
    let mut rng = crate::common::Rng(SEED);
    let mut cubic = || -> Cubic { std::array::from_fn(|_| [rng.unit(), rng.unit()]) };
    let pairs: Vec<(Cubic, Cubic)> = (0..PAIRS).map(|_| (cubic(), cubic())).collect();
    let segments: Vec<_> = pairs
        .iter()
        .map(|(p, q)| (lyon::lyon_cubic(p), lyon::lyon_cubic(q)))
        .collect();
    // The answers agree before they are timed.
    let (mut undecided, mut lyon_differs, mut crossings) = (0, 0, 0);
    for ((p, q), (sp, sq)) in pairs.iter().zip(&segments) {
        let rounded = blossom::intersect_curves_f64_rounded(p, q).expect("finite control points");
        match blossom::certified_crossings_f64(p, q) {
            Some(found) => assert_eq!(found.len(), rounded.points.len(), "{p:?} {q:?}"),
            None => undecided += 1,
        }
        crossings += rounded.points.len();
        if sp.cubic_intersections_t(sq).len() != rounded.points.len() {
            lyon_differs += 1;
        }
    }
    let (mut rounded, mut filter, mut lyon) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..PASSES {
        rounded.push(timed(|| rounded_pass(&pairs)));
        filter.push(timed(|| filter_pass(&pairs)));
        lyon.push(timed(|| lyon_pass(&segments)));
    }
    let least = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let fastest = [least(&lyon), least(&rounded), least(&filter)];
    let (rounded, filter, lyon) = (median(rounded), median(filter), median(lyon));
    println!(
        "curve-curve intersection, {PAIRS} random cubic pairs in [0, 1)^2 (seed {SEED}), {crossings} crossings, \
         median of {PASSES} passes, ns per pair (ratio to lyon):"
    );
    println!("| lyon `cubic_intersections_t` | `intersect_curves_f64_rounded` | `certified_crossings_f64` |");
    println!("|---|---|---|");
    println!(
        "| {lyon:.1} | {rounded:.1} ({:.2}) | {filter:.1} ({:.2}) |",
        rounded / lyon,
        filter / lyon
    );
    println!(
        "fastest passes: lyon {:.1}, rounded {:.1} ({:.2}), filter {:.1} ({:.2})",
        fastest[0],
        fastest[1],
        fastest[1] / fastest[0],
        fastest[2],
        fastest[2] / fastest[0]
    );
    println!("filter undecided on {undecided} pairs; lyon's count differs on {lyon_differs} pairs");
}
