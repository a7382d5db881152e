//! Restriction to [a, b] timed from a dependent crate: for each line, 10^5 random curves are
//! restricted one after another and every answer is consumed (its coordinates summed), the
//! median of 15 passes reported in nanoseconds per curve, with its ratio to the textbook split
//! (and to lyon for the planar cubic) measured in the same run.
//!
//! * `textbook`: de Casteljau at b keeps [0, b], then de Casteljau at a / b keeps the right
//!   part, in place on a fixed-size array `[[f64; D]; N]` (what a user writes by hand);
//! * `BezierCurve::subsegment`, `Bezier::subsegment`: the library's returning forms;
//! * `Bezier::subsegment_into`: into a reused buffer;
//! * lyon's `CubicBezierSegment::split_range` and kurbo's `ParamCurve::subsegment` (cubic only).
//!
//! With the argument `intersect`, only the curve-curve intersections of [`intersect`] run; with
//! `region`, only the certified booleans of [`region`]; with `restrict`, only the restrictions;
//! with none, all three.

#[path = "../../common/mod.rs"]
mod common;
mod intersect;
mod region;

use blossom::{Bezier, BezierCurve};
use blossom_dependent_bench::{textbook, Rng};
use std::hint::black_box;
use std::time::Instant;

const CURVES: usize = 100_000;
const PASSES: usize = 15;

/// The median over `PASSES` passes of `pass`, in nanoseconds per curve.
fn median_ns(mut pass: impl FnMut() -> f64) -> f64 {
    let mut times: Vec<f64> = (0..PASSES)
        .map(|_| {
            let start = Instant::now();
            black_box(pass());
            start.elapsed().as_nanos() as f64 / CURVES as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[PASSES / 2]
}

fn sum_points<const D: usize>(points: &[[f64; D]]) -> f64 {
    points.iter().flatten().sum()
}

struct Cases<const N: usize, const D: usize> {
    arrays: Vec<[[f64; D]; N]>,
    curves: Vec<BezierCurve<f64>>,
    beziers: Vec<Bezier<f64, D>>,
    ranges: Vec<(f64, f64)>,
}

fn cases<const N: usize, const D: usize>(rng: &mut Rng) -> Cases<N, D> {
    let arrays: Vec<[[f64; D]; N]> = (0..CURVES)
        .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| rng.next())))
        .collect();
    let ranges = (0..CURVES)
        .map(|_| {
            let a = 0.05 + 0.4 * rng.next();
            (a, a + 0.1 + 0.4 * rng.next())
        })
        .collect();
    let beziers: Vec<Bezier<f64, D>> = arrays
        .iter()
        .map(|c| Bezier::new(c.to_vec()).expect("a curve"))
        .collect();
    let curves = beziers.iter().map(BezierCurve::from).collect();
    Cases {
        arrays,
        curves,
        beziers,
        ranges,
    }
}

/// One line per library form at degree N - 1 in dimension D; returns the textbook time.
fn degree_lines<const N: usize, const D: usize>(rng: &mut Rng) {
    let cs = cases::<N, D>(rng);
    // The forms agree before they are timed.
    for k in 0..100 {
        let (a, b) = cs.ranges[k];
        let want = textbook(&cs.arrays[k], a, b);
        let got = cs.curves[k].subsegment(a..b);
        for (w, g) in want.iter().flatten().zip(got.coordinates()) {
            assert!((w - g).abs() <= 1e-9 * (1.0 + w.abs()), "degree {}", N - 1);
        }
    }
    let textbook_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.arrays.iter().zip(&cs.ranges) {
            acc += sum_points(&textbook(c, a, b));
        }
        acc
    });
    let curve_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.curves.iter().zip(&cs.ranges) {
            acc += c.subsegment(a..b).coordinates().iter().sum::<f64>();
        }
        acc
    });
    let bezier_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.beziers.iter().zip(&cs.ranges) {
            acc += sum_points(c.subsegment(a..b).points());
        }
        acc
    });
    let mut out = vec![[0.0; D]; N];
    let mut scratch = Vec::new();
    let into_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.beziers.iter().zip(&cs.ranges) {
            c.subsegment_into(&a, &b, &mut out, &mut scratch)
                .expect("sized");
            acc += sum_points(&out);
        }
        acc
    });
    println!(
        "| {D}-D degree {:>2} | {textbook_ns:8.1} | {curve_ns:8.1} ({:.2}) | {bezier_ns:8.1} ({:.2}) | {into_ns:8.1} ({:.2}) |",
        N - 1,
        curve_ns / textbook_ns,
        bezier_ns / textbook_ns,
        into_ns / textbook_ns
    );
}

