//! B-spline curves F(u) = sum_k d_k N_k^p(u) and de Boor's algorithm as blossom evaluation
//! (Theorems 2.2 and 2.3 of seed 002).
//!
//! On a non-empty span [t_s, t_{s+1}) the curve is a polynomial F_s of degree p with blossom
//! f_s, and the de Boor points are its blossom values d_k = f_s(t_{k+1}, ..., t_{k+p}),
//! k = s - p..=s (Theorem 2.2). De Boor's recurrence
//!
//! d_i^r = (1 - w_i^r) d_{i-1}^r-1 + w_i^r d_i^{r-1},  w_i^r = (x_r - t_i) / (t_{i+p+1-r} - t_i),
//!
//! run with one argument x_r per level, computes
//! d_i^r = f_s(t_{i+1}, ..., t_s, x_1, ..., x_r, t_{s+1}, ..., t_{i+p-r}) (claim (1) in the proof
//! of Theorem 2.3), so d_s^p = f_s(x_1, ..., x_p): the blossom at any arguments, and with all
//! x_r = t the point F(t). On a non-empty span every denominator is positive
//! (t_i <= t_s < t_{s+1} <= t_{i+p+1-r}), so the paper's 0/0 convention is never needed.
//!
//! Knot insertion and the split into Bézier pieces are further blossom values of the spans.

use super::de_boor::{self, bezier_points_into, de_boor_in_place, insert_points, insertion};
use super::knots::KnotVector;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::bezier::BezierCurve;
use crate::shape::point::{check_flat, flatten_points, Point, Points};

/// A B-spline curve of degree p: a validated knot vector and m de Boor points of dimension
/// D >= 1, stored in one buffer (`D` coordinates per point, point after point).
///
/// ```
/// use blossom::BSpline;
/// // The de Boor algorithm example of seed 002, from nested points or from one buffer.
/// let knots = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
/// let f = BSpline::from_coordinates(2, knots, 2, vec![1.0, 1.0, 2.0, 3.0, 4.0, 3.0, 3.0, 1.0])?;
/// assert_eq!(f.control_point(1), &[2.0, 3.0]);
/// // F(0.8) with no allocation once `scratch` has grown.
/// let (mut x, mut scratch) = ([0.0f64; 2], Vec::new());
/// f.eval_into(&0.8, &mut x, &mut scratch)?;
/// assert!((x[0] - 2.6).abs() < 1e-12 && (x[1] - 2.92).abs() < 1e-12);
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, PartialEq)]
pub struct BSpline<T> {
    knots: KnotVector<T>,
    dim: usize,
    coords: Vec<T>,
}

/// The knot vector and the de Boor points, each point as a list of its coordinates:
/// `BSpline { knots: KnotVector { .. }, points: [[0.0, 0.0], [1.0, 2.0]] }`.
impl<T: std::fmt::Debug> std::fmt::Debug for BSpline<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BSpline")
            .field("knots", &self.knots)
            .field("points", &Points::new(&self.coords, self.dim))
            .finish()
    }
}

/// One polynomial piece of a spline, in Bézier form over [0, 1] for the parameter
/// (u - a) / (b - a) of its interval [a, b].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(
        deny_unknown_fields,
        bound(
            serialize = "T: crate::Ring + serde::Serialize",
            deserialize = "T: crate::Ring + serde::Deserialize<'de>"
        )
    )
)]
pub struct BezierPiece<T: crate::Ring> {
    /// The interval [a, b] of the global parameter.
    pub interval: [T; 2],
    /// The piece's Bézier curve, b_i = f(a^(p-i), b^i).
    pub curve: BezierCurve<T>,
}

/// The error for an output buffer `out` that does not hold one point of `dim` coordinates.
pub(crate) fn wrong_out(dim: usize, found: usize) -> Error {
    Error::of(
        ErrorKind::Dimension,
        "out",
        format!("the output holds one point of {dim} coordinates, found {found}"),
    )
}

