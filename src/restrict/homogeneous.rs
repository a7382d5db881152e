//! Theorem 1 of seed 004, eq. (18): the symmetric n-*linear* form f of a homogeneous n-atic
//! form q on a linear space, from values of q alone,
//!
//! f(x_1..x_n) = 1/n! sum_{N=1..n} (-1)^(n-N) sum_{i_1 < ... < i_N} q(x_i1 + ... + x_iN),   (18)
//!
//! where q(x) = f(x, ..., x) (eq. (14)) is homogeneous of degree n, q(lambda x) = lambda^n q(x)
//! (eq. (15)). Unlike Theorem 2, eq. (19) ([`crate::polar_form`]), q is evaluated at *sums* of
//! the arguments, not at their averages, so (18) needs a linear space and a homogeneous q.
//!
//! The blossom of a polynomial curve C(t) = sum c_i t^i of degree n is reached through its
//! homogenisation Q(t, s) = s^n C(t / s) = sum c_i t^i s^(n-i), a homogeneous form of degree n
//! on R^2 whose multilinear polar form F satisfies b(t_1..t_n) = F((t_1, 1), .., (t_n, 1)):
//! with every x_k = (t_k, 1), a sum of N arguments is (t_i1 + .. + t_iN, N) = N ((t_i1 + .. +
//! t_iN) / N, 1), and homogeneity turns Q of it into N^n C((t_i1 + .. + t_iN) / N), which is
//! eq. (19) (the substitution the paper describes after Theorem 1). Surfaces as triangular
//! patches of total degree N are homogenised in three variables, Q(u, v, w) = sum c_ij u^i
//! v^j w^(N-i-j), and sampled at (u_k, v_k, 1).
//!
//! Every non-empty subset is visited once (2^n - 1 values of q), with no grouping of repeated
//! arguments: this module is the literal formula, kept apart from the grouped, affine (19).

use crate::error::{check_arity, Error, ErrorKind, Result};
use crate::num::binomial::binomial;
use crate::shape::point::{self, Point};
use crate::shape::power::{check_dims, PowerCurve, PowerSurface};
use crate::{Rational, Ring};
use num_bigint::BigInt;

/// Why the points given to `q` have the length of the homogenised space:
/// [`multilinear_polar_form`] checks the dimension of its arguments, and calls `q` only at
/// sums of them.
const TWO_OR_THREE: &str = "sums of arguments of the checked dimension";

/// The largest degree (18) is evaluated at: 2^n - 1 values of q.
pub const MAX_MULTILINEAR_DEGREE: usize = 24;

/// The symmetric n-linear form f(x_1..x_n) of the homogeneous n-atic form `q` on a linear space
/// of dimension `dim` (points `Vec<T>`), by Theorem 1, eq. (18) of seed 004.
///
/// `q` must be homogeneous of degree `n` for the result to be its polar form. Fails when
/// `args.len() != n` (`args`), when an argument does not have `dim` coordinates (`args[k]`),
/// or when `n` exceeds [`MAX_MULTILINEAR_DEGREE`] (`n`). For `n = 0` the form is the constant
/// `q(0)`.
///
/// ```
/// use blossom::{multilinear_polar_form, Rational, Ring};
/// // q(x, y) = x y on R^2 is the diagonal of f((x1, y1), (x2, y2)) = (x1 y2 + x2 y1) / 2.
/// let q = |p: &[Rational]| vec![p[0].mul(&p[1])];
/// let r = |n: i64| Rational::from_integer(n.into());
/// let f = multilinear_polar_form(2, &[vec![r(1), r(2)], vec![r(3), r(5)]], 2, &q)?;
/// assert_eq!(f, vec![Rational::new(11.into(), 2.into())]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn multilinear_polar_form<T: Ring>(
    n: usize,
    args: &[Point<T>],
    dim: usize,
    q: &dyn Fn(&[T]) -> Point<T>,
) -> Result<Point<T>> {
    if n > MAX_MULTILINEAR_DEGREE {
        return Err(Error::of(
            ErrorKind::Degree,
            "n",
            format!("eq. (18) visits 2^n - 1 subsets; n must be at most {MAX_MULTILINEAR_DEGREE}, found {n}"),
        ));
    }
    check_arity("args", args.len(), n)?;
    check_dims(args, dim, "args")?;
    if n == 0 {
        return Ok(q(&vec![T::zero(); dim]));
    }
    let factorial: BigInt = (1..=n).map(BigInt::from).product();
    let mut acc: Option<Point<T>> = None;
    for mask in 1u32..(1u32 << n) {
        let size = mask.count_ones() as usize;
        let mut sum = vec![T::zero(); dim];
        for (k, x) in args.iter().enumerate() {
            if mask >> k & 1 == 1 {
                point::add_assign(&mut sum, x);
            }
        }
        let sign = if (n - size).is_multiple_of(2) { 1 } else { -1 };
        let weight = Rational::new(BigInt::from(sign), factorial.clone());
        let value = q(&sum);
        match acc.as_mut() {
            Some(acc) => point::add_scaled_rational(acc, &weight, &value),
            None => acc = Some(point::scaled_rational(&value, &weight)),
        }
    }
    Ok(acc.expect("n >= 1 gives at least one subset"))
}

