//! Degree elevation and reduction of tensor-product Bézier patches over [0, 1]^2, exactly.
//!
//! * **Elevation** from bidegree (n, m) to (n', m') >= (n, m): the curve elevation
//!   ([`crate::engine::elevation_matrix`]) along u for the rows of the net, then along v for each row.
//! * **Reduction** to (n', m') <= (n, m), lower in at least one variable, by a [`Reduction`]:
//!   - interpolating: eq. (22) of seed 004 in two passes at the lower bidegree, applied to the
//!     patch as the sampled surface ([`crate::tensor_control_points_from_samples`] on
//!     [0, 1] x [0, 1]); it keeps the four corners and reproduces patches of bidegree
//!     <= (n', m');
//!   - least squares: the L2-best patch over [0, 1]^2, from the normal equations
//!     G x = G' b with G = G_n'n' (x) G_m'm' and G' = G_n'n (x) G_m'm, where (x) is the
//!     Kronecker product and G_ab the curve Gram matrix [`crate::engine::bernstein_gram`]:
//!     int int B_i^a(u) B_j^c(v) B_k^b(u) B_l^d(v) du dv = G_ab[i][k] G_cd[j][l]
//!     (Fubini);
//!   - least squares keeping the four corners p_00, p_0m, p_n0, p_nm (the end points of the
//!     four boundary curves): the same normal equations with those four unknowns pinned.
//! * **Errors**: int int |a - b|^2 du dv = d^T G d (coordinate-wise), with d the difference
//!   of the two nets elevated to a common bidegree.
//!
//! Nets are flattened row-major, index (i, j) -> i (m + 1) + j, matching the Kronecker product.

use super::{check_count, check_higher_degree, check_lower_degree};
use crate::applications::degree::{
    bernstein_gram, check_same_dimension, elevation_matrix, not_a_matrix, Reduction,
};
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg;
use crate::restrict::polarisation::tensor_control_points_from_samples;
use crate::shape::bezier::TensorPatch;
use crate::shape::point::{self, Point};
use crate::{Rational, Ring};

/// The Gram matrix of the tensor Bernstein bases of bidegrees `a` and `b` over [0, 1]^2:
/// `[i (a.1 + 1) + j][k (b.1 + 1) + l]` = int int B_i^a.0(u) B_j^a.1(v) B_k^b.0(u) B_l^b.1(v)
/// du dv, the Kronecker product of the curve Gram matrices `bernstein_gram(a.0, b.0)` and
/// `bernstein_gram(a.1, b.1)`.
pub fn tensor_bernstein_gram(a: (usize, usize), b: (usize, usize)) -> Vec<Vec<Rational>> {
    linalg::kronecker(&bernstein_gram(a.0, b.0), &bernstein_gram(a.1, b.1))
}

/// The number of control points of bidegree `d`, checked.
fn net_len((n, m): (usize, usize)) -> Result<usize> {
    check_count(
        n.checked_add(1)
            .zip(m.checked_add(1))
            .and_then(|(a, b)| a.checked_mul(b)),
    )
}

/// `patch` (bidegree (n, m)) written at bidegree `to_degree` >= (n, m) in each variable,
/// exactly.
///
/// ```
/// use blossom::{elevate_tensor, TensorPatch};
/// // The bilinear patch u v as a biquadratic: only the corner (2, 2) is 1, the middle 1/4.
/// let uv = TensorPatch::new(vec![vec![vec![0.0], vec![0.0]], vec![vec![0.0], vec![1.0]]])?;
/// let e = elevate_tensor(&uv, (2, 2))?;
/// assert_eq!(e.get(1, 1), &[0.25][..]);
/// assert_eq!(e.get(2, 2), &[1.0][..]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn elevate_tensor<T: Ring>(
    patch: &TensorPatch<T>,
    to_degree: (usize, usize),
) -> Result<TensorPatch<T>> {
    let (n, m) = patch.degree();
    check_higher_degree(n, to_degree.0, "in u")?;
    check_higher_degree(m, to_degree.1, "in v")?;
    net_len(to_degree)?;
    let dim = patch.dim();
    // Along u: each row of the net is one long point.
    let rows = linalg::apply(
        &elevation_matrix(n, to_degree.0),
        &point::flatten(&patch.to_nested()),
        dim * (m + 1),
    );
    let ev = elevation_matrix(m, to_degree.1);
    let net = point::unflatten(rows, dim)
        .iter()
        .map(|row| linalg::apply(&ev, row, dim))
        .collect();
    TensorPatch::new(net)
}

