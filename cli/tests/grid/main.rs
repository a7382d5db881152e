//! The carried grid of generated evaluators (feature `carried-grid`), its dispatch and its
//! proofs, the printed expansion, and the expansion of `blossom-codegen` as snapshots.

#[path = "../../../tests/common/mod.rs"]
mod common;

mod expanded_files;
mod macros_proofs;
mod macros_snapshots;
mod macros_specialised;