/// The homogenisation Q(t, s) = s^n C(t / s) = sum c_i t^i s^(n-i) of the curve of degree n,
/// at `x = [t, s]`.
pub fn homogeneous_curve<T: Ring>(curve: &PowerCurve<T>, x: &[T; 2]) -> Point<T> {
    let n = curve.degree();
    let mut acc = point::zero(curve.dim());
    for (i, c) in curve.coefficients().iter().enumerate() {
        let w = x[0].pow(i as u32).mul(&x[1].pow((n - i) as u32));
        point::add_scaled(&mut acc, &w, c);
    }
    acc
}

/// The homogenisation Q(u, v, w) = sum c_ij u^i v^j w^(N-i-j) of the surface as a triangular
/// patch of total degree N = n + m, at `x = [u, v, w]`.
pub fn homogeneous_surface<T: Ring>(surface: &PowerSurface<T>, x: &[T; 3]) -> Point<T> {
    let (n, m) = surface.degree();
    let mut acc = point::zero(surface.dim());
    for (i, row) in surface.rows().enumerate() {
        for (j, c) in row.iter().enumerate() {
            let w = x[0]
                .pow(i as u32)
                .mul(&x[1].pow(j as u32))
                .mul(&x[2].pow((n + m - i - j) as u32));
            point::add_scaled(&mut acc, &w, c);
        }
    }
    acc
}

/// The blossom b(t_1..t_n) of the curve as F((t_1, 1), .., (t_n, 1)), F the multilinear polar
/// form (18) of its homogenisation [`homogeneous_curve`]; `args.len()` must be the degree.
pub fn homogeneous_curve_blossom<T: Ring>(curve: &PowerCurve<T>, args: &[T]) -> Result<Point<T>> {
    let pts: Vec<Point<T>> = args.iter().map(|t| vec![t.clone(), T::one()]).collect();
    multilinear_polar_form(curve.degree(), &pts, 2, &|x| {
        homogeneous_curve(curve, x.try_into().expect(TWO_OR_THREE))
    })
}

/// The blossom b((u_1, v_1)..(u_N, v_N)) of the surface as a triangular patch of total degree
/// N = n + m, as F((u_1, v_1, 1), ..), F the multilinear polar form (18) of its homogenisation
/// [`homogeneous_surface`]; `args.len()` must be N.
pub fn homogeneous_triangle_blossom<T: Ring>(
    surface: &PowerSurface<T>,
    args: &[[T; 2]],
) -> Result<Point<T>> {
    let (n, m) = surface.degree();
    let pts: Vec<Point<T>> = args
        .iter()
        .map(|[u, v]| vec![u.clone(), v.clone(), T::one()])
        .collect();
    multilinear_polar_form(n + m, &pts, 3, &|x| {
        homogeneous_surface(surface, x.try_into().expect(TWO_OR_THREE))
    })
}

/// The count of (18)'s terms that hold a given sub-multiset: every subset of size N is one term,
/// so the number of values of q is sum_N C(n, N) = 2^n - 1.
pub fn multilinear_term_count(n: usize) -> BigInt {
    (1..=n as i64).map(|k| binomial(n as i64, k)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64) -> Rational {
        Rational::from_integer(n.into())
    }

    #[test]
    fn bad_input_is_named() {
        let q = |p: &[Rational]| vec![p[0].clone()];
        let e = multilinear_polar_form(2, &[vec![r(1)]], 1, &q).unwrap_err();
        assert_eq!((e.kind, e.field.as_str()), (ErrorKind::Arity, "args"));
        let e = multilinear_polar_form(2, &[vec![r(1)], vec![r(1), r(2)]], 1, &q).unwrap_err();
        assert_eq!(
            (e.kind, e.field.as_str()),
            (ErrorKind::Dimension, "args[1]")
        );
        let e = multilinear_polar_form(25, &[], 1, &q).unwrap_err();
        assert_eq!((e.kind, e.field.as_str()), (ErrorKind::Degree, "n"));
        assert_eq!(
            multilinear_polar_form(0, &[], 1, &|_| vec![r(7)]).unwrap(),
            vec![r(7)]
        );
        assert_eq!(multilinear_term_count(5), BigInt::from(31));
    }

    #[test]
    fn cube_of_a_linear_form() {
        // q(x) = x^3 on R: f(x1, x2, x3) = x1 x2 x3.
        let q = |p: &[Rational]| vec![p[0].pow(3)];
        let f = multilinear_polar_form(3, &[vec![r(2)], vec![r(3)], vec![r(5)]], 1, &q).unwrap();
        assert_eq!(f, vec![r(30)]);
    }
}
