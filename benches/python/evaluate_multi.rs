//! The Rust side of `benches/python/evaluate_multi.py`: `BezierCurve::eval_many` (de
//! Casteljau) and `BezierCurve::eval_many_linear` (O(n) per point, what `Curve.evaluate_multi`
//! calls) on one random planar curve per degree 1..=20 at 1,000 parameters uniform in [0, 1],
//! in microseconds per call (the best of 7 rounds of the mean over about 20 ms). Printed, one
//! line per degree: `degree <n> <de Casteljau us> <linear us>`.
//!
//! Run: `cargo run --release -p blossom-python --example evaluate_multi --features rust-bench`.

use blossom::BezierCurve;
use std::hint::black_box;
use std::time::Instant;

/// A small deterministic generator (xorshift64*), numbers in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The best over 7 rounds of the mean time of `f` in a round of about 20 ms, in microseconds.
fn time(mut f: impl FnMut()) -> f64 {
    (0..7)
        .map(|_| {
            let start = Instant::now();
            let mut calls = 0u32;
            while start.elapsed().as_secs_f64() < 0.02 {
                f();
                calls += 1;
            }
            start.elapsed().as_secs_f64() * 1e6 / f64::from(calls)
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() -> Result<(), blossom::Error> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let ts: Vec<f64> = (0..1000).map(|_| rng.next()).collect();
    let mut out = vec![0.0; 2 * ts.len()];
    // An optional argument: the one degree to time.
    let only: Option<usize> = std::env::args().nth(1).and_then(|a| a.parse().ok());
    for n in 1..=20 {
        let points = (0..=n)
            .map(|_| vec![2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0])
            .collect();
        let c = BezierCurve::new(points)?;
        if only.is_some_and(|d| d != n) {
            continue;
        }
        let dc = time(|| c.eval_many(black_box(&ts), &mut out).expect("sizes"));
        let linear = time(|| c.eval_many_linear(black_box(&ts), &mut out).expect("sizes"));
        println!("degree {n} {dc:.2} {linear:.2}");
        black_box(&out);
    }
    Ok(())
}
