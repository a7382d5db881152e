//! The jobs of `blossom intersect` (the contract's section "Intersections and zeros"): zeros of
//! a Bézier function ([`roots`]), the intersections of two curves ([`curve_curve`]) and of a
//! curve with itself ([`self_intersections`]), every answer certified by the library's exact
//! methods. The arithmetic names only how the input numbers are read: under `exact` as
//! written, under `f64` each rounded to the nearest double first; either way the answer is the
//! exact one for the numbers so read, every parameter written as a PARAM
//! ([`super::write::Param`]).
//!
//! # Limits
//!
//! Exact intersection costs grow with the product of the degrees (the resultant of two curves
//! of degrees n and m has degree n m) and with the bit length of the integers the exact
//! methods compute with, so a job is refused when a curve's degree is over
//! [`MAX_CURVE_DEGREE`] or a Bézier function's over [`MAX_FUNCTION_DEGREE`] (naming the
//! field, before its numbers are read); then by the work budget ([`certified`]), before
//! computing from the library's estimate ([`blossom::budget::bezier_zeros_work`],
//! [`blossom::budget::curve_pair_work`]: the float filter runs first, and when it decides only
//! the two resultants and one Descartes test per crossing remain;
//! [`blossom::budget::self_intersection_work`]), naming `control_points`, `curves` or `curve`,
//! and while computing under the work meter, which the exact methods charge as they go.

pub mod curve_curve;
pub mod roots;
pub mod self_intersections;

use super::cost::{metered, RAISE_IT};
use super::kind::Context;
use super::read::{items, leaf, numbers, spelling, Reading};
use super::write::{Double, Param};
use blossom::{Error, Intersections, Rational};
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use std::marker::PhantomData;

/// The largest degree of a curve of a `curve-curve` or `self` job. Below it the work budget
/// decides: under the default `--max-work`, degree-20 pairs and loops are answered (the
/// spec's minimum), higher degrees when their estimate and their metered work allow, and a
/// curve of degree 41 or more is refused whatever the budget.
pub const MAX_CURVE_DEGREE: usize = 40;

/// The largest degree of the Bézier function of a `roots` job (then the work budget decides).
pub const MAX_FUNCTION_DEGREE: usize = 200;

/// A job whose estimated work is over this many times `--max-work` is refused before
/// computing. The estimates are at most about twice the measured time where the limit lets
/// jobs through (see [`blossom::budget`]), so no job of 0.5 s is refused by it under the
/// default limit; the meter stops the ones it lets through that run longer.
pub const UP_FRONT_FACTOR: u128 = 2;

/// Computes a certified job (of `blossom intersect` or `blossom region`) within the budget:
/// refused up front when its estimated `work` (units of about a nanosecond of a 2-core machine,
/// see [`blossom::budget`]) is over [`UP_FRONT_FACTOR`] times `--max-work`, else computed under
/// the work meter; both refusals name `path`.
pub fn certified<R>(
    context: &Context,
    path: &str,
    work: u128,
    compute: impl FnOnce() -> Result<R, Error>,
) -> Result<R, Error> {
    let max_work = context.limits.max_work;
    if work > UP_FRONT_FACTOR * u128::from(max_work) {
        return Err(Error::new(
            path,
            format!(
                "the job's work is estimated at {:.1e} units, over the limit of {:.1e} units \
                 {RAISE_IT}",
                work as f64, max_work as f64
            ),
        ));
    }
    metered(&context.limits, path, compute)
}

/// `error` re-addressed to `path` (the library names its own arguments).
pub fn at(path: &str, error: Error) -> Error {
    Error::of(error.kind, path, error.message)
}

/// Which subcommand's curves: the degree limit and the words of its messages.
#[derive(Clone, Copy, Debug)]
pub struct Curves {
    /// The largest degree.
    pub max: usize,
    /// The subcommand, in messages (`blossom intersect`).
    pub subcommand: &'static str,
    /// What its shapes are (`curves are 2-D`).
    pub planar: &'static str,
    /// Whether fewer than 2 control points are refused here (else by the library).
    pub at_least_two: bool,
}

