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

use std::cell::Cell;

/// The de Casteljau levels of one subdivision, in place, two levels to a sweep: `sweep(m)`
/// yields the first m points in sweep order y_0, y_1, ..., and level r = 1..=n (n + 1 points)
/// replaces y_k, k = 0..=n - r, by `step(y_k, y_(k+1))` of level r - 1, leaving the rest.
///
/// A sweep of levels r and r + 1 computes level r at y_k from y_k and y_(k+1), then level r + 1
/// at y_(k-1) from level r at y_(k-1) and y_k, both kept in registers: one load and one store
/// of a point per two steps instead of two loads and a store per step, the same steps on the
/// same operands (so the same numbers) as one level after another. Every point is read and
/// written whole, at its own address, so each load of a level meets the store of the level
/// before at the same place and width (nothing straddles two stores, which the processor
/// could not forward).
#[inline(always)]
fn levels<'a, P: Copy + 'a, I: Iterator<Item = &'a Cell<P>>>(
    n: usize,
    sweep: impl Fn(usize) -> I,
    step: impl Fn(P, P) -> P,
) {
    let mut r = 1;
    while r < n {
        let mut cells = sweep(n - r + 2);
        let (Some(mut store), Some(mut here)) = (cells.next(), cells.next()) else {
            return;
        };
        let mut own = here.get();
        let mut lower = step(store.get(), own);
        for next in cells {
            let value = next.get();
            let this = step(own, value);
            store.set(step(lower, this));
            (lower, own, store, here) = (this, value, here, next);
        }
        store.set(lower);
        r += 2;
    }
    if r == n {
        let mut cells = sweep(2);
        if let (Some(first), Some(second)) = (cells.next(), cells.next()) {
            first.set(step(first.get(), second.get()));
        }
    }
}

/// `out` = the control points over [a, b] of the curve with flat control points `points`
/// (`D` numbers per point), by two subdivisions; `out` has the length of `points`.
///
/// Degrees 9..=12 run the same steps with the number of points fixed at compile time, which
/// the compiler unrolls into straight-line code as it does a textbook split on a fixed-size
/// array (below degree 9 the unrolled evaluators of [`crate::shape::unrolled`] come first;
/// above 12 the loops cost little more than the steps).
macro_rules! two_pass {
    ($name:ident, $t:ty) => {
        #[inline(never)]
        fn $name<const D: usize>(points: &[$t], a: $t, b: $t, out: &mut [$t]) {
            /// The two subdivisions of the points `x` in place.
            #[inline(always)]
            fn subdivide<const D: usize>(x: &mut [[$t; D]], a: $t, b: $t) {
                let (first, second, reversed) = if b.abs() >= a.abs() {
                    (b, a, false)
                } else {
                    (a, b, true)
                };
                if first == 0.0 {
                    // a = b = 0: every control point is the curve's value at 0.
                    let start = x[0];
                    x.fill(start);
                    return;
                }
                let n = x.len() - 1;
                let lerp = |p: [$t; D], q: [$t; D], s: $t| -> [$t; D] {
                    std::array::from_fn(|i| p[i] + s * (q[i] - p[i]))
                };
                let cells = Cell::from_mut(&mut *x).as_slice_of_cells();
                // The part over [0, first]: level r replaces x_i, i = r..=n, by
                // x_(i-1) + first (x_i - x_(i-1)) (sweeping down, y_k = x_(n-k)).
                levels(
                    n,
                    |m| cells[n + 1 - m..].iter().rev(),
                    |own, next| lerp(next, own, first),
                );
                // Its part over [second / first, 1]: level r replaces x_i, i = 0..=n - r, by
                // x_i + t (x_(i+1) - x_i) (sweeping up, y_k = x_k).
                let t = second / first;
                levels(n, |m| cells[..m].iter(), |own, next| lerp(own, next, t));
                if reversed {
                    x.reverse();
                }
            }
            /// The points, as `N` points of `D` numbers, subdivided in a local array: with the
            /// number of points fixed the compiler keeps them in registers, as in a textbook
            /// split of a fixed-size array. (Subdivided in `out` instead, the straight-line
            /// code read pairs of numbers across two points' stores and waited on them.)
            #[inline(always)]
            fn fixed<const D: usize, const N: usize>(points: &[$t], a: $t, b: $t, out: &mut [$t]) {
                let mut x: [[$t; D]; N] =
                    *<&[[$t; D]; N]>::try_from(points.as_chunks::<D>().0).expect("N points");
                subdivide(&mut x, a, b);
                out.copy_from_slice(x.as_flattened());
            }
            match points.len() / D {
                10 => fixed::<D, 10>(points, a, b, out),
                11 => fixed::<D, 11>(points, a, b, out),
                12 => fixed::<D, 12>(points, a, b, out),
                13 => fixed::<D, 13>(points, a, b, out),
                _ => {
                    out.copy_from_slice(points);
                    subdivide(out.as_chunks_mut::<D>().0, a, b);
                }
            }
        }
    };
}

