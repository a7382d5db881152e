//! Bézier objects, the output of restriction: a curve over [0, 1], a tensor-product patch over
//! [0, 1]^2 and a triangular patch over its own triangle in barycentric coordinates.
//!
//! Each is evaluated by de Casteljau's algorithm, its own blossom with all arguments equal
//! (seed 004, section 2):
//!
//! * curve, eq. (2) of 004: b^r_i[t_1..t_r] = (1 - t_r) b^{r-1}_i + t_r b^{r-1}_{i+1}, and the
//!   blossom is b^n_0[t_1..t_n];
//! * tensor patch, eq. (9) of 004: `b[u_1..u_n; v_1..v_m] = b[u_1..u_n][v_1..v_m]`, the curve
//!   algorithm along v for every row, then along u;
//! * triangle: b^r_{ijk} = u_r b^{r-1}_{i+1,j,k} + v_r b^{r-1}_{i,j+1,k} + w_r b^{r-1}_{i,j,k+1}
//!   for barycentric arguments (u_r, v_r, w_r).

use crate::engine::CoordinateBuffer;
use crate::error::{check_arity, Error, ErrorKind, Result};
use crate::num::limits::check_entries;
use crate::shape::flat;
use crate::shape::point::{check_dims, check_flat, flatten_points, Point, Points};
use crate::shape::simplex::{checked_triangle_len, triangle_index};
use crate::Ring;
use std::ops::Range;

/// Checks a control net `net[nu][mu]` (about `field`): at least one row, all rows of one
/// non-zero length, all points of one dimension D >= 1. Returns (rows, cols, dim).
fn check_net<T>(net: &[Vec<Point<T>>], field: &str) -> Result<(usize, usize, usize)> {
    let Some(first) = net.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            field,
            "expected at least one row",
        ));
    };
    let cols = first.len();
    if cols == 0 || first[0].is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            format!("{field}[0]"),
            "expected a non-empty row of points",
        ));
    }
    let dim = first[0].len();
    for (i, row) in net.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::of(
                ErrorKind::Shape,
                format!("{field}[{i}]"),
                format!("expected {cols} points, found {}", row.len()),
            ));
        }
        check_dims(row, dim, &format!("{field}[{i}]"))?;
    }
    Ok((net.len(), cols, dim))
}

/// The number of points (N + 1)(N + 2) / 2 of a triangular net of degree `degree`, checked
/// against overflow and [`MAX_ENTRIES`](crate::MAX_ENTRIES) (about `degree_field`).
pub(crate) fn triangle_points(degree: usize, degree_field: &str) -> Result<usize> {
    check_entries(
        checked_triangle_len(degree),
        degree_field,
        "the number of control points (N + 1)(N + 2) / 2",
    )
}

pub(crate) fn wrong_count(field: &str, what: String, found: usize) -> Error {
    Error::of(ErrorKind::Shape, field, format!("{what}, found {found}"))
}

/// Checks a triangular net `points` of degree `degree` (about `degree_field` and
/// `points_field`): (N + 1)(N + 2) / 2 points, a count that must not overflow nor exceed
/// [`MAX_ENTRIES`](crate::MAX_ENTRIES), all of one dimension D >= 1.
pub(crate) fn check_triangle_net<T: Clone>(
    degree: usize,
    points: &[Point<T>],
    degree_field: &str,
    points_field: &str,
) -> Result<()> {
    let want = triangle_points(degree, degree_field)?;
    if points.len() != want {
        return Err(wrong_count(
            points_field,
            format!("a triangular patch of degree {degree} has {want} points"),
            points.len(),
        ));
    }
    flatten_points(points, points_field).map(|_| ())
}

