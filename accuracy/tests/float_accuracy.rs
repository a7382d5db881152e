//! f64 answers against exact ones: the measured relative error stays within documented bounds
//! (see `cargo run --release -p blossom-accuracy --example float_error` for the full table),
//! and the sweep of every engine path against a stable reference on the same inputs.

#[path = "../../tests/common/mod.rs"]
mod common;

use blossom::{Method, Rational};
use blossom_accuracy::{curve_error, tensor_error, triangle_error};
use common::Rng;
use num_bigint::BigInt;

fn unit(rng: &mut Rng) -> Rational {
    Rational::new(
        BigInt::from((rng.next() % 2001) as i64 - 1000),
        BigInt::from(1000),
    )
}

#[test]
fn low_degree_restrictions_are_accurate_to_a_few_ulps() {
    let mut rng = Rng(11);
    for n in 1..=6 {
        let curve = blossom::PowerCurve::new(
            (0..=n)
                .map(|_| vec![unit(&mut rng), unit(&mut rng)])
                .collect(),
        )
        .unwrap();
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        for method in Method::ALL {
            let e = curve_error(&curve, &a, &b, method);
            assert!(e < 1e-13, "curve n={n} {method:?}: {e:e}");
        }
        let s = blossom::PowerSurface::new(
            (0..=n / 2)
                .map(|_| (0..=n - n / 2).map(|_| vec![unit(&mut rng)]).collect())
                .collect(),
        )
        .unwrap();
        let rect: [Rational; 4] = std::array::from_fn(|_| unit(&mut rng));
        let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [unit(&mut rng), unit(&mut rng)]);
        for method in Method::ALL {
            assert!(tensor_error(&s, &rect, method) < 1e-13, "tensor {method:?}");
            let e = triangle_error(&s, &tri, method);
            assert!(e < 1e-13, "triangle n={n} {method:?}: {e:e}");
        }
    }
}

#[test]
fn high_degree_power_basis_loses_digits_in_the_taylor_shift_only() {
    // Documented conditioning: the Taylor shift amplifies rounding by up to 2^n at degree n,
    // while the closed form (positive weights summing to at most 1 for |a|, |b| <= 1) does
    // not, and neither does the halving engine in the scaled power basis (the default), whose
    // steps d_i + t d_(i+1) evaluate the closed form's sums in nested order.
    let mut rng = Rng(5);
    let (mut taylor, mut closed, mut bulk) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..5 {
        let curve =
            blossom::PowerCurve::new((0..=24).map(|_| vec![unit(&mut rng)]).collect()).unwrap();
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        taylor = taylor.max(curve_error(&curve, &a, &b, Method::TaylorShift));
        closed = closed.max(curve_error(&curve, &a, &b, Method::ClosedForm));
        bulk = bulk.max(curve_error(&curve, &a, &b, Method::Bulk));
    }
    assert!(closed < 1e-13, "closed form {closed:e}");
    assert!(
        taylor > 100.0 * closed,
        "taylor shift {taylor:e} closed {closed:e}"
    );
    assert!(
        bulk <= 4.0 * closed.max(f64::EPSILON),
        "bulk {bulk:e} closed {closed:e}"
    );
}

#[test]
fn the_pyramid_stays_accurate_on_a_long_thin_triangle() {
    // A case found by random testing: a patch of bidegree (5, 1) on a thin triangle reaching
    // y = 737. Over the fixed unit reference triangle the pyramid's relative error was 1.8e-2.
    const COEFFICIENTS: [[[&str; 2]; 2]; 6] = [
        [["-3", "-13/8"], ["-3", "-387"]],
        [["5", "611/1000"], ["0", "-5"]],
        [["2", "-31/25"], ["-1/3", "-15/8"]],
        [["3/2", "19/5"], ["19/8", "-5/12"]],
        [["16/5", "1/1000"], ["-7/3", "-434"]],
        [["-451/500", "-2"], ["-17", "-13/7"]],
    ];
    let q = |x: &str| x.parse::<Rational>().unwrap();
    let s = blossom::PowerSurface::new(
        COEFFICIENTS
            .iter()
            .map(|row| {
                row.iter()
                    .map(|p| p.iter().map(|x| q(x)).collect())
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    let tri = [
        [q("7/1000"), q("567/100")],
        [q("0"), q("0")],
        [q("5/3"), q("737")],
    ];
    let e = triangle_error(&s, &tri, Method::Pyramid);
    assert!(e < 1e-10, "pyramid {e:e}");
}

// Issue 12, item 4: every f64 path of the engine (generic, batch, generated) within 4x of the
// stable reference's error on the same inputs (the textbook pyramid for Bézier input, the
// closed form for power input), on intervals inside [0, 1], of length 1e-3 and in [-3, 3].
// One test per family, so that the test harness runs them on every core.

/// The paths of the engine held to the bound.
const ENGINE_PATHS: [&str; 3] = [
    blossom_accuracy::sweep::ENGINE,
    blossom_accuracy::sweep::BATCH,
    blossom_accuracy::sweep::GENERATED,
];

/// Asserts every row's worst ratio of `paths` to the reference is at most 4.
fn within_4x_of_the_reference(
    rows: Vec<blossom_accuracy::sweep::Row>,
    paths: &[&str],
) -> Vec<blossom_accuracy::sweep::Row> {
    for row in &rows {
        let ratio = row.worst_ratio(paths);
        assert!(ratio <= 4.0, "{ratio:.2}x the reference: {row:?}");
    }
    rows
}

/// Bézier curves of degree 1..=64. The Taylor shift, the old default, must fail the same
/// bound at high degree: the sweep can tell a path that loses digits.
#[test]
fn the_engine_is_as_accurate_as_the_stable_reference_on_curves() {
    use blossom_accuracy::sweep::{bezier_curves, BEFORE};
    let curves = within_4x_of_the_reference(
        bezier_curves(&(1..=64).collect::<Vec<_>>(), 6, 21),
        &ENGINE_PATHS,
    );
    let degree_48 = curves.iter().find(|r| r.degree.0 == 48).expect("degree 48");
    assert!(degree_48.worst_ratio(&[BEFORE]) > 1e6, "{degree_48:?}");
}

/// Tensor-product patches up to (16, 16).
#[test]
fn the_engine_is_as_accurate_as_the_stable_reference_on_tensor_patches() {
    let tensors: Vec<(usize, usize)> = (0..=16)
        .map(|n| (n, n))
        .chain([(3, 1), (2, 5), (16, 3), (1, 16)])
        .collect();
    within_4x_of_the_reference(
        blossom_accuracy::sweep::bezier_tensors(&tensors, 4, 22),
        &ENGINE_PATHS,
    );
}

/// Triangular patches of degree 1..=16.
#[test]
fn the_engine_is_as_accurate_as_the_stable_reference_on_triangles() {
    within_4x_of_the_reference(
        blossom_accuracy::sweep::bezier_triangles(&(1..=16).collect::<Vec<_>>(), 4, 23),
        &ENGINE_PATHS,
    );
}

/// Power-form curves of degree 1..=32 (the reference is the closed form).
#[test]
fn the_engine_is_as_accurate_as_the_stable_reference_on_power_curves() {
    within_4x_of_the_reference(
        blossom_accuracy::sweep::power_curves(&(1..=32).collect::<Vec<_>>(), 10, 24),
        &["bulk"],
    );
}
