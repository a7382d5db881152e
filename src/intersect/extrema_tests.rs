//! Tests of the tight bounding box, the nearest point and directed rounding, against truths
//! that share nothing with `extrema`: closed forms checked by exact squares, de Casteljau in
//! exact rationals written here, and dense sampling in f64.

use super::algebraic::{round_polynomial_at, AlgebraicReal};
use super::extrema::{
    nearest_point, nearest_point_f64, tight_bounding_box, tight_bounding_box_f64,
};
use super::isolate::Isolated;
use super::zeros::power_coefficients;
use crate::error::ErrorKind;
use crate::num::ring::Rational;
use crate::shape::bezier::BezierCurve;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn exact(x: f64) -> Rational {
    Rational::from_float(x).expect("finite")
}

/// The root of `poly` (ascending integers) isolated by the open interval (lo, hi).
fn root(poly: &[i64], lo: Rational, hi: Rational) -> AlgebraicReal {
    let f: Vec<BigInt> = poly.iter().map(|&c| BigInt::from(c)).collect();
    AlgebraicReal::from_isolated(
        &f,
        &Isolated {
            lo,
            hi,
            exact: false,
        },
    )
}

/// The next double above a finite `x`, by its bits (positive `x`) — written here, not shared.
fn next_above(x: f64) -> f64 {
    if x >= 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// Checks that `down` and `up` are adjacent doubles around the positive root of x^2 - n:
/// down^2 < n < up^2 exactly.
fn brackets_square_root(down: f64, up: f64, n: &Rational) {
    assert_eq!(next_above(down), up);
    let (d, u) = (exact(down), exact(up));
    assert!(&(&d * &d) < n && n < &(&u * &u), "{down} {up}");
}

#[test]
fn directed_rounding_brackets_irrational_numbers_by_adjacent_doubles() {
    let sqrt2 = root(&[-2, 0, 1], q(1, 1), q(2, 1));
    brackets_square_root(sqrt2.to_f64_down(), sqrt2.to_f64_up(), &q(2, 1));
    assert_eq!(sqrt2.to_f64(), std::f64::consts::SQRT_2);
    // A negative one: -sqrt(3), and a tiny one: sqrt(2) / 2^1000 is a root of 2^2000 x^2 - 2.
    let minus = root(&[-3, 0, 1], q(-2, 1), q(-1, 1));
    let (down, up) = (minus.to_f64_down(), minus.to_f64_up());
    brackets_square_root(-up, -down, &q(3, 1));
    let big = BigInt::one() << 2000u32;
    let tiny = AlgebraicReal::from_isolated(
        &[BigInt::from(-2), BigInt::zero(), big],
        &Isolated {
            lo: Rational::new(1.into(), BigInt::one() << 1000u32),
            hi: Rational::new(2.into(), BigInt::one() << 1000u32),
            exact: false,
        },
    );
    // Scaling by 2^-1000 stays among normal doubles, so it commutes with rounding.
    let scale = 2f64.powi(-1000);
    assert_eq!(tiny.to_f64_down(), sqrt2.to_f64_down() * scale);
    assert_eq!(tiny.to_f64_up(), sqrt2.to_f64_up() * scale);
    // Rationals: a double is its own rounding both ways; 1/3 is bracketed.
    let half = AlgebraicReal::from_rational(q(1, 2));
    assert_eq!((half.to_f64_down(), half.to_f64_up()), (0.5, 0.5));
    let third = AlgebraicReal::from_rational(q(1, 3));
    let (d, u) = (third.to_f64_down(), third.to_f64_up());
    assert_eq!(next_above(d), u);
    assert!(exact(d) < q(1, 3) && q(1, 3) < exact(u));
}

/// The Bernstein coefficients of degree `n` of the power polynomial `p` (ascending), by the
/// test's own formula b_i = sum_{k <= i} C(i, k) / C(n, k) a_k.
fn bernstein_of(p: &[Rational], n: usize) -> Vec<Rational> {
    let c = |n: usize, k: usize| -> Rational {
        let mut r = Rational::one();
        for j in 0..k {
            r *= q((n - j) as i64, (j + 1) as i64);
        }
        r
    };
    (0..=n)
        .map(|i| {
            (0..=i.min(p.len() - 1))
                .map(|k| &p[k] * c(i, k) / c(n, k))
                .fold(Rational::zero(), |a, b| a + b)
        })
        .collect()
}

#[test]
fn the_box_of_a_cubic_has_its_irrational_minimum_exactly() {
    // x(t) = t, y(t) = t^3 - t/2: y' = 3t^2 - 1/2 vanishes at t = 1/sqrt(6), where y is
    // -sqrt(6)/18, whose square is 1/54; the maximum y(1) = 1/2.
    let x = bernstein_of(&[q(0, 1), q(1, 1)], 3);
    let y = bernstein_of(&[q(0, 1), q(-1, 2), q(0, 1), q(1, 1)], 3);
    let curve = BezierCurve::new(
        x.iter()
            .zip(&y)
            .map(|(a, b)| vec![a.clone(), b.clone()])
            .collect(),
    )
    .unwrap();
    let bounds = tight_bounding_box(&curve);
    let low = &bounds.min[1];
    assert_eq!(low.at.len(), 1);
    assert!(low.at[0].is_root_of(&[BigInt::from(-1), BigInt::zero(), BigInt::from(6)]));
    assert!(low.value.exact().is_none());
    let (down, up) = (low.value.to_f64_down(), low.value.to_f64_up());
    // -up < sqrt(1/54) < -down.
    brackets_square_root(-up, -down, &q(1, 54));
    assert_eq!(bounds.max[1].value.exact(), Some(&q(1, 2)));
    assert_eq!(bounds.max[1].at[0].exact(), Some(&q(1, 1)));
    let (lower, upper) = bounds.outward();
    assert_eq!((lower[0], upper[0], upper[1]), (0.0, 1.0, 0.5));
    assert_eq!(lower[1], down);
}

/// A small pseudo-random generator (xorshift).
fn next(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

fn random_rational(state: &mut u64) -> Rational {
    let n = (next(state) % 41) as i64 - 20;
    let d = (next(state) % 7) as i64 + 1;
    q(n, d)
}

/// The point of the curve at `t` by de Casteljau in exact rationals (the test's own).
fn casteljau(points: &[Vec<Rational>], t: &Rational) -> Vec<Rational> {
    let mut p: Vec<Vec<Rational>> = points.to_vec();
    let s = Rational::one() - t;
    for r in 1..p.len() {
        for i in 0..p.len() - r {
            let next: Vec<Rational> = p[i]
                .iter()
                .zip(&p[i + 1])
                .map(|(a, b)| a * &s + b * t)
                .collect();
            p[i] = next;
        }
    }
    p.swap_remove(0)
}

#[test]
fn random_boxes_hold_every_sample_and_are_attained() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    for case in 0..40 {
        let n = 2 + case % 4;
        let points: Vec<Vec<Rational>> = (0..=n)
            .map(|_| vec![random_rational(&mut state), random_rational(&mut state)])
            .collect();
        let curve = BezierCurve::new(points.clone()).unwrap();
        let bounds = tight_bounding_box(&curve);
        let samples: Vec<Vec<Rational>> = (0..=64).map(|k| casteljau(&points, &q(k, 64))).collect();
        for j in 0..2 {
            let (low, high) = (&bounds.min[j], &bounds.max[j]);
            for s in &samples {
                assert_ne!(
                    low.value.cmp_rational(&s[j]),
                    Ordering::Greater,
                    "case {case}"
                );
                assert_ne!(
                    high.value.cmp_rational(&s[j]),
                    Ordering::Less,
                    "case {case}"
                );
            }
            // Attained where it says, by an independent exact evaluation: the value at the
            // parameter correctly rounded by interval refinement (not by the resultant).
            let coordinate: Vec<Rational> = points.iter().map(|p| p[j].clone()).collect();
            let power = power_coefficients(&coordinate);
            for e in [low, high] {
                for t in &e.at {
                    assert_eq!(
                        round_polynomial_at(&power, t),
                        e.value.to_f64(),
                        "case {case}"
                    );
                }
            }
            // Dense f64 sampling comes within 1e-6 and never beyond the outward box.
            let f: Vec<f64> = coordinate.iter().map(crate::rational_to_f64).collect();
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for k in 0..=20_000 {
                let t = f64::from(k) / 20_000.0;
                let mut c = f.clone();
                for r in 1..c.len() {
                    for i in 0..c.len() - r {
                        c[i] = c[i] * (1.0 - t) + c[i + 1] * t;
                    }
                }
                lo = lo.min(c[0]);
                hi = hi.max(c[0]);
            }
            let (lower, upper) = bounds.outward();
            assert!((lo - low.value.to_f64()).abs() < 1e-6 && lower[j] <= lo + 1e-12);
            assert!((hi - high.value.to_f64()).abs() < 1e-6 && upper[j] >= hi - 1e-12);
        }
    }
}

#[test]
fn nearest_points_are_no_farther_than_any_sample_and_agree_with_sampling() {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    for case in 0..30 {
        let n = 1 + case % 4;
        let points: Vec<Vec<Rational>> = (0..=n)
            .map(|_| vec![random_rational(&mut state), random_rational(&mut state)])
            .collect();
        let target = [random_rational(&mut state), random_rational(&mut state)];
        let curve = BezierCurve::new(points.clone()).unwrap();
        let nearest = nearest_point(&curve, &target).unwrap();
        let squared = |p: &[Rational]| -> Rational {
            p.iter()
                .zip(&target)
                .map(|(a, b)| (a - b) * (a - b))
                .fold(Rational::zero(), |x, y| x + y)
        };
        let mut best_sample = f64::INFINITY;
        for k in 0..=256 {
            let d = squared(&casteljau(&points, &q(k, 256)));
            assert_ne!(
                nearest.squared_distance.cmp_rational(&d),
                Ordering::Greater,
                "case {case}"
            );
            best_sample = best_sample.min(crate::rational_to_f64(&d));
        }
        // The reported points are at the reported distance (in f64, to 1e-12 relative) and
        // the fine sampling comes within 1e-4 of it.
        let d = nearest.squared_distance.to_f64();
        for p in &nearest.points {
            let x: Vec<f64> = p.iter().map(AlgebraicReal::to_f64).collect();
            let e = (x[0] - crate::rational_to_f64(&target[0])).powi(2)
                + (x[1] - crate::rational_to_f64(&target[1])).powi(2);
            assert!((e - d).abs() <= 1e-12 * (1.0 + d), "case {case}: {e} {d}");
        }
        assert!(best_sample - d <= 1e-2 * (1.0 + d), "case {case}");
        assert_eq!(nearest.at.len(), nearest.points.len());
    }
}

#[test]
fn a_single_point_curve_is_nearest_everywhere_and_bad_input_names_the_field() {
    let dot = BezierCurve::new(vec![vec![q(1, 1), q(2, 1)]; 3]).unwrap();
    let nearest = nearest_point(&dot, &[q(0, 1), q(0, 1)]).unwrap();
    assert!(nearest.everywhere);
    assert_eq!(nearest.squared_distance.exact(), Some(&q(5, 1)));
    let bounds = tight_bounding_box(&dot);
    assert!(bounds.min[0].everywhere && bounds.max[1].everywhere);
    let wrong = nearest_point(&dot, &[q(0, 1)]).unwrap_err();
    assert_eq!(
        (wrong.kind, wrong.field.as_str()),
        (ErrorKind::Dimension, "q")
    );
    let curve = BezierCurve::new(vec![vec![0.0, 1.0], vec![f64::NAN, 2.0]]).unwrap();
    let bad = tight_bounding_box_f64(&curve).unwrap_err();
    assert_eq!(
        (bad.kind, bad.field.as_str()),
        (ErrorKind::NotFinite, "control_points[1][0]")
    );
    let fine = BezierCurve::new(vec![vec![0.0, 1.0], vec![1.0, 2.0]]).unwrap();
    let bad = nearest_point_f64(&fine, &[0.0, f64::INFINITY]).unwrap_err();
    assert_eq!(
        (bad.kind, bad.field.as_str()),
        (ErrorKind::NotFinite, "q[1]")
    );
    // The segment (t, 1 + t) is nearest to (1, 0) at its end t = 0: D(t) = 2 t^2 + 2 (the
    // foot of the perpendicular, t = 0, is an end, not an inner critical point).
    let end = nearest_point_f64(&fine, &[1.0, 0.0]).unwrap();
    assert_eq!(end.at[0].exact(), Some(&q(0, 1)));
    assert_eq!(end.squared_distance.exact(), Some(&q(2, 1)));
}