/// A Bézier curve sum_i w_i B_i^n(t) over t in [0, 1], with control points of any dimension
/// `D >= 1` stored in one buffer (`D` coordinates per point, point after point).
///
/// The buffer is the ring's [`Ring::Coords`]: a `Vec<T>`, except for `f64` and `f32`, whose
/// curves of up to 8 coordinates (a planar cubic) keep them inline, so that
/// [`BezierCurve::subsegment`] and [`BezierCurve::split`] of such a curve allocate nothing.
///
/// This is the curve type of the library: every operation on Bézier curves is a method here
/// (or takes this type), the certified ones included, for `f64` and [`crate::Rational`] alike:
/// [`intersect`](Self::intersect), [`self_intersections`](Self::self_intersections),
/// [`bounding_box`](Self::bounding_box), [`nearest_point`](Self::nearest_point),
/// [`zeros`](Self::zeros) (defined with the intersection layer, which they call). [`crate::Bezier`] is the same curve with the dimension in the type
/// (`[T; D]` points), for code that knows it at compile time; the two convert into each other
/// without loss ([`From`] one way, [`TryFrom`] the other).
///
/// ```
/// use blossom::BezierCurve;
/// let cubic = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 3.0], vec![4.0, 0.0]])?;
/// let middle = cubic.subsegment(0.25..0.75);
/// // The ends of a subsegment are points of the curve.
/// assert_eq!(middle.control_points()[0], cubic.eval(&0.25));
/// assert_eq!(middle.control_points()[3], cubic.eval(&0.75));
/// // The same with no allocation once `out` and `scratch` have their size.
/// let (mut out, mut scratch) = (cubic.clone(), Vec::new());
/// cubic.subsegment_into(&0.25, &0.75, &mut out, &mut scratch);
/// assert_eq!(out, middle);
/// # Ok::<(), blossom::Error>(())
/// ```
#[repr(C)]
pub struct BezierCurve<T: Ring> {
    /// `Vec<T>`, or for `f64`/`f32` a buffer that keeps up to 12 coordinates inline
    /// ([`crate::engine::SmallCoords`]): [`Ring::Coords`]. First, so that the inline numbers
    /// start the struct (see [`crate::engine::SmallCoords`] on moves of fresh curves).
    coords: T::Coords,
    dim: usize,
}

impl<T: Ring> Clone for BezierCurve<T> {
    fn clone(&self) -> Self {
        BezierCurve {
            dim: self.dim,
            coords: self.coords.clone(),
        }
    }
}

impl<T: Ring> PartialEq for BezierCurve<T> {
    fn eq(&self, other: &Self) -> bool {
        self.dim == other.dim && self.coords == other.coords
    }
}

/// The control points, each as a list of its coordinates, whichever buffer holds them:
/// `BezierCurve { points: [[0.0, 0.0], [1.0, 2.0]] }`.
impl<T: Ring> std::fmt::Debug for BezierCurve<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BezierCurve")
            .field("points", &self.control_points())
            .finish()
    }
}

impl<T: Ring> BezierCurve<T> {
    /// A curve from its control points `w_0, ..., w_n`, all of one dimension `D >= 1` (copied
    /// once into the curve's buffer; [`BezierCurve::from_coordinates`] takes a buffer as it is).
    ///
    /// ```
    /// use blossom::{BezierCurve, ErrorKind};
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// assert_eq!((c.degree(), c.dim()), (2, 2));
    /// let e = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0]]).unwrap_err();
    /// assert_eq!((e.kind(), e.path()), (ErrorKind::Dimension, "control_points[1]"));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `control_points` when it is empty, `control_points[i]` when point i has no coordinate or
    /// another dimension than the first.
    pub fn new(control_points: Vec<Point<T>>) -> Result<Self> {
        let (dim, coords) = flatten_points(&control_points, "control_points")?;
        Ok(BezierCurve::from_raw(dim, coords))
    }

