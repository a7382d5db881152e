//! The rational Bézier curve, its points and weights in two flat buffers.

use super::homogeneous::{lift_all_into, project_into, restrict_through_homogeneous};
use super::{check_weight_count, wrong_out, zero_weight_of_part};
use crate::error::Result;
use crate::num::linalg::Field;
use crate::shape::flat;
use crate::shape::halving::BernsteinStep;
use crate::shape::point::{check_flat, flatten_points, Point, Points};
use crate::BezierCurve;
use std::ops::Range;

/// A rational Bézier curve sum w_i b_i B_i^n(t) / sum w_i B_i^n(t) over t in [0, 1].
///
/// Stored as (points, weights): the coordinates of b_0, ..., b_n in one buffer (`D` numbers
/// per point, point after point) and w_0, ..., w_n in another. Evaluation and restriction lift
/// them to the homogeneous points (w_i b_i, w_i) in a working buffer, run de Casteljau or the
/// restriction engine there, and project; with caller-owned buffers
/// ([`RationalBezierCurve::eval_into`], [`RationalBezierCurve::subsegment_into`]) nothing is
/// allocated once the buffers have grown. Weights may be zero or negative; evaluation fails
/// where the denominator vanishes, restriction where a weight of the result does.
///
/// ```
/// use blossom::RationalBezierCurve;
/// // The quarter circle: (1, 0), (1, 1), (0, 1) with weights 1, 1, 2.
/// let arc = RationalBezierCurve::from_coordinates(2, vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, 1.0, 2.0])?;
/// let (mut x, mut scratch) = ([0.0_f64; 2], Vec::new());
/// arc.eval_into(&0.5, &mut x, &mut scratch)?;
/// assert!((x[0].hypot(x[1]) - 1.0).abs() < 1e-15);
/// let half = arc.subsegment(0.0..0.5)?;
/// assert_eq!(half.points()[2], x[..]);
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, PartialEq)]
pub struct RationalBezierCurve<T> {
    dim: usize,
    coords: Vec<T>,
    weights: Vec<T>,
}

/// The control points, each as a list of its coordinates, and the weights:
/// `RationalBezierCurve { points: [[1.0, 0.0], [1.0, 1.0]], weights: [1.0, 1.0] }`.
impl<T: std::fmt::Debug> std::fmt::Debug for RationalBezierCurve<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RationalBezierCurve")
            .field("points", &Points::new(&self.coords, self.dim))
            .field("weights", &self.weights)
            .finish()
    }
}

impl<T: Field> RationalBezierCurve<T> {
    /// The curve with control points `points` and weights `weights` (same count, >= 1), copied
    /// once into the curve's buffers.
    ///
    /// # Errors
    /// [`ErrorKind::Empty`](crate::ErrorKind::Empty) or [`ErrorKind::Dimension`](crate::ErrorKind::Dimension) on `points` (or `points[i]`) as
    /// [`BezierCurve::new`]; [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `weights` when there is not one per point.
    pub fn new(points: Vec<Point<T>>, weights: Vec<T>) -> Result<Self> {
        let (dim, coords) = flatten_points(&points, "points")?;
        check_weight_count(&weights, points.len())?;
        Ok(RationalBezierCurve {
            dim,
            coords,
            weights,
        })
    }

