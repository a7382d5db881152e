//! The library's integration tests, one test binary: each of these modules used to be a test
//! crate of its own, and every test crate links the library anew and instantiates its generic
//! code again (at the test profile's `opt-level = 2`), so one crate compiles that once.
//!
//! - `applications`: batches, degree change, derivatives, rational curves and surfaces,
//!   B-splines, the inverse formula for closures, interop, the examples run as tests;
//! - `bezier_input`: restriction of Bézier input (curves, tensor patches, triangles) against
//!   de Casteljau's pyramid on the blossom, exactly, symbolically and in f64;
//! - `cross_checks`: exact cross-checks of independent restriction methods and of peers;
//! - `macros`: `blossom::restriction!` proved symbolically, its printed expansion compiled, its
//!   misuses' compile errors (trybuild, `tests/ui`).
//!
//! Run one part with a filter: `cargo test -p blossom --test suite applications::`.

#[path = "../common/mod.rs"]
mod common;

mod applications;
mod bezier_input;
mod cross_checks;
mod macros;
