//! The one number trait of the crate: a commutative ring with multiplication by exact rational
//! constants.
//!
//! Every algorithm of the crate is written once against [`Ring`]. Three families implement it:
//! `f64`/`f32` (fast, rounded), [`Rational`] (exact, unbounded), and
//! [`Poly`](crate::Poly) (symbolic: exact polynomials in named variables, used to *prove* that
//! two algorithms agree for every input of a given degree).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt::Debug;

use super::meter::{charge_rational, charge_rational_sum};

/// Zero, the second operand of the charge of a one-operand operation.
const ZERO: Rational = Rational::ZERO;

/// Exact rational numbers with unbounded numerator and denominator: num-rational's
/// `BigRational`, under this name.
///
/// Being a type alias, it has num-rational's `FromStr`, which reads integers and fractions
/// (`"-7"`, `"3/4"`) but no decimal: `"0.25".parse::<Rational>()` fails, and this crate cannot
/// change that. Read numbers written as text with [`parse_rational`](crate::parse_rational),
/// which takes integers, fractions and finite decimals with exponents exactly (`"0.25"` is
/// 1/4, `"-1e-3"` is -1/1000), with an error naming the kind of problem otherwise.
///
/// ```
/// use blossom::{parse_rational, Rational};
/// assert!("0.25".parse::<Rational>().is_err());
/// assert_eq!(parse_rational("0.25")?, Rational::new(1.into(), 4.into()));
/// assert_eq!("3/4".parse::<Rational>().ok(), parse_rational("3/4").ok());
/// # Ok::<(), blossom::Error>(())
/// ```
pub type Rational = BigRational;

/// A commutative ring with unit, plus multiplication by an exact rational constant.
///
/// The operations take their operands by reference so that big numbers and polynomials are
/// not cloned needlessly. Implementations must satisfy the ring axioms exactly (`Rational`,
/// `Poly`) or up to rounding (`f64`, `f32`).
pub trait Ring: Clone + PartialEq + Debug {
    /// Whether the compile-time unrolled evaluators pay for this type: `true` for the
    /// hardware floats (`f64`, `f32`), whose steps the unrolled code keeps in registers;
    /// `false` (the default) for every other ring, whose operations (allocation, big-integer
    /// arithmetic) dwarf what unrolling saves. Code that dispatches to the unrolled
    /// evaluators tests this constant first, so they are instantiated only for the types
    /// that set it: the branch is decided when a generic function is instantiated, and the
    /// unrolled functions are not even compiled for the others (the answer is the same bit
    /// for bit either way: the unrolled code runs the engine's steps in the engine's order).
    const UNROLLED: bool = false;
    /// The buffer a [`crate::BezierCurve`] of this type keeps its coordinates in: a
    /// [`Vec<Self>`] for every ring but the hardware floats, whose small curves are kept
    /// inline ([`crate::engine::SmallCoords`]) so that returning a new curve allocates nothing.
    /// A ring defined outside this crate sets `type Coords = Vec<Self>;`.
    type Coords: crate::engine::CoordinateBuffer<Self>;
    /// `out` = the control points of the Bézier curve with flat control points `points` (`dim`
    /// numbers per point) over [a, b] by the unrolled evaluators of the types that set
    /// [`Ring::UNROLLED`], or `false` (and `out` untouched) when there is none for this
    /// degree and dimension; the caller then runs the engine. The unrolled evaluators give the
    /// engine's answer bit for bit.
    /// The default has none; `f64` and `f32` have them for degrees 1..=8 in dimensions
    /// 1..=4 (1..=24 with the feature `unrolled-high`), in functions that are compiled once,
    /// in this crate, rather than in every crate that restricts a float curve, and beyond
    /// those, on intervals inside [0, 1], the two de Casteljau subdivisions of
    /// `shape/two_pass.rs` (the same curve, rounded differently: not the engine's bits).
    fn restrict_unrolled(
        points: &[Self],
        dim: usize,
        a: &Self,
        b: &Self,
        out: &mut [Self],
    ) -> bool {
        let _ = (points, dim, a, b, out);
        false
    }
    /// Runs `work` with a scratch buffer for the engine: for the hardware floats a buffer of
    /// this thread, reused from call to call (so that the forms that return a new shape
    /// allocate only their answer), for every other ring a fresh one (whose numbers allocate
    /// anyway). The buffer's contents on entry are unspecified; the engine only writes before
    /// it reads.
    fn with_scratch<R>(work: impl FnOnce(&mut Vec<Self>) -> R) -> R {
        work(&mut Vec::new())
    }
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// `self + rhs`.
    fn add(&self, rhs: &Self) -> Self;
    /// `self - rhs`.
    fn sub(&self, rhs: &Self) -> Self;
    /// `self * rhs`.
    fn mul(&self, rhs: &Self) -> Self;
    /// `-self`.
    fn neg(&self) -> Self;
    /// `self * k` for an exact rational constant `k`.
    fn scale(&self, k: &Rational) -> Self;
    /// `self * num / den` for a small constant; `den` must be non-zero.
    ///
    /// Generated code calls this with literals, so for floats it folds to one multiplication.
    fn scale_frac(&self, num: i128, den: i128) -> Self {
        self.scale(&Rational::new(BigInt::from(num), BigInt::from(den)))
    }
    /// Whether `self` is exactly zero.
    fn is_zero(&self) -> bool;
    /// `self += rhs`.
    fn add_assign(&mut self, rhs: &Self) {
        *self = self.add(rhs);
    }
    /// The image of an exact rational number in the ring.
    fn from_rational(k: &Rational) -> Self {
        Self::one().scale(k)
    }
    /// The image of an integer in the ring.
    fn from_int(k: i64) -> Self {
        Self::from_rational(&Rational::from_integer(BigInt::from(k)))
    }
    /// `self^e` by repeated squaring (`self^0 = 1`).
    fn pow(&self, mut e: u32) -> Self {
        let mut base = self.clone();
        let mut acc = Self::one();
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.mul(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.mul(&base);
            }
        }
        acc
    }
}

