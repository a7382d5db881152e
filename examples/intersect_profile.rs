//! A profiling aid for the float filter of curve-curve intersection: runs
//! [`blossom::certified_crossings_f64`] on the random cubic pairs of `benches/intersect.rs`
//! (the same SplitMix64 generator, seed 26) and prints how many it decided, the number of
//! crossings and the wall time per pair. Under callgrind:
//!
//! `valgrind --tool=callgrind target/release/examples/intersect_profile 10000`
//!
//! gives the instructions per pair (total over the pair count; the setup is a few percent).

#[path = "../benches/common/mod.rs"]
mod common;

fn main() {
    let count: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(10_000);
    let mut rng = common::Rng(26);
    let mut cubic = || -> [[f64; 2]; 4] { std::array::from_fn(|_| [rng.unit(), rng.unit()]) };
    let pairs: Vec<_> = (0..count).map(|_| (cubic(), cubic())).collect();
    let start = std::time::Instant::now();
    let (mut decided, mut crossings) = (0usize, 0usize);
    for (p, q) in &pairs {
        if let Some(x) = blossom::certified_crossings_f64(p, q) {
            decided += 1;
            crossings += x.len();
        }
    }
    let each = start.elapsed().as_secs_f64() / count.max(1) as f64;
    println!(
        "{count} pairs: {decided} decided, {crossings} crossings, {:.3} us per pair",
        each * 1e6
    );
}
