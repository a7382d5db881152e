//! Exact cross-checks of independent restriction methods against one another.

#[path = "../common/mod.rs"]
mod common;

mod cross_check_exact;
mod peers;
mod total_degree;
