//! Rigorous floating-point enclosures for the float filter ([`super::filter`]): intervals,
//! double-double values with an error bound, and correct rounding decided from an enclosure.
//!
//! **Intervals are [`BoundedF64`].** A `BoundedF64` (v, e) stands for every real x with
//! |x - v| <= e. Its arithmetic is a running error analysis whose bound formulas are worst
//! cases over all operands within their bounds (for a product, |x y - fl(v_x v_y)| is at most
//! |v_x| e_y + |v_y| e_x + e_x e_y + u |fl(v_x v_y)| + η, and so on, each rounded upwards):
//! that is midpoint-radius
//! interval arithmetic, inclusion-isotone, so evaluating a polynomial by any sequence of ring
//! operations on `BoundedF64` arguments (de Casteljau's pyramid with an interval argument, say)
//! encloses its range over the argument intervals. This module adds the few set operations the
//! filter needs: the outward-rounded ends [`lower`] and [`upper`] (one `next_down`/`next_up`
//! after the rounded sum, so that lower <= v - e and upper >= v + e hold exactly).
//!
//! **Double-double with a bound: [`Dd`].** A value hi + lo (two doubles) with a bound e on its
//! distance to the exact result of the same operations. The sums and products use the
//! error-free transformations TwoSum (Knuth: s = fl(a + b), e = (a - (s - b')) + (b - b'),
//! b' = s - a, then a + b = s + e exactly) and TwoProd (p = fl(a b), e = fl(a b - p) by one
//! fused multiply-add, exact unless the product underflows, where it is off by at most η / 2).
//! The low-order terms are added in plain double arithmetic, and every such rounding is charged
//! to the bound (|fl(z) - z| <= u |fl(z)| for a sum, u |fl(z)| + η for a product, u = 2^-53,
//! η = 2^-1074), as are the input bounds (|x y - x̂ ŷ| <= |x̂| e_y + |ŷ| e_x + e_x e_y); the
//! final renormalisation is a TwoSum, exact. The bound is computed in `f64` and pushed up the
//! way [`BoundedF64`]'s is (times 1 + 16u, plus 8η). For de Casteljau's pyramid of degree n on
//! doubles of size M the bound is about n^2 u^2 M, some 1e-31 M.
//!
//! The filter's residual uses
//! de Casteljau's step [`Dd::lerp`], x + s (y - x) with TwoSum and TwoProd and a bound that
//! charges the inputs' errors once per step, as the exact convex combination moves them
//! (their maximum for s in [0, 1]).
//!
//! **Running bounds need the convex step: [`ConvexStep`].** De Casteljau's step is computed
//! by the engine as x + s (y - x); a running bound of that expression is
//! e_x + |s| (e_x + e_y), so over n levels the bound (and the width of an interval) grows like
//! (1 + 2|s|)^n, some 3^20 = 3e9 for degree 20 near s = 1, although the exact operation is
//! the convex combination (1 - s) x + s y, which moves errors by at most max(e_x, e_y).
//! [`ConvexStep`] computes that form, with 1 - s held as a value of the ring (exact for a
//! double s in [`Dd`], bounded in [`BoundedF64`]), so that its bound grows by
//! (|1 - s| + |s|) e plus the new roundings per level: additively for s in [0, 1]. The filter
//! runs the engine's pyramid ([`crate::shape::flat::curve_pyramid_in_place`]) with it.
//!
//! **Correct rounding: [`round_nearest`].** With x known to lie in base + [v - e, v + e]
//! (base a double, the offset an interval), x rounds to the double c = fl(base + v) when the
//! offsets of x from c (an interval [w - e, w + e] with w = base + v - c, exact by TwoSum) lie
//! strictly between minus half the gap to the double below c and half the gap to the double
//! above c (both gaps exact doubles for normal c). Anything else (the enclosure touches a
//! rounding boundary, c is zero, subnormal or the largest double) is undecided (`None`),
//! never guessed.

use crate::num::bounded::{rounding, upward, BoundedF64, ETA, UNIT_ROUNDOFF};
use crate::num::ring::{rational_to_f64, Rational, Ring};
use crate::shape::halving::CurveStep;
use num_traits::FromPrimitive;

/// The exact lower end of the interval `x` rounded down: a double <= v - e (-∞ without a bound).
#[inline]
pub(crate) fn lower(x: &BoundedF64) -> f64 {
    (x.value() - x.error_bound()).next_down()
}

