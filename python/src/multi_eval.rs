//! `Curve.evaluate_multi` in float64: de Casteljau's algorithm run on blocks of [`LANES`]
//! parameters at once, so that every affine step x + s (y - x) is one straight loop over the
//! lanes, which the compiler vectorises (the library's `BezierCurve::eval_into` evaluates one
//! parameter at a time; bezier's compiled `evaluate_multi` is likewise vectorised across
//! parameters). Each step is the library's `BernsteinStep` formula, in the same order, so every
//! answer is bit for bit `Curve.evaluate`'s.
//!
//! This is the one place of this algorithm; it belongs in the library beside `eval_into`
//! (`BezierCurve::eval_many`), where the binding would then call it.

/// Parameters per block.
pub const LANES: usize = 8;

/// The curve with point-major coordinates `points` (`dim` each) at every parameter of `params`,
/// written point after point to `out` (`params.len() * dim` numbers).
pub fn eval_many(points: &[f64], dim: usize, params: &[f64], out: &mut [f64]) {
    let count = points.len() / dim;
    let mut level = vec![[0.0f64; LANES]; points.len()];
    for (s_block, out_block) in params.chunks(LANES).zip(out.chunks_mut(LANES * dim)) {
        let mut s = [0.0f64; LANES];
        s[..s_block.len()].copy_from_slice(s_block);
        for (lane, &v) in level.iter_mut().zip(points) {
            *lane = [v; LANES];
        }
        for r in 1..count {
            for j in 0..(count - r) * dim {
                let y = level[j + dim];
                let x = &mut level[j];
                for l in 0..LANES {
                    x[l] += s[l] * (y[l] - x[l]);
                }
            }
        }
        for (m, point) in out_block.chunks_exact_mut(dim).enumerate() {
            for (x, value) in point.iter_mut().enumerate() {
                *value = level[x][m];
            }
        }
    }
}
