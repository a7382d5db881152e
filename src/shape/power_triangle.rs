//! A polynomial surface of a given total degree in the power basis:
//! S(u, v) = sum_{i + j <= N} c_ij u^i v^j, the natural input of a triangular patch.
//!
//! The subdivision paper states Theorem 3 for a rectangular grid (i <= n, j <= m) at total
//! degree N = n + m. Its eq. (13) and (14) hold for any set of coefficients with i + j <= N,
//! because every term of (14) involves one coefficient c_ij and the degree N only; a grid is
//! the special case whose rows all have m + 1 entries. [`PowerTriangle`] holds either: row i has
//! at most N + 1 - i coefficients, and absent ones are zero. Every triangle restriction of the
//! library (all of [`crate::Method`]) runs on this one type.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::{triangle_points, wrong_count};
use crate::shape::point::{check_flat, Point, Points};
use crate::shape::power::{check_dims, nested_horner, PowerSurface};
use crate::Ring;

/// S(u, v) = sum c_ij u^i v^j with i + j <= N, as a surface of total degree N, its coefficients
/// in one buffer, row after row (c_i0, ..., c_i(k_i - 1) for row i, `D` coordinates each).
///
/// `row(i)[j]` is c_ij; row i has between 1 and N + 1 - i entries (a triangular array from
/// [`PowerTriangle::new`] or [`PowerTriangle::from_coordinates`] has exactly N + 1 - i; a grid
/// from [`PowerTriangle::from_surface`] has m + 1), and a coefficient beyond a row's end is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct PowerTriangle<T> {
    degree: usize,
    dim: usize,
    /// Row i is the points `starts[i]..starts[i + 1]` of `coords` (`starts[0]` = 0, one entry
    /// more than there are rows).
    starts: Vec<usize>,
    coords: Vec<T>,
}

