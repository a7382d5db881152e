//! `--method specialised`: the evaluators that the proc-macro generated at compile time for
//! fixed degrees (formulae (3), (9), (14) unrolled), carried by the binary (see
//! [`crate::specialised`]). A binary built without the default feature `carried-grid` has
//! none: [`BUILT_IN`] is then `false` and `blossom restrict` refuses `--method specialised`
//! (exit 2, before reading any input) with [`NOT_BUILT_IN`].

use blossom::TriangularPatch;
use blossom::{BezierCurve, Error, PowerCurve, PowerSurface, PowerTriangle, TensorPatch};

/// Whether this binary carries specialised evaluators at all.
pub const BUILT_IN: bool = cfg!(feature = "carried-grid");

/// The message (for the argument `--method`) when they are not built in.
pub const NOT_BUILT_IN: &str =
    "specialised evaluators are not built into this binary (built without the feature `carried-grid`)";

/// One wrapper per carried family: the evaluator's answer, or the refusal naming what was
/// asked (`a curve of degree 17`) and the degrees this binary carries.
macro_rules! carried {
    ($(#[$doc:meta] $name:ident($($arg:ident: $ty:ty),*) -> $out:ty = $evaluator:ident, $what:expr;)*) => {$(
        #[$doc]
        #[cfg(feature = "carried-grid")]
        pub fn $name<T: crate::specialised::Carried>($($arg: $ty),*) -> Result<$out, Error> {
            crate::specialised::$evaluator($($arg),*).ok_or_else(|| {
                Error::new(
                    "--method",
                    format!(
                        "no specialised evaluator for {}: this binary carries {}",
                        $what,
                        crate::specialised::carried_degrees()
                    ),
                )
            })
        }

        #[$doc]
        #[cfg(not(feature = "carried-grid"))]
        pub fn $name<T: blossom::Ring>($($arg: $ty),*) -> Result<$out, Error> {
            let _ = ($($arg),*);
            Err(Error::new("--method", NOT_BUILT_IN))
        }
    )*};
}

carried! {
    /// A `curve` job.
    curve(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> = restrict_curve_specialised,
        format!("a curve of degree {}", curve.degree());
    /// A `tensor` job.
    tensor(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> = restrict_tensor_specialised,
        format!("a tensor of degree {:?}", surface.degree());
    /// A `triangle` job of a rectangular grid.
    triangle(surface: &PowerSurface<T>, corners: &[[T; 2]; 3]) -> TriangularPatch<T> = restrict_triangle_specialised,
        format!("a triangle of degree {:?}", surface.degree());
    /// A `triangle` job of a triangular array.
    total_triangle(surface: &PowerTriangle<T>, corners: &[[T; 2]; 3]) -> TriangularPatch<T> = restrict_power_triangle_specialised,
        format!("a triangular array of total degree {}", surface.degree());
    /// A `bezier-curve` job.
    bezier_curve(curve: &BezierCurve<T>, a: &T, b: &T) -> BezierCurve<T> = restrict_bezier_curve_specialised,
        format!("a Bézier curve of degree {}", curve.degree());
    /// A `bezier-tensor` job.
    bezier_tensor(patch: &TensorPatch<T>, rect: &[T; 4]) -> TensorPatch<T> = restrict_bezier_tensor_specialised,
        format!("a Bézier tensor-product patch of degree {:?}", patch.degree());
    /// A `bezier-triangle` job (corners by their first two barycentric coordinates).
    bezier_triangle(patch: &TriangularPatch<T>, plane: &[[T; 2]; 3]) -> TriangularPatch<T> = restrict_bezier_triangle_specialised,
        format!("a Bézier triangular patch of degree {}", patch.degree());
}
