//! Degree elevation and reduction of Bézier curves over [0, 1], exactly.
//!
//! * **Elevation** from degree n to m >= n: b'_j = sum_i C(n, i) C(m - n, j - i) / C(m, j) b_i
//!   (the product of B_i^n with sum_k B_k^(m-n) = 1). Seed 004 notes that the inverse formula has
//!   elevation built in (eq. (22) at degree m applied to a curve of degree n); the tests prove
//!   both identical.
//! * **Reduction** from degree n to m < n, three ways (seed 004, section 4, Example 2):
//!   - [`Reduction::Interpolating`]: the inverse formula (22) of degree m applied to the curve
//!     on [0, 1] ([`crate::curve_control_points_from_samples`]); it keeps both end points and
//!     reproduces curves of degree <= m;
//!   - [`Reduction::LeastSquares`]: the L2-best curve of degree m on [0, 1], from the normal
//!     equations G_mm x = G_mn b with the Gram matrices of the Bernstein bases;
//!   - [`Reduction::LeastSquaresEndpoints`]: the L2-best curve with x_0 = b_0 and x_m = b_n.
//! * **Errors**: the squared L2 distance int_0^1 |x(t) - b(t)|^2 dt of two Bézier curves, exactly,
//!   from the closed-form Gram matrix
//!   int_0^1 B_i^m B_j^n dt = C(m, i) C(n, j) / ((m + n + 1) C(m + n, i + j)).

use crate::error::{Error, ErrorKind, Result};
use crate::num::binomial::binomial;
use crate::num::linalg;
use crate::restrict::polarisation::curve_control_points_from_samples;
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;
use crate::{Rational, Ring};

/// How [`reduce`] lowers the degree.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Reduction {
    /// The inverse formula (22) of the lower degree applied to the curve (interpolation at
    /// the sample points of the formula; keeps both end points).
    Interpolating,
    /// Least squares in L2 on [0, 1].
    LeastSquares,
    /// Least squares in L2 on [0, 1] with both end points kept.
    LeastSquaresEndpoints,
}

impl Reduction {
    /// Every method.
    pub const ALL: [Reduction; 3] = [
        Reduction::Interpolating,
        Reduction::LeastSquares,
        Reduction::LeastSquaresEndpoints,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Reduction::Interpolating => "interpolating",
            Reduction::LeastSquares => "least-squares",
            Reduction::LeastSquaresEndpoints => "least-squares-endpoints",
        }
    }

    /// The method called `name` on the command line.
    pub fn from_name(name: &str) -> Result<Self> {
        Reduction::ALL
            .into_iter()
            .find(|r| r.name() == name)
            .ok_or_else(|| {
                Error::of(
                    ErrorKind::UnknownName,
                    "method",
                    format!(
                        "unknown method {name:?}; expected one of {}",
                        Reduction::ALL.map(|r| format!("{:?}", r.name())).join(", ")
                    ),
                )
            })
    }
}

fn frac(num: num_bigint::BigInt, den: num_bigint::BigInt) -> Rational {
    Rational::new(num, den)
}

/// The matrix `[j][i]` = C(n, i) C(m - n, j - i) / C(m, j) of elevation from degree n to m.
pub fn elevation_matrix(n: usize, m: usize) -> Vec<Vec<Rational>> {
    let (n, m) = (n as i64, m as i64);
    (0..=m)
        .map(|j| {
            (0..=n)
                .map(|i| frac(binomial(n, i) * binomial(m - n, j - i), binomial(m, j)))
                .collect()
        })
        .collect()
}

/// The Gram matrix `[i][j]` = int_0^1 B_i^m(t) B_j^n(t) dt = C(m, i) C(n, j) / ((m + n + 1) C(m + n, i + j)).
pub fn bernstein_gram(m: usize, n: usize) -> Vec<Vec<Rational>> {
    let (m, n) = (m as i64, n as i64);
    (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    frac(
                        binomial(m, i) * binomial(n, j),
                        binomial(m + n, i + j) * (m + n + 1),
                    )
                })
                .collect()
        })
        .collect()
}