    /// A curve from the coordinates of its control points, point after point, `dim` each.
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::from_coordinates(2, vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0])?;
    /// assert_eq!(c.control_points()[1], [1.0, 2.0]);
    /// assert!(BezierCurve::from_coordinates(2, vec![0.0, 0.0, 1.0]).is_err());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `dim` when it is 0, `coordinates` when it is empty or not a whole number of points.
    pub fn from_coordinates(dim: usize, coordinates: Vec<T>) -> Result<Self> {
        check_flat(&coordinates, dim, "coordinates")?;
        Ok(BezierCurve::from_raw(dim, coordinates))
    }

    /// The curve with `coords` as they are (`dim >= 1`, a whole number of at least one point:
    /// the caller's guarantee).
    pub(crate) fn from_raw(dim: usize, coords: Vec<T>) -> Self {
        debug_assert!(dim >= 1 && !coords.is_empty() && coords.len().is_multiple_of(dim));
        BezierCurve {
            dim,
            coords: T::Coords::from_vec(coords),
        }
    }

    /// [`BezierCurve::from_raw`] from a coordinate buffer as it is (the fixed-dimension
    /// [`crate::Bezier`] keeps the same buffer type).
    pub(crate) fn from_buffer(dim: usize, coords: T::Coords) -> Self {
        debug_assert!(dim >= 1 && !coords.as_slice().is_empty());
        BezierCurve { dim, coords }
    }

    /// The curve of `len` zero coordinates, `dim` each: the buffer an answer is written into.
    #[inline]
    fn zero_filled(dim: usize, len: usize) -> Self {
        BezierCurve {
            dim,
            coords: T::Coords::filled(len, T::zero()),
        }
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.coords.as_slice().len() / self.dim - 1
    }

    /// The dimension `D` of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control points `w_0, ..., w_n`, each a `&[T]`.
    pub fn control_points(&self) -> Points<'_, T> {
        Points::new(self.coords.as_slice(), self.dim)
    }

    /// Every coordinate, point after point.
    pub fn coordinates(&self) -> &[T] {
        self.coords.as_slice()
    }

    /// Every coordinate, to change in place (the degree and dimension stay).
    pub fn coordinates_mut(&mut self) -> &mut [T] {
        self.coords.as_mut_slice()
    }

    /// Consumes the curve, returning its coordinates.
    pub fn into_coordinates(self) -> Vec<T> {
        self.coords.into_vec()
    }

    /// Consumes the curve, returning its control points as nested vectors.
    pub fn into_control_points(self) -> Vec<Point<T>> {
        self.control_points().to_vec()
    }

    /// The point at parameter `t` by de Casteljau's algorithm: exact for [`crate::Rational`],
    /// in `f64` within the stability bound of de Casteljau's convex steps (any `t` is
    /// accepted; outside [0, 1] the steps extrapolate).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// assert_eq!(c.eval(&0.5), vec![1.0, 1.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn eval(&self, t: &T) -> Point<T> {
        let mut out = vec![T::zero(); self.dim];
        T::with_scratch(|scratch| self.eval_into(t, &mut out, scratch));
        out
    }

    /// [`BezierCurve::eval`] into `out` (`D` numbers), with `level` as the working copy of the
    /// control points: no allocation once `level` has grown.
    ///
    /// # Panics
    /// When `out.len()` is not the dimension.
    pub fn eval_into(&self, t: &T, out: &mut [T], level: &mut Vec<T>) {
        assert_eq!(out.len(), self.dim, "out holds one point");
        flat::curve_eval_into(self.coords.as_slice(), self.dim, t, out, level);
    }

    /// The blossom b[t_1, ..., t_n], eq. (2) of seed 004.
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0], vec![1.0], vec![4.0]])?;
    /// // The blossom is symmetric and gives the control points at (0, 0), (0, 1), (1, 1).
    /// assert_eq!(c.blossom(&[0.0, 1.0])?, vec![1.0]);
    /// assert_eq!(c.blossom(&[0.5, 0.5])?, c.eval(&0.5));
    /// assert!(c.blossom(&[0.5]).is_err());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `args` when it does not hold n arguments.
    pub fn blossom(&self, args: &[T]) -> Result<Point<T>> {
        check_arity("args", args.len(), self.degree())?;
        Ok(flat::curve_blossom(self.coords.as_slice(), self.dim, args))
    }

    /// The same curve over `range` = a..b, reparametrised over [0, 1]: control points
    /// b[a^(n-j), b^j], j = 0..=n. Any a, b, also outside [0, 1] or with a > b. For `f64`
    /// and `f32` the answer is the one allocation (none for a curve held inline): the engine's
    /// scratch is this thread's ([`Ring::with_scratch`]).
    #[inline(always)]
    pub fn subsegment(&self, range: Range<T>) -> Self {
        let (a, b) = (&range.start, &range.end);
        match flat::curve_subsegment_small(self.coords.as_slice(), self.dim, a, b) {
            Some(coords) => BezierCurve {
                coords,
                dim: self.dim,
            },
            None => self.subsegment_new(a, b),
        }
    }

    /// [`BezierCurve::subsegment`] of every curve but the small float ones, out of line so that
    /// the inlined part stays small, and `#[cold]` so that a caller's loop over small curves
    /// keeps its running values in registers rather than saving them around this call (a call
    /// this long costs the same either way).
    #[cold]
    #[inline(never)]
    fn subsegment_new(&self, a: &T, b: &T) -> Self {
        let points = self.coords.as_slice();
        let mut out = Self::zero_filled(self.dim, points.len());
        flat::curve_subsegment_returned(points, self.dim, a, b, out.coords.as_mut_slice());
        out
    }

    /// [`BezierCurve::subsegment`] over [a, b] into `out`, whose buffer is reused (resized
    /// when its degree or dimension differ), with `scratch` grown to
    /// [`crate::engine::curve_scratch_len`] on first use. Nothing is allocated once both have
    /// their size; `f64` and `f32` curves in dimension up to 4 need no scratch at all up to
    /// degree 8 (the unrolled evaluators of `blossom::restriction!`) and at every degree on
    /// intervals inside [0, 1] (two de Casteljau subdivisions above degree 8).
    #[inline(always)]
    pub fn subsegment_into(&self, a: &T, b: &T, out: &mut Self, scratch: &mut Vec<T>) {
        out.dim = self.dim;
        out.coords.resize(self.coords.as_slice().len(), T::zero());
        flat::curve_subsegment(
            self.coords.as_slice(),
            self.dim,
            a,
            b,
            out.coords.as_mut_slice(),
            scratch,
        );
    }

    /// The parts over [0, t] and [t, 1], each over [0, 1], from one de Casteljau pyramid:
    /// exact for [`crate::Rational`], each control point one de Casteljau evaluation in `f64`.
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// let (left, right) = c.split(&0.5);
    /// assert_eq!(left.control_points()[2], right.control_points()[0]);
    /// assert_eq!(right.control_points()[2], [2.0, 0.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn split(&self, t: &T) -> (Self, Self) {
        let mut left = self.clone();
        let mut right = self.clone();
        crate::shape::halving::curve_split(
            self.coords.as_slice(),
            self.dim,
            t,
            left.coords.as_mut_slice(),
            right.coords.as_mut_slice(),
        );
        (left, right)
    }

    /// The first derivative (the hodograph): n (w_(i+1) - w_i), a curve of degree n - 1; for a
    /// constant curve, the zero curve of degree 0. Exact for [`crate::Rational`].
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// assert_eq!(c.deriv().into_control_points(), vec![vec![2.0, 4.0], vec![2.0, -4.0]]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn deriv(&self) -> Self {
        if self.degree() == 0 {
            return Self::zero_filled(self.dim, self.dim);
        }
        crate::bezier_derivative(self, 1).expect("order 1 <= degree")
    }

    /// The same curve at degree `to_degree` >= n (degree elevation, seed 004).
    ///
    /// ```
    /// use blossom::{BezierCurve, Rational};
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let line = BezierCurve::new(vec![vec![q(0)], vec![q(3)]])?;
    /// // Exact: the same curve with control points 0, 1, 2, 3.
    /// assert_eq!(line.elevate(3)?.into_control_points(), vec![vec![q(0)], vec![q(1)], vec![q(2)], vec![q(3)]]);
    /// assert!(line.elevate(0).is_err());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `to_degree` when it is below the degree.
    pub fn elevate(&self, to_degree: usize) -> Result<Self> {
        crate::elevate(self, to_degree)
    }

    /// The curve of degree `to_degree` <= n nearest to this one by `method` (seed 004).
    ///
    /// ```
    /// use blossom::{BezierCurve, Rational, Reduction};
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let line = BezierCurve::new(vec![vec![q(0)], vec![q(1)], vec![q(2)], vec![q(3)]])?;
    /// // A cubic that is a line reduces to that line exactly, by any method.
    /// let back = line.reduce(1, Reduction::LeastSquares)?;
    /// assert_eq!(back.into_control_points(), vec![vec![q(0)], vec![q(3)]]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`crate::reduce`].
    pub fn reduce(&self, to_degree: usize, method: crate::Reduction) -> Result<Self> {
        crate::reduce(self, to_degree, method)
    }
}

