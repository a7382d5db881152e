//! [`Scalar`]: the one ring the carried grid is instantiated with.
//!
//! The generated evaluators are generic over [`Ring`]; instantiating the whole grid once per
//! number type (f64, exact rationals, symbolic polynomials) would compile it three times. The
//! dispatch instead wraps every number type in `Scalar` and instantiates each evaluator once.
//! The price is a `match` and a call per ring operation, which only the command line and the
//! proofs pay: code that knows its number type and dimension at compile time calls the
//! generated functions directly (see [`crate::grid`]) or generates its own with the macro.
//!
//! The operations are kept out of line (`#[inline(never)]`): a generated evaluator is one long
//! straight-line function, and inlining arithmetic into each of its thousands of call sites
//! makes its build superlinear.
//!
//! Constants: generated code builds constants from [`Ring::one`] (e.g. `T::one().scale_frac(1,
//! 2)`), which cannot know the caller's number type, so they are [`Scalar::Exact`]. An operation
//! on two variants promotes the exact operand to the other's type (exact < f64, exact <
//! symbolic, exact < bounded double), the way an untyped literal takes the type of the expression
//! it appears in; every combination is defined, none panics. An exact constant promoted to a
//! double is its nearest double, as `f64` arithmetic makes it, so that a [`Scalar::Bounded`]
//! computation has exactly the values of the [`Scalar::F64`] one; a plain double meeting a
//! bounded one (never produced by one job) is taken as exact.

use blossom::rational_to_f64;
use blossom::{BoundedF64, Poly, Rational, Ring};
use num_traits::FromPrimitive;

/// A number of one of the crate's number types.
#[derive(Clone, PartialEq, Debug)]
pub enum Scalar {
    /// An exact rational: an input in exact arithmetic, or a constant of the generated code.
    Exact(Rational),
    /// A double.
    F64(f64),
    /// A double with a bound on its rounding error ([`BoundedF64`]).
    Bounded(BoundedF64),
    /// A symbolic polynomial.
    Symbolic(Poly),
}

/// A number type that the carried grid runs on: wrapped in and unwrapped from [`Scalar`].
pub trait Carried: Ring {
    /// `self` as a scalar.
    fn wrap(&self) -> Scalar;
    /// The value of `s` in this type (exact constants are converted).
    fn unwrap(s: Scalar) -> Self;
}

impl Carried for f64 {
    fn wrap(&self) -> Scalar {
        Scalar::F64(*self)
    }
    fn unwrap(s: Scalar) -> f64 {
        match s {
            Scalar::F64(x) => x,
            Scalar::Bounded(x) => x.value(),
            Scalar::Exact(k) => rational_to_f64(&k),
            // Never produced from f64 inputs; the constant term is the only value it can have.
            Scalar::Symbolic(p) => rational_to_f64(&p.constant_term()),
        }
    }
}

impl Carried for Rational {
    fn wrap(&self) -> Scalar {
        Scalar::Exact(self.clone())
    }
    fn unwrap(s: Scalar) -> Rational {
        match s {
            Scalar::Exact(k) => k,
            // Never produced from exact inputs; converted exactly when they are.
            Scalar::F64(x) => exact(x),
            Scalar::Bounded(x) => exact(x.value()),
            Scalar::Symbolic(p) => p.constant_term(),
        }
    }
}

impl Carried for Poly {
    fn wrap(&self) -> Scalar {
        Scalar::Symbolic(self.clone())
    }
    fn unwrap(s: Scalar) -> Poly {
        match s {
            Scalar::Symbolic(p) => p,
            Scalar::Exact(k) => Poly::constant(k),
            Scalar::F64(x) => Poly::constant(exact(x)),
            Scalar::Bounded(x) => Poly::constant(exact(x.value())),
        }
    }
}

impl Carried for BoundedF64 {
    fn wrap(&self) -> Scalar {
        Scalar::Bounded(*self)
    }
    fn unwrap(s: Scalar) -> BoundedF64 {
        match s {
            Scalar::Bounded(x) => x,
            Scalar::Exact(k) => BoundedF64::rounded(&k),
            // Never produced from bounded inputs; a plain double is taken as exact.
            Scalar::F64(x) => BoundedF64::exact(x),
            Scalar::Symbolic(p) => BoundedF64::rounded(&p.constant_term()),
        }
    }
}

