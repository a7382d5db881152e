//! Degree elevation and reduction of Bézier patches, exactly: the patch versions of
//! [`crate::elevate`], [`crate::reduce`] and [`crate::squared_l2_distance`] (seed 004,
//! section 4), built on the curve side's exact matrices.
//!
//! * [`tensor`]: tensor-product patches over [0, 1]^2. Elevation is the curve elevation in each
//!   variable; the L2 Gram matrix of the tensor Bernstein basis is the Kronecker product of
//!   the curve Gram matrices, int B_i^n(u) B_j^m(v) B_k^n'(u) B_l^m'(v) du dv =
//!   G_nn'[i][k] G_mm'[j][l]; the interpolating reduction is eq. (22) in two passes.
//! * [`triangle`]: triangular patches over the unit triangle T = {u, v >= 0, u + v <= 1}
//!   (barycentric s = u, t = v, r = 1 - u - v of the corners (1, 0), (0, 1), (0, 0), area 1/2).
//!   Elevation multiplies by (s + t + r)^(M - N); the Gram matrix is exact in closed form; the
//!   interpolating reduction is eq. (23).
//!
//! Every reduction is one of the curve side's [`Reduction`]s, and its least-squares matrices
//! are formed in [`Rational`](crate::Rational) first (by the one constrained solve of
//! `num::linalg`) and only then applied to points of any [`Ring`](crate::Ring). The
//! corner-keeping variant ([`Reduction::LeastSquaresEndpoints`]) pins the corner control points
//! (the end points of the boundary curves) to those of the input.

pub(crate) mod tensor;
pub(crate) mod triangle;

use crate::applications::degree::Reduction;
use crate::error::{Error, ErrorKind, Result};

/// Checks that the method can reduce one variable from degree `from` to `to <= from` (`what`
/// names the variable in messages): the interpolating and corner-keeping methods cannot reach
/// degree 0 from a higher degree (eq. (22) has no term for degree 0, and a constant cannot keep
/// two different corners).
pub(crate) fn check_lower_degree(
    from: usize,
    to: usize,
    method: Reduction,
    what: &str,
) -> Result<()> {
    if to > from {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!(
                "reduction needs to_degree <= {from}{}, found {to}",
                suffix(what)
            ),
        ));
    }
    if to == 0 && from > 0 && method != Reduction::LeastSquares {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!(
                "the {} reduction needs to_degree >= 1{} where the degree drops",
                method.name(),
                suffix(what)
            ),
        ));
    }
    Ok(())
}

/// Checks that elevation goes from degree `from` to `to >= from` (`what` names the variable).
pub(crate) fn check_higher_degree(from: usize, to: usize, what: &str) -> Result<()> {
    if to < from {
        return Err(Error::of(
            ErrorKind::Degree,
            "to_degree",
            format!(
                "elevation needs to_degree >= {from}{}, found {to}",
                suffix(what)
            ),
        ));
    }
    Ok(())
}

/// `" in u"` for `"in u"`, nothing for `""`.
fn suffix(what: &str) -> String {
    if what.is_empty() {
        String::new()
    } else {
        format!(" {what}")
    }
}

/// An error of kind [`ErrorKind::Degree`] on `to_degree` when `count` (a number of control
/// points derived from it) is `None`: the degree is too large to index.
pub(crate) fn check_count(count: Option<usize>) -> Result<usize> {
    count.filter(|&c| i64::try_from(c).is_ok()).ok_or_else(|| {
        Error::of(
            ErrorKind::Degree,
            "to_degree",
            "the degree is too large: its number of control points overflows",
        )
    })
}
