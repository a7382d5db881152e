//! Curve-curve intersection (issue 26), in one run:
//!
//! * `intersect_cubics`: 10^4 random 2-D cubic pairs, every coordinate an f64 uniform in
//!   [0, 1) from the shared SplitMix64 generator (seed 26). Our certified answer ([`ours`])
//!   against lyon_geom's `CubicBezierSegment::cubic_intersections_t` (fat-line clipping,
//!   uncertified) on the same pairs, both on all 10^4 pairs, in criterion and in a summary
//!   line: the median of 5 wall-clock passes of each over all pairs, one thread, and their
//!   ratio. A reference pass of [`ours`] over all 10^4 pairs, outside criterion, on every core
//!   of the machine (each pair timed alone on its thread), gives the certified answers.
//! * The wrong counts of lyon against the certified answers: pairs where lyon's number of
//!   intersections differs (split into too few and too many), and the largest |s - s_lyon|,
//!   |t - t_lyon| over the points of pairs with equal counts (each certified point matched to
//!   the nearest lyon point).
//! * `intersect_exact`: random pairs of degree 3, 8 and 16 with integer control points in
//!   [0, 16] through [`blossom::intersect_curves`] (rational input), the time per pair and the
//!   log-log growth between degrees. A pair that has not finished in [`EXACT_LIMIT`] stops
//!   that degree with a printed note.
//!
//! Written beside criterion's output, in `$CARGO_TARGET_DIR/intersect/` (else `target/`):
//! `pairs.json` (the 10^4 pairs, `{"seed", "pairs": [[p, q], ...]}` with `p`, `q` four
//! `[x, y]` each, shortest round-trip decimals), `answers.json` (per pair the certified
//! `[s, t]` list and lyon's) and `summary.txt` (every figure printed at the end of the run).
//! `benches/python/intersect_pairs.py` reads the first two to time Python `bezier` on the
//! same pairs.
//!
//! Run: `cargo bench -p blossom --bench intersect` (BENCHMARKS.md, "Intersections", has the
//! figures). `INTERSECT_PAIRS=1000` runs on fewer pairs.

use blossom::{intersect_curves, intersect_curves_f64_rounded, Rational, Ring};
use criterion::{black_box, Criterion, SamplingMode, Throughput};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::{Duration, Instant};

mod common;
#[path = "common/lyon.rs"]
mod lyon;
use common::Rng;

/// The number of random cubic pairs.
const PAIRS: usize = 10_000;
/// The seed of the generator.
const SEED: u64 = 26;
/// The exact-input degrees.
const DEGREES: [usize; 3] = [3, 8, 16];
/// Exact-input pairs per degree (fewer when one is slow, see [`exact_inputs`]).
const EXACT_PAIRS: usize = 10;
/// The longest one exact-input pair may take before its degree is abandoned.
const EXACT_LIMIT: Duration = Duration::from_secs(20);
/// The exact-input budget per degree: pairs are timed until it is spent.
const EXACT_BUDGET: Duration = Duration::from_secs(10);

type Cubic = [[f64; 2]; 4];
/// The (s, t) parameters of one pair's intersections.
type Answer = Vec<(f64, f64)>;

/// The certified intersections of two cubics as f64 parameter pairs (s on `p`, t on `q`),
/// each the correctly rounded double of the exact value, sorted by s then t. Overlaps (none
/// occur in random data) are not counted.
///
/// This is the one place the bench calls the certified path:
/// [`intersect_curves_f64_rounded`], the float filter (Bézier clipping, Krawczyk's test,
/// double-double residuals, correct rounding from the enclosures) with the exact path where
/// the filter does not decide.
fn ours(p: &Cubic, q: &Cubic) -> Vec<(f64, f64)> {
    let found = intersect_curves_f64_rounded(p, q).expect("random cubics intersect exactly");
    found.points.iter().map(|x| (x.s, x.t)).collect()
}

/// lyon_geom's answer, sorted by s then t.
fn lyon(p: &Cubic, q: &Cubic) -> Vec<(f64, f64)> {
    let mut st: Vec<(f64, f64)> = lyon::lyon_cubic(p)
        .cubic_intersections_t(&lyon::lyon_cubic(q))
        .into_iter()
        .collect();
    st.sort_by(|a, b| a.partial_cmp(b).expect("finite parameters"));
    st
}

fn pairs(count: usize) -> Vec<(Cubic, Cubic)> {
    let mut rng = Rng(SEED);
    let mut cubic = || -> Cubic { std::array::from_fn(|_| [rng.unit(), rng.unit()]) };
    (0..count).map(|_| (cubic(), cubic())).collect()
}

fn write_json(path: &PathBuf, value: &serde_json::Value) {
    let text = serde_json::to_string(value).expect("JSON of plain numbers");
    std::fs::write(path, text).expect("a writable target directory");
}

