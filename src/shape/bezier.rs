//! Bézier objects, the output of restriction: a curve over [0, 1], a tensor-product patch over
//! [0, 1]^2 and a triangular patch over its own triangle in barycentric coordinates.
//!
//! Each is evaluated by de Casteljau's algorithm, its own blossom with all arguments equal
//! (seed 004, section 2):
//!
//! * curve, eq. (2) of 004: b^r_i[t_1..t_r] = (1 - t_r) b^{r-1}_i + t_r b^{r-1}_{i+1}, and the
//!   blossom is b^n_0[t_1..t_n];
//! * tensor patch, eq. (9) of 004: `b[u_1..u_n; v_1..v_m] = b[u_1..u_n][v_1..v_m]`, the curve
//!   algorithm along v for every row, then along u;
//! * triangle: b^r_{ijk} = u_r b^{r-1}_{i+1,j,k} + v_r b^{r-1}_{i,j+1,k} + w_r b^{r-1}_{i,j,k+1}
//!   for barycentric arguments (u_r, v_r, w_r).

use crate::error::{check_arity, Error, ErrorKind, Result};
use crate::num::limits::check_entries;
use crate::num::meter::charge_points;
use crate::shape::point::lerp;
use crate::shape::point::Point;
use crate::shape::power::check_dims;
use crate::shape::simplex::{checked_triangle_len, triangle_index, triangle_len};
use crate::Ring;

/// Checks a control polygon `points` (about `field`): at least one point, all of one
/// dimension D >= 1.
fn check_polygon<T>(points: &[Point<T>], field: &str) -> Result<()> {
    let Some(first) = points.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            field,
            "expected at least one point",
        ));
    };
    if first.is_empty() {
        return Err(Error::of(
            ErrorKind::Dimension,
            format!("{field}[0]"),
            "expected at least 1 coordinate",
        ));
    }
    check_dims(points, first.len(), field)
}

/// Checks a control net `net[nu][mu]` (about `field`): at least one row, all rows of one
/// non-zero length, all points of one dimension D >= 1.
fn check_net<T>(net: &[Vec<Point<T>>], field: &str) -> Result<()> {
    let Some(first) = net.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            field,
            "expected at least one row",
        ));
    };
    let cols = first.len();
    if cols == 0 || first[0].is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            format!("{field}[0]"),
            "expected a non-empty row of points",
        ));
    }
    let dim = first[0].len();
    for (i, row) in net.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::of(
                ErrorKind::Shape,
                format!("{field}[{i}]"),
                format!("expected {cols} points, found {}", row.len()),
            ));
        }
        check_dims(row, dim, &format!("{field}[{i}]"))?;
    }
    Ok(())
}

/// Checks a triangular net `points` of degree `degree` (about `degree_field` and
/// `points_field`): (N + 1)(N + 2) / 2 points, a count that must not overflow nor exceed
/// [`MAX_ENTRIES`](crate::MAX_ENTRIES), all of one dimension D >= 1.
pub(crate) fn check_triangle_net<T>(
    degree: usize,
    points: &[Point<T>],
    degree_field: &str,
    points_field: &str,
) -> Result<()> {
    let want = check_entries(
        checked_triangle_len(degree),
        degree_field,
        "the number of control points (N + 1)(N + 2) / 2",
    )?;
    if points.len() != want {
        return Err(Error::of(
            ErrorKind::Shape,
            points_field,
            format!(
                "a triangular patch of degree {degree} has {want} points, found {}",
                points.len()
            ),
        ));
    }
    check_polygon(points, points_field)
}

/// A Bézier curve sum_v w_v B_v^n(t) over t in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<T> {
    control_points: Vec<Point<T>>,
}

impl<T: Ring> BezierCurve<T> {
    /// A curve from its control points `w_0, ..., w_n`, all of one dimension `D >= 1`.
    pub fn new(control_points: Vec<Point<T>>) -> Result<Self> {
        check_polygon(&control_points, "control_points")?;
        Ok(BezierCurve { control_points })
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.control_points.len() - 1
    }

    /// The control points `w_0, ..., w_n`.
    pub fn control_points(&self) -> &[Point<T>] {
        &self.control_points
    }

    /// Consumes the curve, returning its control points.
    pub fn into_control_points(self) -> Vec<Point<T>> {
        self.control_points
    }

    /// The point at parameter `t` (de Casteljau).
    pub fn eval(&self, t: &T) -> Point<T> {
        curve_blossom_unchecked(&self.control_points, &vec![t.clone(); self.degree()])
    }
}

/// A tensor-product Bézier patch sum_{nu, mu} p_{nu mu} B_nu^n(s) B_mu^m(t) over [0, 1]^2.
#[derive(Clone, Debug, PartialEq)]
pub struct TensorPatch<T> {
    control_points: Vec<Vec<Point<T>>>,
}

impl<T: Ring> TensorPatch<T> {
    /// A patch from its control net, `net[nu][mu]` = `p_{nu mu}`: `n + 1` rows of `m + 1`
    /// points, all of one dimension.
    pub fn new(control_points: Vec<Vec<Point<T>>>) -> Result<Self> {
        check_net(&control_points, "control_points")?;
        Ok(TensorPatch { control_points })
    }

