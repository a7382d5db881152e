//! Rational curves and surfaces N / w in the power basis, stored as the polynomial (N, w) of
//! dimension D + 1 in one buffer, and their rational Bézier forms by the inverse formula.

use super::homogeneous::{join, project_in_place, project_point};
use super::rename;
use super::triangle::triangle_entry;
use super::{RationalBezierCurve, RationalTensorPatch, RationalTriangularPatch};
use crate::applications::degree::elevate;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::restrict::polarisation::{
    curve_blossom_from_samples, curve_control_points_from_samples,
    tensor_control_points_from_samples, triangle_control_points_from_samples,
};
use crate::shape::point::{check_flat, flatten_points, Point};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::{BezierCurve, Ring, TensorPatch};

/// A rational curve N(t) / w(t) in the power basis of t, stored as the homogeneous polynomial
/// curve H = (N, w) of dimension D + 1 (one buffer, coefficient after coefficient).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalCurve<T> {
    homogeneous: PowerCurve<T>,
}

impl<T: Ring> RationalCurve<T> {
    /// The curve with numerator coefficients `numerator` (points of dimension D >= 1) and
    /// denominator coefficients `denominator`; either list may be the longer one (the shorter
    /// is padded with zeros).
    ///
    /// # Errors
    /// `numerator` (or `numerator[i]`) as [`PowerCurve::new`]; [`ErrorKind::Empty`] on
    /// `denominator` when it is empty, [`ErrorKind::ZeroWeight`] when it is the zero
    /// polynomial.
    pub fn new(numerator: &[Point<T>], denominator: &[T]) -> Result<Self> {
        let (dim, coords) = flatten_points(numerator, "coefficients")
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
        Self::from_coordinates(dim, coords, denominator.to_vec())
    }

    /// The curve with the numerator's coefficients given by their coordinates, c_0 first, `dim`
    /// each, and the denominator's coefficients; either list may be the longer one.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `dim` when it is 0, [`ErrorKind::Empty`] or
    /// [`ErrorKind::Shape`] on `numerator` when it is empty or not a whole number of points;
    /// `denominator` as [`RationalCurve::new`].
    ///
    /// ```
    /// use blossom::RationalCurve;
    /// // The circle (1 - t^2, 2t) / (1 + t^2).
    /// let arc = RationalCurve::from_coordinates(2, vec![1.0, 0.0, 0.0, 2.0, -1.0, 0.0], vec![1.0, 0.0, 1.0])?;
    /// assert_eq!(arc.eval(&1.0)?, vec![0.0, 1.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn from_coordinates(
        dim: usize,
        numerator: Vec<T>,
        mut denominator: Vec<T>,
    ) -> Result<Self> {
        let points = check_flat(&numerator, dim, "numerator")?;
        check_denominator(&denominator)?;
        let len = points.max(denominator.len());
        let mut numerator = numerator;
        numerator.resize(len * dim, T::zero());
        denominator.resize(len, T::zero());
        Ok(RationalCurve {
            homogeneous: PowerCurve::from_coordinates(
                dim + 1,
                join(&numerator, dim, &denominator),
            )?,
        })
    }

    /// The homogeneous polynomial curve H(t) = (N(t), w(t)).
    pub fn homogeneous(&self) -> &PowerCurve<T> {
        &self.homogeneous
    }

    /// The dimension D of the points (H has D + 1 coordinates).
    pub fn dim(&self) -> usize {
        self.homogeneous.dim() - 1
    }

    /// The largest of the two polynomial degrees (as given: leading zero coefficients count).
    pub fn degree(&self) -> usize {
        self.homogeneous.degree()
    }

    /// The blossom H[t_1, ..., t_n] of the homogeneous curve H = (N, w) at `args`, n =
    /// `args.len()` at least the curve's own degree (a larger n gives the blossom of H written
    /// at degree n), by the inverse formula, Corollary 1, eq. (20), of seed 004, from points of
    /// H alone. Its last coordinate is the blossom of w; the rational blossom is the projection
    /// (the first D coordinates divided by the last), where that is non-zero.
    ///
    /// ```
    /// use blossom::RationalCurve;
    /// use blossom::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// // The circle arc (1 - t^2, 2t) / (1 + t^2): H[a, b] = (1 - ab, a + b, 1 + ab).
    /// let arc = RationalCurve::new(&[vec![q(1), q(0)], vec![q(0), q(2)], vec![q(-1), q(0)]], &[q(1), q(0), q(1)])?;
    /// assert_eq!(arc.homogeneous_blossom(&[q(2), q(3)])?, vec![q(-5), q(5), q(7)]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn homogeneous_blossom(&self, args: &[T]) -> Result<Point<T>> {
        check_degree("args", args.len(), self.degree())?;
        curve_blossom_from_samples(args.len(), args, &|t| self.homogeneous.eval(t))
    }

    /// The homogeneous control points h_i = H[alpha^(n-i), beta^i] = (w_i b_i, w_i) on
    /// [alpha, beta] at degree `degree` (at least the curve's own), by the inverse formula
    /// (22), as a polynomial Bézier curve of dimension D + 1.
    pub fn homogeneous_control_points(
        &self,
        alpha: &T,
        beta: &T,
        degree: usize,
    ) -> Result<BezierCurve<T>> {
        check_degree("degree", degree, self.degree())?;
        let h =
            curve_control_points_from_samples(degree, alpha, beta, &|t| self.homogeneous.eval(t));
        BezierCurve::new(h)
    }
}

