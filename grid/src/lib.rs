//! The carried grid of the `blossom` binary: the evaluators that `blossom::restriction!`
//! generates for curves of degree 1..=16, tensor patches up to (5, 5) and triangles with
//! n, m <= 4, instantiated once on [`Scalar`], and their dispatch from the library types.
//!
//! A crate of its own so that the grid is compiled once per profile: the application's unit
//! tests, its integration tests and the binary all link this one compiled copy (the crate has
//! no tests of its own; `blossom-cli` tests it). Without the feature `carried` only
//! [`Scalar`] and [`Carried`] are here.
#![forbid(unsafe_code)]

#[cfg(feature = "carried")]
mod carried;
mod scalar;

#[cfg(feature = "carried")]
pub use carried::{
    grid, restrict_bezier_curve_specialised, restrict_bezier_tensor_specialised,
    restrict_bezier_triangle_specialised, restrict_curve_specialised,
    restrict_power_triangle_specialised, restrict_tensor_specialised,
    restrict_triangle_specialised,
};
pub use scalar::{Carried, Scalar};
