//! The error of restriction in `f32` against the exact answer on the same `f32` inputs
//! (every `f32` converts to a `Rational` exactly), relative to the size of the exact control
//! points, and the bounds that `docs/error_bounds.md` (section "f32") and the doc comment of
//! `Ring for f32` state.
//!
//! Print the table with
//! `cargo test -p blossom --test suite f32_restriction -- --nocapture`.

use crate::common::Rng;
use blossom::{rational_to_f64, restrict_power_curve, BezierCurve, Method};
use blossom::{PowerCurve, Rational, Ring};
use num_traits::Signed;

/// The unit roundoff of `f32`, 2^-24.
const U: f64 = 5.960_464_477_539_063e-8;

/// The unit roundoff of `f64`, 2^-53.
const U64: f64 = 1.110_223_024_625_156_5e-16;

/// The exact value of an `f32` (finite by construction).
fn exact(x: f32) -> Rational {
    Rational::from_float(x).expect("a finite f32")
}

/// A number in [-1, 1] on the grid of step 1/1000, rounded to `f32`.
fn unit(rng: &mut Rng) -> f32 {
    rng.unit() as f32
}

/// max_k |got_k - want_k| / max_k |want_k| over every coordinate, computed exactly (an `f32`
/// converts to `f64` exactly).
fn relative_error<F: Copy + Into<f64>>(got: &[Vec<F>], want: &[Vec<Rational>]) -> f64 {
    let mut err = Rational::from_int(0);
    let mut size = Rational::from_int(0);
    for (g, w) in got.iter().zip(want) {
        for (x, y) in g.iter().zip(w) {
            let d = (Rational::from_float((*x).into()).expect("finite") - y).abs();
            err = err.max(d);
            size = size.max(y.abs());
        }
    }
    rational_to_f64(&err) / rational_to_f64(&size)
}

/// The f32 and the exact (Rational) image of a list of points.
fn to_exact(points: &[Vec<f32>]) -> Vec<Vec<Rational>> {
    points
        .iter()
        .map(|p| p.iter().map(|&x| exact(x)).collect())
        .collect()
}

/// One row of the table: the worst relative error over the cases, for one kind of input, one
/// method, one degree and one kind of interval.
struct Row {
    input: &'static str,
    method: &'static str,
    degree: usize,
    interval: &'static str,
    error: f64,
    /// The same run in `f64` on the same inputs, for comparison.
    error_f64: f64,
}

/// The intervals of a trial: four random sub-intervals of [0, 1] (one of length 1e-3) and the
/// extrapolating [-1, 2]; all end points are `f32`s, taken exactly by the exact run.
fn intervals(rng: &mut Rng) -> Vec<(&'static str, f32, f32)> {
    let mut out = Vec::new();
    for _ in 0..3 {
        let (x, y) = (rng.unit().abs() as f32, rng.unit().abs() as f32);
        if x != y {
            out.push(("in [0, 1]", x.min(y), x.max(y)));
        }
    }
    let a = rng.unit().abs() as f32 * 0.999;
    out.push(("in [0, 1]", a, a + 1e-3));
    out.push(("[-1, 2]", -1.0, 2.0));
    out
}

/// The worst relative errors of f32 restriction of random 3-D curves of degrees 3, 8, 16:
/// power input by `Method::Bulk` and `Method::Pyramid`, Bézier input by the engine
/// (`BezierCurve::subsegment`).
fn measure() -> Vec<Row> {
    let mut rows: Vec<Row> = Vec::new();
    let mut record = |input, method, degree, interval, (error, error_f64): (f64, f64)| match rows
        .iter_mut()
        .find(|r| (r.input, r.method, r.degree, r.interval) == (input, method, degree, interval))
    {
        Some(r) => {
            r.error = r.error.max(error);
            r.error_f64 = r.error_f64.max(error_f64);
        }
        None => rows.push(Row {
            input,
            method,
            degree,
            interval,
            error,
            error_f64,
        }),
    };
    let mut rng = Rng(32);
    for degree in [3, 8, 16] {
        for _ in 0..30 {
            let points: Vec<Vec<f32>> = (0..=degree)
                .map(|_| (0..3).map(|_| unit(&mut rng)).collect())
                .collect();
            let exact_points = to_exact(&points);
            let wide: Vec<Vec<f64>> = points
                .iter()
                .map(|p| p.iter().map(|&x| x.into()).collect())
                .collect();
            let power = PowerCurve::new(points.clone()).unwrap();
            let power_64 = PowerCurve::new(wide.clone()).unwrap();
            let bezier_64 = BezierCurve::new(wide).unwrap();
            let power_q = PowerCurve::new(exact_points.clone()).unwrap();
            let bezier = BezierCurve::new(points).unwrap();
            let bezier_q = BezierCurve::new(exact_points).unwrap();
            for (kind, a, b) in intervals(&mut rng) {
                let (aq, bq) = (exact(a), exact(b));
                let (a64, b64) = (f64::from(a), f64::from(b));
                let want = restrict_power_curve(&power_q, &aq, &bq, Method::Bulk);
                let want = &want.control_points().to_vec();
                for (name, method) in [("bulk", Method::Bulk), ("pyramid", Method::Pyramid)] {
                    let got = restrict_power_curve(&power, &a, &b, method);
                    let got_64 = restrict_power_curve(&power_64, &a64, &b64, method);
                    let e = relative_error(&got.control_points().to_vec(), want);
                    let e_64 = relative_error(&got_64.control_points().to_vec(), want);
                    record("power", name, degree, kind, (e, e_64));
                }
                let want = bezier_q.subsegment(aq.clone()..bq.clone());
                let want = &want.control_points().to_vec();
                let got = bezier.subsegment(a..b);
                let got_64 = bezier_64.subsegment(a64..b64);
                let e = relative_error(&got.control_points().to_vec(), want);
                let e_64 = relative_error(&got_64.control_points().to_vec(), want);
                record("Bézier", "engine", degree, kind, (e, e_64));
            }
        }
    }
    rows
}

/// The documented bound on the relative error of a restriction of degree n, 150 n u (u = 2^-24
/// the f32 unit roundoff): about 100 times the worst value measured at each degree
/// (docs/error_bounds.md, section "f32").
fn bound_in_u(degree: usize) -> f64 {
    150.0 * degree as f64
}

#[test]
fn f32_restriction_error_is_within_the_documented_bound() {
    let rows = measure();
    println!(
        "| input | method | degree | interval | f32 error | / u | bound / u | f64 error | / u64 |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for r in &rows {
        let bound = bound_in_u(r.degree);
        println!(
            "| {} | {} | {} | {} | {:.1e} | {:.1} | {} | {:.1e} | {:.1} |",
            r.input,
            r.method,
            r.degree,
            r.interval,
            r.error,
            r.error / U,
            bound,
            r.error_f64,
            r.error_f64 / U64
        );
    }
    for r in &rows {
        let bound = bound_in_u(r.degree);
        assert!(
            r.error <= bound * U,
            "{} {} degree {} on {}: {:e} = {:.1} u > {bound} u",
            r.input,
            r.method,
            r.degree,
            r.interval,
            r.error,
            r.error / U
        );
    }
}
