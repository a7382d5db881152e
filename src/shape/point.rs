//! Points of any dimension as plain vectors of ring elements, and the few affine operations the
//! algorithms need on them.

use crate::error::{Error, ErrorKind, Result};
use crate::Ring;

/// A point (or vector) with `D >= 1` coordinates.
pub type Point<T> = Vec<T>;

/// The zero vector of dimension `dim`.
pub fn zero<T: Ring>(dim: usize) -> Point<T> {
    vec![T::zero(); dim]
}

/// `acc += k * p`, coordinate-wise, for a ring element `k`.
pub fn add_scaled<T: Ring>(acc: &mut [T], k: &T, p: &[T]) {
    for (x, y) in acc.iter_mut().zip(p) {
        x.add_assign(&k.mul(y));
    }
}

/// `acc += r * p`, coordinate-wise, for an exact rational constant `r`.
pub fn add_scaled_rational<T: Ring>(acc: &mut [T], r: &crate::Rational, p: &[T]) {
    for (x, y) in acc.iter_mut().zip(p) {
        x.add_assign(&y.scale(r));
    }
}

/// `acc += p`, coordinate-wise.
pub fn add_assign<T: Ring>(acc: &mut [T], p: &[T]) {
    for (x, y) in acc.iter_mut().zip(p) {
        x.add_assign(y);
    }
}

/// The affine combination `(1 - t) p + t q`, computed as `p + t (q - p)`.
pub fn lerp<T: Ring>(p: &[T], q: &[T], t: &T) -> Point<T> {
    p.iter()
        .zip(q)
        .map(|(x, y)| x.add(&t.mul(&y.sub(x))))
        .collect()
}

/// `k * p`, coordinate-wise, for an exact rational constant `k`.
pub fn scaled_rational<T: Ring>(p: &[T], k: &crate::Rational) -> Point<T> {
    p.iter().map(|x| x.scale(k)).collect()
}

/// Splits flat coordinates `flat` back into points of `dim` coordinates.
pub(crate) fn points_of<T: Clone>(flat: &[T], dim: usize) -> Vec<Point<T>> {
    flat.chunks(dim).map(<[T]>::to_vec).collect()
}

/// Splits each point of `rows` into concatenated coordinates: rows of a grid become long
/// points, so that a pass along one variable treats a whole row as one point.
pub(crate) fn flatten<T: Clone>(rows: &[Vec<Point<T>>]) -> Vec<Point<T>> {
    rows.iter().map(|row| row.concat()).collect()
}

pub(crate) fn unflatten<T: Clone>(long: Vec<Point<T>>, dim: usize) -> Vec<Vec<Point<T>>> {
    long.into_iter()
        .map(|p| p.chunks(dim).map(<[T]>::to_vec).collect())
        .collect()
}

/// Checks that every point of `points` has `dim` coordinates, naming the first that does not.
pub(crate) fn check_dims<T>(points: &[Point<T>], dim: usize, field: &str) -> Result<()> {
    for (i, p) in points.iter().enumerate() {
        if p.len() != dim {
            return Err(Error::of(
                ErrorKind::Dimension,
                format!("{field}[{i}]"),
                format!("expected {dim} coordinates, found {}", p.len()),
            ));
        }
    }
    Ok(())
}