two_pass!(two_pass_f64, f64);
two_pass!(two_pass_f32, f32);

/// Whether a curve of `len` numbers, `dim` per point, over [a, b] is restricted here: degree
/// at least 1, `out` as long, a and b in [0, 1] (not NaN). Every degree: with two levels to a
/// sweep the two subdivisions take fewer instructions than the engine's halving at every
/// degree (callgrind, 3-D curves, `benches/dependent/count.sh`: 45,000 against 69,000 per
/// curve at degree 64, where the textbook split takes 74,000).
#[inline]
fn takes(len: usize, dim: usize, out: usize, inside: bool) -> bool {
    inside && out == len && len > dim
}

/// Restricts by [`two_pass_f64`] in dimensions 1..=4 of curves of degree 1 and up over
/// intervals inside [0, 1]; `false` (and `out` untouched) otherwise.
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
    use super::{restrict_f32, restrict_f64};
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

    /// Degrees 1..=13 and four more up to 40 in dimensions 1..=4, then 64 in dimension 1, on
    /// intervals inside [0, 1] either way round, short ones and ones with an end at 0 or 1:
    /// the two subdivisions agree with the exact restriction (the engine in rationals) within
    /// de Casteljau's error, 4 n u times the size of the control points (`u` = 2^-53).
    #[test]
    fn two_subdivisions_agree_with_the_exact_restriction() {
        let mut rng = XorShift(0x2_9a55);
        let mut unit = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
        // Every degree up to 13 (the straight-line code ends at 12), then a few higher (the
        // exact engine's work grows as n^2 times the numbers' length, about n: degree 64 in
        // one dimension only).
        let shapes = (1..=13)
            .chain([17, 24, 31, 40])
            .flat_map(|n| (1..=4).map(move |d| (n, d)));
        for (n, dim) in shapes.chain([(64, 1)]) {
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

    /// What is not taken: dimension 5, degree 0, a wrong `out`, an interval reaching outside
    /// [0, 1] or with a NaN end.
    #[test]
    fn other_shapes_are_left_to_the_engine() {
        let mut out = vec![0.0; 10];
        for (a, b) in [(-0.5, 0.5), (0.5, 1.25), (f64::NAN, 0.5), (0.25, f64::NAN)] {
            assert!(!restrict_f64(&[1.0; 10], 2, a, b, &mut out));
        }
        assert!(!restrict_f64(&[0.0; 10], 5, 0.0, 1.0, &mut out));
        assert!(!restrict_f64(&[0.0; 2], 2, 0.0, 1.0, &mut out[..2]));
        assert!(!restrict_f64(&[0.0; 8], 2, 0.0, 1.0, &mut out[..6]));
        assert_eq!(out, vec![0.0; 10]);
    }

    /// Two levels to a sweep, and the straight-line code of degrees 9..=12, give the bits of
    /// the two subdivisions run one level after another (the same steps on the same operands).
    #[test]
    fn sweeps_are_the_levels_bit_for_bit() {
        let mut rng = XorShift(0x1e7e15);
        let mut unit = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
        for n in 1..=24 {
            for dim in 1..=4 {
                let points: Vec<f64> = (0..(n + 1) * dim).map(|_| 4.0 * unit() - 2.0).collect();
                let (x, y) = (unit(), unit());
                let mut got = vec![0.0; points.len()];
                assert!(restrict_f64(&points, dim, x, y, &mut got));
                // One level after another, as the textbook.
                let mut want = points.clone();
                let (first, second) = if y.abs() >= x.abs() { (y, x) } else { (x, y) };
                for r in 1..=n {
                    for i in (r..=n).rev() {
                        for k in 0..dim {
                            let (p, q) = (want[(i - 1) * dim + k], want[i * dim + k]);
                            want[i * dim + k] = p + first * (q - p);
                        }
                    }
                }
                let t = second / first;
                for r in 1..=n {
                    for i in 0..=n - r {
                        for k in 0..dim {
                            let (p, q) = (want[i * dim + k], want[(i + 1) * dim + k]);
                            want[i * dim + k] = p + t * (q - p);
                        }
                    }
                }
                if y.abs() < x.abs() {
                    let mut reversed: Vec<f64> =
                        want.chunks(dim).rev().flatten().copied().collect();
                    std::mem::swap(&mut want, &mut reversed);
                }
                assert_eq!(got, want, "degree {n}, dim {dim}");
            }
        }
    }
}
