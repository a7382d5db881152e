//! The `blossom` binary driven as a process: `blossom restrict` and the spline jobs.

mod binary;
#[path = "../../../tests/common/mod.rs"]
mod common;

mod cli_budget;
mod cli_check;
mod cli_error_bounds;
mod cli_patch_jobs;
mod cli_restrict;
mod cli_spline_jobs;
mod fuzz_corpus;
