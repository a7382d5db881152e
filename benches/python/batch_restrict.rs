//! The Rust side of `benches/python/bench.py`'s batch figure: 100,000 planar cubics restricted
//! to [0.25, 0.75] by the library's call `RestrictionMap::restrict_arrays` (the caller's
//! `[[f64; 2]; 4]` arrays, curves restricted where they lie), best of 20 runs, printed as
//! `rust_batch_ns <nanoseconds per call>`: the call `blossom.restrict_curves` makes on the
//! same layout. Also, on the same numbers: `rust_rows_ns`, the 200,000 coordinate rows as
//! one-dimensional cubics (the binding's C-order route before issue 47); `rust_c_order_ns`,
//! the C-ordered `N x 2 x 4` layout by the binding's route since (`restrict_c_order` of
//! python/src/batch.rs, copied here: 64 curves at a time copied point after point, restricted,
//! copied back to rows); `rust_chunked_ns`, `restrict_arrays` called on 64 curves at a time
//! (what the chunks cost by themselves).
//!
//! Run: `cargo run --release -p blossom-python --example batch_restrict --features rust-bench`.

use blossom::RestrictionMap;
use std::time::Instant;

const CURVES: usize = 100_000;
const RUNS: usize = 20;

/// A small deterministic generator (xorshift64*), numbers in [-1, 1).
fn numbers(count: usize) -> Vec<f64> {
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    (0..count)
        .map(|_| {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            let bits = state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
            bits as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

fn best_of(mut run: impl FnMut()) -> f64 {
    (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            run();
            start.elapsed().as_nanos() as f64
        })
        .fold(f64::INFINITY, f64::min)
}

/// `restrict_c_order` of python/src/batch.rs for planar cubics.
fn restrict_c_order(
    map: &RestrictionMap,
    input: &[f64],
    output: &mut [f64],
) -> Result<(), blossom::Error> {
    const CHUNK: usize = 64;
    let mut points = [[[0.0; 2]; 4]; CHUNK];
    let mut answers = [[[0.0; 2]; 4]; CHUNK];
    let (curves_in, _) = input.as_chunks::<4>();
    let (curves_in, _) = curves_in.as_chunks::<2>();
    let (curves_out, _) = output.as_chunks_mut::<4>();
    let (curves_out, _) = curves_out.as_chunks_mut::<2>();
    for (rows_in, rows_out) in curves_in.chunks(CHUNK).zip(curves_out.chunks_mut(CHUNK)) {
        let m = rows_in.len();
        for (curve, rows) in points.iter_mut().zip(rows_in) {
            for (x, row) in rows.iter().enumerate() {
                for (p, &v) in curve.iter_mut().zip(row) {
                    p[x] = v;
                }
            }
        }
        map.restrict_arrays(&points[..m], &mut answers[..m])?;
        for (curve, rows) in answers.iter().zip(rows_out.iter_mut()) {
            for (x, row) in rows.iter_mut().enumerate() {
                for (v, p) in row.iter_mut().zip(curve) {
                    *v = p[x];
                }
            }
        }
    }
    Ok(())
}

fn main() -> Result<(), blossom::Error> {
    let flat = numbers(CURVES * 8);
    let curves: Vec<[[f64; 2]; 4]> = flat
        .chunks_exact(8)
        .map(|c| [[c[0], c[1]], [c[2], c[3]], [c[4], c[5]], [c[6], c[7]]])
        .collect();
    let mut out = vec![[[0.0; 2]; 4]; CURVES];
    let map = RestrictionMap::curve(3, 0.25, 0.75)?;
    let arrays = best_of(|| map.restrict_arrays(&curves, &mut out).expect("shapes fit"));
    // The same numbers as 2N one-dimensional cubics (the C-order N x 2 x 4 layout).
    let rows: Vec<[[f64; 1]; 4]> = flat
        .chunks_exact(4)
        .map(|c| [[c[0]], [c[1]], [c[2]], [c[3]]])
        .collect();
    let mut out_rows = vec![[[0.0; 1]; 4]; rows.len()];
    let by_rows = best_of(|| {
        map.restrict_arrays(&rows, &mut out_rows)
            .expect("shapes fit")
    });
    // The same numbers in C order (each curve's x row, then its y row) restricted the way
    // `blossom.restrict_curves` does it (python/src/batch.rs, `restrict_c_order`, copied
    // here: the binding is a cdylib): 64 curves at a time copied point after point, restricted
    // by `restrict_arrays`, copied back to rows.
    let mut out_c = vec![0.0; flat.len()];
    let c_order = best_of(|| restrict_c_order(&map, &flat, &mut out_c).expect("shapes fit"));
    println!("rust_batch_ns {arrays:.0}");
    println!("rust_rows_ns {by_rows:.0}");
    println!("rust_c_order_ns {c_order:.0}");
    let chunked = best_of(|| {
        for (a, b) in curves.chunks(64).zip(out.chunks_mut(64)) {
            map.restrict_arrays(a, b).expect("shapes fit");
        }
    });
    println!("rust_chunked_ns {chunked:.0}");
    std::hint::black_box((&out, &out_rows));
    Ok(())
}
