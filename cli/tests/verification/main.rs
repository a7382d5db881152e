//! `blossom verify` and the symbolic proofs: the papers' tables and examples re-derived, the
//! methods proved identical as polynomials, and the measured f64 accuracy.

#[path = "../../../tests/common/mod.rs"]
mod common;

mod new_sections;
mod paper_tables;
mod seeds_002_004;
mod symbolic_proofs;