#[cfg(test)]
impl BezierCurve<f64> {
    /// Whether the coordinates are held inline, for the tests of that path.
    pub(crate) fn coords_are_inline(&self) -> bool {
        self.coords.is_inline()
    }
}

/// A tensor-product Bézier patch sum_{nu, mu} p_{nu mu} B_nu^n(s) B_mu^m(t) over [0, 1]^2, its
/// control points in one buffer, row by row (point (ν, μ) at position ν (m + 1) + μ).
#[derive(Clone, Debug, PartialEq)]
pub struct TensorPatch<T> {
    cols: usize,
    dim: usize,
    coords: Vec<T>,
}

impl<T: Ring> TensorPatch<T> {
    /// A patch from its control net, `net[nu][mu]` = `p_{nu mu}`: `n + 1` rows of `m + 1`
    /// points, all of one dimension (copied once into the patch's buffer).
    ///
    /// # Errors
    /// `control_points` (or one of its rows or points) when the net is empty, not rectangular
    /// or of mixed dimensions.
    pub fn new(control_points: Vec<Vec<Point<T>>>) -> Result<Self> {
        let (_, cols, dim) = check_net(&control_points, "control_points")?;
        let coords = control_points.iter().flatten().flatten().cloned().collect();
        Ok(TensorPatch { cols, dim, coords })
    }

