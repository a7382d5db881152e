//! blossom's certified booleans beside flo_curves' `path_intersect` and `path_add` (not
//! certified: float subdivision with an accuracy of 0.01, see its docs), on the same inputs, in
//! one criterion run:
//!
//! * `region_peers/stars`: the intersection and the union of two stars of 8 cubic edges each
//!   ([`shapes::star_pair`]), blossom on the f64 control points read exactly, flo_curves on
//!   the same doubles; then the median of 21 timed runs of each, and their ratios.
//! * The wrong answers of flo_curves on a corpus: 200 random star pairs
//!   ([`shapes::random_star_pair`]) and degenerate pairs (a star and its copy, two squares that
//!   share an edge or half of one, two that touch at a corner, nested stars, a square and its
//!   copy moved along its bottom edge), intersection and union each. flo_curves' answer is wrong
//!   when the area of its loops (each cubic's exact integral of x dy, summed with signs as
//!   its loops nest, see [`flo_area`]) is farther than `1e-6 B` from blossom's certified
//!   enclosure (B the area of the input's box), grossly wrong when farther than `1e-2 B`; a
//!   panic counts as wrong. flo_curves treats every loop as even-odd without orientation; the
//!   stars here run counter-clockwise and do not cross themselves, where the two rules agree.
//!
//! Run: `cd benches/region_peers && CARGO_TARGET_DIR=... cargo bench`. The summary is printed
//! at the end and written to `$CARGO_TARGET_DIR/region/peers_summary.txt`.

use blossom::region::{boolean, BooleanOp};
use blossom_region_peers::common::median_time;
use blossom_region_peers::shapes::{self, region_of, Cubic, Rng};
use criterion::{black_box, Criterion};
use flo_curves::bezier::path::{path_add, path_intersect, SimpleBezierPath};
use flo_curves::Coord2;
use std::fmt::Write as _;
use std::time::Duration;

/// flo_curves' accuracy argument (its documentation's example value).
const ACCURACY: f64 = 0.01;

fn path_of(curves: &[Cubic]) -> SimpleBezierPath {
    let c = |p: [f64; 2]| Coord2(p[0], p[1]);
    (
        c(curves[0][0]),
        curves.iter().map(|k| (c(k[1]), c(k[2]), c(k[3]))).collect(),
    )
}

/// The signed area of one closed cubic path: the sum over its cubics of the integral of x dy,
/// exact for the polynomial x(t) y'(t) of degree 5 by 3-point Gauss-Legendre.
fn path_area((start, curves): &SimpleBezierPath) -> f64 {
    let nodes = [
        (0.5 - 0.5 * (0.6f64).sqrt(), 5.0 / 18.0),
        (0.5, 8.0 / 18.0),
        (0.5 + 0.5 * (0.6f64).sqrt(), 5.0 / 18.0),
    ];
    let mut total = 0.0;
    let mut p0 = *start;
    for (c1, c2, p3) in curves {
        let (x, y) = ([p0.0, c1.0, c2.0, p3.0], [p0.1, c1.1, c2.1, p3.1]);
        for (t, w) in nodes {
            let s = 1.0 - t;
            let xt = s * s * s * x[0]
                + 3.0 * s * s * t * x[1]
                + 3.0 * s * t * t * x[2]
                + t * t * t * x[3];
            let dy =
                3.0 * (s * s * (y[1] - y[0]) + 2.0 * s * t * (y[2] - y[1]) + t * t * (y[3] - y[2]));
            total += w * xt * dy;
        }
        p0 = *p3;
    }
    total
}

/// A closed path sampled (32 points a cubic).
fn sampled((start, curves): &SimpleBezierPath) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut p0 = *start;
    for (c1, c2, p3) in curves {
        for k in 0..32 {
            let t = k as f64 / 32.0;
            let s = 1.0 - t;
            let b = [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t];
            out.push([
                b[0] * p0.0 + b[1] * c1.0 + b[2] * c2.0 + b[3] * p3.0,
                b[0] * p0.1 + b[1] * c1.1 + b[2] * c2.1 + b[3] * p3.1,
            ]);
        }
        p0 = *p3;
    }
    out
}

/// Whether `p` is inside the polygon by the even-odd rule.
fn inside(polygon: &[[f64; 2]], p: [f64; 2]) -> bool {
    let n = polygon.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        {
            odd = !odd;
        }
    }
    odd
}

/// The area of flo_curves' answer. Its loops carry no orientation (it treats every edge as an
/// exterior edge, like even-odd), so each loop counts with its absolute area, added at even
/// nesting depth and subtracted at odd depth (the depth of a loop: how many other loops hold
/// a point of it, the middle of its first cubic).
fn flo_area(paths: &[SimpleBezierPath]) -> f64 {
    let polygons: Vec<Vec<[f64; 2]>> = paths.iter().map(sampled).collect();
    paths
        .iter()
        .enumerate()
        .map(|(i, path)| {
            let probe = polygons[i][polygons[i].len().min(16) - 1];
            let depth = polygons
                .iter()
                .enumerate()
                .filter(|(j, other)| *j != i && inside(other, probe))
                .count();
            let area = path_area(path).abs();
            if depth % 2 == 0 {
                area
            } else {
                -area
            }
        })
        .sum()
}

fn flo(a: &SimpleBezierPath, b: &SimpleBezierPath, op: BooleanOp) -> Vec<SimpleBezierPath> {
    let (a, b) = (vec![a.clone()], vec![b.clone()]);
    match op {
        BooleanOp::Intersection => path_intersect::<SimpleBezierPath>(&a, &b, ACCURACY),
        _ => path_add::<SimpleBezierPath>(&a, &b, ACCURACY),
    }
}

