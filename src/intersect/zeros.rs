//! Zeros of a polynomial in Bernstein form over [0, 1], with multiplicities.
//!
//! The Bernstein coefficients b_0..b_n (exact rationals) are turned into power coefficients
//! by the library's [`bernstein_to_power_flat`], scaled to a primitive integer polynomial p, and
//! split by Yun's square-free factorisation p = c f_1 f_2^2 ... f_k^k. The square-free part
//! f_1 f_2 ... f_k is isolated on [0, 1] by Descartes' rule (see `isolate`); each isolated
//! root belongs to exactly one f_i (they are pairwise coprime), which gives its multiplicity
//! i and the polynomial of its [`AlgebraicReal`]. Both ends 0 and 1 are included.

use super::algebraic::{has_no_rational_root, AlgebraicReal};
use super::isolate::{isolate, Isolated};
use super::upoly::{self, mul, sign_at, ZPoly};
use crate::error::{Error, ErrorKind, Result};
use crate::num::ring::Rational;
use crate::shape::basis::bernstein_to_power_flat;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// One distinct zero of a polynomial: the parameter and its multiplicity.
#[derive(Clone, Debug)]
pub struct PolynomialZero {
    /// The zero, exactly.
    pub t: AlgebraicReal,
    /// Its multiplicity as a zero of the polynomial (>= 1).
    pub multiplicity: usize,
}

/// The zeros of a Bézier function over [0, 1].
#[derive(Clone, Debug)]
pub struct BezierZeros {
    /// Whether the function is zero everywhere (then `zeros` is empty).
    pub identically_zero: bool,
    /// Every distinct zero in [0, 1], in increasing order.
    pub zeros: Vec<PolynomialZero>,
}

/// An isolated root of a polynomial with its multiplicity and an open neighbourhood (lo, hi)
/// holding no other root of the polynomial (used to match roots found by other means).
#[derive(Clone, Debug)]
pub(crate) struct RootInfo {
    pub value: AlgebraicReal,
    pub multiplicity: usize,
    pub nbhd: (Rational, Rational),
}

/// The distinct real roots of the non-zero integer polynomial `p` in [a, b] (a < b), in
/// increasing order, with multiplicities and isolating neighbourhoods.
pub(crate) fn roots_with_multiplicity(p: &[BigInt], a: &Rational, b: &Rational) -> Vec<RootInfo> {
    let factors = upoly::square_free_factors(p);
    if factors.is_empty() {
        return Vec::new();
    }
    let mut sqfree: ZPoly = vec![BigInt::one()];
    for (f, _) in &factors {
        sqfree = mul(&sqfree, f);
    }
    let isolated = isolate(&sqfree, a, b);
    let owners: Vec<usize> = isolated
        .iter()
        .map(|iso| {
            factors
                .iter()
                .position(|(f, _)| holds_root(f, iso))
                .expect("every root of the square-free part is a root of one factor")
        })
        .collect();
    // The rational roots a short search finds are divided out of their factor first: the
    // factor's other roots are then settled irrational by the modular test at once, where a
    // rational root (an end point of a curve, say) would make them refine to 1 / lc(f)^2.
    // A factor without a root modulo some small prime has no rational root at all (most
    // factors of a resultant of random curves): its roots skip the search.
    let may_be_rational: Vec<bool> = factors
        .iter()
        .map(|(f, _)| !has_no_rational_root(f))
        .collect();
    let rational: Vec<Option<Rational>> = isolated
        .iter()
        .zip(&owners)
        .map(|(iso, &i)| {
            if iso.exact || may_be_rational[i] {
                AlgebraicReal::quick_rational_root(&factors[i].0, iso)
            } else {
                None
            }
        })
        .collect();
    let mut deflated: Vec<ZPoly> = factors.iter().map(|(f, _)| f.clone()).collect();
    for (r, &i) in rational.iter().zip(&owners) {
        if let Some(r) = r {
            let linear = AlgebraicReal::from_rational(r.clone());
            deflated[i] = upoly::exact_div(&deflated[i], linear.polynomial())
                .expect("a rational root's primitive linear factor divides the integer factor");
        }
    }
    let mut out: Vec<RootInfo> = Vec::with_capacity(isolated.len());
    for (k, iso) in isolated.iter().enumerate() {
        let multiplicity = factors[owners[k]].1;
        let nbhd = if iso.exact {
            let lo = if k > 0 {
                isolated[k - 1].hi.clone()
            } else {
                a.clone()
            };
            let hi = match isolated.get(k + 1) {
                Some(next) => next.lo.clone(),
                None => b.clone(),
            };
            (lo, hi)
        } else {
            (iso.lo.clone(), iso.hi.clone())
        };
        let value = match &rational[k] {
            Some(r) => AlgebraicReal::from_rational(r.clone()),
            None => AlgebraicReal::from_isolated(&deflated[owners[k]], iso),
        };
        out.push(RootInfo {
            value,
            multiplicity,
            nbhd,
        });
    }
    out
}

/// Whether the root isolated by `iso` is a root of the square-free divisor `f`.
fn holds_root(f: &[BigInt], iso: &Isolated) -> bool {
    if iso.exact {
        sign_at(f, &iso.lo) == Ordering::Equal
    } else {
        sign_at(f, &iso.lo) != sign_at(f, &iso.hi)
    }
}

/// Every zero in [0, 1] of the Bézier function with Bernstein coefficients `coefficients`
/// over [0, 1], exactly, with multiplicities (see the module docs).
///
/// # Errors
/// [`ErrorKind::Empty`] on `coefficients` when there are none.
pub fn bezier_zeros(coefficients: &[Rational]) -> Result<BezierZeros> {
    if coefficients.is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            "coefficients",
            "expected at least one coefficient",
        ));
    }
    let p = upoly::from_rationals(&power_coefficients(coefficients));
    if p.is_empty() {
        return Ok(BezierZeros {
            identically_zero: true,
            zeros: Vec::new(),
        });
    }
    let zeros = roots_with_multiplicity(&p, &Rational::zero(), &Rational::one())
        .into_iter()
        .map(|r| PolynomialZero {
            t: r.value,
            multiplicity: r.multiplicity,
        })
        .collect();
    Ok(BezierZeros {
        identically_zero: false,
        zeros,
    })
}

/// The power coefficients a_0..a_n (ascending) of the Bézier function with Bernstein
/// coefficients `coefficients` over [0, 1]: sum b_i B_i^n(t) = sum a_k t^k, exactly.
pub(crate) fn power_coefficients(coefficients: &[Rational]) -> Vec<Rational> {
    let mut power = coefficients.to_vec();
    bernstein_to_power_flat(&mut power, 1);
    power
}

/// [`bezier_zeros`] of doubles, each read exactly (every finite double is a rational).
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `coefficients[i]` for a NaN or an infinity, and as
/// [`bezier_zeros`].
pub fn bezier_zeros_f64(coefficients: &[f64]) -> Result<BezierZeros> {
    let exact = rationals_of("coefficients", coefficients)?;
    bezier_zeros(&exact)
}

/// Doubles read exactly as rationals, NaN and infinities refused naming `field[i]`.
pub(crate) fn rationals_of(field: &str, values: &[f64]) -> Result<Vec<Rational>> {
    values
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            Rational::from_float(x).ok_or_else(|| {
                Error::of(
                    ErrorKind::NotFinite,
                    format!("{field}[{i}]"),
                    format!("expected a finite number, found {x}"),
                )
            })
        })
        .collect()
}
