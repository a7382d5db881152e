//! The restriction of Bézier curves of degree 1..=24 with `[T; D]` points by the evaluators
//! `blossom::restriction!` generates: the engine's halving unrolled for one degree (the same
//! steps in the same order, so the same answer bit for bit), with every level in registers
//! instead of scratch buffers. [`crate::Bezier`] dispatches here first.
//!
//! The evaluators are generic, but only `f64` and `f32` run them ([`crate::Ring::UNROLLED`]),
//! and only in dimensions 1..=4: [`restrict_f64`] and [`restrict_f32`] instantiate them and
//! are neither generic nor inlined, so the grid of 24 degrees x 4 dimensions is compiled once,
//! in this crate. (Reached from generic code instead, it was monomorphised anew in every crate
//! that restricts a float curve: about 100 s of CPU at `opt-level = 2` for a program of a few
//! lines, in every example and test crate.) The front ends reach them through
//! [`crate::Ring::restrict_unrolled`].

macro_rules! unrolled {
    ($($n:literal => $name:ident,)*) => {
        $(crate::restriction!(name = $name, shape = bezier_curve, degree = $n);)*

        /// `out` = the control points of the curve with flat control points `points` (`D`
        /// coordinates each, degree 1..=24) over [a, b] by the unrolled evaluator of that
        /// degree; `false` (and `out` untouched) for any other degree or when `out` has another
        /// length. The flat slices are read as `[T; D]` points in place (`as_chunks`), so
        /// nothing is copied on the way in.
        #[inline]
        fn restrict_curve_unrolled<T: crate::Ring, const D: usize>(
            points: &[T],
            a: &T,
            b: &T,
            out: &mut [T],
        ) -> bool {
            if D == 0 || out.len() != points.len() {
                return false;
            }
            let (points, rest) = points.as_chunks::<D>();
            let (out, _) = out.as_chunks_mut::<D>();
            if !rest.is_empty() {
                return false;
            }
            match points.len().wrapping_sub(1) {
                $($n => {
                    let Ok(ctrl) = <&[[T; D]; $n + 1]>::try_from(points) else {
                        return false;
                    };
                    for (o, q) in out.iter_mut().zip($name(ctrl, a, b)) {
                        *o = q;
                    }
                    true
                })*
                _ => false,
            }
        }
    };
}

unrolled! {
    1 => degree_1, 2 => degree_2, 3 => degree_3, 4 => degree_4, 5 => degree_5, 6 => degree_6,
    7 => degree_7, 8 => degree_8, 9 => degree_9, 10 => degree_10, 11 => degree_11,
    12 => degree_12, 13 => degree_13, 14 => degree_14, 15 => degree_15, 16 => degree_16,
    17 => degree_17, 18 => degree_18, 19 => degree_19, 20 => degree_20, 21 => degree_21,
    22 => degree_22, 23 => degree_23, 24 => degree_24,
}

/// `out` = the control points of the curve with flat control points `points` (`dim` numbers
/// each) over [a, b] by the unrolled evaluator of its degree, for a dimension `dim` in 1..=4
/// and a degree in 1..=24 of `T` = `f64` or `f32`; `false` (and `out` untouched) otherwise.
/// Called by the two non-generic entry points only, so that it is instantiated twice.
#[inline]
fn restrict_flat<T: crate::Ring>(points: &[T], dim: usize, a: &T, b: &T, out: &mut [T]) -> bool {
    match dim {
        1 => restrict_curve_unrolled::<T, 1>(points, a, b, out),
        2 => restrict_curve_unrolled::<T, 2>(points, a, b, out),
        3 => restrict_curve_unrolled::<T, 3>(points, a, b, out),
        4 => restrict_curve_unrolled::<T, 4>(points, a, b, out),
        _ => false,
    }
}

/// [`restrict_flat`] in `f64`, compiled in this crate only (see the module documentation).
#[inline(never)]
pub(crate) fn restrict_f64(points: &[f64], dim: usize, a: &f64, b: &f64, out: &mut [f64]) -> bool {
    restrict_flat(points, dim, a, b, out)
}

/// [`restrict_flat`] in `f32`, compiled in this crate only (see the module documentation).
#[inline(never)]
pub(crate) fn restrict_f32(points: &[f32], dim: usize, a: &f32, b: &f32, out: &mut [f32]) -> bool {
    restrict_flat(points, dim, a, b, out)
}