impl<T: Field> RationalCurve<T> {
    /// The rational Bézier form on [alpha, beta] at degree `degree` (default: the curve's own),
    /// with an error naming `denominator` when a weight w_i vanishes, and `degree` when it is
    /// below the curve's own.
    ///
    /// ```
    /// use blossom::RationalCurve;
    /// use blossom::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// // The quarter circle ((1 - t^2), 2t) / (1 + t^2) on [0, 1] (seed 004, Example 1).
    /// let arc = RationalCurve::new(&[vec![q(1), q(0)], vec![q(0), q(2)], vec![q(-1), q(0)]], &[q(1), q(0), q(1)])?;
    /// let bez = arc.bezier(&q(0), &q(1), None)?;
    /// assert_eq!(bez.weights(), &[q(1), q(1), q(2)]);
    /// assert_eq!(bez.points()[1], vec![q(1), q(1)]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn bezier(
        &self,
        alpha: &T,
        beta: &T,
        degree: Option<usize>,
    ) -> Result<RationalBezierCurve<T>> {
        let own = self.degree();
        let target = degree.unwrap_or(own);
        check_degree("degree", target, own)?;
        // Eq. (22) at the curve's own degree, then exact elevation: the same points as (22) at
        // the target degree (the built-in elevation of section 4, proved identical in the
        // tests), at O(n m) instead of O(m^3) evaluations.
        let low = self.homogeneous_control_points(alpha, beta, own)?;
        let mut coords = elevate(&low, target)?.into_coordinates();
        let mut weights = Vec::with_capacity(target + 1);
        project_in_place(&mut coords, self.dim() + 1, &mut weights, |i| {
            weight_is_zero("denominator", format!("weight w_{i}"))
        })?;
        RationalBezierCurve::from_coordinates(self.dim(), coords, weights)
    }

    /// x(t) = N(t) / w(t), or an error when w(t) = 0.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        project_point(self.homogeneous.eval(t))
            .ok_or_else(|| Error::of(ErrorKind::ZeroWeight, "t", "the denominator vanishes there"))
    }
}

/// A rational surface N(u, v) / w(u, v) in the power basis: a tensor patch of bidegree (n, m)
/// or, with total degree n + m, a triangular patch. Stored as the homogeneous polynomial
/// surface (N, w) of dimension D + 1 (one buffer, row by row).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalSurface<T> {
    homogeneous: PowerSurface<T>,
}

impl<T: Ring> RationalSurface<T> {
    /// The surface with numerator grid `numerator[i][j]` (points of dimension D) and scalar
    /// denominator grid `denominator[i][j]` of the same shape.
    ///
    /// # Errors
    /// `numerator` (or its rows and points) as [`PowerSurface::new`]; [`ErrorKind::Shape`] on
    /// `denominator` (or `denominator[i]`) when its shape differs, [`ErrorKind::ZeroWeight`]
    /// when it is the zero polynomial.
    pub fn new(numerator: &[Vec<Point<T>>], denominator: &[Vec<T>]) -> Result<Self> {
        let num = PowerSurface::new(numerator.to_vec())
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
        check_rows(numerator.iter().map(Vec::len), denominator)?;
        let (n, m) = num.degree();
        Self::from_coordinates(
            (n, m),
            num.dim(),
            num.coordinates().to_vec(),
            denominator.concat(),
        )
    }

    /// The surface of bidegree `degree` = (n, m) from the coordinates of the numerator's
    /// coefficients, row by row (c_ij at i (m + 1) + j), `dim` each, and the denominator's
    /// coefficients in the same order.
    ///
    /// # Errors
    /// As [`TensorPatch::from_coordinates`] on `dim`, `degree` and `numerator`;
    /// [`ErrorKind::Shape`] on `denominator` when there is not one coefficient per point,
    /// [`ErrorKind::ZeroWeight`] when it is the zero polynomial.
    pub fn from_coordinates(
        degree: (usize, usize),
        dim: usize,
        numerator: Vec<T>,
        denominator: Vec<T>,
    ) -> Result<Self> {
        // The same checks as a tensor patch's coordinates: (n + 1)(m + 1) points of `dim`.
        let num = TensorPatch::from_coordinates(degree, dim, numerator)
            .map_err(|e| rename(e, "coordinates", "numerator"))?;
        check_count(&denominator, num.coordinates().len() / dim)?;
        check_denominator(&denominator)?;
        let h = join(num.coordinates(), dim, &denominator);
        Ok(RationalSurface {
            homogeneous: PowerSurface::from_raw(degree.1 + 1, dim + 1, h),
        })
    }

