//! Blossoms by their definition as subset sums, equations (2), (8) and (13) of the subdivision
//! paper.
//!
//! * curve, eq. (2): b(u_1..u_n) = sum_i c_i b_i(u), b_i(u) = e_i(u_1..u_n) / C(n, i), where
//!   e_i is the sum over all i-subsets {alpha_1..alpha_i} of {1..n} of u_alpha_1 ... u_alpha_i;
//! * tensor patch, eqs. (7)-(8): b_ij(u; v) = e_i(u) / C(n, i) * e_j(v) / C(m, j);
//! * triangle, eq. (13): b_ij((u_1, v_1)..(u_N, v_N)) = E_ij / (N! / (i! j! (N-i-j)!)), where
//!   E_ij is the sum over disjoint index sets {alpha_1..alpha_i}, {beta_1..beta_j} of {1..N}
//!   of u_alpha_1 ... u_alpha_i v_beta_1 ... v_beta_j.
//!
//! The subset sums are enumerated by deciding, argument after argument, whether its index
//! joins a subset (Pascal's rule for subsets): e_i(u_1..u_k) = e_i(u_1..u_{k-1}) +
//! u_k e_{i-1}(u_1..u_{k-1}), and for the triangle E_ij gains u_k E_{i-1,j} + v_k E_{i,j-1}.
//! Every subset is counted exactly once, with no closed-form counting of the kind used by
//! Theorems 1-3, at O(n^2) (curve) and O(N n m) (triangle) ring operations per blossom value.

use crate::error::{check_arity, Result};
use crate::num::binomial::{binomial, multinomial};
use crate::restrict::nets::{repeated, tensor_net, triangle_net};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point::{self, Point};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::{Rational, Ring};

/// The subset sums e_0..e_n of `args` (e_i = sum over i-subsets of the product), n = args.len().
pub fn subset_sums<T: Ring>(args: &[T]) -> Vec<T> {
    let mut e = vec![T::zero(); args.len() + 1];
    e[0] = T::one();
    for (k, u) in args.iter().enumerate() {
        for i in (1..=k + 1).rev() {
            let add = u.mul(&e[i - 1]);
            e[i].add_assign(&add);
        }
    }
    e
}

/// The blossom b(u_1..u_n) of the curve, eq. (2).
///
/// # Errors
/// [`ErrorKind::Arity`](crate::ErrorKind::Arity) on `args` when `args.len()` is not the degree.
pub fn curve_blossom<T: Ring>(curve: &PowerCurve<T>, args: &[T]) -> Result<Point<T>> {
    check_arity("args", args.len(), curve.degree())?;
    Ok(curve_blossom_unchecked(curve, args))
}

/// [`curve_blossom`] with `args.len()` known to be the degree.
fn curve_blossom_unchecked<T: Ring>(curve: &PowerCurve<T>, args: &[T]) -> Point<T> {
    let n = curve.degree();
    let e = subset_sums(args);
    let mut acc = point::zero(curve.dim());
    for (i, c) in curve.coefficients().iter().enumerate() {
        let weight = e[i].scale(&Rational::new(1.into(), binomial(n as i64, i as i64)));
        point::add_scaled(&mut acc, &weight, c);
    }
    acc
}

/// The blossom b(u_1..u_n; v_1..v_m) of the tensor patch, eqs. (7)-(8).
///
/// # Errors
/// [`ErrorKind::Arity`](crate::ErrorKind::Arity) on `us` (`vs`) when it does not hold n (m)
/// arguments for bidegree (n, m).
pub fn tensor_blossom<T: Ring>(surface: &PowerSurface<T>, us: &[T], vs: &[T]) -> Result<Point<T>> {
    let (n, m) = surface.degree();
    check_arity("us", us.len(), n)?;
    check_arity("vs", vs.len(), m)?;
    Ok(tensor_blossom_unchecked(surface, us, vs))
}

/// [`tensor_blossom`] with n + m arguments known to fit the bidegree (n, m).
fn tensor_blossom_unchecked<T: Ring>(surface: &PowerSurface<T>, us: &[T], vs: &[T]) -> Point<T> {
    let (n, m) = surface.degree();
    let eu = subset_sums(us);
    let ev = subset_sums(vs);
    let mut acc = point::zero(surface.dim());
    for (i, row) in surface.rows().enumerate() {
        for (j, c) in row.iter().enumerate() {
            let k = Rational::new(
                1.into(),
                binomial(n as i64, i as i64) * binomial(m as i64, j as i64),
            );
            point::add_scaled(&mut acc, &eu[i].mul(&ev[j]).scale(&k), c);
        }
    }
    acc
}

