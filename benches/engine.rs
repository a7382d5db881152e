//! The restriction engine against plain textbook code and against the path it replaced, f64,
//! 3-D, in one run (BENCHMARKS.md has the figures and the commands):
//!
//! * `curve`: a Bézier curve of degree n restricted to [a, b]: the engine without allocation
//!   (`Bezier::subsegment_into`), the engine through the runtime-dimension API
//!   (`BezierCurve::subsegment`, a new curve each call, and `BezierCurve::subsegment_into`,
//!   into a reused curve: `engine_vec_api_into`), a textbook de Casteljau restriction written here (split at b,
//!   then the right part at a / b, in place, no allocation), and the previous default (to the
//!   power basis by forward differences, then the Taylor shift: `before`);
//! * `tensor`: a tensor patch of bidegree (n, n): the engine, and `before`;
//! * `triangle`: a triangular patch of degree N: the engine, and a naive barycentric pyramid
//!   per control point written here without allocation;
//! * `power`: a power-basis curve of degree n: `Method::Bulk` (the engine in the scaled power
//!   basis), `Method::TaylorShift` (the previous default) and `Method::ClosedForm`.
//!
//! Before timing, every path is checked against the textbook one (1e-9 relative).
//! Run: `cargo bench -p blossom --bench engine`; `cargo run --release --example bench_slopes`
//! then prints the log-log slopes from criterion's estimates.

use blossom::engine::bernstein_to_power;
use blossom::{
    restrict_power_curve, restrict_power_surface, Bezier, BezierCurve, BezierTensor,
    BezierTriangle, Method, PowerCurve, PowerSurface,
};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

mod common;
use common::Rng;

/// The textbook restriction: de Casteljau at b keeps the part over [0, b] (its left edge, in
/// place), then de Casteljau at a / b keeps that part's right piece (its right edge).
// Written as the textbook writes it, indexing neighbours i - 1, i and i + 1.
#[allow(clippy::needless_range_loop)]
fn textbook_restrict(ctrl: &[[f64; 3]], a: f64, b: f64, out: &mut [[f64; 3]]) {
    let n = ctrl.len() - 1;
    out.copy_from_slice(ctrl);
    for r in 1..=n {
        for i in (r..=n).rev() {
            for x in 0..3 {
                out[i][x] = out[i - 1][x] + b * (out[i][x] - out[i - 1][x]);
            }
        }
    }
    let t = a / b;
    for r in 1..=n {
        for i in 0..=n - r {
            for x in 0..3 {
                out[i][x] += t * (out[i + 1][x] - out[i][x]);
            }
        }
    }
}

/// The naive triangle restriction: one barycentric pyramid per control point, in `level`.
fn naive_triangle(
    net: &[[f64; 3]],
    n: usize,
    corners: &[[f64; 2]; 3],
    level: &mut [[f64; 3]],
    out: &mut [[f64; 3]],
) {
    let index = |d: usize, i: usize, j: usize| i * (d + 1) - i * i.saturating_sub(1) / 2 + j;
    let mut k = 0;
    for nu in 0..=n {
        for mu in 0..=n - nu {
            level.copy_from_slice(net);
            for r in 0..n {
                let [s, t] = if r < nu {
                    corners[0]
                } else if r < nu + mu {
                    corners[1]
                } else {
                    corners[2]
                };
                let d = n - r - 1;
                for i in 0..=d {
                    for j in 0..=d - i {
                        let (pa, pb, pc) = (
                            level[index(d + 1, i + 1, j)],
                            level[index(d + 1, i, j + 1)],
                            level[index(d + 1, i, j)],
                        );
                        level[index(d, i, j)] = std::array::from_fn(|x| {
                            pc[x] + s * (pa[x] - pc[x]) + t * (pb[x] - pc[x])
                        });
                    }
                }
            }
            out[k] = level[0];
            k += 1;
        }
    }
}

fn close(got: &[[f64; 3]], want: &[[f64; 3]], what: &str) {
    let size = want.iter().flatten().fold(1.0f64, |m, x| m.max(x.abs()));
    for (g, w) in got.iter().flatten().zip(want.iter().flatten()) {
        assert!((g - w).abs() <= 1e-9 * size, "{what}: {g} vs {w}");
    }
}

const CURVE_DEGREES: [usize; 10] = [3, 4, 6, 8, 12, 16, 24, 32, 48, 64];