    /// The bidegree `(n, m)`.
    pub fn degree(&self) -> (usize, usize) {
        (
            self.control_points.len() - 1,
            self.control_points[0].len() - 1,
        )
    }

    /// The control net, `[nu][mu]`.
    pub fn control_points(&self) -> &[Vec<Point<T>>] {
        &self.control_points
    }

    /// Consumes the patch, returning its control net.
    pub fn into_control_points(self) -> Vec<Vec<Point<T>>> {
        self.control_points
    }

    /// Every coordinate of the net in one run, row after row (the layout of the engine).
    pub(crate) fn flat_coordinates(&self) -> Vec<T> {
        self.control_points
            .iter()
            .flatten()
            .flatten()
            .cloned()
            .collect()
    }

    /// The point at `(s, t)` (two passes of de Casteljau).
    pub fn eval(&self, s: &T, t: &T) -> Point<T> {
        let (n, m) = self.degree();
        tensor_blossom_unchecked(
            &self.control_points,
            &vec![s.clone(); n],
            &vec![t.clone(); m],
        )
    }
}

/// A triangular Bézier patch of total degree N over a triangle `abc`:
/// sum_{nu + mu + lambda = N} q_{nu mu lambda} N!/(nu! mu! lambda!) s^nu t^mu r^lambda in the
/// barycentric coordinates (s, t, r) of the triangle's corners (a, b, c).
///
/// The control point `q_{nu mu lambda}` is the blossom value at `a^nu, b^mu, c^lambda`
/// (equation (12)); points are stored in lexicographic order of `(nu, mu)`.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangularPatch<T> {
    degree: usize,
    control_points: Vec<Point<T>>,
}

impl<T: Ring> TriangularPatch<T> {
    /// A patch of degree `degree` from its control points in lexicographic order of
    /// `(nu, mu)`: `(0, 0), (0, 1), ..., (0, N), (1, 0), ..., (N, 0)`.
    ///
    /// # Errors
    /// [`ErrorKind::TooLarge`] on `degree` when (N + 1)(N + 2) / 2 overflows or exceeds
    /// [`MAX_ENTRIES`](crate::MAX_ENTRIES); [`ErrorKind::Shape`] on `control_points` when there
    /// are not that many points; [`ErrorKind::Dimension`] when a point has no coordinate or
    /// another dimension than the first.
    pub fn new(degree: usize, control_points: Vec<Point<T>>) -> Result<Self> {
        check_triangle_net(degree, &control_points, "degree", "control_points")?;
        Ok(TriangularPatch {
            degree,
            control_points,
        })
    }

    /// The total degree `N`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control point `q_{nu mu lambda}` with `lambda = N - nu - mu`.
    ///
    /// # Panics
    /// When `nu + mu > N`, as slice indexing does; [`TriangularPatch::try_get`] returns `None`
    /// instead.
    pub fn get(&self, nu: usize, mu: usize) -> &Point<T> {
        self.try_get(nu, mu).unwrap_or_else(|| {
            panic!(
                "index (nu, mu) = ({nu}, {mu}) out of range for a triangular patch of degree {}",
                self.degree
            )
        })
    }

    /// The control point `q_{nu mu lambda}` with `lambda = N - nu - mu`, or `None` when
    /// `nu + mu > N`.
    pub fn try_get(&self, nu: usize, mu: usize) -> Option<&Point<T>> {
        let in_range = nu.checked_add(mu).is_some_and(|s| s <= self.degree);
        in_range.then(|| &self.control_points[triangle_index(self.degree, nu, mu)])
    }

    /// All control points in lexicographic order of `(nu, mu)`.
    pub fn control_points(&self) -> &[Point<T>] {
        &self.control_points
    }

    /// `(nu, mu, lambda, q)` for every control point, in lexicographic order of `(nu, mu)`.
    pub fn entries(&self) -> impl Iterator<Item = (usize, usize, usize, &Point<T>)> {
        let n = self.degree;
        (0..=n)
            .flat_map(move |nu| (0..=n - nu).map(move |mu| (nu, mu)))
            .zip(&self.control_points)
            .map(move |((nu, mu), q)| (nu, mu, n - nu - mu, q))
    }

    /// The point with barycentric coordinates `(s, t, r)` (`s + t + r = 1`), by de Casteljau.
    pub fn eval(&self, bary: &[T; 3]) -> Point<T> {
        triangle_blossom_unchecked(self, &vec![bary.clone(); self.degree])
    }
}

// De Casteljau's algorithm on the blossom (seed 004, section 2): the evaluation of every
// Bézier shape, and its blossom at any arguments.