    /// A patch of bidegree `degree` = (n, m) from the coordinates of its points, row by row,
    /// `dim` each.
    ///
    /// # Errors
    /// `dim` when it is 0, `coordinates` when it does not hold (n + 1)(m + 1) points,
    /// `degree` when that count overflows.
    pub fn from_coordinates(
        degree: (usize, usize),
        dim: usize,
        coordinates: Vec<T>,
    ) -> Result<Self> {
        let points = check_flat(&coordinates, dim, "coordinates")?;
        let cols = degree.1.checked_add(1);
        let want = degree
            .0
            .checked_add(1)
            .zip(cols)
            .and_then(|(r, c)| r.checked_mul(c))
            .ok_or_else(|| {
                Error::of(
                    ErrorKind::TooLarge,
                    "degree",
                    "the number of control points overflows usize",
                )
            })?;
        if points != want {
            return Err(wrong_count(
                "coordinates",
                format!(
                    "a patch of bidegree ({}, {}) has {want} points",
                    degree.0, degree.1
                ),
                points,
            ));
        }
        Ok(TensorPatch {
            cols: degree.1 + 1,
            dim,
            coords: coordinates,
        })
    }

    /// The patch with `coords` as they are (rows of `cols >= 1` points of `dim >= 1`: the
    /// caller's guarantee).
    pub(crate) fn from_raw(cols: usize, dim: usize, coords: Vec<T>) -> Self {
        debug_assert!(cols >= 1 && dim >= 1 && !coords.is_empty());
        debug_assert!(coords.len().is_multiple_of(cols * dim));
        TensorPatch { cols, dim, coords }
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

    /// The control point p_(ν μ).
    ///
    /// # Panics
    /// When ν > n or μ > m, as slice indexing does.
    pub fn get(&self, nu: usize, mu: usize) -> &[T] {
        let (n, m) = self.degree();
        assert!(
            nu <= n && mu <= m,
            "control point ({nu}, {mu}) of a patch of bidegree ({n}, {m})"
        );
        let start = (nu * self.cols + mu) * self.dim;
        &self.coords[start..start + self.dim]
    }

    /// Row ν of the net: the points p_(ν 0), ..., p_(ν m).
    ///
    /// # Panics
    /// When ν > n.
    pub fn row(&self, nu: usize) -> Points<'_, T> {
        Points::grid_row(&self.coords, self.cols, self.dim, nu)
    }

    /// The rows of the net, ν = 0..=n.
    pub fn rows(&self) -> impl ExactSizeIterator<Item = Points<'_, T>> + '_ {
        Points::grid_rows(&self.coords, self.cols, self.dim)
    }

    /// All control points, row by row.
    pub fn points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// Every coordinate, row by row, point after point (the layout of the engine).
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the patch, returning its coordinates.
    pub fn into_coordinates(self) -> Vec<T> {
        self.coords
    }

    /// The control net as nested vectors, `[nu][mu]` (one allocation per point).
    pub fn to_nested(&self) -> Vec<Vec<Point<T>>> {
        self.rows().map(|r| r.to_vec()).collect()
    }

    /// Consumes the patch, returning its control net as nested vectors, `[nu][mu]`.
    pub fn into_control_points(self) -> Vec<Vec<Point<T>>> {
        self.to_nested()
    }

    /// The point at `(s, t)` (two passes of de Casteljau).
    pub fn eval(&self, s: &T, t: &T) -> Point<T> {
        flat::tensor_eval(&self.coords, self.cols, self.dim, s, t)
    }

    /// The blossom b[u_1..u_n; v_1..v_m], eq. (9) of seed 004.
    ///
    /// # Errors
    /// `us` (`vs`) when it does not hold n (m) arguments.
    pub fn blossom(&self, us: &[T], vs: &[T]) -> Result<Point<T>> {
        let (n, m) = self.degree();
        check_arity("us", us.len(), n)?;
        check_arity("vs", vs.len(), m)?;
        Ok(flat::tensor_blossom(
            &self.coords,
            self.cols,
            self.dim,
            us,
            vs,
        ))
    }

    /// The patch over `rect` = [a, b, c, d], i.e. [a, b] x [c, d], reparametrised over
    /// [0, 1]^2: p_(ν μ) = b[a^(n-ν), b^ν; c^(m-μ), d^μ]. O(nm(n + m)) per coordinate.
    pub fn restrict(&self, rect: &[T; 4]) -> Self {
        let mut out = self.clone();
        T::with_scratch(|scratch| self.restrict_into(rect, &mut out, scratch));
        out
    }

