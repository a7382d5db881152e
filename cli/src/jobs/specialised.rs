//! `--method specialised`: the evaluators that the proc-macro generated at compile time for
//! fixed degrees (formulae (3), (9), (14) unrolled), carried by the binary (see
//! [`crate::specialised`]).
//!
//! This is the one place where they plug into the command line. A binary built without the
//! default feature `carried-grid` has none: [`BUILT_IN`] is then `false` and the command line
//! refuses `--method specialised` (exit 2, before reading any input) with [`NOT_BUILT_IN`].

use super::answer::Answer;
use super::job::Job;
use blossom::Error;

/// Whether this binary carries specialised evaluators at all.
pub const BUILT_IN: bool = cfg!(feature = "carried-grid");

/// The message (for the argument `--method`) when they are not built in.
pub const NOT_BUILT_IN: &str =
    "specialised evaluators are not built into this binary (built without the feature `carried-grid`)";

/// The answer of `job` by the specialised evaluator of its degree: `None` when this binary
/// has no specialised evaluators, `Some(Err(..))` naming the carried degrees for a degree it
/// does not carry.
#[cfg(feature = "carried-grid")]
pub fn specialised<T: crate::specialised::Carried>(
    job: &Job<T>,
) -> Option<Result<Answer<T>, Error>> {
    use crate::specialised::{
        carried_degrees, restrict_curve_specialised, restrict_tensor_specialised,
        restrict_triangle_specialised, Shape,
    };
    let (answer, shape) = match job {
        Job::Curve {
            curve,
            interval: [a, b],
        } => (
            restrict_curve_specialised(curve, a, b).map(Answer::Curve),
            Shape::Curve(curve.degree()),
        ),
        Job::Tensor { surface, rectangle } => {
            let (n, m) = surface.degree();
            (
                restrict_tensor_specialised(surface, rectangle).map(Answer::Tensor),
                Shape::Tensor(n, m),
            )
        }
        Job::Triangle { surface, triangle } => {
            let (n, m) = surface.degree();
            (
                restrict_triangle_specialised(surface, triangle).map(Answer::Triangle),
                Shape::Triangle(n, m),
            )
        }
        Job::TotalDegreeTriangle { surface, triangle } => (
            crate::specialised::restrict_power_triangle_specialised(surface, triangle)
                .map(Answer::Triangle),
            Shape::TriangleTotal(surface.degree()),
        ),
    };
    let what = match shape {
        Shape::TriangleTotal(n) => format!("triangular array of total degree {n}"),
        _ => format!("{} of degree {}", shape.keyword(), shape.degree_text()),
    };
    Some(answer.ok_or_else(|| {
        Error::new(
            "--method",
            format!(
                "no specialised evaluator for a {what}: this binary carries {}",
                carried_degrees()
            ),
        )
    }))
}

/// The Bézier curve `curve` restricted to [a, b] by the carried Bézier-input evaluator of its
/// degree: `None` when this binary has no specialised evaluators, `Some(Err(..))` naming the
/// carried degrees for a degree it does not carry.
#[cfg(feature = "carried-grid")]
pub fn specialised_bezier_curve<T: crate::specialised::Carried>(
    curve: &blossom::BezierCurve<T>,
    a: &T,
    b: &T,
) -> Option<Result<blossom::BezierCurve<T>, Error>> {
    use crate::specialised::{carried_degrees, restrict_bezier_curve_specialised};
    Some(
        restrict_bezier_curve_specialised(curve, a, b).ok_or_else(|| {
            Error::new(
                "--method",
                format!(
                    "no specialised evaluator for a Bézier curve of degree {}: this binary carries {}",
                    curve.degree(),
                    carried_degrees()
                ),
            )
        }),
    )
}

/// Without the carried grid there is no specialised evaluator.
#[cfg(not(feature = "carried-grid"))]
pub fn specialised_bezier_curve<T: blossom::Ring>(
    curve: &blossom::BezierCurve<T>,
    a: &T,
    b: &T,
) -> Option<Result<blossom::BezierCurve<T>, Error>> {
    let _ = (curve, a, b);
    None
}

/// Without the carried grid there is no specialised evaluator.
#[cfg(not(feature = "carried-grid"))]
pub fn specialised<T: blossom::Ring>(job: &Job<T>) -> Option<Result<Answer<T>, Error>> {
    let _ = job;
    None
}

/// The message for a degree this binary does not carry: what was asked and what is carried.
#[cfg(feature = "carried-grid")]
fn not_carried(what: String) -> Error {
    Error::new(
        "--method",
        format!(
            "no specialised evaluator for {what}: this binary carries {}",
            crate::specialised::carried_degrees()
        ),
    )
}

/// The Bézier patch `patch` restricted to `rect` by a carried Bézier-input evaluator of its
/// bidegree: `None` when this binary has no specialised evaluators, `Some(Err(..))` naming the
/// carried degrees for a bidegree it does not carry.
#[cfg(feature = "carried-grid")]
pub fn specialised_bezier_tensor<T: crate::specialised::Carried>(
    patch: &blossom::TensorPatch<T>,
    rect: &[T; 4],
) -> Option<Result<blossom::TensorPatch<T>, Error>> {
    let (n, m) = patch.degree();
    Some(
        crate::specialised::restrict_bezier_tensor_specialised(patch, rect).ok_or_else(|| {
            not_carried(format!(
                "a Bézier tensor-product patch of degree ({n}, {m})"
            ))
        }),
    )
}

/// The Bézier triangle `patch` restricted to the sub-triangle with corners `plane` (each given
/// by its first two barycentric coordinates) by a carried Bézier-input evaluator of its degree:
/// `None` when this binary has no specialised evaluators, `Some(Err(..))` naming the carried
/// degrees for a degree it does not carry.
#[cfg(feature = "carried-grid")]
pub fn specialised_bezier_triangle<T: crate::specialised::Carried>(
    patch: &blossom::TriangularPatch<T>,
    plane: &[[T; 2]; 3],
) -> Option<Result<blossom::TriangularPatch<T>, Error>> {
    Some(
        crate::specialised::restrict_bezier_triangle_specialised(patch, plane).ok_or_else(|| {
            not_carried(format!(
                "a Bézier triangular patch of degree {}",
                patch.degree()
            ))
        }),
    )
}

/// Without the carried grid there is no specialised evaluator.
#[cfg(not(feature = "carried-grid"))]
pub fn specialised_bezier_tensor<T: blossom::Ring>(
    patch: &blossom::TensorPatch<T>,
    rect: &[T; 4],
) -> Option<Result<blossom::TensorPatch<T>, Error>> {
    let _ = (patch, rect);
    None
}

/// Without the carried grid there is no specialised evaluator.
#[cfg(not(feature = "carried-grid"))]
pub fn specialised_bezier_triangle<T: blossom::Ring>(
    patch: &blossom::TriangularPatch<T>,
    plane: &[[T; 2]; 3],
) -> Option<Result<blossom::TriangularPatch<T>, Error>> {
    let _ = (patch, plane);
    None
}
