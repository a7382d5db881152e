//! `"kind": "curve-curve"`: every isolated intersection and every overlap of two curves
//! ([`blossom::intersect_curves`]).

use super::{at, certified, Curve, IntersectionsAnswer};
use crate::jobs::kind::prelude::*;
use crate::jobs::read::Two;
use crate::jobs::restrict::Number;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct CurveCurve<T> {
    /// P and Q.
    curves: Two<Curve<T>>,
}

impl<T> Estimate for CurveCurve<T> {}

impl<T: Number> Kind for CurveCurve<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [p, q] = self.curves.0.map(|c| c.0);
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
