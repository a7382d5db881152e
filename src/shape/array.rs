//! Bézier shapes with contiguous fixed-dimension points `[T; D]`: the front end for Rust code
//! that knows its dimension. The control points of one shape are one allocation, and every
//! restriction has an `_into` form that allocates nothing once its scratch buffer has grown.
//!
//! * [`Bezier`]: a curve sum_i p_i B_i^n(t) over [0, 1];
//! * [`BezierTensor`]: a tensor-product patch over [0, 1]^2, points row by row;
//! * [`BezierTriangle`]: a triangular patch over the reference triangle, with corners
//!   (1, 0), (0, 1), (0, 0) in the affine coordinates (s, t) and barycentric coordinates
//!   (s, t, 1 - s - t); points in lexicographic order of (ν, μ) as [`crate::TriangularPatch`].
//!
//! Restriction is the halving engine ([`crate::engine::curve_net`] and its siblings) with de Casteljau
//! steps; evaluation and blossoms are de Casteljau's pyramid.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::coords::CoordinateBuffer;
use crate::shape::flat;
use crate::shape::halving::curve_split;
use crate::shape::simplex::{checked_triangle_len, triangle_index};
use crate::Ring;
use std::ops::Range;

fn empty_dimension<const D: usize>() -> Result<()> {
    if D == 0 {
        return Err(Error::of(
            ErrorKind::Dimension,
            "D",
            "points need at least 1 coordinate",
        ));
    }
    Ok(())
}

/// The error of a degree whose number of points overflows `usize`.
fn too_large(field: &str) -> Error {
    Error::of(
        ErrorKind::TooLarge,
        field,
        "the number of control points overflows usize",
    )
}

/// `Ok` when `found` is `want`, else the error about `field`: inlined into the restrictions'
/// hot paths (a call of a function of this crate that is neither generic nor `#[inline]`
/// cannot be inlined into another crate), with the error made out of line.
#[inline]
fn check_out(field: &str, want: usize, found: usize) -> Result<()> {
    #[cold]
    #[inline(never)]
    fn wrong(field: &str, want: usize, found: usize) -> Error {
        Error::of(
            ErrorKind::Shape,
            field,
            format!("expected {want} points, found {found}"),
        )
    }
    if want != found {
        return Err(wrong(field, want, found));
    }
    Ok(())
}

fn first_point<T: Clone, const D: usize>(flat: &[T]) -> [T; D] {
    std::array::from_fn(|x| flat[x].clone())
}

fn to_points<T: Clone, const D: usize>(flat: &[T]) -> Vec<[T; D]> {
    flat.chunks(D).map(first_point).collect()
}

/// A Bézier curve of any degree with `D`-dimensional control points stored contiguously.
///
/// ```
/// use blossom::Bezier;
/// let cubic = Bezier::new(vec![[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]])?;
/// let middle = cubic.subsegment(0.25..0.75);
/// // The ends of a subsegment are points of the curve.
/// assert_eq!(middle.points()[0], cubic.eval(&0.25));
/// assert_eq!(middle.points()[3], cubic.eval(&0.75));
/// let (left, right) = cubic.split(&0.5);
/// assert_eq!(left.points()[3], right.points()[0]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// The points are kept in the number type's coordinate buffer ([`Ring::Coords`]): for `f64`
/// and `f32` up to [`crate::engine::INLINE_COORDINATES`] numbers inline (a planar quintic, a
/// 3-D cubic, a 4-D quadratic), so that [`Bezier::subsegment`] and [`Bezier::split`] return
/// such curves without touching the heap.
#[repr(C)]
pub struct Bezier<T: Ring, const D: usize> {
    /// D numbers per point, point after point; a whole number of points, at least one.
    coords: T::Coords,
}

impl<T: Ring, const D: usize> Clone for Bezier<T, D> {
    fn clone(&self) -> Self {
        Bezier {
            coords: self.coords.clone(),
        }
    }
}

impl<T: Ring, const D: usize> PartialEq for Bezier<T, D> {
    fn eq(&self, other: &Self) -> bool {
        self.coords.as_slice() == other.coords.as_slice()
    }
}

impl<T: Ring + std::fmt::Debug, const D: usize> std::fmt::Debug for Bezier<T, D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Bezier")
            .field("points", &self.points())
            .finish()
    }
}