    /// The curve from the coordinates of its control points, point after point, `dim` each,
    /// and one weight per point.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`](crate::ErrorKind::Dimension) on `dim` when it is 0; [`ErrorKind::Empty`](crate::ErrorKind::Empty) or
    /// [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `coordinates` when it is empty or not a whole number of points;
    /// [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `weights` when there is not one per point.
    pub fn from_coordinates(dim: usize, coordinates: Vec<T>, weights: Vec<T>) -> Result<Self> {
        let points = check_flat(&coordinates, dim, "coordinates")?;
        check_weight_count(&weights, points)?;
        Ok(RationalBezierCurve {
            dim,
            coords: coordinates,
            weights,
        })
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.weights.len() - 1
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control points b_i, each a `&[T]`.
    pub fn points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// The weights w_i.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// Every coordinate of the control points, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the curve, returning its coordinates and its weights.
    pub fn into_parts(self) -> (Vec<T>, Vec<T>) {
        (self.coords, self.weights)
    }

    /// The control points as nested vectors (one allocation per point).
    pub fn to_nested(&self) -> Vec<Point<T>> {
        self.points().to_vec()
    }

    /// The homogeneous control points (w_i b_i, w_i), a polynomial curve of dimension D + 1.
    pub fn homogeneous(&self) -> BezierCurve<T> {
        let mut h = Vec::with_capacity(self.weights.len() * (self.dim + 1));
        lift_all_into(&self.coords, self.dim, &self.weights, &mut h);
        BezierCurve::from_raw(self.dim + 1, h)
    }

    /// The point at t (de Casteljau on the homogeneous points, then projection), or `None`
    /// where the denominator vanishes.
    pub fn eval(&self, t: &T) -> Option<Point<T>> {
        let mut out = vec![T::zero(); self.dim];
        T::with_scratch(|scratch| self.eval_into(t, &mut out, scratch)).ok()?;
        Some(out)
    }

    /// [`RationalBezierCurve::eval`] into `out` (D numbers), with `scratch` as the working
    /// copy of the homogeneous points: no allocation once `scratch` has grown.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`](crate::ErrorKind::Dimension) on `out` when it does not hold D numbers;
    /// [`ErrorKind::ZeroWeight`](crate::ErrorKind::ZeroWeight) on `t` where the denominator vanishes.
    pub fn eval_into(&self, t: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        if out.len() != self.dim {
            return Err(wrong_out(self.dim, out.len()));
        }
        lift_all_into(&self.coords, self.dim, &self.weights, scratch);
        flat::curve_pyramid_in_place(scratch, self.dim + 1, &BernsteinStep(t));
        project_into(&scratch[..=self.dim], out, "t", || {
            "the denominator vanishes there".to_string()
        })
    }

    /// The same curve over `range` = a..b, reparametrised over [0, 1]: the homogeneous
    /// control points h[a^(n-j), b^j] of the part, projected. Any a, b, also outside [0, 1].
    ///
    /// # Errors
    /// [`ErrorKind::ZeroWeight`](crate::ErrorKind::ZeroWeight) on `range` when a weight of the part vanishes (the
    /// denominator is zero at a or b, or the part has no rational Bézier form with finite
    /// control points).
    pub fn subsegment(&self, range: Range<T>) -> Result<Self> {
        let mut out = RationalBezierCurve {
            dim: self.dim,
            coords: Vec::with_capacity(self.weights.len() * (self.dim + 1)),
            weights: Vec::with_capacity(self.weights.len() * (self.dim + 1)),
        };
        T::with_scratch(|scratch| {
            self.subsegment_into(&range.start, &range.end, &mut out, scratch)
        })?;
        Ok(out)
    }

    /// [`RationalBezierCurve::subsegment`] over [a, b] into `out`, whose buffers are reused
    /// (resized when the degree or dimension differ), with `scratch` grown to
    /// [`crate::engine::curve_scratch_len`] of (n, D + 1) on first use: nothing is allocated
    /// once all three have their size. On an error `out` is a curve of the right shape with
    /// unspecified points and weights.
    ///
    /// # Errors
    /// As [`RationalBezierCurve::subsegment`].
    pub fn subsegment_into(
        &self,
        a: &T,
        b: &T,
        out: &mut Self,
        scratch: &mut Vec<T>,
    ) -> Result<()> {
        out.dim = self.dim;
        restrict_through_homogeneous(
            &self.coords,
            &self.weights,
            self.dim,
            &mut out.coords,
            &mut out.weights,
            |h, part| flat::curve_subsegment(h, self.dim + 1, a, b, part, scratch),
            |j| zero_weight_of_part("range", format!("w_{j}"), format!("[{a}, {b}]")),
        )
    }
}
