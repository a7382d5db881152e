//! The pyramid (de Casteljau) algorithm for blossoms, seed 004 section 2.
//!
//! * curve, eq. (2) of 004: b^r_i[t_1..t_r] = (1 - t_r) b^{r-1}_i + t_r b^{r-1}_{i+1}, and the
//!   blossom is b^n_0[t_1..t_n];
//! * tensor patch, eq. (9) of 004: b[u_1..u_n; v_1..v_m] = b[u_1..u_n][v_1..v_m], the curve
//!   pyramid along v for every row, then along u;
//! * triangle: b^r_{ijk} = u_r b^{r-1}_{i+1,j,k} + v_r b^{r-1}_{i,j+1,k} + w_r b^{r-1}_{i,j,k+1}
//!   for barycentric arguments (u_r, v_r, w_r).
//!
//! Restriction by the pyramid first writes the power-basis input in Bernstein form over the
//! reference domain ([0, 1], [0, 1]^2, the triangle (1, 0), (0, 1), (0, 0)), then evaluates the
//! blossom at the new domain's corners: O(n^2) per control point of a curve.

use crate::basis::{power_to_bernstein, triangle_power_to_bernstein};
use crate::bezier::{triangle_index, triangle_len, BezierCurve, TensorPatch, TriangularPatch};
use crate::blossoms::{repeated, tensor_net, triangle_net};
use crate::point::{lerp, Point};
use crate::power::{PowerCurve, PowerSurface};
use crate::Ring;

/// The blossom b[t_1, ..., t_n] of the Bézier curve with control points `control` (degree
/// `n = control.len() - 1 = args.len()`), eq. (2) of seed 004.
pub fn bezier_curve_blossom<T: Ring>(control: &[Point<T>], args: &[T]) -> Point<T> {
    assert_eq!(
        args.len() + 1,
        control.len(),
        "a blossom of degree n takes n arguments"
    );
    let mut level: Vec<Point<T>> = control.to_vec();
    for t in args {
        level = level.windows(2).map(|w| lerp(&w[0], &w[1], t)).collect();
    }
    level.pop().expect("one point remains")
}

/// The blossom b[u_1..u_n; v_1..v_m] of the tensor patch with net `net[nu][mu]`, in two passes
/// (eq. (9) of seed 004): along v for every row, then along u.
pub fn bezier_tensor_blossom<T: Ring>(net: &[Vec<Point<T>>], us: &[T], vs: &[T]) -> Point<T> {
    let column: Vec<Point<T>> = net
        .iter()
        .map(|row| bezier_curve_blossom(row, vs))
        .collect();
    bezier_curve_blossom(&column, us)
}

/// The blossom of a triangular patch at barycentric arguments (u_r, v_r, w_r) (weights of the
/// patch's corners a, b, c), by the triangular pyramid.
pub fn bezier_triangle_blossom<T: Ring>(patch: &TriangularPatch<T>, args: &[[T; 3]]) -> Point<T> {
    let n = patch.degree();
    assert_eq!(args.len(), n, "a blossom of degree N takes N arguments");
    let mut level: Vec<Point<T>> = patch.control_points().to_vec();
    for (r, [u, v, w]) in args.iter().enumerate() {
        let d = n - r - 1;
        let mut next = Vec::with_capacity(triangle_len(d));
        for i in 0..=d {
            for j in 0..=d - i {
                let pa = &level[triangle_index(d + 1, i + 1, j)];
                let pb = &level[triangle_index(d + 1, i, j + 1)];
                let pc = &level[triangle_index(d + 1, i, j)];
                let q = pa
                    .iter()
                    .zip(pb)
                    .zip(pc)
                    .map(|((x, y), z)| u.mul(x).add(&v.mul(y)).add(&w.mul(z)))
                    .collect();
                next.push(q);
            }
        }
        level = next;
    }
    level.pop().expect("one point remains")
}

/// Control points w_v = b[b^v, a^(n-v)] of `curve` on [a, b], by the pyramid on its Bernstein
/// form over [0, 1].
pub fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let n = curve.degree();
    let control = power_to_bernstein(curve.coefficients());
    let points = (0..=n)
        .map(|v| bezier_curve_blossom(&control, &repeated(b, v, a, n - v)))
        .collect();
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

/// Control points p_{nu mu} = b[b^nu, a^(n-nu); d^mu, c^(m-mu)] of `surface` on
/// [a, b] x [c, d] (`rect = [a, b, c, d]`), by the two-pass pyramid on its Bernstein net over
/// [0, 1]^2.
pub fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let (n, m) = surface.degree();
    // Bernstein along v for every row i, then along u for every column mu.
    let rows: Vec<Vec<Point<T>>> = surface
        .coefficients()
        .iter()
        .map(|r| power_to_bernstein(r))
        .collect();
    let cols: Vec<Vec<Point<T>>> = (0..=m)
        .map(|mu| power_to_bernstein(&rows.iter().map(|r| r[mu].clone()).collect::<Vec<_>>()))
        .collect();
    let net: Vec<Vec<Point<T>>> = (0..=n)
        .map(|nu| cols.iter().map(|col| col[nu].clone()).collect())
        .collect();
    let points = tensor_net((n, m), rect, |us, vs| bezier_tensor_blossom(&net, us, vs));
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b[a^nu, b^mu, c^lambda] of `surface` (total degree
/// N = n + m) on the triangle with corners `tri = [a, b, c]`, by the triangular pyramid on its
/// Bernstein net over the reference triangle (1, 0), (0, 1), (0, 0), where a point (x, y) has
/// barycentric coordinates (x, y, 1 - x - y).
pub fn restrict_triangle<T: Ring>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (n, m) = surface.degree();
    let big_n = n + m;
    let dim = surface.dim();
    let mut d = vec![crate::point::zero::<T>(dim); triangle_len(big_n)];
    for (i, row) in surface.coefficients().iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            d[triangle_index(big_n, i, j)] = c.clone();
        }
    }
    let reference = triangle_power_to_bernstein(big_n, &d);
    let bary = |p: &[T; 2]| [p[0].clone(), p[1].clone(), T::one().sub(&p[0]).sub(&p[1])];
    let corners = tri.each_ref().map(bary);
    let points = triangle_net(big_n, &corners, |args| {
        bezier_triangle_blossom(&reference, args)
    });
    TriangularPatch::new(big_n, points).expect("a full triangular net")
}