    /// [`TensorPatch::restrict`] into `out` (its buffer reused, resized when the shapes
    /// differ), with `scratch` grown to [`crate::engine::tensor_scratch_len`] on first use.
    pub fn restrict_into(&self, rect: &[T; 4], out: &mut Self, scratch: &mut Vec<T>) {
        out.cols = self.cols;
        out.dim = self.dim;
        out.coords.resize(self.coords.len(), T::zero());
        flat::tensor_restrict(
            &self.coords,
            self.cols,
            self.dim,
            rect,
            &mut out.coords,
            scratch,
        );
    }
}

/// A triangular Bézier patch of total degree N over a triangle `abc`:
/// sum_{nu + mu + lambda = N} q_{nu mu lambda} N!/(nu! mu! lambda!) s^nu t^mu r^lambda in the
/// barycentric coordinates (s, t, r) of the triangle's corners (a, b, c).
///
/// The control point `q_{nu mu lambda}` is the blossom value at `a^nu, b^mu, c^lambda`
/// (equation (12)); points are stored in one buffer in lexicographic order of `(nu, mu)`.
///
/// Points of the domain are given by their **affine coordinates** `[s, t]`: the barycentric
/// coordinates (s, t, 1 - s - t), i.e. the point of the reference triangle with corners
/// a = (1, 0), b = (0, 1), c = (0, 0). [`TriangularPatch::eval`] and
/// [`TriangularPatch::restrict`] both take them (as [`crate::BezierTriangle`] does); only the
/// blossom, which is multi-affine in three free weights, takes `[u, v, w]`.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangularPatch<T> {
    degree: usize,
    dim: usize,
    coords: Vec<T>,
}

impl<T: Ring> TriangularPatch<T> {
    /// A patch of degree `degree` from its control points in lexicographic order of
    /// `(nu, mu)`: `(0, 0), (0, 1), ..., (0, N), (1, 0), ..., (N, 0)` (copied once).
    ///
    /// # Errors
    /// [`ErrorKind::TooLarge`] on `degree` when (N + 1)(N + 2) / 2 overflows or exceeds
    /// [`MAX_ENTRIES`](crate::MAX_ENTRIES); [`ErrorKind::Shape`] on `control_points` when there
    /// are not that many points; [`ErrorKind::Dimension`] when a point has no coordinate or
    /// another dimension than the first.
    pub fn new(degree: usize, control_points: Vec<Point<T>>) -> Result<Self> {
        check_triangle_net(degree, &control_points, "degree", "control_points")?;
        let (dim, coords) = flatten_points(&control_points, "control_points")?;
        Ok(TriangularPatch {
            degree,
            dim,
            coords,
        })
    }

