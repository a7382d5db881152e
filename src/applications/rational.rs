//! Rational curves and surfaces through the blossoms of their homogeneous form (seed 004,
//! section 4 and Example 1).
//!
//! A rational curve x(t) = N(t) / w(t) (numerator N with points of dimension D, scalar
//! denominator w) is the central projection of the polynomial curve H(t) = (N(t), w(t)) of
//! dimension D + 1. Its control points and weights on [alpha, beta] at degree n are read off
//! the homogeneous control points h_i = H[alpha^(n-i), beta^i] = (w_i b_i, w_i), which the
//! inverse formula (22) computes from points of H alone ([`crate::curve_control_points_from_samples`]); any n at least
//! the degree of H gives a degree-elevated description of the same curve. Surfaces work the
//! same way with the tensor (two passes of (22)) and triangle (eq. (23)) versions.
//!
//! Rational B-splines (NURBS) are B-splines of homogeneous control points (w_i d_i, w_i);
//! [`RationalBSpline`] evaluates them by de Boor's algorithm and projects (the surfaces,
//! [`crate::RationalBSplineSurface`], are in `spline/rational_surface.rs`).

use crate::applications::degree::elevate;
use crate::applications::spline::bspline::wrong_out;
use crate::applications::spline::BSpline;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::restrict::polarisation::{
    curve_blossom_from_samples, curve_control_points_from_samples,
    tensor_control_points_from_samples, triangle_control_points_from_samples,
};
use crate::shape::bezier::{curve_blossom_unchecked, tensor_blossom_unchecked};
use crate::shape::point::{check_flat, flatten_points, Point};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::triangle_len;
use crate::{Ring, TriangularPatch};

/// A rational curve N(t) / w(t) in the power basis of t.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalCurve<T> {
    homogeneous: PowerCurve<T>,
}

impl<T: Ring> RationalCurve<T> {
    /// The curve with numerator coefficients `numerator` (points of dimension D >= 1) and
    /// denominator coefficients `denominator`; either list may be the longer one.
    pub fn new(numerator: &[Point<T>], denominator: &[T]) -> Result<Self> {
        let num = PowerCurve::new(numerator.to_vec())
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
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
        let dim = num.dim();
        let len = numerator.len().max(denominator.len());
        let homogeneous = (0..len)
            .map(|i| {
                let mut p = numerator
                    .get(i)
                    .cloned()
                    .unwrap_or_else(|| crate::shape::point::zero(dim));
                p.push(denominator.get(i).cloned().unwrap_or_else(T::zero));
                p
            })
            .collect();
        Ok(RationalCurve {
            homogeneous: PowerCurve::new(homogeneous)?,
        })
    }

    /// The homogeneous polynomial curve H(t) = (N(t), w(t)).
    pub fn homogeneous(&self) -> &PowerCurve<T> {
        &self.homogeneous
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
    /// [alpha, beta] at degree `degree` (at least the curve's own), by the inverse formula (22).
    pub fn homogeneous_control_points(
        &self,
        alpha: &T,
        beta: &T,
        degree: usize,
    ) -> Result<Vec<Point<T>>> {
        check_degree("degree", degree, self.degree())?;
        Ok(curve_control_points_from_samples(
            degree,
            alpha,
            beta,
            &|t| self.homogeneous.eval(t),
        ))
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
        let h = elevate(&crate::BezierCurve::new(low)?, target)?.into_control_points();
        let (points, weights) = project(h, "denominator", |i| format!("weight w_{i}"))?;
        Ok(RationalBezierCurve { points, weights })
    }

    /// x(t) = N(t) / w(t), or an error when w(t) = 0.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        let mut h = self.homogeneous.eval(t);
        let w = h.pop().expect("D + 1 >= 2 coordinates");
        divide_point(h, &w)
            .ok_or_else(|| Error::of(ErrorKind::ZeroWeight, "t", "the denominator vanishes there"))
    }
}

fn rename(mut e: Error, from: &str, to: &str) -> Error {
    if let Some(rest) = e.field.strip_prefix(from) {
        e.field = format!("{to}{rest}");
    }
    e
}

