//! Homogeneous coordinates on flat buffers: the lift of a weighted point (b, w) to (w b, w),
//! the central projection of (N, w) back to N / w, and the restriction of a rational Bézier
//! shape through its homogeneous points.
//!
//! A rational Bézier shape sum w_i b_i B_i / sum w_i B_i is the central projection of the
//! polynomial shape with control points h_i = (w_i b_i, w_i) of dimension D + 1. Every affine
//! operation of Bézier shapes (de Casteljau, restriction) is done on the h_i; only its result is
//! projected. The buffers hold `dim` (or `dim + 1`) numbers per point, point after point.

use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::point::Point;
use crate::Ring;

/// Appends the homogeneous point (w b, w) to `out`.
pub(crate) fn push_lifted<T: Ring>(out: &mut Vec<T>, b: &[T], w: &T) {
    out.extend(b.iter().map(|x| x.mul(w)));
    out.push(w.clone());
}

/// Replaces `out` by the homogeneous points (w_i b_i, w_i) of the points `coords` (`dim`
/// numbers each) and their weights `weights` (one per point). No allocation once `out` has
/// grown to (n + 1)(D + 1) numbers.
pub(crate) fn lift_all_into<T: Ring>(coords: &[T], dim: usize, weights: &[T], out: &mut Vec<T>) {
    out.resize(weights.len() * (dim + 1), T::zero());
    lift_into(coords, dim, weights, out);
}

/// Writes the homogeneous points (w_i b_i, w_i) of the points `coords` (`dim` numbers each)
/// and their weights `weights` into `out`, (n + 1)(D + 1) numbers.
pub(crate) fn lift_into<T: Ring>(coords: &[T], dim: usize, weights: &[T], out: &mut [T]) {
    debug_assert_eq!(coords.len(), weights.len() * dim);
    debug_assert_eq!(out.len(), weights.len() * (dim + 1));
    for ((h, b), w) in out
        .chunks_exact_mut(dim + 1)
        .zip(coords.chunks_exact(dim))
        .zip(weights)
    {
        for (x, y) in h.iter_mut().zip(b) {
            *x = y.mul(w);
        }
        h[dim] = w.clone();
    }
}

/// The homogeneous points (N_i, w_i) of numerator points `numerator` (`dim` numbers each) and
/// denominator values `denominator`, side by side with no product: the polynomial (N, w) whose
/// projection is the rational map N / w. Both lists hold one entry per point.
pub(crate) fn join<T: Clone>(numerator: &[T], dim: usize, denominator: &[T]) -> Vec<T> {
    debug_assert_eq!(numerator.len(), denominator.len() * dim);
    let mut h = Vec::with_capacity(denominator.len() * (dim + 1));
    for (n, w) in numerator.chunks_exact(dim).zip(denominator) {
        h.extend_from_slice(n);
        h.push(w.clone());
    }
    h
}

/// Writes the central projection N / w of the homogeneous point `h` = (N, w) into `out`
/// (`h.len() - 1` numbers).
///
/// # Errors
/// [`ErrorKind::ZeroWeight`] on `field` when w is zero, with `detail()` as the message;
/// `out` is then untouched.
pub(crate) fn project_into<T: Field>(
    h: &[T],
    out: &mut [T],
    field: &str,
    detail: impl FnOnce() -> String,
) -> Result<()> {
    let (w, n) = h.split_last().expect("D + 1 >= 2 coordinates");
    debug_assert_eq!(out.len(), n.len());
    if w.is_zero() {
        return Err(Error::of(ErrorKind::ZeroWeight, field, detail()));
    }
    for (o, x) in out.iter_mut().zip(n) {
        *o = x.divide(w);
    }
    Ok(())
}

/// The central projection N / w of the homogeneous point `h` = (N, w), computed in `h`'s own
/// buffer (the answer's one allocation is the caller's), or `None` when w is zero.
pub(crate) fn project_point<T: Field>(mut h: Point<T>) -> Option<Point<T>> {
    let w = h.pop().expect("D + 1 >= 2 coordinates");
    if w.is_zero() {
        return None;
    }
    for x in &mut h {
        *x = x.divide(&w);
    }
    Some(h)
}

