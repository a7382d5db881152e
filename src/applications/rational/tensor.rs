//! The rational tensor-product Bézier patch, its points and weights in two flat buffers, row
//! by row.

use super::homogeneous::{
    lift_all_into, lift_into, project_in_place, project_into, restrict_through_homogeneous,
};
use super::{check_weight_count, wrong_out, zero_weight_of_part};
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::flat;
use crate::shape::halving::BernsteinStep;
use crate::shape::point::{Point, Points};
use crate::TensorPatch;

/// A rational tensor-product Bézier patch over [0, 1]^2:
/// sum w_(ν μ) b_(ν μ) B_ν^n(s) B_μ^m(t) / sum w_(ν μ) B_ν^n(s) B_μ^m(t).
///
/// Stored as (points, weights), row by row as [`TensorPatch`] stores its net: point (ν, μ) at
/// position ν (m + 1) + μ of the point buffer (`D` numbers each) and of the weight buffer.
/// Evaluation and restriction work on the homogeneous points (w b, w) in a working buffer and
/// project the result; with caller-owned buffers ([`RationalTensorPatch::eval_into`],
/// [`RationalTensorPatch::restrict_into`]) nothing is allocated once they have grown.
///
/// ```
/// use blossom::RationalTensorPatch;
/// // A bilinear patch with the corner (1, 1) of weight 3: x(1/2, 1/2) = (0 + 1 + 2 + 3 * 3) / 6.
/// let p = RationalTensorPatch::from_coordinates((1, 1), 1, vec![0.0, 1.0, 2.0, 3.0], vec![1.0, 1.0, 1.0, 3.0])?;
/// assert_eq!(p.eval(&0.5, &0.5), Some(vec![2.0]));
/// let corner = p.restrict(&[0.5, 1.0, 0.5, 1.0])?;
/// assert_eq!((corner.get(0, 0), corner.weight(0, 0)), (&[2.0][..], &1.5));
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalTensorPatch<T> {
    cols: usize,
    dim: usize,
    coords: Vec<T>,
    weights: Vec<T>,
}