/// The exact upper end of the interval `x` rounded up: a double >= v + e (+∞ without a bound).
#[inline]
pub(crate) fn upper(x: &BoundedF64) -> f64 {
    (x.value() + x.error_bound()).next_up()
}

/// TwoSum: `(s, e)` with s = fl(a + b) and a + b = s + e exactly (finite operands).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// TwoProd: `(p, e)` with p = fl(a b) and |a b - (p + e)| <= η / 2 (exact without underflow).
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// A double-double hi + lo together with a bound on its distance to the exact value of the
/// same operations on the same inputs (module documentation). Equality compares the values
/// only, as [`BoundedF64`]'s does.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Dd {
    hi: f64,
    lo: f64,
    bound: f64,
}

impl Dd {
    /// The double `x`, exact.
    pub(crate) fn exact(x: f64) -> Self {
        Dd {
            hi: x,
            lo: 0.0,
            bound: 0.0,
        }
    }

    /// The leading double.
    pub(crate) fn hi(&self) -> f64 {
        self.hi
    }

    /// The rest: the exact value lies in hi + (this interval).
    pub(crate) fn rest(&self) -> BoundedF64 {
        BoundedF64::with_bound(self.lo, self.bound_or_infinite())
    }

    /// The whole value as an interval of one double: fl(hi + lo) with the bound and the
    /// (exact) rounding residual of that sum.
    pub(crate) fn to_bounded(self) -> BoundedF64 {
        let (v, r) = two_sum(self.hi, self.lo);
        BoundedF64::with_bound(v, upward(self.bound_or_infinite() + r.abs()))
    }

    /// De Casteljau's step x + s (y - x) at the double `s`, for the pyramid of the filter's
    /// residual (module documentation): the difference, the product by s and the sum, each
    /// with TwoSum or TwoProd on the leading parts (exact, TwoProd but for η / 2 of
    /// underflow) and the low-order terms added in plain doubles (u |fl| each, u |fl| + η for
    /// the product s y_lo), renormalised exactly. The inputs' errors move by the exact
    /// combination (1 - s) e_x + s e_y <= (|1 - s| + |s|) max(e_x, e_y): their maximum for s in
    /// [0, 1], with no growth over the levels of the pyramid.
    #[inline]
    pub(crate) fn lerp(x: &Dd, y: &Dd, s: f64) -> Dd {
        let (r1, w3, [t1, w1, c, w2, t3]) = Dd::lerp_parts(x, y, s);
        let own = UNIT_ROUNDOFF * (t1.abs() + w1.abs() + c.abs() + w2.abs() + t3.abs() + w3.abs())
            + 2.0 * ETA;
        let spread = upward((1.0 - s).abs() + s.abs());
        Dd::make(r1, w3, spread * x.bound.max(y.bound) + own)
    }

    /// [`Dd::lerp`]'s value alone (the same doubles hi and lo, bit for bit), its bound left
    /// at zero: for a pyramid whose bound is known a priori ([`lerp_pyramid_bound`]).
    #[inline]
    pub(crate) fn lerp_value(x: &Dd, y: &Dd, s: f64) -> Dd {
        let (r1, w3, _) = Dd::lerp_parts(x, y, s);
        Dd::make(r1, w3, 0.0)
    }

    /// The operations of [`Dd::lerp`]: r1 + w3 and the rounded low-order terms whose
    /// roundings its bound charges (t1, w1, c, w2, t3; w3 is the second result).
    #[inline(always)]
    fn lerp_parts(x: &Dd, y: &Dd, s: f64) -> (f64, f64, [f64; 5]) {
        // d = y - x.
        let (d1, e1) = two_sum(y.hi, -x.hi);
        let t1 = y.lo - x.lo;
        let w1 = e1 + t1;
        let (dh, dl) = two_sum(d1, w1);
        // p = s d.
        let (ph, pe) = two_prod(s, dh);
        let c = s * dl;
        let w2 = pe + c;
        let (p1, p2) = two_sum(ph, w2);
        // x + p.
        let (r1, e3) = two_sum(x.hi, p1);
        let t3 = x.lo + p2;
        let w3 = e3 + t3;
        (r1, w3, [t1, w1, c, w2, t3])
    }

