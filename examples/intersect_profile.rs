//! A profiling aid for the float filter of curve-curve intersection: runs
//! [`blossom::certified_crossings_f64`] on the random cubic pairs of `benches/intersect.rs`
//! (the same SplitMix64 generator, seed 26) and prints how many it decided, the number of
//! crossings and the wall time per pair. With `lyon` as the second argument it runs lyon_geom's
//! `cubic_intersections_t` on the same pairs instead, and with `both` the two in turn (each
//! loop in its own function, `certified_pass` and `lyon_pass`, so that callgrind's per-function
//! totals give both instruction counts of one run). Under callgrind:
//!
//! `valgrind --tool=callgrind target/release/examples/intersect_profile 10000 both`
//!
//! then `callgrind_annotate --inclusive=yes` gives the instructions of each pass (divide by
//! the pair count).

#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/common/lyon.rs"]
mod lyon;

type Cubic = [[f64; 2]; 4];

/// The certified pass: (decided pairs, crossings).
#[inline(never)]
fn certified_pass(pairs: &[(Cubic, Cubic)]) -> (usize, usize) {
    let (mut decided, mut crossings) = (0usize, 0usize);
    for (p, q) in pairs {
        if let Some(x) = blossom::certified_crossings_f64(p, q) {
            decided += 1;
            crossings += x.len();
        }
    }
    (decided, crossings)
}

/// lyon_geom's pass on the same pairs: crossings.
#[inline(never)]
fn lyon_pass(pairs: &[(Cubic, Cubic)]) -> usize {
    pairs
        .iter()
        .map(|(p, q)| {
            lyon::lyon_cubic(p)
                .cubic_intersections_t(&lyon::lyon_cubic(q))
                .len()
        })
        .sum()
}

fn main() {
    let mut args = std::env::args().skip(1);
    let count: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(10_000);
    let mode = args.next().unwrap_or_else(|| "certified".into());
    let mut rng = common::Rng(26);
    let mut cubic = || -> Cubic { std::array::from_fn(|_| [rng.unit(), rng.unit()]) };
    let pairs: Vec<_> = (0..count).map(|_| (cubic(), cubic())).collect();
    let per_pair =
        |start: std::time::Instant| start.elapsed().as_secs_f64() / count.max(1) as f64 * 1e6;
    if mode == "certified" || mode == "both" {
        let start = std::time::Instant::now();
        let (decided, crossings) = certified_pass(&pairs);
        println!(
            "certified: {count} pairs: {decided} decided, {crossings} crossings, {:.3} us per pair",
            per_pair(start)
        );
    }
    if mode == "lyon" || mode == "both" {
        let start = std::time::Instant::now();
        let crossings = lyon_pass(&pairs);
        println!(
            "lyon: {count} pairs: {crossings} crossings, {:.3} us per pair",
            per_pair(start)
        );
    }
}
