//! The restriction engine: the blossom of a form, in the basis the form is written in, at every
//! argument tuple of a restriction net at once, with the work shared by halving.
//!
//! # One argument at a time
//!
//! A form of degree n is a level of n + 1 coefficients (a curve) or (n + 1)(n + 2) / 2
//! coefficients (a triangle). Fixing one argument of its blossom gives a form of degree n - 1
//! whose coefficients are ring combinations of neighbours:
//!
//! * Bernstein curve (de Casteljau, eq. (2) of seed 004), argument t:
//!   x'_i = (1 - t) x_i + t x_(i+1), computed as x_i + t (x_(i+1) - x_i);
//! * power curve C(u) = sum_i C(n, i) d_i u^i in the *scaled* power basis
//!   (d_i = c_i / C(n, i)), argument t: d'_i = d_i + t d_(i+1), because the blossom is
//!   sum_i d_i e_i(u_1, ..., u_n) and e_i(u', t) = e_i(u') + t e_(i-1)(u');
//! * Bernstein triangle, argument (s, t) (barycentric (s, t, 1 - s - t)):
//!   x'_ij = x_ij + s (x_(i+1)j - x_ij) + t (x_i(j+1) - x_ij);
//! * power triangle S(u, v) = sum M(N; i, j) d_ij u^i v^j (M the trinomial), argument
//!   (u, v): d'_ij = d_ij + u d_(i+1)j + v d_i(j+1), de Casteljau's step on the homogeneous
//!   form at the point (u, v, 1).
//!
//! Every step is a ring operation (no division), so the engine runs on f64, exact rationals
//! and symbolic polynomials alike, and the symbolic proofs apply to the code that runs in f64.
//! In the Bernstein basis each step is a convex combination when the argument lies in the
//! reference domain, which is why de Casteljau is stable; the engine does nothing else.
//!
//! # Vector arguments
//!
//! The blossom extends to a multilinear form of homogeneous arguments: a point is an argument
//! of weight 1, a vector (a difference of two points) one of weight 0. With weight w the four
//! steps above read w x + t (y - x), w x + t y, w c + s (a - c) + t (b - c) and
//! w c + u a + v b, so the steps of a vector argument are [`BernsteinVectorStep`]
//! (delta (y - x), a forward difference for delta = 1), [`PowerVectorStep`] (delta y, a shift of
//! the scaled power coefficients for delta = 1), [`BernsteinPairVectorStep`] and
//! [`PowerPairVectorStep`]. Vector arguments give derivatives (seed 004, eq. (10), and its
//! generalisation d^k C / dt^k = n! / (n - k)! f(t^(n-k), delta^k)).
//!
//! They are step types of their own rather than a weight inside the existing ones, because
//! the engine's hot loops would then pay one more multiplication per step for every
//! restriction. They are not mixed with point steps inside one net either: the blossom is
//! symmetric, so a mixed value f(a^(n-k-j), b^j, delta_1, ..., delta_k) is the net of the form
//! of degree n - k left after fixing the k vector arguments first ([`curve_fix_in_place`],
//! [`triangle_fix_in_place`]); [`curve_net`], [`tensor_net`] and [`triangle_net`] are
//! unchanged and run on that form with the ordinary point steps.
//!
//! # Shared work
//!
//! A control point of a restriction to [a, b] is q_j = f(a^(n-j), b^j). The left half
//! q_0..q_(s-1), s = ceil((n+1)/2), has at least n + 1 - s arguments a, the right half at least
//! s arguments b. Fixing those once gives two forms of about half the degree, each restricted in
//! the same way: the cost is C(r) = (3/4) r^2 + 2 C(r / 2) = (3/2) r^2 steps per coordinate,
//! O(n^2), against O(n^3) for one pyramid per control point. Tensor patches are two passes
//! (whole rows as points along u, then each row along v): O(nm(n + m)).
//!
//! For a triangle with corners A, B, C the outputs q_(ν μ λ) = f(A^ν, B^μ, C^λ) form a simplex.
//! A node of the recursion is a box lo <= (ν, μ, λ) <= hi cut by ν + μ + λ = r; every output
//! in it has at least lo_A arguments A, lo_B arguments B and lo_C arguments C, which are fixed
//! once; the box is then cut in half along its widest side, down to boxes of degree 2, whose
//! outputs share one step per first argument. Counted (one step of one point as the unit),
//! that is about 1.5 N^3 for all (N + 1)(N + 2) / 2 control points, i.e. O(N) per control
//! point, against about N^3 / 6 per control point for one pyramid each: 6.8x fewer steps at
//! N = 8, 20x at N = 16. The order is N^3, the size of the answer times N; the measured
//! log-log slope is in `BENCHMARKS.md`.
//!
//! # Storage
//!
//! Levels are contiguous runs of coordinates: point i of a level of `dim`-dimensional points
//! is `level[i * dim..(i + 1) * dim]`, so one step is a single loop over `(len - 1) * dim`
//! numbers, x'[k] = step(x[k], x[k + dim]), whatever the dimension, written from one buffer
//! into another so that the compiler vectorises it. Levels of at most four points are written
//! out without loops over points. The width is a [`Width`]: a runtime `usize`, or [`Fixed`]
//! for callers that know it at compile time. Nothing is allocated inside the engine: the caller
//! passes the output and a scratch buffer, which grows on first use and is reused afterwards.
//! On x86-64, levels of at least 64 floats run a build of the same source compiled for AVX
//! when the processor has it (detected at run time): the same operations in the same order,
//! so the same bits, four doubles to a vector instead of two.
//!
//! Division-free restriction needs more steps than the textbook's two subdivisions (split at
//! b, then at a / b: n(n + 1) steps): exactly 1.17 n(n + 1) at n = 3 and 1.45 n(n + 1) at
//! n = 64 for the halving, the optimum over binary splits. It pays for them with long
//! vectorised loops, and it never divides, which keeps short and extrapolating intervals as
//! accurate as inside ones (`BENCHMARKS.md` has both measurements).

