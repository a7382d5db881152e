//! The restriction of Bézier curves of degree 1..=24 with `[T; D]` points by the evaluators
//! `blossom::restriction!` generates: the engine's halving unrolled for one degree (the same
//! steps in the same order, so the same answer bit for bit), with every level in registers
//! instead of scratch buffers. [`crate::Bezier`] dispatches here first.

macro_rules! unrolled {
    ($($n:literal => $name:ident,)*) => {
        $(crate::restriction!(name = $name, shape = bezier_curve, degree = $n);)*

        /// `out` = the control points of the curve with flat control points `points` (`D`
        /// coordinates each, degree 1..=24) over [a, b] by the unrolled evaluator of that
        /// degree; `false` (and `out` untouched) for any other degree or when `out` has another
        /// length. The flat slices are read as `[T; D]` points in place (`as_chunks`), so
        /// nothing is copied on the way in.
        #[inline]
        pub(crate) fn restrict_curve_unrolled<T: crate::Ring, const D: usize>(
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
