//! Writing answers: every answer is a struct deriving `Serialize`, turned into JSON by
//! [`write()`], which names the path of a number that cannot be written (`control_points[2][0]:
//! the result inf is not finite ...`, `serde_path_to_error`). Numbers of the arithmetic go
//! through [`Out`] ([`Write`]: exact numbers as strings in lowest terms, doubles as JSON
//! numbers, bounded doubles marked for the answer's `"error_bound"`); certified parameters are
//! [`Param`]s.

use crate::number::{f64_to_json, format_rational, JsonNumber};
use blossom::{AlgebraicReal, BoundedF64, Error, Rational};
use serde::ser::{Error as _, Serializer};
use serde::Serialize;
use serde_json::Value;

/// The answer `answer` as JSON, or the error naming the path of the number that failed.
pub fn write<A: Serialize>(answer: &A) -> Result<Value, Error> {
    serde_path_to_error::serialize(answer, serde_json::value::Serializer).map_err(|e| {
        let path = e.path().to_string();
        let field = if path == "." {
            String::from("internal")
        } else {
            path
        };
        Error::new(field, e.into_inner().to_string())
    })
}

/// Something made of the arithmetic's numbers that an answer holds: a number, or arrays of
/// them at any depth.
pub trait Write {
    /// Serializes it (numbers as [`JsonNumber::to_json`] writes them).
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error>;
}

/// `Write` for the numbers: each through [`JsonNumber::to_json`].
macro_rules! write_numbers {
    ($($ty:ty),*) => {$(
        impl Write for $ty {
            fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                self.to_json().map_err(S::Error::custom)?.serialize(s)
            }
        }
    )*};
}

/// `Write` for sequences: an array of what each element writes.
macro_rules! write_sequences {
    ($([$($g:tt)*] $ty:ty),*) => {$(
        impl<$($g)*> Write for $ty {
            fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.collect_seq(self.iter().map(Out))
            }
        }
    )*};
}

write_numbers!(Rational, BoundedF64, f64);
write_sequences!([X: Write] Vec<X>, [X: Write] [X], [X: Write, const N: usize] [X; N]);

impl<X: Write + ?Sized> Write for &X {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        (**self).write(s)
    }
}

/// Numbers of an answer, serialized by [`Write`].
#[derive(Clone, Debug)]
pub struct Out<X>(pub X);

impl<X: Write> Serialize for Out<X> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.write(s)
    }
}

/// A double of a certified answer: a JSON number (non-finite ones are internal errors).
#[derive(Clone, Copy, Debug)]
pub struct Double(pub f64);

impl Serialize for Double {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        f64_to_json(self.0).map_err(S::Error::custom)?.serialize(s)
    }
}

/// An exact number written as the contract writes it (`"p/q"`).
#[derive(Clone, Debug)]
pub struct Exact(pub Rational);

impl Serialize for Exact {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        format_rational(&self.0)
            .map_err(S::Error::custom)?
            .serialize(s)
    }
}

/// A PARAM: the correctly rounded double, the exact value when rational, an isolating
/// interval and the square-free integer polynomial of the parameter.
#[derive(Clone, Debug, Serialize)]
pub struct Param {
    value: Double,
    exact: Option<Exact>,
    interval: [Exact; 2],
    polynomial: Vec<String>,
}

impl Param {
    /// The PARAM of `x`.
    pub fn of(x: &AlgebraicReal) -> Param {
        let (lo, hi) = x.interval();
        Param {
            value: Double(x.to_f64()),
            exact: x.exact().cloned().map(Exact),
            interval: [Exact(lo.clone()), Exact(hi.clone())],
            polynomial: x.polynomial().iter().map(ToString::to_string).collect(),
        }
    }
}