/// The curves of `blossom intersect`.
pub const INTERSECT: Curves = Curves {
    max: MAX_CURVE_DEGREE,
    subcommand: "blossom intersect",
    planar: "coordinates (curves are 2-D)",
    at_least_two: true,
};

/// The control points of a 2-D curve read exactly, and its first and last points as written
/// (`(1, 0.1)`, for messages).
#[derive(Clone, Debug)]
pub struct Curve2 {
    /// The control points.
    pub points: Vec<[Rational; 2]>,
    /// The first and the last point as written.
    pub ends: [String; 2],
}

impl Curves {
    /// A point `[x, y]`, read exactly as the arithmetic `T` reads it.
    pub fn point<T: Reading>(self, value: &Value) -> Result<[Rational; 2], Error> {
        let xy: [T; 2] = numbers(value, "a point [x, y]", self.planar)?;
        Ok(xy.map(|x| x.exact()))
    }

    /// A curve: its number of points checked (at most `max` + 1) before they are read.
    pub fn curve<T: Reading>(self, value: &Value) -> Result<Curve2, Error> {
        let count = |found: usize| {
            match found {
            _ if self.at_least_two && found < 2 => Err(format!(
                "expected at least 2 control points (a curve of degree n >= 1 has n + 1), found {found}"
            )),
            _ if found > self.max + 1 => Err(self.over_degree(found - 1)),
            _ => Ok(()),
        }
        };
        let expected = "a curve (an array of 2-D control points)";
        let points = items(value, expected, count, |p| self.point::<T>(p))?;
        let shown = |p: Option<&Value>| match p {
            Some(Value::Array(xy)) => format!("({}, {})", spelling(&xy[0]), spelling(&xy[1])),
            _ => String::new(),
        };
        let ends = match value {
            Value::Array(items) => [shown(items.first()), shown(items.last())],
            _ => Default::default(),
        };
        Ok(Curve2 { points, ends })
    }

    /// `degree N is over the limit of MAX of SUBCOMMAND`.
    pub fn over_degree(self, degree: usize) -> String {
        format!(
            "degree {degree} is over the limit of {} of {}",
            self.max, self.subcommand
        )
    }
}

/// A curve of `blossom intersect` ([`INTERSECT`]), read as the arithmetic `T` reads numbers.
#[derive(Clone, Debug)]
pub struct Curve<T>(pub Vec<[Rational; 2]>, PhantomData<T>);

impl<'de, T: Reading> Deserialize<'de> for Curve<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| INTERSECT.curve::<T>(v)).map(|c| Curve(c.points, PhantomData))
    }
}
impl<T> super::read::Plural for Curve<T> {
    const PLURAL: &'static str = "curves";
}

/// The answer of a `curve-curve` or `self` job.
#[derive(Serialize)]
pub struct IntersectionsAnswer {
    points: Vec<PointAnswer>,
    overlaps: Vec<OverlapAnswer>,
}

#[derive(Serialize)]
struct PointAnswer {
    s: Param,
    t: Param,
    tangent: bool,
    point: [Double; 2],
}

#[derive(Serialize)]
struct OverlapAnswer {
    s: [Param; 2],
    t: [Param; 2],
}

impl IntersectionsAnswer {
    /// The answer of a job that found `found`.
    pub fn of(found: &Intersections) -> Self {
        IntersectionsAnswer {
            points: found
                .points
                .iter()
                .map(|p| PointAnswer {
                    s: Param::of(&p.s),
                    t: Param::of(&p.t),
                    tangent: p.tangent,
                    point: [Double(p.point[0]), Double(p.point[1])],
                })
                .collect(),
            overlaps: found
                .overlaps
                .iter()
                .map(|o| OverlapAnswer {
                    s: [Param::of(&o.s[0]), Param::of(&o.s[1])],
                    t: [Param::of(&o.t[0]), Param::of(&o.t[1])],
                })
                .collect(),
        }
    }
}