use crate::shape::simplex::{triangle_index, triangle_len};
use crate::Ring;

/// One fixed argument of the blossom of a curve-like form: how it combines two neighbouring
/// coefficients of a level into one of the next.
pub trait CurveStep<T> {
    /// The coefficient of the next level made from neighbours `x` (index i) and `y` (i + 1).
    fn combine(&self, x: &T, y: &T) -> T;
}

/// One fixed argument of the blossom of a triangular form: how it combines the neighbours
/// `a` = x_(i+1)j, `b` = x_i(j+1) and `c` = x_ij of a level into x'_ij.
pub trait TriangleStep<T> {
    /// The coefficient x'_ij of the next level.
    fn combine(&self, a: &T, b: &T, c: &T) -> T;
}

/// The de Casteljau argument t of a Bernstein form: x + t (y - x).
#[derive(Clone, Copy, Debug)]
pub struct BernsteinStep<'a, T>(pub &'a T);

impl<T: Ring> CurveStep<T> for BernsteinStep<'_, T> {
    #[inline]
    fn combine(&self, x: &T, y: &T) -> T {
        x.add(&self.0.mul(&y.sub(x)))
    }
}

/// The argument t of a form in the scaled power basis: x + t y.
#[derive(Clone, Copy, Debug)]
pub struct PowerStep<'a, T>(pub &'a T);

impl<T: Ring> CurveStep<T> for PowerStep<'_, T> {
    #[inline]
    fn combine(&self, x: &T, y: &T) -> T {
        x.add(&self.0.mul(y))
    }
}

/// The barycentric argument (s, t, 1 - s - t) of a Bernstein triangle:
/// c + s (a - c) + t (b - c).
#[derive(Clone, Copy, Debug)]
pub struct BernsteinPairStep<'a, T>(pub &'a [T; 2]);

impl<T: Ring> TriangleStep<T> for BernsteinPairStep<'_, T> {
    #[inline]
    fn combine(&self, a: &T, b: &T, c: &T) -> T {
        let [s, t] = self.0;
        c.add(&s.mul(&a.sub(c))).add(&t.mul(&b.sub(c)))
    }
}

/// The argument (u, v) of a triangular form in the scaled power basis: c + u a + v b.
#[derive(Clone, Copy, Debug)]
pub struct PowerPairStep<'a, T>(pub &'a [T; 2]);

impl<T: Ring> TriangleStep<T> for PowerPairStep<'_, T> {
    #[inline]
    fn combine(&self, a: &T, b: &T, c: &T) -> T {
        let [u, v] = self.0;
        c.add(&u.mul(a)).add(&v.mul(b))
    }
}

/// The vector argument delta (homogeneous weight 0) of a Bernstein form: delta (y - x). For
/// delta = 1 a forward difference, the step of a derivative.
#[derive(Clone, Copy, Debug)]
pub struct BernsteinVectorStep<'a, T>(pub &'a T);

impl<T: Ring> CurveStep<T> for BernsteinVectorStep<'_, T> {
    #[inline]
    fn combine(&self, x: &T, y: &T) -> T {
        self.0.mul(&y.sub(x))
    }
}

/// The vector argument delta (homogeneous weight 0) of a form in the scaled power basis:
/// delta y. For delta = 1 the shift d_i -> d_(i+1).
#[derive(Clone, Copy, Debug)]
pub struct PowerVectorStep<'a, T>(pub &'a T);

impl<T: Ring> CurveStep<T> for PowerVectorStep<'_, T> {
    #[inline]
    fn combine(&self, _x: &T, y: &T) -> T {
        self.0.mul(y)
    }
}

/// The barycentric vector argument (s, t, -s - t) (coordinates adding up to 0, homogeneous
/// weight 0) of a Bernstein triangle: s (a - c) + t (b - c).
#[derive(Clone, Copy, Debug)]
pub struct BernsteinPairVectorStep<'a, T>(pub &'a [T; 2]);

impl<T: Ring> TriangleStep<T> for BernsteinPairVectorStep<'_, T> {
    #[inline]
    fn combine(&self, a: &T, b: &T, c: &T) -> T {
        let [s, t] = self.0;
        s.mul(&a.sub(c)).add(&t.mul(&b.sub(c)))
    }
}

/// The vector argument (u, v) (the homogeneous point (u, v, 0)) of a triangular form in the
/// scaled power basis: u a + v b.
#[derive(Clone, Copy, Debug)]
pub struct PowerPairVectorStep<'a, T>(pub &'a [T; 2]);

impl<T: Ring> TriangleStep<T> for PowerPairVectorStep<'_, T> {
    #[inline]
    fn combine(&self, a: &T, b: &T, _c: &T) -> T {
        let [u, v] = self.0;
        u.mul(a).add(&v.mul(b))
    }
}

/// The number of numbers per point: a runtime value (`usize`), or a constant ([`Fixed`]) that
/// lets the compiler unroll and drop bounds checks (the `[T; D]` front end passes `Fixed<D>`).
pub trait Width: Copy {
    /// The number of numbers per point.
    fn get(self) -> usize;
}

