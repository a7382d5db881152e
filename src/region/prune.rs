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
//! Both proofs take control points of exact rationals or of doubles ([`ProofPoint`]); the
//! candidate directions are any doubles (the proofs hold for every direction), computed from
//! the points rounded to doubles.
//!
//! Every sign is exact: a float filter with a rigorous error bound when the points are
//! doubles, exact rational arithmetic otherwise or when the filter cannot tell.

use super::curve::is_double;
use crate::intersect::algebraic::exact_f64;
use crate::num::ring::{rational_to_f64, Rational};
use num_traits::Zero;
use std::cmp::Ordering;

/// A control point as the proofs see it: its coordinates as doubles (exact for `f64`
/// points, rounded for rationals: they only choose candidate directions) and the exact sign
/// of n . (x - v) for a normal n of doubles.
pub(crate) trait ProofPoint: PartialEq {
    /// The coordinates as doubles.
    fn approx(&self) -> [f64; 2];
    /// The exact sign of n . (self - v).
    fn side(&self, n: &[f64; 2], v: &Self) -> Ordering;
}

/// The float filter of a sign n . (x - v) on doubles: fl(x - v) has relative error at most
/// u = 2^-53 and each product and the sum add at most u more each, so the computed value is
/// within 4u (|n0 d0| + |n1 d1|) plus an underflow margin of the exact one. `None` when that
/// does not decide.
fn side_filter(n: &[f64; 2], x: [f64; 2], v: [f64; 2]) -> Option<Ordering> {
    let d = [x[0] - v[0], x[1] - v[1]];
    let value = n[0] * d[0] + n[1] * d[1];
    let bound = 4.0 * f64::EPSILON * ((n[0] * d[0]).abs() + (n[1] * d[1]).abs()) + 1e-300;
    (value.is_finite() && value.abs() > bound).then(|| value.partial_cmp(&0.0).expect("finite"))
}

/// The exact sign of n . (x - v) in rationals.
fn side_exact(n: &[f64; 2], x: &[Rational; 2], v: &[Rational; 2]) -> Ordering {
    let n = [exact_f64(n[0]), exact_f64(n[1])];
    (&n[0] * (&x[0] - &v[0]) + &n[1] * (&x[1] - &v[1])).cmp(&Rational::zero())
}

impl ProofPoint for [Rational; 2] {
    fn approx(&self) -> [f64; 2] {
        [rational_to_f64(&self[0]), rational_to_f64(&self[1])]
    }
    fn side(&self, n: &[f64; 2], v: &Self) -> Ordering {
        if self.iter().chain(v).all(is_double) {
            if let Some(o) = side_filter(n, self.approx(), v.approx()) {
                return o;
            }
        }
        side_exact(n, self, v)
    }
}

impl ProofPoint for [f64; 2] {
    fn approx(&self) -> [f64; 2] {
        *self
    }
    fn side(&self, n: &[f64; 2], v: &Self) -> Ordering {
        side_filter(n, *self, *v).unwrap_or_else(|| {
            let exact = |p: &[f64; 2]| [exact_f64(p[0]), exact_f64(p[1])];
            side_exact(n, &exact(self), &exact(v))
        })
    }
}

/// A double approximation of a unit vector along `v` (`None` for zero, or when the square
/// of its length overflows or underflows: the exact path then decides). The directions to the
/// neighbours of a corner at unit length make their difference normal to the corner's
/// bisector (any direction is sound: the proof tests it exactly).
fn unit(v: [f64; 2]) -> Option<[f64; 2]> {
    let n = (v[0] * v[0] + v[1] * v[1]).sqrt();
    (n > 0.0 && n.is_finite()).then(|| [v[0] / n, v[1] / n])
}

fn minus(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// Whether P (ending at v) and Q (starting at v) provably meet only at v.
pub(crate) fn consecutive_meet_only_at_join<P: ProofPoint>(p: &[P], q: &[P]) -> bool {
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
    let (vf, bf, af) = (v.approx(), before.approx(), after.approx());
    let (Some(ub), Some(ua)) = (unit(minus(bf, vf)), unit(minus(af, vf))) else {
        return false;
    };
    let candidates = [minus(ua, ub), minus(af, bf)];
    candidates.into_iter().any(|n| {
        n.iter().all(|c| c.is_finite())
            && p.iter()
                .filter(|x| *x != v)
                .all(|x| x.side(&n, v) == Ordering::Less)
            && q.iter()
                .filter(|x| *x != v)
                .all(|x| x.side(&n, v) == Ordering::Greater)
    })
}

/// Whether the curve with control points `p` is provably one-to-one (so has no
/// self-intersection and does not retrace itself): some direction d (the chord, or the sum of
/// the legs as computed) has d . (P_(i+1) - P_i) >= 0 for every leg and > 0 for one, decided
/// exactly. Then d . P'(t) = n Σ_i d . (P_(i+1) - P_i) B_i^(n-1)(t) > 0 on (0, 1), so d . P
/// increases strictly and P takes no point twice. Legs of length zero (a control point on
/// an end, as fonts write straight quadratics) are allowed.
pub(crate) fn one_to_one<P: ProofPoint>(p: &[P]) -> bool {
    let chord = minus(p[p.len() - 1].approx(), p[0].approx());
    let mut sum = [0.0, 0.0];
    for w in p.windows(2) {
        let d = minus(w[1].approx(), w[0].approx());
        sum = [sum[0] + d[0], sum[1] + d[1]];
    }
    [chord, sum].iter().any(|d| {
        let mut advances = false;
        d.iter().all(|c| c.is_finite())
            && p.windows(2).all(|w| match w[1].side(d, &w[0]) {
                Ordering::Less => false,
                Ordering::Equal => true,
                Ordering::Greater => {
                    advances = true;
                    true
                }
            })
            && advances
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
