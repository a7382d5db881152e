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
use crate::shape::point::{self, Point};
use crate::shape::power::{check_dims, nested_horner, PowerSurface};
use crate::Ring;

/// S(u, v) = sum c_ij u^i v^j with i + j <= N, as a surface of total degree N.
///
/// `rows()[i][j]` is c_ij; row i has between 1 and N + 1 - i entries (a triangular array from
/// [`PowerTriangle::new`] has exactly N + 1 - i; a grid from [`PowerTriangle::from_surface`]
/// has m + 1), and a coefficient beyond a row's end is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct PowerTriangle<T> {
    degree: usize,
    rows: Vec<Vec<Point<T>>>,
}

impl<T: Ring> PowerTriangle<T> {
    /// The surface of total degree N from its triangular array: `rows.len()` = N + 1, and row i
    /// holds the N + 1 - i points c_i0, ..., c_i(N-i), all of one dimension D >= 1.
    ///
    /// ```
    /// use blossom::PowerTriangle;
    /// // u + v at total degree 1: rows [c_00, c_01], [c_10].
    /// let s = PowerTriangle::new(vec![vec![vec![0.0], vec![1.0]], vec![vec![1.0]]])?;
    /// assert_eq!((s.degree(), s.eval(&2.0, &3.0)), (1, vec![5.0]));
    /// # Ok::<(), blossom::Error>(())
    /// ```
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
        Ok(PowerTriangle {
            degree: big_n,
            rows,
        })
    }

    /// The grid of `surface` as a surface of total degree n + m (the paper's convention).
    pub fn from_surface(surface: &PowerSurface<T>) -> Self {
        let (n, m) = surface.degree();
        PowerTriangle {
            degree: n + m,
            rows: surface.to_nested(),
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
        let rows = self
            .rows
            .iter()
            .take(degree + 1)
            .enumerate()
            .map(|(i, row)| row.iter().take(degree + 1 - i).cloned().collect())
            .collect();
        Ok(PowerTriangle { degree, rows })
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
        self.rows[0][0].len()
    }

    /// The rows of coefficients, `[i][j]` = c_ij (rows may be shorter than N + 1 - i).
    pub fn rows(&self) -> &[Vec<Point<T>>] {
        &self.rows
    }

    /// Every stored coefficient with its indices: (i, j, c_ij).
    pub fn terms(&self) -> impl Iterator<Item = (usize, usize, &Point<T>)> {
        self.rows
            .iter()
            .enumerate()
            .flat_map(|(i, row)| row.iter().enumerate().map(move |(j, c)| (i, j, c)))
    }

    /// The rows padded with zeros to one length, a rectangular grid holding the same polynomial
    /// (for algorithms that work on grids).
    pub fn padded_grid(&self) -> Vec<Vec<Point<T>>> {
        let width = self.rows.iter().map(Vec::len).max().unwrap_or(1);
        let zero = point::zero::<T>(self.dim());
        self.rows
            .iter()
            .map(|row| {
                let mut r = row.clone();
                r.resize(width, zero.clone());
                r
            })
            .collect()
    }

    /// S(u, v) by nested Horner's rule.
    pub fn eval(&self, u: &T, v: &T) -> Point<T> {
        let rows = self.rows.iter().map(|r| r.iter().map(Vec::as_slice));
        nested_horner(rows, self.dim(), u, v)
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
        assert_eq!(t.padded_grid(), grid.coefficients());
    }
}
