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
//! the error grew like the corners' barycentric coordinates to the power n (relative error
//! 2e-2 measured on a sextic triangle with a corner at y = 737). The enlargement costs accuracy
//! the other way: the Bernstein coefficients over the reference domain are larger than the
//! answer by up to k^n, which is at most e for k = (n + 1) / n (a fixed factor 2 cost 3e-1
//! at curve degree 24 where this choice gives 1e-6, as the bulk path: `cargo run --release
//! --example float_error`). The choice uses ring operations only, so the symbolic proofs
//! cover it. The Bernstein form over the reference domain comes from the bulk change of basis
//! ([`crate::restrict`], `Method::Bulk`); the pyramid's own part is the blossom evaluation.

use crate::bezier::{triangle_index, triangle_len, BezierCurve, TensorPatch, TriangularPatch};
use crate::blossoms::{repeated, tensor_net, triangle_net};
use crate::point::{lerp, Point};
use crate::power::{PowerCurve, PowerSurface};
use crate::restrict::{bulk_curve_points, Method};
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
    let control = bulk_curve_points(curve.coefficients().to_vec(), &ra, &rb);
    let [ta, tb] = local_ends::<T>(n);
    let points = (0..=n)
        .map(|v| bezier_curve_blossom(&control, &repeated(&tb, v, &ta, n - v)))
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
    let reference = crate::restrict::restrict_tensor(surface, &[ra, rb, rc, rd], Method::Bulk);
    let [ta, tb] = local_ends::<T>(n);
    let [tc, td] = local_ends::<T>(m);
    let net = reference.control_points();
    let points = tensor_net((n, m), &[ta, tb, tc, td], |us, vs| {
        bezier_tensor_blossom(net, us, vs)
    });
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b[a^nu, b^mu, c^lambda] of `surface` (total degree
/// N = n + m) on the triangle with corners `tri = [a, b, c]`, by the triangular pyramid on its
/// Bernstein net over the reference triangle g + k(p - g), p = a, b, c (g the centroid,
/// k = (N + 1) / N), in which each corner p has the barycentric coordinate (3N + 1) / (3(N + 1))
/// on its own enlarged corner and 1 / (3(N + 1)) on the two others.
pub fn restrict_triangle<T: Ring>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (n, m) = surface.degree();
    let k = enlargement(n + m);
    let [a, b, c] = tri;
    // g + k (p - g) = ((3N + 2) p - q - r) / (3N).
    let enlarged = |p: &[T; 2], q: &[T; 2], r: &[T; 2]| -> [T; 2] {
        std::array::from_fn(|x| {
            p[x].scale_frac(3 * k + 2, 3 * k)
                .sub(&q[x].add(&r[x]).scale_frac(1, 3 * k))
        })
    };
    let reference_corners = [enlarged(a, b, c), enlarged(b, a, c), enlarged(c, a, b)];
    let reference = crate::restrict::restrict_triangle(surface, &reference_corners, Method::Bulk);
    let (major, minor) = (
        T::one().scale_frac(3 * k + 1, 3 * (k + 1)),
        T::one().scale_frac(1, 3 * (k + 1)),
    );
    let local = [
        [major.clone(), minor.clone(), minor.clone()],
        [minor.clone(), major.clone(), minor.clone()],
        [minor.clone(), minor, major],
    ];
    let points = triangle_net(n + m, &local, |args| {
        bezier_triangle_blossom(&reference, args)
    });
    TriangularPatch::new(n + m, points).expect("a full triangular net")
}
