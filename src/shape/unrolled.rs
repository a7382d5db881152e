//! The restriction of Bézier curves of degree 1..=8 (1..=24 with the feature `unrolled-high`)
//! in dimensions 1..=4 by the evaluators `blossom::restriction!` generates: the engine's
//! halving unrolled for one degree (the same steps in the same order, so the same answer bit
//! for bit), with every level in registers instead of scratch buffers. [`crate::Bezier`] and
//! [`crate::BezierCurve`] dispatch here first.
//!
//! Why only to degree 8 by default: every crate that depends on this one compiles these
//! tables. Degrees 9..=24 were 70 % of the library's LLVM IR; without them a dependent
//! crate's first release build went from 146 s to 21 s of wall time on 2 cores and its
//! largest rustc process from 4.6 GB to 0.56 GB (README, "Build time"), and those degrees
//! restrict by two de Casteljau subdivisions ([`crate::shape::two_pass`]) instead.
//!
//! The evaluators are generic, but only `f64` and `f32` run them ([`crate::Ring::UNROLLED`]):
//! the two tables [`F64`] and [`F32`] hold one function pointer per (dimension, number of
//! coordinates), filled at compile time, so the grid of 8 (or 24) degrees x 4 dimensions is
//! compiled once, in this crate. (Reached from generic code instead, it was monomorphised anew in every
//! crate that restricts a float curve: about 100 s of CPU at `opt-level = 2` for a program of a
//! few lines, in every example and test crate.) A call is one bounds-checked table load and
//! one indirect call, with no division by the dimension and no match on the degree. The front
//! ends reach the tables through [`crate::Ring::restrict_unrolled`].

use crate::Ring;

/// One unrolled evaluator: `out` = the control points of the curve with flat control points
/// `points` over [a, b]. Both slices have the length the table entry was filed under.
pub(crate) type Evaluator<T> = fn(&[T], &T, &T, &mut [T]);

/// The most coordinates of a curve with an unrolled evaluator: 25 points of dimension 4.
const MAX_COORDINATES: usize = 100;

/// The unrolled evaluators of one number type, by dimension and number of coordinates.
pub(crate) struct Evaluators<T: 'static> {
    /// `by_shape[dim - 1][(degree + 1) * dim]`, `None` where no evaluator exists.
    by_shape: [[Option<Evaluator<T>>; MAX_COORDINATES + 1]; 4],
}

impl<T: Ring> Evaluators<T> {
    /// The evaluator of curves with `dim` numbers per point and `len` numbers in all.
    #[inline]
    fn get(&self, dim: usize, len: usize) -> Option<Evaluator<T>> {
        *self.by_shape.get(dim.wrapping_sub(1))?.get(len)?
    }

    /// `out` = the control points of the curve with flat control points `points` (`dim`
    /// numbers each) over [a, b] by the unrolled evaluator of its shape; `false` (and `out`
    /// untouched) when there is none or `out` has another length.
    #[inline]
    pub(crate) fn restrict(&self, points: &[T], dim: usize, a: &T, b: &T, out: &mut [T]) -> bool {
        if out.len() != points.len() {
            return false;
        }
        match self.get(dim, points.len()) {
            Some(evaluate) => {
                evaluate(points, a, b, out);
                true
            }
            None => false,
        }
    }
}