    /// The same value with another bound.
    #[inline]
    pub(crate) fn with_bound(self, bound: f64) -> Dd {
        Dd { bound, ..self }
    }

    fn bound_or_infinite(&self) -> f64 {
        if self.hi.is_finite() && self.lo.is_finite() && self.bound >= 0.0 {
            self.bound
        } else {
            f64::INFINITY
        }
    }

    /// Renormalises s + w (exactly) with the given bound.
    #[inline]
    fn make(s: f64, w: f64, bound: f64) -> Self {
        let (hi, lo) = two_sum(s, w);
        Dd {
            hi,
            lo,
            bound: upward(bound),
        }
    }
}

/// A bound, known before the evaluation, on the error of de Casteljau's pyramid of degree n
/// by [`Dd::lerp`] at a double s in [0, 1] on doubles of size at most `size`: every entry's
/// running bound of [`Dd::lerp`] is at most this, so that [`Dd::lerp_value`] may be used
/// with it.
///
/// Each entry's exact value is a convex combination of the inputs, at most M = `size`; a
/// computed entry hi + lo (|lo| <= u |hi| after the renormalising TwoSum) lies within its
/// bound B of it, so |hi| <= H = M (1 + 2^-40) while B <= 2^-80 M (true for n <= 256, see
/// below). From |x_hi|, |y_hi| <= H and |x_lo|, |y_lo| <= u H the low-order terms of
/// [`Dd::lerp`] are at most, up to factors (1 + 12u): |t1| <= 2uH, |w1| <= 4uH (|e1| <= 2uH
/// plus |t1|), |c| <= 2uH (|dl| <= u |dh|, |dh| <= 2H), |w2| <= 4uH (|pe| <= u |ph|),
/// |t3| <= 3uH (|x_lo| plus |p2| <= u |p1|), |w3| <= 4uH (|e3| <= u |r1|, |r1| <= H (1 + 10u)
/// as r1 is the convex combination x + s (y - x) up to the terms above): the step's own
/// charge u (|t1| + |w1| + |c| + |w2| + |t3| + |w3|) + 2η is at most 19 u^2 H (1 + 12u) + 2η
/// < 20 u^2 H + 2η. The spread |1 - s| + |s| is 1 for s in [0, 1]; the running bound rounds
/// it upwards (1 + 16u + 8η) and each step's bound once more ([`upward`]), so that n levels
/// give at most n (1 + 33u)^n (20 u^2 H + 10η) <= n (1 + 2^-36) (20 u^2 H + 10η) for
/// n <= 256, below 2^-80 M for M >= 1e-90; pushed upwards once more.
pub(crate) fn lerp_pyramid_bound(degree: usize, size: f64) -> f64 {
    let h = size * (1.0 + 2f64.powi(-40));
    let per_level = 20.0 * UNIT_ROUNDOFF * UNIT_ROUNDOFF * h + 10.0 * ETA;
    upward(degree as f64 * per_level * (1.0 + 2f64.powi(-36)))
}

impl PartialEq for Dd {
    fn eq(&self, other: &Self) -> bool {
        self.hi == other.hi && self.lo == other.lo
    }
}

