//! Rational B-spline (NURBS) curves: B-splines of homogeneous control points (w_i d_i, w_i),
//! evaluated by de Boor's algorithm and projected (the surfaces, [`crate::RationalBSplineSurface`],
//! are in `spline/rational_surface.rs`).

use super::homogeneous::{project_into, push_lifted};
use super::{check_weight_count, wrong_out};
use crate::applications::spline::BSpline;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::point::{check_flat, flatten_points, Point};
use crate::Ring;

/// A rational B-spline (NURBS) curve: a B-spline of homogeneous control points (w_i d_i, w_i).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBSpline<T> {
    homogeneous: BSpline<T>,
}

impl<T: Field> RationalBSpline<T> {
    /// The NURBS curve of degree `degree` on `knots` with control points `points` and weights
    /// `weights`; a zero weight is an error naming `weights[i]`. The homogeneous points are
    /// written once into one buffer.
    pub fn new(
        degree: usize,
        knots: Vec<T>,
        points: Vec<Point<T>>,
        weights: Vec<T>,
    ) -> Result<Self> {
        check_weights(&weights, points.len())?;
        let (dim, coords) = flatten_points(&points, "control_points")?;
        Self::lifted(degree, knots, dim, &coords, &weights, "control_points")
    }

    /// The NURBS curve of degree `degree` on `knots` from the coordinates of its control
    /// points, point after point, `dim` each, and one weight per point.
    ///
    /// # Errors
    /// As [`BSpline::from_coordinates`] on `dim` and `coordinates`; [`ErrorKind::Shape`] on
    /// `weights` when there is not one per point, [`ErrorKind::ZeroWeight`] on `weights[i]`.
    ///
    /// ```
    /// use blossom::RationalBSpline;
    /// // A quarter circle: (1, 0), (1, 1), (0, 1) with weights 1, 1/sqrt 2, 1.
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let f = RationalBSpline::from_coordinates(
    ///     2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, w, 1.0],
    /// )?;
    /// let (mut x, mut scratch) = ([0.0; 2], Vec::new());
    /// f.eval_into(&0.5, &mut x, &mut scratch)?;
    /// assert!((x[0].hypot(x[1]) - 1.0).abs() < 1e-15);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn from_coordinates(
        degree: usize,
        knots: Vec<T>,
        dim: usize,
        coordinates: Vec<T>,
        weights: Vec<T>,
    ) -> Result<Self> {
        let points = check_flat(&coordinates, dim, "coordinates")?;
        check_weights(&weights, points)?;
        Self::lifted(degree, knots, dim, &coordinates, &weights, "coordinates")
    }

    /// The spline of the homogeneous points (w d, w) of checked flat points `coords` and
    /// non-zero `weights`, one per point.
    fn lifted(
        degree: usize,
        knots: Vec<T>,
        dim: usize,
        coords: &[T],
        weights: &[T],
        points_field: &str,
    ) -> Result<Self> {
        let mut h = Vec::with_capacity(weights.len() * (dim + 1));
        for (b, w) in coords.chunks_exact(dim).zip(weights) {
            push_lifted(&mut h, b, w);
        }
        Ok(RationalBSpline {
            homogeneous: BSpline::checked(degree, knots, dim + 1, h, points_field)?,
        })
    }

    /// The B-spline of homogeneous control points.
    pub fn homogeneous(&self) -> &BSpline<T> {
        &self.homogeneous
    }

    /// The point at `t` (de Boor on the homogeneous points, then projection); an error outside
    /// the domain or where the denominator vanishes.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        let mut out = vec![T::zero(); self.homogeneous.dim() - 1];
        T::with_scratch(|scratch| self.eval_into(t, &mut out, scratch))?;
        Ok(out)
    }

    /// [`RationalBSpline::eval`] into `out` (D numbers), with `scratch` as the working copy of
    /// the homogeneous de Boor points of the span: no allocation once `scratch` has grown.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `out` when it does not hold D numbers; otherwise as
    /// [`RationalBSpline::eval`].
    pub fn eval_into(&self, t: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        let dim = self.homogeneous.dim() - 1;
        if out.len() != dim {
            return Err(wrong_out(dim, out.len()));
        }
        project_into(self.homogeneous.eval_in(t, scratch)?, out, "t", || {
            "the denominator vanishes there".to_string()
        })
    }
}

/// Checks one non-zero weight per point (`count` points): a NURBS weight may not vanish.
fn check_weights<T: Ring>(weights: &[T], count: usize) -> Result<()> {
    check_weight_count(weights, count)?;
    if let Some(i) = weights.iter().position(Ring::is_zero) {
        return Err(Error::of(
            ErrorKind::ZeroWeight,
            format!("weights[{i}]"),
            "a weight must be non-zero",
        ));
    }
    Ok(())
}
