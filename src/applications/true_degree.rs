//! The true degree of a Bézier curve or patch: the lowest degree at which it is exactly
//! representable, found by exact reduction.
//!
//! A curve of degree n is of degree <= m iff reducing it to m and elevating back to n gives it
//! again: every reduction reproduces curves of degree <= m (seed 004, section 4), and elevation
//! is exact. The search uses [`Reduction::LeastSquares`] (the one method defined down to
//! degree 0) and tries m = 0, 1, ... in turn, so the first success is the true degree.
//! For a tensor patch the degrees in u and v are found one after the other (the degree in u of
//! a patch does not depend on its degree in v), and the returned patch is checked by its own
//! round trip to the input. For a triangular patch the total degree is searched as for curves.
//!
//! The test is equality after the round trip in the arithmetic of `T`. Over exact rings
//! ([`Rational`](crate::Rational), [`Poly`](crate::Poly)) that is exact representability.
//! Over floats it means that the rounded round trip reproduces the input bit for bit: rounding
//! usually prevents that, so a float answer is a degree at which the input is reproduced
//! exactly by the floats, often the stated degree even for a patch that is mathematically of
//! lower degree; use exact input to decide representability.

use crate::applications::degree::{elevate, reduce, Reduction};
use crate::applications::patch_degree::tensor::{elevate_tensor, reduce_tensor};
use crate::applications::patch_degree::triangle::{elevate_triangle, reduce_triangle};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::Ring;

const LS: Reduction = Reduction::LeastSquares;
const VALID: &str = "a least-squares reduction to a lower degree of a valid input";

/// The lowest degree m at which `curve` is exactly representable, with the curve of degree m
/// that elevates to it.
///
/// ```
/// use blossom::{true_degree, BezierCurve, Rational};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // 0, 1, 2, 3 lie on a line: the cubic is the line from 0 to 3.
/// let c = BezierCurve::new(vec![vec![q(0)], vec![q(1)], vec![q(2)], vec![q(3)]])?;
/// let (m, line) = true_degree(&c);
/// assert_eq!(m, 1);
/// assert_eq!(line.control_points(), vec![vec![q(0)], vec![q(3)]]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn true_degree<T: Ring>(curve: &BezierCurve<T>) -> (usize, BezierCurve<T>) {
    let n = curve.degree();
    for m in 0..n {
        let low = reduce(curve, m, LS).expect(VALID);
        if &elevate(&low, n).expect("elevation to a higher degree") == curve {
            return (m, low);
        }
    }
    (n, curve.clone())
}

/// `patch` reduced to `to` (returned as is when `to` is its bidegree) if the round trip back
/// to its bidegree reproduces it.
fn tensor_at<T: Ring>(patch: &TensorPatch<T>, to: (usize, usize)) -> Option<TensorPatch<T>> {
    if to == patch.degree() {
        return Some(patch.clone());
    }
    let low = reduce_tensor(patch, to, LS).expect(VALID);
    let back = elevate_tensor(&low, patch.degree()).expect("elevation to a higher degree");
    (&back == patch).then_some(low)
}

/// The lowest bidegree (n', m') at which `patch` is exactly representable (the lowest degree
/// in each variable), with the patch of that bidegree that elevates to it.
///
/// ```
/// use blossom::{elevate_tensor, tensor_true_degree, Rational, TensorPatch};
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = TensorPatch::new(vec![vec![vec![q(1)], vec![q(4)], vec![q(0)]]])?;
/// let (d, low) = tensor_true_degree(&elevate_tensor(&p, (3, 4))?);
/// assert_eq!((d, low), ((0, 2), p));
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn tensor_true_degree<T: Ring>(patch: &TensorPatch<T>) -> ((usize, usize), TensorPatch<T>) {
    let (n, m) = patch.degree();
    let nu = (0..=n)
        .find(|&k| tensor_at(patch, (k, m)).is_some())
        .expect("the patch is of its own bidegree");
    (0..=m)
        .find_map(|l| tensor_at(patch, (nu, l)).map(|low| ((nu, l), low)))
        .expect("the patch is of bidegree (n', m) with n' found above")
}

/// The lowest total degree at which `patch` is exactly representable, with the patch of that
/// degree that elevates to it.
///
/// ```
/// use blossom::{elevate_triangle, triangle_true_degree, Rational, TriangularPatch};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // u + v (q_001 = 0, q_010 = q_100 = 1), written at degree 2, is of degree 1.
/// let p = TriangularPatch::new(1, vec![vec![q(0)], vec![q(1)], vec![q(1)]])?;
/// assert_eq!(triangle_true_degree(&elevate_triangle(&p, 2)?), (1, p));
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn triangle_true_degree<T: Ring>(patch: &TriangularPatch<T>) -> (usize, TriangularPatch<T>) {
    let n = patch.degree();
    for m in 0..n {
        let low = reduce_triangle(patch, m, LS).expect(VALID);
        if &elevate_triangle(&low, n).expect("elevation to a higher degree") == patch {
            return (m, low);
        }
    }
    (n, patch.clone())
}
