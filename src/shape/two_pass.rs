//! The restriction of a float Bézier curve by two de Casteljau subdivisions, for the degrees
//! that have no unrolled evaluator ([`crate::shape::unrolled`]) in dimensions 1..=4.
//!
//! With c the end of [a, b] of larger magnitude and e the other, the part of the curve over
//! [0, c] is de Casteljau's left piece at c (eq. (2) of the inverse-relations paper, applied
//! n times in place), and the part over [e, c] is the right piece of that at t = e / c, with
//! |t| <= 1. When c = b that is the answer, from a to b; when c = a it runs from b to a and is
//! reversed. Both passes take n(n + 1) / 2 steps x + s (y - x), so the whole restriction takes
//! n(n + 1) per coordinate, fewer than the division-free halving of the engine
//! (1.17 n(n + 1) at n = 3 to 1.45 n(n + 1) at n = 64, `shape/halving.rs`), in loops short
//! enough to compile in a moment for every degree (the unrolled evaluators of degrees 9..=24
//! cost minutes of compile time; they are the feature `unrolled-high`).
//!
//! Only intervals inside [0, 1] come here (the restriction of a curve to a piece of itself,
//! the common case); an interval reaching outside goes to the engine, whose steps at a and b
//! themselves extrapolate more accurately than a first pass that extrapolates every level
//! (measured: 18x the reference's error at degree 20 on [-3, 3] intervals, the engine 1x,
//! `accuracy/tests/float_accuracy.rs`). Inside [0, 1] accuracy is de Casteljau's: every step
//! is a convex combination, and the one division rounds t to within half an ulp, which moves the cut by
//! |e| 2^-53 relative to its position: the computed points are those of the exact restriction
//! to an interval whose ends differ from a and b by a relative 2^-53, plus the rounding of
//! the steps (measured against the exact answer in `tests/suite/bezier_input/arrays.rs`).
//! Exact rings never come here: their restriction is the engine's, division-free.

/// `out` = the control points over [a, b] of the curve with flat control points `points`
/// (`D` numbers per point), by two subdivisions; `out` has the length of `points`.
macro_rules! two_pass {
    ($name:ident, $t:ty) => {
        #[inline(never)]
        fn $name<const D: usize>(points: &[$t], a: $t, b: $t, out: &mut [$t]) {
            out.copy_from_slice(points);
            let (out, _) = out.as_chunks_mut::<D>();
            let (first, second, reversed) = if b.abs() >= a.abs() {
                (b, a, false)
            } else {
                (a, b, true)
            };
            if first == 0.0 {
                // a = b = 0: every control point is the curve's value at 0.
                let start = out[0];
                out.fill(start);
                return;
            }
            let n = out.len() - 1;
            // The part over [0, first]: at level r, points r..=n become
            // x_i = x_(i-1) + first (x_i - x_(i-1)) of the previous level, read from a carry.
            for r in 1..=n {
                let level = &mut out[r - 1..];
                let mut previous = level[0];
                for point in &mut level[1..] {
                    let current = *point;
                    for x in 0..D {
                        point[x] = previous[x] + first * (current[x] - previous[x]);
                    }
                    previous = current;
                }
            }
            // Its part over [second / first, 1]: at level r, points 0..=n - r.
            let t = second / first;
            for r in 1..=n {
                let level = &mut out[..=n - r + 1];
                let mut next = level[level.len() - 1];
                for point in level[..n - r + 1].iter_mut().rev() {
                    let current = *point;
                    for x in 0..D {
                        point[x] = current[x] + t * (next[x] - current[x]);
                    }
                    next = current;
                }
            }
            if reversed {
                out.reverse();
            }
        }
    };
}

two_pass!(two_pass_f64, f64);
two_pass!(two_pass_f32, f32);

/// The highest degree restricted here: above it the engine's halving, with its long
/// vectorised levels, takes fewer instructions (callgrind, 3-D curves, `benches/dependent`:
/// 21.6 against 22.5 thousand instructions per curve at degree 32, 79 against 69 thousand at
/// degree 64).
pub(crate) const MAX_DEGREE: usize = 40;

/// Whether a curve of `len` numbers, `dim` per point, over [a, b] is restricted here: degree
/// 1..=[`MAX_DEGREE`], `out` as long, a and b in [0, 1] (not NaN).
#[inline]
fn takes(len: usize, dim: usize, out: usize, inside: bool) -> bool {
    inside && out == len && len > dim && len <= (MAX_DEGREE + 1) * dim
}

/// Restricts by [`two_pass_f64`] in dimensions 1..=4 of curves of degree 1..=[`MAX_DEGREE`]
/// over intervals inside [0, 1]; `false` (and `out` untouched) otherwise.
#[inline]
pub(crate) fn restrict_f64(points: &[f64], dim: usize, a: f64, b: f64, out: &mut [f64]) -> bool {
    let inside = (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b);
    if !takes(points.len(), dim, out.len(), inside) {
        return false;
    }
    match dim {
        1 => two_pass_f64::<1>(points, a, b, out),
        2 => two_pass_f64::<2>(points, a, b, out),
        3 => two_pass_f64::<3>(points, a, b, out),
        4 => two_pass_f64::<4>(points, a, b, out),
        _ => return false,
    }
    true
}

