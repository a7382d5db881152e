//! Exact cross-checks of independent restriction methods against one another.

mod cross_check_exact;
mod peers;
mod total_degree;
