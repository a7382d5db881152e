//! A float filter for the side test of [`ray_count`](super::winding::ray_count): where does a
//! monotone piece cross the ray's line, before or after the ray's start?
//!
//! On a piece [t0, t1] of a curve where the coordinate c_b(t) is strictly monotone and spans
//! the height h = p_b, the crossing is the one root t* of c_b(t) - h in (t0, t1); the ray
//! counts it when c_a(t*) > p_a. The filter brackets t* between doubles ta < tb inside
//! [t0, t1] (outward-rounded ends of the breaks' isolating intervals) at which c_b - h has
//! proved opposite signs, halves the bracket while the sign at its midpoint is proved, and
//! encloses c_a - p_a over the bracket; a proved sign of that enclosure is the answer.
//!
//! **Certified.** Every sign comes from midpoint-radius interval arithmetic
//! ([`BoundedF64`], inclusion-isotone; the coefficients and the point are enclosed by
//! [`BoundedF64::rounded`]), so a proved sign is the exact sign. Monotony on [t0, t1] makes
//! the root between ta and tb the crossing t* itself. When no sign is proved (t* at a break,
//! a crossing at the ray's start, a bracket that does not shrink) the filter answers `None`
//! and the caller takes the exact path.

use super::curve::{f64_down, f64_up, Curve};
use crate::intersect::algebraic::AlgebraicReal;
use crate::intersect::interval::{lower, upper};
use crate::num::bounded::BoundedF64;
use crate::num::ring::{Rational, Ring};
use std::cmp::Ordering;

/// The most halvings of the bracket (a double bracket inside [0, 1] is down to a few ulps
/// after about 60).
const MAX_HALVINGS: usize = 64;

/// p(t) - h over the interval t (midpoint-radius), by Horner.
fn shifted_at(p: &[BoundedF64], h: &BoundedF64, t: &BoundedF64) -> BoundedF64 {
    let mut acc = p.last().copied().unwrap_or(BoundedF64::exact(0.0));
    for c in p.iter().rev().skip(1) {
        acc = acc.mul(t).add(c);
    }
    acc.sub(h)
}

/// The proved sign of an enclosure, `None` when it holds 0.
fn proved_sign(x: &BoundedF64) -> Option<Ordering> {
    if lower(x) > 0.0 {
        Some(Ordering::Greater)
    } else if upper(x) < 0.0 {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// The exact sign of c_a(t*) - p_a, for t* the one root of c_b(t) - p_b in the piece
/// (t0, t1) of `curve` on which c_b is strictly monotone and spans p_b (`a` the ray's axis,
/// `b` the other), when the float filter proves it; `None` otherwise.
pub(crate) fn crossing_side(
    curve: &Curve,
    a: usize,
    (t0, t1): (&AlgebraicReal, &AlgebraicReal),
    p: &[Rational; 2],
) -> Option<Ordering> {
    let b = 1 - a;
    let power = curve.power_bounded();
    let (ha, hb) = (BoundedF64::rounded(&p[a]), BoundedF64::rounded(&p[b]));
    let (mut ta, mut tb) = (f64_up(t0.interval().1), f64_down(t1.interval().0));
    if ta >= tb {
        return None;
    }
    let sign_b = |t: f64| proved_sign(&shifted_at(&power[b], &hb, &BoundedF64::exact(t)));
    let sa = sign_b(ta)?;
    if sign_b(tb)? != sa.reverse() {
        return None;
    }
    for _ in 0..MAX_HALVINGS {
        // The bracket as midpoint-radius: mid exact or rounded, radius rounded up.
        let mid = 0.5 * (ta + tb);
        let radius = (mid - ta).max(tb - mid).next_up();
        let side = shifted_at(&power[a], &ha, &BoundedF64::with_bound(mid, radius));
        if let Some(s) = proved_sign(&side) {
            return Some(s);
        }
        if mid <= ta || mid >= tb {
            return None;
        }
        match sign_b(mid)? {
            s if s == sa => ta = mid,
            _ => tb = mid,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::crossing_side;
    use crate::intersect::algebraic::shifted_poly;
    use crate::intersect::zeros::roots_with_multiplicity;
    use crate::num::ring::Rational;
    use crate::region::curve::Curve;
    use crate::Bezier;
    use num_traits::{One, Zero};
    use std::cmp::Ordering;

    /// The filter against the exact isolation (the root of c_b - p_b inside the piece, then
    /// the sign of c_a - p_a there) on random cubics and points: every proved answer agrees,
    /// and most crossings are decided by the filter.
    #[test]
    fn filter_agrees_with_exact_isolation() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut unit = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut decided, mut total) = (0, 0);
        for _ in 0..300 {
            let mut exact = || Rational::from_float(unit()).unwrap();
            let points: Vec<[Rational; 2]> = (0..4).map(|_| [exact(), exact()]).collect();
            let curve = Curve::new(&Bezier::new(points).unwrap());
            let p = [exact(), exact()];
            for a in 0..2 {
                let b = 1 - a;
                let mono = curve.monotone(b);
                if mono.constant {
                    continue;
                }
                let roots: Vec<_> = roots_with_multiplicity(
                    &shifted_poly(&curve.power[b], &p[b]),
                    &Rational::zero(),
                    &Rational::one(),
                )
                .into_iter()
                .map(|r| r.value)
                .collect();
                for k in 0..mono.params.len() - 1 {
                    let (t0, t1) = (&mono.params[k], &mono.params[k + 1]);
                    let Some(root) = roots.iter().find(|t| {
                        t.compare(t0) == Ordering::Greater && t.compare(t1) == Ordering::Less
                    }) else {
                        continue;
                    };
                    let exact = root.clone().sign_of(&shifted_poly(&curve.power[a], &p[a]));
                    total += 1;
                    if let Some(s) = crossing_side(&curve, a, (t0, t1), &p) {
                        assert_eq!(s, exact, "curve {:?}, p {p:?}, axis {a}", curve.points);
                        decided += 1;
                    }
                }
            }
        }
        assert!(total > 100, "{total} crossings");
        assert!(decided * 10 >= total * 9, "{decided} of {total} decided");
    }
}