/// The curve `points` over [a, b] by [`restrict_flat`] as a curve whose numbers are inline
/// ([`crate::engine::SmallCoords`]), when it has at most `N` coordinates and an unrolled
/// evaluator; `None` otherwise.
///
/// The curve is built first and its numbers written last: a move of a curve whose length and
/// dimension were just stored stalls on store forwarding for longer than the restriction of a
/// cubic takes (measured in `benches/peers.rs`, group `cubic2d`), and the caller moves it.
#[inline]
fn small<T, const N: usize>(points: &[T], dim: usize, a: &T, b: &T) -> Option<crate::BezierCurve<T>>
where
    T: crate::Ring<Coords = crate::engine::SmallCoords<T, N>> + Copy + Default,
{
    if points.len() > N {
        return None;
    }
    let mut curve = crate::BezierCurve::from_buffer(
        dim,
        crate::engine::SmallCoords::from_inline([T::default(); N], points.len()),
    );
    restrict_flat(points, dim, a, b, curve.coordinates_mut()).then_some(curve)
}

/// [`small`] in `f64` for [`crate::Ring::subsegment_small`], compiled in this crate only.
#[inline(never)]
pub(crate) fn small_f64(
    points: &[f64],
    dim: usize,
    a: &f64,
    b: &f64,
) -> Option<crate::BezierCurve<f64>> {
    small(points, dim, a, b)
}

/// [`small`] in `f32` for [`crate::Ring::subsegment_small`], compiled in this crate only.
#[inline(never)]
pub(crate) fn small_f32(
    points: &[f32],
    dim: usize,
    a: &f32,
    b: &f32,
) -> Option<crate::BezierCurve<f32>> {
    small(points, dim, a, b)
}

#[cfg(test)]
mod tests {
    use crate::engine::{curve_net, BernsteinStep};
    use crate::test_rng::XorShift;
    use crate::BezierCurve;

    /// `BezierCurve::subsegment` of float curves (inline answers up to 8 coordinates through
    /// [`super::small_f64`], heap answers through the flat path) gives, bit for bit, the
    /// control points of the halving engine run with a runtime width (no unrolled code), and
    /// the same as `subsegment_into`; in every dimension 1..=6 and degree 0..=9, so across
    /// the inline limit, the degree 0 (no unrolled evaluator) and dimensions above 4.
    #[test]
    fn returned_subsegments_are_the_engines_bit_for_bit() {
        let mut rng = XorShift(0x5eed_cafe);
        let mut unit = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0;
        let mut inline_answers = 0;
        for dim in 1..=6 {
            for degree in 0..=9 {
                let coords: Vec<f64> = (0..(degree + 1) * dim).map(|_| unit()).collect();
                let curve = BezierCurve::from_coordinates(dim, coords.clone()).expect("a curve");
                let (a, b) = (unit(), unit());
                let got = curve.subsegment(a..b);
                let mut want = vec![0.0; coords.len()];
                let (step_a, step_b) = (BernsteinStep(&a), BernsteinStep(&b));
                curve_net(&coords, dim, &step_a, &step_b, &mut want, &mut Vec::new());
                assert_eq!(got.coordinates(), &want[..], "dim {dim}, degree {degree}");
                assert_eq!((got.dim(), got.degree()), (dim, degree));
                let mut into = BezierCurve::from_coordinates(1, vec![9.0; 30]).expect("a curve");
                curve.subsegment_into(&a, &b, &mut into, &mut Vec::new());
                assert_eq!(into, got, "subsegment_into, dim {dim}, degree {degree}");
                inline_answers += usize::from(got.coords_are_inline());
                // The f32 curve goes the same way.
                let narrow: Vec<f32> = coords.iter().map(|&x| x as f32).collect();
                let curve32 = BezierCurve::from_coordinates(dim, narrow.clone()).expect("a curve");
                let (a32, b32) = (a as f32, b as f32);
                let mut want32 = vec![0.0f32; narrow.len()];
                let (s_a, s_b) = (BernsteinStep(&a32), BernsteinStep(&b32));
                curve_net(&narrow, dim, &s_a, &s_b, &mut want32, &mut Vec::new());
                assert_eq!(curve32.subsegment(a32..b32).coordinates(), &want32[..]);
            }
        }
        // Every (dim, degree) with (degree + 1) dim <= 8: 8 + 4 + 2 + 2 + 1 + 1.
        assert_eq!(inline_answers, 18);
    }
}
