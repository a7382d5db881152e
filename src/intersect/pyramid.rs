//! The two point evaluations of the float filter's Krawczyk test ([`super::filter`], module
//! documentation 2), for 2-D curves: P(s) at a double s in double-double ([`dd_point`]) and
//! an enclosure of a curve over an interval argument in convex form ([`convex_point`]).
//!
//! Each is de Casteljau's pyramid: level r + 1 is made from level r by one step on
//! neighbouring points, coordinate by coordinate, [`Dd::lerp`] for the first and
//! [`ConvexStep`] on [`BoundedF64`] for the second, whose bounds are derived in
//! [`super::interval`]. A pyramid's value (and bound) is a function of the control points
//! and the argument alone: each entry of level r + 1 is the step applied to two entries of
//! level r, whatever order the entries of a level are computed in, and the step is a fixed
//! sequence of floating-point operations. So computing the pyramid of N points in registers
//! ([`dd_point_fixed`], [`convex_point_fixed`]: arrays of constant length, the loops unrolled
//! by the compiler) or in a vector ([`dd_point_general`], [`convex_point_general`], the
//! engine's [`curve_pyramid_in_place`]) gives the same doubles, bounds included, bit for bit:
//! the unrolled forms carry the generic path's rigorous bounds unchanged, with no new error
//! analysis. They serve degrees 1 to 3 (the common case; a settlement of two cubics ran two
//! vector copies and two pyramids per evaluation before), the vectors every other degree.
//! The tests below hold both forms to equality on random inputs of extreme magnitudes (a
//! unrolling with two neighbours swapped fails them), and
//! the unrolled ones to their bounds against exact rationals.

use super::interval::{ConvexStep, Dd};
use crate::num::bounded::BoundedF64;
use crate::shape::flat::curve_pyramid_in_place;
use crate::shape::halving::CurveStep;

/// The curve with control points `points` at the double `s`, in double-double with a bound
/// (de Casteljau by [`Dd::lerp`]); `level` is scratch for degrees above 3.
#[inline]
pub(super) fn dd_point(points: &[[f64; 2]], s: f64, level: &mut Vec<Dd>) -> [Dd; 2] {
    match *points {
        [p0, p1] => dd_point_fixed(&[p0, p1], s),
        [p0, p1, p2] => dd_point_fixed(&[p0, p1, p2], s),
        [p0, p1, p2, p3] => dd_point_fixed(&[p0, p1, p2, p3], s),
        _ => dd_point_general(points, s, level),
    }
}

/// [`dd_point`] on N points held in arrays.
#[inline(always)]
pub(super) fn dd_point_fixed<const N: usize>(points: &[[f64; 2]; N], s: f64) -> [Dd; 2] {
    // One coordinate at a time: N double-doubles in registers.
    [0, 1].map(|c| {
        let mut level: [Dd; N] = points.map(|p| Dd::exact(p[c]));
        for k in (1..N).rev() {
            for i in 0..k {
                level[i] = Dd::lerp(&level[i], &level[i + 1], s);
            }
        }
        level[0]
    })
}

/// [`dd_point`]'s values (bit for bit) at a double `s` in [0, 1] with the bound `bound`
/// known before the evaluation ([`lerp_pyramid_bound`] of the degree and the largest
/// coordinate), so that no step computes a bound: [`Dd::lerp_value`] in place of
/// [`Dd::lerp`], whose running bound the a-priori one dominates.
///
/// On x86-64 processors with FMA (detected at run time) this runs a build of the same source
/// compiled with FMA enabled: TwoProd's fused multiply-add ([`f64::mul_add`], correctly
/// rounded either way) is then one instruction instead of a call into the run-time library,
/// and the same doubles come out bit for bit (no other operation is fused: Rust never
/// contracts a multiplication and an addition by itself).
#[inline]
pub(super) fn dd_point_bounded(
    points: &[[f64; 2]],
    s: f64,
    bound: f64,
    level: &mut Vec<Dd>,
) -> [Dd; 2] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the processor has just been seen to support FMA.
        #[allow(unsafe_code)]
        return unsafe { dd_point_bounded_fma(points, s, bound, level) };
    }
    dd_point_bounded_body(points, s, bound, level)
}

