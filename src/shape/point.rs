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

/// `k * p`, coordinate-wise, for an exact rational constant `k`.
pub fn scaled_rational<T: Ring>(p: &[T], k: &crate::Rational) -> Point<T> {
    p.iter().map(|x| x.scale(k)).collect()
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

/// A run of points stored flat, `dim` coordinates each: the read-only view that every shape
/// hands out of its one buffer. Point `i` is the slice `coordinates()[i * dim..(i + 1) * dim]`.
///
/// It indexes like a slice of points (`points[i]` is a `&[T]`), iterates over `&[T]`, and
/// compares equal to nested vectors with the same points, so code written against `&[Vec<T>]`
/// mostly reads the same.
///
/// ```
/// use blossom::BezierCurve;
/// let c = BezierCurve::from_coordinates(2, vec![0.0, 0.0, 1.0, 2.0, 4.0, 0.0])?;
/// let points = c.control_points();
/// assert_eq!((points.len(), &points[1]), (3, &[1.0, 2.0][..]));
/// assert_eq!(points, vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![4.0, 0.0]]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// `{:?}` shows the points, each as a list of its coordinates (`[[0.0, 0.0], [1.0, 2.0]]`),
/// not the flat storage behind them.
#[derive(Clone, Copy)]
pub struct Points<'a, T> {
    coords: &'a [T],
    dim: usize,
}

impl<'a, T> Points<'a, T> {
    /// The view of `coords` as points of `dim >= 1` coordinates (`coords.len()` a multiple of
    /// `dim`; the library's shapes guarantee both).
    pub(crate) fn new(coords: &'a [T], dim: usize) -> Self {
        debug_assert!(dim >= 1 && coords.len().is_multiple_of(dim));
        Points { coords, dim }
    }

    /// Row `i` of the row-major grid `coords` of `cols` points a row (the flat storage of
    /// tensor patches, power surfaces and B-spline surfaces). Panics when there is no row `i`.
    pub(crate) fn grid_row(coords: &'a [T], cols: usize, dim: usize, i: usize) -> Self {
        let width = cols * dim;
        Points::new(&coords[i * width..(i + 1) * width], dim)
    }

    /// The rows of the row-major grid `coords` of `cols` points a row, in order.
    pub(crate) fn grid_rows(
        coords: &'a [T],
        cols: usize,
        dim: usize,
    ) -> impl ExactSizeIterator<Item = Self> + 'a {
        coords
            .chunks_exact(cols * dim)
            .map(move |row| Points::new(row, dim))
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.coords.len() / self.dim
    }

    /// Whether there is no point (never for a shape's points).
    pub fn is_empty(&self) -> bool {
        self.coords.is_empty()
    }

    /// The number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Every coordinate, point after point.
    pub fn coordinates(&self) -> &'a [T] {
        self.coords
    }

    /// Point `i`, or `None` past the end.
    #[inline]
    pub fn get(&self, i: usize) -> Option<&'a [T]> {
        let start = i.checked_mul(self.dim)?;
        self.coords.get(start..start.checked_add(self.dim)?)
    }

    /// The first point.
    pub fn first(&self) -> Option<&'a [T]> {
        self.get(0)
    }

    /// The last point.
    pub fn last(&self) -> Option<&'a [T]> {
        self.len().checked_sub(1).and_then(|i| self.get(i))
    }

    /// The points in order, each a slice of `dim` coordinates.
    pub fn iter(&self) -> std::slice::ChunksExact<'a, T> {
        self.coords.chunks_exact(self.dim)
    }

    /// The points from `range`, as a view.
    pub fn slice(&self, range: std::ops::Range<usize>) -> Points<'a, T> {
        Points::new(
            &self.coords[range.start * self.dim..range.end * self.dim],
            self.dim,
        )
    }

    /// Every coordinate copied into one vector, point after point (as `[Vec<T>]::concat`).
    pub fn concat(&self) -> Vec<T>
    where
        T: Clone,
    {
        self.coords.to_vec()
    }

    /// The points copied into nested vectors (one allocation per point).
    pub fn to_vec(&self) -> Vec<Point<T>>
    where
        T: Clone,
    {
        self.iter().map(<[T]>::to_vec).collect()
    }
}

