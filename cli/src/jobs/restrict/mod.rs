//! The jobs of `blossom restrict`, one file per kind, each a struct deriving `Deserialize`
//! (its fields in the order they are checked) that implements
//! [`Estimate`](super::kinds::Estimate) (the cost model of [`super::cost`]) and
//! [`Kind`](super::kinds::Kind): its answer, a struct deriving `Serialize` ([`restricted`]). This module holds what they share: the number types they compute in
//! ([`Number`]), the answers' common forms and the carried evaluators of `--method
//! specialised` ([`specialised`]).
//!
//! # Exact decisions under `--arithmetic f64`
//!
//! `bspline` chooses each knot's multiplicity from the continuity that holds *exactly* at the
//! breakpoint, and the rational jobs refuse a weight that is *exactly* zero: rounding would
//! falsify both. Under `f64` they read their numbers as written
//! ([`Written`](super::read::Written)), compute exactly and round each number of the answer
//! once to the nearest double ([`rounded`]).

pub mod bezier_curve;
pub mod bezier_tensor;
pub mod bezier_triangle;
pub mod bspline;
pub mod bspline_eval;
pub mod curve;
pub mod derivative;
pub mod elevate;
pub mod rational_curve;
pub mod rational_tensor;
pub mod rational_triangle;
pub mod reduce;
pub mod specialised;
pub mod tensor;
pub mod triangle;

use super::read::Reading;
use super::write::{write, Out, Write};
use crate::number::JsonNumber;
use blossom::{Error, Field, Point, Rational, Ring, TriangularPatch};
use serde::Serialize;
use serde_json::Value;

/// A number type `blossom restrict` computes in: [`Rational`] (`exact`) or
/// [`blossom::BoundedF64`] (`f64`, with its error bound).
pub trait Number: JsonNumber + Field + Reading + Write {}

impl<T: JsonNumber + Field + Reading + Write> Number for T {}

/// The answer of a restriction (`curve`, `tensor`, `triangle`, `elevate`, ...): the degree
/// (`n`, `[n, m]`) and the control points (the numbers of a curve or a net, [`Out`]; the
/// entries of a triangular net, [`entries`]).
#[derive(Serialize)]
pub struct Restricted<D, P> {
    /// The degree.
    pub degree: D,
    /// The control points.
    pub control_points: P,
}

/// The answer of a restriction of degree `degree` whose control points are `control_points`.
pub fn restricted<D: Serialize, P: Serialize>(
    degree: D,
    control_points: P,
) -> Result<Value, Error> {
    write(&Restricted {
        degree,
        control_points,
    })
}

/// One control point of a triangular patch: its indices, the point and, for a rational
/// patch, its weight.
#[derive(Serialize)]
#[serde(bound = "T: Write")]
pub struct Entry<T: Write> {
    a: usize,
    b: usize,
    c: usize,
    point: Out<Point<T>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    weight: Option<Out<T>>,
}

/// The entries of a triangular net in lexicographic order of (a, b), with `weights` when
/// rational.
pub fn entries<T: Ring + Write>(net: &TriangularPatch<T>, weights: Option<&[T]>) -> Vec<Entry<T>> {
    net.entries()
        .enumerate()
        .map(|(k, (a, b, c, point))| Entry {
            a,
            b,
            c,
            point: Out(point.to_vec()),
            weight: weights.map(|w| Out(w[k].clone())),
        })
        .collect()
}

/// Exact numbers in the arithmetic `T` (rounded once to the nearest double under `f64`).
pub fn rounded<T: Number>(xs: &[Rational]) -> Vec<T> {
    xs.iter().map(T::from_rational).collect()
}

/// Refuses a weight that is not zero exactly but rounds to zero (its rounded control point
/// would be meaningless), named by `path`.
pub fn check_rounded_weights<'a, T: Ring + 'a>(
    weights: impl Iterator<Item = (String, &'a T)>,
) -> Result<(), Error> {
    for (path, w) in weights {
        if w.is_zero() {
            return Err(Error::new(
                path,
                "the weight is not zero but rounds to zero in f64 (underflow)",
            ));
        }
    }
    Ok(())
}

/// The exact value of numbers read as written.
pub fn exact<T: Reading>(xs: &[T]) -> Vec<Rational> {
    xs.iter().map(Reading::exact).collect()
}

/// The exact value of points read as written.
pub fn exact_points<T: Reading>(points: &[Point<T>]) -> Vec<Point<Rational>> {
    points.iter().map(|p| exact(p)).collect()
}
