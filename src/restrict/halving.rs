//! The default restriction of power-basis input ([`crate::Method::Bulk`]): the scaled power
//! basis and the halving engine of [`crate::engine::curve_net`], with no change of basis.
//!
//! * curve C(u) = sum_i c_i u^i of degree n: d_i = c_i / C(n, i), and the blossom is
//!   f(u_1, ..., u_n) = sum_i d_i e_i(u_1, ..., u_n) (Theorem 1, eq. (3): the weight of c_i
//!   in (3) is e_i / C(n, i)). Fixing one argument t is d'_i = d_i + t d_(i+1); the control
//!   points over [a, b] are f(a^(n-j), b^j);
//! * tensor surface of bidegree (n, m): d_ij = c_ij / (C(n, i) C(m, j)) (eq. (9)), the curve
//!   engine along u with whole rows as points, then along v;
//! * triangle of total degree N = n + m: d_ij = c_ij i! j! (N - i - j)! / N! (eq. (14)), the
//!   homogeneous form sum_ij M(N; i, j) d_ij u^i v^j w^(N-i-j) at w = 1, whose de Casteljau
//!   step at the point (u, v, 1) is d'_ij = d_ij + u d_(i+1)j + v d_i(j+1).
//!
//! The only divisions are the exact constants 1 / C(n, i), applied once by
//! [`Ring::scale_frac`] (or [`Ring::scale`] above degree 120); every step after them is a ring operation, so the same code runs on
//! f64, rationals and symbolic polynomials. In f64 the steps evaluate the same sums as the
//! closed form, in nested order, and their error is that of the closed form (the accuracy test
//! `tests/accuracy` measures it at every degree to 32), at O(n^2) cost instead of O(n^3).

use crate::num::binomial::binomial;
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::halving::{curve_net, tensor_net, triangle_net, PowerPairStep, PowerStep};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::{triangle_index, triangle_len};
use crate::{Rational, Ring};

/// 1 / C(n, i) for i = 0..=n in the ring: exact in exact rings, one rounding in floats.
fn reciprocal_binomials<T: Ring>(n: usize) -> impl Iterator<Item = T> {
    // C(n, i) = C(n, i - 1) (n - i + 1) / i stays within i128 (below 2^n n) for n <= 120.
    let mut c: i128 = 1;
    (0..=n).map(move |i| {
        if n > 120 {
            return T::one().scale(&Rational::new(1.into(), binomial(n as i64, i as i64)));
        }
        if i > 0 {
            c = c * (n - i + 1) as i128 / i as i128;
        }
        T::one().scale_frac(1, c)
    })
}

/// The coefficients d_i = c_i / C(n, i) of `curve` in the scaled power basis, one contiguous
/// run of n + 1 points.
pub(crate) fn scaled_curve<T: Ring>(curve: &PowerCurve<T>) -> Vec<T> {
    let n = curve.degree();
    let dim = curve.dim();
    let mut scaled = Vec::with_capacity((n + 1) * dim);
    for (c, k) in curve
        .coefficients()
        .iter()
        .zip(reciprocal_binomials::<T>(n))
    {
        scaled.extend(c.iter().map(|x| x.mul(&k)));
    }
    scaled
}

/// `curve` restricted to [a, b] in the scaled power basis.
pub(crate) fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let dim = curve.dim();
    let scaled = scaled_curve(curve);
    let mut out = vec![T::zero(); scaled.len()];
    T::with_scratch(|scratch| {
        curve_net(
            &scaled,
            dim,
            &PowerStep(a),
            &PowerStep(b),
            &mut out,
            scratch,
        )
    });
    BezierCurve::from_coordinates(dim, out).expect("n + 1 points of one dimension")
}

/// The coefficients d_ij = c_ij / (C(n, i) C(m, j)) of `surface` in the scaled tensor power
/// basis: n + 1 rows of m + 1 points, one contiguous run.
pub(crate) fn scaled_tensor<T: Ring>(surface: &PowerSurface<T>) -> Vec<T> {
    let (n, m) = surface.degree();
    let dim = surface.dim();
    let along_u: Vec<T> = reciprocal_binomials(n).collect();
    let along_v: Vec<T> = reciprocal_binomials(m).collect();
    let mut scaled = Vec::with_capacity((n + 1) * (m + 1) * dim);
    for (row, ku) in surface.rows().zip(&along_u) {
        for (c, kv) in row.iter().zip(&along_v) {
            let k = ku.mul(kv);
            scaled.extend(c.iter().map(|x| x.mul(&k)));
        }
    }
    scaled
}

/// `surface` restricted to `rect = [a, b, c, d]` in the scaled power basis.
pub(crate) fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let (_, m) = surface.degree();
    let dim = surface.dim();
    let scaled = scaled_tensor(surface);
    let mut out = vec![T::zero(); scaled.len()];
    let steps = rect.each_ref().map(PowerStep);
    T::with_scratch(|scratch| tensor_net(&scaled, m + 1, dim, steps.each_ref(), &mut out, scratch));
    TensorPatch::from_coordinates(surface.degree(), dim, out).expect("a rectangular net")
}

/// The coefficients d_ij = c_ij / M(N; i, j) of `surface` (total degree N) as a triangular form
/// in the scaled power basis, in the lexicographic order of (i, j), one contiguous run.
pub(crate) fn scaled_triangle<T: Ring>(surface: &PowerTriangle<T>) -> Vec<T> {
    let big_n = surface.degree();
    let dim = surface.dim();
    let mut scaled = vec![T::zero(); triangle_len(big_n) * dim];
    // 1 / M(N; i, j) = 1 / (C(N, i) C(N - i, j)).
    let first: Vec<T> = reciprocal_binomials(big_n).collect();
    for (i, row) in surface.rows().enumerate() {
        let second: Vec<T> = reciprocal_binomials(big_n - i).collect();
        for (j, c) in row.iter().enumerate() {
            let k = first[i].mul(&second[j]);
            let at = triangle_index(big_n, i, j) * dim;
            for (slot, x) in scaled[at..at + dim].iter_mut().zip(c) {
                *slot = x.mul(&k);
            }
        }
    }
    scaled
}

/// `surface`, of total degree N, restricted to the triangle `tri` in the scaled power basis.
pub(crate) fn restrict_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let big_n = surface.degree();
    let dim = surface.dim();
    let scaled = scaled_triangle(surface);
    let mut out = vec![T::zero(); scaled.len()];
    let steps = tri.each_ref().map(PowerPairStep);
    T::with_scratch(|scratch| {
        triangle_net(&scaled, big_n, dim, steps.each_ref(), &mut out, scratch)
    });
    TriangularPatch::from_coordinates(big_n, dim, out).expect("a triangular net")
}
