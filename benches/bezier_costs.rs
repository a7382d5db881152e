//! Growth of the cost of restricting Bézier input with the degree, f64, 3-D points, three
//! algorithms in the same run:
//!
//! * `bulk`: `BezierCurve::subsegment` and its siblings, the halving engine in the Bernstein
//!   basis through the runtime-dimension API, O(n^2) per curve, O(nm(n + m)) per tensor patch,
//!   O(N^3) per triangle (`benches/engine.rs` measures the allocation-free front end);
//! * `pyramid`: every control point on its own by de Casteljau's pyramid on the blossom,
//!   O(n^3), O(n^2 m^2 (n + m)) (with n = m: O(n^5)) and O(N^5) in all;
//! * `closed_form`: the power form, then every control point by the closed forms (3) and (9).
//!   Formula (14) takes a power form of bidegree (n, m) with N = n + m, and the power form of a
//!   triangular Bézier net (every i + j <= N) is not one, so triangles are compared with the
//!   pyramid only; `benches/restrict.rs` compares (14) with the bulk path on power input.
//!
//! Run: `cargo bench --bench bezier_costs`, then
//! `cargo run --release --example bench_slopes bezier_curve bezier_tensor bezier_triangle`
//! for the medians, the log-log slopes and the ratios.

use blossom::engine::bernstein_to_power;
use blossom::{bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom};
use blossom::{
    restrict_power_curve, restrict_power_surface, BezierCurve, Method, PowerCurve, PowerSurface,
    TensorPatch, TriangularPatch,
};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

fn value(k: usize) -> f64 {
    // Deterministic, varied, of moderate size.
    ((k * 7919 % 1000) as f64 - 500.0) / 250.0
}

fn point(k: usize) -> Vec<f64> {
    (0..3).map(|x| value(3 * k + x)).collect()
}

fn repeated(x: f64, k: usize, y: f64, l: usize) -> Vec<f64> {
    std::iter::repeat_n(x, k)
        .chain(std::iter::repeat_n(y, l))
        .collect()
}

const A: f64 = 0.25;
const B: f64 = 0.75;
const RECT: [f64; 4] = [0.25, 0.75, 0.125, 0.5];
const TRI: [[f64; 2]; 3] = [[0.5, 0.25], [0.125, 0.75], [0.25, 0.125]];

fn curves(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier_curve");
    for n in [4usize, 8, 16, 32, 64, 128, 256] {
        let curve = BezierCurve::new((0..=n).map(point).collect()).unwrap();
        group.bench_with_input(BenchmarkId::new("bulk", n), &curve, |bench, curve| {
            bench.iter(|| black_box(curve).subsegment(A..B))
        });
        if n > 128 {
            continue; // the per-point algorithms: 0.04 s (pyramid) per call at n = 128
        }
        group.bench_with_input(BenchmarkId::new("pyramid", n), &curve, |bench, curve| {
            bench.iter(|| {
                (0..=n)
                    .map(|j| {
                        bezier_curve_blossom(
                            &black_box(curve).control_points().to_vec(),
                            &repeated(A, n - j, B, j),
                        )
                        .expect("the arguments of the degree")
                    })
                    .collect::<Vec<_>>()
            })
        });
        if n > 64 {
            continue; // (3) per point: O(n^3) with big binomials, 2.4 s per call at n = 128
        }
        group.bench_with_input(
            BenchmarkId::new("closed_form", n),
            &curve,
            |bench, curve| {
                bench.iter(|| {
                    let power = PowerCurve::new(bernstein_to_power(
                        &black_box(curve).control_points().to_vec(),
                    ))
                    .unwrap();
                    restrict_power_curve(&power, &A, &B, Method::ClosedForm)
                })
            },
        );
    }
    group.finish();
}

fn tensors(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier_tensor");
    for n in [4usize, 8, 16, 24, 32, 48, 64] {
        let net = (0..=n)
            .map(|i| (0..=n).map(|j| point(97 * i + j)).collect())
            .collect();
        let patch = TensorPatch::new(net).unwrap();
        let [a, b, cc, d] = RECT;
        group.bench_with_input(BenchmarkId::new("bulk", n), &patch, |bench, patch| {
            bench.iter(|| black_box(patch).restrict(&RECT))
        });
        if n > 24 {
            continue; // the per-point algorithms: 0.1 s (pyramid) per call at n = 24
        }
        group.bench_with_input(BenchmarkId::new("pyramid", n), &patch, |bench, patch| {
            bench.iter(|| {
                let mut out = Vec::new();
                for nu in 0..=n {
                    for mu in 0..=n {
                        out.push(
                            bezier_tensor_blossom(
                                &black_box(patch).to_nested(),
                                &repeated(a, n - nu, b, nu),
                                &repeated(cc, n - mu, d, mu),
                            )
                            .expect("the arguments of the degree"),
                        );
                    }
                }
                out
            })
        });
        if n > 16 {
            continue; // (9) per point: 0.17 s per call at n = 24
        }
        group.bench_with_input(
            BenchmarkId::new("closed_form", n),
            &patch,
            |bench, patch| {
                bench.iter(|| {
                    // The power form, converting along u (rows as long points), then along v.
                    let rows: Vec<Vec<f64>> = black_box(patch)
                        .to_nested()
                        .iter()
                        .map(|row| row.concat())
                        .collect();
                    let coefficients: Vec<Vec<Vec<f64>>> = bernstein_to_power(&rows)
                        .into_iter()
                        .map(|long| {
                            let row: Vec<Vec<f64>> = long.chunks(3).map(<[f64]>::to_vec).collect();
                            bernstein_to_power(&row)
                        })
                        .collect();
                    restrict_power_surface(
                        &PowerSurface::new(coefficients).unwrap(),
                        &RECT,
                        Method::ClosedForm,
                    )
                })
            },
        );
    }
    group.finish();
}

fn triangles(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier_triangle");
    for big_n in [4usize, 8, 16, 24, 32, 48, 64] {
        let len = (big_n + 1) * (big_n + 2) / 2;
        let patch = TriangularPatch::new(big_n, (0..len).map(point).collect()).unwrap();
        let bary = TRI.map(|[s, t]| [s, t, 1.0 - s - t]);
        group.bench_with_input(BenchmarkId::new("bulk", big_n), &patch, |bench, patch| {
            bench.iter(|| black_box(patch).restrict(&TRI))
        });
        if big_n > 24 {
            continue; // the pyramid: 0.04 s per call at N = 24
        }
        group.bench_with_input(
            BenchmarkId::new("pyramid", big_n),
            &patch,
            |bench, patch| {
                bench.iter(|| {
                    black_box(patch)
                        .entries()
                        .map(|(nu, mu, la, _)| {
                            let args: Vec<[f64; 3]> = std::iter::repeat_n(bary[0], nu)
                                .chain(std::iter::repeat_n(bary[1], mu))
                                .chain(std::iter::repeat_n(bary[2], la))
                                .collect();
                            bezier_triangle_blossom(patch, &args)
                                .expect("the arguments of the degree")
                        })
                        .collect::<Vec<_>>()
                })
            },
        );
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = curves, tensors, triangles
}
criterion_main!(benches);
