//! The exact error of the peers' `f64` subdivision next to blossom's: kurbo's
//! `CubicBez::subsegment`, lyon's `CubicBezierSegment::split_range`, blossom's
//! `BezierCurve::subsegment` (runtime dimension) and `subsegment_into` (arrays, the unrolled
//! engine), each on the same random cubics and sub-intervals t0 < t1 of [0, 1], all measured by
//! [`blossom::check_bezier_restriction`] against the exact restriction of the same doubles.
//!
//! Asserted: every error is finite; blossom's absolute error is at most
//! [`ABS_BOUND_ULPS`] · 2^-53 · max_i |b_i| (the size of the input control points), and its
//! relative error per control point at most [`REL_BOUND`]. The peers' errors are recorded, not
//! judged. The table (max and median of both errors per library) prints with
//!
//! ```text
//! cargo test -p blossom --test suite peers -- --nocapture
//! ```

use crate::common::Rng;
use blossom::engine::subsegment_into;
use blossom::{check_bezier_restriction, BezierCurve};
use kurbo::ParamCurve;

/// How many random cubics.
const CUBICS: usize = 2000;

/// Blossom's absolute error, in units of 2^-53 · max_i |b_i|. Each control point of the
/// restriction is a blossom value b[t0^(3-j), t1^j], three rounds of affine combinations with
/// weights in [0, 1] whose rounding errors add up to a small multiple of u · max |b_i| (about
/// 4.4 on the inputs here: 4.9e-13 for |b_i| up to 1000).
const ABS_BOUND_ULPS: f64 = 16.0;

/// Blossom's relative error per control point on these inputs (coordinates of all magnitudes
/// up to 1000): the absolute bound above divided by the size of the point, which here is
/// rarely far below that of the curve (1.7e-14 at most here; the median is 1.7e-16).
const REL_BOUND: f64 = 1e-12;

/// A double in [-1000, 1000] with all 53 bits of its significand random.
fn coordinate(r: &mut Rng) -> f64 {
    ((r.next() >> 11) as f64 / (1u64 << 53) as f64) * 2000.0 - 1000.0
}

/// A double in [0, 1] with 53 random bits.
fn parameter(r: &mut Rng) -> f64 {
    (r.next() >> 11) as f64 / (1u64 << 53) as f64
}

/// The errors of one library: absolute and relative, per cubic (the maximum over its points).
#[derive(Default)]
struct Errors {
    abs: Vec<f64>,
    rel: Vec<f64>,
}

fn max_and_median(xs: &[f64]) -> (f64, f64) {
    let mut sorted = xs.to_vec();
    sorted.sort_by(f64::total_cmp);
    (sorted[sorted.len() - 1], sorted[sorted.len() / 2])
}

#[test]
fn peers_errors_next_to_blossoms() {
    let names = ["kurbo", "lyon", "blossom", "blossom-array"];
    let mut errors: Vec<Errors> = names.iter().map(|_| Errors::default()).collect();
    let mut rng = Rng(0x5EED_0015);
    let mut scratch = Vec::new();
    for _ in 0..CUBICS {
        let ctrl: [[f64; 2]; 4] =
            std::array::from_fn(|_| [coordinate(&mut rng), coordinate(&mut rng)]);
        let (t0, t1) = loop {
            let (s, t) = (parameter(&mut rng), parameter(&mut rng));
            if s != t {
                break (s.min(t), s.max(t));
            }
        };
        let curve = BezierCurve::new(ctrl.iter().map(|p| p.to_vec()).collect()).unwrap();

        let p = |i: usize| kurbo::Point::new(ctrl[i][0], ctrl[i][1]);
        let k = kurbo::CubicBez::new(p(0), p(1), p(2), p(3)).subsegment(t0..t1);
        let kurbo = [k.p0, k.p1, k.p2, k.p3].map(|p| vec![p.x, p.y]);

        let p = |i: usize| lyon_geom::point(ctrl[i][0], ctrl[i][1]);
        let segment = lyon_geom::CubicBezierSegment {
            from: p(0),
            ctrl1: p(1),
            ctrl2: p(2),
            to: p(3),
        };
        let l = segment.split_range(t0..t1);
        let lyon = [l.from, l.ctrl1, l.ctrl2, l.to].map(|p| vec![p.x, p.y]);

        let ours = curve.subsegment(t0..t1).into_control_points();

        let mut out = [[0.0; 2]; 4];
        subsegment_into(&ctrl, &t0, &t1, &mut out, &mut scratch).unwrap();
        let array = out.map(|p| p.to_vec());

        let size = ctrl.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        for (i, answer) in [&kurbo[..], &lyon[..], &ours[..], &array[..]]
            .into_iter()
            .enumerate()
        {
            let e = check_bezier_restriction(&curve, t0, t1, answer).unwrap();
            let (abs, rel) = (e.max_abs_f64(), e.max_rel_f64());
            assert!(
                abs.is_finite() && rel.is_finite(),
                "{}: {ctrl:?} on [{t0}, {t1}]",
                names[i]
            );
            if names[i].starts_with("blossom") {
                let bound = ABS_BOUND_ULPS * f64::EPSILON / 2.0 * size;
                assert!(
                    abs <= bound,
                    "{}: abs {abs} > {bound}: {ctrl:?} on [{t0}, {t1}]",
                    names[i]
                );
                assert!(
                    rel <= REL_BOUND,
                    "{}: rel {rel}: {ctrl:?} on [{t0}, {t1}]",
                    names[i]
                );
            }
            errors[i].abs.push(abs);
            errors[i].rel.push(rel);
        }
    }
    println!("{CUBICS} random cubics in [-1000, 1000]^2, t0 < t1 in [0, 1], exact errors:");
    println!(
        "{:<14} {:>11} {:>11} {:>11} {:>11}",
        "library", "max abs", "median abs", "max rel", "median rel"
    );
    for (name, e) in names.iter().zip(&errors) {
        let (max_abs, med_abs) = max_and_median(&e.abs);
        let (max_rel, med_rel) = max_and_median(&e.rel);
        println!("{name:<14} {max_abs:>11.3e} {med_abs:>11.3e} {max_rel:>11.3e} {med_rel:>11.3e}");
    }
}