/// `curve` (degree n) written at degree `to_degree` >= n, exactly.
///
/// ```
/// use blossom::elevate;
/// use blossom::BezierCurve;
/// // The line from 0 to 3 as a cubic: 0, 1, 2, 3.
/// let line = BezierCurve::new(vec![vec![0.0], vec![3.0]])?;
/// assert_eq!(elevate(&line, 3)?.control_points(), &[vec![0.0], vec![1.0], vec![2.0], vec![3.0]]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn elevate<T: Ring>(curve: &BezierCurve<T>, to_degree: usize) -> Result<BezierCurve<T>> {
    let n = curve.degree();
    if to_degree < n {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!(
                "elevation needs to_degree >= {n} (the degree of the curve), found {to_degree}"
            ),
        ));
    }
    let dim = curve.dim();
    let points = linalg::apply(
        &elevation_matrix(n, to_degree),
        &curve.control_points().to_vec(),
        dim,
    );
    BezierCurve::new(points)
}

/// A Bézier curve of degree `to_degree` < n approximating `curve` on [0, 1] by `method`.
///
/// The interpolating and end-point-keeping methods need `to_degree >= 1` (eq. (22) has no
/// term for degree 0, and a constant cannot keep two different end points).
pub fn reduce<T: Ring>(
    curve: &BezierCurve<T>,
    to_degree: usize,
    method: Reduction,
) -> Result<BezierCurve<T>> {
    let n = curve.degree();
    let m = to_degree;
    if m >= n {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!("reduction needs to_degree < {n} (the degree of the curve), found {m}"),
        ));
    }
    if m == 0 && method != Reduction::LeastSquares {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!("the {} reduction needs to_degree >= 1", method.name()),
        ));
    }
    let b = curve.control_points();
    let dim = b[0].len();
    let points = match method {
        Reduction::Interpolating => {
            let zero = T::zero();
            let one = T::one();
            curve_control_points_from_samples(m, &zero, &one, &|t| curve.eval(t))
        }
        Reduction::LeastSquares | Reduction::LeastSquaresEndpoints => {
            linalg::apply(&least_squares_matrix(n, m, method)?, &b.to_vec(), dim)
        }
    };
    BezierCurve::new(points)
}

/// The exact matrix R (m + 1 rows, n + 1 columns) with x = R b for the least-squares
/// reductions from degree n to m: R = G_mm^-1 G_mn for [`Reduction::LeastSquares`] (the normal
/// equations G_mm x = G_mn b), and for [`Reduction::LeastSquaresEndpoints`] the rows e_0 and
/// e_n (x_0 = b_0, x_m = b_n) around the solution of the interior normal equations
/// `sum_{j=1..m-1} G[i][j] x_j = (G_mn b)_i - G[i][0] b_0 - G[i][m] b_n`, i = 1..m-1.
///
/// The matrix is formed exactly before it meets the points, so that floats are rounded only in
/// the final combination instead of passing through the ill-conditioned normal equations.
/// The end-point-keeping matrix needs `m >= 1` (error [`ErrorKind::Degree`] on `to_degree`).
pub fn least_squares_matrix(n: usize, m: usize, method: Reduction) -> Result<Vec<Vec<Rational>>> {
    let fixed: &[(usize, usize)] = match method {
        Reduction::LeastSquares => &[],
        Reduction::LeastSquaresEndpoints if m == 0 => {
            return Err(Error::of(
                ErrorKind::Degree,
                "to_degree",
                "a constant cannot keep both end points: to_degree must be >= 1",
            ))
        }
        Reduction::LeastSquaresEndpoints => &[(0, 0), (m, n)],
        Reduction::Interpolating => return Err(not_a_matrix()),
    };
    linalg::least_squares_operator(
        &bernstein_gram(m, m),
        &bernstein_gram(m, n),
        fixed,
        "to_degree",
    )
}