impl Width for usize {
    #[inline]
    fn get(self) -> usize {
        self
    }
}

/// A compile-time [`Width`] of `D` numbers per point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Fixed<const D: usize>;

impl<const D: usize> Width for Fixed<D> {
    #[inline]
    fn get(self) -> usize {
        D
    }
}

/// `dst[k] = step(src[k], src[k + dim])`: the next level of `src`, written to `dst`. The two
/// slices are distinct, so this is one straight loop that the compiler vectorises.
#[inline(always)]
fn step_into<T, S: CurveStep<T>>(src: &[T], dst: &mut [T], dim: usize, step: &S) {
    let m = src.len() - dim;
    for ((d, x), y) in dst[..m].iter_mut().zip(&src[..m]).zip(&src[dim..]) {
        *d = step.combine(x, y);
    }
}

/// The next level of `buf` in place, left-aligned: `buf[k] = step(buf[k], buf[k + dim])`
/// for increasing k, so that every read precedes the write that would change it. (For the
/// blossom at given arguments, which is not on the engine's hot path.)
#[inline]
pub(crate) fn step_left<T, S: CurveStep<T>>(buf: &mut [T], dim: usize, step: &S) {
    let m = buf.len() - dim;
    for k in 0..m {
        let v = step.combine(&buf[k], &buf[k + dim]);
        buf[k] = v;
    }
}

/// Applies `count >= 1` steps of `step` to `level`, alternating between the two scratch
/// buffers `ping` and `pong` (each at least `(len - 1)` points long): the result, `count`
/// points fewer, is returned as a slice of one of them.
#[inline(always)]
fn chain<'s, T, S: CurveStep<T>>(
    level: &[T],
    dim: usize,
    step: &S,
    count: usize,
    ping: &'s mut [T],
    pong: &'s mut [T],
) -> &'s [T] {
    let len = level.len();
    step_into(level, &mut ping[..len - dim], dim, step);
    let (mut src, mut dst) = (ping, pong);
    for l in 1..count {
        step_into(
            &src[..len - l * dim],
            &mut dst[..len - (l + 1) * dim],
            dim,
            step,
        );
        std::mem::swap(&mut src, &mut dst);
    }
    &src[..len - count * dim]
}

/// The scratch length (in numbers) that [`curve_net`] needs for degree `n` and `dim`: two
/// levels per depth of the halving.
///
/// # Panics
/// When the length overflows `usize`, which only sizes whose nets could not be stored reach.
pub fn curve_scratch_len(n: usize, dim: usize) -> usize {
    checked_curve_scratch_len(n, dim).expect(SCRATCH_OVERFLOWS)
}

const SCRATCH_OVERFLOWS: &str = "the scratch length overflows usize";

/// [`curve_scratch_len`], or `None` when it overflows `usize`.
pub(crate) fn checked_curve_scratch_len(n: usize, dim: usize) -> Option<usize> {
    let (mut r, mut len) = (n.checked_add(1)?, 0usize);
    while r > 4 {
        len = len.checked_add((r - 1).checked_mul(dim)?.checked_mul(2)?)?;
        r = r.div_ceil(2);
    }
    Some(len)
}

/// Restricts the curve-like form with coefficients `src` (n + 1 points of `dim` numbers) to the
/// arguments `a`, `b`: `out` receives q_j = f(a^(n-j), b^j), j = 0..=n.
///
/// `scratch` is grown to [`curve_scratch_len`] if it is shorter; nothing else is allocated.
///
/// # Panics
/// If `dim == 0`, `src` is empty or not a whole number of points, or `out.len() != src.len()`
/// (the public entry points check their input first).
#[inline]
pub fn curve_net<T: Ring, S: CurveStep<T>, W: Width>(
    src: &[T],
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let dim = width.get();
    let points = src.len().checked_div(dim).unwrap_or(0);
    assert!(points > 0 && points * dim == src.len() && out.len() == src.len());
    let need = curve_scratch_len(points - 1, dim);
    if scratch.len() < need {
        scratch.resize(need, T::zero());
    }
    // Small levels directly, so that a caller with a constant `dim` (the `[T; D]` front end)
    // gets them inlined and unrolled.
    match points {
        1 => out.clone_from_slice(src),
        2 => small_node::<T, S, W, 2>(src, width, a, b, out),
        3 => small_node::<T, S, W, 3>(src, width, a, b, out),
        4 => small_node::<T, S, W, 4>(src, width, a, b, out),
        _ => curve_node_widest(src, points, width, a, b, out, scratch),
    }
}

/// [`curve_node`], or the same compiled for AVX ([`curve_node_avx`]) when the numbers are
/// floats, the level has at least [`WIDE_FROM`] numbers and the processor has AVX.
#[inline]
fn curve_node_widest<T: Ring, S: CurveStep<T>, W: Width>(
    level: &[T],
    r: usize,
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
    scratch: &mut [T],
) {
    #[cfg(target_arch = "x86_64")]
    if T::UNROLLED && r * width.get() >= WIDE_FROM && std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the processor has just been seen to support AVX.
        #[allow(unsafe_code)]
        return unsafe { curve_node_avx(level, r, width, a, b, out, scratch) };
    }
    curve_node(level, r, width, a, b, out, scratch)
}

/// The level length (in numbers) from which the halving runs compiled for AVX when the
/// processor has it (x86-64, `f64`/`f32`): from there the steps' loops are long enough for the
/// wider vectors to pay. Curves of low degree take the unrolled evaluators anyway.
const WIDE_FROM: usize = 64;

