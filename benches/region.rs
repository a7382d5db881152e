//! Regions (issue 40), blossom alone (the peers run in `benches/region_peers`, a crate of its
//! own so that `cargo test --workspace` never builds them), in one run:
//!
//! * `region_stars`: the intersection and the union of two star-shaped regions of 8 cubic
//!   edges each ([`shapes::star_pair`]), f64 control points read exactly.
//! * `region_triangles`: the intersection of two quadratic Bézier triangles
//!   ([`shapes::triangle_pairs`], 200 pairs near the unit triangle and its half turn), per pair.
//! * `region_scale`: the union of two gears of N cubic edges each ([`shapes::gear_pair`]) for
//!   N = 100, 300, 1000, 3000, and the log-log slope of the time between consecutive sizes
//!   (1 for linear growth, 2 for quadratic). A size whose first run takes longer than
//!   [`CRITERION_LIMIT`] is timed by the median of 3 runs outside criterion; one longer than
//!   [`SCALE_LIMIT`] stops the series with a printed note.
//!
//! Written beside criterion's output, in `$CARGO_TARGET_DIR/region/` (else `target/region/`):
//! `triangles.json` (the triangle pairs, `{"pairs": [[t1, t2], ...]}`, six `[x, y]` nodes each
//! in the contract's order, and per pair the certified area enclosure `[lo, hi]` and the time
//! of the library's answer in seconds) and `summary.txt` (every figure printed at the end).
//! `benches/python/triangle_intersect.py` reads `triangles.json` to time Python `bezier`'s
//! `Triangle.intersect` on the same pairs and to count its wrong areas.
//!
//! Run: `cargo bench -p blossom --bench region`; `cargo bench -p blossom --bench region --
//! --test` is a quick pass (20 triangle pairs, sizes up to 300).

use blossom::region::{boolean, triangle_intersection, BooleanOp, Region};
use criterion::{black_box, Criterion, SamplingMode};
use std::fmt::Write as _;
use std::time::{Duration, Instant};

mod common;
#[path = "region_peers/src/shapes.rs"]
#[allow(dead_code)]
mod shapes;
use common::median_time;
use shapes::{region_of, Triangle};

/// The sizes of the scale series (edges per region).
const SIZES: [usize; 4] = [100, 300, 1000, 3000];
/// A size whose one timed run takes longer than this ends the series.
const SCALE_LIMIT: Duration = Duration::from_secs(60);
/// A size whose one timed run takes longer than this is timed outside criterion (the median
/// of 3 runs).
const CRITERION_LIMIT: Duration = Duration::from_secs(2);
/// The number of triangle pairs.
const TRIANGLE_PAIRS: usize = 200;

/// The region of a quadratic triangle.
fn triangle_of(t: &Triangle) -> Region {
    Region::triangle_f64(2, t.to_vec()).expect("six finite nodes")
}

fn time_text(seconds: f64) -> String {
    if seconds >= 1.0 {
        format!("{seconds:.2} s")
    } else if seconds >= 1e-3 {
        format!("{:.3} ms", seconds * 1e3)
    } else {
        format!("{:.2} us", seconds * 1e6)
    }
}