impl<T: Ring, const D: usize> Bezier<T, D> {
    /// The curve with control points `points` (degree `points.len() - 1`).
    ///
    /// ```
    /// use blossom::{Bezier, ErrorKind};
    /// let c = Bezier::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])?;
    /// assert_eq!((c.degree(), c.points()[1]), (2, [1.0, 2.0]));
    /// let none: Vec<[f64; 2]> = Vec::new();
    /// assert_eq!(Bezier::new(none).unwrap_err().kind(), ErrorKind::Empty);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `points` when it is empty, `D` when `D == 0`.
    pub fn new(points: Vec<[T; D]>) -> Result<Self> {
        empty_dimension::<D>()?;
        if points.is_empty() {
            return Err(Error::of(
                ErrorKind::Empty,
                "points",
                "expected at least one control point",
            ));
        }
        Ok(Bezier {
            coords: T::Coords::from_vec(points.into_iter().flatten().collect()),
        })
    }

    /// The curve with flat coordinates `coords`: a whole, nonzero number of points (the
    /// callers' invariant).
    fn from_coords(coords: T::Coords) -> Self {
        debug_assert!(
            D > 0 && !coords.as_slice().is_empty() && coords.as_slice().len().is_multiple_of(D)
        );
        Bezier { coords }
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.coords.as_slice().len() / D - 1
    }

    /// The control points p_0, ..., p_n.
    pub fn points(&self) -> &[[T; D]] {
        self.coords.as_slice().as_chunks::<D>().0
    }

    /// Consumes the curve, returning its control points.
    pub fn into_points(self) -> Vec<[T; D]> {
        self.points().to_vec()
    }

    /// The coordinates, D per point, point after point.
    fn flat(&self) -> &[T] {
        self.coords.as_slice()
    }

    /// The blossom f(t_1, ..., t_n) (de Casteljau with one argument per level): symmetric,
    /// affine in each argument, f(t, ..., t) the point at t; exact for [`crate::Rational`].
    ///
    /// ```
    /// use blossom::Bezier;
    /// let c = Bezier::new(vec![[0.0], [1.0], [4.0]])?;
    /// assert_eq!(c.blossom(&[0.0, 1.0])?, [1.0]); // a control point
    /// assert_eq!(c.blossom(&[0.5, 0.5])?, c.eval(&0.5));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `args` when it does not hold n arguments.
    pub fn blossom(&self, args: &[T]) -> Result<[T; D]> {
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
        Ok(first_point(&flat::curve_blossom(self.flat(), D, args)))
    }

    /// The point at `t` (de Casteljau; the working level in [`Ring::with_scratch`]'s buffer, so
    /// floats allocate nothing).
    pub fn eval(&self, t: &T) -> [T; D] {
        let mut out: [T; D] = std::array::from_fn(|_| T::zero());
        T::with_scratch(|scratch| flat::curve_eval_into(self.flat(), D, t, &mut out, scratch));
        out
    }

    /// The same curve over `range` = a..b, reparametrised over [0, 1]: control points
    /// f(a^(n-j), b^j). Any a, b, also outside [0, 1] or with a > b.
    #[inline(always)]
    pub fn subsegment(&self, range: Range<T>) -> Self {
        let (a, b) = (&range.start, &range.end);
        match flat::curve_subsegment_small(self.flat(), D, a, b) {
            Some(coords) => Bezier { coords },
            None => self.subsegment_new(a, b),
        }
    }

    /// [`Bezier::subsegment`] of every curve but the small float ones, out of line so that
    /// the inlined part stays small, and `#[cold]` so that a caller's loop over small curves
    /// keeps its running values in registers rather than saving them around this call (a call
    /// this long costs the same either way).
    #[cold]
    #[inline(never)]
    fn subsegment_new(&self, a: &T, b: &T) -> Self {
        let mut out: Self = Bezier::from_coords(T::Coords::filled(self.flat().len(), T::zero()));
        flat::curve_subsegment_returned(self.flat(), D, a, b, out.coords.as_mut_slice());
        out
    }

