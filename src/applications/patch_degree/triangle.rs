//! Degree elevation and reduction of triangular Bézier patches over the unit triangle, exactly.
//!
//! Control points q_a, a = (a1, a2, a3) with |a| = N, weigh the Bernstein polynomials
//! B_a^N = [N!/a!] s^a1 t^a2 r^a3, where a! = a1! a2! a3! and (s, t, r) are the barycentric
//! coordinates of the patch's corners. Over the unit triangle T = {u, v >= 0, u + v <= 1} with
//! corners (1, 0), (0, 1), (0, 0): s = u, t = v, r = 1 - u - v, and dA = du dv (area 1/2).
//!
//! * **Elevation** from N to M >= N multiplies by (s + t + r)^(M - N) = sum_c B_c^(M-N):
//!   B_a^N B_c^(M-N) = ([N!/a!] [(M-N)!/c!] / [M!/(a+c)!]) B_(a+c)^M, so
//!   q'_g = sum_{a <= g} [N!/a!] [(M-N)!/(g-a)!] / [M!/g!] q_a (componentwise a <= g).
//! * **Gram matrix**. By the Dirichlet integral int_T s^i t^j r^k dA = i! j! k! / (i+j+k+2)!,
//!   int_T B_c^L dA = [L!/c!] c!/(L+2)! = L!/(L+2)! = 1/((L+1)(L+2)) for every c, and the
//!   product rule above gives
//!   int_T B_a^m B_b^n dA = [m!/a!] [n!/b!] / [(m+n)!/(a+b)!] / ((m+n+1)(m+n+2)).
//!   (Over a triangle of area A the integrals scale by 2A.)
//! * **Reduction** to N' < N by a [`Reduction`]:
//!   - interpolating: eq. (23) of seed 004 at degree N' applied to the patch as the sampled
//!     surface on T ([`crate::triangle_control_points_from_samples`]); it keeps the three
//!     corners and reproduces patches of degree <= N';
//!   - least squares: the L2-best patch over T, from G_N'N' x = G_N'N b;
//!   - least squares keeping the three corners q_(N,0,0), q_(0,N,0), q_(0,0,N) (the end
//!     points of the boundary curves): the same normal equations with those unknowns pinned.
//! * **Errors**: int_T |a - b|^2 dA = d^T G d (coordinate-wise) for the difference d of the two
//!   patches elevated to a common degree.
//!
//! Matrices index control points in the lexicographic order of (a1, a2) of
//! [`crate::TriangularPatch`].

use super::{check_count, check_higher_degree, check_lower_degree};
use crate::applications::degree::{check_same_dimension, not_a_matrix, Reduction};
use crate::error::{Error, ErrorKind, Result};
use crate::num::binomial::multinomial;
use crate::num::linalg;
use crate::restrict::polarisation::triangle_control_points_from_samples;
use crate::shape::bezier::TriangularPatch;
use crate::shape::simplex::{checked_triangle_len, triangle_index};
use crate::{Rational, Ring};
use num_bigint::BigInt;

/// The indices (a1, a2) of degree `n` in lexicographic order (a3 = n - a1 - a2).
fn indices(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=n).flat_map(move |i| (0..=n - i).map(move |j| (i, j)))
}

/// The multinomial n!/(a1! a2! (n - a1 - a2)!), zero when a part is negative.
fn multi(n: usize, a1: i64, a2: i64) -> BigInt {
    multinomial(n as i64, &[a1, a2])
}

/// The number of control points of degree `n`, (n + 1)(n + 2)/2, checked.
fn net_len(n: usize) -> Result<usize> {
    check_count(checked_triangle_len(n))
}

/// The matrix `[g][a]` = [N!/a!] [(M-N)!/(g-a)!] / [M!/g!] of elevation from degree `n` = N to
/// `m` = M >= N (rows: indices g of degree M, columns: a of degree N, both lexicographic).
///
/// Fails with [`ErrorKind::Degree`] on `to_degree` when M < N.
pub fn triangle_elevation_matrix(n: usize, m: usize) -> Result<Vec<Vec<Rational>>> {
    check_higher_degree(n, m, "")?;
    let k = m - n;
    Ok(indices(m)
        .map(|(g1, g2)| {
            let den = multi(m, g1 as i64, g2 as i64);
            indices(n)
                .map(|(a1, a2)| {
                    let num = multi(n, a1 as i64, a2 as i64)
                        * multi(k, g1 as i64 - a1 as i64, g2 as i64 - a2 as i64);
                    Rational::new(num, den.clone())
                })
                .collect()
        })
        .collect())
}

/// The Gram matrix `[a][b]` = int_T B_a^m B_b^n du dv over the unit triangle T
/// = [m!/a!] [n!/b!] / [(m+n)!/(a+b)!] / ((m+n+1)(m+n+2)) (derivation in the module
/// documentation).
pub fn triangle_bernstein_gram(m: usize, n: usize) -> Vec<Vec<Rational>> {
    let l = m + n;
    let scale = BigInt::from(l + 1) * BigInt::from(l + 2);
    indices(m)
        .map(|(a1, a2)| {
            indices(n)
                .map(|(b1, b2)| {
                    let num = multi(m, a1 as i64, a2 as i64) * multi(n, b1 as i64, b2 as i64);
                    let den = multi(l, (a1 + b1) as i64, (a2 + b2) as i64) * &scale;
                    Rational::new(num, den)
                })
                .collect()
        })
        .collect()
}