/// [`dd_point_bounded`] of two curves at once, `p` at `s` and `q` at `t` (both in [0, 1]),
/// with their bounds: the same doubles as two calls, in one body (the FMA build when the
/// processor has it), where the processor can overlap the two pyramids.
#[inline]
pub(super) fn dd_points_bounded(
    (p, s, bound_p): (&[[f64; 2]], f64, f64),
    (q, t, bound_q): (&[[f64; 2]], f64, f64),
    level: &mut Vec<Dd>,
) -> [[Dd; 2]; 2] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the processor has just been seen to support FMA.
        #[allow(unsafe_code)]
        return unsafe { dd_points_bounded_fma((p, s, bound_p), (q, t, bound_q), level) };
    }
    dd_points_bounded_body((p, s, bound_p), (q, t, bound_q), level)
}

/// [`dd_points_bounded`] compiled with FMA enabled; callers make sure the processor has it.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn dd_points_bounded_fma(
    p: (&[[f64; 2]], f64, f64),
    q: (&[[f64; 2]], f64, f64),
    level: &mut Vec<Dd>,
) -> [[Dd; 2]; 2] {
    dd_points_bounded_body(p, q, level)
}

/// The body of [`dd_points_bounded`], shared by its two builds.
#[inline(always)]
fn dd_points_bounded_body(
    (p, s, bound_p): (&[[f64; 2]], f64, f64),
    (q, t, bound_q): (&[[f64; 2]], f64, f64),
    level: &mut Vec<Dd>,
) -> [[Dd; 2]; 2] {
    [
        dd_point_bounded_body(p, s, bound_p, level),
        dd_point_bounded_body(q, t, bound_q, level),
    ]
}

/// [`dd_point_bounded`] compiled with FMA enabled; callers make sure the processor has it.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn dd_point_bounded_fma(points: &[[f64; 2]], s: f64, bound: f64, level: &mut Vec<Dd>) -> [Dd; 2] {
    dd_point_bounded_body(points, s, bound, level)
}

/// The body of [`dd_point_bounded`], shared by its two builds.
#[inline(always)]
fn dd_point_bounded_body(points: &[[f64; 2]], s: f64, bound: f64, level: &mut Vec<Dd>) -> [Dd; 2] {
    debug_assert!((0.0..=1.0).contains(&s));
    let values = match *points {
        [p0, p1] => dd_point_values(&[p0, p1], s),
        [p0, p1, p2] => dd_point_values(&[p0, p1, p2], s),
        [p0, p1, p2, p3] => dd_point_values(&[p0, p1, p2, p3], s),
        _ => {
            level.clear();
            level.extend(points.iter().flatten().map(|&x| Dd::exact(x)));
            for k in (4..=level.len()).rev().step_by(2) {
                for i in 0..k - 2 {
                    level[i] = Dd::lerp_value(&level[i], &level[i + 2], s);
                }
            }
            [level[0], level[1]]
        }
    };
    values.map(|v| v.with_bound(bound))
}

/// [`dd_point_fixed`]'s values by [`Dd::lerp_value`] (bounds left at zero).
#[inline(always)]
fn dd_point_values<const N: usize>(points: &[[f64; 2]; N], s: f64) -> [Dd; 2] {
    // Plain loops rather than `map` closures, which the compiler keeps out of line (and
    // out of the FMA build of `dd_point_bounded`).
    let mut out = [Dd::exact(0.0); 2];
    for (c, value) in out.iter_mut().enumerate() {
        let mut level = [Dd::exact(0.0); N];
        for (entry, p) in level.iter_mut().zip(points) {
            *entry = Dd::exact(p[c]);
        }
        for k in (1..N).rev() {
            for i in 0..k {
                level[i] = Dd::lerp_value(&level[i], &level[i + 1], s);
            }
        }
        *value = level[0];
    }
    out
}