    /// [`Bezier::subsegment`] into `out` (n + 1 points), with `scratch` grown to
    /// [`crate::engine::curve_scratch_len`]`(n, D)` on first use and reused afterwards: no allocation
    /// once it is large enough. In `f64` and `f32` (dimensions 1..=4), degrees 1..=8 run the
    /// engine's steps unrolled by `blossom::restriction!` (no scratch; the engine's answer bit
    /// for bit; the planar quadratic and cubic and the 3-D cubic inlined into the caller),
    /// higher degrees on intervals inside [0, 1] two de Casteljau subdivisions (no scratch),
    /// the rest and every other ring [`crate::engine::curve_net`].
    ///
    /// # Errors
    /// `out` when it does not hold n + 1 points.
    #[inline(always)]
    pub fn subsegment_into(
        &self,
        a: &T,
        b: &T,
        out: &mut [[T; D]],
        scratch: &mut Vec<T>,
    ) -> Result<()> {
        subsegment_into(self.points(), a, b, out, scratch)
    }

    /// The parts over [0, t] and [t, 1], each over [0, 1], by one de Casteljau pyramid.
    pub fn split(&self, t: &T) -> (Self, Self) {
        let src = self.flat();
        let mut left = self.coords.clone();
        let mut right = self.coords.clone();
        curve_split(src, D, t, left.as_mut_slice(), right.as_mut_slice());
        (Bezier::from_coords(left), Bezier::from_coords(right))
    }
}

/// [`Bezier::subsegment_into`] on control points held anywhere (an array, a slice of a larger
/// buffer): `out` receives f(a^(n-j), b^j) for the curve with control points `points`.
///
/// # Errors
/// `points` when it is empty, `out` when it does not hold as many points.
#[inline(always)]
pub fn subsegment_into<T: Ring, const D: usize>(
    points: &[[T; D]],
    a: &T,
    b: &T,
    out: &mut [[T; D]],
    scratch: &mut Vec<T>,
) -> Result<()> {
    if points.is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            "points",
            "expected at least one control point",
        ));
    }
    check_out("out", points.len(), out.len())?;
    flat::curve_subsegment_fixed::<T, D>(
        points.as_flattened(),
        a,
        b,
        out.as_flattened_mut(),
        scratch,
    );
    Ok(())
}

/// A tensor-product Bézier patch of bidegree (n, m) with `D`-dimensional control points stored
/// contiguously, row by row: point (ν, μ) is `points()[ν * (m + 1) + μ]`.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierTensor<T, const D: usize> {
    cols: usize,
    points: Vec<[T; D]>,
}

impl<T: Ring, const D: usize> BezierTensor<T, D> {
    /// The patch of bidegree `degree` = (n, m) with the (n + 1)(m + 1) points `points`.
    ///
    /// # Errors
    /// `points` when their number is not (n + 1)(m + 1), `D` when `D == 0`,
    /// [`ErrorKind::TooLarge`] at `degree` when (n + 1)(m + 1) overflows `usize`.
    pub fn new(degree: (usize, usize), points: Vec<[T; D]>) -> Result<Self> {
        empty_dimension::<D>()?;
        let (rows, cols) = (degree.0.checked_add(1), degree.1.checked_add(1));
        let (cols, want) = match (rows, cols) {
            (Some(rows), Some(cols)) => (cols, rows.checked_mul(cols)),
            _ => (0, None),
        };
        let want = want.ok_or_else(|| too_large("degree"))?;
        check_out("points", want, points.len())?;
        Ok(BezierTensor { cols, points })
    }

    /// The bidegree (n, m).
    pub fn degree(&self) -> (usize, usize) {
        (self.points.len() / self.cols - 1, self.cols - 1)
    }

    /// The control points, row by row.
    pub fn points(&self) -> &[[T; D]] {
        &self.points
    }

    /// The control point p_(ν μ).
    ///
    /// # Panics
    /// When ν > n or μ > m, as slice indexing does (an index past a row would otherwise name
    /// a point of the next row).
    pub fn get(&self, nu: usize, mu: usize) -> &[T; D] {
        let (n, m) = self.degree();
        assert!(
            nu <= n && mu <= m,
            "control point ({nu}, {mu}) of a patch of bidegree ({n}, {m})"
        );
        &self.points[nu * self.cols + mu]
    }

    /// The point at (s, t): de Casteljau along v in every row, then along u.
    pub fn eval(&self, s: &T, t: &T) -> [T; D] {
        first_point(&flat::tensor_eval(
            self.points.as_flattened(),
            self.cols,
            D,
            s,
            t,
        ))
    }

