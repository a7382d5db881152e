//! Polynomial curves and surfaces in the power (monomial) basis, the input of the subdivision
//! paper: C(u) = sum_i c_i u^i and S(u, v) = sum_ij c_ij u^i v^j, with points of any dimension.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::point::{self, Point, Points};
use crate::Ring;

pub(crate) use crate::shape::point::check_dims;

/// A polynomial curve C(u) = sum_{i=0..n} c_i u^i of degree `n` (the paper's problem (1)), its
/// coefficients in one buffer (`D` coordinates each, c_0 first).
///
/// The degree is the number of coefficients minus one, even when the leading ones are zero:
/// the paper's convention, under which the Bézier form of degree `n` is asked for.
#[derive(Clone, PartialEq)]
pub struct PowerCurve<T> {
    dim: usize,
    coords: Vec<T>,
}

/// The coefficients, each as a list of its coordinates:
/// `PowerCurve { coefficients: [[1.0, 0.0], [0.0, 2.0]] }`.
impl<T: std::fmt::Debug> std::fmt::Debug for PowerCurve<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PowerCurve")
            .field("coefficients", &Points::new(&self.coords, self.dim))
            .finish()
    }
}

impl<T: Ring> PowerCurve<T> {
    /// A curve from its coefficients `c_0, ..., c_n`, all of one dimension `D >= 1` (copied
    /// once into the curve's buffer).
    ///
    /// # Errors
    /// `coefficients` when it is empty, `coefficients[i]` when coefficient i has no coordinate
    /// or another dimension than the first.
    pub fn new(coefficients: Vec<Point<T>>) -> Result<Self> {
        let (dim, coords) = point::flatten_points(&coefficients, "coefficients")?;
        Ok(PowerCurve { dim, coords })
    }

    /// A curve from the coordinates of its coefficients, c_0 first, `dim` each.
    ///
    /// # Errors
    /// `dim` when it is 0, `coordinates` when it is empty or not a whole number of points.
    pub fn from_coordinates(dim: usize, coordinates: Vec<T>) -> Result<Self> {
        point::check_flat(&coordinates, dim, "coordinates")?;
        Ok(PowerCurve {
            dim,
            coords: coordinates,
        })
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.coords.len() / self.dim - 1
    }

