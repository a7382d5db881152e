//! The Bézier algorithms on flat coordinates (`dim` numbers per point, points one after
//! another), shared by both front ends: the runtime-dimension shapes ([`crate::BezierCurve`],
//! [`crate::TensorPatch`], [`crate::TriangularPatch`]) and the fixed-dimension ones
//! ([`crate::Bezier`], [`crate::BezierTensor`], [`crate::BezierTriangle`]). One implementation,
//! two typings: every method of either front end is a call of one function here.
//!
//! * restriction: the halving engine ([`crate::engine::curve_net`] and its siblings) with
//!   de Casteljau's steps; for `f64`/`f32` curves of degree 1..=8 in dimension 1..=4 the same
//!   steps unrolled by `blossom::restriction!` (no scratch, the same answer bit for bit;
//!   degrees 1..=24 with the feature `unrolled-high`; the planar quadratic and cubic and the
//!   3-D cubic inlined into the caller), above them, on intervals inside [0, 1], two
//!   de Casteljau subdivisions (`shape/two_pass.rs`, no scratch, fewer steps);
//! * evaluation and blossoms: de Casteljau's pyramid, eq. (2) of seed 004 for curves, its
//!   triangular form b^r_(ijk) = u_r b_(i+1,j,k) + v_r b_(i,j+1,k) + w_r b_(i,j,k+1), and the
//!   tensor product as curves of curves (eq. (9) of seed 004).

use crate::num::meter::charge_points;
use crate::shape::coords::CoordinateBuffer;
use crate::shape::halving::{
    curve_blossom_in_place, curve_net, step_left, tensor_net, triangle_blossom_in_place,
    triangle_net, BernsteinPairStep, BernsteinStep, CurveStep, Fixed, TriangleStep,
};
use crate::shape::unrolled;
use crate::Ring;

/// `out` = the control points f(a^(n-j), b^j) of the curve `points` (`D` numbers per point)
/// over [a, b]. `scratch` grows to [`crate::engine::curve_scratch_len`] on first use.
#[inline(always)]
pub(crate) fn curve_subsegment_fixed<T: Ring, const D: usize>(
    points: &[T],
    a: &T,
    b: &T,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    if !small_into(points, D, a, b, out) {
        curve_subsegment_fixed_general::<T, D>(points, a, b, out, scratch);
    }
}

/// [`curve_subsegment_fixed`] past the small curves, out of line so that the inlined part
/// stays small: the unrolled evaluators and the two subdivisions of the floats, else the
/// engine with the width fixed at compile time.
#[inline(never)]
fn curve_subsegment_fixed_general<T: Ring, const D: usize>(
    points: &[T],
    a: &T,
    b: &T,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    if T::UNROLLED && T::restrict_unrolled(points, D, a, b, out) {
        return;
    }
    curve_net(
        points,
        Fixed::<D>,
        &BernsteinStep(a),
        &BernsteinStep(b),
        out,
        scratch,
    );
}

/// [`curve_subsegment_fixed`] for a dimension known at run time.
#[inline(always)]
pub(crate) fn curve_subsegment<T: Ring>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    if !small_into(points, dim, a, b, out) {
        curve_subsegment_general(points, dim, a, b, out, scratch);
    }
}

/// The coordinates of a small float curve over [a, b] in a new buffer, for the forms that
/// return a new curve: made by [`unrolled::small`] where they are computed, inline, with nothing
/// allocated; `None` for every other curve (then [`curve_subsegment_returned`]).
#[inline(always)]
pub(crate) fn curve_subsegment_small<T: Ring>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
) -> Option<T::Coords> {
    if !T::UNROLLED {
        return None;
    }
    unrolled::small(points, dim, a, b, T::Coords::from_slice)
}

/// `out` = the control points of the curve `points` over [a, b], for the returning forms
/// once they have made the answer's buffer (one allocation where it does not fit inline;
/// made in the answer, so that nothing is copied after): the unrolled evaluators and the two
/// subdivisions of the floats, else the engine with this thread's scratch
/// ([`Ring::with_scratch`]).
#[inline(always)]
pub(crate) fn curve_subsegment_returned<T: Ring>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
    out: &mut [T],
) {
    if !(T::UNROLLED && T::restrict_unrolled(points, dim, a, b, out)) {
        curve_subsegment_own_scratch(points, dim, a, b, out);
    }
}

