//! `"kind": "self"`: every pair s < t with P(s) = P(t) and every stretch a curve retraces
//! ([`blossom::self_intersections`]).

use super::{at, certified, Curve, IntersectionsAnswer};
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct SelfIntersections<T> {
    /// P.
    curve: Curve<T>,
}

impl<T> Estimate for SelfIntersections<T> {}

impl<T: Number> Kind for SelfIntersections<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let p = self.curve.0;
        certified(
            context,
            "curve",
            blossom::budget::self_intersection_work(&p),
            || {
                let found = blossom::self_intersections(&p).map_err(|e| at("curve", e))?;
                write(&IntersectionsAnswer::of(&found))
            },
        )
    }
}