    /// The dimension `D` of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The coefficients `c_0, ..., c_n`, each a `&[T]`.
    pub fn coefficients(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// Every coordinate, c_0 first.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// C(u) by Horner's rule.
    pub fn eval(&self, u: &T) -> Point<T> {
        let mut points = self.coords.chunks_exact(self.dim).rev();
        let mut acc = points.next().expect("at least one coefficient").to_vec();
        for c in points {
            for (x, ci) in acc.iter_mut().zip(c) {
                *x = x.mul(u).add(ci);
            }
        }
        acc
    }
}

/// sum_i u^i sum_j v^j rows[i][j] (rows of any lengths) by nested Horner's rule; `rows`
/// yields the rows in order, each yielding its points as `&[T]`.
pub(crate) fn nested_horner<'a, T: Ring + 'a, R>(
    rows: impl DoubleEndedIterator<Item = R>,
    dim: usize,
    u: &T,
    v: &T,
) -> Point<T>
where
    R: DoubleEndedIterator<Item = &'a [T]>,
{
    let mut acc: Point<T> = point::zero(dim);
    let mut inner: Point<T> = point::zero(dim);
    for row in rows.rev() {
        inner.iter_mut().for_each(|x| *x = T::zero());
        for c in row.rev() {
            for (x, cj) in inner.iter_mut().zip(c) {
                *x = x.mul(v).add(cj);
            }
        }
        for (x, y) in acc.iter_mut().zip(&inner) {
            *x = x.mul(u).add(y);
        }
    }
    acc
}

/// A polynomial surface S(u, v) = sum_{i=0..n} sum_{j=0..m} c_ij u^i v^j of bidegree (n, m)
/// (the paper's problems (2) and (3); as a triangular patch its total degree is N = n + m), its
/// coefficients in one buffer, row by row (c_ij at position i (m + 1) + j).
#[derive(Clone, Debug, PartialEq)]
pub struct PowerSurface<T> {
    cols: usize,
    dim: usize,
    coords: Vec<T>,
}

impl<T: Ring> PowerSurface<T> {
    /// A surface from its coefficient grid: `coefficients[i][j]` is `c_ij`, `n + 1` rows of
    /// `m + 1` points each, all of one dimension `D >= 1`.
    pub fn new(coefficients: Vec<Vec<Point<T>>>) -> Result<Self> {
        let Some(first_row) = coefficients.first() else {
            return Err(Error::of(
                ErrorKind::Empty,
                "coefficients",
                "expected at least one row",
            ));
        };
        let cols = first_row.len();
        if cols == 0 {
            return Err(Error::of(
                ErrorKind::Empty,
                "coefficients[0]",
                "expected at least one point",
            ));
        }
        let dim = first_row[0].len();
        if dim == 0 {
            return Err(Error::of(
                ErrorKind::Dimension,
                "coefficients[0][0]",
                "expected at least 1 coordinate",
            ));
        }
        for (i, row) in coefficients.iter().enumerate() {
            if row.len() != cols {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("coefficients[{i}]"),
                    format!(
                        "expected {cols} points (the grid must be rectangular), found {}",
                        row.len()
                    ),
                ));
            }
            check_dims(row, dim, &format!("coefficients[{i}]"))?;
        }
        let coords = coefficients.iter().flatten().flatten().cloned().collect();
        Ok(PowerSurface { cols, dim, coords })
    }

    /// The surface with `coords` as they are (rows of `cols >= 1` points of `dim >= 1`: the
    /// caller's guarantee).
    pub(crate) fn from_raw(cols: usize, dim: usize, coords: Vec<T>) -> Self {
        debug_assert!(cols >= 1 && dim >= 1 && !coords.is_empty());
        debug_assert!(coords.len().is_multiple_of(cols * dim));
        PowerSurface { cols, dim, coords }
    }

    /// The bidegree `(n, m)`.
    pub fn degree(&self) -> (usize, usize) {
        (
            self.coords.len() / (self.cols * self.dim) - 1,
            self.cols - 1,
        )
    }

    /// The dimension `D` of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The coefficient grid by rows: `coefficients()[i][j]` is `c_ij` (a `&[T]`). This collects
    /// the row views into a vector; [`PowerSurface::rows`] walks them with no allocation.
    pub fn coefficients(&self) -> Vec<Points<'_, T>> {
        self.rows().collect()
    }

    /// The rows of the coefficient grid, i = 0..=n: row i is the view of c_i0, ..., c_im, each
    /// a `&[T]`. No allocation.
    ///
    /// ```
    /// use blossom::PowerSurface;
    /// // 1 + 2v + 3u + 4uv.
    /// let s = PowerSurface::new(vec![vec![vec![1.0], vec![2.0]], vec![vec![3.0], vec![4.0]]])?;
    /// let sums: Vec<f64> = s.rows().map(|row| row.iter().map(|c| c[0]).sum()).collect();
    /// assert_eq!((sums, s.row(1)[0][0]), (vec![3.0, 7.0], 3.0));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn rows(&self) -> impl ExactSizeIterator<Item = Points<'_, T>> + '_ {
        Points::grid_rows(&self.coords, self.cols, self.dim)
    }

    /// Row i of the coefficient grid: c_i0, ..., c_im.
    ///
    /// # Panics
    /// When i > n.
    pub fn row(&self, i: usize) -> Points<'_, T> {
        Points::grid_row(&self.coords, self.cols, self.dim, i)
    }

    /// The coefficient `c_ij`.
    ///
    /// # Panics
    /// When i > n or j > m.
    pub fn get(&self, i: usize, j: usize) -> &[T] {
        let (n, m) = self.degree();
        assert!(
            i <= n && j <= m,
            "coefficient ({i}, {j}) of bidegree ({n}, {m})"
        );
        let start = (i * self.cols + j) * self.dim;
        &self.coords[start..start + self.dim]
    }

    /// Every coordinate, row by row, coefficient after coefficient.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// The coefficient grid as nested vectors, `[i][j]` = `c_ij`.
    pub fn to_nested(&self) -> Vec<Vec<Point<T>>> {
        self.rows().map(|row| row.to_vec()).collect()
    }

    /// S(u, v) by nested Horner's rule.
    pub fn eval(&self, u: &T, v: &T) -> Point<T> {
        let rows = self.coords.chunks_exact(self.cols * self.dim);
        nested_horner(rows.map(|r| r.chunks_exact(self.dim)), self.dim, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horner_matches_monomial_sum() {
        let c = PowerCurve::new(vec![vec![1.0, 0.0], vec![2.0, 1.0], vec![3.0, -1.0]]).unwrap();
        assert_eq!(c.eval(&2.0), vec![1.0 + 4.0 + 12.0, 2.0 - 4.0]);
        let s = PowerSurface::new(vec![vec![vec![1.0], vec![2.0]], vec![vec![3.0], vec![4.0]]])
            .unwrap();
        // 1 + 2v + 3u + 4uv at (2, 5)
        assert_eq!(s.eval(&2.0, &5.0), vec![1.0 + 10.0 + 6.0 + 40.0]);
    }

    #[test]
    fn bad_shapes_name_the_field() {
        assert_eq!(
            PowerCurve::<f64>::new(vec![]).unwrap_err().field,
            "coefficients"
        );
        let e = PowerCurve::new(vec![vec![1.0, 2.0], vec![1.0]]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "coefficients[1]: expected 2 coordinates, found 1"
        );
        let e = PowerSurface::new(vec![vec![vec![1.0], vec![2.0]], vec![vec![3.0]]]).unwrap_err();
        assert_eq!(e.field, "coefficients[1]");
        let e = PowerSurface::new(vec![vec![vec![1.0], vec![2.0, 3.0]]]).unwrap_err();
        assert_eq!(e.field, "coefficients[0][1]");
    }

    #[test]
    fn bad_shapes_have_a_matchable_kind() {
        use crate::error::ErrorKind;
        let kind = |r: Result<PowerCurve<f64>>| r.unwrap_err().kind();
        assert_eq!(kind(PowerCurve::new(vec![])), ErrorKind::Empty);
        assert_eq!(kind(PowerCurve::new(vec![vec![]])), ErrorKind::Dimension);
        assert_eq!(
            kind(PowerCurve::new(vec![vec![1.0, 2.0], vec![1.0]])),
            ErrorKind::Dimension
        );
        let e = PowerSurface::new(vec![vec![vec![1.0], vec![2.0]], vec![vec![3.0]]]).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("coefficients[1]", ErrorKind::Shape));
    }
}