/// The halving's recursion, named so that one body ([`curve_node_with`]) serves a plain build
/// and one compiled for wider vectors: each recurses into itself.
trait Recurse {
    fn node<T: Ring, S: CurveStep<T>, W: Width>(
        level: &[T],
        r: usize,
        width: W,
        a: &S,
        b: &S,
        out: &mut [T],
        scratch: &mut [T],
    );
}

/// The halving as compiled for the crate's target.
struct Plain;

impl Recurse for Plain {
    #[inline(always)]
    fn node<T: Ring, S: CurveStep<T>, W: Width>(
        level: &[T],
        r: usize,
        width: W,
        a: &S,
        b: &S,
        out: &mut [T],
        scratch: &mut [T],
    ) {
        curve_node(level, r, width, a, b, out, scratch)
    }
}

/// One node of the halving, out of line: [`curve_node_with`] recursing into itself.
fn curve_node<T: Ring, S: CurveStep<T>, W: Width>(
    level: &[T],
    r: usize,
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
    scratch: &mut [T],
) {
    curve_node_with::<Plain, T, S, W>(level, r, width, a, b, out, scratch)
}

/// The halving compiled with AVX enabled (x86-64): the same source and the same operations in
/// the same order, so the same numbers bit for bit (Rust never fuses a multiplication and an
/// addition), four doubles to a vector instead of two.
#[cfg(target_arch = "x86_64")]
struct Avx;

#[cfg(target_arch = "x86_64")]
impl Recurse for Avx {
    #[inline(always)]
    fn node<T: Ring, S: CurveStep<T>, W: Width>(
        level: &[T],
        r: usize,
        width: W,
        a: &S,
        b: &S,
        out: &mut [T],
        scratch: &mut [T],
    ) {
        // SAFETY: only reached from `curve_node_avx`, which runs only where AVX was detected.
        #[allow(unsafe_code)]
        unsafe {
            curve_node_avx(level, r, width, a, b, out, scratch)
        }
    }
}

/// [`curve_node`] compiled for AVX; callers make sure that the processor has it.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn curve_node_avx<T: Ring, S: CurveStep<T>, W: Width>(
    level: &[T],
    r: usize,
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
    scratch: &mut [T],
) {
    curve_node_with::<Avx, T, S, W>(level, r, width, a, b, out, scratch)
}

/// One node of the halving: `level` holds a form of degree r - 1 (r points); `out` receives
/// its r control points. The halves recurse through `R`.
#[inline(always)]
fn curve_node_with<R: Recurse, T: Ring, S: CurveStep<T>, W: Width>(
    level: &[T],
    r: usize,
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
    scratch: &mut [T],
) {
    let dim = width.get();
    match r {
        1 => out.clone_from_slice(level),
        2 => small_node::<T, S, W, 2>(level, width, a, b, out),
        3 => small_node::<T, S, W, 3>(level, width, a, b, out),
        4 => small_node::<T, S, W, 4>(level, width, a, b, out),
        _ => {
            // The left half (s outputs) fixes r - s arguments a, the right half s arguments b.
            let s = r.div_ceil(2);
            let (ping, rest) = scratch.split_at_mut((r - 1) * dim);
            let (pong, rest) = rest.split_at_mut((r - 1) * dim);
            let (left, right) = out.split_at_mut(s * dim);
            let half = chain(level, dim, a, r - s, ping, pong);
            R::node(half, s, width, a, b, left, rest);
            let half = chain(level, dim, b, s, ping, pong);
            R::node(half, r - s, width, a, b, right, rest);
        }
    }
}

/// The halving of a level of R = 2, 3 or 4 points written out, one coordinate at a time: the
/// same steps as [`curve_node`] (q_0 = f(a), q_1 = f(b) for two points; for three, the levels
/// A = f(a, ·), B = f(b, ·) and q = f(a, a), f(a, b), f(b, b); for four, the levels f(a^2, ·)
/// and f(b^2, ·), each restricted), without recursion or scratch.
#[inline]
fn small_node<T: Ring, S: CurveStep<T>, W: Width, const R: usize>(
    level: &[T],
    width: W,
    a: &S,
    b: &S,
    out: &mut [T],
) {
    let dim = width.get();
    let (level, out) = (&level[..R * dim], &mut out[..R * dim]);
    for x in 0..dim {
        let p = |i: usize| &level[i * dim + x];
        match R {
            2 => {
                out[x] = a.combine(p(0), p(1));
                out[dim + x] = b.combine(p(0), p(1));
            }
            3 => {
                let (a0, a1) = (a.combine(p(0), p(1)), a.combine(p(1), p(2)));
                let (b0, b1) = (b.combine(p(0), p(1)), b.combine(p(1), p(2)));
                out[x] = a.combine(&a0, &a1);
                out[dim + x] = b.combine(&a0, &a1);
                out[2 * dim + x] = b.combine(&b0, &b1);
            }
            _ => {
                let (p0, p1, p2, p3) = (p(0), p(1), p(2), p(3));
                let (a10, a11, a12) = (a.combine(p0, p1), a.combine(p1, p2), a.combine(p2, p3));
                let (a20, a21) = (a.combine(&a10, &a11), a.combine(&a11, &a12));
                let (b10, b11, b12) = (b.combine(p0, p1), b.combine(p1, p2), b.combine(p2, p3));
                let (b20, b21) = (b.combine(&b10, &b11), b.combine(&b11, &b12));
                out[x] = a.combine(&a20, &a21);
                out[dim + x] = b.combine(&a20, &a21);
                out[2 * dim + x] = a.combine(&b20, &b21);
                out[3 * dim + x] = b.combine(&b20, &b21);
            }
        }
    }
}