/// `p / w` coordinate-wise, or `None` when w is zero.
pub(crate) fn divide_point<T: Field>(p: Point<T>, w: &T) -> Option<Point<T>> {
    if w.is_zero() {
        None
    } else {
        Some(p.iter().map(|x| x.divide(w)).collect())
    }
}

/// The index of the first homogeneous point of `h` (`hdim` numbers each) whose weight (last
/// coordinate) is zero.
pub(crate) fn first_zero_weight<T: Ring>(h: &[T], hdim: usize) -> Option<usize> {
    h.chunks_exact(hdim)
        .position(|p| p.last().is_some_and(Ring::is_zero))
}

/// Projects the homogeneous points in `coords` (`hdim` = D + 1 numbers each) in place: on
/// success `coords` holds the points b_i = N_i / w_i (D numbers each) and `weights` the w_i.
/// The projection walks forward and point i is written at or before where it was read, so
/// one buffer serves both. When a weight is zero nothing is changed and the error is
/// `zero_weight(i)` for the first such point i.
pub(crate) fn project_in_place<T: Field>(
    coords: &mut Vec<T>,
    hdim: usize,
    weights: &mut Vec<T>,
    zero_weight: impl FnOnce(usize) -> Error,
) -> Result<()> {
    if let Some(i) = first_zero_weight(coords, hdim) {
        return Err(zero_weight(i));
    }
    let dim = hdim - 1;
    let count = coords.len() / hdim;
    weights.clear();
    for i in 0..count {
        let w = coords[i * hdim + dim].clone();
        for k in 0..dim {
            coords[i * dim + k] = coords[i * hdim + k].divide(&w);
        }
        weights.push(w);
    }
    coords.truncate(count * dim);
    Ok(())
}

/// The restriction of the rational Bézier shape with points `coords` (`dim` numbers each) and
/// weights `weights` into `out_coords` and `out_weights`: `engine` maps the lifted points
/// (w b, w) (its first argument) to the homogeneous points of the restriction (its second, of
/// the same length), which are then projected in place ([`project_in_place`]).
///
/// While the engine runs, `out_weights` holds the lifted input and `out_coords` the engine's
/// output, so nothing is allocated once the output shape's two buffers have grown to
/// (n + 1)(D + 1) numbers. On an error (`zero_weight(i)` for the first vanishing weight of the
/// result), both buffers keep the result's shape with unspecified values.
pub(crate) fn restrict_through_homogeneous<T: Field>(
    coords: &[T],
    weights: &[T],
    dim: usize,
    out_coords: &mut Vec<T>,
    out_weights: &mut Vec<T>,
    engine: impl FnOnce(&[T], &mut [T]),
    zero_weight: impl FnOnce(usize) -> Error,
) -> Result<()> {
    lift_all_into(coords, dim, weights, out_weights);
    out_coords.resize(out_weights.len(), T::zero());
    engine(out_weights, out_coords);
    let result = project_in_place(out_coords, dim + 1, out_weights, zero_weight);
    if result.is_err() {
        out_coords.truncate(weights.len() * dim);
        out_weights.truncate(weights.len());
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    #[test]
    fn projection_in_place_undoes_the_lift() {
        let (coords, weights) = (vec![1.0, 2.0, -3.0, 0.5], vec![2.0, 4.0]);
        let mut h = Vec::new();
        lift_all_into(&coords, 2, &weights, &mut h);
        assert_eq!(h, vec![2.0, 4.0, 2.0, -12.0, 2.0, 4.0]);
        let mut w = Vec::new();
        project_in_place(&mut h, 3, &mut w, |_| unreachable!()).unwrap();
        assert_eq!((h, w), (coords, weights));
    }

    #[test]
    fn a_zero_weight_changes_nothing() {
        let mut h = vec![1.0, 1.0, 5.0, 0.0];
        let mut w = vec![7.0];
        let e = project_in_place(&mut h, 2, &mut w, |i| {
            Error::of(ErrorKind::ZeroWeight, "weights", format!("w_{i}"))
        })
        .unwrap_err();
        assert_eq!(
            (e.message.as_str(), h, w),
            ("w_1", vec![1.0, 1.0, 5.0, 0.0], vec![7.0])
        );
    }
}
