//! Interoperation with the ecosystem's types, each behind an optional feature: mint's,
//! kurbo's and lyon_geom's points and curves (conversions, `with_mint.rs`, `with_kurbo.rs`,
//! `with_lyon.rs`, on the one trait and the one segment macro of `points.rs`), kurbo's paths
//! as regions and boolean answers (`kurbo_region.rs`) and serde (`with_serde.rs`). This layer
//! sits beside the applications: it imports the shapes, applications and regions, and nothing
//! imports it but for one re-export (`region::binary_op`, the kurbo one-call boolean).

#[cfg(feature = "kurbo")]
pub(crate) mod kurbo_region;
#[cfg(any(feature = "mint", feature = "kurbo", feature = "lyon"))]
pub(crate) mod points;
#[cfg(feature = "kurbo")]
mod with_kurbo;
#[cfg(feature = "lyon")]
mod with_lyon;
#[cfg(feature = "mint")]
mod with_mint;
#[cfg(feature = "serde")]
mod with_serde;