fn st_json(st: &[(f64, f64)]) -> serde_json::Value {
    st.iter().map(|&(s, t)| serde_json::json!([s, t])).collect()
}

/// How lyon's answers compare with the certified ones.
#[derive(Default)]
struct Agreement {
    too_few: usize,
    too_many: usize,
    points_too_few: usize,
    points_too_many: usize,
    max_ds: f64,
    max_dt: f64,
}

impl Agreement {
    fn add(&mut self, ours: &[(f64, f64)], theirs: &[(f64, f64)]) {
        use std::cmp::Ordering::*;
        match theirs.len().cmp(&ours.len()) {
            Less => {
                self.too_few += 1;
                self.points_too_few += ours.len() - theirs.len();
            }
            Greater => {
                self.too_many += 1;
                self.points_too_many += theirs.len() - ours.len();
            }
            Equal => {
                for &(s, t) in ours {
                    let nearest = theirs
                        .iter()
                        .min_by(|a, b| {
                            let d = |x: &(f64, f64)| (x.0 - s).hypot(x.1 - t);
                            d(a).total_cmp(&d(b))
                        })
                        .expect("as many points as ours");
                    self.max_ds = self.max_ds.max((nearest.0 - s).abs());
                    self.max_dt = self.max_dt.max((nearest.1 - t).abs());
                }
            }
        }
    }
}

/// Every certified answer, computed on as many threads as the machine has (the exact path is
/// slow), and the mean time of one pair, each pair timed alone on its thread.
fn reference_pass(pairs: &[(Cubic, Cubic)]) -> (Vec<Answer>, f64) {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let chunk = pairs.len().div_ceil(threads).max(1);
    let parts: Vec<(Vec<Answer>, Duration)> = std::thread::scope(|scope| {
        let workers: Vec<_> = pairs
            .chunks(chunk)
            .map(|part| {
                scope.spawn(move || {
                    let mut spent = Duration::ZERO;
                    let answers = part
                        .iter()
                        .map(|(p, q)| {
                            let start = Instant::now();
                            let st = ours(p, q);
                            spent += start.elapsed();
                            st
                        })
                        .collect();
                    (answers, spent)
                })
            })
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().expect("a reference worker"))
            .collect()
    });
    let spent: Duration = parts.iter().map(|(_, d)| *d).sum();
    let answers = parts.into_iter().flat_map(|(a, _)| a).collect();
    (answers, spent.as_secs_f64() / pairs.len().max(1) as f64)
}

/// The median of `runs` wall-clock passes of `f` over every pair, per pair.
fn per_pair(
    runs: usize,
    pairs: &[(Cubic, Cubic)],
    f: fn(&Cubic, &Cubic) -> Vec<(f64, f64)>,
) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            for (p, q) in pairs {
                black_box(f(black_box(p), black_box(q)));
            }
            start.elapsed().as_secs_f64() / pairs.len() as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[runs / 2]
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

/// A random curve of degree `n` with integer control points in [0, 16].
fn integer_curve(rng: &mut Rng, n: usize) -> Vec<[Rational; 2]> {
    let mut k = || Rational::from_int((rng.unit() * 17.0).floor() as i64);
    (0..=n).map(|_| [k(), k()]).collect()
}

/// Times exact-input pairs of each degree on a worker thread; returns (degree, seconds per
/// pair, pairs, intersections found) for the degrees that finished, and notes.
fn exact_inputs(summary: &mut String) {
    let mut rng = Rng(SEED + 1);
    let mut measured: Vec<(usize, f64)> = Vec::new();
    for n in DEGREES {
        let (tx, rx) = mpsc::channel();
        let inputs: Vec<_> = (0..EXACT_PAIRS)
            .map(|_| (integer_curve(&mut rng, n), integer_curve(&mut rng, n)))
            .collect();
        std::thread::spawn(move || {
            for (p, q) in inputs {
                let start = Instant::now();
                let found = intersect_curves(&p, &q).map(|x| x.points.len() + x.overlaps.len());
                if tx.send((start.elapsed(), found)).is_err() {
                    return;
                }
            }
        });
        let (mut total, mut done, mut hits) = (Duration::ZERO, 0usize, 0usize);
        let mut stuck = false;
        while done < EXACT_PAIRS && total < EXACT_BUDGET {
            match rx.recv_timeout(EXACT_LIMIT) {
                Ok((took, found)) => {
                    total += took;
                    done += 1;
                    hits += found.expect("random integer curves intersect exactly");
                }
                Err(_) => {
                    stuck = true;
                    break;
                }
            }
        }
        if stuck {
            let line = format!(
                "exact degree {n}: a pair took more than {} s; degree skipped ({done} pairs done)",
                EXACT_LIMIT.as_secs()
            );
            eprintln!("{line}");
            writeln!(summary, "{line}").expect("a String");
            // The worker cannot be stopped; the process exits after the summary.
            break;
        }
        let each = total.as_secs_f64() / done as f64;
        let line = format!(
            "exact degree {n}: {} per pair ({done} pairs, {hits} intersections)",
            time_text(each)
        );
        eprintln!("{line}");
        writeln!(summary, "{line}").expect("a String");
        if let Some(&(m, before)) = measured.last() {
            let growth = (each / before).ln() / (n as f64 / m as f64).ln();
            let line = format!(
                "exact growth {m} -> {n}: x{:.1}, cost ~ degree^{growth:.1}",
                each / before
            );
            eprintln!("{line}");
            writeln!(summary, "{line}").expect("a String");
        }
        measured.push((n, each));
    }
}

