//! The rational triangular Bézier patch, its points and weights in two flat buffers in
//! lexicographic order of (ν, μ).

use super::homogeneous::{lift_all_into, project_into, restrict_through_homogeneous};
use super::{check_weight_count, wrong_out, zero_weight_of_part};
use crate::error::Result;
use crate::num::linalg::Field;
use crate::shape::flat;
use crate::shape::halving::{triangle_fix_in_place, BernsteinPairStep};
use crate::shape::point::{Point, Points};
use crate::shape::simplex::{triangle_index, triangle_len};
use crate::TriangularPatch;

/// The indices (ν, μ) of the point at position `k` of a triangular net of degree `n` in
/// lexicographic order.
pub(crate) fn triangle_entry(n: usize, k: usize) -> (usize, usize) {
    let nu = (0..=n)
        .rev()
        .find(|&nu| triangle_index(n, nu, 0) <= k)
        .expect("k < (n + 1)(n + 2) / 2");
    (nu, k - triangle_index(n, nu, 0))
}

/// A rational triangular Bézier patch of total degree N:
/// sum w_(ν μ λ) b_(ν μ λ) B_(ν μ λ)^N / sum w_(ν μ λ) B_(ν μ λ)^N in the barycentric
/// coordinates of its triangle.
///
/// Stored as (points, weights) in lexicographic order of (ν, μ), as [`TriangularPatch`] stores
/// its net: the coordinates in one buffer (`D` numbers per point), the weights in another.
/// Evaluation and restriction work on the homogeneous points (w b, w) in a working buffer and
/// project the result; with caller-owned buffers ([`RationalTriangularPatch::eval_into`],
/// [`RationalTriangularPatch::restrict_into`]) nothing is allocated once they have grown.
/// Points of the domain are affine coordinates `[s, t]` (barycentric (s, t, 1 - s - t)), as
/// for [`TriangularPatch`].
///
/// ```
/// use blossom::RationalTriangularPatch;
/// // Degree 1: the values 1, 2, 4 at the corners a, b, c with weights 1, 1, 2, stored in
/// // lexicographic order of (ν, μ): (0, 0) is c, (0, 1) is b, (1, 0) is a.
/// let p = RationalTriangularPatch::from_coordinates(1, 1, vec![4.0, 2.0, 1.0], vec![2.0, 1.0, 1.0])?;
/// // At the centre: (4 * 2 + 2 + 1) / (2 + 1 + 1).
/// let third = 1.0_f64 / 3.0;
/// assert!((p.eval(&[third, third]).unwrap()[0] - 11.0 / 4.0).abs() < 1e-15);
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalTriangularPatch<T> {
    degree: usize,
    dim: usize,
    coords: Vec<T>,
    weights: Vec<T>,
}

impl<T: Field> RationalTriangularPatch<T> {
    /// The patch of total degree `degree` with control points `points` and weights `weights`,
    /// both in lexicographic order of (ν, μ), copied once into the patch's buffers.
    ///
    /// # Errors
    /// As [`TriangularPatch::new`] on `degree` and `points`; [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `weights`
    /// when there is not one per point.
    pub fn new(degree: usize, points: Vec<Point<T>>, weights: Vec<T>) -> Result<Self> {
        let net = TriangularPatch::new(degree, points)
            .map_err(|e| super::rename(e, "control_points", "points"))?;
        Self::weighted(net, weights)
    }

    /// The patch of total degree `degree` from the coordinates of its points (lexicographic
    /// order of (ν, μ)), `dim` each, and one weight per point in the same order.
    ///
    /// # Errors
    /// As [`TriangularPatch::from_coordinates`]; [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `weights` when there
    /// is not one per point.
    pub fn from_coordinates(
        degree: usize,
        dim: usize,
        coordinates: Vec<T>,
        weights: Vec<T>,
    ) -> Result<Self> {
        Self::weighted(
            TriangularPatch::from_coordinates(degree, dim, coordinates)?,
            weights,
        )
    }

    fn weighted(net: TriangularPatch<T>, weights: Vec<T>) -> Result<Self> {
        check_weight_count(&weights, triangle_len(net.degree()))?;
        Ok(RationalTriangularPatch {
            degree: net.degree(),
            dim: net.dim(),
            coords: net.into_coordinates(),
            weights,
        })
    }

    /// The patch with the projected points `coords` and weights `weights` as they are (the
    /// caller's guarantee: a full net of degree `degree`).
    pub(crate) fn from_raw(degree: usize, dim: usize, coords: Vec<T>, weights: Vec<T>) -> Self {
        debug_assert_eq!(weights.len(), triangle_len(degree));
        debug_assert_eq!(coords.len(), weights.len() * dim);
        RationalTriangularPatch {
            degree,
            dim,
            coords,
            weights,
        }
    }