    /// A patch of degree `degree` from the coordinates of its points (lexicographic order of
    /// `(nu, mu)`), `dim` each.
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
                format!("a triangular patch of degree {degree} has {want} points"),
                points,
            ));
        }
        Ok(TriangularPatch {
            degree,
            dim,
            coords: coordinates,
        })
    }

    /// The patch with `coords` as they are ((N + 1)(N + 2) / 2 points of `dim >= 1`: the
    /// caller's guarantee).
    pub(crate) fn from_raw(degree: usize, dim: usize, coords: Vec<T>) -> Self {
        debug_assert!(dim >= 1 && coords.len() == crate::engine::triangle_len(degree) * dim);
        TriangularPatch {
            degree,
            dim,
            coords,
        }
    }

    /// The total degree `N`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The dimension `D` of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control point `q_{nu mu lambda}` with `lambda = N - nu - mu`.
    ///
    /// # Panics
    /// When `nu + mu > N`, as slice indexing does; [`TriangularPatch::try_get`] returns `None`
    /// instead.
    pub fn get(&self, nu: usize, mu: usize) -> &[T] {
        self.try_get(nu, mu).unwrap_or_else(|| {
            panic!(
                "index (nu, mu) = ({nu}, {mu}) out of range for a triangular patch of degree {}",
                self.degree
            )
        })
    }

    /// The control point `q_{nu mu lambda}` with `lambda = N - nu - mu`, or `None` when
    /// `nu + mu > N`.
    pub fn try_get(&self, nu: usize, mu: usize) -> Option<&[T]> {
        let in_range = nu.checked_add(mu).is_some_and(|s| s <= self.degree);
        in_range.then(|| {
            let start = triangle_index(self.degree, nu, mu) * self.dim;
            &self.coords[start..start + self.dim]
        })
    }

    /// All control points in lexicographic order of `(nu, mu)`.
    pub fn control_points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// Every coordinate, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the patch, returning its coordinates.
    pub fn into_coordinates(self) -> Vec<T> {
        self.coords
    }

    /// Consumes the patch, returning its control points as nested vectors.
    pub fn into_control_points(self) -> Vec<Point<T>> {
        self.control_points().to_vec()
    }

    /// `(nu, mu, lambda, q)` for every control point, in lexicographic order of `(nu, mu)`.
    pub fn entries(&self) -> impl Iterator<Item = (usize, usize, usize, &[T])> {
        let n = self.degree;
        (0..=n)
            .flat_map(move |nu| (0..=n - nu).map(move |mu| (nu, mu)))
            .zip(self.control_points())
            .map(move |((nu, mu), q)| (nu, mu, n - nu - mu, q))
    }

    /// The point at the affine coordinates `[s, t]` (barycentric (s, t, 1 - s - t)), by
    /// de Casteljau.
    pub fn eval(&self, at: &[T; 2]) -> Point<T> {
        flat::triangle_eval(&self.coords, self.degree, self.dim, at)
    }

    /// The blossom at barycentric arguments `[u_r, v_r, w_r]` (weights of the corners a, b, c,
    /// free: the blossom is multi-affine in them).
    ///
    /// # Errors
    /// `args` when it does not hold N arguments.
    pub fn blossom(&self, args: &[[T; 3]]) -> Result<Point<T>> {
        check_arity("args", args.len(), self.degree)?;
        Ok(flat::triangle_blossom(&self.coords, self.dim, args))
    }

    /// The patch over the sub-triangle with corners `corners` = [A, B, C], each by its affine
    /// coordinates [s, t], reparametrised over the reference triangle:
    /// q_(ν μ λ) = b[A^ν, B^μ, C^λ]. O(N^3) per coordinate.
    pub fn restrict(&self, corners: &[[T; 2]; 3]) -> Self {
        let mut out = self.clone();
        T::with_scratch(|scratch| self.restrict_into(corners, &mut out, scratch));
        out
    }

    /// [`TriangularPatch::restrict`] into `out` (its buffer reused, resized when the shapes
    /// differ), with `scratch` grown to [`crate::engine::triangle_scratch_len`] on first use.
    pub fn restrict_into(&self, corners: &[[T; 2]; 3], out: &mut Self, scratch: &mut Vec<T>) {
        out.degree = self.degree;
        out.dim = self.dim;
        out.coords.resize(self.coords.len(), T::zero());
        flat::triangle_restrict(
            &self.coords,
            self.degree,
            self.dim,
            corners,
            &mut out.coords,
            scratch,
        );
    }
}

// The blossoms on nested input, for the library's independent algorithms (the pyramid, the
// rational shapes) and for users holding nested points: each flattens once and runs the one
// implementation in `flat`.

/// The blossom b[t_1, ..., t_n] of the Bézier curve with control points `control` (degree
/// `n = control.len() - 1 = args.len()`), eq. (2) of seed 004.
///
/// # Errors
/// [`ErrorKind::Empty`] or [`ErrorKind::Dimension`] on `control` as [`BezierCurve::new`];
/// [`ErrorKind::Arity`] on `args` when `args.len() + 1 != control.len()`.
pub fn bezier_curve_blossom<T: Ring>(control: &[Point<T>], args: &[T]) -> Result<Point<T>> {
    let (dim, coords) = flatten_points(control, "control")?;
    check_arity("args", args.len(), control.len() - 1)?;
    Ok(flat::curve_blossom(&coords, dim, args))
}

/// The blossom b[u_1..u_n; v_1..v_m] of the tensor patch with net `net[nu][mu]`, in two passes
/// (eq. (9) of seed 004): along v for every row, then along u.
///
/// # Errors
/// [`ErrorKind::Empty`], [`ErrorKind::Shape`] or [`ErrorKind::Dimension`] on `net` as
/// [`TensorPatch::new`]; [`ErrorKind::Arity`] on `us` (`vs`) when it does not hold n (m)
/// arguments for n + 1 rows (m + 1 columns).
pub fn bezier_tensor_blossom<T: Ring>(
    net: &[Vec<Point<T>>],
    us: &[T],
    vs: &[T],
) -> Result<Point<T>> {
    check_net(net, "net")?;
    check_arity("us", us.len(), net.len() - 1)?;
    check_arity("vs", vs.len(), net[0].len() - 1)?;
    Ok(tensor_blossom_unchecked(net, us, vs))
}