impl<T: std::fmt::Debug> std::fmt::Debug for Points<'_, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<T> std::ops::Index<usize> for Points<'_, T> {
    type Output = [T];

    /// Point `i`.
    ///
    /// # Panics
    /// When `i >= len()`, as slice indexing does.
    #[inline]
    fn index(&self, i: usize) -> &[T] {
        // The count (a division) is computed only for the panic message: on the hot path the
        // bounds check is the slice's own.
        match self.get(i) {
            Some(point) => point,
            None => panic!("point index {i} out of range for {} points", self.len()),
        }
    }
}

impl<'a, T> IntoIterator for Points<'a, T> {
    type Item = &'a [T];
    type IntoIter = std::slice::ChunksExact<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a, T> IntoIterator for &Points<'a, T> {
    type Item = &'a [T];
    type IntoIter = std::slice::ChunksExact<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<T: PartialEq> PartialEq for Points<'_, T> {
    fn eq(&self, other: &Self) -> bool {
        self.dim == other.dim && self.coords == other.coords
    }
}

impl<T: PartialEq> PartialEq<[Point<T>]> for Points<'_, T> {
    fn eq(&self, other: &[Point<T>]) -> bool {
        self.len() == other.len() && self.iter().zip(other).all(|(p, q)| p == &q[..])
    }
}

impl<T: PartialEq> PartialEq<Vec<Point<T>>> for Points<'_, T> {
    fn eq(&self, other: &Vec<Point<T>>) -> bool {
        *self == other[..]
    }
}

impl<T: PartialEq, const N: usize> PartialEq<[Point<T>; N]> for Points<'_, T> {
    fn eq(&self, other: &[Point<T>; N]) -> bool {
        *self == other[..]
    }
}

impl<T: PartialEq, const N: usize> PartialEq<&[Point<T>; N]> for Points<'_, T> {
    fn eq(&self, other: &&[Point<T>; N]) -> bool {
        *self == other[..]
    }
}

impl<T: PartialEq> PartialEq<&[Point<T>]> for Points<'_, T> {
    fn eq(&self, other: &&[Point<T>]) -> bool {
        *self == **other
    }
}

/// Copies nested points into one flat buffer after checking them: at least one point, all of
/// one dimension `D >= 1` (about `field`). Returns the dimension and the coordinates.
pub(crate) fn flatten_points<T: Clone>(
    points: &[Point<T>],
    field: &str,
) -> Result<(usize, Vec<T>)> {
    let Some(first) = points.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            field,
            "expected at least one point",
        ));
    };
    if first.is_empty() {
        return Err(Error::of(
            ErrorKind::Dimension,
            format!("{field}[0]"),
            "expected at least 1 coordinate",
        ));
    }
    check_dims(points, first.len(), field)?;
    Ok((first.len(), points.concat()))
}

/// Checks flat coordinates (about `field`): `dim >= 1` and a whole number of at least one point.
/// Returns the number of points.
pub(crate) fn check_flat<T>(coords: &[T], dim: usize, field: &str) -> Result<usize> {
    if dim == 0 {
        return Err(Error::of(
            ErrorKind::Dimension,
            "dim",
            "points need at least 1 coordinate",
        ));
    }
    if coords.is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            field,
            "expected at least one point",
        ));
    }
    if !coords.len().is_multiple_of(dim) {
        return Err(Error::of(
            ErrorKind::Shape,
            field,
            format!(
                "{} coordinates are not a whole number of points of dimension {dim}",
                coords.len()
            ),
        ));
    }
    Ok(coords.len() / dim)
}

impl<T: PartialEq> PartialEq<Points<'_, T>> for Vec<Point<T>> {
    fn eq(&self, other: &Points<'_, T>) -> bool {
        *other == self[..]
    }
}

impl<T: PartialEq> PartialEq<Points<'_, T>> for &[Point<T>] {
    fn eq(&self, other: &Points<'_, T>) -> bool {
        *other == **self
    }
}
