//! A batch of Bézier curves restricted to one interval together (`Batch`, `RestrictionMap`).
//!
//! `cargo run -p blossom --example batch_of_curves`.
//!
//! The batch stores blocks of `BATCH_LANES` curves coordinate by coordinate, so one block is
//! one Bézier curve whose points have 512-fold coordinates: every de Casteljau step of the
//! restriction is one long vectorised loop, and every curve gets exactly (bit for bit) what the
//! engine gives it alone.

use blossom::{Batch, BezierCurve, RestrictionMap, BATCH_LANES};

pub fn main() {
    // 1000 cubic curves in 3-D (two blocks, the second one partly filled), from a small
    // deterministic generator.
    let mut state = 1u64;
    let mut number = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let curves: Vec<BezierCurve<f64>> = (0..1000)
        .map(|_| {
            BezierCurve::new((0..4).map(|_| (0..3).map(|_| number()).collect()).collect()).unwrap()
        })
        .collect();

    // Every curve restricted to [0.2, 0.7]: one map, one call.
    let batch = Batch::from_curves(&curves).unwrap();
    let map = RestrictionMap::curve(3, 0.2, 0.7).unwrap();
    let mut out = Batch::zeros(map.outputs(), batch.dim(), batch.len()).unwrap();
    batch.restrict_into(&map, &mut out).unwrap();

    // Each result is bit for bit the single-curve restriction.
    for (k, curve) in curves.iter().enumerate() {
        let alone = curve.subsegment(0.2..0.7);
        assert_eq!(alone.control_points(), out.net(k));
    }
    // The first point of each restricted curve is the curve at 0.2 (to rounding).
    let p = out.net(999)[0].clone();
    let want = curves[999].eval(&0.2);
    assert!(p.iter().zip(&want).all(|(x, y)| (x - y).abs() <= 1e-15));
    println!(
        "{} curves ({} blocks of {BATCH_LANES}) restricted; curve 999 now starts at {p:?}",
        out.len(),
        out.len().div_ceil(BATCH_LANES)
    );
}