/// [`bezier_tensor_blossom`] on input known to fit.
pub(crate) fn tensor_blossom_unchecked<T: Ring>(
    net: &[Vec<Point<T>>],
    us: &[T],
    vs: &[T],
) -> Point<T> {
    let coords: Vec<T> = net.iter().flatten().flatten().cloned().collect();
    flat::tensor_blossom(&coords, net[0].len(), net[0][0].len(), us, vs)
}

/// The blossom of a triangular patch at barycentric arguments (u_r, v_r, w_r) (weights of the
/// patch's corners a, b, c), by the triangular pyramid.
///
/// # Errors
/// [`ErrorKind::Arity`] on `args` when it does not hold N arguments for a patch of degree N.
pub fn bezier_triangle_blossom<T: Ring>(
    patch: &TriangularPatch<T>,
    args: &[[T; 3]],
) -> Result<Point<T>> {
    patch.blossom(args)
}

/// [`bezier_triangle_blossom`] with `args.len()` known to be the degree.
pub(crate) fn triangle_blossom_unchecked<T: Ring>(
    patch: &TriangularPatch<T>,
    args: &[[T; 3]],
) -> Point<T> {
    flat::triangle_blossom(&patch.coords, patch.dim, args)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoints_interpolate() {
        let c = BezierCurve::new(vec![vec![0.0, 1.0], vec![5.0, 7.0], vec![2.0, 3.0]]).unwrap();
        assert_eq!(c.eval(&0.0), vec![0.0, 1.0]);
        assert_eq!(c.eval(&1.0), vec![2.0, 3.0]);
        assert_eq!(c.eval(&0.5), vec![3.0, 4.5]);
        let t = TriangularPatch::new(1, vec![vec![1.0], vec![2.0], vec![3.0]]).unwrap();
        // q_001 = c-corner, q_010 = b-corner, q_100 = a-corner.
        assert_eq!(t.eval(&[1.0, 0.0]), vec![3.0]);
        assert_eq!(t.eval(&[0.0, 0.0]), vec![1.0]);
        assert!(TriangularPatch::new(2, vec![vec![1.0]; 5]).is_err());
    }

    /// `{:?}` of a curve and of its views shows points, whatever holds them: an inline
    /// float buffer, a heap one, exact numbers; the fixed-dimension curve prints the same
    /// points, and the other curve types theirs.
    #[test]
    fn debug_shows_points() {
        let c = BezierCurve::new(vec![vec![1.0, 2.0], vec![3.0, 4.0]]).unwrap();
        assert_eq!(
            format!("{c:?}"),
            "BezierCurve { points: [[1.0, 2.0], [3.0, 4.0]] }"
        );
        assert_eq!(
            format!("{:?}", c.control_points()),
            "[[1.0, 2.0], [3.0, 4.0]]"
        );
        let fixed = crate::Bezier::<f64, 2>::try_from(&c).unwrap();
        assert_eq!(
            format!("{fixed:?}"),
            "Bezier { points: [[1.0, 2.0], [3.0, 4.0]] }"
        );
        // Past the inline limit, on the heap: the same form.
        let long = BezierCurve::from_coordinates(1, (0..20).map(f64::from).collect()).unwrap();
        assert!(format!("{long:?}").starts_with("BezierCurve { points: [[0.0], [1.0], [2.0]"));
        let q = |n: i64| crate::Rational::from_integer(n.into());
        let exact = BezierCurve::new(vec![vec![q(1)], vec![q(-2)]]).unwrap();
        assert_eq!(
            format!("{exact:?}"),
            "BezierCurve { points: [[Ratio { numer: 1, denom: 1 }], [Ratio { numer: -2, denom: 1 }]] }"
        );
        let power = crate::PowerCurve::new(vec![vec![1.0, 0.0], vec![0.0, 2.0]]).unwrap();
        assert_eq!(
            format!("{power:?}"),
            "PowerCurve { coefficients: [[1.0, 0.0], [0.0, 2.0]] }"
        );
        let arc = crate::RationalBezierCurve::from_coordinates(
            2,
            vec![1.0, 0.0, 1.0, 1.0],
            vec![1.0, 2.0],
        )
        .unwrap();
        assert_eq!(
            format!("{arc:?}"),
            "RationalBezierCurve { points: [[1.0, 0.0], [1.0, 1.0]], weights: [1.0, 2.0] }"
        );
        let spline = crate::BSpline::new(
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![vec![0.0, 1.0], vec![2.0, 3.0]],
        )
        .unwrap();
        assert!(format!("{spline:?}").ends_with("points: [[0.0, 1.0], [2.0, 3.0]] }"));
    }
}