/// [`curve_subsegment_engine`] with the ring's scratch buffer ([`Ring::with_scratch`]: this
/// thread's, reused, for the floats).
#[inline(never)]
fn curve_subsegment_own_scratch<T: Ring>(points: &[T], dim: usize, a: &T, b: &T, out: &mut [T]) {
    T::with_scratch(|scratch| curve_subsegment_engine(points, dim, a, b, out, scratch));
}

/// `out` = the restriction of a small float curve by [`unrolled::small`], inlined; `false`
/// (and `out` untouched) for every other curve, or when `out` has another length.
#[inline(always)]
fn small_into<T: Ring>(points: &[T], dim: usize, a: &T, b: &T, out: &mut [T]) -> bool {
    T::UNROLLED
        && out.len() == points.len()
        && unrolled::small(points, dim, a, b, |answer| out.clone_from_slice(answer)).is_some()
}

/// [`curve_subsegment`] past the small curves: the unrolled evaluators and the two
/// subdivisions of the floats, else [`curve_subsegment_engine`]. Out of line, so that the
/// inlined part stays small.
#[inline(never)]
fn curve_subsegment_general<T: Ring>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    if T::UNROLLED && T::restrict_unrolled(points, dim, a, b, out) {
        return;
    }
    curve_subsegment_engine(points, dim, a, b, out, scratch);
}

/// The halving engine for [`curve_subsegment`]: with the width fixed at compile time in
/// dimensions 1..=4 of the unrolled rings (degrees above 24), a runtime width otherwise.
fn curve_subsegment_engine<T: Ring>(
    points: &[T],
    dim: usize,
    a: &T,
    b: &T,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let (step_a, step_b) = (BernsteinStep(a), BernsteinStep(b));
    if T::UNROLLED {
        match dim {
            1 => return curve_net(points, Fixed::<1>, &step_a, &step_b, out, scratch),
            2 => return curve_net(points, Fixed::<2>, &step_a, &step_b, out, scratch),
            3 => return curve_net(points, Fixed::<3>, &step_a, &step_b, out, scratch),
            4 => return curve_net(points, Fixed::<4>, &step_a, &step_b, out, scratch),
            _ => {}
        }
    }
    curve_net(points, dim, &step_a, &step_b, out, scratch);
}

/// Applies `level.len() / dim - 1` steps of `step` to `level` in place: the de Casteljau
/// pyramid of a curve at one argument. The answer is `level[..dim]`.
pub(crate) fn curve_pyramid_in_place<T: Ring, S: CurveStep<T>>(
    level: &mut [T],
    dim: usize,
    step: &S,
) {
    let len = level.len();
    let n = len / dim - 1;
    charge_points(n + 1);
    for r in 0..n {
        charge_points(n - r);
        step_left(&mut level[..len - r * dim], dim, step);
    }
}

/// The point of the curve `points` at `t` (de Casteljau), written to `out` (`dim` numbers);
/// `level` is the working copy, grown once and reused.
pub(crate) fn curve_eval_into<T: Ring>(
    points: &[T],
    dim: usize,
    t: &T,
    out: &mut [T],
    level: &mut Vec<T>,
) {
    level.clear();
    level.extend_from_slice(points);
    curve_pyramid_in_place(level, dim, &BernsteinStep(t));
    out.clone_from_slice(&level[..dim]);
}

/// The blossom of the curve `points` at `args` (one per degree), eq. (2) of seed 004.
pub(crate) fn curve_blossom<T: Ring>(points: &[T], dim: usize, args: &[T]) -> Vec<T> {
    debug_assert_eq!((args.len() + 1) * dim, points.len());
    charge_points(args.len() + 1);
    let mut level = points.to_vec();
    let steps: Vec<BernsteinStep<'_, T>> = args.iter().map(BernsteinStep).collect();
    curve_blossom_in_place(&mut level, dim, &steps);
    level.truncate(dim);
    level
}