/// The median of `runs` timings of `f`, in seconds.
fn main() {
    // `cargo test --benches` passes `--test`: a quick pass.
    let quick = std::env::args().any(|a| a == "--test");
    let mut summary = String::new();
    let mut c = Criterion::default().configure_from_args();

    // Two stars of 8 cubic edges.
    let [a, b] = shapes::star_pair();
    let (ra, rb) = (region_of(&a), region_of(&b));
    {
        let mut group = c.benchmark_group("region_stars");
        group.sample_size(20);
        group.measurement_time(Duration::from_secs(3));
        for (name, op) in [
            ("intersection", BooleanOp::Intersection),
            ("union", BooleanOp::Union),
        ] {
            group.bench_function(name, |bench| {
                bench.iter(|| boolean(black_box(&ra), black_box(&rb), op).expect("answered"))
            });
        }
        group.finish();
    }
    for (name, op) in [
        ("intersection", BooleanOp::Intersection),
        ("union", BooleanOp::Union),
    ] {
        let t = median_time(21, || {
            black_box(boolean(&ra, &rb, op).expect("answered"));
        });
        let r = boolean(&ra, &rb, op).expect("answered");
        let _ = writeln!(
            summary,
            "stars 8+8 cubic edges, {name}: {} (median of 21), {} loops, area in [{}, {}]",
            time_text(t),
            r.loops.len(),
            r.area[0],
            r.area[1]
        );
    }

    // Triangle pairs: the certified areas and the time of each pair, for the Python peer.
    let count = if quick { 20 } else { TRIANGLE_PAIRS };
    let pairs = shapes::triangle_pairs(count);
    let regions: Vec<(Region, Region)> = pairs
        .iter()
        .map(|[t1, t2]| (triangle_of(t1), triangle_of(t2)))
        .collect();
    {
        let mut group = c.benchmark_group("region_triangles");
        group.sampling_mode(SamplingMode::Flat);
        group.sample_size(10);
        group.measurement_time(Duration::from_secs(5));
        group.bench_function(format!("quadratic/{count}"), |bench| {
            bench.iter(|| {
                for (t1, t2) in &regions {
                    black_box(
                        triangle_intersection(black_box(t1), black_box(t2)).expect("answered"),
                    );
                }
            })
        });
        group.finish();
    }
    let mut records = Vec::new();
    let (mut total, mut total_first) = (0.0, 0.0);
    for ([t1, t2], (r1, r2)) in pairs.iter().zip(&regions) {
        // The first boolean on fresh regions also proves each region's loops simple (kept
        // on the region for later booleans): timed alone.
        let (f1, f2) = (triangle_of(t1), triangle_of(t2));
        let start = Instant::now();
        black_box(triangle_intersection(&f1, &f2).expect("answered"));
        let first = start.elapsed().as_secs_f64();
        total_first += first;
        let t = median_time(5, || {
            black_box(triangle_intersection(r1, r2).expect("answered"));
        });
        total += t;
        let r = triangle_intersection(r1, r2).expect("answered");
        records.push(serde_json::json!({
            "triangles": [t1, t2],
            "area": r.area,
            "loops": r.loops.len(),
            "seconds": t,
            "seconds_first": first,
        }));
    }
    // The degenerate pairs, for the peer's wrong answers (not timed).
    let degenerate: Vec<serde_json::Value> = shapes::degenerate_triangle_pairs()
        .iter()
        .map(|(name, [t1, t2])| {
            let r = triangle_intersection(&triangle_of(t1), &triangle_of(t2)).expect("answered");
            serde_json::json!({
                "name": name,
                "triangles": [t1, t2],
                "area": r.area,
                "loops": r.loops.len(),
            })
        })
        .collect();
    std::fs::write(
        common::out_dir("region").join("triangles.json"),
        serde_json::json!({ "degree": 2, "pairs": records, "degenerate": degenerate }).to_string(),
    )
    .expect("a writable target directory");
    let _ = writeln!(
        summary,
        "triangle-triangle, {count} quadratic pairs: {} per pair (median of 5 runs of each pair, averaged); the first boolean on fresh regions {}",
        time_text(total / count as f64),
        time_text(total_first / count as f64)
    );

    // Growth with the number of edges.
    let sizes: Vec<usize> = SIZES
        .iter()
        .copied()
        .filter(|&n| !quick || n <= 300)
        .collect();
    let mut measured: Vec<(usize, f64)> = Vec::new();
    {
        let mut group = c.benchmark_group("region_scale");
        group.sampling_mode(SamplingMode::Flat);
        group.sample_size(10);
        group.warm_up_time(Duration::from_millis(500));
        for &n in &sizes {
            let [a, b] = shapes::gear_pair(n);
            let (ra, rb) = (region_of(&a), region_of(&b));
            let start = Instant::now();
            let r = boolean(&ra, &rb, BooleanOp::Union).expect("answered");
            let once = start.elapsed();
            let _ = writeln!(
                summary,
                "gears {n}+{n} cubic edges, union: first run {} ({} loops, {} edges)",
                time_text(once.as_secs_f64()),
                r.loops.len(),
                r.loops.iter().map(|l| l.edges.len()).sum::<usize>()
            );
            if once > SCALE_LIMIT {
                let _ = writeln!(summary, "  over {SCALE_LIMIT:?}: larger sizes skipped");
                measured.push((n, once.as_secs_f64()));
                break;
            }
            // Criterion for the sizes that take a few seconds at most; the larger ones are
            // timed by the median of 3 runs only.
            if once <= CRITERION_LIMIT {
                group.measurement_time(once.mul_f64(12.0).max(Duration::from_secs(2)));
                group.bench_function(format!("union/{n}"), |bench| {
                    bench.iter(|| {
                        boolean(black_box(&ra), black_box(&rb), BooleanOp::Union).expect("answered")
                    })
                });
            }
            let runs = if once > CRITERION_LIMIT { 3 } else { 7 };
            measured.push((
                n,
                median_time(runs, || {
                    black_box(boolean(&ra, &rb, BooleanOp::Union).expect("answered"));
                }),
            ));
        }
        group.finish();
    }
    for w in measured.windows(2) {
        let ((n0, t0), (n1, t1)) = (w[0], w[1]);
        let slope = (t1 / t0).ln() / (n1 as f64 / n0 as f64).ln();
        let _ = writeln!(
            summary,
            "gears {n0} -> {n1}: {} -> {}, log-log slope {slope:.2}",
            time_text(t0),
            time_text(t1)
        );
    }
    print!("\n{summary}");
    std::fs::write(common::out_dir("region").join("summary.txt"), &summary)
        .expect("a writable target directory");
    c.final_summary();
}
