//! `"kind": "curve-curve"`: every isolated intersection and every overlap of two curves
//! ([`blossom::intersect_curves`]).

use super::{at, certified, Curve, IntersectionsAnswer};
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct CurveCurve<T> {
    /// P and Q.
    curves: Pair<T>,
}

/// Two curves.
#[derive(Debug)]
struct Pair<T>(Vec<Curve<T>>);

impl<'de, T: Reading> Deserialize<'de> for Pair<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let curves = |v: &Value| items(v, "an array of two curves", exactly(2, "curves"), object);
        leaf(d, curves).map(Pair)
    }
}

impl<T> Estimate for CurveCurve<T> {}

impl<T: Number> Kind for CurveCurve<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [p, q]: [Curve<T>; 2] = self.curves.0.try_into().unwrap_or_else(|_| unreachable!());
        let (p, q) = (p.0, q.0);
        certified(
            context,
            "curves",
            blossom::budget::curve_pair_work(&p, &q),
            || {
                let found = blossom::intersect_curves(&p, &q).map_err(|e| {
                    let path = match e.path() {
                        "p" => "curves[0]",
                        "q" => "curves[1]",
                        _ => "curves",
                    };
                    at(path, e)
                })?;
                write(&IntersectionsAnswer::of(&found))
            },
        )
    }
}
