//! De Boor's algorithm, the Bézier points of a span and knot insertion on flat coordinates:
//! a run of de Boor points is one slice of `dim` numbers per point, point after point, and
//! every algorithm works in place in one scratch buffer (no allocation per point).
//!
//! On the non-empty domain span s of a knot vector of degree p, level r of de Boor's
//! recurrence (Theorem 2.3 of seed 002) with the argument x_r is
//!
//! d_i^r = d_{i-1}^{r-1} + w_i^r (d_i^{r-1} - d_{i-1}^{r-1}),  w_i^r = (x_r - t_i) / (t_{i+p+1-r} - t_i),
//!
//! for i = s - p + r..=s, and d_s^p = f_s(x_1, ..., x_p), the blossom of the piece on the span.
//! Stored as `level[j]` = d_{s-p+r+j}^r, the new point j reads the old points j and j + 1 only,
//! so the levels overwrite one another from the left. Every step is an affine combination taken
//! coordinate by coordinate, so a "point" may be a whole row of a surface's grid (the
//! tensor-product surfaces run these algorithms one variable at a time with `dim` the length of
//! a row).

use super::knots::KnotVector;
use crate::error::{Error, Result};
use crate::num::linalg::Field;

/// Level `r` (1..=p) of de Boor's recurrence on the span `s` with the argument `x`, in place:
/// on entry `level` holds d_i^(r-1) for i = s - p + r - 1..=s (p + 2 - r points of `dim`), on
/// exit its first p + 1 - r points are d_i^r for i = s - p + r..=s.
pub(crate) fn de_boor_level<T: Field>(
    knots: &KnotVector<T>,
    s: usize,
    r: usize,
    x: &T,
    level: &mut [T],
    dim: usize,
) {
    let p = knots.degree();
    let t = knots.knots();
    for j in 0..=p - r {
        let i = s - p + r + j;
        let w = x.sub(&t[i]).divide(&t[i + p + 1 - r].sub(&t[i]));
        let (left, right) = level.split_at_mut((j + 1) * dim);
        for (a, b) in left[j * dim..].iter_mut().zip(&right[..dim]) {
            *a = a.add(&w.mul(&b.sub(a)));
        }
    }
}

/// The blossom f_s(args) on the non-empty domain span `s`, in place: `level` holds the de Boor
/// points d_{s-p}..d_s (p + 1 points of `dim`) on entry and the answer in its first `dim`
/// numbers on exit; `args` yields the p arguments x_1..x_p in order.
pub(crate) fn de_boor_in_place<'a, T: Field + 'a>(
    knots: &KnotVector<T>,
    s: usize,
    level: &mut [T],
    dim: usize,
    args: impl IntoIterator<Item = &'a T>,
) {
    let p = knots.degree();
    debug_assert!(knots.is_span(s) && level.len() == (p + 1) * dim);
    let mut levels = 0;
    for (r, x) in (1..=p).zip(args) {
        de_boor_level(knots, s, r, x, level, dim);
        levels += 1;
    }
    debug_assert_eq!(levels, p, "one argument per level");
}

/// The blossom f_s(args) on the span `s` from the de Boor points `window` = d_{s-p}..d_s,
/// written to `out` (`dim` numbers), with `scratch` as the working copy of the window.
pub(crate) fn de_boor_into<'a, T: Field + 'a>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[T],
    dim: usize,
    args: impl IntoIterator<Item = &'a T>,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    scratch.clear();
    scratch.extend_from_slice(window);
    de_boor_in_place(knots, s, scratch, dim, args);
    out.clone_from_slice(&scratch[..dim]);
}

/// The Bézier points b_i = f_s(a^(p-i), b^i), i = 0..=p, of the piece on the non-empty domain
/// span `s` = [a, b] from the de Boor points `window` = d_{s-p}..d_s, written to `out`
/// ((p + 1) `dim` numbers), with `scratch` as the working copy of the window.
pub(crate) fn bezier_points_into<T: Field>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[T],
    dim: usize,
    out: &mut [T],
    scratch: &mut Vec<T>,
) {
    let p = knots.degree();
    let (a, b) = (&knots.knots()[s], &knots.knots()[s + 1]);
    debug_assert_eq!(out.len(), (p + 1) * dim);
    for (i, point) in out.chunks_exact_mut(dim).enumerate() {
        let args = std::iter::repeat_n(a, p - i).chain(std::iter::repeat_n(b, i));
        de_boor_into(knots, s, window, dim, args, point, scratch);
    }
}

/// De Boor's full table on the span `s` from `window` = d_{s-p}..d_s with one argument per
/// level: entry r holds d_i^r for i = s - p + r..=s, point after point (level 0 is `window`,
/// level p is f_s(args)).
pub(crate) fn de_boor_table<'a, T: Field + 'a>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[T],
    dim: usize,
    args: impl IntoIterator<Item = &'a T>,
) -> Vec<Vec<T>> {
    let p = knots.degree();
    let mut level = window.to_vec();
    let mut table = vec![window.to_vec()];
    for (r, x) in (1..=p).zip(args) {
        de_boor_level(knots, s, r, x, &mut level, dim);
        table.push(level[..(p + 1 - r) * dim].to_vec());
    }
    table
}

/// Where `x` goes: the span s with t_s <= x < t_(s+1) (the last span at the right end) and
/// the knot vector with x inserted after t_s. An error names `x` outside the domain, or
/// `knots[i]` when x would exceed multiplicity p + 1.
pub(crate) fn insertion<T: Field>(knots: &KnotVector<T>, x: &T) -> Result<(usize, KnotVector<T>)> {
    let s = knots
        .span(x)
        .map_err(|e| Error::of(e.kind, "x", e.message))?;
    let mut new = Vec::with_capacity(knots.knots().len() + 1);
    new.extend_from_slice(&knots.knots()[..=s]);
    new.push(x.clone());
    new.extend_from_slice(&knots.knots()[s + 1..]);
    Ok((s, KnotVector::new(knots.degree(), new)?))
}

/// The de Boor points `points` (all m of them, `dim` numbers each) on `old` with the knot of
/// [`insertion`] on the span `s` inserted, giving `new`: appended to `out` (m + 1 points).
/// By Theorem 2.2 on the new knot vector T', d'_k = f_s(t'_(k+1), ..., t'_(k+p)) for
/// k = s - p + 1..=s; the other points keep their values (their knot windows miss x).
pub(crate) fn insert_points<T: Field>(
    old: &KnotVector<T>,
    new: &KnotVector<T>,
    s: usize,
    points: &[T],
    dim: usize,
    out: &mut Vec<T>,
    scratch: &mut Vec<T>,
) {
    let p = old.degree();
    let t = new.knots();
    let window = &points[(s - p) * dim..(s + 1) * dim];
    out.extend_from_slice(&points[..(s - p + 1) * dim]);
    for k in s - p + 1..=s {
        let start = out.len();
        out.resize(start + dim, T::zero());
        de_boor_into(
            old,
            s,
            window,
            dim,
            &t[k + 1..=k + p],
            &mut out[start..],
            scratch,
        );
    }
    out.extend_from_slice(&points[s * dim..]);
}