/// A square of straight cubics (handles at thirds), counter-clockwise.
fn square(x: f64, y: f64, side: f64) -> Vec<Cubic> {
    shapes::cubic_loop(
        &[[x, y], [x + side, y], [x + side, y + side], [x, y + side]],
        0.0,
    )
}

fn moved(curves: &[Cubic], d: [f64; 2]) -> Vec<Cubic> {
    curves
        .iter()
        .map(|c| c.map(|p| [p[0] + d[0], p[1] + d[1]]))
        .collect()
}

/// The corpus: (name, A, B).
fn corpus() -> Vec<(String, Vec<Cubic>, Vec<Cubic>)> {
    let mut out = Vec::new();
    let mut rng = Rng(4040_4040);
    for i in 0..200 {
        let [a, b] = shapes::random_star_pair(&mut rng);
        out.push((format!("random star pair {i}"), a, b));
    }
    let star = shapes::star([0.0, 0.0], 5, 1.0, 0.5, 0.3);
    out.push(("a star and its copy".into(), star.clone(), star.clone()));
    out.push((
        "two squares sharing an edge".into(),
        square(0.0, 0.0, 1.0),
        square(1.0, 0.0, 1.0),
    ));
    out.push((
        "two squares sharing half an edge".into(),
        square(0.0, 0.0, 1.0),
        square(1.0, 0.5, 1.0),
    ));
    out.push((
        "two squares touching at a corner".into(),
        square(0.0, 0.0, 1.0),
        square(1.0, 1.0, 1.0),
    ));
    out.push((
        "nested stars".into(),
        star.clone(),
        shapes::star([0.0, 0.0], 5, 0.4, 0.2, 0.3),
    ));
    out.push((
        "a square and its copy moved along an edge".into(),
        square(0.0, 0.0, 1.0),
        moved(&square(0.0, 0.0, 1.0), [0.25, 0.0]),
    ));
    out
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    let mut summary = String::new();

    let [a, b] = shapes::star_pair();
    let (ra, rb) = (region_of(&a), region_of(&b));
    let (pa, pb) = (path_of(&a), path_of(&b));
    {
        let mut group = c.benchmark_group("region_peers/stars");
        group.sample_size(20);
        group.measurement_time(Duration::from_secs(3));
        for (name, op) in [
            ("intersection", BooleanOp::Intersection),
            ("union", BooleanOp::Union),
        ] {
            group.bench_function(format!("blossom/{name}"), |bench| {
                bench.iter(|| boolean(black_box(&ra), black_box(&rb), op).expect("answered"))
            });
            group.bench_function(format!("flo_curves/{name}"), |bench| {
                bench.iter(|| flo(black_box(&pa), black_box(&pb), op))
            });
        }
        group.finish();
    }
    for (name, op) in [
        ("intersection", BooleanOp::Intersection),
        ("union", BooleanOp::Union),
    ] {
        let ours = median_time(21, || {
            black_box(boolean(&ra, &rb, op).expect("answered"));
        });
        let theirs = median_time(21, || {
            black_box(flo(&pa, &pb, op));
        });
        let _ = writeln!(
            summary,
            "stars 8+8 cubic edges, {name}: blossom {:.1} us, flo_curves {:.1} us, blossom / flo_curves {:.2}",
            ours * 1e6,
            theirs * 1e6,
            ours / theirs
        );
    }

    // Wrong answers of flo_curves against the certified enclosures.
    let cases = corpus();
    let (mut wrong, mut gross, mut panics, mut total) = (0, 0, 0, 0);
    let mut notes = Vec::new();
    std::panic::set_hook(Box::new(|_| {}));
    for (name, a, b) in &cases {
        let (ra, rb) = (region_of(a), region_of(b));
        let points = a.iter().chain(b).flatten();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let big_b = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        for (op_name, op) in [
            ("intersection", BooleanOp::Intersection),
            ("union", BooleanOp::Union),
        ] {
            total += 1;
            let certified = boolean(&ra, &rb, op).expect("answered").area;
            let (pa, pb) = (path_of(a), path_of(b));
            match std::panic::catch_unwind(|| flo_area(&flo(&pa, &pb, op))) {
                Err(_) => {
                    panics += 1;
                    wrong += 1;
                    notes.push(format!("{name}, {op_name}: flo_curves panicked"));
                }
                Ok(area) => {
                    let off = (certified[0] - area).max(area - certified[1]).max(0.0);
                    if off > 1e-6 * big_b {
                        wrong += 1;
                        if off > 1e-2 * big_b {
                            gross += 1;
                        }
                        notes.push(format!(
                            "{name}, {op_name}: flo_curves area {area:.9}, certified [{:.9}, {:.9}]",
                            certified[0], certified[1]
                        ));
                    }
                }
            }
        }
    }
    let _ = std::panic::take_hook();
    let _ = writeln!(
        summary,
        "flo_curves wrong: {wrong} of {total} answers (area off the certified enclosure by more than 1e-6 B; {gross} by more than 1e-2 B; {panics} panics)"
    );
    for note in &notes {
        let _ = writeln!(summary, "  {note}");
    }
    print!("\n{summary}");
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::PathBuf::from("target"));
    let dir = target.join("region");
    let _ = std::fs::create_dir_all(&dir);
    let _ = std::fs::write(dir.join("peers_summary.txt"), &summary);
    c.final_summary();
}
