//! The error type of the library: where the problem is (a path naming the argument or field)
//! and what kind of problem it is (an enum a caller can match on), with a message in words.

use std::fmt;

/// What kind of input the library refused. New kinds may be added.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A list that must not be empty is empty (no coefficients, no points, no pieces).
    Empty,
    /// Points of one object have different numbers of coordinates, or none.
    Dimension,
    /// A count or arrangement is wrong: a grid that is not rectangular, a net with the wrong
    /// number of points, a knot vector of the wrong length, sizes of two operands that differ.
    Shape,
    /// A blossom got a number of arguments different from its degree.
    Arity,
    /// A degree outside what the operation accepts (elevation to a lower degree, say).
    Degree,
    /// A parameter or domain that is not allowed: outside the knot range, an empty interval,
    /// knots out of order, barycentric coordinates that do not add up to 1.
    Domain,
    /// A weight or denominator that is zero where it must not be.
    ZeroWeight,
    /// A number that is not finite (NaN or an infinity) where a finite one is needed.
    NotFinite,
    /// A size (a degree, a number of objects, of knots or of points) whose storage would exceed
    /// [`MAX_ENTRIES`](crate::MAX_ENTRIES) entries, or whose computation overflows `usize`.
    TooLarge,
    /// A linear system without a unique solution.
    Singular,
    /// A name that is not one of the known ones (a method, a reduction).
    UnknownName,
    /// Anything else, described by the message (used by the application's input layer).
    Invalid,
}

/// An input that the library refuses, with the path of the offending field (for example
/// `coefficients[2]`), the kind of problem and what is wrong in words.
///
/// `Display` writes `path: message` (or the message alone when the path is empty).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// Where the problem is: an argument name or a JSON-like path such as `interval[1]`.
    pub field: String,
    /// What kind of problem it is.
    pub kind: ErrorKind,
    /// What is wrong, in words.
    pub message: String,
}

impl Error {
    /// A new error of `kind` about `field`.
    pub fn of(kind: ErrorKind, field: impl Into<String>, message: impl Into<String>) -> Self {
        Error {
            field: field.into(),
            kind,
            message: message.into(),
        }
    }

    /// A new error about `field` of kind [`ErrorKind::Invalid`].
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self::of(ErrorKind::Invalid, field, message)
    }

    /// The path of the offending field or argument.
    pub fn path(&self) -> &str {
        &self.field
    }

    /// The kind of problem.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

impl std::error::Error for Error {}

/// `Ok(())` when a blossom of degree `degree` got `found` arguments (in `field`), else an
/// [`ErrorKind::Arity`] error: the one arity check of every blossom of the crate.
pub(crate) fn check_arity(field: &str, found: usize, degree: usize) -> Result<()> {
    if found == degree {
        Ok(())
    } else {
        Err(Error::of(
            ErrorKind::Arity,
            field,
            format!("a blossom of degree {degree} takes {degree} arguments, found {found}"),
        ))
    }
}

/// Shorthand for results of this crate.
pub(crate) type Result<T> = std::result::Result<T, Error>;
