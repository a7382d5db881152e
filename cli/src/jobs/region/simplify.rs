//! `"kind": "simplify"`: a region under its own fill rule as regularized, simple, oriented
//! loops (overlap removal, [`blossom::region::simplify`]), answered in the form of a `boolean`
//! answer whose edges all name `"region": 0`.

use super::{at, RegionAnswer, RegionShape};
use crate::jobs::cost::metered;
use crate::jobs::intersect::within_budget;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::Reading;
use crate::jobs::restrict::Number;
use blossom::region::{simplify, simplify_work};
use blossom::Error;
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Simplify<T> {
    /// A.
    region: RegionShape<T>,
}

impl<T: Number> Kind for Simplify<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let a = self.region.0;
        within_budget("region", simplify_work(&a), context.limits.max_work)?;
        metered(&context.limits, "region", || {
            let result = simplify(&a).map_err(|e| at("region", e))?;
            RegionAnswer::write("simplify", &result, false)
        })
    }
}
