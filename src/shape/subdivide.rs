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
//! All control points come from the halving engine ([`crate::curve_net`],
//! [`crate::tensor_net`], [`crate::triangle_net`]) with de Casteljau's affine steps: the input
//! stays in the Bernstein basis, every step is (1 - t) x + t y (or its triangular form), and
//! the work is shared between control points. The costs are O(n^2) per curve, O(nm(n + m))
//! per tensor patch and O(N^3) per triangular patch, division-free, so the same code runs on
//! f64, exact rationals and symbolic polynomials, and in f64 it is as accurate as one
//! de Casteljau pyramid per control point (`tests/accuracy` measures both on the same inputs).
//!
//! These functions take and return the runtime-dimension shapes; the coordinates are copied to
//! one contiguous run in and out. [`crate::Bezier`] and its siblings store contiguous `[T; D]`
//! points and restrict without any allocation.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::halving::{
    curve_net, tensor_net, triangle_net, BernsteinPairStep, BernsteinStep,
};
use crate::shape::point::points_of;
use crate::Ring;

/// The Bézier curve `curve` over [0, 1] restricted to [a, b] (any a, b, also outside [0, 1]
/// or with a > b): control points q_j = b[a^(n-j), b^j]. O(n^2) per coordinate, by halving.
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
    let dim = curve.control_points()[0].len();
    let flat = curve.control_points().concat();
    let mut out = vec![T::zero(); flat.len()];
    let (a, b) = (BernsteinStep(a), BernsteinStep(b));
    curve_net(&flat, dim, &a, &b, &mut out, &mut Vec::new());
    BezierCurve::new(points_of(&out, dim)).expect("n + 1 points of one dimension")
}

/// The tensor-product patch `patch` over [0, 1]^2 restricted to `rect = [a, b, c, d]`, i.e.
/// [a, b] x [c, d]: control points p_(nu mu) = b[a^(n-nu), b^nu; c^(m-mu), d^mu].
/// The curve algorithm along u with whole rows as points, then along v for every row:
/// O(nm(n + m)) per coordinate.
pub fn restrict_bezier_tensor<T: Ring>(patch: &TensorPatch<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let dim = patch.control_points()[0][0].len();
    let cols = patch.control_points()[0].len();
    let flat: Vec<T> = patch.flat_coordinates();
    let mut out = vec![T::zero(); flat.len()];
    let steps = rect.each_ref().map(BernsteinStep);
    tensor_net(
        &flat,
        cols,
        dim,
        steps.each_ref(),
        &mut out,
        &mut Vec::new(),
    );
    let net = out
        .chunks(cols * dim)
        .map(|row| points_of(row, dim))
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
    let flat = patch.control_points().concat();
    let mut out = vec![T::zero(); flat.len()];
    let steps = corners.each_ref().map(BernsteinPairStep);
    triangle_net(&flat, n, dim, steps.each_ref(), &mut out, &mut Vec::new());
    TriangularPatch::new(n, points_of(&out, dim)).expect("a triangular net")
}