macro_rules! unrolled {
    (
        default: $($n:literal => $name:ident, $into:ident;)*
        high: $($hn:literal => $hname:ident, $hinto:ident;)*
    ) => {
        $(unrolled!(@one $n => $name, $into);)*
        $(
            #[cfg(feature = "unrolled-high")]
            unrolled!(@one $hn => $hname, $hinto);
        )*

        /// The table of every unrolled evaluator of `T`, built at compile time.
        const fn evaluators<T: Ring>() -> Evaluators<T> {
            let mut by_shape: [[Option<Evaluator<T>>; MAX_COORDINATES + 1]; 4] =
                [[None; MAX_COORDINATES + 1]; 4];
            $(
                by_shape[0][$n + 1] = Some($into::<T, 1> as Evaluator<T>);
                by_shape[1][2 * ($n + 1)] = Some($into::<T, 2> as Evaluator<T>);
                by_shape[2][3 * ($n + 1)] = Some($into::<T, 3> as Evaluator<T>);
                by_shape[3][4 * ($n + 1)] = Some($into::<T, 4> as Evaluator<T>);
            )*
            #[cfg(feature = "unrolled-high")]
            {
                $(
                    by_shape[0][$hn + 1] = Some($hinto::<T, 1> as Evaluator<T>);
                    by_shape[1][2 * ($hn + 1)] = Some($hinto::<T, 2> as Evaluator<T>);
                    by_shape[2][3 * ($hn + 1)] = Some($hinto::<T, 3> as Evaluator<T>);
                    by_shape[3][4 * ($hn + 1)] = Some($hinto::<T, 4> as Evaluator<T>);
                )*
            }
            Evaluators { by_shape }
        }
    };
    (@one $n:literal => $name:ident, $into:ident) => {
        crate::restriction!(#[inline(always)] name = $name, shape = bezier_curve, degree = $n);

        /// The evaluator of this degree on flat slices, read as `[T; D]` points in place
        /// (`as_chunks`), so nothing is copied on the way in. Filed in the table under its
        /// exact length, so the conversions cannot fail there; a slice of another length
        /// leaves `out` untouched.
        #[inline]
        fn $into<T: Ring, const D: usize>(points: &[T], a: &T, b: &T, out: &mut [T]) {
            let (points, _) = points.as_chunks::<D>();
            let (out, _) = out.as_chunks_mut::<D>();
            if let (Ok(ctrl), Ok(out)) = (
                <&[[T; D]; $n + 1]>::try_from(points),
                <&mut [[T; D]; $n + 1]>::try_from(out),
            ) {
                *out = $name(ctrl, a, b);
            }
        }
    };
}

unrolled! {
    default:
    1 => degree_1, into_1; 2 => degree_2, into_2; 3 => degree_3, into_3;
    4 => degree_4, into_4; 5 => degree_5, into_5; 6 => degree_6, into_6;
    7 => degree_7, into_7; 8 => degree_8, into_8;
    high:
    9 => degree_9, into_9;
    10 => degree_10, into_10; 11 => degree_11, into_11; 12 => degree_12, into_12;
    13 => degree_13, into_13; 14 => degree_14, into_14; 15 => degree_15, into_15;
    16 => degree_16, into_16; 17 => degree_17, into_17; 18 => degree_18, into_18;
    19 => degree_19, into_19; 20 => degree_20, into_20; 21 => degree_21, into_21;
    22 => degree_22, into_22; 23 => degree_23, into_23; 24 => degree_24, into_24;
}

/// The curves restricted where they are asked for, with no call and no table: the planar
/// quadratic and cubic and the 3-D cubic, the curves of vector graphics and of most CAD. Their
/// unrolled evaluators are inlined into the caller together with `finish`, which receives the
/// answer's coordinates and copies them into the caller's buffer or makes the returned
/// curve's inline buffer of them, so the answer goes from registers to where it is used, once.
/// (Through a table's indirect call, or through a buffer that an out-of-line call fills and
/// the caller then copies, the answer waits on stores that have just been made, and how long
/// depends on the processor's store forwarding, not on the arithmetic.) `None` for every
/// other shape.
#[inline(always)]
pub(crate) fn small<T: Ring, R>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
    finish: impl FnOnce(&[T]) -> R,
) -> Option<R> {
    match (dim, points.len()) {
        (2, 6) => Some(finish(
            degree_2::<T, 2>(points.as_chunks().0.try_into().ok()?, a, b).as_flattened(),
        )),
        (2, 8) => Some(finish(
            degree_3::<T, 2>(points.as_chunks().0.try_into().ok()?, a, b).as_flattened(),
        )),
        (3, 12) => Some(finish(
            degree_3::<T, 3>(points.as_chunks().0.try_into().ok()?, a, b).as_flattened(),
        )),
        _ => None,
    }
}

/// The unrolled evaluators in `f64`.
pub(crate) static F64: Evaluators<f64> = evaluators::<f64>();

/// The unrolled evaluators in `f32`.
pub(crate) static F32: Evaluators<f32> = evaluators::<f32>();

#[cfg(test)]
mod tests {
    use crate::engine::{curve_net, BernsteinStep};
    use crate::test_rng::XorShift;
    use crate::BezierCurve;

    /// `BezierCurve::subsegment` of float curves (inline answers up to 12 coordinates (restricted in place
    /// through [`super::F64`]), heap answers through the flat path) gives, bit for bit, the
    /// control points of the halving engine run with a runtime width (no unrolled code), and
    /// the same as `subsegment_into`; in every dimension 1..=6 and degree 0..=8, so across
    /// the inline limit, the degree 0 (no unrolled evaluator) and dimensions above 4 (degrees
    /// 9 and up inside [0, 1] are `shape::two_pass`'s, tested there).
    #[test]
    fn returned_subsegments_are_the_engines_bit_for_bit() {
        let mut rng = XorShift(0x5eed_cafe);
        let mut unit = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0;
        let mut inline_answers = 0;
        for dim in 1..=6 {
            for degree in 0..=8 {
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
        // Every (dim, degree) with (degree + 1) dim <= 12: 9 + 6 + 4 + 3 + 2 + 2.
        assert_eq!(inline_answers, 26);
    }
}