impl<T: Ring> PowerTriangle<T> {
    /// The surface of total degree N from its triangular array: `rows.len()` = N + 1, and row i
    /// holds the N + 1 - i points c_i0, ..., c_i(N-i), all of one dimension D >= 1 (copied once
    /// into the surface's buffer).
    ///
    /// ```
    /// use blossom::PowerTriangle;
    /// // u + v at total degree 1: rows [c_00, c_01], [c_10].
    /// let s = PowerTriangle::new(vec![vec![vec![0.0], vec![1.0]], vec![vec![1.0]]])?;
    /// assert_eq!((s.degree(), s.eval(&2.0, &3.0)), (1, vec![5.0]));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `coefficients` when there is no row, `coefficients[i]` when row i does not hold
    /// N + 1 - i points, `coefficients[i][j]` when a point has no coordinate or another
    /// dimension than the first.
    pub fn new(rows: Vec<Vec<Point<T>>>) -> Result<Self> {
        if rows.is_empty() {
            return Err(Error::of(
                ErrorKind::Empty,
                "coefficients",
                "expected at least one row",
            ));
        }
        let big_n = rows.len() - 1;
        for (i, row) in rows.iter().enumerate() {
            if row.len() != big_n + 1 - i {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("coefficients[{i}]"),
                    format!(
                        "expected {} points (row i of a triangular array of total degree {big_n} \
                         holds N + 1 - i), found {}",
                        big_n + 1 - i,
                        row.len()
                    ),
                ));
            }
        }
        let dim = rows[0][0].len();
        if dim == 0 {
            return Err(Error::of(
                ErrorKind::Dimension,
                "coefficients[0][0]",
                "expected at least 1 coordinate",
            ));
        }
        for (i, row) in rows.iter().enumerate() {
            check_dims(row, dim, &format!("coefficients[{i}]"))?;
        }
        let coords = rows.iter().flatten().flatten().cloned().collect();
        Ok(Self::triangular(big_n, dim, coords))
    }

    /// The surface of total degree `degree` from the coordinates of its full triangular array,
    /// `dim` each, row after row: c_00, ..., c_0N, c_10, ..., c_N0 (c_ij at
    /// [`triangle_index(N, i, j)`](crate::engine::triangle_index), the order of a
    /// [`crate::TriangularPatch`]'s points).
    ///
    /// ```
    /// use blossom::PowerTriangle;
    /// // u + v at total degree 1: c_00 = 0, c_01 = 1, c_10 = 1.
    /// let s = PowerTriangle::from_coordinates(1, 1, vec![0.0, 1.0, 1.0])?;
    /// assert_eq!(s.eval(&2.0, &3.0), vec![5.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `dim` when it is 0, `coordinates` when it does not hold (N + 1)(N + 2) / 2 points,
    /// `degree` when that count overflows or exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    pub fn from_coordinates(degree: usize, dim: usize, coordinates: Vec<T>) -> Result<Self> {
        let want = triangle_points(degree, "degree")?;
        let points = check_flat(&coordinates, dim, "coordinates")?;
        if points != want {
            return Err(wrong_count(
                "coordinates",
                format!("a triangular array of total degree {degree} has {want} points"),
                points,
            ));
        }
        Ok(Self::triangular(degree, dim, coordinates))
    }

    /// The full triangular array of total degree `degree` with `coords` as they are
    /// ((N + 1)(N + 2) / 2 points of `dim >= 1`: the caller's guarantee).
    pub(crate) fn triangular(degree: usize, dim: usize, coords: Vec<T>) -> Self {
        let starts = std::iter::once(0)
            .chain((0..=degree).scan(0, |end, i| {
                *end += degree + 1 - i;
                Some(*end)
            }))
            .collect();
        PowerTriangle {
            degree,
            dim,
            starts,
            coords,
        }
    }

    /// The grid of `surface` as a surface of total degree n + m (the paper's convention).
    pub fn from_surface(surface: &PowerSurface<T>) -> Self {
        let (n, m) = surface.degree();
        PowerTriangle {
            degree: n + m,
            dim: surface.dim(),
            starts: (0..=n + 1).map(|i| i * (m + 1)).collect(),
            coords: surface.coordinates().to_vec(),
        }
    }

    /// The same polynomial taken at total degree `degree`, which must be at least
    /// [`PowerTriangle::true_degree`] (the highest i + j of a non-zero coefficient): a higher
    /// degree elevates, a lower one drops only zero coefficients.
    pub fn at_degree(&self, degree: usize) -> Result<Self> {
        let least = self.true_degree();
        if degree < least {
            return Err(Error::of(
                ErrorKind::Degree,
                "degree",
                format!(
                    "the surface has a non-zero term of total degree {least}, so it has no form of \
                     total degree {degree}"
                ),
            ));
        }
        let mut starts = vec![0];
        let mut coords = Vec::with_capacity(self.coords.len());
        for (i, row) in self.rows().take(degree + 1).enumerate() {
            let keep = row.len().min(degree + 1 - i);
            coords.extend_from_slice(&row.coordinates()[..keep * self.dim]);
            starts.push(starts[i] + keep);
        }
        Ok(PowerTriangle {
            degree,
            dim: self.dim,
            starts,
            coords,
        })
    }

    /// The total degree N the surface is taken at.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The true total degree: the highest i + j with c_ij != 0 (0 for the zero surface), the
    /// lowest total degree at which the surface is exactly a triangular patch.
    pub fn true_degree(&self) -> usize {
        self.terms()
            .filter(|(_, _, c)| c.iter().any(|x| !x.is_zero()))
            .map(|(i, j, _)| i + j)
            .max()
            .unwrap_or(0)
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Row i of coefficients, c_i0, c_i1, ... (it may be shorter than N + 1 - i).
    ///
    /// # Panics
    /// When there is no row i (see [`PowerTriangle::rows`]).
    pub fn row(&self, i: usize) -> Points<'_, T> {
        let (start, end) = (self.starts[i], self.starts[i + 1]);
        Points::new(&self.coords[start * self.dim..end * self.dim], self.dim)
    }

    /// The rows of coefficients, `[i][j]` = c_ij (rows may be shorter than N + 1 - i, and there
    /// may be fewer than N + 1 rows).
    pub fn rows(&self) -> impl ExactSizeIterator<Item = Points<'_, T>> + DoubleEndedIterator + '_ {
        self.starts
            .windows(2)
            .map(|w| Points::new(&self.coords[w[0] * self.dim..w[1] * self.dim], self.dim))
    }

    /// Whether the rows are the full triangular array: N + 1 rows, row i of N + 1 - i points.
    pub fn is_triangular(&self) -> bool {
        self.starts.len() == self.degree + 2
            && self
                .starts
                .windows(2)
                .enumerate()
                .all(|(i, w)| w[1] - w[0] == self.degree + 1 - i)
    }

    /// Every stored coefficient with its indices: (i, j, c_ij).
    pub fn terms(&self) -> impl Iterator<Item = (usize, usize, &[T])> {
        self.rows()
            .enumerate()
            .flat_map(|(i, row)| row.iter().enumerate().map(move |(j, c)| (i, j, c)))
    }

    /// Every stored coordinate, row after row, coefficient after coefficient.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// The rows as nested vectors, `[i][j]` = c_ij (one allocation per point).
    pub fn to_nested(&self) -> Vec<Vec<Point<T>>> {
        self.rows().map(|r| r.to_vec()).collect()
    }

    /// The rows padded with zeros to one length, a rectangular grid holding the same polynomial
    /// (for algorithms that work on grids).
    pub fn padded_grid(&self) -> PowerSurface<T> {
        let width = self.rows().map(|r| r.len()).max().unwrap_or(1);
        let row_len = width * self.dim;
        let mut coords = vec![T::zero(); (self.starts.len() - 1) * row_len];
        for (out, row) in coords.chunks_exact_mut(row_len).zip(self.rows()) {
            out[..row.coordinates().len()].clone_from_slice(row.coordinates());
        }
        PowerSurface::from_raw(width, self.dim, coords)
    }

    /// S(u, v) by nested Horner's rule.
    pub fn eval(&self, u: &T, v: &T) -> Point<T> {
        nested_horner(self.rows().map(|r| r.iter()), self.dim, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pt(x: i64) -> Point<f64> {
        vec![x as f64]
    }

    #[test]
    fn shapes_are_checked_row_by_row() {
        let e = PowerTriangle::new(vec![vec![pt(1), pt(2)], vec![pt(3), pt(4)]]).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("coefficients[1]", ErrorKind::Shape));
        let e = PowerTriangle::<f64>::new(vec![]).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Empty);
        let e = PowerTriangle::new(vec![vec![pt(1), vec![1.0, 2.0]], vec![pt(3)]]).unwrap_err();
        assert_eq!(
            (e.path(), e.kind()),
            ("coefficients[0][1]", ErrorKind::Dimension)
        );
    }

    #[test]
    fn true_degree_ignores_zero_terms() {
        // 1 + u v^0 ... : c_00 = 1, c_10 = 0, c_01 = 2, c_20 = 0, c_11 = 0, c_02 = 0.
        let s = PowerTriangle::new(vec![
            vec![pt(1), pt(2), pt(0)],
            vec![pt(0), pt(0)],
            vec![pt(0)],
        ])
        .unwrap();
        assert_eq!((s.degree(), s.true_degree()), (2, 1));
        let low = s.at_degree(1).unwrap();
        assert_eq!(
            (low.degree(), low.eval(&3.0, &5.0)),
            (1, s.eval(&3.0, &5.0))
        );
        assert_eq!(s.at_degree(0).unwrap_err().kind(), ErrorKind::Degree);
        let grid = PowerSurface::new(vec![vec![pt(0), pt(1)], vec![pt(1), pt(0)]]).unwrap();
        let t = PowerTriangle::from_surface(&grid);
        assert_eq!((t.degree(), t.true_degree()), (2, 1));
        assert_eq!(t.padded_grid(), grid);
    }

    #[test]
    fn flat_and_nested_constructors_agree() {
        let nested = PowerTriangle::new(vec![
            vec![pt(1), pt(2), pt(3)],
            vec![pt(4), pt(5)],
            vec![pt(6)],
        ])
        .unwrap();
        let flat =
            PowerTriangle::from_coordinates(2, 1, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
        assert_eq!(flat, nested);
        assert!(flat.is_triangular());
        assert_eq!(flat.row(1), vec![pt(4), pt(5)]);
        assert_eq!(flat.to_nested()[2], vec![pt(6)]);
        let e = PowerTriangle::from_coordinates(2, 1, vec![1.0; 5]).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("coordinates", ErrorKind::Shape));
        let e = PowerTriangle::from_coordinates(2, 0, vec![1.0; 6]).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("dim", ErrorKind::Dimension));
        // The padded grid holds the same polynomial.
        let grid = flat.padded_grid();
        assert_eq!(grid.degree(), (2, 2));
        assert_eq!(grid.get(2, 2), &[0.0][..]);
        assert_eq!(grid.eval(&3.0, &-2.0), flat.eval(&3.0, &-2.0));
        let low = flat.at_degree(4).unwrap();
        assert!(!low.is_triangular());
        assert_eq!(low.eval(&3.0, &-2.0), flat.eval(&3.0, &-2.0));
    }
}