    /// The patch over `rect` = [a, b, c, d], i.e. [a, b] x [c, d], reparametrised over
    /// [0, 1]^2.
    pub fn restrict(&self, rect: &[T; 4]) -> Self {
        let mut out = self.points.clone();
        T::with_scratch(|scratch| self.restrict_into(rect, &mut out, scratch))
            .expect("out has as many points");
        BezierTensor {
            cols: self.cols,
            points: out,
        }
    }

    /// [`BezierTensor::restrict`] into `out`, with a reusable `scratch`
    /// ([`crate::engine::tensor_scratch_len`]).
    ///
    /// # Errors
    /// `out` when it does not hold (n + 1)(m + 1) points.
    pub fn restrict_into(
        &self,
        rect: &[T; 4],
        out: &mut [[T; D]],
        scratch: &mut Vec<T>,
    ) -> Result<()> {
        check_out("out", self.points.len(), out.len())?;
        flat::tensor_restrict(
            self.points.as_flattened(),
            self.cols,
            D,
            rect,
            out.as_flattened_mut(),
            scratch,
        );
        Ok(())
    }
}

/// A triangular Bézier patch of degree N with `D`-dimensional control points stored
/// contiguously in lexicographic order of (ν, μ), over the reference triangle with corners
/// (1, 0), (0, 1), (0, 0) in the affine coordinates (s, t).
#[derive(Clone, Debug, PartialEq)]
pub struct BezierTriangle<T, const D: usize> {
    degree: usize,
    points: Vec<[T; D]>,
}

impl<T: Ring, const D: usize> BezierTriangle<T, D> {
    /// The patch of degree `degree` with the (N + 1)(N + 2) / 2 points `points`.
    ///
    /// # Errors
    /// `points` when their number is wrong, `D` when `D == 0`, [`ErrorKind::TooLarge`] at
    /// `degree` when (N + 1)(N + 2) / 2 overflows `usize`.
    pub fn new(degree: usize, points: Vec<[T; D]>) -> Result<Self> {
        empty_dimension::<D>()?;
        let want = checked_triangle_len(degree).ok_or_else(|| too_large("degree"))?;
        check_out("points", want, points.len())?;
        Ok(BezierTriangle { degree, points })
    }

    /// The degree N.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points in lexicographic order of (ν, μ).
    pub fn points(&self) -> &[[T; D]] {
        &self.points
    }

    /// The control point q_(ν μ λ), λ = N - ν - μ.
    ///
    /// # Panics
    /// When ν + μ > N, as slice indexing does (the listing's position of such a pair would
    /// name another point).
    pub fn get(&self, nu: usize, mu: usize) -> &[T; D] {
        let n = self.degree;
        assert!(
            nu.checked_add(mu).is_some_and(|s| s <= n),
            "control point ({nu}, {mu}) of a triangle of degree {n}"
        );
        &self.points[triangle_index(n, nu, mu)]
    }

    /// The point at the affine coordinates (s, t) (barycentric (s, t, 1 - s - t)).
    pub fn eval(&self, at: &[T; 2]) -> [T; D] {
        first_point(&flat::triangle_eval(
            self.points.as_flattened(),
            self.degree,
            D,
            at,
        ))
    }

    /// The patch over the triangle with corners `corners` = [A, B, C] (affine coordinates),
    /// reparametrised over the reference triangle: q_(ν μ λ) = f(A^ν, B^μ, C^λ).
    pub fn restrict(&self, corners: &[[T; 2]; 3]) -> Self {
        let mut out = self.points.clone();
        T::with_scratch(|scratch| self.restrict_into(corners, &mut out, scratch))
            .expect("out has as many points");
        BezierTriangle {
            degree: self.degree,
            points: out,
        }
    }

    /// [`BezierTriangle::restrict`] into `out`, with a reusable `scratch`
    /// ([`crate::engine::triangle_scratch_len`]).
    ///
    /// # Errors
    /// `out` when it does not hold (N + 1)(N + 2) / 2 points.
    pub fn restrict_into(
        &self,
        corners: &[[T; 2]; 3],
        out: &mut [[T; D]],
        scratch: &mut Vec<T>,
    ) -> Result<()> {
        check_out("out", self.points.len(), out.len())?;
        flat::triangle_restrict(
            self.points.as_flattened(),
            self.degree,
            D,
            corners,
            out.as_flattened_mut(),
            scratch,
        );
        Ok(())
    }
}

