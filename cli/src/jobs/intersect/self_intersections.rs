//! `"kind": "self"`: every pair s < t with P(s) = P(t) and every stretch a curve retraces
//! ([`blossom::self_intersections`]).

use super::{at, within_budget, Curve2, Intersect, IntersectionsAnswer};
use crate::jobs::cost::metered;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::Reading;
use crate::jobs::restrict::Number;
use crate::jobs::write::write;
use blossom::Error;
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct SelfIntersections<T> {
    /// P.
    curve: Curve2<T, Intersect>,
}

impl<T: Number> Kind for SelfIntersections<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let p = self.curve.0;
        let work = blossom::budget::self_intersection_work(&p);
        within_budget("curve", work, context.limits.max_work)?;
        metered(&context.limits, "curve", || {
            let found = blossom::self_intersections(&p).map_err(|e| at("curve", e))?;
            write(&IntersectionsAnswer::of("self", &found))
        })
    }
}