fn planar_cubic_peers(rng: &mut Rng) {
    use kurbo::ParamCurve;
    let cs = cases::<4, 2>(rng);
    let lyons: Vec<lyon_geom::CubicBezierSegment<f64>> = cs
        .arrays
        .iter()
        .map(|c| lyon_geom::CubicBezierSegment {
            from: lyon_geom::point(c[0][0], c[0][1]),
            ctrl1: lyon_geom::point(c[1][0], c[1][1]),
            ctrl2: lyon_geom::point(c[2][0], c[2][1]),
            to: lyon_geom::point(c[3][0], c[3][1]),
        })
        .collect();
    let kurbos: Vec<kurbo::CubicBez> = cs
        .arrays
        .iter()
        .map(|c| {
            kurbo::CubicBez::new(
                (c[0][0], c[0][1]),
                (c[1][0], c[1][1]),
                (c[2][0], c[2][1]),
                (c[3][0], c[3][1]),
            )
        })
        .collect();
    let lyon_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in lyons.iter().zip(&cs.ranges) {
            let s = c.split_range(a..b);
            acc += s.from.x
                + s.from.y
                + s.ctrl1.x
                + s.ctrl1.y
                + s.ctrl2.x
                + s.ctrl2.y
                + s.to.x
                + s.to.y;
        }
        acc
    });
    let kurbo_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in kurbos.iter().zip(&cs.ranges) {
            let s = c.subsegment(a..b);
            acc += s.p0.x + s.p0.y + s.p1.x + s.p1.y + s.p2.x + s.p2.y + s.p3.x + s.p3.y;
        }
        acc
    });
    let textbook_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.arrays.iter().zip(&cs.ranges) {
            acc += sum_points(&textbook(c, a, b));
        }
        acc
    });
    let curve_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.curves.iter().zip(&cs.ranges) {
            acc += c.subsegment(a..b).coordinates().iter().sum::<f64>();
        }
        acc
    });
    let bezier_ns = median_ns(|| {
        let mut acc = 0.0;
        for (c, &(a, b)) in cs.beziers.iter().zip(&cs.ranges) {
            acc += sum_points(c.subsegment(a..b).points());
        }
        acc
    });
    println!("planar cubic, ns per curve (ratio to lyon):");
    println!("| lyon | kurbo | textbook | BezierCurve::subsegment | Bezier::subsegment |");
    println!("|---|---|---|---|---|");
    println!(
        "| {lyon_ns:.2} | {kurbo_ns:.2} ({:.2}) | {textbook_ns:.2} ({:.2}) | {curve_ns:.2} ({:.2}) | {bezier_ns:.2} ({:.2}) |",
        kurbo_ns / lyon_ns,
        textbook_ns / lyon_ns,
        curve_ns / lyon_ns,
        bezier_ns / lyon_ns
    );
}

fn main() {
    let only = std::env::args().nth(1);
    let runs = |part: &str| only.is_none() || only.as_deref() == Some(part);
    if runs("intersect") {
        intersect::intersection_peers();
        println!();
    }
    if runs("region") {
        region::region_booleans();
        println!();
    }
    if !runs("restrict") {
        return;
    }
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    planar_cubic_peers(&mut rng);
    println!();
    println!("ns per curve (ratio to the textbook split on fixed arrays):");
    println!("| curve | textbook | BezierCurve::subsegment | Bezier::subsegment | Bezier::subsegment_into |");
    println!("|---|---|---|---|---|");
    degree_lines::<4, 3>(&mut rng);
    degree_lines::<6, 3>(&mut rng);
    degree_lines::<9, 3>(&mut rng);
    degree_lines::<13, 3>(&mut rng);
    degree_lines::<17, 3>(&mut rng);
    degree_lines::<25, 3>(&mut rng);
    degree_lines::<33, 3>(&mut rng);
    degree_lines::<49, 3>(&mut rng);
    degree_lines::<65, 3>(&mut rng);
}
