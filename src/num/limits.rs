//! The one size limit of the crate: how many entries (numbers, points, knots, terms) an
//! allocation sized by a caller's argument may hold, and the checked size arithmetic that
//! enforces it. A size above the limit, or one whose computation overflows `usize`, is refused
//! with [`ErrorKind::TooLarge`] naming the argument, instead of a panic on overflow or an abort
//! on allocation.

use crate::error::{Error, ErrorKind, Result};

/// The most entries a caller-sized allocation may hold: 2^25 (256 MiB of `f64`). Degrees,
/// batch sizes and knot counts whose storage or scratch would exceed it are refused with
/// [`ErrorKind::TooLarge`]: for instance a [`RestrictionMap`](crate::RestrictionMap) of a curve
/// of degree 20000, whose engine scratch for one block is about 4 x 20000 x 512 numbers.
pub const MAX_ENTRIES: usize = 1 << 25;

/// The refusal of a size about `field`: above [`MAX_ENTRIES`] or overflowing.
fn too_large(field: &str, what: &str) -> Error {
    Error::of(
        ErrorKind::TooLarge,
        field,
        format!("{what} exceeds the limit of {MAX_ENTRIES} entries"),
    )
}

/// `n` itself when `n <= MAX_ENTRIES`, or an error about `field` (`what` says what `n`
/// counts, for the message).
pub(crate) fn check_entries(n: Option<usize>, field: &str, what: &str) -> Result<usize> {
    match n {
        Some(n) if n <= MAX_ENTRIES => Ok(n),
        _ => Err(too_large(field, what)),
    }
}

/// The product of `factors` when it does not overflow and is at most [`MAX_ENTRIES`], or an
/// error about `field`.
pub(crate) fn checked_product(factors: &[usize], field: &str, what: &str) -> Result<usize> {
    let n = factors
        .iter()
        .try_fold(1usize, |acc, &k| acc.checked_mul(k));
    check_entries(n, field, what)
}