    /// The homogeneous surface (N, w).
    pub fn homogeneous(&self) -> &PowerSurface<T> {
        &self.homogeneous
    }

    /// The bidegree (n, m).
    pub fn degree(&self) -> (usize, usize) {
        self.homogeneous.degree()
    }
}

impl<T: Field> RationalSurface<T> {
    /// x(u, v) = N(u, v) / w(u, v), or `None` where w vanishes.
    pub fn eval(&self, u: &T, v: &T) -> Option<Point<T>> {
        project_point(self.homogeneous.eval(u, v))
    }

    /// The rational tensor patch on `rect = [a, b, c, d]` at bidegree `degree` (default: the
    /// surface's own), by two passes of eq. (22) on the homogeneous surface.
    pub fn tensor(
        &self,
        rect: &[T; 4],
        degree: Option<(usize, usize)>,
    ) -> Result<RationalTensorPatch<T>> {
        let own = self.degree();
        let (n, m) = degree.unwrap_or(own);
        check_degree("degree[0]", n, own.0)?;
        check_degree("degree[1]", m, own.1)?;
        let net =
            tensor_control_points_from_samples((n, m), rect, &|u, v| self.homogeneous.eval(u, v));
        RationalTensorPatch::from_homogeneous(TensorPatch::new(net)?, "denominator", "")
    }

    /// The rational triangular patch on the triangle `tri = [a, b, c]` at total degree
    /// `degree` (default n + m, the paper's convention; any degree at least the true total
    /// degree of the homogeneous surface is accepted), by eq. (23) on the homogeneous surface.
    pub fn triangle(
        &self,
        tri: &[[T; 2]; 3],
        degree: Option<usize>,
    ) -> Result<RationalTriangularPatch<T>> {
        RationalPowerTriangle::from_surface(self).triangle(tri, degree)
    }
}

/// A rational surface N(u, v) / w(u, v) whose numerator and denominator are given by
/// triangular arrays (i + j <= N) in the power basis: the input of a rational triangular patch
/// of total degree N. Stored as the homogeneous polynomial (N, w) of dimension D + 1.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalPowerTriangle<T> {
    homogeneous: PowerTriangle<T>,
}

impl<T: Ring> RationalPowerTriangle<T> {
    /// The surface with numerator array `numerator[i][j]` (points of dimension D) and scalar
    /// denominator array `denominator[i][j]`, both triangular of the same total degree N
    /// (row i holds N + 1 - i entries).
    ///
    /// # Errors
    /// `numerator` (or its rows and points) as [`PowerTriangle::new`]; [`ErrorKind::Shape`] on
    /// `denominator` (or `denominator[i]`) when its shape differs, [`ErrorKind::ZeroWeight`]
    /// when it is the zero polynomial.
    pub fn new(numerator: &[Vec<Point<T>>], denominator: &[Vec<T>]) -> Result<Self> {
        let num = PowerTriangle::new(numerator.to_vec())
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
        check_rows(numerator.iter().map(Vec::len), denominator)?;
        Self::from_coordinates(
            num.degree(),
            num.dim(),
            num.coordinates().to_vec(),
            denominator.concat(),
        )
    }

    /// The surface of total degree `degree` from the coordinates of the numerator's full
    /// triangular array (c_00, ..., c_0N, c_10, ..., c_N0), `dim` each, and the denominator's
    /// coefficients in the same order.
    ///
    /// # Errors
    /// As [`PowerTriangle::from_coordinates`] on `degree`, `dim` and `numerator`;
    /// [`ErrorKind::Shape`] on `denominator` when there is not one coefficient per point,
    /// [`ErrorKind::ZeroWeight`] when it is the zero polynomial.
    pub fn from_coordinates(
        degree: usize,
        dim: usize,
        numerator: Vec<T>,
        denominator: Vec<T>,
    ) -> Result<Self> {
        let num = PowerTriangle::from_coordinates(degree, dim, numerator)
            .map_err(|e| rename(e, "coordinates", "numerator"))?;
        check_count(&denominator, num.coordinates().len() / dim)?;
        check_denominator(&denominator)?;
        let h = join(num.coordinates(), dim, &denominator);
        Ok(RationalPowerTriangle {
            homogeneous: PowerTriangle::triangular(degree, dim + 1, h),
        })
    }