/// The scratch length that [`tensor_net`] needs for bidegree (n, m) and `dim`: the net after
/// the pass along u, and the halving's levels of either pass.
///
/// # Panics
/// When the length overflows `usize`, which only sizes whose nets could not be stored reach.
pub fn tensor_scratch_len(n: usize, m: usize, dim: usize) -> usize {
    checked_tensor_scratch_len(n, m, dim).expect(SCRATCH_OVERFLOWS)
}

/// [`tensor_scratch_len`], or `None` when it overflows `usize`.
pub(crate) fn checked_tensor_scratch_len(n: usize, m: usize, dim: usize) -> Option<usize> {
    let row = m.checked_add(1)?.checked_mul(dim)?;
    let net = n.checked_add(1)?.checked_mul(row)?;
    let levels = checked_curve_scratch_len(n, row)?.max(checked_curve_scratch_len(m, dim)?);
    net.checked_add(levels)
}

/// Restricts the tensor-product form with coefficients `src` (rows of m + 1 points, row by row,
/// n + 1 rows) to [a, b] x [c, d]: `out[nu][mu]` = f(a^(n-nu), b^nu; c^(m-mu), d^mu). Along u
/// with whole rows as points, then every row along v.
///
/// # Panics
/// As [`curve_net`], for `cols` points per row.
pub fn tensor_net<T: Ring, S: CurveStep<T>>(
    src: &[T],
    cols: usize,
    dim: usize,
    [a, b, c, d]: [&S; 4],
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let row = cols * dim;
    assert!(row > 0 && src.len().is_multiple_of(row) && out.len() == src.len());
    let rows = src.len() / row;
    let need = tensor_scratch_len(rows - 1, cols - 1, dim);
    if scratch.len() < need {
        scratch.resize(need, T::zero());
    }
    let (along_u, rest) = scratch.split_at_mut(src.len());
    curve_node_widest(src, rows, row, a, b, along_u, rest);
    for (from, to) in along_u.chunks(row).zip(out.chunks_mut(row)) {
        curve_node_widest(from, cols, dim, c, d, to, rest);
    }
}

/// The scratch length that [`triangle_net`] needs for degree `n` and `dim`: two levels for each
/// of the degrees n - 1, ..., 0, the most a path of the recursion can hold at once.
///
/// # Panics
/// When the length overflows `usize`, which only sizes whose nets could not be stored reach.
pub fn triangle_scratch_len(n: usize, dim: usize) -> usize {
    checked_triangle_scratch_len(n, dim).expect(SCRATCH_OVERFLOWS)
}

/// [`triangle_scratch_len`], or `None` when it overflows `usize`: 2 sum_{k < n} (k + 1)(k + 2)
/// / 2 = n (n + 1) (n + 2) / 3 numbers per coordinate.
pub(crate) fn checked_triangle_scratch_len(n: usize, dim: usize) -> Option<usize> {
    // Above 2^40 the cube alone exceeds any usize; below, it fits u128.
    if n > 1 << 40 {
        return None;
    }
    let n = n as u128;
    let per_coordinate = usize::try_from(n * (n + 1) * (n + 2) / 3).ok()?;
    per_coordinate.checked_mul(dim)
}

/// Restricts the triangular form with coefficients `src` (degree `n`, (n + 1)(n + 2) / 2
/// points in lexicographic order of (i, j)) to the triangle with corners `corners = [A, B, C]`:
/// `out` receives q_(ν μ λ) = f(A^ν, B^μ, C^λ) at `triangle_index(n, ν, μ)`.
///
/// # Panics
/// If `src` or `out` do not hold `triangle_len(n)` points of `dim > 0` numbers.
pub fn triangle_net<T: Ring, S: TriangleStep<T>>(
    src: &[T],
    n: usize,
    dim: usize,
    corners: [&S; 3],
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let len = triangle_len(n) * dim;
    assert!(dim > 0 && src.len() == len && out.len() == len);
    let need = triangle_scratch_len(n, dim);
    if scratch.len() < need {
        scratch.resize(need, T::zero());
    }
    let node = TriangleBox {
        degree: n,
        lo: [0; 3],
        hi: [n; 3],
        offset: [0; 3],
    };
    let ctx = TriangleRun {
        total: n,
        dim,
        corners,
    };
    ctx.node(src, node, out, scratch);
}

/// The outputs of one node: (ν, μ, λ) = offset + (x, y, z) with lo <= (x, y, z) <= hi and
/// x + y + z = degree, the degree of the node's level.
#[derive(Clone, Copy, Debug)]
struct TriangleBox {
    degree: usize,
    lo: [usize; 3],
    hi: [usize; 3],
    offset: [usize; 3],
}

impl TriangleBox {
    /// The box shrunk to the points of the plane; `None` when it holds none.
    fn tightened(mut self) -> Option<Self> {
        let r = self.degree;
        for k in 0..3 {
            let (p, q) = ((k + 1) % 3, (k + 2) % 3);
            let others_hi = self.hi[p] + self.hi[q];
            let others_lo = self.lo[p] + self.lo[q];
            if others_lo > r {
                return None;
            }
            self.lo[k] = self.lo[k].max(r.saturating_sub(others_hi));
            self.hi[k] = self.hi[k].min(r - others_lo);
            if self.lo[k] > self.hi[k] {
                return None;
            }
        }
        Some(self)
    }
}

/// What every node of one triangle restriction shares.
struct TriangleRun<'a, S> {
    total: usize,
    dim: usize,
    corners: [&'a S; 3],
}