/// The blossom b[u_1..u_n; v_1..v_m] of the tensor patch `points` (n + 1 rows of `cols`
/// points), eq. (9) of seed 004: along v in every row, then along u.
pub(crate) fn tensor_blossom<T: Ring>(
    points: &[T],
    cols: usize,
    dim: usize,
    us: &[T],
    vs: &[T],
) -> Vec<T> {
    let rows = points.len() / (cols * dim);
    debug_assert_eq!((us.len() + 1, vs.len() + 1), (rows, cols));
    let along_v: Vec<BernsteinStep<'_, T>> = vs.iter().map(BernsteinStep).collect();
    let mut column = Vec::with_capacity(rows * dim);
    let mut row = Vec::with_capacity(cols * dim);
    for r in points.chunks_exact(cols * dim) {
        charge_points(cols);
        row.clear();
        row.extend_from_slice(r);
        curve_blossom_in_place(&mut row, dim, &along_v);
        column.extend_from_slice(&row[..dim]);
    }
    curve_blossom(&column, dim, us)
}

/// The point of the tensor patch at (s, t): [`tensor_blossom`] with every argument equal.
pub(crate) fn tensor_eval<T: Ring>(points: &[T], cols: usize, dim: usize, s: &T, t: &T) -> Vec<T> {
    let rows = points.len() / (cols * dim);
    let mut column = Vec::with_capacity(rows * dim);
    let mut row = Vec::with_capacity(cols * dim);
    for r in points.chunks_exact(cols * dim) {
        row.clear();
        row.extend_from_slice(r);
        curve_pyramid_in_place(&mut row, dim, &BernsteinStep(t));
        column.extend_from_slice(&row[..dim]);
    }
    curve_pyramid_in_place(&mut column, dim, &BernsteinStep(s));
    column.truncate(dim);
    column
}

/// The patch over [a, b] x [c, d] (`rect` = [a, b, c, d]) of the tensor patch `points`.
pub(crate) fn tensor_restrict<T: Ring>(
    points: &[T],
    cols: usize,
    dim: usize,
    rect: &[T; 4],
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let steps = rect.each_ref().map(BernsteinStep);
    tensor_net(points, cols, dim, steps.each_ref(), out, scratch);
}

/// A barycentric argument (u, v, w) of a triangle's blossom, the three weights free (the
/// blossom is multi-affine, so they need not add up to 1): u a + v b + w c.
struct BarycentricStep<'a, T>(&'a [T; 3]);

impl<T: Ring> TriangleStep<T> for BarycentricStep<'_, T> {
    #[inline]
    fn combine(&self, a: &T, b: &T, c: &T) -> T {
        let [u, v, w] = self.0;
        u.mul(a).add(&v.mul(b)).add(&w.mul(c))
    }
}

/// The blossom of the triangular patch `points` (degree n, lexicographic order of (ν, μ)) at
/// barycentric arguments (u_r, v_r, w_r), the weights of the corners a, b, c.
pub(crate) fn triangle_blossom<T: Ring>(points: &[T], dim: usize, args: &[[T; 3]]) -> Vec<T> {
    charge_points(points.len() / dim);
    let mut level = points.to_vec();
    let steps: Vec<BarycentricStep<'_, T>> = args.iter().map(BarycentricStep).collect();
    triangle_blossom_in_place(&mut level, dim, &steps);
    level.truncate(dim);
    level
}

/// The point of the triangular patch `points` (degree n) at the affine coordinates (s, t) of
/// the reference triangle, i.e. barycentric (s, t, 1 - s - t).
pub(crate) fn triangle_eval<T: Ring>(points: &[T], n: usize, dim: usize, at: &[T; 2]) -> Vec<T> {
    charge_points(points.len() / dim);
    let mut level = points.to_vec();
    triangle_blossom_in_place(&mut level, dim, &vec![BernsteinPairStep(at); n]);
    level.truncate(dim);
    level
}

/// The patch over the triangle with corners `corners` (affine coordinates (s, t)) of the
/// triangular patch `points` of degree `n`.
pub(crate) fn triangle_restrict<T: Ring>(
    points: &[T],
    n: usize,
    dim: usize,
    corners: &[[T; 2]; 3],
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let steps = corners.each_ref().map(BernsteinPairStep);
    triangle_net(points, n, dim, steps.each_ref(), out, scratch);
}