    /// The total degree N.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control points b_(ν μ λ), lexicographic in (ν, μ), each a `&[T]`.
    pub fn points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// The weights w_(ν μ λ), lexicographic in (ν, μ).
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// Every coordinate of the control points, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the patch, returning its coordinates and its weights.
    pub fn into_parts(self) -> (Vec<T>, Vec<T>) {
        (self.coords, self.weights)
    }

    /// The control points as nested vectors (one allocation per point).
    pub fn to_nested(&self) -> Vec<Point<T>> {
        self.points().to_vec()
    }

    /// The homogeneous net (w_ijk b_ijk, w_ijk), a polynomial triangular patch of dimension
    /// D + 1.
    pub fn homogeneous(&self) -> TriangularPatch<T> {
        let mut h = Vec::with_capacity(self.weights.len() * (self.dim + 1));
        lift_all_into(&self.coords, self.dim, &self.weights, &mut h);
        TriangularPatch::from_raw(self.degree, self.dim + 1, h)
    }

    /// The point at the affine coordinates `[s, t]` of the reference triangle (barycentric
    /// (s, t, 1 - s - t) of the corners (a, b, c), as [`TriangularPatch::eval`]), or `None`
    /// where the denominator vanishes.
    pub fn eval(&self, at: &[T; 2]) -> Option<Point<T>> {
        let mut out = vec![T::zero(); self.dim];
        T::with_scratch(|scratch| self.eval_into(at, &mut out, scratch)).ok()?;
        Some(out)
    }

    /// [`RationalTriangularPatch::eval`] into `out` (D numbers), with `scratch` as the working
    /// copy of the homogeneous points (the triangular de Casteljau pyramid runs in it): no
    /// allocation once `scratch` has grown.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`](crate::ErrorKind::Dimension) on `out` when it does not hold D numbers;
    /// [`ErrorKind::ZeroWeight`](crate::ErrorKind::ZeroWeight) on `at` where the denominator vanishes.
    pub fn eval_into(&self, at: &[T; 2], out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        if out.len() != self.dim {
            return Err(wrong_out(self.dim, out.len()));
        }
        let hdim = self.dim + 1;
        lift_all_into(&self.coords, self.dim, &self.weights, scratch);
        let step = [BernsteinPairStep(at)];
        for n in (1..=self.degree).rev() {
            triangle_fix_in_place(&mut scratch[..triangle_len(n) * hdim], n, hdim, &step);
        }
        project_into(&scratch[..hdim], out, "at", || {
            let [s, t] = at;
            format!("the denominator vanishes at [{s}, {t}]")
        })
    }

    /// The patch over the sub-triangle with corners `corners` = [A, B, C], each by its affine
    /// coordinates [s, t], reparametrised over the reference triangle: the homogeneous net
    /// h[A^ν, B^μ, C^λ] of the part, projected.
    ///
    /// # Errors
    /// [`ErrorKind::ZeroWeight`](crate::ErrorKind::ZeroWeight) on `corners` when a weight of the part vanishes.
    pub fn restrict(&self, corners: &[[T; 2]; 3]) -> Result<Self> {
        let len = self.weights.len() * (self.dim + 1);
        let mut out = RationalTriangularPatch {
            degree: self.degree,
            dim: self.dim,
            coords: Vec::with_capacity(len),
            weights: Vec::with_capacity(len),
        };
        T::with_scratch(|scratch| self.restrict_into(corners, &mut out, scratch))?;
        Ok(out)
    }

    /// [`RationalTriangularPatch::restrict`] into `out`, whose buffers are reused (resized
    /// when the shapes differ), with `scratch` grown to [`crate::engine::triangle_scratch_len`]
    /// of (N, D + 1) on first use: nothing is allocated once all three have their size. On an
    /// error `out` is a patch of the right shape with unspecified points and weights.
    ///
    /// # Errors
    /// As [`RationalTriangularPatch::restrict`].
    pub fn restrict_into(
        &self,
        corners: &[[T; 2]; 3],
        out: &mut Self,
        scratch: &mut Vec<T>,
    ) -> Result<()> {
        out.degree = self.degree;
        out.dim = self.dim;
        let n = self.degree;
        restrict_through_homogeneous(
            &self.coords,
            &self.weights,
            self.dim,
            &mut out.coords,
            &mut out.weights,
            |h, part| flat::triangle_restrict(h, n, self.dim + 1, corners, part, scratch),
            |k| {
                let (nu, mu) = triangle_entry(n, k);
                let [a, b, c] = corners.each_ref().map(|[s, t]| format!("[{s}, {t}]"));
                zero_weight_of_part(
                    "corners",
                    format!("w_{nu}{mu}{}", n - nu - mu),
                    format!("the triangle {a}, {b}, {c}"),
                )
            },
        )
    }
}
