//! Rational curves and surfaces through the blossoms of their homogeneous form (seed 004,
//! section 4 and Example 1).
//!
//! A rational curve x(t) = N(t) / w(t) (numerator N with points of dimension D, scalar
//! denominator w) is the central projection of the polynomial curve H(t) = (N(t), w(t)) of
//! dimension D + 1. Its control points and weights on [alpha, beta] at degree n are read off
//! the homogeneous control points h_i = H[alpha^(n-i), beta^i] = (w_i b_i, w_i), which the
//! inverse formula (22) computes from points of H alone
//! ([`crate::curve_control_points_from_samples`]); any n at least the degree of H gives a
//! degree-elevated description of the same curve. Surfaces work the same way with the tensor
//! (two passes of (22)) and triangle (eq. (23)) versions.
//!
//! Storage: every shape keeps its numbers in flat buffers, `D` (or `D + 1`) numbers per point,
//! point after point. The power forms ([`RationalCurve`], [`RationalSurface`],
//! [`RationalPowerTriangle`]) store the homogeneous polynomial (N, w) in one buffer; the
//! rational Bézier forms ([`RationalBezierCurve`], [`RationalTensorPatch`],
//! [`RationalTriangularPatch`]) store (points, weights): the points b_i in one buffer, the
//! weights w_i in another, so that both read as slices; evaluation and restriction lift them
//! to (w_i b_i, w_i) in a working buffer the caller may own and project the result.
//!
//! Rational B-splines (NURBS) are B-splines of homogeneous control points (w_i d_i, w_i);
//! [`RationalBSpline`] evaluates them by de Boor's algorithm and projects (the surfaces,
//! [`crate::RationalBSplineSurface`], are in `spline/rational_surface.rs`).
//!
//! One job per module: `homogeneous` (lift, project, restrict through the homogeneous points),
//! `curve`, `tensor`, `triangle` (the rational Bézier shapes), `power` (the power forms and
//! their Bézier forms by the inverse formula), `nurbs` (the NURBS curve).

mod curve;
pub(crate) mod homogeneous;
mod nurbs;
mod power;
mod tensor;
mod triangle;

#[cfg(test)]
mod flat_tests;

pub(crate) use crate::applications::spline::bspline::wrong_out;
pub use curve::RationalBezierCurve;
pub use nurbs::RationalBSpline;
pub use power::{RationalCurve, RationalPowerTriangle, RationalSurface};
pub use tensor::RationalTensorPatch;
pub use triangle::RationalTriangularPatch;

use crate::error::{Error, ErrorKind, Result};

/// `e` with its field's prefix `from` replaced by `to` (a checked constructor's error, renamed
/// to the caller's parameter).
pub(crate) fn rename(mut e: Error, from: &str, to: &str) -> Error {
    if let Some(rest) = e.field.strip_prefix(from) {
        e.field = format!("{to}{rest}");
    }
    e
}

/// Checks one weight per point (`count` points).
pub(crate) fn check_weight_count<T>(weights: &[T], count: usize) -> Result<()> {
    if weights.len() == count {
        Ok(())
    } else {
        Err(Error::of(
            ErrorKind::Shape,
            "weights",
            format!("expected {count} weights, found {}", weights.len()),
        ))
    }
}

/// The error of a restriction whose weight `which` vanishes on the part `part`, about the
/// argument `field` that chose the part.
pub(crate) fn zero_weight_of_part(field: &str, which: String, part: String) -> Error {
    Error::of(
        ErrorKind::ZeroWeight,
        field,
        format!(
            "the weight {which} of the part over {part} is zero: it has no rational Bézier form \
             with finite control points"
        ),
    )
}
