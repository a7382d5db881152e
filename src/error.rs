//! The error type of the library: every message names the offending argument or field.

use std::fmt;

/// An input that the library refuses, with the path of the offending field
/// (for example `coefficients[2]`) and what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// Where the problem is: an argument name or a JSON-like path such as `interval[1]`.
    pub field: String,
    /// What is wrong, in words.
    pub message: String,
}

impl Error {
    /// A new error about `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Error {
            field: field.into(),
            message: message.into(),
        }
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

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