/// [`dd_point`] in the vector `level` (interleaved coordinates), for any number of points.
pub(super) fn dd_point_general(points: &[[f64; 2]], s: f64, level: &mut Vec<Dd>) -> [Dd; 2] {
    level.clear();
    level.extend(points.iter().flatten().map(|&x| Dd::exact(x)));
    for k in (4..=level.len()).rev().step_by(2) {
        for i in 0..k - 2 {
            level[i] = Dd::lerp(&level[i], &level[i + 2], s);
        }
    }
    [level[0], level[1]]
}

/// An enclosure of the curve with control points `points` (with their bounds) over the
/// interval argument of `step`: de Casteljau's pyramid in convex form; `level` is scratch
/// for more than 3 points.
#[inline]
pub(super) fn convex_point(
    points: &[[BoundedF64; 2]],
    step: &ConvexStep<BoundedF64>,
    level: &mut Vec<BoundedF64>,
) -> [BoundedF64; 2] {
    match *points {
        [p0] => p0,
        [p0, p1] => convex_point_fixed(&[p0, p1], step),
        [p0, p1, p2] => convex_point_fixed(&[p0, p1, p2], step),
        _ => convex_point_general(points, step, level),
    }
}

/// [`convex_point`] on N points held in arrays.
#[inline(always)]
pub(super) fn convex_point_fixed<const N: usize>(
    points: &[[BoundedF64; 2]; N],
    step: &ConvexStep<BoundedF64>,
) -> [BoundedF64; 2] {
    let mut level = *points;
    for k in (1..N).rev() {
        for i in 0..k {
            let (x, y) = (level[i], level[i + 1]);
            level[i] = [step.combine(&x[0], &y[0]), step.combine(&x[1], &y[1])];
        }
    }
    level[0]
}