/// Checks a reduction from bidegree `from` to `to`: no higher in either variable, lower in at
/// least one, and degree 0 only where the method allows it.
fn check_reduction(from: (usize, usize), to: (usize, usize), method: Reduction) -> Result<()> {
    check_lower_degree(from.0, to.0, method, "in u")?;
    check_lower_degree(from.1, to.1, method, "in v")?;
    if from == to {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!(
                "reduction needs a bidegree lower than {from:?} in at least one variable, found {to:?}"
            ),
        ));
    }
    Ok(())
}

/// The exact matrix R ((n'+1)(m'+1) rows, (n+1)(m+1) columns, row-major nets) with x = R b
/// for the least-squares reductions from bidegree `from` = (n, m) to `to` = (n', m'):
/// R = G^-1 G' for [`Reduction::LeastSquares`], and for [`Reduction::LeastSquaresEndpoints`]
/// the unit rows of the four corners around the solution of the normal equations of the other
/// unknowns (see the module documentation).
pub fn tensor_least_squares_matrix(
    from: (usize, usize),
    to: (usize, usize),
    method: Reduction,
) -> Result<Vec<Vec<Rational>>> {
    check_reduction(from, to, method)?;
    net_len(from)?;
    net_len(to)?;
    let (low, high) = (
        |i: usize, j: usize| i * (to.1 + 1) + j,
        |k: usize, l: usize| k * (from.1 + 1) + l,
    );
    let fixed: Vec<(usize, usize)> = match method {
        Reduction::LeastSquares => Vec::new(),
        Reduction::LeastSquaresEndpoints => {
            let mut corners = vec![
                (low(0, 0), high(0, 0)),
                (low(0, to.1), high(0, from.1)),
                (low(to.0, 0), high(from.0, 0)),
                (low(to.0, to.1), high(from.0, from.1)),
            ];
            // A variable of degree 0 in both has one end: its corners coincide.
            corners.sort_unstable();
            corners.dedup();
            corners
        }
        Reduction::Interpolating => return Err(not_a_matrix()),
    };
    linalg::least_squares_operator(
        &tensor_bernstein_gram(to, to),
        &tensor_bernstein_gram(to, from),
        &fixed,
        "to_degree",
    )
}

/// A tensor patch of bidegree `to_degree` (no higher than that of `patch` in either variable,
/// lower in at least one) approximating `patch` on [0, 1]^2 by `method`.
///
/// The interpolating and corner-keeping methods need `to_degree >= 1` in every variable whose
/// degree drops.
///
/// ```
/// use blossom::{elevate_tensor, reduce_tensor, Rational, Reduction, TensorPatch};
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = TensorPatch::new(vec![vec![vec![q(1)], vec![q(2)]], vec![vec![q(3)], vec![q(5)]]])?;
/// let high = elevate_tensor(&p, (3, 2))?;
/// for method in Reduction::ALL {
///     assert_eq!(reduce_tensor(&high, (1, 1), method)?, p);
/// }
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn reduce_tensor<T: Ring>(
    patch: &TensorPatch<T>,
    to_degree: (usize, usize),
    method: Reduction,
) -> Result<TensorPatch<T>> {
    let from = patch.degree();
    check_reduction(from, to_degree, method)?;
    let net = match method {
        Reduction::Interpolating => {
            let rect = [T::zero(), T::one(), T::zero(), T::one()];
            tensor_control_points_from_samples(to_degree, &rect, &|u, v| patch.eval(u, v))
        }
        Reduction::LeastSquares | Reduction::LeastSquaresEndpoints => {
            let r = tensor_least_squares_matrix(from, to_degree, method)?;
            let dim = patch.dim();
            let flat: Vec<Point<T>> = patch.points().to_vec();
            let x = linalg::apply(&r, &flat, dim);
            x.chunks(to_degree.1 + 1)
                .map(<[Point<T>]>::to_vec)
                .collect()
        }
    };
    TensorPatch::new(net)
}

/// The squared L2 distance int_0^1 int_0^1 |a(u, v) - b(u, v)|^2 du dv of two tensor patches
/// of any bidegrees and one dimension, exactly: both are elevated to the larger degree in
/// each variable and the difference d of the nets gives d^T G d with G the tensor Gram matrix.
pub fn tensor_squared_l2_distance<T: Ring>(a: &TensorPatch<T>, b: &TensorPatch<T>) -> Result<T> {
    check_same_dimension(&a.row(0).to_vec(), &b.row(0).to_vec(), "patches")?;
    let (da, db) = (a.degree(), b.degree());
    let d = (da.0.max(db.0), da.1.max(db.1));
    let (ea, eb) = (elevate_tensor(a, d)?, elevate_tensor(b, d)?);
    let diff = linalg::differences(&ea.points().to_vec(), &eb.points().to_vec());
    Ok(linalg::gram_quadratic_form(
        &tensor_bernstein_gram(d, d),
        &diff,
    ))
}