/// Rows of homogeneous points (p_ij, w_ij) from rows of numerator points and of denominator
/// values of the same shape (checked row by row), refusing a denominator that is zero.
fn homogeneous_rows<T: Ring>(
    numerator: &[Vec<Point<T>>],
    denominator: &[Vec<T>],
) -> Result<Vec<Vec<Point<T>>>> {
    if denominator.len() != numerator.len() {
        return Err(Error::of(
            ErrorKind::Shape,
            "denominator",
            format!(
                "expected {} rows, found {}",
                numerator.len(),
                denominator.len()
            ),
        ));
    }
    for (i, (d, r)) in denominator.iter().zip(numerator).enumerate() {
        if d.len() != r.len() {
            return Err(Error::of(
                ErrorKind::Shape,
                format!("denominator[{i}]"),
                format!("expected {} entries, found {}", r.len(), d.len()),
            ));
        }
    }
    if denominator.iter().flatten().all(Ring::is_zero) {
        return Err(Error::of(
            ErrorKind::ZeroWeight,
            "denominator",
            "the denominator is the zero polynomial",
        ));
    }
    Ok(numerator
        .iter()
        .zip(denominator)
        .map(|(nr, dr)| {
            nr.iter()
                .zip(dr)
                .map(|(p, w)| [p.as_slice(), std::slice::from_ref(w)].concat())
                .collect()
        })
        .collect())
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

pub(crate) fn divide_point<T: Field>(p: Point<T>, w: &T) -> Option<Point<T>> {
    if w.is_zero() {
        None
    } else {
        Some(p.iter().map(|x| x.divide(w)).collect())
    }
}

/// Splits homogeneous points (w b, w) into Cartesian points b and weights w.
fn project<T: Field>(
    h: Vec<Point<T>>,
    field: &str,
    name: impl Fn(usize) -> String,
) -> Result<(Vec<Point<T>>, Vec<T>)> {
    let mut points = Vec::with_capacity(h.len());
    let mut weights = Vec::with_capacity(h.len());
    for (i, mut p) in h.into_iter().enumerate() {
        let w = p.pop().expect("D + 1 >= 2 coordinates");
        let b = divide_point(p, &w).ok_or_else(|| {
            Error::of(
                ErrorKind::ZeroWeight,
                field,
                format!(
                    "{} is zero: no rational Bézier form with finite control points",
                    name(i)
                ),
            )
        })?;
        points.push(b);
        weights.push(w);
    }
    Ok((points, weights))
}

/// The homogeneous point (w b, w).
pub(crate) fn lift<T: Ring>(b: &[T], w: &T) -> Point<T> {
    let mut h = Vec::with_capacity(b.len() + 1);
    push_lifted(&mut h, b, w);
    h
}

/// Appends the homogeneous point (w b, w) to `out`.
pub(crate) fn push_lifted<T: Ring>(out: &mut Vec<T>, b: &[T], w: &T) {
    out.extend(b.iter().map(|x| x.mul(w)));
    out.push(w.clone());
}

/// Writes the central projection N / w of the homogeneous point `h` = (N, w) into `out`
/// (`h.len() - 1` numbers); `false`, with `out` untouched, when w is zero.
pub(crate) fn project_into<T: Field>(h: &[T], out: &mut [T]) -> bool {
    let (w, n) = h.split_last().expect("D + 1 >= 2 coordinates");
    debug_assert_eq!(out.len(), n.len());
    if w.is_zero() {
        return false;
    }
    for (o, x) in out.iter_mut().zip(n) {
        *o = x.divide(w);
    }
    true
}

/// A rational Bézier curve sum w_i b_i B_i^n(t) / sum w_i B_i^n(t) over t in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierCurve<T> {
    points: Vec<Point<T>>,
    weights: Vec<T>,
}

