//! [`BoundedF64`]: a double that carries a rigorous bound on its own rounding error. The
//! model and the guarantee are documented on the type, where rustdoc shows them.

use crate::num::linalg::Field;
use crate::num::meter::{charge_bounded, charge_bounded_constant};
use crate::num::ring::{rational_to_f64, Rational, Ring};
use num_traits::{FromPrimitive, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;

/// The unit roundoff of binary64 with round-to-nearest, u = 2^-53.
pub(crate) const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// The smallest positive subnormal double, 2^-1074 (η of [`BoundedF64`]'s model).
pub(crate) const ETA: f64 = 5e-324;

/// The factor (1 + 16u) that makes a computed bound an upper bound of the exact expression.
const SAFETY: f64 = 1.0 + 16.0 * UNIT_ROUNDOFF;

/// A double together with a rigorous bound on its distance to the exact result of the same
/// operations on the same inputs: the value is **bit for bit** plain `f64`'s, the bound is
/// **certified** (a running error analysis, not an estimate). No limits beyond `f64`'s: an
/// overflowing bound is +∞, still a bound.
///
/// ```
/// use blossom::{restrict_power_curve, BoundedF64, Method, PowerCurve};
///
/// // C(u) = 1 + u + u^2 on [0.1, 0.7], in f64 with a bound on every control point's error.
/// let x = BoundedF64::exact;
/// let curve = PowerCurve::new(vec![vec![x(1.0)], vec![x(1.0)], vec![x(1.0)]])?;
/// let bezier = restrict_power_curve(&curve, &x(0.1), &x(0.7), Method::Bulk);
/// let plain = PowerCurve::new(vec![vec![1.0], vec![1.0], vec![1.0]])?;
/// let plain = restrict_power_curve(&plain, &0.1, &0.7, Method::Bulk);
/// for (p, q) in bezier.control_points().iter().zip(plain.control_points()) {
///     assert_eq!(p[0].value(), q[0]); // the very same doubles as plain f64
///     assert!(p[0].error_bound() < 1e-14); // and a few ulps of bound
/// }
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # The model
///
/// A `BoundedF64` is a pair (x̂, e): x̂ is exactly the double that plain `f64` arithmetic
/// computes by the same operations on the same inputs (bit for bit: every operation below does
/// the `f64` operation of [`Ring for f64`](crate::Ring) on the values), and e bounds the distance
/// |x - x̂| to the number x that *exact* arithmetic computes by the same operations on the same
/// inputs. Inputs made by [`BoundedF64::exact`] have e = 0; constants the algorithms make from
/// exact rationals ([`Ring::scale`], [`Ring::from_rational`], [`Ring::scale_frac`],
/// [`Ring::from_int`]) carry the exact error of their conversion to a double.
///
/// Since every algorithm of the crate is generic over [`Ring`], running it on `BoundedF64` gives
/// its `f64` answer together with a bound on the answer's error, for free. The bound is a
/// *running error analysis* (Wilkinson): first-order effects and second-order terms are both
/// kept, so the bound is rigorous, not an estimate.
///
/// ## The rounding model
///
/// With round-to-nearest in binary64 and u = 2^-53, the rounded result fl(s) of an operation
/// whose exact result is s satisfies |s - fl(s)| <= u |fl(s)| + η, where η = 2^-1074 covers
/// underflow into the subnormal range (half an ulp of a subnormal is at most 2^-1075). With
/// |x - x̂| <= e_x and |y - ŷ| <= e_y:
///
/// * x ± y:  |(x ± y) - fl(x̂ ± ŷ)| <= e_x + e_y + u |v| + η, v = fl(x̂ ± ŷ);
/// * x y:    |x y - fl(x̂ ŷ)| <= |x̂| e_y + |ŷ| e_x + e_x e_y + u |v| + η;
/// * x / y:  when e_y < |ŷ|, |x/y - fl(x̂/ŷ)| <= (e_x |ŷ| + |x̂| e_y) / (|ŷ| (|ŷ| - e_y)) + u |v| + η,
///   and no finite bound otherwise (the exact divisor may be zero).
///
/// The bound itself is computed in `f64`, so it is rounded too: each bound is the computed
/// expression times (1 + 16u) plus 8η, which covers the downward rounding of the at most seven
/// operations of any bound formula above (each loses at most a factor (1 - u) and, in a product,
/// η). An overflowing bound is +∞, which is still a bound; a NaN value or bound means "no bound"
/// and is reported as an infinite bound by [`BoundedF64::error_bound`].
///
/// ## Comparisons
///
/// Equality and order compare the values only, exactly as the `f64` path does, so that every
/// algorithm takes the same branches as it does on `f64` (the polarisation formula groups equal
/// arguments, say). Such a branch decides on x̂, not on x: the bound is rigorous for the
/// operations the `f64` path performed, which is what it claims. Inputs are exact (e = 0), so a
/// comparison of inputs (a knot span search, a parameter against an interval) decides exactly.
#[derive(Clone, Copy, Debug, Default)]
pub struct BoundedF64 {
    value: f64,
    bound: f64,
}

/// `(e) * (1 + 16u) + 8η`: the computed bound expression `e`, rounded upwards (the model of
/// [`BoundedF64`]).
#[inline]
pub(crate) fn upward(e: f64) -> f64 {
    e * SAFETY + 8.0 * ETA
}

/// The rounding error bound u |v| + η of a result v.
#[inline]
pub(crate) fn rounding(v: f64) -> f64 {
    UNIT_ROUNDOFF * v.abs() + ETA
}

/// The exact value of a finite double, or `None` for NaN and the infinities.
fn exact_value(x: f64) -> Option<Rational> {
    if x.is_finite() {
        Rational::from_f64(x)
    } else {
        None
    }
}

/// An upper bound on |k - x| for an exact k and a double x (+∞ when x is not finite),
/// computed exactly.
fn conversion_error(k: &Rational, x: f64) -> f64 {
    match exact_value(x) {
        Some(xq) => {
            let difference = (k - xq).abs();
            if Zero::is_zero(&difference) {
                0.0
            } else {
                // Rounded to nearest, then pushed up by more than its rounding error.
                upward(rational_to_f64(&difference))
            }
        }
        None => f64::INFINITY,
    }
}

/// The largest integer m such that every integer of [-m, m] is a double, 2^53.
const EXACT_INTEGERS: i64 = 1 << 53;

/// Whether `n` and `d` are doubles exactly (so that `n as f64 / d as f64` is the correctly
/// rounded quotient, IEEE division being correctly rounded).
fn exact_operands(n: i128, d: i128) -> bool {
    let range = -i128::from(EXACT_INTEGERS)..=i128::from(EXACT_INTEGERS);
    range.contains(&n) && range.contains(&d)
}

/// The bound of the double `x` that stands for `n / d` (`d != 0`): zero when the quotient is
/// a double (an integer, or a dyadic fraction, of operands below 2^53), u |x| + η when `x` is the correctly rounded quotient of exact operands
/// (the common case, without big-number arithmetic), else the exact conversion error.
fn quotient_error(n: i128, d: i128, x: f64) -> f64 {
    if exact_operands(n, d) {
        // An integer quotient, or one over a power of two, of operands below 2^53 is a double.
        if d != 0 && (n % d == 0 || d.unsigned_abs().is_power_of_two()) {
            0.0
        } else {
            rounding(x)
        }
    } else {
        conversion_error(&Rational::new(n.into(), d.into()), x)
    }
}

/// The bound of `rational_to_f64(k)`. That conversion is correctly rounded (num-rational 0.4
/// divides numerator and denominator to 55 or 56 bits and rounds half to even with the
/// remainder as sticky bit; the test `rational_conversion_is_correctly_rounded` checks it), so
/// the bound is u |x| + η without big-number arithmetic, and zero for a quotient that is a
/// double.
fn rational_error(k: &Rational, x: f64) -> f64 {
    if !x.is_finite() {
        return f64::INFINITY;
    }
    match (k.numer().to_i64(), k.denom().to_i64()) {
        (Some(n), Some(d)) if exact_operands(n.into(), d.into()) => {
            quotient_error(n.into(), d.into(), x)
        }
        _ => rounding(x),
    }
}

impl BoundedF64 {
    /// An input: the double `value`, taken as exact (bound 0).
    pub fn exact(value: f64) -> Self {
        BoundedF64 { value, bound: 0.0 }
    }

    /// A double known to lie within `bound` of the exact value (a negative or NaN bound is
    /// taken as +∞, "no bound").
    pub fn with_bound(value: f64, bound: f64) -> Self {
        let bound = if bound >= 0.0 { bound } else { f64::INFINITY };
        BoundedF64 { value, bound }
    }

    /// The nearest double to the exact `k`, with the exact error of that rounding as its bound.
    pub fn rounded(k: &Rational) -> Self {
        let value = rational_to_f64(k);
        BoundedF64 {
            value,
            bound: rational_error(k, value),
        }
    }

    /// The double `value` standing for the exact `k`, with the exact distance |k - value| as
    /// its bound (an input number read as its nearest double, say).
    pub fn rounded_from(k: &Rational, value: f64) -> Self {
        BoundedF64 {
            value,
            bound: conversion_error(k, value),
        }
    }

    /// The double, the same as plain `f64` arithmetic computes.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The bound on |exact - value|: finite and >= 0, or +∞ when no finite bound is known
    /// (overflow, NaN, division by an interval containing zero).
    pub fn error_bound(&self) -> f64 {
        if self.bound.is_nan() || self.value.is_nan() {
            f64::INFINITY
        } else {
            self.bound
        }
    }

    /// `value * c` for a double constant `c` whose own error is at most `c_bound`.
    fn times_constant(&self, c: f64, c_bound: f64) -> Self {
        let value = self.value * c;
        let e = self.value.abs() * c_bound
            + c.abs() * self.bound
            + self.bound * c_bound
            + rounding(value);
        BoundedF64 {
            value,
            bound: upward(e),
        }
    }
}

impl PartialEq for BoundedF64 {
    /// Compares the values only (see "Comparisons" in the type's docs).
    fn eq(&self, other: &Self) -> bool {
        self.value == other.value
    }
}

impl PartialOrd for BoundedF64 {
    /// Orders the values only (see "Comparisons" in the type's docs).
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.value.partial_cmp(&other.value)
    }
}

