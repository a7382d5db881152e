//! Growth of the cost of restriction with the degree, f64, 3-D points: the bulk path
//! (`Method::Bulk`, the default) against the paper's per-point closed forms (3), (9), (14)
//! (`Method::ClosedForm`) in the same run.
//!
//! Run: `cargo bench --bench restrict`, then `cargo run --release --example bench_slopes` for
//! the log-log slopes and ratios.

use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
    PowerCurve, PowerSurface,
};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

fn value(k: usize) -> f64 {
    // Deterministic, varied, of moderate size.
    ((k * 7919 % 1000) as f64 - 500.0) / 250.0
}

fn curve(n: usize) -> PowerCurve<f64> {
    PowerCurve::new(
        (0..=n)
            .map(|i| (0..3).map(|k| value(3 * i + k)).collect())
            .collect(),
    )
    .unwrap()
}

fn surface(n: usize, m: usize) -> PowerSurface<f64> {
    PowerSurface::new(
        (0..=n)
            .map(|i| {
                (0..=m)
                    .map(|j| (0..3).map(|k| value(97 * i + 3 * j + k)).collect())
                    .collect()
            })
            .collect(),
    )
    .unwrap()
}

const METHODS: [Method; 2] = [Method::Bulk, Method::ClosedForm];

fn curves(c: &mut Criterion) {
    let mut group = c.benchmark_group("curve");
    for n in [4usize, 8, 16, 32, 64] {
        let input = curve(n);
        for method in METHODS {
            group.bench_with_input(
                BenchmarkId::new(method.name(), n),
                &input,
                |bench, input| {
                    bench.iter(|| restrict_power_curve(black_box(input), &0.25, &0.75, method))
                },
            );
        }
    }
    group.finish();
}

fn tensors(c: &mut Criterion) {
    let mut group = c.benchmark_group("tensor");
    let rect = [0.25, 0.75, -0.5, 0.5];
    for n in [2usize, 4, 8, 16] {
        let input = surface(n, n);
        for method in METHODS {
            group.bench_with_input(
                BenchmarkId::new(method.name(), n),
                &input,
                |bench, input| {
                    bench.iter(|| restrict_power_surface(black_box(input), &rect, method))
                },
            );
        }
    }
    group.finish();
}

fn triangles(c: &mut Criterion) {
    let mut group = c.benchmark_group("triangle");
    let tri = [[0.0, 0.5], [0.5, 0.0], [0.5, 0.5]];
    for big_n in [2usize, 4, 8, 16] {
        let input = surface(big_n / 2, big_n - big_n / 2);
        for method in METHODS {
            group.bench_with_input(
                BenchmarkId::new(method.name(), big_n),
                &input,
                |bench, input| {
                    bench
                        .iter(|| restrict_power_surface_to_triangle(black_box(input), &tri, method))
                },
            );
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(20);
    targets = curves, tensors, triangles
}
criterion_main!(benches);
