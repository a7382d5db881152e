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
