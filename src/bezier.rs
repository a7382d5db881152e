//! Bézier objects, the output of restriction: a curve over [0, 1], a tensor-product patch over
//! [0, 1]^2 and a triangular patch over its own triangle in barycentric coordinates.
//!
//! Each is evaluated by the pyramid (de Casteljau) algorithm, that is by its blossom with all
//! arguments equal ([`crate::blossoms::pyramid`]).

use crate::blossoms::pyramid;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::power::check_dims;
use crate::Ring;

/// A Bézier curve sum_v w_v B_v^n(t) over t in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<T> {
    control_points: Vec<Point<T>>,
}

impl<T: Ring> BezierCurve<T> {
    /// A curve from its control points `w_0, ..., w_n`, all of one dimension `D >= 1`.
    pub fn new(control_points: Vec<Point<T>>) -> Result<Self> {
        let Some(first) = control_points.first() else {
            return Err(Error::new("control_points", "expected at least one point"));
        };
        if first.is_empty() {
            return Err(Error::new(
                "control_points[0]",
                "expected at least 1 coordinate",
            ));
        }
        check_dims(&control_points, first.len(), "control_points")?;
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
        pyramid::bezier_curve_blossom(&self.control_points, &vec![t.clone(); self.degree()])
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
        let Some(first) = control_points.first() else {
            return Err(Error::new("control_points", "expected at least one row"));
        };
        let cols = first.len();
        if cols == 0 || first[0].is_empty() {
            return Err(Error::new(
                "control_points[0]",
                "expected a non-empty row of points",
            ));
        }
        let dim = first[0].len();
        for (i, row) in control_points.iter().enumerate() {
            if row.len() != cols {
                return Err(Error::new(
                    format!("control_points[{i}]"),
                    format!("expected {cols} points, found {}", row.len()),
                ));
            }
            check_dims(row, dim, &format!("control_points[{i}]"))?;
        }
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

    /// The point at `(s, t)` (two passes of de Casteljau).
    pub fn eval(&self, s: &T, t: &T) -> Point<T> {
        let (n, m) = self.degree();
        pyramid::bezier_tensor_blossom(
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

/// The position of `(nu, mu)` in the lexicographic listing of `{(nu, mu) : nu + mu <= n}`.
pub fn triangle_index(n: usize, nu: usize, mu: usize) -> usize {
    debug_assert!(nu + mu <= n);
    nu * (n + 1) - nu * nu.saturating_sub(1) / 2 + mu
}

/// The number of control points of a triangular patch of degree `n`: (n + 1)(n + 2) / 2.
pub fn triangle_len(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

impl<T: Ring> TriangularPatch<T> {
    /// A patch of degree `degree` from its control points in lexicographic order of
    /// `(nu, mu)`: `(0, 0), (0, 1), ..., (0, N), (1, 0), ..., (N, 0)`.
    pub fn new(degree: usize, control_points: Vec<Point<T>>) -> Result<Self> {
        let want = triangle_len(degree);
        if control_points.len() != want {
            return Err(Error::new(
                "control_points",
                format!(
                    "a triangular patch of degree {degree} has {want} points, found {}",
                    control_points.len()
                ),
            ));
        }
        if control_points[0].is_empty() {
            return Err(Error::new(
                "control_points[0]",
                "expected at least 1 coordinate",
            ));
        }
        check_dims(&control_points, control_points[0].len(), "control_points")?;
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
    pub fn get(&self, nu: usize, mu: usize) -> &Point<T> {
        &self.control_points[triangle_index(self.degree, nu, mu)]
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
        pyramid::bezier_triangle_blossom(self, &vec![bary.clone(); self.degree])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_indices_are_lexicographic() {
        for n in 0..8 {
            let mut k = 0;
            for nu in 0..=n {
                for mu in 0..=n - nu {
                    assert_eq!(triangle_index(n, nu, mu), k);
                    k += 1;
                }
            }
            assert_eq!(k, triangle_len(n));
        }
    }

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