/// [`convex_point`] in the vector `level` by the engine's pyramid, for any number of points.
pub(super) fn convex_point_general(
    points: &[[BoundedF64; 2]],
    step: &ConvexStep<BoundedF64>,
    level: &mut Vec<BoundedF64>,
) -> [BoundedF64; 2] {
    level.clear();
    level.extend_from_slice(points.as_flattened());
    curve_pyramid_in_place(level, 2, step);
    [level[0], level[1]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::interval::lerp_pyramid_bound;
    use crate::num::ring::Rational;
    use crate::test_rng::XorShift;
    use num_traits::FromPrimitive;

    /// A double of random sign, mantissa and binary exponent in [-lo, hi].
    fn double(rng: &mut XorShift, exponents: i32) -> f64 {
        let r = rng.next();
        let mantissa = 1.0 + (r >> 12) as f64 / (1u64 << 52) as f64;
        let e = (r % (2 * exponents as u64 + 1)) as i32 - exponents;
        let sign = if r & (1 << 11) == 0 { 1.0 } else { -1.0 };
        sign * mantissa * 2f64.powi(e)
    }

    /// Points of one size class: coordinates near 2^e for a random e in [-range, range],
    /// spread over 2^±8.
    fn points(rng: &mut XorShift, count: usize, range: u64) -> Vec<[f64; 2]> {
        let scale = 2f64.powi((rng.next() % (2 * range + 1)) as i32 - range as i32);
        (0..count)
            .map(|_| [scale * double(rng, 8), scale * double(rng, 8)])
            .collect()
    }

    /// Arguments in [0, 1] with the awkward ones: the ends, near them, tiny, and random.
    fn argument(rng: &mut XorShift) -> f64 {
        match rng.next() % 6 {
            0 => 0.0,
            1 => 1.0,
            2 => 1.0f64.next_down(),
            3 => double(rng, 60).abs().min(1.0) * 2f64.powi(-40),
            _ => (rng.next() >> 11) as f64 / (1u64 << 53) as f64,
        }
    }

    fn exact(x: f64) -> Rational {
        Rational::from_f64(x).unwrap()
    }

    /// Whether the exact `truth` lies within `bound` of the exact `value`.
    fn within(value: Rational, bound: f64, truth: &Rational) -> bool {
        let diff = if &value > truth {
            &value - truth
        } else {
            truth - &value
        };
        diff <= exact(bound)
    }

    /// The exact point at `s` of the curve with the exact control points `level` (de
    /// Casteljau in rationals), per coordinate.
    fn exact_point(mut level: Vec<[Rational; 2]>, s: &Rational) -> [Rational; 2] {
        let one_minus = Rational::from_integer(1.into()) - s;
        for k in (1..level.len()).rev() {
            for i in 0..k {
                level[i] = [0, 1].map(|c| &one_minus * &level[i][c] + s * &level[i + 1][c]);
            }
        }
        level.swap_remove(0)
    }

    fn same_dd(a: &[Dd; 2], b: &[Dd; 2]) -> bool {
        (0..2).all(|c| {
            let (x, y) = (a[c].to_bounded(), b[c].to_bounded());
            a[c].hi().to_bits() == b[c].hi().to_bits()
                && a[c].rest().value().to_bits() == b[c].rest().value().to_bits()
                && a[c].rest().error_bound().to_bits() == b[c].rest().error_bound().to_bits()
                && x.value().to_bits() == y.value().to_bits()
        })
    }

    fn same_bounded(a: &[BoundedF64; 2], b: &[BoundedF64; 2]) -> bool {
        (0..2).all(|c| {
            a[c].value().to_bits() == b[c].value().to_bits()
                && a[c].error_bound().to_bits() == b[c].error_bound().to_bits()
        })
    }

    #[test]
    fn unrolled_double_double_point_is_the_general_one_and_within_its_bound() {
        let mut rng = XorShift(0x2545_f491_4f6c_dd1d);
        let mut level = Vec::new();
        for round in 0..900 {
            let n = 2 + round % 3;
            // The filter takes sizes 1e-90 to 1e90; the bounds hold to 2^±300, and the two
            // forms agree at any size (infinities and NaNs included).
            let range = if round % 3 == 0 { 1020 } else { 300 };
            let p = points(&mut rng, n, range);
            let s = argument(&mut rng);
            let fast = dd_point(&p, s, &mut level);
            let general = dd_point_general(&p, s, &mut level);
            assert!(same_dd(&fast, &general), "{p:?} at {s}");
            if range > 300 {
                continue;
            }
            let exact_points = p.iter().map(|q| q.map(exact)).collect();
            let truth = exact_point(exact_points, &exact(s));
            for c in 0..2 {
                let value = exact(fast[c].hi()) + exact(fast[c].rest().value());
                let bound = fast[c].rest().error_bound();
                assert!(within(value, bound, &truth[c]), "{p:?} at {s}");
                // The bound is of double-double size, some n^2 u^2 times the points.
                let size = p.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
                assert!(bound <= 1e-30 * size + 1e-300, "{bound:e} for {size:e}");
            }
        }
    }

    #[test]
    fn a_priori_bounded_point_has_the_values_and_dominates_the_running_bound() {
        // Degrees 1 to 3 (unrolled) and 4 to 9 (the vector), sizes 2^±300, arguments in
        // [0, 1]: the same hi and lo as `dd_point`, a bound at least its running bound, and the
        // exact value within it. On a processor with FMA `dd_point_bounded` runs its FMA build
        // and `dd_point` the plain one, so this also holds the two builds to the same bits.
        let mut rng = XorShift(0x3c6e_f372_fe94_f82b);
        let mut level = Vec::new();
        for round in 0..900 {
            let n = 2 + round % 9;
            let p = points(&mut rng, n, 300);
            let s = argument(&mut rng);
            let size = p.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
            let bound = lerp_pyramid_bound(n - 1, size);
            let fast = dd_point_bounded(&p, s, bound, &mut level);
            let running = dd_point(&p, s, &mut level);
            let truth = exact_point(p.iter().map(|q| q.map(exact)).collect(), &exact(s));
            for c in 0..2 {
                assert_eq!(fast[c].hi().to_bits(), running[c].hi().to_bits());
                assert_eq!(
                    fast[c].rest().value().to_bits(),
                    running[c].rest().value().to_bits()
                );
                assert!(bound >= running[c].rest().error_bound(), "{p:?} at {s}");
                let value = exact(fast[c].hi()) + exact(fast[c].rest().value());
                assert!(within(value, bound, &truth[c]), "{p:?} at {s}");
            }
            // And of double-double size: some n u^2 times the points.
            assert!(bound <= 1e-30 * size * n as f64, "{bound:e} for {size:e}");
            // Two curves at once: the same doubles and bounds as one by one.
            let other = points(&mut rng, 2 + round % 4, 300);
            let t = argument(&mut rng);
            let other_bound = lerp_pyramid_bound(other.len() - 1, 1e300);
            let [a, b] = dd_points_bounded((&p, s, bound), (&other, t, other_bound), &mut level);
            let single = dd_point_bounded(&other, t, other_bound, &mut level);
            assert!(
                same_dd(&a, &fast) && same_dd(&b, &single),
                "{p:?} {other:?}"
            );
        }
    }

    #[test]
    fn unrolled_convex_point_is_the_general_one_and_encloses_the_range() {
        let mut rng = XorShift(0x9e37_79b9_7f4a_7c15);
        let mut level = Vec::new();
        for round in 0..900 {
            let n = 1 + round % 3;
            let range = if round % 3 == 0 { 1020 } else { 300 };
            let raw = points(&mut rng, n, range);
            // Points with bounds of their own, as the hodograph carries.
            let p: Vec<[BoundedF64; 2]> = raw
                .iter()
                .map(|q| q.map(|x| BoundedF64::with_bound(x, x.abs() * 1e-16)))
                .collect();
            let mid = argument(&mut rng);
            let radius = argument(&mut rng) * 2f64.powi(-((rng.next() % 50) as i32));
            let step = ConvexStep::new(BoundedF64::with_bound(mid, radius));
            let fast = convex_point(&p, &step, &mut level);
            let general = convex_point_general(&p, &step, &mut level);
            assert!(same_bounded(&fast, &general), "{p:?} at {mid} ± {radius}");
            if range > 300 {
                continue;
            }
            // The enclosure holds the exact curve of points at the ends of their bounds and
            // at their values, at the ends of the argument interval and at its middle.
            let (m, r) = (exact(mid), exact(radius));
            for s in [&m - &r, m.clone(), &m + &r] {
                for sign in [-1, 0, 1] {
                    let moved = p
                        .iter()
                        .map(|q| {
                            q.map(|x| {
                                exact(x.value())
                                    + exact(x.error_bound()) * Rational::from_integer(sign.into())
                            })
                        })
                        .collect();
                    let truth = exact_point(moved, &s);
                    for c in 0..2 {
                        let bound = fast[c].error_bound();
                        assert!(within(exact(fast[c].value()), bound, &truth[c]));
                    }
                }
            }
        }
        // One point: the point itself.
        let one = [[BoundedF64::exact(3.0), BoundedF64::with_bound(-2.0, 1e-16)]];
        let step = ConvexStep::new(BoundedF64::with_bound(0.5, 0.25));
        assert!(same_bounded(
            &convex_point(&one, &step, &mut level),
            &one[0]
        ));
    }
}