impl<T: Field> RationalTensorPatch<T> {
    /// The patch with control net `points[ν][μ]` and weights `weights[ν][μ]` of the same
    /// shape, copied once into the patch's buffers.
    ///
    /// # Errors
    /// As [`TensorPatch::new`] on `points` (a ragged or empty net, mixed dimensions);
    /// [`ErrorKind::Shape`] on `weights` (or `weights[ν]`) when its shape differs.
    pub fn new(points: Vec<Vec<Point<T>>>, weights: Vec<Vec<T>>) -> Result<Self> {
        let net =
            TensorPatch::new(points).map_err(|e| super::rename(e, "control_points", "points"))?;
        let ((n, m), dim) = (net.degree(), net.dim());
        if weights.len() != n + 1 {
            return Err(Error::of(
                ErrorKind::Shape,
                "weights",
                format!("expected {} rows, found {}", n + 1, weights.len()),
            ));
        }
        for (nu, row) in weights.iter().enumerate() {
            if row.len() != m + 1 {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("weights[{nu}]"),
                    format!("expected {} weights, found {}", m + 1, row.len()),
                ));
            }
        }
        Ok(RationalTensorPatch {
            cols: m + 1,
            dim,
            coords: net.into_coordinates(),
            weights: weights.concat(),
        })
    }

    /// The patch of bidegree `degree` = (n, m) from the coordinates of its points, row by row,
    /// `dim` each, and its weights in the same order.
    ///
    /// # Errors
    /// As [`TensorPatch::from_coordinates`]; [`ErrorKind::Shape`] on `weights` when there is
    /// not one per point.
    pub fn from_coordinates(
        degree: (usize, usize),
        dim: usize,
        coordinates: Vec<T>,
        weights: Vec<T>,
    ) -> Result<Self> {
        let net = TensorPatch::from_coordinates(degree, dim, coordinates)?;
        check_weight_count(&weights, net.coordinates().len() / dim)?;
        Ok(RationalTensorPatch {
            cols: degree.1 + 1,
            dim,
            coords: net.into_coordinates(),
            weights,
        })
    }

    /// The patch of the homogeneous net `net` = (w b, w), with an error naming `field` when a
    /// weight w_(ν μ) vanishes (`context` is added to the message). The projection is done in
    /// the net's own buffer.
    pub(crate) fn from_homogeneous(
        net: TensorPatch<T>,
        field: &str,
        context: &str,
    ) -> Result<Self> {
        let (cols, hdim) = (net.degree().1 + 1, net.dim());
        let mut coords = net.into_coordinates();
        let mut weights = Vec::with_capacity(coords.len() / hdim);
        project_in_place(&mut coords, hdim, &mut weights, |k| {
            Error::of(
                ErrorKind::ZeroWeight,
                field,
                format!(
                    "weight w_{}{}{context} is zero: no rational Bézier form with finite control \
                     points",
                    k / cols,
                    k % cols
                ),
            )
        })?;
        Ok(RationalTensorPatch {
            cols,
            dim: hdim - 1,
            coords,
            weights,
        })
    }

    /// The bidegree (n, m).
    pub fn degree(&self) -> (usize, usize) {
        (self.weights.len() / self.cols - 1, self.cols - 1)
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control point b_(ν μ).
    ///
    /// # Panics
    /// When ν > n or μ > m.
    pub fn get(&self, nu: usize, mu: usize) -> &[T] {
        let (n, m) = self.degree();
        assert!(
            nu <= n && mu <= m,
            "control point ({nu}, {mu}) of a patch of bidegree ({n}, {m})"
        );
        let start = (nu * self.cols + mu) * self.dim;
        &self.coords[start..start + self.dim]
    }

    /// The weight w_(ν μ).
    ///
    /// # Panics
    /// When ν > n or μ > m.
    pub fn weight(&self, nu: usize, mu: usize) -> &T {
        let (n, m) = self.degree();
        assert!(
            nu <= n && mu <= m,
            "weight ({nu}, {mu}) of a patch of bidegree ({n}, {m})"
        );
        &self.weights[nu * self.cols + mu]
    }

    /// Row ν of the net: the points b_(ν 0), ..., b_(ν m).
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

    /// All weights, row by row (w_(ν μ) at ν (m + 1) + μ).
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// The rows of weights, ν = 0..=n.
    pub fn weight_rows(&self) -> std::slice::ChunksExact<'_, T> {
        self.weights.chunks_exact(self.cols)
    }

    /// Every coordinate of the control points, row by row, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the patch, returning its coordinates and its weights (row by row).
    pub fn into_parts(self) -> (Vec<T>, Vec<T>) {
        (self.coords, self.weights)
    }

    /// The net and the weights as nested vectors, `[ν][μ]` (one allocation per point).
    pub fn to_nested(&self) -> (Vec<Vec<Point<T>>>, Vec<Vec<T>>) {
        (
            self.rows().map(|r| r.to_vec()).collect(),
            self.weight_rows().map(<[T]>::to_vec).collect(),
        )
    }

    /// The homogeneous net (w b, w), a polynomial tensor patch of dimension D + 1.
    pub fn homogeneous(&self) -> TensorPatch<T> {
        let mut h = Vec::with_capacity(self.weights.len() * (self.dim + 1));
        lift_all_into(&self.coords, self.dim, &self.weights, &mut h);
        TensorPatch::from_raw(self.cols, self.dim + 1, h)
    }

    /// The point at (s, t) in [0, 1]^2, or `None` where the denominator vanishes.
    pub fn eval(&self, s: &T, t: &T) -> Option<Point<T>> {
        let mut out = vec![T::zero(); self.dim];
        T::with_scratch(|scratch| self.eval_into(s, t, &mut out, scratch)).ok()?;
        Some(out)
    }

    /// [`RationalTensorPatch::eval`] into `out` (D numbers), with `scratch` as the working
    /// space: every row is lifted to homogeneous points and run along t (de Casteljau), the
    /// n + 1 results along s (eq. (9) of seed 004), and the point projected. No allocation
    /// once `scratch` has grown to (n + m + 2)(D + 1) numbers.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `out` when it does not hold D numbers;
    /// [`ErrorKind::ZeroWeight`] on `(s, t)` where the denominator vanishes.
    pub fn eval_into(&self, s: &T, t: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        if out.len() != self.dim {
            return Err(wrong_out(self.dim, out.len()));
        }
        let (hdim, rows) = (self.dim + 1, self.degree().0 + 1);
        scratch.clear();
        scratch.resize((rows + self.cols) * hdim, T::zero());
        let (column, row) = scratch.split_at_mut(rows * hdim);
        let points = self.coords.chunks_exact(self.cols * self.dim);
        let weights = self.weight_rows();
        for ((b, w), h) in points.zip(weights).zip(column.chunks_exact_mut(hdim)) {
            lift_into(b, self.dim, w, row);
            flat::curve_pyramid_in_place(row, hdim, &BernsteinStep(t));
            h.clone_from_slice(&row[..hdim]);
        }
        flat::curve_pyramid_in_place(column, hdim, &BernsteinStep(s));
        project_into(&column[..hdim], out, "(s, t)", || {
            format!("the denominator vanishes at ({s}, {t})")
        })
    }

    /// The patch over `rect` = [a, b, c, d], i.e. [a, b] x [c, d], reparametrised over
    /// [0, 1]^2: the homogeneous net h[a^(n-ν), b^ν; c^(m-μ), d^μ] of the part, projected.
    ///
    /// # Errors
    /// [`ErrorKind::ZeroWeight`] on `rect` when a weight of the part vanishes.
    pub fn restrict(&self, rect: &[T; 4]) -> Result<Self> {
        let len = self.weights.len() * (self.dim + 1);
        let mut out = RationalTensorPatch {
            cols: self.cols,
            dim: self.dim,
            coords: Vec::with_capacity(len),
            weights: Vec::with_capacity(len),
        };
        T::with_scratch(|scratch| self.restrict_into(rect, &mut out, scratch))?;
        Ok(out)
    }

    /// [`RationalTensorPatch::restrict`] into `out`, whose buffers are reused (resized when
    /// the shapes differ), with `scratch` grown to [`crate::engine::tensor_scratch_len`] of
    /// (n, m, D + 1) on first use: nothing is allocated once all three have their size. On an
    /// error `out` is a patch of the right shape with unspecified points and weights.
    ///
    /// # Errors
    /// As [`RationalTensorPatch::restrict`].
    pub fn restrict_into(&self, rect: &[T; 4], out: &mut Self, scratch: &mut Vec<T>) -> Result<()> {
        out.cols = self.cols;
        out.dim = self.dim;
        let cols = self.cols;
        restrict_through_homogeneous(
            &self.coords,
            &self.weights,
            self.dim,
            &mut out.coords,
            &mut out.weights,
            |h, part| flat::tensor_restrict(h, cols, self.dim + 1, rect, part, scratch),
            |k| {
                let [a, b, c, d] = rect;
                zero_weight_of_part(
                    "rect",
                    format!("w_{}{}", k / cols, k % cols),
                    format!("[{a}, {b}] x [{c}, {d}]"),
                )
            },
        )
    }
}
