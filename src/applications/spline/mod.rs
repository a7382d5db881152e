//! B-spline curves through blossoms (seed 002): validated knot vectors, de Boor points as
//! blossom values of the polynomial pieces (Theorem 2.2), de Boor's algorithm as blossom
//! evaluation (Theorem 2.3), piecewise polynomials as B-splines (Curry-Schoenberg, Theorem 2.4),
//! knot insertion and the split into Bézier pieces; and, independently of blossoms, the
//! normalised B-splines by their recursive definition (Definition 1.1) as a cross-check.
//! Tensor-product surfaces (`surface.rs`, `surface_pieces.rs`) run the curve algorithms in one
//! variable at a time; their rational (NURBS) form is `rational_surface.rs`.
//!
//! Knots and points share one number type, a [`Field`](crate::num::linalg::Field): exact
//! [`Rational`](crate::Rational) or `f64`.

pub(crate) mod bspline;
pub(crate) mod cox_de_boor;
pub(crate) mod curry_schoenberg;
pub(crate) mod de_boor;
#[cfg(test)]
mod flat_tests;
pub(crate) mod knots;
pub(crate) mod rational_surface;
pub(crate) mod surface;
pub(crate) mod surface_pieces;

pub use bspline::{BSpline, BezierPiece};
pub use cox_de_boor::{bspline_basis_on_span, PowerPiece};
pub use curry_schoenberg::{
    bspline_from_pieces, bspline_from_pieces_with_knots, continuity_at, Piece,
};
pub use knots::KnotVector;
pub use rational_surface::{RationalBSplineSurface, RationalBezierCell};
pub use surface::{BSplineSurface, BezierCell};
pub use surface_pieces::{bspline_surface_from_pieces, SurfacePiece};