impl fmt::Display for BoundedF64 {
    /// `value ± bound`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ± {:e}", self.value, self.error_bound())
    }
}

/// Every operation but `zero`, `one` and `is_zero` charges the work meter first
/// (`blossom::meter` with the feature `meter`, a no-op unless a meter runs).
impl Ring for BoundedF64 {
    type Coords = Vec<Self>;
    fn zero() -> Self {
        Self::exact(0.0)
    }
    fn one() -> Self {
        Self::exact(1.0)
    }
    fn add(&self, rhs: &Self) -> Self {
        charge_bounded();
        let value = self.value + rhs.value;
        BoundedF64 {
            value,
            bound: upward(self.bound + rhs.bound + rounding(value)),
        }
    }
    fn sub(&self, rhs: &Self) -> Self {
        charge_bounded();
        let value = self.value - rhs.value;
        BoundedF64 {
            value,
            bound: upward(self.bound + rhs.bound + rounding(value)),
        }
    }
    fn mul(&self, rhs: &Self) -> Self {
        charge_bounded();
        let value = self.value * rhs.value;
        let e = self.value.abs() * rhs.bound
            + rhs.value.abs() * self.bound
            + self.bound * rhs.bound
            + rounding(value);
        BoundedF64 {
            value,
            bound: upward(e),
        }
    }
    fn neg(&self) -> Self {
        charge_bounded();
        BoundedF64 {
            value: -self.value,
            bound: self.bound,
        }
    }
    /// `self * k` as `f64` computes it: times the nearest double to k, whose exact conversion
    /// error joins the bound.
    fn scale(&self, k: &Rational) -> Self {
        charge_bounded_constant(k);
        let c = rational_to_f64(k);
        self.times_constant(c, rational_error(k, c))
    }
    /// `self * (num as f64 / den as f64)` as `f64` computes it; the constant's error against
    /// the exact num/den joins the bound.
    fn scale_frac(&self, num: i128, den: i128) -> Self {
        charge_bounded();
        let c = num as f64 / den as f64;
        self.times_constant(c, quotient_error(num, den, c))
    }
    fn is_zero(&self) -> bool {
        self.value == 0.0
    }
    fn from_rational(k: &Rational) -> Self {
        charge_bounded_constant(k);
        // `f64` computes 1.0 * (nearest double to k), which is that double.
        Self::rounded(k)
    }
    fn from_int(k: i64) -> Self {
        charge_bounded();
        let value = k as f64;
        BoundedF64 {
            value,
            bound: quotient_error(k.into(), 1, value),
        }
    }
}