impl<T: Field> BSpline<T> {
    /// The B-spline of degree `degree` with knots `knots` (m + p + 1 of them) and de Boor points
    /// `control_points` (m of them, all of one dimension D >= 1), copied once into the
    /// spline's buffer ([`BSpline::from_coordinates`] takes a buffer as it is).
    ///
    /// # Errors
    /// [`ErrorKind::Empty`] or [`ErrorKind::Dimension`] on `control_points` as
    /// [`BezierCurve::new`]; [`ErrorKind::Shape`] on `control_points` when m < p + 1 and on
    /// `knots` when there are not m + p + 1; otherwise as [`KnotVector::new`] (knots that are
    /// not finite, out of order or of too high a multiplicity).
    ///
    /// ```
    /// use blossom::BSpline;
    /// // The de Boor algorithm example of seed 002: F(0.8) = (2.6, 2.92).
    /// let f = BSpline::new(
    ///     2,
    ///     vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
    ///     vec![vec![1.0, 1.0], vec![2.0, 3.0], vec![4.0, 3.0], vec![3.0, 1.0]],
    /// )?;
    /// let x: Vec<f64> = f.eval(&0.8)?;
    /// assert!((x[0] - 2.6).abs() < 1e-12 && (x[1] - 2.92).abs() < 1e-12);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn new(degree: usize, knots: Vec<T>, control_points: Vec<Point<T>>) -> Result<Self> {
        // The same checks as a Bézier polygon: at least one point, all of one dimension D >= 1.
        let (dim, coords) = flatten_points(&control_points, "control_points")?;
        Self::checked(degree, knots, dim, coords, "control_points")
    }

    /// The B-spline of degree `degree` with knots `knots` (m + p + 1 of them) and the
    /// coordinates of its m de Boor points, point after point, `dim` each.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `dim` when it is 0; [`ErrorKind::Empty`] or
    /// [`ErrorKind::Shape`] on `coordinates` when it is empty, not a whole number of points
    /// or fewer than p + 1 points; otherwise as [`BSpline::new`] on `knots`.
    pub fn from_coordinates(
        degree: usize,
        knots: Vec<T>,
        dim: usize,
        coordinates: Vec<T>,
    ) -> Result<Self> {
        check_flat(&coordinates, dim, "coordinates")?;
        Self::checked(degree, knots, dim, coordinates, "coordinates")
    }

    /// The spline from checked flat points (`dim >= 1`, a whole number of at least one point):
    /// the counts of points and knots and the knot vector are checked here, an error about the
    /// number of points naming `points_field`.
    pub(crate) fn checked(
        degree: usize,
        knots: Vec<T>,
        dim: usize,
        coords: Vec<T>,
        points_field: &str,
    ) -> Result<Self> {
        let m = coords.len() / dim;
        if m <= degree {
            return Err(Error::of(ErrorKind::Shape,
                points_field,
                format!(
                    "a B-spline of degree {degree} needs at least p + 1 = {} de Boor points (Theorem 2.3, ii), found {m}",
                    degree as u128 + 1
                ),
            ));
        }
        if knots.len() != m + degree + 1 {
            return Err(Error::of(
                ErrorKind::Shape,
                "knots",
                format!(
                    "{m} de Boor points of degree {degree} need m + p + 1 = {} knots, found {}",
                    m + degree + 1,
                    knots.len()
                ),
            ));
        }
        Ok(BSpline {
            knots: KnotVector::new(degree, knots)?,
            dim,
            coords,
        })
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The knots.
    pub fn knots(&self) -> &[T] {
        self.knots.knots()
    }

    /// The validated knot vector.
    pub fn knot_vector(&self) -> &KnotVector<T> {
        &self.knots
    }

    /// The de Boor points d_1..d_m (0-based), each a `&[T]`.
    pub fn control_points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// The de Boor point d_(i+1) (0-based `i`).
    ///
    /// # Panics
    /// When `i` >= m, as slice indexing does.
    pub fn control_point(&self, i: usize) -> &[T] {
        let m = self.control_points().len();
        self.control_points()
            .get(i)
            .unwrap_or_else(|| panic!("de Boor point {i} out of range for {m} points"))
    }

    /// Every coordinate of the de Boor points, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the spline, returning the coordinates of its de Boor points.
    pub fn into_coordinates(self) -> Vec<T> {
        self.coords
    }

    /// The de Boor points as nested vectors (one allocation per point).
    pub fn to_nested(&self) -> Vec<Point<T>> {
        self.control_points().to_vec()
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The domain [t_{p+1}, t_{m+1}].
    pub fn domain(&self) -> (&T, &T) {
        self.knots.domain()
    }

    /// The de Boor points d_{s-p}..d_s that act on span `s`, point after point.
    fn window(&self, s: usize) -> &[T] {
        &self.coords[(s - self.degree()) * self.dim..(s + 1) * self.dim]
    }

    /// The blossom f_s(args) of the polynomial piece on the non-empty domain span `s`
    /// (0-based: `[knots[s], knots[s+1])`), by de Boor's algorithm with one argument per level.
    pub fn blossom(&self, s: usize, args: &[T]) -> Result<Point<T>> {
        if !self.knots.is_span(s) {
            return Err(Error::of(
                ErrorKind::Domain,
                "span",
                format!(
                    "{s} is not a non-empty span of the domain (spans: {:?})",
                    self.knots.spans()
                ),
            ));
        }
        if args.len() != self.degree() {
            return Err(Error::of(
                ErrorKind::Arity,
                "args",
                format!(
                    "a blossom of degree {} takes {} arguments, found {}",
                    self.degree(),
                    self.degree(),
                    args.len()
                ),
            ));
        }
        let mut level = self.window(s).to_vec();
        de_boor_in_place(&self.knots, s, &mut level, self.dim, args);
        level.truncate(self.dim);
        Ok(level)
    }

    /// De Boor's full table at parameter t: the span k (0-based) with t_k <= t < t_{k+1} and
    /// `table[r][j]` = d_i^r(t) for i = k - p + r + j; F(t) = `table[p][0]`.
    pub fn de_boor(&self, t: &T) -> Result<(usize, Vec<Vec<Point<T>>>)> {
        let k = self.knots.span(t)?;
        let args = std::iter::repeat_n(t, self.degree());
        let table = de_boor::de_boor_table(&self.knots, k, self.window(k), self.dim, args);
        let nested = table
            .iter()
            .map(|level| Points::new(level, self.dim).to_vec())
            .collect();
        Ok((k, nested))
    }

    /// F(t) by de Boor's algorithm (Theorem 2.3), left in the first D numbers of `level`, which
    /// is the working copy of the p + 1 de Boor points of the span.
    pub(crate) fn eval_in<'a>(&self, t: &T, level: &'a mut Vec<T>) -> Result<&'a [T]> {
        let k = self.knots.span(t)?;
        level.clear();
        level.extend_from_slice(self.window(k));
        de_boor_in_place(
            &self.knots,
            k,
            level,
            self.dim,
            std::iter::repeat_n(t, self.degree()),
        );
        Ok(&level[..self.dim])
    }

    /// F(t) by de Boor's algorithm (Theorem 2.3). At the right end of the domain the last span
    /// is used.
    ///
    /// # Errors
    /// As [`KnotVector::span`]: [`ErrorKind::NotFinite`] on `t` for a NaN or an infinity,
    /// [`ErrorKind::Domain`] on `t` outside the domain.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        let mut level = Vec::with_capacity((self.degree() + 1) * self.dim);
        self.eval_in(t, &mut level)?;
        level.truncate(self.dim);
        Ok(level)
    }

    /// [`BSpline::eval`] into `out` (D numbers), with `scratch` as the working copy of the
    /// de Boor points of the span: no allocation once `scratch` has grown to (p + 1) D.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `out` when it does not hold D numbers; otherwise as
    /// [`BSpline::eval`].
    pub fn eval_into(&self, t: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        if out.len() != self.dim {
            return Err(wrong_out(self.dim, out.len()));
        }
        out.clone_from_slice(self.eval_in(t, scratch)?);
        Ok(())
    }

    /// The Bézier pieces: on every non-empty domain span [a, b], b_i = f_s(a^(p-i), b^i).
    pub fn bezier_pieces(&self) -> Vec<BezierPiece<T>> {
        let t = self.knots();
        let len = (self.degree() + 1) * self.dim;
        let mut scratch = Vec::with_capacity(len);
        self.knots
            .spans()
            .into_iter()
            .map(|s| {
                let mut points = vec![T::zero(); len];
                bezier_points_into(
                    &self.knots,
                    s,
                    self.window(s),
                    self.dim,
                    &mut points,
                    &mut scratch,
                );
                BezierPiece {
                    interval: [t[s].clone(), t[s + 1].clone()],
                    curve: BezierCurve::from_raw(self.dim, points),
                }
            })
            .collect()
    }

    /// The same curve with the knot `x` inserted once (Boehm's algorithm read as blossoms).
    ///
    /// With x in the span s, the new knot vector T' has x after t_s, and by Theorem 2.2 the new
    /// de Boor points are d'_k = f_s(t'_{k+1}, ..., t'_{k+p}) for k = s - p + 1..=s; the others
    /// are old points (their knot windows do not contain x). An error names `x` outside the
    /// domain, or `knots` when x would exceed multiplicity p + 1.
    pub fn insert_knot(&self, x: &T) -> Result<BSpline<T>> {
        let (s, knots) = insertion(&self.knots, x)?;
        let mut coords = Vec::with_capacity(self.coords.len() + self.dim);
        let mut scratch = Vec::with_capacity((self.degree() + 1) * self.dim);
        insert_points(
            &self.knots,
            &knots,
            s,
            &self.coords,
            self.dim,
            &mut coords,
            &mut scratch,
        );
        Ok(BSpline {
            knots,
            dim: self.dim,
            coords,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    fn example() -> BSpline<Rational> {
        // The de Boor algorithm example of seed 002.
        let knots = [0, 0, 0, 1, 2, 2, 2].map(|k| q(k, 1)).to_vec();
        let pts = [(1, 1), (2, 3), (4, 3), (3, 1)]
            .map(|(x, y)| vec![q(x, 1), q(y, 1)])
            .to_vec();
        BSpline::new(2, knots, pts).unwrap()
    }

    #[test]
    fn f_of_four_fifths() {
        assert_eq!(example().eval(&q(4, 5)).unwrap(), vec![q(13, 5), q(73, 25)]);
    }

    #[test]
    fn insertion_keeps_the_curve() {
        let f = example();
        let g = f
            .insert_knot(&q(1, 2))
            .unwrap()
            .insert_knot(&q(1, 1))
            .unwrap();
        assert_eq!(g.control_points().len(), 6);
        for k in 0..=8 {
            let t = q(k, 4);
            assert_eq!(f.eval(&t).unwrap(), g.eval(&t).unwrap(), "t = {t}");
        }
        // The end knot 2 already has multiplicity p + 1.
        assert_eq!(f.insert_knot(&q(2, 1)).unwrap_err().field, "knots[7]");
        assert_eq!(f.insert_knot(&q(3, 1)).unwrap_err().field, "x");
    }

    #[test]
    fn count_mismatch_is_an_error() {
        let e = BSpline::new(
            1,
            vec![q(0, 1), q(0, 1), q(1, 1)],
            vec![vec![q(0, 1)], vec![q(1, 1)]],
        )
        .unwrap_err();
        assert_eq!(e.field, "knots");
    }
}