impl<S> TriangleRun<'_, S> {
    fn node<T: Ring>(&self, level: &[T], node: TriangleBox, out: &mut [T], rest: &mut [T])
    where
        S: TriangleStep<T>,
    {
        let Some(node) = node.tightened() else {
            return;
        };
        let dim = self.dim;
        let fixed: usize = node.lo.iter().sum();
        if fixed > 0 {
            // Fix lo_A arguments A, lo_B arguments B, lo_C arguments C once for the whole box,
            // one step at a time between two buffers.
            let e = node.degree;
            let (ping, rest) = rest.split_at_mut(triangle_len(e - 1) * dim);
            let (pong, rest) = rest.split_at_mut(triangle_len(e.saturating_sub(2)) * dim);
            let mut degree = e;
            let (mut src, mut dst): (&mut [T], &mut [T]) = (ping, pong);
            for (k, &count) in node.lo.iter().enumerate() {
                for _ in 0..count {
                    if degree == e {
                        triangle_step_into(level, src, degree, dim, self.corners[k]);
                    } else {
                        triangle_step_into(src, dst, degree, dim, self.corners[k]);
                        std::mem::swap(&mut src, &mut dst);
                    }
                    degree -= 1;
                }
            }
            let inner = TriangleBox {
                degree,
                lo: [0; 3],
                hi: [0, 1, 2].map(|k| node.hi[k] - node.lo[k]),
                offset: [0, 1, 2].map(|k| node.offset[k] + node.lo[k]),
            };
            self.node(&src[..triangle_len(degree) * dim], inner, out, rest);
            return;
        }
        if node.degree <= 2 {
            self.small_box(level, node, out, rest);
            return;
        }
        // Cut the box in half along its widest side.
        let k = (0..3)
            .max_by_key(|&k| node.hi[k] - node.lo[k])
            .expect("three sides");
        let mid = (node.lo[k] + node.hi[k]) / 2;
        let mut low = node;
        low.hi[k] = mid;
        let mut high = node;
        high.lo[k] = mid + 1;
        self.node(level, low, out, rest);
        self.node(level, high, out, rest);
    }
}

impl<S> TriangleRun<'_, S> {
    /// The outputs of a box of degree at most 2 straight from `level`: for degree 2, one step
    /// per first argument (A before B before C) shared by the outputs that start with it,
    /// then each output's second step; cutting such a box further would cost more than it
    /// saves.
    fn small_box<T: Ring>(&self, level: &[T], node: TriangleBox, out: &mut [T], rest: &mut [T])
    where
        S: TriangleStep<T>,
    {
        let dim = self.dim;
        let outputs = small_box_outputs(node);
        match node.degree {
            0 => {
                let at = self.at(node, [0, 0]);
                out[at..at + dim].clone_from_slice(&level[..dim]);
            }
            1 => {
                for &(xy, [first, _]) in outputs.iter() {
                    let at = self.at(node, xy);
                    triangle_step_into(level, &mut out[at..at + dim], 1, dim, self.corners[first]);
                }
            }
            _ => {
                let tmp = &mut rest[..3 * dim];
                for k in 0..3 {
                    let mut shared = false;
                    for &(xy, [first, second]) in outputs.iter().filter(|(_, ks)| ks[0] == k) {
                        if !shared {
                            triangle_step_into(level, tmp, 2, dim, self.corners[first]);
                            shared = true;
                        }
                        let at = self.at(node, xy);
                        let target = &mut out[at..at + dim];
                        triangle_step_into(tmp, target, 1, dim, self.corners[second]);
                    }
                }
            }
        }
    }

    /// Where output (x, y) of `node` goes in `out`.
    fn at(&self, node: TriangleBox, [x, y]: [usize; 2]) -> usize {
        triangle_index(self.total, node.offset[0] + x, node.offset[1] + y) * self.dim
    }
}

/// The outputs (x, y) of a box of degree at most 2, each with its arguments in the order A,
/// B, C (the corner indices; the second is unused below degree 2).
fn small_box_outputs(node: TriangleBox) -> SmallOutputs {
    let r = node.degree;
    let mut found = SmallOutputs {
        items: [([0; 2], [0; 2]); 6],
        len: 0,
    };
    for x in node.lo[0]..=node.hi[0] {
        for y in node.lo[1]..=node.hi[1] {
            let Some(z) = r.checked_sub(x + y) else {
                continue;
            };
            if z < node.lo[2] || z > node.hi[2] {
                continue;
            }
            let mut ks = [0; 2];
            let mut count = 0;
            for (k, c) in [x, y, z].into_iter().enumerate() {
                for _ in 0..c {
                    ks[count] = k;
                    count += 1;
                }
            }
            found.items[found.len] = ([x, y], ks);
            found.len += 1;
        }
    }
    found
}

/// At most six outputs of a small box, without allocating.
struct SmallOutputs {
    items: [([usize; 2], [usize; 2]); 6],
    len: usize,
}

impl SmallOutputs {
    fn iter(&self) -> std::slice::Iter<'_, ([usize; 2], [usize; 2])> {
        self.items[..self.len].iter()
    }
}