/// `patch` (degree N) written at degree `to_degree` >= N, exactly.
///
/// ```
/// use blossom::{elevate_triangle, TriangularPatch};
/// // u + v (control points q_100 = q_010 = 1, q_001 = 0) at degree 2.
/// let p = TriangularPatch::new(1, vec![vec![0.0], vec![1.0], vec![1.0]])?;
/// let e = elevate_triangle(&p, 2)?;
/// assert_eq!(e.get(1, 0), &vec![0.5]);
/// assert_eq!(e.get(1, 1), &vec![1.0]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn elevate_triangle<T: Ring>(
    patch: &TriangularPatch<T>,
    to_degree: usize,
) -> Result<TriangularPatch<T>> {
    check_higher_degree(patch.degree(), to_degree, "")?;
    net_len(to_degree)?;
    let dim = patch.dim();
    let points = linalg::apply(
        &triangle_elevation_matrix(patch.degree(), to_degree)?,
        &patch.control_points().to_vec(),
        dim,
    );
    TriangularPatch::new(to_degree, points)
}

/// Checks a reduction from degree `from` to `to < from`.
fn check_reduction(from: usize, to: usize, method: Reduction) -> Result<()> {
    check_lower_degree(from, to, method, "")?;
    if to == from {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!("reduction needs to_degree < {from} (the degree of the patch), found {to}"),
        ));
    }
    Ok(())
}

/// The exact matrix R (rows: degree `to`, columns: degree `from`) with x = R b for the
/// least-squares reductions of triangular patches from degree N = `from` to N' = `to` < N:
/// R = G_N'N'^-1 G_N'N for [`Reduction::LeastSquares`], and for
/// [`Reduction::LeastSquaresEndpoints`] the unit rows of the three corners around the solution
/// of the normal equations of the other unknowns.
pub fn triangle_least_squares_matrix(
    from: usize,
    to: usize,
    method: Reduction,
) -> Result<Vec<Vec<Rational>>> {
    check_reduction(from, to, method)?;
    net_len(from)?;
    let fixed: Vec<(usize, usize)> = match method {
        Reduction::LeastSquares => Vec::new(),
        // The corners a, b, c: q_(N,0,0), q_(0,N,0), q_(0,0,N).
        Reduction::LeastSquaresEndpoints => vec![
            (triangle_index(to, to, 0), triangle_index(from, from, 0)),
            (triangle_index(to, 0, to), triangle_index(from, 0, from)),
            (triangle_index(to, 0, 0), triangle_index(from, 0, 0)),
        ],
        Reduction::Interpolating => return Err(not_a_matrix()),
    };
    linalg::least_squares_operator(
        &triangle_bernstein_gram(to, to),
        &triangle_bernstein_gram(to, from),
        &fixed,
        "to_degree",
    )
}

/// A triangular patch of degree `to_degree` < N approximating `patch` over the unit triangle
/// (corners (1, 0), (0, 1), (0, 0)) by `method`.
///
/// The interpolating and corner-keeping methods need `to_degree >= 1`.
///
/// ```
/// use blossom::{elevate_triangle, reduce_triangle, Rational, Reduction, TriangularPatch};
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = TriangularPatch::new(1, vec![vec![q(2)], vec![q(-1)], vec![q(7)]])?;
/// let high = elevate_triangle(&p, 4)?;
/// for method in Reduction::ALL {
///     assert_eq!(reduce_triangle(&high, 1, method)?, p);
/// }
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn reduce_triangle<T: Ring>(
    patch: &TriangularPatch<T>,
    to_degree: usize,
    method: Reduction,
) -> Result<TriangularPatch<T>> {
    let from = patch.degree();
    check_reduction(from, to_degree, method)?;
    let points = match method {
        Reduction::Interpolating => {
            let (zero, one) = (T::zero(), T::one());
            let tri = [
                [one.clone(), zero.clone()],
                [zero.clone(), one.clone()],
                [zero.clone(), zero],
            ];
            triangle_control_points_from_samples(to_degree, &tri, &|u, v| {
                patch.eval(&[u.clone(), v.clone()])
            })
        }
        Reduction::LeastSquares | Reduction::LeastSquaresEndpoints => {
            let r = triangle_least_squares_matrix(from, to_degree, method)?;
            linalg::apply(&r, &patch.control_points().to_vec(), patch.dim())
        }
    };
    TriangularPatch::new(to_degree, points)
}

/// The squared L2 distance int_T |a - b|^2 du dv of two triangular patches over the unit
/// triangle, of any degrees and one dimension, exactly (both elevated to the larger degree;
/// d^T G d for the difference d).
pub fn triangle_squared_l2_distance<T: Ring>(
    a: &TriangularPatch<T>,
    b: &TriangularPatch<T>,
) -> Result<T> {
    check_same_dimension(
        &a.control_points().to_vec(),
        &b.control_points().to_vec(),
        "patches",
    )?;
    let n = a.degree().max(b.degree());
    let (ea, eb) = (elevate_triangle(a, n)?, elevate_triangle(b, n)?);
    let diff = linalg::differences(&ea.control_points().to_vec(), &eb.control_points().to_vec());
    Ok(linalg::gram_quadratic_form(
        &triangle_bernstein_gram(n, n),
        &diff,
    ))
}
