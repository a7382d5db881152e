//! Restriction of Bézier input (control points, not power coefficients): a Bézier curve over
//! [0, 1] to a sub-interval, a tensor-product patch over [0, 1]^2 to a sub-rectangle, and a
//! triangular patch to a sub-triangle given in barycentric coordinates of its own domain.
//!
//! The answer is a net of blossom values (seed 004, section 2):
//!
//! * curve: q_j = b[a^(n-j), b^j], j = 0..=n;
//! * tensor patch on [a, b] x [c, d]: p_(nu mu) = b[a^(n-nu), b^nu; c^(m-mu), d^mu];
//! * triangle with corners A, B, C: q_(nu mu lambda) = b[A^nu, B^mu, C^lambda].
//!
//! Every control point could be computed on its own by de Casteljau's pyramid on the blossom
//! ([`crate::blossoms::pyramid`]), O(n^2) per point and O(n^3) in all for a curve. Here they
//! are computed together, as the subdivision paper's conclusion suggests, by a change of
//! basis and an affine change of variable:
//!
//! 1. to the power basis by forward differences ([`crate::shape::basis::bernstein_to_power`],
//!    [`crate::shape::basis::triangle_bernstein_to_power`]): c_k = C(n, k) Δ^k b_0;
//! 2. the bulk restriction of the power form ([`crate::restrict`], [`crate::Method::Bulk`]):
//!    a Taylor shift and a scaling, then the Bernstein form.
//!
//! The costs are O(n^2) per curve, O(nm(n + m)) per tensor patch (curve passes along rows,
//! then along columns) and O(N^3) per triangular patch. Every step is division-free, so the
//! same code runs on f64, exact rationals and symbolic polynomials. The tests prove it equal to
//! the pyramid for every control point. In f64 the power basis costs accuracy at high degree
//! (`examples/float_error.rs` measures it).

use crate::error::{Error, ErrorKind, Result};
use crate::restrict::bulk::{bulk_curve_points, bulk_triangle_grid};
use crate::shape::basis::{bernstein_to_power, triangle_bernstein_to_power};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point::{self, flatten, unflatten, Point};
use crate::shape::simplex::triangle_index;
use crate::Ring;

/// The Bézier curve `curve` over [0, 1] restricted to [a, b] (any a, b, also outside [0, 1]
/// or with a > b): control points q_j = b[a^(n-j), b^j]. O(n^2) per coordinate.
///
/// ```
/// use blossom::{restrict_bezier_curve, BezierCurve};
/// // The left half of the cubic (0,0), (1,2), (3,3), (4,0), as de Casteljau splits it.
/// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 3.0], vec![4.0, 0.0]])?;
/// let left = restrict_bezier_curve(&c, &0.0, &0.5);
/// assert_eq!(left.control_points()[2], vec![1.25, 1.75]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn restrict_bezier_curve<T: Ring>(curve: &BezierCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let power = bernstein_to_power(curve.control_points());
    BezierCurve::new(bulk_curve_points(power, a, b)).expect("n + 1 points of one dimension")
}

/// The tensor-product patch `patch` over [0, 1]^2 restricted to `rect = [a, b, c, d]`, i.e.
/// [a, b] x [c, d]: control points p_(nu mu) = b[a^(n-nu), b^nu; c^(m-mu), d^mu].
/// The curve algorithm along u with whole rows as points, then along v for every row:
/// O(nm(n + m)) per coordinate.
pub fn restrict_bezier_tensor<T: Ring>(patch: &TensorPatch<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let [a, b, c, d] = rect;
    let dim = patch.control_points()[0][0].len();
    let rows = flatten(patch.control_points());
    let rows = unflatten(bulk_curve_points(bernstein_to_power(&rows), a, b), dim);
    let net = rows
        .iter()
        .map(|row| bulk_curve_points(bernstein_to_power(row), c, d))
        .collect();
    TensorPatch::new(net).expect("a rectangular net")
}

/// The triangular patch `patch` restricted to the sub-triangle with corners `corners = [A, B,
/// C]`, each given by its barycentric coordinates (w.r.t. the patch's own corners, in the
/// order of the net's indices): control points q_(nu mu lambda) = b[A^nu, B^mu, C^lambda], in
/// the order of [`TriangularPatch`]. O(N^3) per coordinate.
///
/// # Errors
/// `corners[k]` when the coordinates of corner k do not add up to 1 ([`Ring::is_zero`] of
/// their sum minus one). Under exact arithmetic that is exact. Under f64 it asks for a sum that
/// rounds to exactly 1, which holds for coordinates such as (0.25, 0.25, 0.5) but may fail
/// for (0.1, 0.2, 0.7). Use [`restrict_bezier_triangle_affine`], which takes two coordinates
/// per corner, when the third is 1 minus the others by construction.
pub fn restrict_bezier_triangle<T: Ring>(
    patch: &TriangularPatch<T>,
    corners: &[[T; 3]; 3],
) -> Result<TriangularPatch<T>> {
    for (k, [s, t, r]) in corners.iter().enumerate() {
        if !s.add(t).add(r).sub(&T::one()).is_zero() {
            return Err(Error::of(
                ErrorKind::Dimension,
                format!("corners[{k}]"),
                "barycentric coordinates must add up to 1",
            ));
        }
    }
    let affine = corners.each_ref().map(|[s, t, _]| [s.clone(), t.clone()]);
    Ok(restrict_bezier_triangle_affine(patch, &affine))
}

/// [`restrict_bezier_triangle`] with each corner given by its first two barycentric
/// coordinates (s, t); the third is 1 - s - t. These are also the (u, v) coordinates of the
/// corner when the patch's domain is the triangle (1, 0), (0, 1), (0, 0).
pub fn restrict_bezier_triangle_affine<T: Ring>(
    patch: &TriangularPatch<T>,
    corners: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let n = patch.degree();
    let dim = patch.control_points()[0].len();
    // The power form in (s, t) as an (N+1) x (N+1) grid, zero where i + j > N.
    let power = triangle_bernstein_to_power(patch);
    let grid: Vec<Vec<Point<T>>> = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    if i + j <= n {
                        power[triangle_index(n, i, j)].clone()
                    } else {
                        point::zero(dim)
                    }
                })
                .collect()
        })
        .collect();
    bulk_triangle_grid(&grid, n, corners)
}
