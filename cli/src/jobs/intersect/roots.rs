//! `"kind": "roots"`: every distinct zero in [0, 1] of a 1-D Bézier function, with its
//! multiplicity ([`blossom::bezier_zeros`]).

use super::{at, certified, MAX_FUNCTION_DEGREE};
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;
use std::marker::PhantomData;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Roots<T> {
    /// b_0, ..., b_n.
    control_points: Coefficients<T>,
}

/// The coefficients, read exactly: at least one, at most [`MAX_FUNCTION_DEGREE`] + 1 (checked
/// before they are read).
#[derive(Debug)]
struct Coefficients<T>(Vec<Rational>, PhantomData<T>);

impl<'de, T: Reading> Deserialize<'de> for Coefficients<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let count = |found: usize| match found {
            0 => {
                Err("expected at least one number (a Bézier function of degree n has n + 1)".into())
            }
            _ if found - 1 > MAX_FUNCTION_DEGREE => Err(format!(
                "degree {} is over the limit of {MAX_FUNCTION_DEGREE} of blossom intersect",
                found - 1
            )),
            _ => Ok(()),
        };
        let exact = |x: &Value| number::<T>(x).map(|x| x.exact());
        leaf(d, |v| items(v, "an array of numbers", count, exact))
            .map(|c| Coefficients(c, PhantomData))
    }
}

/// The answer.
#[derive(Serialize)]
struct Answer {
    identically_zero: bool,
    roots: Vec<Root>,
}

#[derive(Serialize)]
struct Root {
    t: Param,
    multiplicity: usize,
}

impl<T> Estimate for Roots<T> {}

impl<T: Number> Kind for Roots<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let coefficients = self.control_points.0;
        let work = blossom::budget::bezier_zeros_work(&coefficients);
        certified(context, "control_points", work, || {
            let zeros =
                blossom::bezier_zeros(&coefficients).map_err(|e| at("control_points", e))?;
            let root = |z: &blossom::PolynomialZero| Root {
                t: Param::of(&z.t),
                multiplicity: z.multiplicity,
            };
            write(&Answer {
                identically_zero: zeros.identically_zero,
                roots: zeros.zeros.iter().map(root).collect(),
            })
        })
    }
}
