//! Cheap exact proofs that spare the exact intersector its work on the commonest pairs.
//!
//! * **Consecutive curves.** P ends where Q starts, at v. If some line through v has every
//!   control point of P but v strictly on one side and every control point of Q but v
//!   strictly on the other, the curves meet only at v: P(t) for t < 1 is a convex
//!   combination giving positive weight to a point strictly on P's side, so it is strictly
//!   on that side, and likewise Q(t) for t > 0. The answer is then the single intersection
//!   (s, t) = (1, 0). Candidate normals (exact rationals made from doubles) are the
//!   difference of the unit directions from v to the nearest distinct control points of Q
//!   and of P (a corner), and the direction from P's to Q's (a smooth join); the signs are
//!   tested in exact rational arithmetic, so a candidate either proves the claim or is
//!   discarded.
//! * **Curves without a self-intersection.** If every difference of consecutive control
//!   points (the hodograph's control points, up to the factor n) has a positive dot product
//!   with one direction d, the curve moves strictly forward along d and is one-to-one. d is
//!   tried as the chord P_n - P_0 and as the sum of the differences (both as doubles, made
//!   exact).
//!
//! Every sign is exact: a float filter with a rigorous error bound when the points are
//! doubles, exact rational arithmetic otherwise or when the filter cannot tell.

use super::curve::is_double;
use crate::num::ring::{rational_to_f64, Rational};
use num_traits::Zero;
use std::cmp::Ordering;

fn sub(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

fn dot(a: &[Rational; 2], b: &[Rational; 2]) -> Rational {
    &a[0] * &b[0] + &a[1] * &b[1]
}

/// A double approximation of a unit vector along `v` (`None` for zero), as exact rationals.
fn unit(v: &[Rational; 2]) -> Option<[f64; 2]> {
    let x = rational_to_f64(&v[0]);
    let y = rational_to_f64(&v[1]);
    let n = x.hypot(y);
    (n > 0.0 && n.is_finite()).then(|| [x / n, y / n])
}

fn exact(v: [f64; 2]) -> Option<[Rational; 2]> {
    Some([Rational::from_float(v[0])?, Rational::from_float(v[1])?])
}

/// The exact sign of n . (x - v) for a normal n of doubles: a float filter first (when x and
/// v are doubles: fl(x - v) has relative error at most u = 2^-53 and each product and the sum
/// add at most u more each, so an error below 4u (|n0 d0| + |n1 d1|) plus an underflow
/// margin), exact rational arithmetic when the filter cannot tell.
fn side(n: &[f64; 2], n_exact: &[Rational; 2], x: &[Rational; 2], v: &[Rational; 2]) -> Ordering {
    let doubles = x.iter().chain(v).all(is_double);
    if doubles {
        let xf = [rational_to_f64(&x[0]), rational_to_f64(&x[1])];
        let vf = [rational_to_f64(&v[0]), rational_to_f64(&v[1])];
        let d = [xf[0] - vf[0], xf[1] - vf[1]];
        let value = n[0] * d[0] + n[1] * d[1];
        let bound = 4.0 * f64::EPSILON * ((n[0] * d[0]).abs() + (n[1] * d[1]).abs()) + 1e-300;
        if value.is_finite() && value.abs() > bound {
            return value.partial_cmp(&0.0).expect("finite");
        }
    }
    dot(n_exact, &sub(x, v)).cmp(&Rational::zero())
}

/// Whether P (ending at v) and Q (starting at v) provably meet only at v.
pub(crate) fn consecutive_meet_only_at_join(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> bool {
    let v = &p[p.len() - 1];
    if &q[0] != v {
        return false;
    }
    let Some(before) = p.iter().rev().find(|x| *x != v) else {
        return false;
    };
    let Some(after) = q.iter().find(|x| *x != v) else {
        return false;
    };
    let (Some(ub), Some(ua)) = (unit(&sub(before, v)), unit(&sub(after, v))) else {
        return false;
    };
    let candidates = [
        [ua[0] - ub[0], ua[1] - ub[1]],
        [
            rational_to_f64(&(&after[0] - &before[0])),
            rational_to_f64(&(&after[1] - &before[1])),
        ],
    ];
    candidates.into_iter().any(|n| {
        let Some(n_exact) = exact(n) else {
            return false;
        };
        p.iter()
            .filter(|x| *x != v)
            .all(|x| side(&n, &n_exact, x, v) == Ordering::Less)
            && q.iter()
                .filter(|x| *x != v)
                .all(|x| side(&n, &n_exact, x, v) == Ordering::Greater)
    })
}

/// Whether the curve with control points `p` is provably one-to-one (so has no
/// self-intersection and does not retrace itself).
pub(crate) fn one_to_one(p: &[[Rational; 2]]) -> bool {
    let chord = sub(&p[p.len() - 1], &p[0]);
    let mut sum = [0.0, 0.0];
    for w in p.windows(2) {
        for a in 0..2 {
            sum[a] += rational_to_f64(&w[1][a]) - rational_to_f64(&w[0][a]);
        }
    }
    let candidates = [
        [rational_to_f64(&chord[0]), rational_to_f64(&chord[1])],
        sum,
    ];
    candidates.iter().any(|d| {
        let Some(d_exact) = exact(*d) else {
            return false;
        };
        p.windows(2)
            .all(|w| side(d, &d_exact, &w[1], &w[0]) == Ordering::Greater)
    })
}

#[cfg(test)]
mod tests {
    use super::{consecutive_meet_only_at_join, one_to_one};
    use crate::num::ring::Rational;

    fn p(x: i64, y: i64) -> [Rational; 2] {
        [
            Rational::from_integer(x.into()),
            Rational::from_integer(y.into()),
        ]
    }

    #[test]
    fn doubles_are_recognised_exactly() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        assert!(
            crate::region::curve::is_double(&q(3, 8))
                && crate::region::curve::is_double(&q(0, 1))
                && crate::region::curve::is_double(&q(-5, 1))
        );
        assert!(
            !crate::region::curve::is_double(&q(1, 3))
                && !crate::region::curve::is_double(&q((1 << 54) + 1, 1))
        );
        for r in [q(3, 8), q(-7, 1024), q(1 << 52, 1)] {
            assert_eq!(
                crate::intersect::algebraic::exact_f64(crate::rational_to_f64(&r)),
                r
            );
        }
    }

    #[test]
    fn joins_and_injectivity() {
        // A corner and a smooth join: proved.
        assert!(consecutive_meet_only_at_join(
            &[p(0, 0), p(1, 0)],
            &[p(1, 0), p(1, 1)]
        ));
        assert!(consecutive_meet_only_at_join(
            &[p(0, 0), p(1, 1), p(2, 1)],
            &[p(2, 1), p(3, 1), p(4, 0)]
        ));
        // Q doubles back over P: not proved (they share a stretch).
        assert!(!consecutive_meet_only_at_join(
            &[p(0, 0), p(2, 0)],
            &[p(2, 0), p(1, 0)]
        ));
        // Q crosses P again: not proved.
        assert!(!consecutive_meet_only_at_join(
            &[p(0, 0), p(4, 0)],
            &[p(4, 0), p(0, 4), p(2, -4)]
        ));
        assert!(one_to_one(&[p(0, 0), p(1, 2), p(3, 2), p(4, 0)]));
        // A loop (control polygon crossing back): not proved.
        assert!(!one_to_one(&[p(0, 0), p(4, 4), p(0, 4), p(4, 0)]));
        // Closed: not proved.
        assert!(!one_to_one(&[p(0, 0), p(4, 4), p(0, 4), p(0, 0)]));
    }
}