/// The error of asking the interpolating reduction for a least-squares matrix.
pub(crate) fn not_a_matrix() -> Error {
    Error::of(
        ErrorKind::Invalid,
        "method",
        "the interpolating reduction is the inverse formula, not a least-squares matrix",
    )
}

/// The squared L2 distance int_0^1 |a(t) - b(t)|^2 dt of two Bézier curves over [0, 1] of any
/// degrees and one dimension, exactly (`a` is elevated to the degree of `b` or vice versa,
/// and the difference d gives sum_coords d^T G d).
pub fn squared_l2_distance<T: Ring>(a: &BezierCurve<T>, b: &BezierCurve<T>) -> Result<T> {
    check_same_dimension(
        &a.control_points().to_vec(),
        &b.control_points().to_vec(),
        "curves",
    )?;
    let n = a.degree().max(b.degree());
    let (ea, eb) = (elevate(a, n)?, elevate(b, n)?);
    let diff = linalg::differences(&ea.control_points().to_vec(), &eb.control_points().to_vec());
    Ok(linalg::gram_quadratic_form(&bernstein_gram(n, n), &diff))
}

/// An error of kind [`ErrorKind::Dimension`] on `control_points` unless the first points of
/// `a` and `b` (two `what`, e.g. "curves") have the same number of coordinates.
pub(crate) fn check_same_dimension<T>(a: &[Point<T>], b: &[Point<T>], what: &str) -> Result<()> {
    let (da, db) = (a[0].len(), b[0].len());
    if da == db {
        Ok(())
    } else {
        Err(Error::of(
            ErrorKind::Dimension,
            "control_points",
            format!("{what} of dimensions {da} and {db} cannot be compared"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::basis::bernstein_to_power;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn gram_rows_sum_to_the_integral_of_a_bernstein_polynomial() {
        // sum_j int B_i^m B_j^n = int B_i^m = 1 / (m + 1).
        for (m, n) in [(0, 0), (2, 3), (5, 4)] {
            for row in bernstein_gram(m, n) {
                assert_eq!(row.iter().sum::<Rational>(), q(1, m as i64 + 1));
            }
        }
    }

    #[test]
    fn power_and_bernstein_are_inverse() {
        let b: Vec<Point<Rational>> = [3, -1, 4, 1, -5, 9]
            .iter()
            .map(|&x| vec![q(x, 7)])
            .collect();
        let c = bernstein_to_power(&b);
        assert_eq!(crate::shape::basis::power_to_bernstein(&c), b);
        // 1 - 2t + t^2 = (1 - t)^2 has control points 1, 0, 0.
        let sq = bernstein_to_power(&[vec![q(1, 1)], vec![q(0, 1)], vec![q(0, 1)]]);
        assert_eq!(sq, vec![vec![q(1, 1)], vec![q(-2, 1)], vec![q(1, 1)]]);
    }

    #[test]
    fn reduction_errors_name_the_field() {
        let c = BezierCurve::new(vec![vec![q(0, 1)], vec![q(1, 1)], vec![q(0, 1)]]).unwrap();
        assert_eq!(
            reduce(&c, 2, Reduction::LeastSquares).unwrap_err().field,
            "to_degree"
        );
        assert_eq!(
            reduce(&c, 0, Reduction::Interpolating).unwrap_err().field,
            "to_degree"
        );
        assert_eq!(elevate(&c, 1).unwrap_err().field, "to_degree");
        assert!(Reduction::from_name("chebyshev")
            .unwrap_err()
            .message
            .contains("least-squares-endpoints"));
        // The mean of the parabola 2t(1-t) is 1/3.
        let mean = reduce(&c, 0, Reduction::LeastSquares).unwrap();
        assert_eq!(mean.control_points(), &[vec![q(1, 3)]]);
    }
}