/// The level of degree `degree - 1` of the triangular level `src` (degree `degree`), written
/// to the front of `dst`: row i of the result from rows i and i + 1 of `src`, one straight
/// loop per row.
fn triangle_step_into<T, S: TriangleStep<T>>(
    src: &[T],
    dst: &mut [T],
    degree: usize,
    dim: usize,
    step: &S,
) {
    if degree == 1 {
        // x_00, x_01, x_10 in that order: c, b, a.
        let (c, rest) = src.split_at(dim);
        let (b, a) = rest.split_at(dim);
        for (((d, a), b), c) in dst[..dim].iter_mut().zip(a).zip(b).zip(c) {
            *d = step.combine(a, b, c);
        }
        return;
    }
    for i in 0..degree {
        let row = triangle_index(degree, i, 0) * dim;
        let next_row = triangle_index(degree, i + 1, 0) * dim;
        let out_row = triangle_index(degree - 1, i, 0) * dim;
        let width = (degree - i) * dim;
        let a = &src[next_row..next_row + width];
        let b = &src[row + dim..row + dim + width];
        let c = &src[row..row + width];
        let d = &mut dst[out_row..out_row + width];
        for (((d, a), b), c) in d.iter_mut().zip(a).zip(b).zip(c) {
            *d = step.combine(a, b, c);
        }
    }
}

/// [`triangle_step_into`] in place: the new coefficient (i, j) lands at or before the old
/// (i, j), and every coefficient it reads lies at or after it, so reading in increasing order
/// never sees a value already overwritten.
fn triangle_step_in_place<T, S: TriangleStep<T>>(
    buf: &mut [T],
    degree: usize,
    dim: usize,
    step: &S,
) {
    for i in 0..degree {
        let row = triangle_index(degree, i, 0) * dim;
        let next_row = triangle_index(degree, i + 1, 0) * dim;
        let out_row = triangle_index(degree - 1, i, 0) * dim;
        let width = (degree - i) * dim;
        for x in 0..width {
            let v = step.combine(&buf[next_row + x], &buf[row + dim + x], &buf[row + x]);
            buf[out_row + x] = v;
        }
    }
}

/// The blossom of the curve-like form `level` (n + 1 points) at `args` (n of them), in place:
/// the answer is `level[..dim]`. n steps of one argument each, O(n^2).
///
/// # Panics
/// If `args.len() + 1` is not the number of points of `level`.
pub(crate) fn curve_blossom_in_place<T: Ring, S: CurveStep<T>>(
    level: &mut [T],
    dim: usize,
    args: &[S],
) {
    assert_eq!(
        (args.len() + 1) * dim,
        level.len(),
        "n arguments for n + 1 points"
    );
    let len = level.len();
    for (r, step) in args.iter().enumerate() {
        step_left(&mut level[..len - r * dim], dim, step);
    }
}

/// The blossom of the triangular form `level` (degree n) at `args` (n of them), in place: the
/// answer is `level[..dim]`.
///
/// # Panics
/// If `level` does not hold `triangle_len(args.len())` points.
pub(crate) fn triangle_blossom_in_place<T: Ring, S: TriangleStep<T>>(
    level: &mut [T],
    dim: usize,
    args: &[S],
) {
    let n = args.len();
    assert_eq!(
        triangle_len(n) * dim,
        level.len(),
        "n arguments for degree n"
    );
    for (r, step) in args.iter().enumerate() {
        triangle_step_in_place(level, n - r, dim, step);
    }
}

/// Fixes the arguments `args` of the blossom of the curve-like form `level` (n + 1 points of
/// `dim` numbers, n >= `args.len()`), in place: afterwards the first `(n + 1 - args.len()) *
/// dim` numbers of `level`, whose count is returned, hold the form of degree n - `args.len()`
/// whose blossom is f(args, ·). One step per argument, as in [`curve_blossom_in_place`].
///
/// # Panics
/// If `level` is not a whole number of points or has fewer than `args.len() + 1` of them.
pub(crate) fn curve_fix_in_place<T: Ring, S: CurveStep<T>>(
    level: &mut [T],
    dim: usize,
    args: &[S],
) -> usize {
    let len = level.len();
    assert!(
        dim > 0 && len.is_multiple_of(dim) && len / dim > args.len(),
        "at most n arguments for n + 1 points"
    );
    for (r, step) in args.iter().enumerate() {
        step_left(&mut level[..len - r * dim], dim, step);
    }
    len - args.len() * dim
}

/// Fixes the arguments `args` of the blossom of the triangular form `level` (degree `n >=
/// args.len()`), in place: afterwards the first `triangle_len(n - args.len()) * dim` numbers
/// of `level` hold the triangular form of degree n - `args.len()` (in the same lexicographic
/// order) whose blossom is f(args, ·); its degree is returned.
///
/// # Panics
/// If `level` does not hold `triangle_len(n)` points or `args.len() > n`.
pub(crate) fn triangle_fix_in_place<T: Ring, S: TriangleStep<T>>(
    level: &mut [T],
    n: usize,
    dim: usize,
    args: &[S],
) -> usize {
    assert!(
        args.len() <= n && triangle_len(n) * dim == level.len(),
        "at most n arguments for degree n"
    );
    for (r, step) in args.iter().enumerate() {
        triangle_step_in_place(level, n - r, dim, step);
    }
    n - args.len()
}

