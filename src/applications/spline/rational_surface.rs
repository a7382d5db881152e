//! Rational tensor-product B-spline (NURBS) surfaces through the homogeneous form (seed 004,
//! section 4, applied to the B-splines of seed 002).
//!
//! The NURBS surface with de Boor points d_kl and weights w_kl is the central projection of
//! the polynomial B-spline surface H(u, v) = sum_kl (w_kl d_kl, w_kl) N_k^p(u) N_l^q(v) of
//! dimension D + 1: x(u, v) = N(u, v) / w(u, v) with (N, w) = H. Everything polynomial (de Boor's
//! algorithm, the blossom, knot insertion, the Bézier patches) is done on H by
//! [`BSplineSurface`]; only the results are projected, so the only new failure is a vanishing
//! weight: of the surface at a point, of a new de Boor point after insertion (the
//! constructor's invariant: every weight non-zero), or of a Bézier control point.

use super::bspline::wrong_out;
use super::surface::BSplineSurface;
use crate::applications::rational::homogeneous::{divide_point, project_into, push_lifted};
use crate::applications::rational::RationalTensorPatch;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::bezier::TensorPatch;
use crate::shape::point::Point;

/// A rational B-spline surface: a [`BSplineSurface`] of homogeneous points (w d, w), every
/// weight w non-zero.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBSplineSurface<T> {
    homogeneous: BSplineSurface<T>,
}

/// The rational Bézier patch of a NURBS surface on one non-empty cell [a, b] x [c, d].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize),
    serde(bound(serialize = "T: crate::Field + serde::Serialize"))
)]
pub struct RationalBezierCell<T> {
    /// The cell as `[a, b, c, d]`.
    pub rect: [T; 4],
    /// The patch over [0, 1]^2 in the local parameters of the cell.
    pub patch: RationalTensorPatch<T>,
}

fn rename_points(mut e: Error) -> Error {
    if let Some(rest) = e.field.strip_prefix("control_points") {
        e.field = format!("points{rest}");
    }
    e
}

/// The first zero weight (last coordinate) of a homogeneous grid, as (k, l).
fn zero_weight<T: Field>(grid: &BSplineSurface<T>) -> Option<(usize, usize)> {
    let n = grid.grid_size().1;
    grid.points()
        .iter()
        .position(|h| h.last().is_some_and(|w| w.is_zero()))
        .map(|i| (i / n, i % n))
}