/// [`restrict_f64`] in single precision.
#[inline]
pub(crate) fn restrict_f32(points: &[f32], dim: usize, a: f32, b: f32, out: &mut [f32]) -> bool {
    let inside = (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b);
    if !takes(points.len(), dim, out.len(), inside) {
        return false;
    }
    match dim {
        1 => two_pass_f32::<1>(points, a, b, out),
        2 => two_pass_f32::<2>(points, a, b, out),
        3 => two_pass_f32::<3>(points, a, b, out),
        4 => two_pass_f32::<4>(points, a, b, out),
        _ => return false,
    }
    true
}

#[cfg(test)]
mod tests {
    use super::{restrict_f32, restrict_f64, MAX_DEGREE};
    use crate::test_rng::XorShift;
    use crate::{BezierCurve, Rational};

    /// The largest |x| of the exact answer, and the largest error of `got` against it.
    fn error_against_exact(points: &[f64], dim: usize, a: f64, b: f64, got: &[f64]) -> (f64, f64) {
        let exact = |x: f64| Rational::from_float(x).expect("finite");
        let curve = BezierCurve::from_coordinates(dim, points.iter().map(|&x| exact(x)).collect())
            .expect("a curve");
        // The engine in exact arithmetic: the halving, no division, no rounding.
        let want = curve.subsegment(exact(a)..exact(b));
        let mut scale: f64 = 0.0;
        let mut error: f64 = 0.0;
        for (w, &g) in want.coordinates().iter().zip(got) {
            let w = crate::rational_to_f64(w);
            scale = scale.max(w.abs());
            error = error.max((w - g).abs());
        }
        (scale, error)
    }

    /// Degrees 1..=10 and five more up to MAX_DEGREE in dimensions 1..=4, on intervals inside
    /// [0, 1] either way round, short ones and ones with an end at 0 or 1: the two
    /// subdivisions agree with the exact restriction (the engine in rationals) within
    /// de Casteljau's error, 4 n u times the size of the control points (`u` = 2^-53).
    #[test]
    fn two_subdivisions_agree_with_the_exact_restriction() {
        let mut rng = XorShift(0x2_9a55);
        let mut unit = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
        // Every degree up to 10, then a few up to the limit (the exact engine grows with n^2).
        let degrees = (1..=10).chain([13, 17, 24, 31, MAX_DEGREE]);
        for n in degrees {
            for dim in 1..=4 {
                let points: Vec<f64> = (0..(n + 1) * dim).map(|_| 4.0 * unit() - 2.0).collect();
                let (x, y) = (unit(), unit());
                // x + 1e-9 may pass 1: the short interval starts a little below x.
                let short = (0.999 * x, 0.999 * x + 1e-9);
                for (a, b) in [
                    (x, y),
                    (y, x),
                    short,
                    (0.0, y),
                    (x, 0.0),
                    (1.0, x),
                    (0.0, 1.0),
                ] {
                    let mut got = vec![0.0; points.len()];
                    assert!(restrict_f64(&points, dim, a, b, &mut got));
                    let (scale, error) = error_against_exact(&points, dim, a, b, &got);
                    let bound = 4.0 * n as f64 * f64::EPSILON * scale.max(1.0);
                    assert!(
                        error <= bound,
                        "dim {dim}, degree {n}, [{a}, {b}]: {error:e} > {bound:e}"
                    );
                }
            }
        }
    }

    /// a = b = 0 gives n + 1 copies of the first control point; a = b elsewhere n + 1 copies of
    /// the curve's point there (up to rounding); f32 takes the same path.
    #[test]
    fn a_point_interval_gives_copies_of_one_point() {
        let points = [
            1.0, 2.0, 3.0, -1.0, 0.5, 0.25, 7.0, 1.0, 2.0, 2.0, 9.0, 9.0, 4.0, 4.0, 0.0, 1.0, -3.0,
            2.0, 1.0, 1.0,
        ];
        let mut got = [0.0; 20];
        assert!(restrict_f64(&points, 2, 0.0, 0.0, &mut got));
        for point in got.chunks(2) {
            assert_eq!(point, &[1.0, 2.0]);
        }
        let narrow: Vec<f32> = points.iter().map(|&x| x as f32).collect();
        let mut got32 = [0.0f32; 20];
        assert!(restrict_f32(&narrow, 2, 0.5, 0.5, &mut got32));
        for point in got32.chunks(2) {
            assert!((point[0] - got32[0]).abs() < 1e-5 && (point[1] - got32[1]).abs() < 1e-5);
        }
    }

    /// What is not taken: dimension 5, degree 0, degree over the limit, a wrong `out`, an
    /// interval reaching outside [0, 1] or with a NaN end.
    #[test]
    fn other_shapes_are_left_to_the_engine() {
        let mut out = vec![0.0; 10];
        for (a, b) in [(-0.5, 0.5), (0.5, 1.25), (f64::NAN, 0.5), (0.25, f64::NAN)] {
            assert!(!restrict_f64(&[1.0; 10], 2, a, b, &mut out));
        }
        assert!(!restrict_f64(&[0.0; 10], 5, 0.0, 1.0, &mut out));
        assert!(!restrict_f64(&[0.0; 2], 2, 0.0, 1.0, &mut out[..2]));
        let long = vec![0.0; (MAX_DEGREE + 2) * 2];
        let mut long_out = long.clone();
        assert!(!restrict_f64(&long, 2, 0.0, 1.0, &mut long_out));
        assert!(!restrict_f64(&[0.0; 8], 2, 0.0, 1.0, &mut out[..6]));
        assert_eq!(out, vec![0.0; 10]);
    }
}
