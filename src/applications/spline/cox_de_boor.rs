//! The normalised B-splines N_i^p by their recursive definition (Definition 1.1 of seed 002),
//! as polynomials on each span, and the power-basis pieces of a B-spline curve from them:
//!
//! N_i^0(u) = 1 on [t_i, t_{i+1}), 0 elsewhere;
//! N_i^r(u) = (u - t_i) / (t_{i+r} - t_i) N_i^{r-1}(u) + (t_{i+r+1} - u) / (t_{i+r+1} - t_{i+1}) N_{i+1}^{r-1}(u),
//!
//! with 0/0 = 0. This is independent of de Boor's algorithm and of blossoms, which makes it a
//! cross-check for both: F_s = sum_k d_k N_k^p on the span s, written in the power basis of u.

use super::bspline::BSpline;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::{check_all_finite, Field};
use crate::shape::point::{self, Point};
use crate::shape::power::PowerCurve;

/// A univariate polynomial as coefficients of 1, u, u^2, ...
type Coeffs<T> = Vec<T>;

/// `f * (a + b u)`, with `f` of length at most `len - 1`, padded to `len`.
fn times_linear<T: Field>(f: &[T], a: &T, b: &T, len: usize) -> Coeffs<T> {
    let mut out = vec![T::zero(); len];
    for (k, c) in f.iter().enumerate() {
        out[k].add_assign(&a.mul(c));
        if k + 1 < len {
            out[k + 1].add_assign(&b.mul(c));
        }
    }
    out
}

/// The polynomials N_i^p restricted to the span `[knots[s], knots[s+1])`, for i = s - p..=s
/// (0-based), in the power basis of u.
///
/// # Errors
/// [`ErrorKind::Domain`] on `s` unless p <= s and s + p + 1 < `knots.len()` (the knots
/// t_(s-p)..t_(s+p+1) the recursion reads); [`ErrorKind::NotFinite`] on `knots[i]` for a NaN
/// or an infinity (a zero test on knot differences decides each term).
pub fn bspline_basis_on_span<T: Field>(knots: &[T], p: usize, s: usize) -> Result<Vec<Coeffs<T>>> {
    let end = s.checked_add(p).and_then(|k| k.checked_add(1));
    let fits = s >= p && end.is_some_and(|k| k < knots.len());
    if !fits {
        return Err(Error::of(
            ErrorKind::Domain,
            "s",
            format!(
                "the span {s} of degree {p} needs p <= s and s + p + 1 < {} knots",
                knots.len()
            ),
        ));
    }
    check_all_finite(knots, "knots")?;
    Ok(basis_on_span(knots, p, s))
}

/// [`bspline_basis_on_span`] on a span known to fit finite knots.
fn basis_on_span<T: Field>(knots: &[T], p: usize, s: usize) -> Vec<Coeffs<T>> {
    let len = p + 1;
    // level[i - (s - r)] = N_i^r on the span, for i = s - r..=s.
    let mut level: Vec<Coeffs<T>> = vec![{
        let mut one = vec![T::zero(); len];
        one[0] = T::one();
        one
    }];
    for r in 1..=p {
        let lo = s - r;
        let next = (lo..=s)
            .map(|i| {
                let mut acc = vec![T::zero(); len];
                // (u - t_i) / (t_{i+r} - t_i) N_i^{r-1}, present for i >= s - r + 1.
                if i > lo {
                    let den = knots[i + r].sub(&knots[i]);
                    if !den.is_zero() {
                        let f = &level[i - (lo + 1)];
                        let b = T::one().divide(&den);
                        let a = knots[i].neg().mul(&b);
                        add_into(&mut acc, &times_linear(f, &a, &b, len));
                    }
                }
                // (t_{i+r+1} - u) / (t_{i+r+1} - t_{i+1}) N_{i+1}^{r-1}, present for i + 1 <= s.
                if i < s {
                    let den = knots[i + r + 1].sub(&knots[i + 1]);
                    if !den.is_zero() {
                        let f = &level[i + 1 - (lo + 1)];
                        let b = T::one().divide(&den).neg();
                        let a = knots[i + r + 1].mul(&b).neg();
                        add_into(&mut acc, &times_linear(f, &a, &b, len));
                    }
                }
                acc
            })
            .collect();
        level = next;
    }
    level
}

fn add_into<T: Field>(acc: &mut [T], f: &[T]) {
    for (x, y) in acc.iter_mut().zip(f) {
        x.add_assign(y);
    }
}

/// One polynomial piece of a spline in the power basis of the global parameter u.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(
        deny_unknown_fields,
        bound(
            serialize = "T: crate::Ring + serde::Serialize",
            deserialize = "T: crate::Ring + serde::Deserialize<'de>"
        )
    )
)]
pub struct PowerPiece<T> {
    /// The interval [a, b] where the piece is the curve.
    pub interval: [T; 2],
    /// F(u) = sum_i c_i u^i on the interval, of degree p.
    pub curve: PowerCurve<T>,
}

impl<T: Field> BSpline<T> {
    /// The pieces F_s = sum_k d_k N_k^p on every non-empty domain span, in the power basis, by
    /// the recursive definition of the N_k^p (Definition 1.1), not by blossoms.
    pub fn power_pieces(&self) -> Result<Vec<PowerPiece<T>>> {
        let p = self.degree();
        let t = self.knots();
        let d = self.control_points();
        self.knot_vector()
            .spans()
            .into_iter()
            .map(|s| {
                let basis = basis_on_span(t, p, s);
                let coefficients: Vec<Point<T>> = (0..=p)
                    .map(|e| {
                        let mut c = point::zero::<T>(self.dim());
                        for (n, dk) in basis.iter().zip(d.slice(s - p..s + 1)) {
                            point::add_scaled(&mut c, &n[e], dk);
                        }
                        c
                    })
                    .collect();
                Ok(PowerPiece {
                    interval: [t[s].clone(), t[s + 1].clone()],
                    curve: PowerCurve::new(coefficients)?,
                })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    #[test]
    fn bernstein_basis_on_a_clamped_span() {
        // Knots 0,0,0,1,1,1: N_0^2 = (1-u)^2, N_1^2 = 2u(1-u), N_2^2 = u^2.
        let knots = [0, 0, 0, 1, 1, 1].map(q);
        let b = bspline_basis_on_span(&knots, 2, 2).unwrap();
        assert_eq!(
            b,
            vec![
                vec![q(1), q(-2), q(1)],
                vec![q(0), q(2), q(-2)],
                vec![q(0), q(0), q(1)]
            ]
        );
    }

    #[test]
    fn partition_of_unity_on_uniform_knots() {
        let knots: Vec<Rational> = (0..10).map(q).collect();
        for s in 3..6 {
            let b = bspline_basis_on_span(&knots, 3, s).unwrap();
            let mut sum = vec![q(0); 4];
            for f in &b {
                add_into(&mut sum, f);
            }
            assert_eq!(sum, vec![q(1), q(0), q(0), q(0)], "span {s}");
        }
    }
}