// Lossless conversions between the two front ends, owned and borrowed: the coordinates are the
// same numbers in the same order, so each way is one copy of the buffer (or none of the
// numbers' values changed).

/// The error of a runtime dimension that is not the type's `D`.
fn other_dimension<const D: usize>(found: usize) -> Error {
    Error::of(
        ErrorKind::Dimension,
        "dim",
        format!("expected points of {D} coordinates, found {found}"),
    )
}

fn to_arrays<T: Clone, const D: usize>(coords: &[T], dim: usize) -> Result<Vec<[T; D]>> {
    if dim != D {
        return Err(other_dimension::<D>(dim));
    }
    Ok(to_points(coords))
}

impl<T: Ring, const D: usize> From<Bezier<T, D>> for BezierCurve<T> {
    fn from(curve: Bezier<T, D>) -> Self {
        BezierCurve::from_buffer(D, curve.coords)
    }
}

impl<T: Ring, const D: usize> From<&Bezier<T, D>> for BezierCurve<T> {
    fn from(curve: &Bezier<T, D>) -> Self {
        BezierCurve::from_buffer(D, curve.coords.clone())
    }
}

impl<T: Ring, const D: usize> TryFrom<&BezierCurve<T>> for Bezier<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the curve's dimension is not `D`.
    fn try_from(curve: &BezierCurve<T>) -> Result<Self> {
        if curve.dim() != D {
            return Err(other_dimension::<D>(curve.dim()));
        }
        Ok(Bezier::from_coords(T::Coords::from_slice(
            curve.coordinates(),
        )))
    }
}

impl<T: Ring, const D: usize> TryFrom<BezierCurve<T>> for Bezier<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the curve's dimension is not `D`.
    fn try_from(curve: BezierCurve<T>) -> Result<Self> {
        Bezier::try_from(&curve)
    }
}

impl<T: Ring, const D: usize> From<&BezierTensor<T, D>> for TensorPatch<T> {
    fn from(patch: &BezierTensor<T, D>) -> Self {
        TensorPatch::from_raw(patch.cols, D, patch.points.as_flattened().to_vec())
    }
}

impl<T: Ring, const D: usize> From<BezierTensor<T, D>> for TensorPatch<T> {
    fn from(patch: BezierTensor<T, D>) -> Self {
        let cols = patch.cols;
        TensorPatch::from_raw(cols, D, patch.points.into_iter().flatten().collect())
    }
}

impl<T: Ring, const D: usize> TryFrom<&TensorPatch<T>> for BezierTensor<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the patch's dimension is not `D`.
    fn try_from(patch: &TensorPatch<T>) -> Result<Self> {
        Ok(BezierTensor {
            cols: patch.degree().1 + 1,
            points: to_arrays(patch.coordinates(), patch.dim())?,
        })
    }
}

impl<T: Ring, const D: usize> TryFrom<TensorPatch<T>> for BezierTensor<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the patch's dimension is not `D`.
    fn try_from(patch: TensorPatch<T>) -> Result<Self> {
        BezierTensor::try_from(&patch)
    }
}

impl<T: Ring, const D: usize> From<&BezierTriangle<T, D>> for TriangularPatch<T> {
    fn from(patch: &BezierTriangle<T, D>) -> Self {
        TriangularPatch::from_raw(patch.degree, D, patch.points.as_flattened().to_vec())
    }
}

impl<T: Ring, const D: usize> From<BezierTriangle<T, D>> for TriangularPatch<T> {
    fn from(patch: BezierTriangle<T, D>) -> Self {
        let degree = patch.degree;
        TriangularPatch::from_raw(degree, D, patch.points.into_iter().flatten().collect())
    }
}

impl<T: Ring, const D: usize> TryFrom<&TriangularPatch<T>> for BezierTriangle<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the patch's dimension is not `D`.
    fn try_from(patch: &TriangularPatch<T>) -> Result<Self> {
        Ok(BezierTriangle {
            degree: patch.degree(),
            points: to_arrays(patch.coordinates(), patch.dim())?,
        })
    }
}

impl<T: Ring, const D: usize> TryFrom<TriangularPatch<T>> for BezierTriangle<T, D> {
    type Error = Error;

    /// # Errors
    /// `dim` when the patch's dimension is not `D`.
    fn try_from(patch: TriangularPatch<T>) -> Result<Self> {
        BezierTriangle::try_from(&patch)
    }
}