impl<T: Field> RationalBezierCurve<T> {
    /// The curve with control points `points` and weights `weights` (same count, >= 1).
    pub fn new(points: Vec<Point<T>>, weights: Vec<T>) -> Result<Self> {
        crate::BezierCurve::new(points.clone())?;
        if weights.len() != points.len() {
            return Err(Error::of(
                ErrorKind::Shape,
                "weights",
                format!("expected {} weights, found {}", points.len(), weights.len()),
            ));
        }
        Ok(RationalBezierCurve { points, weights })
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The control points b_i.
    pub fn points(&self) -> &[Point<T>] {
        &self.points
    }

    /// The weights w_i.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// The homogeneous control points (w_i b_i, w_i).
    pub fn homogeneous(&self) -> Vec<Point<T>> {
        self.points
            .iter()
            .zip(&self.weights)
            .map(|(b, w)| lift(b, w))
            .collect()
    }

    /// The point at t (de Casteljau on the homogeneous points, then projection), or `None`
    /// where the denominator vanishes.
    pub fn eval(&self, t: &T) -> Option<Point<T>> {
        let mut h = curve_blossom_unchecked(&self.homogeneous(), &vec![t.clone(); self.degree()]);
        let w = h.pop()?;
        divide_point(h, &w)
    }
}

/// A rational surface N(u, v) / w(u, v) in the power basis: a tensor patch of bidegree (n, m)
/// or, with total degree n + m, a triangular patch.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalSurface<T> {
    homogeneous: PowerSurface<T>,
}

