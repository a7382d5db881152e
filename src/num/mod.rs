//! Numbers: the [`Ring`](crate::Ring) trait every algorithm is written against, its
//! [`Field`](crate::Field) refinement, exact binomials, symbolic polynomials and exact linear
//! algebra. This layer imports nothing else of the crate but the error type.

pub(crate) mod binomial;
pub(crate) mod bounded;
pub(crate) mod exact;
pub(crate) mod limits;
pub(crate) mod linalg;
// Public through `blossom::meter` with the feature `meter`.
pub mod meter;
pub(crate) mod parse;
pub(crate) mod poly;
pub(crate) mod ring;
pub(crate) mod small;
