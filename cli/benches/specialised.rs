//! Specialised (macro-generated, eq. (3)/(9) unrolled) restriction against the runtime generic
//! bulk path and the per-point closed form, f64 and 3-D points, in one run:
//!
//! `cargo bench --bench specialised`
//!
//! * `curve3/specialised`: `blossom::restriction!` cubic on `[[f64; 3]; 4]`;
//! * `curve3/specialised_dispatch`: the carried evaluator through the `Vec` API
//!   (`restrict_curve_specialised`, one `D = 1` call per coordinate);
//! * `curve3/generic_bulk`: `restrict_power_curve(.., Method::Bulk)`;
//! * `curve3/closed_form`: `restrict_power_curve(.., Method::ClosedForm)` (eq. (3) per point);
//! * the same for the (3, 3) tensor patch.

use blossom::{restrict_power_curve, restrict_power_surface, Method, PowerCurve, PowerSurface};
use blossom_cli::specialised::{restrict_curve_specialised, restrict_tensor_specialised};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;

blossom::restriction!(name = cubic, shape = curve, degree = 3);
blossom::restriction!(name = bicubic, shape = tensor, degree = (3, 3));

fn curve(c: &mut Criterion) {
    let coef: [[f64; 3]; 4] = [
        [1.0, -2.0, 0.5],
        [0.25, 3.0, -1.0],
        [2.0, 0.5, 1.5],
        [-0.75, 1.0, 2.0],
    ];
    let power = PowerCurve::new(coef.iter().map(|p| p.to_vec()).collect()).unwrap();
    let (a, b) = (0.25, 0.75);
    let mut g = c.benchmark_group("curve3");
    g.bench_function("specialised", |bch| {
        bch.iter(|| cubic(black_box(&coef), black_box(&a), black_box(&b)))
    });
    g.bench_function("specialised_dispatch", |bch| {
        bch.iter(|| restrict_curve_specialised(black_box(&power), black_box(&a), black_box(&b)))
    });
    g.bench_function("generic_bulk", |bch| {
        bch.iter(|| {
            restrict_power_curve(
                black_box(&power),
                black_box(&a),
                black_box(&b),
                Method::Bulk,
            )
        })
    });
    g.bench_function("closed_form", |bch| {
        bch.iter(|| {
            restrict_power_curve(
                black_box(&power),
                black_box(&a),
                black_box(&b),
                Method::ClosedForm,
            )
        })
    });
    g.finish();
}

fn tensor(c: &mut Criterion) {
    let coef: [[[f64; 3]; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let (i, j) = (i as f64, j as f64);
            [i - j * 0.5, 0.25 * i * j + 1.0, 2.0 - i + j]
        })
    });
    let power = PowerSurface::new(
        coef.iter()
            .map(|r| r.iter().map(|p| p.to_vec()).collect())
            .collect(),
    )
    .unwrap();
    let rect = [0.25, 0.75, -0.5, 0.5];
    let mut g = c.benchmark_group("tensor3x3");
    g.bench_function("specialised", |bch| {
        bch.iter(|| bicubic(black_box(&coef), black_box(&rect)))
    });
    g.bench_function("specialised_dispatch", |bch| {
        bch.iter(|| restrict_tensor_specialised(black_box(&power), black_box(&rect)))
    });
    g.bench_function("generic_bulk", |bch| {
        bch.iter(|| restrict_power_surface(black_box(&power), black_box(&rect), Method::Bulk))
    });
    g.bench_function("closed_form", |bch| {
        bch.iter(|| restrict_power_surface(black_box(&power), black_box(&rect), Method::ClosedForm))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(50);
    targets = curve, tensor
}
criterion_main!(benches);