impl<T: Field> RationalBSplineSurface<T> {
    /// The NURBS surface of bidegree `degree` on `u_knots` x `v_knots` with the de Boor grid
    /// `points` (`[k][l]`, dimension D >= 1) and the weights `weights` of the same shape.
    /// Errors name `points[...]`, `weights[...]` (a wrong shape, a zero weight: `weights[k][l]`),
    /// `u_knots[...]` or `v_knots[...]`.
    ///
    /// ```
    /// use blossom::RationalBSplineSurface;
    /// // A bilinear patch with one corner of weight 3: x(1/2, 1/2) = (0 + 1 + 2 + 3 * 3) / 6.
    /// let f = RationalBSplineSurface::new(
    ///     (1, 1),
    ///     vec![0.0, 0.0, 1.0, 1.0],
    ///     vec![0.0, 0.0, 1.0, 1.0],
    ///     vec![vec![vec![0.0], vec![1.0]], vec![vec![2.0], vec![3.0]]],
    ///     vec![vec![1.0, 1.0], vec![1.0, 3.0]],
    /// )?;
    /// assert_eq!(f.eval(&0.5, &0.5)?, vec![2.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn new(
        degree: (usize, usize),
        u_knots: Vec<T>,
        v_knots: Vec<T>,
        points: Vec<Vec<Point<T>>>,
        weights: Vec<Vec<T>>,
    ) -> Result<Self> {
        let net = TensorPatch::new(points).map_err(rename_points)?;
        let (rows, cols) = (net.degree().0 + 1, net.degree().1 + 1);
        if weights.len() != rows {
            return Err(Error::of(
                ErrorKind::Shape,
                "weights",
                format!("expected {rows} rows, found {}", weights.len()),
            ));
        }
        for (k, row) in weights.iter().enumerate() {
            if row.len() != cols {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("weights[{k}]"),
                    format!("expected {cols} weights, found {}", row.len()),
                ));
            }
            if let Some(l) = row.iter().position(|w| w.is_zero()) {
                return Err(Error::of(
                    ErrorKind::ZeroWeight,
                    format!("weights[{k}][{l}]"),
                    "a weight must be non-zero",
                ));
            }
        }
        // The homogeneous points (w d, w), copied once into one buffer, row by row.
        let mut h = Vec::with_capacity(rows * cols * (net.dim() + 1));
        for (b, w) in net.points().iter().zip(weights.iter().flatten()) {
            push_lifted(&mut h, b, w);
        }
        let homogeneous =
            BSplineSurface::from_grid(degree, u_knots, v_knots, (rows, cols), net.dim() + 1, h)
                .map_err(rename_points)?;
        Ok(RationalBSplineSurface { homogeneous })
    }

    /// The NURBS surface whose homogeneous form is `homogeneous` (points (w d, w), the last
    /// coordinate the weight): for instance [`crate::bspline_surface_from_pieces`] of the
    /// pieces (N, w) of a piecewise rational surface. Errors: fewer than two coordinates
    /// (`homogeneous`), a zero weight (`control_points[k][l]`).
    pub fn from_homogeneous(homogeneous: BSplineSurface<T>) -> Result<Self> {
        if homogeneous.dim() < 2 {
            return Err(Error::of(
                ErrorKind::Dimension,
                "homogeneous",
                "homogeneous points (w d, w) need at least 2 coordinates, found 1",
            ));
        }
        if let Some((k, l)) = zero_weight(&homogeneous) {
            return Err(Error::of(
                ErrorKind::ZeroWeight,
                format!("control_points[{k}][{l}]"),
                "the weight (last coordinate) must be non-zero",
            ));
        }
        Ok(RationalBSplineSurface { homogeneous })
    }

    /// The B-spline surface of homogeneous points (w d, w).
    pub fn homogeneous(&self) -> &BSplineSurface<T> {
        &self.homogeneous
    }

    /// The bidegree (p, q).
    pub fn degree(&self) -> (usize, usize) {
        self.homogeneous.degree()
    }

    /// The weights w_kl.
    pub fn weights(&self) -> Vec<Vec<T>> {
        self.homogeneous
            .control_points()
            .map(|row| {
                row.iter()
                    .map(|h| h.last().expect("D + 1 >= 2 coordinates").clone())
                    .collect()
            })
            .collect()
    }

    /// The de Boor points d_kl (the homogeneous points divided by their weights).
    pub fn points(&self) -> Vec<Vec<Point<T>>> {
        self.homogeneous
            .control_points()
            .map(|row| {
                row.iter()
                    .map(|h| {
                        let (w, b) = h.split_last().expect("D + 1 >= 2 coordinates");
                        divide_point(b.to_vec(), w).expect("the weights are non-zero")
                    })
                    .collect()
            })
            .collect()
    }

    /// x(u, v) = N(u, v) / w(u, v), with H = (N, w) by de Boor's algorithm in two passes; an
    /// error naming `u` or `v` outside the domain, or `(u, v)` where the denominator vanishes.
    pub fn eval(&self, u: &T, v: &T) -> Result<Point<T>> {
        let mut out = vec![T::zero(); self.homogeneous.dim() - 1];
        T::with_scratch(|scratch| self.eval_into(u, v, &mut out, scratch))?;
        Ok(out)
    }

    /// [`RationalBSplineSurface::eval`] into `out` (D numbers), with `scratch` as the working
    /// space of de Boor's two passes on H: no allocation once `scratch` has grown.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `out` when it does not hold D numbers; otherwise as
    /// [`RationalBSplineSurface::eval`].
    pub fn eval_into(&self, u: &T, v: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        let dim = self.homogeneous.dim() - 1;
        if out.len() != dim {
            return Err(wrong_out(dim, out.len()));
        }
        project_into(
            self.homogeneous.eval_in(u, v, scratch)?,
            out,
            "(u, v)",
            || format!("the denominator vanishes at ({u}, {v})"),
        )
    }

    fn checked(homogeneous: BSplineSurface<T>, x: &T) -> Result<Self> {
        match zero_weight(&homogeneous) {
            Some((k, l)) => Err(Error::of(
                ErrorKind::ZeroWeight,
                "x",
                format!(
                    "inserting the knot {x} gives the de Boor point d_{k}{l} the weight zero \
                     (a point at infinity)"
                ),
            )),
            None => Ok(RationalBSplineSurface { homogeneous }),
        }
    }

    /// The same surface with `x` inserted once into the u knots (on the homogeneous points).
    /// Errors as [`BSplineSurface::insert_u_knot`], and `x` when a new weight is zero.
    pub fn insert_u_knot(&self, x: &T) -> Result<Self> {
        Self::checked(self.homogeneous.insert_u_knot(x)?, x)
    }

    /// The same surface with `x` inserted once into the v knots (on the homogeneous points).
    /// Errors as [`BSplineSurface::insert_v_knot`], and `x` when a new weight is zero.
    pub fn insert_v_knot(&self, x: &T) -> Result<Self> {
        Self::checked(self.homogeneous.insert_v_knot(x)?, x)
    }

    /// The rational Bézier patches, one per non-empty cell in the order of
    /// [`BSplineSurface::bezier_patches`]: the homogeneous patches projected. An error names
    /// `weights` when a Bézier weight of some cell vanishes.
    pub fn bezier_patches(&self) -> Result<Vec<RationalBezierCell<T>>> {
        self.homogeneous
            .bezier_patches()
            .into_iter()
            .map(|cell| {
                let [a, b, c, d] = &cell.rect;
                let context = format!(" of the cell [{a}, {b}] x [{c}, {d}]");
                Ok(RationalBezierCell {
                    patch: RationalTensorPatch::from_homogeneous(cell.patch, "weights", &context)?,
                    rect: cell.rect,
                })
            })
            .collect()
    }
}