/// The blossom b((u_1, v_1)..(u_N, v_N)) of the surface as a triangular patch of total degree
/// N = n + m, eq. (13).
///
/// # Errors
/// [`ErrorKind::Arity`](crate::ErrorKind::Arity) on `args` when `args.len()` is not n + m.
pub fn triangle_blossom<T: Ring>(surface: &PowerSurface<T>, args: &[[T; 2]]) -> Result<Point<T>> {
    power_triangle_blossom(&PowerTriangle::from_surface(surface), args)
}

/// The blossom b((u_1, v_1)..(u_N, v_N)) of a surface of total degree N, eq. (13):
/// sum_{i+j<=N} c_ij E_ij / M(N; i, j), where E_ij is the sum over disjoint index sets I, J
/// (|I| = i, |J| = j) of prod_{k in I} u_k prod_{l in J} v_l and M(N; i, j) = N! / (i! j! (N-i-j)!)
/// counts them. The paper states it for a grid (i <= n, j <= m, N = n + m); the sum is the same
/// for any array with i + j <= N.
///
/// # Errors
/// [`ErrorKind::Arity`](crate::ErrorKind::Arity) on `args` when `args.len()` is not N.
pub fn power_triangle_blossom<T: Ring>(
    surface: &PowerTriangle<T>,
    args: &[[T; 2]],
) -> Result<Point<T>> {
    check_arity("args", args.len(), surface.degree())?;
    Ok(power_triangle_blossom_unchecked(surface, args))
}

/// [`power_triangle_blossom`] with `args.len()` known to be the degree.
fn power_triangle_blossom_unchecked<T: Ring>(
    surface: &PowerTriangle<T>,
    args: &[[T; 2]],
) -> Point<T> {
    let big_n = surface.degree();
    let n = surface.rows().len() - 1;
    let m = surface.rows().map(|r| r.len()).max().unwrap_or(1) - 1;
    // e[i][j] = E_ij over the arguments seen so far, truncated to the array's rows and columns.
    let mut e = vec![vec![T::zero(); m + 1]; n + 1];
    e[0][0] = T::one();
    for [u, v] in args {
        for i in (0..=n).rev() {
            for j in (0..=m).rev() {
                let mut gain = T::zero();
                if i > 0 {
                    gain.add_assign(&u.mul(&e[i - 1][j]));
                }
                if j > 0 {
                    gain.add_assign(&v.mul(&e[i][j - 1]));
                }
                e[i][j].add_assign(&gain);
            }
        }
    }
    let mut acc = point::zero(surface.dim());
    for (i, j, c) in surface.terms() {
        let k = Rational::new(1.into(), multinomial(big_n as i64, &[i as i64, j as i64]));
        point::add_scaled(&mut acc, &e[i][j].scale(&k), c);
    }
    acc
}

/// Control points w_v = b(b^v, a^(n-v)) of `curve` on [a, b], eq. (1) with (2).
pub fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let n = curve.degree();
    let points = (0..=n)
        .map(|v| curve_blossom_unchecked(curve, &repeated(b, v, a, n - v)))
        .collect();
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

/// Control points p_{nu mu} = b(b^nu, a^(n-nu); d^mu, c^(m-mu)), eq. (6) with (7)-(8).
pub fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let points = tensor_net(surface.degree(), rect, |us, vs| {
        tensor_blossom_unchecked(surface, us, vs)
    });
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b(a^nu, b^mu, c^lambda), eq. (12) with (13).
pub fn restrict_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let big_n = surface.degree();
    let points = triangle_net(big_n, tri, |args| {
        power_triangle_blossom_unchecked(surface, args)
    });
    TriangularPatch::new(big_n, points).expect("a full triangular net")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subset_sums_enumerate_every_subset() {
        // Brute force over bitmasks for 5 arguments.
        let args = [2.0, 3.0, 5.0, 7.0, 11.0];
        let e = subset_sums(&args);
        let mut brute = [0.0; 6];
        for mask in 0u32..32 {
            let prod: f64 = (0..5)
                .filter(|k| mask >> k & 1 == 1)
                .map(|k| args[k])
                .product();
            brute[mask.count_ones() as usize] += prod;
        }
        assert_eq!(e, brute.to_vec());
    }
}
