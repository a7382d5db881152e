//! The pyramid (de Casteljau) algorithm for blossoms, seed 004 section 2.
//!
//! * curve, eq. (2) of 004: b^r_i[t_1..t_r] = (1 - t_r) b^{r-1}_i + t_r b^{r-1}_{i+1}, and the
//!   blossom is b^n_0[t_1..t_n];
//! * tensor patch, eq. (9) of 004: `b[u_1..u_n; v_1..v_m] = b[u_1..u_n][v_1..v_m]`, the curve
//!   pyramid along v for every row, then along u;
//! * triangle: b^r_{ijk} = u_r b^{r-1}_{i+1,j,k} + v_r b^{r-1}_{i,j+1,k} + w_r b^{r-1}_{i,j,k+1}
//!   for barycentric arguments (u_r, v_r, w_r).
//!
//! Restriction by the pyramid first writes the power-basis input in Bernstein form over a
//! reference domain, then evaluates the blossom at the new domain's corners: O(n^2) per control
//! point of a curve. The reference domain is the new one enlarged about its centre by the factor
//! k = (n + 1) / n for degree n: [a - h, b + h] with h = (b - a) / (2n) for [a, b] (a and b sit
//! at the local parameters 1 / (2(n + 1)) and (2n + 1) / (2(n + 1))), the product of two such
//! intervals for a rectangle, and for a triangle of degree N its image under the homothety of
//! ratio (N + 1) / N about the centroid. Every de Casteljau step is then a convex combination,
//! which is what keeps the pyramid stable in floating point: over a fixed reference domain
//! ([0, 1], the unit triangle) corners far outside it make every step an extrapolation, and
//! the error grows like the corners' barycentric coordinates to the power n. The enlargement
//! costs accuracy the other way: the Bernstein coefficients over the reference domain are
//! larger than the answer by up to k^n, which is at most e for k = (n + 1) / n, where a fixed
//! factor 2 would cost up to 2^n (`BENCHMARKS.md` has the measured errors). The choice uses
//! ring operations only, so the symbolic proofs cover it. The Bernstein form over the reference domain comes from Horner's rule carried out in
//! the Bernstein basis ([`crate::engine::bernstein_by_horner`], [`crate::engine::triangle_bernstein_by_horner`]),
//! not from the Taylor shift of [`crate::Method::TaylorShift`], so the pyramid computes through no other
//! method.

use crate::restrict::nets::{repeated, tensor_net, triangle_net};
use crate::shape::basis::{bernstein_by_horner, triangle_bernstein_by_horner};
use crate::shape::bezier::{triangle_blossom_unchecked, BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::flat::{curve_blossom, tensor_blossom};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::Ring;

/// The enlargement k = (n + 1) / n of the reference domain for degree n (module docs), as the
/// integer n (at least 1, a degree of 0 being served by any k).
fn enlargement(degree: usize) -> i128 {
    degree.max(1) as i128
}

/// The reference interval [a - h, b + h], h = (b - a) / (2n), of [a, b] for degree n: [a, b]
/// enlarged by k = (n + 1) / n about its centre.
fn reference_interval<T: Ring>(a: &T, b: &T, degree: usize) -> [T; 2] {
    let h = b.sub(a).scale_frac(1, 2 * enlargement(degree));
    [a.sub(&h), b.add(&h)]
}

/// The local parameters 1 / (2(n + 1)) and (2n + 1) / (2(n + 1)) of a and b in their
/// reference interval.
fn local_ends<T: Ring>(degree: usize) -> [T; 2] {
    let n = enlargement(degree);
    [
        T::one().scale_frac(1, 2 * (n + 1)),
        T::one().scale_frac(2 * n + 1, 2 * (n + 1)),
    ]
}

/// Control points w_v = b[b^v, a^(n-v)] of `curve` on [a, b], by the pyramid on its Bernstein
/// form over the reference interval [a - h, b + h], h = (b - a) / (2n).
pub fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let n = curve.degree();
    let [ra, rb] = reference_interval(a, b, n);
    let dim = curve.dim();
    let control = bernstein_by_horner(curve.coordinates(), dim, &ra, &rb);
    let [ta, tb] = local_ends::<T>(n);
    let points = (0..=n)
        .map(|v| curve_blossom(&control, dim, &repeated(&tb, v, &ta, n - v)))
        .collect();
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

/// Control points p_{nu mu} = b[b^nu, a^(n-nu); d^mu, c^(m-mu)] of `surface` on
/// [a, b] x [c, d] (`rect = [a, b, c, d]`), by the two-pass pyramid on its Bernstein net over
/// the product of the reference intervals of [a, b] (degree n) and [c, d] (degree m).
pub fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let (n, m) = surface.degree();
    let [a, b, c, d] = rect;
    let [ra, rb] = reference_interval(a, b, n);
    let [rc, rd] = reference_interval(c, d, m);
    let dim = surface.dim();
    // Along u with whole rows as points, then along v row by row.
    let rows = bernstein_by_horner(surface.coordinates(), (m + 1) * dim, &ra, &rb);
    let net: Vec<T> = rows
        .chunks_exact((m + 1) * dim)
        .flat_map(|row| bernstein_by_horner(row, dim, &rc, &rd))
        .collect();
    let net = &net;
    let [ta, tb] = local_ends::<T>(n);
    let [tc, td] = local_ends::<T>(m);
    let points = tensor_net((n, m), &[ta, tb, tc, td], |us, vs| {
        tensor_blossom(net, m + 1, dim, us, vs)
    });
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b[a^nu, b^mu, c^lambda] of `surface` (total degree N) on the triangle with corners `tri = [a, b, c]`, by the triangular pyramid on its
/// Bernstein net over the reference triangle g + k(p - g), p = a, b, c (g the centroid,
/// k = (N + 1) / N), in which each corner p has the barycentric coordinate (3N + 1) / (3(N + 1))
/// on its own enlarged corner and 1 / (3(N + 1)) on the two others.
pub fn restrict_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let big_n = surface.degree();
    let k = enlargement(big_n);
    let [a, b, c] = tri;
    // g + k (p - g) = ((3N + 2) p - q - r) / (3N).
    let enlarged = |p: &[T; 2], q: &[T; 2], r: &[T; 2]| -> [T; 2] {
        std::array::from_fn(|x| {
            p[x].scale_frac(3 * k + 2, 3 * k)
                .sub(&q[x].add(&r[x]).scale_frac(1, 3 * k))
        })
    };
    let reference_corners = [enlarged(a, b, c), enlarged(b, a, c), enlarged(c, a, b)];
    let reference = triangle_bernstein_by_horner(surface, &reference_corners);
    let (major, minor) = (
        T::one().scale_frac(3 * k + 1, 3 * (k + 1)),
        T::one().scale_frac(1, 3 * (k + 1)),
    );
    let local = [
        [major.clone(), minor.clone(), minor.clone()],
        [minor.clone(), major.clone(), minor.clone()],
        [minor.clone(), minor, major],
    ];
    let points = triangle_net(big_n, &local, |args| {
        triangle_blossom_unchecked(&reference, args)
    });
    TriangularPatch::new(big_n, points).expect("a full triangular net")
}