/// The exact value of a finite double (zero for a non-finite one, which has no exact value).
fn exact(x: f64) -> Rational {
    Rational::from_f64(x).unwrap_or_default()
}

/// Applies `op` after promoting both operands to a common type.
fn promote(
    lhs: &Scalar,
    rhs: &Scalar,
    exact_op: fn(&Rational, &Rational) -> Rational,
    f64_op: fn(&f64, &f64) -> f64,
    bounded_op: fn(&BoundedF64, &BoundedF64) -> BoundedF64,
    poly_op: fn(&Poly, &Poly) -> Poly,
) -> Scalar {
    use Scalar::{Bounded, Exact, Symbolic, F64};
    match (lhs, rhs) {
        (Exact(x), Exact(y)) => Exact(exact_op(x, y)),
        (F64(x), F64(y)) => F64(f64_op(x, y)),
        (Bounded(x), Bounded(y)) => Bounded(bounded_op(x, y)),
        (Symbolic(x), Symbolic(y)) => Symbolic(poly_op(x, y)),
        (F64(x), Exact(y)) => F64(f64_op(x, &rational_to_f64(y))),
        (Exact(x), F64(y)) => F64(f64_op(&rational_to_f64(x), y)),
        (Bounded(_), Exact(_) | F64(_)) | (Exact(_) | F64(_), Bounded(_)) => Bounded(bounded_op(
            &BoundedF64::unwrap(lhs.clone()),
            &BoundedF64::unwrap(rhs.clone()),
        )),
        (Symbolic(_), _) | (_, Symbolic(_)) => Symbolic(poly_op(
            &Poly::unwrap(lhs.clone()),
            &Poly::unwrap(rhs.clone()),
        )),
    }
}

impl Ring for Scalar {
    type Coords = Vec<Self>;
    fn zero() -> Self {
        Scalar::Exact(<Rational as Ring>::zero())
    }
    fn one() -> Self {
        Scalar::Exact(<Rational as Ring>::one())
    }
    #[inline(never)]
    fn add(&self, rhs: &Self) -> Self {
        promote(self, rhs, Ring::add, Ring::add, Ring::add, Ring::add)
    }
    #[inline(never)]
    fn sub(&self, rhs: &Self) -> Self {
        promote(self, rhs, Ring::sub, Ring::sub, Ring::sub, Ring::sub)
    }
    #[inline(never)]
    fn mul(&self, rhs: &Self) -> Self {
        promote(self, rhs, Ring::mul, Ring::mul, Ring::mul, Ring::mul)
    }
    #[inline(never)]
    fn neg(&self) -> Self {
        match self {
            Scalar::Exact(x) => Scalar::Exact(x.neg()),
            Scalar::F64(x) => Scalar::F64(-x),
            Scalar::Bounded(x) => Scalar::Bounded(x.neg()),
            Scalar::Symbolic(x) => Scalar::Symbolic(x.neg()),
        }
    }
    #[inline(never)]
    fn scale(&self, k: &Rational) -> Self {
        match self {
            Scalar::Exact(x) => Scalar::Exact(x.scale(k)),
            Scalar::F64(x) => Scalar::F64(x.scale(k)),
            Scalar::Bounded(x) => Scalar::Bounded(x.scale(k)),
            Scalar::Symbolic(x) => Scalar::Symbolic(x.scale(k)),
        }
    }
    #[inline(never)]
    fn scale_frac(&self, num: i128, den: i128) -> Self {
        match self {
            Scalar::Exact(x) => Scalar::Exact(x.scale_frac(num, den)),
            Scalar::F64(x) => Scalar::F64(x.scale_frac(num, den)),
            Scalar::Bounded(x) => Scalar::Bounded(x.scale_frac(num, den)),
            Scalar::Symbolic(x) => Scalar::Symbolic(x.scale_frac(num, den)),
        }
    }
    #[inline(never)]
    fn is_zero(&self) -> bool {
        match self {
            Scalar::Exact(x) => Ring::is_zero(x),
            Scalar::F64(x) => Ring::is_zero(x),
            Scalar::Bounded(x) => Ring::is_zero(x),
            Scalar::Symbolic(x) => Ring::is_zero(x),
        }
    }
}
