//! The inputs shared by the region benchmarks (`benches/region.rs` of the root crate includes
//! [`shapes`] by path) and this crate's comparison with flo_curves (`benches/flo_curves.rs`).
//!
//! Run: `cd benches/region_peers && cargo bench` (see that file for what it prints).

#[path = "../../common/mod.rs"]
pub mod common;
pub mod shapes;
