//! The `blossom` binary driven as a process: `blossom restrict`, the spline jobs,
//! `blossom intersect`, `blossom region` (with its exact polygon oracle), `blossom check` and
//! `blossom figures` (its SVGs rendered to pixels).

mod binary;
#[path = "../../../tests/common/mod.rs"]
mod common;

mod cli_args;
mod cli_budget;
mod cli_check;
mod cli_error_bounds;
mod cli_intersect;
mod cli_jobs;
mod cli_patch_jobs;
mod cli_region;
mod cli_region_forms;
mod cli_restrict;
mod cli_spline_jobs;
mod figures;
mod fuzz_corpus;
mod intersect_corpus;
mod region_oracle;
