//! `blossom figures`: the papers' pictures drawn from values the library computes, never from
//! transcribed coordinates (only the inputs are transcribed: Example 1's coefficients, the
//! rectangles and triangles, the de Boor points and knots, the arc's and ln's definitions, the
//! control points of the intersecting curves).
//!
//! * [`patches`]: Figures 1 and 2 of the subdivision paper (S_1, S_2 by formula (9); S_3, S_4
//!   by formula (14)), surfaces as iso-parameter lines in 3-D with their control nets;
//! * [`spline`]: the cubic B-spline of seed 002 with its de Boor polygon and knots;
//! * [`circle`]: the circle arc of seed 004 as a rational quadratic and quartic with weights;
//! * [`logarithm`]: the ln t cubic of seed 004 against ln t, and its error;
//! * [`intersections`]: certified intersections (issue 26): crossings, a tangency, an overlap
//!   and a loop, every mark from the library's exact answer;
//! * [`regions`]: certified booleans (issue 40): two regions with a shared edge, a tangency
//!   and crossings, and their union, intersection and difference filled from the exact answer.
//!
//! A picture is first a [`Figure`] ([`scene`]: plain f64 layers in drawing order), then an SVG
//! ([`render`], plotters' SVG backend). [`pixels`] puts any point on the page through the same
//! chart the drawing builds, so that tests can check that control points land where they
//! should. Every dot colour ([`palette::DOT_COLOURS`]) is used for dots only.

pub mod circle;
pub mod intersections;
pub mod logarithm;
pub mod mesh;
pub mod palette;
pub mod patches;
pub mod regions;
pub mod render;
pub mod scene;
pub mod spline;
mod write;

pub use render::{pixels, svg, HEADER, SIZE};
pub use scene::{Figure, Layer, Point3, Rgb, View};
pub use write::write_figures;

use blossom::Error;

/// Every picture, in the order they are written.
pub fn figures() -> Result<Vec<Figure>, Error> {
    let mut all = patches::figures()?;
    all.push(spline::figure()?);
    all.extend(circle::figures()?);
    all.push(logarithm::figure()?);
    all.push(logarithm::error_figure()?);
    all.push(intersections::figure()?);
    all.push(regions::figure()?);
    Ok(all)
}
