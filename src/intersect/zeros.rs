//! Zeros of a polynomial in Bernstein form over [0, 1], with multiplicities: the method,
//! the guarantee and the limits are documented on [`bezier_zeros`], where rustdoc shows them.
//! The same operation is the method `zeros` of a 1-D curve ([`crate::BezierCurve::zeros`],
//! [`crate::Bezier::zeros`]); the free functions stay because they take the coefficients of
//! a function as a plain slice, which need not be a curve the caller holds.

use super::algebraic::{has_no_rational_root, AlgebraicReal};
use super::isolate::{isolate, Isolated};
use super::upoly::{self, mul, sign_at, ZPoly};
use crate::error::{Error, ErrorKind, Result};
use crate::num::exact::exact_values;
use crate::num::ring::Rational;
use crate::shape::basis::bernstein_to_power_flat;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// One distinct zero of a polynomial, exactly: the parameter and its multiplicity. `Display`
/// writes `t = 1/2, multiplicity 2`.
#[derive(Clone, Debug)]
pub struct PolynomialZero {
    /// The zero, exactly.
    pub t: AlgebraicReal,
    /// Its multiplicity as a zero of the polynomial (>= 1).
    pub multiplicity: usize,
}

/// The zeros of a Bézier function over [0, 1], exactly (see [`bezier_zeros`]). `Display`
/// writes one zero per line, or `identically zero`, or `no zero in [0, 1]`.
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

/// Every zero in [0, 1] of the Bézier function f(t) = sum_i b_i B_i^n(t) with Bernstein
/// coefficients `coefficients` = b_0..b_n, **exact**, with multiplicities; both ends 0 and 1
/// included. The method `zeros` of a 1-D curve ([`crate::BezierCurve::zeros`],
/// [`crate::Bezier::zeros`]) is the same.
///
/// Guarantee: every distinct zero is listed once, in increasing order, as an exact
/// [`AlgebraicReal`] (a rational zero is found exactly; an irrational one is a root of a
/// square-free integer polynomial with an isolating interval), with its exact multiplicity.
///
/// Method: the coefficients are turned into power coefficients (exact change of basis),
/// scaled to a primitive integer polynomial p and split by Yun's square-free factorisation
/// p = c f_1 f_2^2 ... f_k^k. The square-free part f_1 f_2 ... f_k is isolated on [0, 1] by
/// Descartes' rule on exact Bernstein coefficients; each isolated root belongs to exactly one
/// f_i (they are pairwise coprime), which gives its multiplicity i and its polynomial.
///
/// Limits: any degree; no budget is enforced here. The cost grows about as n^3 operations
/// on integers of about n + bits bits (bits: the longest coefficient over the common
/// denominator), so bound the degree and the size of the coefficients when the input is
/// not yours (the `blossom` binary refuses degree above 200 and meters the work).
///
/// ```
/// use blossom::{bezier_zeros, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// // f(t) = (2t - 1)^2 (Bernstein coefficients 1, -1, 1): one double zero at 1/2.
/// let z = bezier_zeros(&[q(1, 1), q(-1, 1), q(1, 1)])?;
/// assert_eq!(z.to_string(), "t = 1/2, multiplicity 2");
/// // f(t) = 2t^2 - 1 (coefficients -1, -1, 1): the irrational zero 1/sqrt(2).
/// let z = bezier_zeros(&[q(-1, 1), q(-1, 1), q(1, 1)])?;
/// assert_eq!(z.zeros[0].t.to_f64(), 0.5f64.sqrt());
/// assert_eq!(z.zeros[0].t.polynomial(), [(-1).into(), 0.into(), 2.into()]);
/// # Ok::<(), blossom::Error>(())
/// ```
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

/// [`bezier_zeros`] of doubles, each read exactly (every finite double is a rational): the
/// exact zeros of the function with those coefficients.
///
/// ```
/// use blossom::bezier_zeros_f64;
/// // f(t) = 1 - 3t (coefficients 1, -2): its zero 1/3, exactly, though 1/3 is no double.
/// let z = bezier_zeros_f64(&[1.0, -2.0])?;
/// assert_eq!(z.zeros[0].t.to_string(), "1/3");
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `coefficients[i]` for a NaN or an infinity, and as
/// [`bezier_zeros`].
pub fn bezier_zeros_f64(coefficients: &[f64]) -> Result<BezierZeros> {
    bezier_zeros(&exact_values("coefficients", coefficients)?)
}