/// The blossom b[t_1, ..., t_n] of the Bézier curve with control points `control` (degree
/// `n = control.len() - 1 = args.len()`), eq. (2) of seed 004.
///
/// # Errors
/// [`ErrorKind::Empty`] or [`ErrorKind::Dimension`] on `control` as [`BezierCurve::new`];
/// [`ErrorKind::Arity`] on `args` when `args.len() + 1 != control.len()`.
pub fn bezier_curve_blossom<T: Ring>(control: &[Point<T>], args: &[T]) -> Result<Point<T>> {
    check_polygon(control, "control")?;
    check_arity("args", args.len(), control.len() - 1)?;
    Ok(curve_blossom_unchecked(control, args))
}

/// [`bezier_curve_blossom`] on input known to fit: a non-empty polygon of one dimension and
/// `args.len() + 1 == control.len()`.
pub(crate) fn curve_blossom_unchecked<T: Ring>(control: &[Point<T>], args: &[T]) -> Point<T> {
    debug_assert_eq!(args.len() + 1, control.len());
    charge_points(control.len());
    let mut level: Vec<Point<T>> = control.to_vec();
    for t in args {
        charge_points(level.len());
        level = level.windows(2).map(|w| lerp(&w[0], &w[1], t)).collect();
    }
    level.pop().expect("one point remains")
}

/// The blossom b[u_1..u_n; v_1..v_m] of the tensor patch with net `net[nu][mu]`, in two passes
/// (eq. (9) of seed 004): along v for every row, then along u.
///
/// # Errors
/// [`ErrorKind::Empty`], [`ErrorKind::Shape`] or [`ErrorKind::Dimension`] on `net` as
/// [`TensorPatch::new`]; [`ErrorKind::Arity`] on `us` (`vs`) when it does not hold n (m)
/// arguments for n + 1 rows (m + 1 columns).
pub fn bezier_tensor_blossom<T: Ring>(
    net: &[Vec<Point<T>>],
    us: &[T],
    vs: &[T],
) -> Result<Point<T>> {
    check_net(net, "net")?;
    check_arity("us", us.len(), net.len() - 1)?;
    check_arity("vs", vs.len(), net[0].len() - 1)?;
    Ok(tensor_blossom_unchecked(net, us, vs))
}

/// [`bezier_tensor_blossom`] on input known to fit.
pub(crate) fn tensor_blossom_unchecked<T: Ring>(
    net: &[Vec<Point<T>>],
    us: &[T],
    vs: &[T],
) -> Point<T> {
    let column: Vec<Point<T>> = net
        .iter()
        .map(|row| curve_blossom_unchecked(row, vs))
        .collect();
    curve_blossom_unchecked(&column, us)
}

/// The blossom of a triangular patch at barycentric arguments (u_r, v_r, w_r) (weights of the
/// patch's corners a, b, c), by the triangular pyramid.
///
/// # Errors
/// [`ErrorKind::Arity`] on `args` when it does not hold N arguments for a patch of degree N.
pub fn bezier_triangle_blossom<T: Ring>(
    patch: &TriangularPatch<T>,
    args: &[[T; 3]],
) -> Result<Point<T>> {
    check_arity("args", args.len(), patch.degree())?;
    Ok(triangle_blossom_unchecked(patch, args))
}

/// [`bezier_triangle_blossom`] with `args.len()` known to be the degree.
pub(crate) fn triangle_blossom_unchecked<T: Ring>(
    patch: &TriangularPatch<T>,
    args: &[[T; 3]],
) -> Point<T> {
    let n = patch.degree();
    debug_assert_eq!(args.len(), n);
    charge_points(patch.control_points().len());
    let mut level: Vec<Point<T>> = patch.control_points().to_vec();
    for (r, [u, v, w]) in args.iter().enumerate() {
        let d = n - r - 1;
        charge_points(triangle_len(d));
        let mut next = Vec::with_capacity(triangle_len(d));
        for i in 0..=d {
            for j in 0..=d - i {
                let pa = &level[triangle_index(d + 1, i + 1, j)];
                let pb = &level[triangle_index(d + 1, i, j + 1)];
                let pc = &level[triangle_index(d + 1, i, j)];
                let q = pa
                    .iter()
                    .zip(pb)
                    .zip(pc)
                    .map(|((x, y), z)| u.mul(x).add(&v.mul(y)).add(&w.mul(z)))
                    .collect();
                next.push(q);
            }
        }
        level = next;
    }
    level.pop().expect("one point remains")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoints_interpolate() {
        let c = BezierCurve::new(vec![vec![0.0, 1.0], vec![5.0, 7.0], vec![2.0, 3.0]]).unwrap();
        assert_eq!(c.eval(&0.0), vec![0.0, 1.0]);
        assert_eq!(c.eval(&1.0), vec![2.0, 3.0]);
        assert_eq!(c.eval(&0.5), vec![3.0, 4.5]);
        let t = TriangularPatch::new(1, vec![vec![1.0], vec![2.0], vec![3.0]]).unwrap();
        // q_001 = c-corner, q_010 = b-corner, q_100 = a-corner.
        assert_eq!(t.eval(&[1.0, 0.0, 0.0]), vec![3.0]);
        assert_eq!(t.eval(&[0.0, 0.0, 1.0]), vec![1.0]);
        assert!(TriangularPatch::new(2, vec![vec![1.0]; 5]).is_err());
    }
}