/// Converts an exact rational to the nearest `f64` (infinite when out of range).
pub fn rational_to_f64(k: &Rational) -> f64 {
    k.to_f64().unwrap_or_else(|| {
        if k.is_negative() {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        }
    })
}

macro_rules! float_ring {
    ($(#[$doc:meta])* $t:ty => $evaluators:path, $two_pass:path) => {
        $(#[$doc])*
        impl Ring for $t {
            const UNROLLED: bool = true;
            type Coords = crate::engine::SmallCoords<Self, { crate::engine::INLINE_COORDINATES }>;
            fn with_scratch<R>(work: impl FnOnce(&mut Vec<Self>) -> R) -> R {
                thread_local! {
                    static SCRATCH: std::cell::RefCell<Vec<$t>> =
                        const { std::cell::RefCell::new(Vec::new()) };
                }
                // A fresh buffer when this thread's is in use already (`work` calling back).
                SCRATCH.with(|cell| match cell.try_borrow_mut() {
                    Ok(mut scratch) => work(&mut scratch),
                    Err(_) => work(&mut Vec::new()),
                })
            }
            #[inline]
            fn restrict_unrolled(points: &[Self], dim: usize, a: &Self, b: &Self, out: &mut [Self]) -> bool {
                $evaluators.restrict(points, dim, a, b, out)
                    || $two_pass(points, dim, *a, *b, out)
            }
            #[inline]
            fn zero() -> Self {
                0.0
            }
            #[inline]
            fn one() -> Self {
                1.0
            }
            #[inline]
            fn add(&self, rhs: &Self) -> Self {
                self + rhs
            }
            #[inline]
            fn sub(&self, rhs: &Self) -> Self {
                self - rhs
            }
            #[inline]
            fn mul(&self, rhs: &Self) -> Self {
                self * rhs
            }
            #[inline]
            fn neg(&self) -> Self {
                -self
            }
            #[inline]
            fn scale(&self, k: &Rational) -> Self {
                self * (rational_to_f64(k) as $t)
            }
            #[inline]
            fn scale_frac(&self, num: i128, den: i128) -> Self {
                self * ((num as f64 / den as f64) as $t)
            }
            #[inline]
            fn is_zero(&self) -> bool {
                *self == 0.0
            }
            #[inline]
            fn add_assign(&mut self, rhs: &Self) {
                *self += rhs;
            }
            #[inline]
            fn from_int(k: i64) -> Self {
                k as $t
            }
        }
    };
}

float_ring!(
    /// Doubles: every operation rounded once (`scale` multiplies by the constant rounded to
    /// the nearest double). `docs/accuracy.md` and `docs/error_bounds.md` give
    /// the measured errors of every method.
    f64 => crate::shape::unrolled::F64, crate::shape::two_pass::restrict_f64
);
float_ring!(
    /// Single precision: every operation rounded once, with unit roundoff u = 2^-24 ≈ 6.0e-8
    /// (`scale` rounds the constant to a double, then to the nearest `f32`).
    ///
    /// Restriction in `f32` keeps 6 to 7 digits: on random 3-D curves of degree 3 to 16, on
    /// sub-intervals of [0, 1] and on [-1, 2], the error max |got - exact| / max |exact| against
    /// the exact answer on the same `f32` inputs stays within 150 n u at degree n (asserted by
    /// `tests/suite/applications/f32_accuracy.rs`; the measured table is in `docs/error_bounds.md`,
    /// section "f32", printed by
    /// `cargo test -p blossom --test suite f32_restriction -- --nocapture`).
    f32 => crate::shape::unrolled::F32, crate::shape::two_pass::restrict_f32
);

/// Every operation but `zero`, `one` and `is_zero` charges the work meter first
/// (`blossom::meter` with the feature `meter`, a no-op unless a meter runs).
impl Ring for Rational {
    type Coords = Vec<Self>;
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn add(&self, rhs: &Self) -> Self {
        charge_rational_sum(self, rhs);
        self + rhs
    }
    fn sub(&self, rhs: &Self) -> Self {
        charge_rational_sum(self, rhs);
        self - rhs
    }
    fn mul(&self, rhs: &Self) -> Self {
        charge_rational(self, rhs);
        self * rhs
    }
    fn neg(&self) -> Self {
        charge_rational_sum(self, &ZERO);
        -self
    }
    fn scale(&self, k: &Rational) -> Self {
        charge_rational(self, k);
        self * k
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn add_assign(&mut self, rhs: &Self) {
        charge_rational_sum(self, rhs);
        *self += rhs;
    }
    fn from_rational(k: &Rational) -> Self {
        charge_rational_sum(k, &ZERO);
        k.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn rational_ring_is_exact() {
        let x = q(1, 3);
        let y = q(1, 6);
        assert_eq!(x.add(&y), q(1, 2));
        assert_eq!(x.sub(&y), q(1, 6));
        assert_eq!(x.mul(&y), q(1, 18));
        assert_eq!(x.neg(), q(-1, 3));
        assert_eq!(x.scale_frac(3, 2), q(1, 2));
        assert_eq!(q(2, 3).pow(3), q(8, 27));
        assert_eq!(q(2, 3).pow(0), q(1, 1));
        assert!(Ring::is_zero(&x.sub(&x)));
    }

    #[test]
    fn float_ring_matches_native_arithmetic() {
        assert_eq!(2.5f64.scale(&q(2, 5)), 1.0);
        assert_eq!(3.0f64.scale_frac(-1, 3), -1.0);
        assert_eq!(1.5f64.pow(2), 2.25);
        assert_eq!(f32::from_int(-7), -7.0);
        assert_eq!(rational_to_f64(&q(1, 4)), 0.25);
    }
}
