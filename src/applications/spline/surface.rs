//! Tensor-product B-spline surfaces through blossoms: Theorems 2.2 and 2.3 of seed 002 in each
//! variable.
//!
//! A B-spline surface of bidegree (p, q) on the knot vectors T = (t_1, ..., t_{m+p+1}) in u and
//! S = (s_1, ..., s_{n+q+1}) in v is F(u, v) = sum_k sum_l d_kl N_k^p(u) N_l^q(v). On a
//! non-empty cell [t_σ, t_{σ+1}) x [s_τ, s_{τ+1}) it is one polynomial F_στ of bidegree
//! (p, q), whose tensor blossom f_στ(u_1..u_p; v_1..v_q) is symmetric and multi-affine in each
//! group of arguments. For fixed v-arguments, F is a B-spline curve in u whose de Boor points
//! are the v-curves of the rows of the grid, so Theorem 2.2 applied in u and then in v gives
//!
//! d_kl = f_στ(t_{k+1}, ..., t_{k+p}; s_{l+1}, ..., s_{l+q}),  σ - p <= k <= σ, τ - q <= l <= τ,
//!
//! and de Boor's algorithm (Theorem 2.3) computes the blossom in two passes: **first along v
//! for every row** k = σ - p..=σ (the curve de Boor algorithm on d_k,τ-q..d_k,τ with the
//! v-arguments), **then along u on the resulting column** of p + 1 points with the u-arguments
//! (the order of [`crate::bezier_tensor_blossom`]). The blossom is the same in the other order;
//! with all u_r = u and v_r = v it is F(u, v).
//!
//! Knot insertion and the Bézier patches run the curve algorithms of `de_boor.rs` in one
//! variable at a time: a whole row of the grid, flattened into one long point, is a single
//! de Boor point of a curve in u.

use super::bspline::wrong_out;
use super::de_boor::{bezier_points_into, de_boor_in_place, insert_points, insertion};
use super::knots::KnotVector;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::bezier::TensorPatch;
use crate::shape::point::{check_flat, Point, Points};

/// A tensor-product B-spline surface of bidegree (p, q): two validated knot vectors and an
/// m x n grid of de Boor points d_kl (k along u, l along v), stored in one buffer row by row
/// (point (k, l) at position k n + l, `D` coordinates each).
///
/// ```
/// use blossom::BSplineSurface;
/// // Bilinear on [0, 1]^2 from one buffer: d_00 = 0, d_01 = 1, d_10 = 2, d_11 = 4.
/// let f = BSplineSurface::from_coordinates(
///     (1, 1),
///     vec![0.0, 0.0, 1.0, 1.0],
///     vec![0.0, 0.0, 1.0, 1.0],
///     1,
///     vec![0.0, 1.0, 2.0, 4.0],
/// )?;
/// assert_eq!((f.grid_size(), f.control_point(1, 0)), ((2, 2), &[2.0][..]));
/// let (mut x, mut scratch) = ([0.0], Vec::new());
/// f.eval_into(&0.5, &0.5, &mut x, &mut scratch)?;
/// assert_eq!(x, [1.75]);
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineSurface<T> {
    u_knots: KnotVector<T>,
    v_knots: KnotVector<T>,
    cols: usize,
    dim: usize,
    coords: Vec<T>,
}

/// The Bézier patch of a surface on one non-empty cell [a, b] x [c, d], over [0, 1]^2 in the
/// local parameters ((u - a) / (b - a), (v - c) / (d - c)).
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
pub struct BezierCell<T> {
    /// The cell as `[a, b, c, d]`.
    pub rect: [T; 4],
    /// The patch, `[nu][mu]` = f(a^(p-nu) b^nu; c^(q-mu) d^mu).
    pub patch: TensorPatch<T>,
}

/// Renames an error about `knots...` (the curve's name) to `to...`.
fn rename_knots(mut e: Error, to: &str) -> Error {
    if let Some(rest) = e.field.strip_prefix("knots") {
        e.field = format!("{to}{rest}");
    }
    e
}