impl Field for BoundedF64 {
    const EXACT: bool = false;
    /// Whether the value is finite (the bound may be infinite: the value still decides).
    fn is_finite(&self) -> bool {
        self.value.is_finite()
    }
    /// `self / rhs` as `f64` computes it; no finite bound when `rhs`'s bound reaches its value.
    fn divide(&self, rhs: &Self) -> Self {
        charge_bounded();
        let value = self.value / rhs.value;
        let divisor = rhs.value.abs();
        // A lower bound of |ŷ| - e_y (the subtraction may round up by a factor 1 + u).
        let margin = (divisor - rhs.bound) * (1.0 - 2.0 * UNIT_ROUNDOFF);
        let bound = if margin > 0.0 {
            let e = (self.bound * divisor + self.value.abs() * rhs.bound) / (divisor * margin)
                + rounding(value);
            upward(e)
        } else {
            f64::INFINITY
        };
        BoundedF64 { value, bound }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    /// |exact - value| for a result computed from exact inputs, against the exact result.
    fn exact_error(x: &BoundedF64, exact: &Rational) -> Rational {
        (exact - Rational::from_f64(x.value()).unwrap()).abs()
    }

    fn within(x: &BoundedF64, exact: &Rational) -> bool {
        let bound = Rational::from_f64(x.error_bound()).unwrap();
        exact_error(x, exact) <= bound
    }

    #[test]
    fn values_are_those_of_plain_f64() {
        let (a, b) = (0.1f64, 0.7f64);
        let (x, y) = (BoundedF64::exact(a), BoundedF64::exact(b));
        assert_eq!(x.add(&y).value(), a + b);
        assert_eq!(x.sub(&y).value(), a - b);
        assert_eq!(x.mul(&y).value(), a * b);
        assert_eq!(x.divide(&y).value(), a / b);
        assert_eq!(x.scale(&q(1, 3)).value(), a.scale(&q(1, 3)));
        assert_eq!(x.scale_frac(2, 7).value(), a.scale_frac(2, 7));
        assert_eq!(
            BoundedF64::from_int(i64::MAX).value(),
            f64::from_int(i64::MAX)
        );
        assert_eq!(x.pow(5).value(), a.pow(5));
    }

    #[test]
    fn bounds_cover_the_exact_error_of_each_operation() {
        let (a, b) = (0.1f64, 0.7f64);
        let (qa, qb) = (exact_value(a).unwrap(), exact_value(b).unwrap());
        let (x, y) = (BoundedF64::exact(a), BoundedF64::exact(b));
        assert!(within(&x.add(&y), &(&qa + &qb)));
        assert!(within(&x.sub(&y), &(&qa - &qb)));
        assert!(within(&x.mul(&y), &(&qa * &qb)));
        assert!(within(&x.divide(&y), &(&qa / &qb)));
        assert!(within(&x.scale(&q(1, 3)), &(&qa * q(1, 3))));
        assert!(within(&x.scale_frac(2, 7), &(&qa * q(2, 7))));
        assert!(within(&BoundedF64::from_rational(&q(1, 3)), &q(1, 3)));
        let big = i64::MAX;
        assert!(within(
            &BoundedF64::from_int(big),
            &Rational::from_integer(big.into())
        ));
        // A long chain: the bound grows but keeps covering the exact error.
        let mut acc = BoundedF64::one();
        let mut exact = q(1, 1);
        for k in 1..200 {
            let t = BoundedF64::from_rational(&q(k, 7));
            acc = acc.mul(&t).add(&x).divide(&y.add(&t));
            exact = (&exact * q(k, 7) + &qa) / (&qb + q(k, 7));
            assert!(within(&acc, &exact), "step {k}");
        }
        assert!(acc.error_bound() < 1e-12, "{}", acc);
    }

    #[test]
    fn exact_operations_keep_a_zero_error_but_not_always_a_zero_bound() {
        let x = BoundedF64::exact(0.5).add(&BoundedF64::exact(0.25));
        assert_eq!(x.value(), 0.75);
        assert!(x.error_bound() > 0.0 && x.error_bound() < 1e-16);
        assert_eq!(BoundedF64::from_rational(&q(3, 4)).error_bound(), 0.0);
    }

    #[test]
    fn division_by_a_divisor_that_may_be_zero_has_no_finite_bound() {
        let y = BoundedF64::with_bound(1e-300, 1e-299);
        assert_eq!(BoundedF64::one().divide(&y).error_bound(), f64::INFINITY);
        let nan = BoundedF64::exact(f64::NAN);
        assert_eq!(nan.add(&BoundedF64::one()).error_bound(), f64::INFINITY);
        assert_eq!(
            BoundedF64::with_bound(1.0, -1.0).error_bound(),
            f64::INFINITY
        );
    }

    #[test]
    fn rational_conversion_is_correctly_rounded() {
        // Big numerators and denominators (the path without the FPU), against the exact error.
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..2000 {
            let limbs = |next: &mut dyn FnMut() -> u64, k: u64| {
                (0..1 + k % 4).fold(BigInt::from(1), |acc, _| acc * BigInt::from(next()) + 1)
            };
            let (a, b) = (next(), next());
            let k = Rational::new(limbs(&mut next, a), limbs(&mut next, b));
            let x = rational_to_f64(&k);
            let bound = rational_error(&k, x);
            assert!(conversion_error(&k, x) <= bound * (1.0 + 1e-9), "{k}");
            // Correct rounding: no double is nearer (the neighbours of the positive x are
            // farther).
            let error = (&k - exact_value(x).unwrap()).abs();
            let neighbours = [
                f64::from_bits(x.to_bits() + 1),
                f64::from_bits(x.to_bits() - 1),
            ];
            for neighbour in neighbours {
                assert!((&k - exact_value(neighbour).unwrap()).abs() >= error, "{k}");
            }
        }
    }

    #[test]
    fn comparisons_see_the_values_only() {
        let x = BoundedF64::with_bound(1.0, 0.5);
        assert_eq!(x, BoundedF64::exact(1.0));
        assert!(x < BoundedF64::exact(2.0));
        assert!(BoundedF64::exact(0.0).is_zero());
    }
}
