//! The Taylor-shift path ([`crate::Method::TaylorShift`]): all control points at once by changes of
//! variable and of basis, through the power basis.
//!
//! * curve on [a, b]: the coefficients of C(a + (b - a) t) by a Taylor shift and a scaling,
//!   then the Bernstein form over [0, 1] (w_v = sum_{i <= v} C(v, i) / C(n, i) d_i):
//!   O(n^2) ring operations per coordinate;
//! * tensor patch on [a, b] x [c, d]: the curve algorithm along u with whole rows as points,
//!   then along v for every row: O(nm(n + m));
//! * triangle abc: a two-dimensional Taylor shift that moves c to the origin, then each
//!   homogeneous part f_k(x, y) = sum_{i+j=k} c'_ij x^i y^j is composed with the linear map
//!   x = (a1 - c1) s + (b1 - c1) t, y = (a2 - c2) s + (b2 - c2) t by the mixed Horner rule
//!   g_0 = f_{k,0}, g_l = g_{l-1} X + f_{k-l, l} Y^l (O(k^2) per part), and the result, a
//!   polynomial in the barycentric coordinates (s, t) of a and b, is written in the Bernstein
//!   basis of the triangle: O(N^3) in all, against O(N^6)-O(N^8) for eq. (14) per point.
//!
//! Every step is division-free, so the same code runs on floats, rationals and symbolic
//! polynomials. In floating point the power basis is ill-conditioned: the error grows with the
//! degree (`BENCHMARKS.md` has the measured figures).

use crate::shape::basis::{
    power_to_bernstein_flat, scale_argument_flat, taylor_shift_flat,
    triangle_power_to_bernstein_flat,
};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point;
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::{triangle_index, triangle_len};
use crate::Ring;

/// Replaces the coefficients `d` of C (flat, `stride` coordinates each) by the Bézier control
/// points over [0, 1] of C(a + (b - a) t), in place.
pub(crate) fn bulk_curve_points<T: Ring>(d: &mut [T], stride: usize, a: &T, b: &T) {
    taylor_shift_flat(d, stride, a);
    scale_argument_flat(d, stride, &b.sub(a));
    power_to_bernstein_flat(d, stride);
}

/// `curve` restricted to [a, b] by the Taylor shift.
pub(crate) fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let mut d = curve.coordinates().to_vec();
    bulk_curve_points(&mut d, curve.dim(), a, b);
    BezierCurve::from_raw(curve.dim(), d)
}

/// `surface` restricted to `rect = [a, b, c, d]` by the curve path along u, then along v.
pub(crate) fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let [a, b, c, d] = rect;
    let (dim, cols) = (surface.dim(), surface.degree().1 + 1);
    // Along u with whole rows as points, then along v row by row.
    let mut net = surface.coordinates().to_vec();
    bulk_curve_points(&mut net, cols * dim, a, b);
    for row in net.chunks_exact_mut(cols * dim) {
        bulk_curve_points(row, dim, c, d);
    }
    TensorPatch::from_raw(cols, dim, net)
}

/// Multiplies the binary form `form` (coefficients of s^alpha t^(l - alpha), alpha = 0..=l,
/// flat, `dim` coordinates each) by the linear form `p s + q t`.
fn times_linear<T: Ring>(form: &[T], dim: usize, p: &T, q: &T) -> Vec<T> {
    let mut out = vec![T::zero(); form.len() + dim];
    for (alpha, f) in form.chunks_exact(dim).enumerate() {
        point::add_scaled(&mut out[(alpha + 1) * dim..(alpha + 2) * dim], p, f);
        point::add_scaled(&mut out[alpha * dim..(alpha + 1) * dim], q, f);
    }
    out
}

/// `surface`, of total degree N, restricted to the triangle `tri`: its rows padded with zeros
/// to a grid (a no-op for a grid input) and [`bulk_triangle_grid`] at degree N.
pub(crate) fn restrict_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    bulk_triangle_grid(&surface.padded_grid(), surface.degree(), tri)
}

/// The bulk triangle restriction of the polynomial sum c_ij u^i v^j with the coefficient grid
/// `coefficients` (c_ij, i <= n, j <= m) as a triangular patch of total degree `big_n`: n + m
/// for the paper's convention, or N for a grid of total degree N padded with zeros (the power
/// form of a triangular Bézier patch, or of a triangular array). Terms with i + j > N are
/// zero by that convention and never visited.
pub(crate) fn bulk_triangle_grid<T: Ring>(
    coefficients: &PowerSurface<T>,
    big_n: usize,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (n, m) = coefficients.degree();
    let dim = coefficients.dim();
    let [[a1, a2], [b1, b2], [c1, c2]] = tri;
    // 1. S(c1 + x, c2 + y): Taylor shift along u with rows as points, then along v.
    let width = (m + 1) * dim;
    let mut shifted = coefficients.coordinates().to_vec();
    taylor_shift_flat(&mut shifted, width, c1);
    for row in shifted.chunks_exact_mut(width) {
        taylor_shift_flat(row, dim, c2);
    }
    let c_shifted = |i: usize, j: usize| &shifted[i * width + j * dim..i * width + (j + 1) * dim];
    // 2. x = p s + q t, y = r s + w t applied to every homogeneous part.
    let (p, q) = (a1.sub(c1), b1.sub(c1));
    let (r, w) = (a2.sub(c2), b2.sub(c2));
    // y_powers[l] = Y^l as a binary form of degree l with scalar coefficients.
    let mut y_powers: Vec<Vec<T>> = vec![vec![T::one()]];
    for l in 1..=m {
        let prev = &y_powers[l - 1];
        let mut next = vec![T::zero(); l + 1];
        for (alpha, f) in prev.iter().enumerate() {
            next[alpha + 1].add_assign(&r.mul(f));
            next[alpha].add_assign(&w.mul(f));
        }
        y_powers.push(next);
    }
    let mut d = vec![T::zero(); triangle_len(big_n) * dim];
    for k in 0..=big_n {
        // f_k = sum_{i + j = k} c'_ij x^i y^j, i <= n, j <= m; Horner over descending i.
        let i_top = k.min(n);
        let j_low = k - i_top;
        if j_low > m {
            continue;
        }
        // acc = c'_{i_top, j_low} X^0 Y^{j_low}.
        let mut acc: Vec<T> = y_powers[j_low]
            .iter()
            .flat_map(|y| c_shifted(i_top, j_low).iter().map(move |c| c.mul(y)))
            .collect();
        for i in (0..i_top).rev() {
            let j = k - i;
            acc = times_linear(&acc, dim, &p, &q);
            if j <= m {
                for (alpha, y) in y_powers[j].iter().enumerate() {
                    point::add_scaled(&mut acc[alpha * dim..(alpha + 1) * dim], y, c_shifted(i, j));
                }
            }
        }
        // acc[alpha] is the coefficient of s^alpha t^(k - alpha).
        for (alpha, coef) in acc.chunks_exact(dim).enumerate() {
            let at = triangle_index(big_n, alpha, k - alpha) * dim;
            d[at..at + dim].clone_from_slice(coef);
        }
    }
    // 3. Bernstein form on the triangle (s <-> a, t <-> b, 1 - s - t <-> c).
    triangle_power_to_bernstein_flat(big_n, dim, d)
}