impl<T: Field> BSplineSurface<T> {
    /// The surface of bidegree `degree` = (p, q) with knots `u_knots` (m + p + 1 of them) and
    /// `v_knots` (n + q + 1) and the de Boor grid `control_points` (m rows of n points, all of
    /// one dimension D >= 1), copied once into the surface's buffer. Errors name
    /// `control_points[...]`, `u_knots[...]` or `v_knots[...]`.
    ///
    /// ```
    /// use blossom::BSplineSurface;
    /// // Bilinear on [0, 2] x [0, 1] with an interior u knot at 1.
    /// let f = BSplineSurface::new(
    ///     (1, 1),
    ///     vec![0.0, 0.0, 1.0, 2.0, 2.0],
    ///     vec![0.0, 0.0, 1.0, 1.0],
    ///     vec![vec![vec![0.0], vec![0.0]], vec![vec![1.0], vec![2.0]], vec![vec![0.0], vec![4.0]]],
    /// )?;
    /// assert_eq!(f.eval(&1.5, &0.5)?, vec![1.75]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn new(
        degree: (usize, usize),
        u_knots: Vec<T>,
        v_knots: Vec<T>,
        control_points: Vec<Vec<Point<T>>>,
    ) -> Result<Self> {
        // The same checks as a Bézier net: non-empty, rectangular, one dimension D >= 1.
        let net = TensorPatch::new(control_points)?;
        let (rows, cols) = (net.degree().0 + 1, net.degree().1 + 1);
        let dim = net.dim();
        Self::from_grid(
            degree,
            u_knots,
            v_knots,
            (rows, cols),
            dim,
            net.into_coordinates(),
        )
    }

    /// The surface from a checked grid of `m` x `n` points of `dim >= 1` coordinates, row by
    /// row: the counts against the degrees and knots, and the knot vectors, are checked here.
    pub(crate) fn from_grid(
        (p, q): (usize, usize),
        u_knots: Vec<T>,
        v_knots: Vec<T>,
        (m, n): (usize, usize),
        dim: usize,
        coords: Vec<T>,
    ) -> Result<Self> {
        debug_assert_eq!(coords.len(), m * n * dim);
        for (field, deg, count, var, what) in [
            ("control_points", p, m, "u", "rows"),
            ("control_points[0]", q, n, "v", "points a row"),
        ] {
            if count <= deg {
                return Err(Error::of(
                    ErrorKind::Shape,
                    field,
                    format!(
                        "a B-spline surface of degree {deg} in {var} needs at least {deg} + 1 {what} of de Boor points (Theorem 2.3, ii), found {count}"
                    ),
                ));
            }
        }
        let mut kvs = Vec::with_capacity(2);
        for (field, deg, count, knots) in [("u_knots", p, m, u_knots), ("v_knots", q, n, v_knots)] {
            // count > deg, so count + deg + 1 <= 2 count fits.
            if knots.len() != count + deg + 1 {
                return Err(Error::of(
                    ErrorKind::Shape,
                    field,
                    format!(
                        "{count} de Boor points of degree {deg} need {count} + {deg} + 1 = {} knots, found {}",
                        count + deg + 1,
                        knots.len()
                    ),
                ));
            }
            kvs.push(KnotVector::new(deg, knots).map_err(|e| rename_knots(e, field))?);
        }
        let v_knots = kvs.pop().expect("two knot vectors");
        let u_knots = kvs.pop().expect("two knot vectors");
        Ok(BSplineSurface {
            u_knots,
            v_knots,
            cols: n,
            dim,
            coords,
        })
    }

    /// The surface of bidegree `degree` = (p, q) on `u_knots` and `v_knots` from the
    /// coordinates of its de Boor grid, row by row (point (k, l) at k n + l), `dim` each; the
    /// grid is m x n with m = `u_knots.len()` - p - 1 and n = `v_knots.len()` - q - 1.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `dim` when it is 0; [`ErrorKind::Empty`] or
    /// [`ErrorKind::Shape`] on `coordinates` when it is empty, not a whole number of points or
    /// not m n points; as [`KnotVector::new`] on `u_knots[...]` and `v_knots[...]`.
    pub fn from_coordinates(
        (p, q): (usize, usize),
        u_knots: Vec<T>,
        v_knots: Vec<T>,
        dim: usize,
        coordinates: Vec<T>,
    ) -> Result<Self> {
        let points = check_flat(&coordinates, dim, "coordinates")?;
        let u_knots = KnotVector::new(p, u_knots).map_err(|e| rename_knots(e, "u_knots"))?;
        let v_knots = KnotVector::new(q, v_knots).map_err(|e| rename_knots(e, "v_knots"))?;
        let (m, n) = (u_knots.control_count(), v_knots.control_count());
        if m.checked_mul(n) != Some(points) {
            return Err(Error::of(
                ErrorKind::Shape,
                "coordinates",
                format!(
                    "the knots of bidegree ({p}, {q}) need a grid of {m} x {n} de Boor points, found {points} points of dimension {dim}"
                ),
            ));
        }
        Ok(BSplineSurface {
            u_knots,
            v_knots,
            cols: n,
            dim,
            coords: coordinates,
        })
    }

    /// The bidegree (p, q).
    pub fn degree(&self) -> (usize, usize) {
        (self.u_knots.degree(), self.v_knots.degree())
    }

    /// The knots in u.
    pub fn u_knots(&self) -> &[T] {
        self.u_knots.knots()
    }

    /// The knots in v.
    pub fn v_knots(&self) -> &[T] {
        self.v_knots.knots()
    }

    /// The validated knot vector in u.
    pub fn u_knot_vector(&self) -> &KnotVector<T> {
        &self.u_knots
    }

    /// The validated knot vector in v.
    pub fn v_knot_vector(&self) -> &KnotVector<T> {
        &self.v_knots
    }

    /// The size (m, n) of the de Boor grid: m rows (along u) of n points (along v).
    pub fn grid_size(&self) -> (usize, usize) {
        (self.coords.len() / (self.cols * self.dim), self.cols)
    }

    /// The de Boor point d_kl (0-based).
    ///
    /// # Panics
    /// When k >= m or l >= n, as slice indexing does.
    pub fn control_point(&self, k: usize, l: usize) -> &[T] {
        let (m, n) = self.grid_size();
        assert!(
            k < m && l < n,
            "de Boor point ({k}, {l}) of a {m} x {n} grid"
        );
        let start = (k * n + l) * self.dim;
        &self.coords[start..start + self.dim]
    }

    /// Row k of the grid: the points d_k0, ..., d_k(n-1).
    ///
    /// # Panics
    /// When k >= m.
    pub fn row(&self, k: usize) -> Points<'_, T> {
        Points::grid_row(&self.coords, self.cols, self.dim, k)
    }

    /// The de Boor grid row by row, k = 0..m: row k is the view of d_k0, ..., d_k(n-1), each
    /// point a `&[T]`.
    pub fn control_points(&self) -> impl ExactSizeIterator<Item = Points<'_, T>> + '_ {
        Points::grid_rows(&self.coords, self.cols, self.dim)
    }

    /// All de Boor points in one view, row by row (point (k, l) at k n + l).
    pub fn points(&self) -> Points<'_, T> {
        Points::new(&self.coords, self.dim)
    }

    /// Every coordinate, row by row, point after point.
    pub fn coordinates(&self) -> &[T] {
        &self.coords
    }

    /// Consumes the surface, returning the coordinates of its grid.
    pub fn into_coordinates(self) -> Vec<T> {
        self.coords
    }

    /// The de Boor grid as nested vectors, `[k][l]` = d_kl (one allocation per point).
    pub fn to_nested(&self) -> Vec<Vec<Point<T>>> {
        self.control_points().map(|r| r.to_vec()).collect()
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The domain [t_{p+1}, t_{m+1}] x [s_{q+1}, s_{n+1}] as `[a, b, c, d]`.
    pub fn domain(&self) -> [&T; 4] {
        let (a, b) = self.u_knots.domain();
        let (c, d) = self.v_knots.domain();
        [a, b, c, d]
    }

    /// The blossom f_στ(us; vs) of the polynomial on the non-empty cell `span` = (σ, τ)
    /// (0-based knot spans `[t_σ, t_σ+1)` in u and `[s_τ, s_τ+1)` in v), by de Boor's algorithm
    /// along v for each of the p + 1 rows, then along u. Errors name `span[0]`/`span[1]` (not a
    /// non-empty domain span) and `us`/`vs` (not p, q arguments).
    pub fn blossom(&self, span: (usize, usize), us: &[T], vs: &[T]) -> Result<Point<T>> {
        let (p, q) = self.degree();
        for (field, kv, s) in [
            ("span[0]", &self.u_knots, span.0),
            ("span[1]", &self.v_knots, span.1),
        ] {
            if !kv.is_span(s) {
                return Err(Error::of(
                    ErrorKind::Domain,
                    field,
                    format!(
                        "{s} is not a non-empty span of the domain (spans: {:?})",
                        kv.spans()
                    ),
                ));
            }
        }
        for (field, deg, args) in [("us", p, us), ("vs", q, vs)] {
            if args.len() != deg {
                return Err(Error::of(
                    ErrorKind::Arity,
                    field,
                    format!(
                        "a blossom of degree {deg} takes {deg} arguments, found {}",
                        args.len()
                    ),
                ));
            }
        }
        let mut scratch = Vec::new();
        self.blossom_in(span, us, vs.iter(), &mut scratch);
        scratch.truncate(self.dim);
        Ok(scratch)
    }

    /// The blossom on the cell (σ, τ) in `scratch`: the column of p + 1 points in its first
    /// (p + 1) D numbers and the working row after it. De Boor along v on the p + 1 rows
    /// k = σ - p..=σ (each window d_k,τ-q..d_kτ is contiguous), each answer one point of the
    /// column, then along u on the column; the answer is the first D numbers of `scratch`.
    fn blossom_in<'a>(
        &self,
        (s, t): (usize, usize),
        us: impl IntoIterator<Item = &'a T>,
        vs: impl Iterator<Item = &'a T> + Clone,
        scratch: &mut Vec<T>,
    ) where
        T: 'a,
    {
        let (p, q) = self.degree();
        let (d, n) = (self.dim, self.cols);
        scratch.clear();
        scratch.resize((p + q + 2) * d, T::zero());
        let (column, row) = scratch.split_at_mut((p + 1) * d);
        for (j, k) in (s - p..=s).enumerate() {
            let start = (k * n + t - q) * d;
            row.clone_from_slice(&self.coords[start..start + (q + 1) * d]);
            de_boor_in_place(&self.v_knots, t, row, d, vs.clone());
            column[j * d..(j + 1) * d].clone_from_slice(&row[..d]);
        }
        de_boor_in_place(&self.u_knots, s, column, d, us);
    }

    /// The non-empty cell (σ, τ) of the point (u, v) (the last span at the right or top end),
    /// or an error naming `u` or `v` outside the domain.
    pub fn span(&self, u: &T, v: &T) -> Result<(usize, usize)> {
        let s = self
            .u_knots
            .span(u)
            .map_err(|e| Error::of(e.kind, "u", e.message))?;
        let t = self
            .v_knots
            .span(v)
            .map_err(|e| Error::of(e.kind, "v", e.message))?;
        Ok((s, t))
    }

    /// F(u, v) left in the first D numbers of `scratch` (see [`BSplineSurface::eval`]).
    pub(crate) fn eval_in<'a>(&self, u: &T, v: &T, scratch: &'a mut Vec<T>) -> Result<&'a [T]> {
        let span = self.span(u, v)?;
        let (p, q) = self.degree();
        self.blossom_in(
            span,
            std::iter::repeat_n(u, p),
            std::iter::repeat_n(v, q),
            scratch,
        );
        Ok(&scratch[..self.dim])
    }

    /// F(u, v) = f_στ(u^p; v^q) by de Boor's algorithm in two passes (rows along v, then the
    /// column along u); an error naming `u` or `v` outside the domain.
    pub fn eval(&self, u: &T, v: &T) -> Result<Point<T>> {
        let mut scratch = Vec::new();
        self.eval_in(u, v, &mut scratch)?;
        scratch.truncate(self.dim);
        Ok(scratch)
    }

    /// [`BSplineSurface::eval`] into `out` (D numbers), with `scratch` as the working space of
    /// de Boor's two passes: no allocation once `scratch` has grown to (p + q + 2) D.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `out` when it does not hold D numbers; otherwise as
    /// [`BSplineSurface::eval`].
    pub fn eval_into(&self, u: &T, v: &T, out: &mut [T], scratch: &mut Vec<T>) -> Result<()> {
        if out.len() != self.dim {
            return Err(wrong_out(self.dim, out.len()));
        }
        out.clone_from_slice(self.eval_in(u, v, scratch)?);
        Ok(())
    }

    /// The Bézier patches, one per non-empty cell (σ, τ) = [a, b] x [c, d], in the order of the
    /// u spans and within each of the v spans: the net f_στ(a^(p-nu) b^nu; c^(q-mu) d^mu), by
    /// the curve's Bézier points of every row along v (p + 1 rows of q + 1 points), then of
    /// the column of those rows (each row one long point of (q + 1) D numbers) along u.
    pub fn bezier_patches(&self) -> Vec<BezierCell<T>> {
        let (p, q) = self.degree();
        let (d, n) = (self.dim, self.cols);
        let (tu, tv) = (self.u_knots(), self.v_knots());
        let width = (q + 1) * d;
        let mut rows = vec![T::zero(); (p + 1) * width];
        let mut scratch = Vec::new();
        let mut out = Vec::new();
        for s in self.u_knots.spans() {
            for t in self.v_knots.spans() {
                for (j, k) in (s - p..=s).enumerate() {
                    let start = (k * n + t - q) * d;
                    bezier_points_into(
                        &self.v_knots,
                        t,
                        &self.coords[start..start + width],
                        d,
                        &mut rows[j * width..(j + 1) * width],
                        &mut scratch,
                    );
                }
                let mut net = vec![T::zero(); rows.len()];
                bezier_points_into(&self.u_knots, s, &rows, width, &mut net, &mut scratch);
                out.push(BezierCell {
                    rect: [
                        tu[s].clone(),
                        tu[s + 1].clone(),
                        tv[t].clone(),
                        tv[t + 1].clone(),
                    ],
                    patch: TensorPatch::from_raw(q + 1, d, net),
                });
            }
        }
        out
    }

    /// The same surface with the knot `x` inserted once into the u knots: the curve insertion
    /// (Theorem 2.2 on the new knot vector) on the column of rows, each row one long point.
    /// An error names `x` outside the u domain, or `u_knots[i]` when x would exceed
    /// multiplicity p + 1.
    pub fn insert_u_knot(&self, x: &T) -> Result<Self> {
        let (s, u_knots) = insertion(&self.u_knots, x).map_err(|e| rename_knots(e, "u_knots"))?;
        let width = self.cols * self.dim;
        let mut coords = Vec::with_capacity(self.coords.len() + width);
        let mut scratch = Vec::new();
        insert_points(
            &self.u_knots,
            &u_knots,
            s,
            &self.coords,
            width,
            &mut coords,
            &mut scratch,
        );
        Ok(BSplineSurface {
            u_knots,
            v_knots: self.v_knots.clone(),
            cols: self.cols,
            dim: self.dim,
            coords,
        })
    }

    /// The same surface with the knot `x` inserted once into the v knots: the curve insertion
    /// on every row. An error names `x` outside the v domain, or `v_knots[i]` when x would
    /// exceed multiplicity q + 1.
    pub fn insert_v_knot(&self, x: &T) -> Result<Self> {
        let (t, v_knots) = insertion(&self.v_knots, x).map_err(|e| rename_knots(e, "v_knots"))?;
        let m = self.grid_size().0;
        let mut coords = Vec::with_capacity(self.coords.len() + m * self.dim);
        let mut scratch = Vec::new();
        for row in self.coords.chunks_exact(self.cols * self.dim) {
            insert_points(
                &self.v_knots,
                &v_knots,
                t,
                row,
                self.dim,
                &mut coords,
                &mut scratch,
            );
        }
        Ok(BSplineSurface {
            u_knots: self.u_knots.clone(),
            v_knots,
            cols: self.cols + 1,
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

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    #[test]
    fn bilinear_values_and_errors() {
        let grid = |v: &[&[i64]]| {
            v.iter()
                .map(|r| r.iter().map(|&x| vec![q(x)]).collect())
                .collect::<Vec<Vec<_>>>()
        };
        let f = BSplineSurface::new(
            (1, 1),
            [0, 0, 1, 1].map(q).to_vec(),
            [0, 0, 1, 1].map(q).to_vec(),
            grid(&[&[0, 1], &[2, 4]]),
        )
        .unwrap();
        // (1 - u)(v) + u((1 - v) 2 + 4 v) at (1/2, 1/2) = 1/4 + 3/2.
        let h = Rational::new(1.into(), 2.into());
        assert_eq!(
            f.eval(&h, &h).unwrap(),
            vec![Rational::new(7.into(), 4.into())]
        );
        assert_eq!(f.eval(&q(2), &h).unwrap_err().field, "u");
        assert_eq!(f.eval(&h, &q(-1)).unwrap_err().field, "v");
        let e = f.insert_u_knot(&q(1)).unwrap_err();
        assert_eq!(
            (e.kind, e.field.as_str()),
            (ErrorKind::Domain, "u_knots[4]")
        );
    }
}