/// De Casteljau's subdivision of the Bernstein curve `src` at `t`: `left` receives the
/// control points f(0^(n-i), t^i) of the part over [0, t], `right` those f(t^(n-i), 1^i) of
/// the part over [t, 1], from the edges of one pyramid (n(n + 1) / 2 steps). `right` doubles as
/// the working level.
///
/// # Panics
/// If the three slices differ in length or are not whole points.
pub(crate) fn curve_split<T: Ring>(src: &[T], dim: usize, t: &T, left: &mut [T], right: &mut [T]) {
    assert!(left.len() == src.len() && right.len() == src.len() && src.len().is_multiple_of(dim));
    let n = src.len() / dim - 1;
    let step = BernsteinStep(t);
    right.clone_from_slice(src);
    for r in 0..=n {
        // The level of r steps occupies right[..(n + 1 - r) * dim]; its first point is
        // f(0^(n-r), t^r), its last f(t^r, 1^(n-r)), which is where it stays.
        left[r * dim..(r + 1) * dim].clone_from_slice(&right[..dim]);
        if r < n {
            step_left(&mut right[..(n + 1 - r) * dim], dim, &step);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checked_scratch_lengths_agree_with_their_definitions() {
        for n in 0usize..40 {
            for dim in [1, 3, 1536] {
                let (mut r, mut curve) = (n + 1, 0);
                while r > 4 {
                    curve += 2 * (r - 1) * dim;
                    r = r.div_ceil(2);
                }
                assert_eq!(checked_curve_scratch_len(n, dim), Some(curve));
                let triangle = 2 * (0..n).map(triangle_len).sum::<usize>() * dim;
                assert_eq!(checked_triangle_scratch_len(n, dim), Some(triangle));
                let m = n % 5;
                let tensor = (n + 1) * (m + 1) * dim
                    + checked_curve_scratch_len(n, (m + 1) * dim)
                        .unwrap()
                        .max(checked_curve_scratch_len(m, dim).unwrap());
                assert_eq!(checked_tensor_scratch_len(n, m, dim), Some(tensor));
            }
        }
        assert_eq!(checked_curve_scratch_len(usize::MAX, 1), None);
        assert_eq!(checked_curve_scratch_len(1 << 40, 1 << 30), None);
        assert_eq!(checked_triangle_scratch_len(1 << 22, 1), None);
        assert_eq!(checked_triangle_scratch_len(usize::MAX, 1), None);
        assert_eq!(checked_tensor_scratch_len(usize::MAX, 1, 1), None);
        assert_eq!(checked_tensor_scratch_len(1 << 20, 1 << 20, 1 << 30), None);
    }
    use crate::shape::bezier::bezier_curve_blossom;
    use crate::Rational;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn curve_net_is_the_blossom_at_every_control_point() {
        for n in 0..12 {
            let ctrl: Vec<Vec<Rational>> = (0..=n)
                .map(|i| vec![q((i * i) as i64 - 3, 1), q(i as i64, 7)])
                .collect();
            let flat: Vec<Rational> = ctrl.concat();
            let (a, b) = (q(-2, 3), q(5, 4));
            let mut out = vec![Rational::from_integer(0.into()); flat.len()];
            let mut scratch = Vec::new();
            curve_net(
                &flat,
                2,
                &BernsteinStep(&a),
                &BernsteinStep(&b),
                &mut out,
                &mut scratch,
            );
            for j in 0..=n {
                let args: Vec<Rational> = (0..n)
                    .map(|k| if k < n - j { a.clone() } else { b.clone() })
                    .collect();
                assert_eq!(
                    out[j * 2..j * 2 + 2],
                    bezier_curve_blossom(&ctrl, &args).unwrap()[..]
                );
            }
        }
    }

    /// The AVX build computes the same numbers bit for bit as the plain one: the same
    /// operations in the same order, only wider vectors.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn avx_build_gives_the_plain_build_bit_for_bit() {
        if !std::arch::is_x86_feature_detected!("avx") {
            return;
        }
        fn both<T: Ring + Copy + PartialEq + std::fmt::Debug>(
            src: &[T],
            r: usize,
            dim: usize,
            a: T,
            b: T,
        ) -> (Vec<T>, Vec<T>) {
            let scratch_len = checked_curve_scratch_len(r - 1, dim).unwrap();
            let (mut plain, mut wide) = (vec![T::zero(); src.len()], vec![T::zero(); src.len()]);
            let mut scratch = vec![T::zero(); scratch_len];
            let (sa, sb) = (BernsteinStep(&a), BernsteinStep(&b));
            curve_node(src, r, dim, &sa, &sb, &mut plain, &mut scratch);
            // SAFETY: AVX was detected above.
            #[allow(unsafe_code)]
            unsafe {
                curve_node_avx(src, r, dim, &sa, &sb, &mut wide, &mut scratch)
            };
            (plain, wide)
        }
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
        };
        for r in (26..=71).step_by(5) {
            for dim in 1..=5 {
                let src: Vec<f64> = (0..r * dim).map(|_| next()).collect();
                let (a, b) = (next() * 2.0, next() * 2.0);
                let (plain, wide) = both(&src, r, dim, a, b);
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(
                    bits(&plain),
                    bits(&wide),
                    "f64, {r} points, dimension {dim}"
                );
                let src: Vec<f32> = src.iter().map(|&x| x as f32).collect();
                let (plain, wide) = both(&src, r, dim, a as f32, b as f32);
                let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(
                    bits(&plain),
                    bits(&wide),
                    "f32, {r} points, dimension {dim}"
                );
            }
        }
    }

    #[test]
    fn triangle_boxes_cover_every_output_once() {
        // Restricting to the reference corners themselves reproduces the net exactly.
        for n in 0..9 {
            let src: Vec<Rational> = (0..triangle_len(n) as i64).map(|k| q(k * k, 3)).collect();
            let corners = [[q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], [q(0, 1), q(0, 1)]];
            let steps = corners.each_ref().map(BernsteinPairStep);
            let mut out = vec![q(-1, 1); src.len()];
            let mut scratch = Vec::new();
            triangle_net(&src, n, 1, steps.each_ref(), &mut out, &mut scratch);
            assert_eq!(out, src, "degree {n}");
        }
    }
}