fn main() {
    // `cargo test --benches` passes `--test`: a quick pass over a few pairs, no exact inputs.
    let quick = std::env::args().any(|a| a == "--test");
    let count = std::env::var("INTERSECT_PAIRS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(if quick { 100 } else { PAIRS });
    let pairs = pairs(count);
    let dir = common::out_dir("intersect");
    let pair_json: Vec<serde_json::Value> = pairs
        .iter()
        .map(|(p, q)| serde_json::json!([p, q]))
        .collect();
    write_json(
        &dir.join("pairs.json"),
        &serde_json::json!({ "seed": SEED, "pairs": pair_json }),
    );

    // The reference pass: every certified answer, each pair timed alone.
    let (certified, ours_full) = reference_pass(&pairs);
    let theirs: Vec<Vec<(f64, f64)>> = pairs.iter().map(|(p, q)| lyon(p, q)).collect();
    let mut agreement = Agreement::default();
    for (a, b) in certified.iter().zip(&theirs) {
        agreement.add(a, b);
    }
    let answers: Vec<serde_json::Value> = certified
        .iter()
        .zip(&theirs)
        .map(|(a, b)| serde_json::json!({ "ours": st_json(a), "lyon": st_json(b) }))
        .collect();
    write_json(
        &dir.join("answers.json"),
        &serde_json::json!({ "seed": SEED, "answers": answers }),
    );

    let mut c = Criterion::default().configure_from_args();
    {
        let mut group = c.benchmark_group("intersect_cubics");
        group.sampling_mode(SamplingMode::Flat);
        group.throughput(Throughput::Elements(count as u64));
        group.sample_size(20);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(5));
        group.bench_function(format!("certified/{count}"), |b| {
            b.iter(|| {
                for (p, q) in &pairs {
                    black_box(ours(black_box(p), black_box(q)));
                }
            })
        });
        group.measurement_time(Duration::from_secs(5));
        group.bench_function(format!("lyon/{count}"), |b| {
            b.iter(|| {
                for (p, q) in &pairs {
                    black_box(lyon(black_box(p), black_box(q)));
                }
            })
        });
        group.finish();
    }

    // The ratio on the same pairs, one thread each, all pairs.
    let ours_each = per_pair(5, &pairs, ours);
    let lyon_each = per_pair(5, &pairs, lyon);
    let total_points: usize = certified.iter().map(Vec::len).sum();
    let mut summary = String::new();
    let lines = [
        format!("pairs: {count} random cubic pairs in [0, 1)^2, seed {SEED}, {total_points} certified intersections"),
        format!(
            "certified (ours): {} per pair (median of 5 passes over all {count}, one thread; reference pass on every core, each pair timed alone: {})",
            time_text(ours_each),
            time_text(ours_full)
        ),
        format!("lyon cubic_intersections_t: {} per pair (median of 5 passes)", time_text(lyon_each)),
        format!(
            "ratio certified / lyon on all {count} pairs, one thread: {:.2}",
            ours_each / lyon_each
        ),
        format!(
            "lyon wrong count: {} of {count} pairs ({} too few, missing {} points; {} too many, {} extra points)",
            agreement.too_few + agreement.too_many,
            agreement.too_few,
            agreement.points_too_few,
            agreement.too_many,
            agreement.points_too_many
        ),
        format!(
            "lyon on pairs with the right count: max |s - s_lyon| = {:.3e}, max |t - t_lyon| = {:.3e}",
            agreement.max_ds, agreement.max_dt
        ),
    ];
    for line in lines {
        eprintln!("{line}");
        writeln!(summary, "{line}").expect("a String");
    }
    if !quick {
        exact_inputs(&mut summary);
    }
    std::fs::write(dir.join("summary.txt"), &summary).expect("a writable target directory");
    eprintln!("written: {}", dir.display());
    c.final_summary();
    // A worker still on a skipped exact-input pair is ended with the process.
    std::process::exit(0);
}