impl Ring for Dd {
    type Coords = Vec<Self>;
    fn zero() -> Self {
        Dd::exact(0.0)
    }
    fn one() -> Self {
        Dd::exact(1.0)
    }
    /// (s, e) = TwoSum(x_hi, y_hi); t = fl(x_lo + y_lo); w = fl(e + t): two roundings,
    /// u (|t| + |w|).
    #[inline]
    fn add(&self, rhs: &Self) -> Self {
        let (s, e) = two_sum(self.hi, rhs.hi);
        let t = self.lo + rhs.lo;
        let w = e + t;
        let bound = self.bound + rhs.bound + UNIT_ROUNDOFF * (t.abs() + w.abs());
        Dd::make(s, w, bound)
    }
    #[inline]
    fn sub(&self, rhs: &Self) -> Self {
        self.add(&rhs.neg())
    }
    /// (p, e) = TwoProd(x_hi, y_hi) (η / 2), the three cross products (u |c| + η each) and the
    /// three sums of the low-order terms (u |fl| each), plus the propagated input bounds.
    #[inline]
    fn mul(&self, rhs: &Self) -> Self {
        let (p, e) = two_prod(self.hi, rhs.hi);
        let c1 = self.hi * rhs.lo;
        let c2 = self.lo * rhs.hi;
        let c3 = self.lo * rhs.lo;
        let t = c1 + c2;
        let t2 = t + c3;
        let w = e + t2;
        let own = rounding(c1) + rounding(c2) + rounding(c3) + 2.0 * ETA;
        let sums = UNIT_ROUNDOFF * (t.abs() + t2.abs() + w.abs());
        let x = upward(self.hi.abs() + self.lo.abs());
        let y = upward(rhs.hi.abs() + rhs.lo.abs());
        let propagated = x * rhs.bound + y * self.bound + self.bound * rhs.bound;
        Dd::make(p, w, propagated + own + sums)
    }
    fn neg(&self) -> Self {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
            bound: self.bound,
        }
    }
    /// Times k as a double-double: c = the nearest double to k, c_lo = the nearest double to
    /// k - c, off from k by at most u |c_lo| + η (both conversions correctly rounded).
    fn scale(&self, k: &Rational) -> Self {
        let c = rational_to_f64(k);
        let rest = Rational::from_f64(c).map(|cq| k - cq);
        let constant = match rest {
            Some(rest) => {
                let c_lo = rational_to_f64(&rest);
                Dd {
                    hi: c,
                    lo: c_lo,
                    bound: rounding(c_lo),
                }
            }
            None => Dd {
                hi: c,
                lo: 0.0,
                bound: f64::INFINITY,
            },
        };
        self.mul(&constant)
    }
    fn is_zero(&self) -> bool {
        self.hi == 0.0 && self.lo == 0.0
    }
}

/// De Casteljau's step at the argument s in the convex form (1 - s) x + s y (module
/// documentation): the argument and its complement, both values of the ring.
pub(crate) struct ConvexStep<T> {
    s: T,
    complement: T,
}

impl<T: Ring> ConvexStep<T> {
    /// The step at `s`, with 1 - s computed in the ring.
    pub(crate) fn new(s: T) -> Self {
        ConvexStep {
            complement: T::one().sub(&s),
            s,
        }
    }
}

impl<T: Ring> CurveStep<T> for ConvexStep<T> {
    #[inline]
    fn combine(&self, x: &T, y: &T) -> T {
        x.mul(&self.complement).add(&y.mul(&self.s))
    }
}