    /// The grid surface `surface` taken at total degree n + m.
    pub fn from_surface(surface: &RationalSurface<T>) -> Self {
        RationalPowerTriangle {
            homogeneous: PowerTriangle::from_surface(&surface.homogeneous),
        }
    }

    /// The homogeneous surface (N, w).
    pub fn homogeneous(&self) -> &PowerTriangle<T> {
        &self.homogeneous
    }

    /// The total degree N the surface is given at.
    pub fn degree(&self) -> usize {
        self.homogeneous.degree()
    }

    /// The true total degree: the highest i + j of a non-zero term of numerator or denominator.
    pub fn true_degree(&self) -> usize {
        self.homogeneous.true_degree()
    }
}

impl<T: Field> RationalPowerTriangle<T> {
    /// x(u, v) = N(u, v) / w(u, v), or `None` where w vanishes.
    pub fn eval(&self, u: &T, v: &T) -> Option<Point<T>> {
        project_point(self.homogeneous.eval(u, v))
    }

    /// The rational triangular patch on the triangle `tri = [a, b, c]` at total degree
    /// `degree` (default: the degree the surface is given at; any degree at least its true
    /// total degree), by eq. (23) on the homogeneous surface.
    pub fn triangle(
        &self,
        tri: &[[T; 2]; 3],
        degree: Option<usize>,
    ) -> Result<RationalTriangularPatch<T>> {
        let big_n = degree.unwrap_or(self.degree());
        let least = self.true_degree();
        if big_n < least {
            return Err(Error::of(
                ErrorKind::Degree,
                "degree",
                format!(
                    "expected a total degree >= {least} (the surface's true total degree), found \
                     {big_n}"
                ),
            ));
        }
        let h =
            triangle_control_points_from_samples(big_n, tri, &|u, v| self.homogeneous.eval(u, v));
        let (hdim, mut coords) = flatten_points(&h, "control_points")?;
        let mut weights = Vec::with_capacity(h.len());
        project_in_place(&mut coords, hdim, &mut weights, |k| {
            let (i, j) = triangle_entry(big_n, k);
            weight_is_zero("denominator", format!("weight w_{i}{j}{}", big_n - i - j))
        })?;
        Ok(RationalTriangularPatch::from_raw(
            big_n,
            hdim - 1,
            coords,
            weights,
        ))
    }
}

/// The error of a vanishing weight `what` of a rational Bézier form computed from the power
/// form (about `field`).
fn weight_is_zero(field: &str, what: String) -> Error {
    Error::of(
        ErrorKind::ZeroWeight,
        field,
        format!("{what} is zero: no rational Bézier form with finite control points"),
    )
}

/// Checks a denominator: at least one coefficient, not all zero.
fn check_denominator<T: Ring>(denominator: &[T]) -> Result<()> {
    if denominator.is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            "denominator",
            "expected at least one coefficient",
        ));
    }
    if denominator.iter().all(Ring::is_zero) {
        return Err(Error::of(
            ErrorKind::ZeroWeight,
            "denominator",
            "the denominator is the zero polynomial",
        ));
    }
    Ok(())
}

/// Checks one denominator coefficient per numerator point (`points` of them).
fn check_count<T>(denominator: &[T], points: usize) -> Result<()> {
    if denominator.len() == points {
        Ok(())
    } else {
        Err(Error::of(
            ErrorKind::Shape,
            "denominator",
            format!(
                "expected {points} coefficients, found {}",
                denominator.len()
            ),
        ))
    }
}

/// Checks that the rows of `denominator` have the lengths `lengths` of the numerator's rows.
fn check_rows<T>(
    lengths: impl ExactSizeIterator<Item = usize>,
    denominator: &[Vec<T>],
) -> Result<()> {
    if denominator.len() != lengths.len() {
        return Err(Error::of(
            ErrorKind::Shape,
            "denominator",
            format!(
                "expected {} rows, found {}",
                lengths.len(),
                denominator.len()
            ),
        ));
    }
    for (i, (d, len)) in denominator.iter().zip(lengths).enumerate() {
        if d.len() != len {
            return Err(Error::of(
                ErrorKind::Shape,
                format!("denominator[{i}]"),
                format!("expected {len} entries, found {}", d.len()),
            ));
        }
    }
    Ok(())
}

fn check_degree(field: &str, degree: usize, own: usize) -> Result<()> {
    if degree < own {
        Err(Error::of(
            ErrorKind::Degree,
            field,
            format!("expected a degree >= {own} (the curve's own degree), found {degree}"),
        ))
    } else {
        Ok(())
    }
}
