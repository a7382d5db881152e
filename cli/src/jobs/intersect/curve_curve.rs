//! `"kind": "curve-curve"`: every isolated intersection and every overlap of two curves
//! ([`blossom::intersect_curves`]).

use super::{at, within_budget, Curve2, Intersect, IntersectionsAnswer};
use crate::jobs::cost::metered;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{counted, Count, Reading};
use crate::jobs::restrict::Number;
use crate::jobs::write::write;
use blossom::Error;
use serde::{Deserialize, Deserializer};
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct CurveCurve<T> {
    /// P and Q.
    curves: Pair<T>,
}

/// Two curves.
#[derive(Debug)]
struct Pair<T>(Vec<Curve2<T, Intersect>>);

impl<'de, T: Reading> Deserialize<'de> for Pair<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        counted(d, Count::Exactly(2, "curves"), "an array of two curves").map(Pair)
    }
}

impl<T: Number> Kind for CurveCurve<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [p, q]: [Curve2<T, Intersect>; 2] =
            self.curves.0.try_into().unwrap_or_else(|_| unreachable!());
        let (p, q) = (p.0, q.0);
        within_budget(
            "curves",
            blossom::budget::curve_pair_work(&p, &q),
            context.limits.max_work,
        )?;
        metered(&context.limits, "curves", || {
            let found = blossom::intersect_curves(&p, &q).map_err(|e| {
                let path = match e.path() {
                    "p" => "curves[0]",
                    "q" => "curves[1]",
                    _ => "curves",
                };
                at(path, e)
            })?;
            write(&IntersectionsAnswer::of("curve-curve", &found))
        })
    }
}
