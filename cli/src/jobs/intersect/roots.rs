//! `"kind": "roots"`: every distinct zero in [0, 1] of a 1-D Bézier function, with its
//! multiplicity ([`blossom::bezier_zeros`]).

use super::{at, within_budget, MAX_FUNCTION_DEGREE};
use crate::jobs::cost::metered;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Num, Reading};
use crate::jobs::restrict::Number;
use crate::jobs::write::{write, Param};
use blossom::{Error, Rational};
use serde::de::{self, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use std::fmt;
use std::marker::PhantomData;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Roots<T> {
    /// b_0, ..., b_n.
    control_points: Coefficients<T>,
}

/// The coefficients: at least one, at most [`MAX_FUNCTION_DEGREE`] + 1 (checked before they
/// are read).
#[derive(Debug)]
struct Coefficients<T>(Vec<Rational>, PhantomData<T>);

impl<'de, T: Reading> Deserialize<'de> for Coefficients<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Reading> Visitor<'de> for V<T> {
            type Value = Coefficients<T>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an array of numbers")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let found = seq.size_hint().unwrap_or(0);
                if found == 0 {
                    return Err(de::Error::custom(
                        "expected at least one number (a Bézier function of degree n has n + 1)",
                    ));
                }
                if found - 1 > MAX_FUNCTION_DEGREE {
                    return Err(de::Error::custom(format!(
                        "degree {} is over the limit of {MAX_FUNCTION_DEGREE} of blossom intersect",
                        found - 1
                    )));
                }
                let mut out = Vec::with_capacity(found);
                while let Some(Num(x)) = seq.next_element::<Num<T>>()? {
                    out.push(x.exact());
                }
                Ok(Coefficients(out, PhantomData))
            }
        }
        d.deserialize_seq(V(PhantomData))
    }
}

/// The answer.
#[derive(Serialize)]
struct Answer {
    kind: &'static str,
    identically_zero: bool,
    roots: Vec<Root>,
}

#[derive(Serialize)]
struct Root {
    t: Param,
    multiplicity: usize,
}

impl<T: Number> Kind for Roots<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let coefficients = self.control_points.0;
        let work = blossom::budget::bezier_zeros_work(&coefficients);
        within_budget("control_points", work, context.limits.max_work)?;
        metered(&context.limits, "control_points", || {
            let zeros =
                blossom::bezier_zeros(&coefficients).map_err(|e| at("control_points", e))?;
            write(&Answer {
                kind: "roots",
                identically_zero: zeros.identically_zero,
                roots: zeros
                    .zeros
                    .iter()
                    .map(|z| Root {
                        t: Param::of(&z.t),
                        multiplicity: z.multiplicity,
                    })
                    .collect(),
            })
        })
    }
}
