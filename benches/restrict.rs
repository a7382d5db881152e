//! Growth of the cost of restriction with the degree, f64, 3-D points: the bulk path
//! (`Method::Bulk`, the default) against the paper's per-point closed forms (3), (9), (14)
//! (`Method::ClosedForm`) in the same run.
//!
//! Run: `cargo bench --bench restrict`, then `cargo run --release --example bench_slopes` for
//! the log-log slopes and ratios.
//!
//! The group `batch` (`cargo bench -p blossom --bench restrict -- batch`): 10^5 planar cubics
//! held as plain arrays, restricted to one interval and read back as plain arrays, through a
//! [`Batch`] (pack, restrict, unpack) against [`RestrictionMap::restrict_arrays`] (the
//! caller's layout), the three steps of the round trip apart, and the round trip with every
//! buffer reused (`Batch::copy_from_arrays`, `Batch::copy_to_arrays`).

use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Batch,
    Method, PowerCurve, PowerSurface, RestrictionMap,
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

/// Planar cubics for the group `batch`.
const CUBICS: usize = 100_000;

fn batch(c: &mut Criterion) {
    let input: Vec<[[f64; 2]; 4]> = (0..CUBICS)
        .map(|k| std::array::from_fn(|p| [value(8 * k + 2 * p), value(8 * k + 2 * p + 1)]))
        .collect();
    let map = RestrictionMap::curve(3, 0.25, 0.75).expect("a finite interval");
    let mut out = vec![[[0.0; 2]; 4]; CUBICS];
    let packed = Batch::from_arrays(&input).expect("fits");
    let mut restricted = Batch::zeros(4, 2, CUBICS).expect("fits");
    let mut group = c.benchmark_group("batch");
    group.bench_function("round_trip", |bench| {
        bench.iter(|| {
            let batch = Batch::from_arrays(black_box(&input)).expect("fits");
            let mut restricted = Batch::zeros(4, 2, CUBICS).expect("fits");
            batch.restrict_into(&map, &mut restricted).expect("fits");
            restricted.to_arrays::<4, 2>().expect("fits")
        })
    });
    group.bench_function("restrict_arrays", |bench| {
        bench.iter(|| {
            map.restrict_arrays(black_box(&input), &mut out)
                .expect("fits")
        })
    });
    group.bench_function("pack", |bench| {
        bench.iter(|| Batch::from_arrays(black_box(&input)).expect("fits"))
    });
    group.bench_function("restrict_into", |bench| {
        bench.iter(|| packed.restrict_into(&map, &mut restricted).expect("fits"))
    });
    group.bench_function("unpack", |bench| {
        bench.iter(|| black_box(&packed).to_arrays::<4, 2>().expect("fits"))
    });
    // The same round trip with every buffer reused from call to call.
    let mut reused = Batch::zeros(4, 2, 0).expect("fits");
    group.bench_function("round_trip_reused", |bench| {
        bench.iter(|| {
            reused.copy_from_arrays(black_box(&input)).expect("fits");
            reused.restrict_into(&map, &mut restricted).expect("fits");
            restricted.copy_to_arrays(&mut out).expect("fits")
        })
    });
    group.bench_function("pack_reused", |bench| {
        bench.iter(|| reused.copy_from_arrays(black_box(&input)).expect("fits"))
    });
    group.bench_function("unpack_reused", |bench| {
        bench.iter(|| black_box(&packed).copy_to_arrays(&mut out).expect("fits"))
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(20);
    targets = curves, tensors, triangles, batch
}
criterion_main!(benches);