impl<T: Ring> RationalSurface<T> {
    /// The surface with numerator grid `numerator[i][j]` (points of dimension D) and scalar
    /// denominator grid `denominator[i][j]` of the same shape.
    pub fn new(numerator: &[Vec<Point<T>>], denominator: &[Vec<T>]) -> Result<Self> {
        PowerSurface::new(numerator.to_vec())
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
        Ok(RationalSurface {
            homogeneous: PowerSurface::new(homogeneous_rows(numerator, denominator)?)?,
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
        let mut h = self.homogeneous.eval(u, v);
        let w = h.pop()?;
        divide_point(h, &w)
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
        RationalTensorPatch::from_homogeneous(net, "denominator", "")
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
/// of total degree N.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalPowerTriangle<T> {
    homogeneous: PowerTriangle<T>,
}

impl<T: Ring> RationalPowerTriangle<T> {
    /// The surface with numerator array `numerator[i][j]` (points of dimension D) and scalar
    /// denominator array `denominator[i][j]`, both triangular of the same total degree N
    /// (row i holds N + 1 - i entries).
    pub fn new(numerator: &[Vec<Point<T>>], denominator: &[Vec<T>]) -> Result<Self> {
        PowerTriangle::new(numerator.to_vec())
            .map_err(|e| rename(e, "coefficients", "numerator"))?;
        Ok(RationalPowerTriangle {
            homogeneous: PowerTriangle::new(homogeneous_rows(numerator, denominator)?)?,
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
        let mut h = self.homogeneous.eval(u, v);
        let w = h.pop()?;
        divide_point(h, &w)
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
        let index: Vec<(usize, usize)> = (0..=big_n)
            .flat_map(|i| (0..=big_n - i).map(move |j| (i, j)))
            .collect();
        let (points, weights) = project(h, "denominator", |k| {
            let (i, j) = index[k];
            format!("weight w_{i}{j}{}", big_n - i - j)
        })?;
        Ok(RationalTriangularPatch {
            degree: big_n,
            points,
            weights,
        })
    }
}

/// A rational tensor-product Bézier patch over [0, 1]^2: points `[nu][mu]` and weights.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalTensorPatch<T> {
    points: Vec<Vec<Point<T>>>,
    weights: Vec<Vec<T>>,
}

impl<T: Field> RationalTensorPatch<T> {
    /// The patch of the homogeneous net `[nu][mu]` = (w b, w), with an error naming `field`
    /// when a weight w_{nu mu} vanishes (`context` is added to the message).
    pub(crate) fn from_homogeneous(
        net: Vec<Vec<Point<T>>>,
        field: &str,
        context: &str,
    ) -> Result<Self> {
        let mut points = Vec::with_capacity(net.len());
        let mut weights = Vec::with_capacity(net.len());
        for (nu, row) in net.into_iter().enumerate() {
            let (p, w) = project(row, field, |mu| format!("weight w_{nu}{mu}{context}"))?;
            points.push(p);
            weights.push(w);
        }
        Ok(RationalTensorPatch { points, weights })
    }

    /// The control points `[nu][mu]`.
    pub fn points(&self) -> &[Vec<Point<T>>] {
        &self.points
    }

    /// The weights `[nu][mu]`.
    pub fn weights(&self) -> &[Vec<T>] {
        &self.weights
    }

    /// The point at (s, t) in [0, 1]^2, or `None` where the denominator vanishes.
    pub fn eval(&self, s: &T, t: &T) -> Option<Point<T>> {
        let net: Vec<Vec<Point<T>>> = self
            .points
            .iter()
            .zip(&self.weights)
            .map(|(pr, wr)| pr.iter().zip(wr).map(|(b, w)| lift(b, w)).collect())
            .collect();
        let (n, m) = (net.len() - 1, net[0].len() - 1);
        let mut h = tensor_blossom_unchecked(&net, &vec![s.clone(); n], &vec![t.clone(); m]);
        let w = h.pop()?;
        divide_point(h, &w)
    }
}

/// A rational triangular Bézier patch: points and weights in lexicographic order of (i, j).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalTriangularPatch<T> {
    degree: usize,
    points: Vec<Point<T>>,
    weights: Vec<T>,
}

impl<T: Field> RationalTriangularPatch<T> {
    /// The total degree N.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points b_ijk, lexicographic in (i, j).
    pub fn points(&self) -> &[Point<T>] {
        &self.points
    }

    /// The weights w_ijk, lexicographic in (i, j).
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// The homogeneous net (w_ijk b_ijk, w_ijk), a polynomial triangular patch of dimension
    /// D + 1.
    pub fn homogeneous(&self) -> TriangularPatch<T> {
        let h: Vec<Point<T>> = self
            .points
            .iter()
            .zip(&self.weights)
            .map(|(b, w)| lift(b, w))
            .collect();
        TriangularPatch::new(self.degree, h).expect("a full net of one dimension")
    }

    /// The point at the affine coordinates `[s, t]` of the reference triangle (barycentric
    /// (s, t, 1 - s - t) of the corners (a, b, c), as [`TriangularPatch::eval`]), or `None`
    /// where the denominator vanishes.
    pub fn eval(&self, at: &[T; 2]) -> Option<Point<T>> {
        debug_assert_eq!(self.points.len(), triangle_len(self.degree));
        let mut p = self.homogeneous().eval(at);
        let w = p.pop()?;
        divide_point(p, &w)
    }
}

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
        self.eval_into(t, &mut out, &mut Vec::new())?;
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
        if project_into(self.homogeneous.eval_in(t, scratch)?, out) {
            Ok(())
        } else {
            Err(Error::of(
                ErrorKind::ZeroWeight,
                "t",
                "the denominator vanishes there",
            ))
        }
    }
}

/// Checks one non-zero weight per point (`count` points).
fn check_weights<T: Ring>(weights: &[T], count: usize) -> Result<()> {
    if weights.len() != count {
        return Err(Error::of(
            ErrorKind::Shape,
            "weights",
            format!("expected {count} weights, found {}", weights.len()),
        ));
    }
    if let Some(i) = weights.iter().position(Ring::is_zero) {
        return Err(Error::of(
            ErrorKind::ZeroWeight,
            format!("weights[{i}]"),
            "a weight must be non-zero",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    #[test]
    fn zero_weights_and_low_degrees_are_errors() {
        // 1 / t on [0, 1]: w_0 = w(0) = 0.
        let c = RationalCurve::new(&[vec![q(1)]], &[q(0), q(1)]).unwrap();
        let e = c.bezier(&q(0), &q(1), None).unwrap_err();
        assert_eq!(e.field, "denominator");
        assert!(e.message.starts_with("weight w_0 is zero"), "{e}");
        assert_eq!(c.bezier(&q(1), &q(2), Some(0)).unwrap_err().field, "degree");
        assert_eq!(
            RationalCurve::new(&[vec![q(1)]], &[q(0)])
                .unwrap_err()
                .field,
            "denominator"
        );
        assert_eq!(
            RationalCurve::<Rational>::new(&[], &[q(1)])
                .unwrap_err()
                .field,
            "numerator"
        );
        let e = RationalBSpline::new(
            1,
            vec![q(0), q(0), q(1), q(1)],
            vec![vec![q(0)], vec![q(1)]],
            vec![q(1), q(0)],
        );
        assert_eq!(e.unwrap_err().field, "weights[1]");
    }
}