fn curves(c: &mut Criterion) {
    let mut rng = Rng(12);
    let mut group = c.benchmark_group("curve");
    for n in CURVE_DEGREES {
        let ctrl: Vec<[f64; 3]> = (0..=n).map(|_| rng.point()).collect();
        let (a, b) = (0.2 + 0.1 * rng.unit(), 0.7 + 0.1 * rng.unit());
        let curve = Bezier::new(ctrl.clone()).expect("points");
        let vec_curve =
            BezierCurve::new(ctrl.iter().map(|p| p.to_vec()).collect()).expect("points");
        let mut out = ctrl.clone();
        let mut scratch = Vec::new();
        let mut want = ctrl.clone();
        textbook_restrict(&ctrl, a, b, &mut want);
        curve
            .subsegment_into(&a, &b, &mut out, &mut scratch)
            .expect("fits");
        close(&out, &want, "engine");
        let before = || {
            let power = PowerCurve::new(bernstein_to_power(&vec_curve.control_points().to_vec()))
                .expect("points");
            restrict_power_curve(&power, &a, &b, Method::TaylorShift)
        };
        let as_arrays = |c: BezierCurve<f64>| -> Vec<[f64; 3]> {
            c.control_points()
                .iter()
                .map(|p| [p[0], p[1], p[2]])
                .collect()
        };
        if n <= 16 {
            close(&as_arrays(before()), &want, "before");
        }
        close(&as_arrays(vec_curve.subsegment(a..b)), &want, "vec");
        group.bench_with_input(BenchmarkId::new("engine", n), &n, |bench, _| {
            bench.iter(|| {
                curve
                    .subsegment_into(black_box(&a), black_box(&b), &mut out, &mut scratch)
                    .expect("fits");
                black_box(&out);
            })
        });
        group.bench_with_input(BenchmarkId::new("textbook", n), &n, |bench, _| {
            bench.iter(|| {
                textbook_restrict(black_box(&ctrl), black_box(a), black_box(b), &mut out);
                black_box(&out);
            })
        });
        group.bench_with_input(BenchmarkId::new("engine_vec_api", n), &n, |bench, _| {
            bench.iter(|| black_box(&vec_curve).subsegment(a..b))
        });
        let mut vec_out = vec_curve.clone();
        group.bench_with_input(
            BenchmarkId::new("engine_vec_api_into", n),
            &n,
            |bench, _| {
                bench.iter(|| {
                    black_box(&vec_curve).subsegment_into(
                        black_box(&a),
                        black_box(&b),
                        &mut vec_out,
                        &mut scratch,
                    );
                    black_box(&vec_out);
                })
            },
        );
        group.bench_with_input(BenchmarkId::new("before", n), &n, |bench, _| {
            bench.iter(|| black_box(before()))
        });
    }
    group.finish();
}

fn tensors(c: &mut Criterion) {
    let mut rng = Rng(13);
    let mut group = c.benchmark_group("tensor");
    for n in [2, 4, 6, 8, 12, 16, 24, 32, 48] {
        let net: Vec<[f64; 3]> = (0..(n + 1) * (n + 1)).map(|_| rng.point()).collect();
        let rect = [0.25, 0.75, 0.125, 0.625];
        let patch = BezierTensor::new((n, n), net.clone()).expect("net");
        let mut out = net.clone();
        let mut scratch = Vec::new();
        let rows: Vec<Vec<Vec<f64>>> = net
            .chunks(n + 1)
            .map(|r| r.iter().map(|p| p.to_vec()).collect())
            .collect();
        let before = || {
            let rows: Vec<Vec<Vec<f64>>> = rows.iter().map(|r| bernstein_to_power(r)).collect();
            let long: Vec<Vec<f64>> = rows.iter().map(|r| r.concat()).collect();
            let grid: Vec<Vec<Vec<f64>>> = bernstein_to_power(&long)
                .into_iter()
                .map(|r| r.chunks(3).map(<[f64]>::to_vec).collect())
                .collect();
            restrict_power_surface(
                &PowerSurface::new(grid).expect("grid"),
                &rect,
                Method::TaylorShift,
            )
        };
        group.bench_with_input(BenchmarkId::new("engine", n), &n, |bench, _| {
            bench.iter(|| {
                patch
                    .restrict_into(black_box(&rect), &mut out, &mut scratch)
                    .expect("fits");
                black_box(&out);
            })
        });
        if n > 16 {
            continue;
        }
        group.bench_with_input(BenchmarkId::new("before", n), &n, |bench, _| {
            bench.iter(|| black_box(before()))
        });
    }
    group.finish();
}

fn triangles(c: &mut Criterion) {
    let mut rng = Rng(14);
    let mut group = c.benchmark_group("triangle");
    let corners = [[0.5, 0.25], [0.125, 0.625], [0.25, 0.0625]];
    for n in [2, 3, 4, 6, 8, 10, 12, 14, 16, 24, 32, 48] {
        let len = (n + 1) * (n + 2) / 2;
        let net: Vec<[f64; 3]> = (0..len).map(|_| rng.point()).collect();
        let patch = BezierTriangle::new(n, net.clone()).expect("net");
        let (mut out, mut level, mut want) = (net.clone(), net.clone(), net.clone());
        let mut scratch = Vec::new();
        naive_triangle(&net, n, &corners, &mut level, &mut want);
        patch
            .restrict_into(&corners, &mut out, &mut scratch)
            .expect("fits");
        close(&out, &want, "triangle engine");
        group.bench_with_input(BenchmarkId::new("engine", n), &n, |bench, _| {
            bench.iter(|| {
                patch
                    .restrict_into(black_box(&corners), &mut out, &mut scratch)
                    .expect("fits");
                black_box(&out);
            })
        });
        if n > 16 {
            continue;
        }
        group.bench_with_input(BenchmarkId::new("naive_pyramid", n), &n, |bench, _| {
            bench.iter(|| {
                naive_triangle(
                    black_box(&net),
                    n,
                    black_box(&corners),
                    &mut level,
                    &mut out,
                );
                black_box(&out);
            })
        });
    }
    group.finish();
}

fn powers(c: &mut Criterion) {
    let mut rng = Rng(15);
    let mut group = c.benchmark_group("power");
    for n in [3, 8, 16, 24, 32] {
        let curve = PowerCurve::new((0..=n).map(|_| rng.point().to_vec()).collect()).expect("c");
        let (a, b) = (0.25, 0.75);
        for method in [Method::Bulk, Method::TaylorShift, Method::ClosedForm] {
            group.bench_with_input(BenchmarkId::new(method.name(), n), &n, |bench, _| {
                bench.iter(|| restrict_power_curve(black_box(&curve), &a, &b, method))
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(1));
    targets = curves, tensors, triangles, powers
}
criterion_main!(benches);
