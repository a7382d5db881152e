//! The Rust side of `benches/python/region_call.py`: the library's region calls on the cases
//! that script writes (its first argument, a text file), each timed two ways, in nanoseconds
//! per call:
//!
//! * `kept`: the operation alone on regions built once (`simplify(&a)` or `boolean(&a, &b,
//!   op)`), the answer dropped in the loop: what `CurvedRegion.simplify()` or `.union(other)`
//!   calls;
//! * `built`: the regions built from the control points (`Region::from_f64`, the points cloned
//!   in the loop) and then the operation: what a caller holding only the numbers pays;
//! * `estimate`: the work estimate alone on the kept regions (`simplify_work` or
//!   `boolean_work`), which the Python call computes before the operation (to refuse work
//!   over `max_work`) unless the regions hold at most 8 curves of degree <= 4.
//!
//! Each figure is the best of 7 rounds of the mean over a round of about 20 ms. Printed, one
//! line per case: `rust <name> <kept ns> <built ns> <estimate ns>`.
//!
//! The file, one token group per line: `case <name> <op> <fill>` (op `simplify`, `union`,
//! `intersection`, `difference`, `xor`; fill `nonzero` or `evenodd`), then for each of the
//! case's regions (one for `simplify`, two otherwise) its loops, each `loop` followed by one
//! `c x0 y0 x1 y1 ...` line per curve, and `end`. Numbers are Python's `repr` of doubles
//! (read back exactly).
//!
//! Run: `cargo run --release -p blossom-python --example region_call --features rust-bench --
//! FILE` (the Python script does it).

use blossom::region::{
    boolean, boolean_work, simplify, simplify_work, BooleanOp, FillRule, Region, RegionResult,
};
use blossom::Bezier;
use std::hint::black_box;
use std::time::Instant;

type Loops = Vec<Vec<Bezier<f64, 2>>>;

struct Case {
    name: String,
    op: Option<BooleanOp>,
    fill: FillRule,
    regions: Vec<Loops>,
}

fn parse(text: &str) -> Vec<Case> {
    let mut cases: Vec<Case> = Vec::new();
    let mut current: Loops = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("case") => {
                let name = words.next().expect("a name").to_string();
                let op = match words.next().expect("an op") {
                    "simplify" => None,
                    "union" => Some(BooleanOp::Union),
                    "intersection" => Some(BooleanOp::Intersection),
                    "difference" => Some(BooleanOp::Difference),
                    "xor" => Some(BooleanOp::Xor),
                    other => panic!("unknown op {other}"),
                };
                let fill = match words.next().expect("a fill rule") {
                    "evenodd" => FillRule::EvenOdd,
                    _ => FillRule::NonZero,
                };
                cases.push(Case {
                    name,
                    op,
                    fill,
                    regions: Vec::new(),
                });
            }
            Some("loop") => current.push(Vec::new()),
            Some("c") => {
                let numbers: Vec<f64> = words.map(|w| w.parse().expect("a number")).collect();
                let points = numbers.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
                let curve = Bezier::new(points).expect("a curve");
                current.last_mut().expect("a loop").push(curve);
            }
            Some("end") => {
                let case = cases.last_mut().expect("a case");
                case.regions.push(std::mem::take(&mut current));
            }
            _ => {}
        }
    }
    cases
}

/// The best over 7 rounds of the mean time of `f` in a round of about 20 ms, in nanoseconds.
fn time(mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    let once = start.elapsed().as_nanos().max(1) as f64;
    let inner = ((20e6 / once) as usize).clamp(1, 100_000);
    (0..7)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..inner {
                f();
            }
            start.elapsed().as_nanos() as f64 / inner as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn run(case: &Case, regions: &[Region]) -> RegionResult {
    match case.op {
        None => simplify(&regions[0]),
        Some(op) => boolean(&regions[0], &regions[1], op),
    }
    .expect("the boolean answers")
}

fn main() {
    let path = std::env::args()
        .nth(1)
        .expect("the cases file (region_call.py writes it)");
    let text = std::fs::read_to_string(&path).expect("a readable file");
    for case in parse(&text) {
        let build = || -> Vec<Region> {
            case.regions
                .iter()
                .map(|loops| Region::from_f64(loops.clone(), case.fill).expect("a region"))
                .collect()
        };
        let regions = build();
        let kept = time(|| {
            black_box(run(&case, &regions));
        });
        let built = time(|| {
            black_box(run(&case, &build()));
        });
        let estimate = time(|| {
            black_box(match case.op {
                None => simplify_work(&regions[0]),
                Some(_) => boolean_work(&regions[0], &regions[1]),
            });
        });
        println!("rust {} {kept:.0} {built:.0} {estimate:.0}", case.name);
    }
}
