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
    power_to_bernstein_in_place, scale_argument, taylor_shift, triangle_power_to_bernstein,
};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point::{self, flatten, unflatten, Point};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::{triangle_index, triangle_len};
use crate::Ring;

/// Bézier control points over [0, 1] of C(a + (b - a) t), given the coefficients of C.
/// The coefficients are taken by value and transformed in place.
pub(crate) fn bulk_curve_points<T: Ring>(mut d: Vec<Point<T>>, a: &T, b: &T) -> Vec<Point<T>> {
    taylor_shift(&mut d, a);
    scale_argument(&mut d, &b.sub(a));
    power_to_bernstein_in_place(&mut d);
    d
}

/// `curve` restricted to [a, b] by the Taylor shift.
pub(crate) fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    BezierCurve::new(bulk_curve_points(curve.coefficients().to_vec(), a, b))
        .expect("n + 1 points of one dimension")
}

/// `surface` restricted to `rect = [a, b, c, d]` by the curve path along u, then along v.
pub(crate) fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let [a, b, c, d] = rect;
    let dim = surface.dim();
    // Along u with whole rows as points, then along v row by row.
    let rows = unflatten(bulk_curve_points(flatten(&surface.to_nested()), a, b), dim);
    let net = rows
        .into_iter()
        .map(|row| bulk_curve_points(row, c, d))
        .collect();
    TensorPatch::new(net).expect("a rectangular net")
}

/// Multiplies the binary form `form` (coefficients of s^alpha t^(l - alpha), alpha = 0..=l)
/// by the linear form `p s + q t`.
fn times_linear<T: Ring>(form: &[Point<T>], p: &T, q: &T) -> Vec<Point<T>> {
    let l = form.len() - 1;
    let dim = form[0].len();
    let mut out = vec![point::zero::<T>(dim); l + 2];
    for (alpha, f) in form.iter().enumerate() {
        point::add_scaled(&mut out[alpha + 1], p, f);
        point::add_scaled(&mut out[alpha], q, f);
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
/// `coefficients[i][j]` (i <= n, j <= m), as a triangular patch of total degree `big_n`: n + m
/// for the paper's convention, or N for a grid of total degree N padded with zeros (the power
/// form of a triangular Bézier patch, or of a triangular array). Terms with i + j > N are
/// zero by that convention and never visited.
pub(crate) fn bulk_triangle_grid<T: Ring>(
    coefficients: &[Vec<Point<T>>],
    big_n: usize,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (n, m) = (coefficients.len() - 1, coefficients[0].len() - 1);
    let dim = coefficients[0][0].len();
    let [[a1, a2], [b1, b2], [c1, c2]] = tri;
    // 1. S(c1 + x, c2 + y): Taylor shift along u with rows as points, then along v.
    let mut long = flatten(coefficients);
    taylor_shift(&mut long, c1);
    let mut shifted = unflatten(long, dim);
    for row in shifted.iter_mut() {
        taylor_shift(row, c2);
    }
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
    let mut d = vec![point::zero::<T>(dim); triangle_len(big_n)];
    for k in 0..=big_n {
        // f_k = sum_{i + j = k} c'_ij x^i y^j, i <= n, j <= m; Horner over descending i.
        let i_top = k.min(n);
        let j_low = k - i_top;
        if j_low > m {
            continue;
        }
        // acc = c'_{i_top, j_low} X^0 Y^{j_low}.
        let mut acc: Vec<Point<T>> = y_powers[j_low]
            .iter()
            .map(|y| shifted[i_top][j_low].iter().map(|c| c.mul(y)).collect())
            .collect();
        for i in (0..i_top).rev() {
            let j = k - i;
            acc = times_linear(&acc, &p, &q);
            if j <= m {
                for (alpha, y) in y_powers[j].iter().enumerate() {
                    point::add_scaled(&mut acc[alpha], y, &shifted[i][j]);
                }
            }
        }
        // acc[alpha] is the coefficient of s^alpha t^(k - alpha).
        for (alpha, coef) in acc.into_iter().enumerate() {
            d[triangle_index(big_n, alpha, k - alpha)] = coef;
        }
    }
    // 3. Bernstein form on the triangle (s <-> a, t <-> b, 1 - s - t <-> c).
    triangle_power_to_bernstein(big_n, &d)
        .expect("a full triangular net of the surface's dimension")
}