/// The double nearest to x (ties to even) for x in `base` + `offset` (exactly, `base` a
/// double), or `None` when the enclosure does not decide it (module documentation).
///
/// With v ± e the offset, TwoSum gives c = fl(base + v) and its error w = base + v - c
/// exactly, so x - c lies in [w - e, w + e]. For normal c below the largest double, the gaps
/// to its neighbours are exact doubles (one unit of the last place apart in the bits), and so
/// are their halves h_down and h_up. x rounds to c when -h_down < w - e and w + e < h_up:
/// decided from the rounded fl(w - e) > -h_down and fl(w + e) < h_up (rounding is monotone
/// and the halves are doubles, so the rounded comparisons imply the exact ones). A tie
/// (x exactly half-way) is never inside the strict inequalities: undecided, as is anything
/// non-finite, a c that is zero, subnormal or near the top of the range.
#[inline]
pub(crate) fn round_nearest(base: f64, offset: &BoundedF64) -> Option<f64> {
    let (v, e) = (offset.value(), offset.error_bound());
    // Also false for NaN.
    if !(base.is_finite() && v.is_finite() && e < f64::INFINITY) {
        return None;
    }
    let (c, w) = two_sum(base, v);
    // Half gaps are exact for normal c away from the top of the range.
    let size = c.abs();
    if !(4.0 * f64::MIN_POSITIVE..f64::MAX).contains(&size) {
        return None;
    }
    // The neighbours of the normal, finite c: one unit of the last place away in the bits
    // (towards zero and away from it; the magnitude's bits are ordered as the magnitudes).
    let bits = c.to_bits();
    let (smaller, larger) = (f64::from_bits(bits - 1), f64::from_bits(bits + 1));
    let (below, above) = if c > 0.0 {
        (smaller, larger)
    } else {
        (larger, smaller)
    };
    let half_up = 0.5 * (above - c);
    let half_down = 0.5 * (c - below);
    (w - e > -half_down && w + e < half_up).then_some(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::flat::{curve_eval_into, curve_pyramid_in_place};
    use num_bigint::BigInt;

    fn exact(x: f64) -> Rational {
        Rational::from_f64(x).unwrap()
    }

    /// The exact value hi + lo and a check that the exact `truth` lies within the bound.
    fn encloses(d: &Dd, truth: &Rational) -> bool {
        let v = exact(d.hi) + exact(d.lo);
        let diff = if &v > truth { &v - truth } else { truth - &v };
        diff <= exact(d.bound)
    }

    #[test]
    fn double_double_pyramid_bound_holds_and_is_tiny() {
        // de Casteljau in Dd against exact rationals, on awkward doubles.
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for n in [1usize, 3, 8, 20] {
            for _ in 0..20 {
                let pts: Vec<f64> = (0..=n).map(|_| next()).collect();
                let s = 0.5 * (next() + 1.0);
                let dd: Vec<Dd> = pts.iter().map(|&x| Dd::exact(x)).collect();
                let mut out = dd.clone();
                curve_pyramid_in_place(&mut out, 1, &ConvexStep::new(Dd::exact(s)));
                let q: Vec<Rational> = pts.iter().map(|&x| exact(x)).collect();
                let mut out_q = [Rational::from_integer(BigInt::from(0))];
                curve_eval_into(&q, 1, &exact(s), &mut out_q, &mut Vec::new());
                assert!(encloses(&out[0], &out_q[0]), "n = {n}");
                // The same pyramid by `Dd::lerp`.
                let mut level = dd.clone();
                for k in (2..=level.len()).rev() {
                    for i in 0..k - 1 {
                        level[i] = Dd::lerp(&level[i], &level[i + 1], s);
                    }
                }
                assert!(encloses(&level[0], &out_q[0]), "lerp, n = {n}");
                assert!(level[0].bound < (n * n) as f64 * 1e-31);
                // Some n^2 u^2: far below the half ulps the filter decides against.
                assert!(
                    out[0].bound < (n * n) as f64 * 1e-31,
                    "bound {:e}",
                    out[0].bound
                );
                let b = out[0].to_bounded();
                let lo = exact(lower(&b));
                let hi = exact(upper(&b));
                assert!(lo <= out_q[0] && out_q[0] <= hi);
            }
        }
    }

    #[test]
    fn scale_by_a_third_is_within_its_bound() {
        let third = Rational::new(BigInt::from(1), BigInt::from(3));
        let d = Dd::exact(0.7).scale(&third);
        assert!(encloses(&d, &(exact(0.7) * third)));
        assert!(d.bound < 1e-32);
    }

    #[test]
    fn rounding_decisions() {
        // 1/3 enclosed tightly rounds to the nearest double of 1/3.
        let third = Dd::exact(1.0).scale(&Rational::new(BigInt::from(1), BigInt::from(3)));
        assert_eq!(round_nearest(third.hi(), &third.rest()), Some(1.0 / 3.0));
        // An enclosure of a rounding boundary is undecided, one just off it is decided.
        let half_gap = 0.5 * (1.0f64.next_up() - 1.0);
        let on = BoundedF64::with_bound(half_gap, 1e-30);
        assert_eq!(round_nearest(1.0, &on), None);
        let below = BoundedF64::with_bound(half_gap * (1.0 - 1e-10), 1e-30);
        assert_eq!(round_nearest(1.0, &below), Some(1.0));
        let above = BoundedF64::with_bound(half_gap * (1.0 + 1e-10), 1e-30);
        assert_eq!(round_nearest(1.0, &above), Some(1.0f64.next_up()));
        // Below a power of two the gap is half as large.
        let down = BoundedF64::with_bound(-0.75 * half_gap, 1e-30);
        assert_eq!(round_nearest(1.0, &down), Some(1.0f64.next_down()));
        // Zero and wide enclosures are undecided.
        assert_eq!(
            round_nearest(0.0, &BoundedF64::with_bound(0.0, 1e-300)),
            None
        );
        assert_eq!(
            round_nearest(0.5, &BoundedF64::with_bound(0.0, 1e-16)),
            None
        );
    }

    #[test]
    fn interval_helpers_round_outwards() {
        let x = BoundedF64::with_bound(0.2, 0.1);
        assert!(lower(&x) <= 0.1 && upper(&x) >= 0.3);
    }
}
