//! `"kind": "boolean"`: the intersection, union, difference (A minus B) or xor of two regions
//! ([`blossom::region::boolean`]).

use super::{at, Name, RegionAnswer, RegionShape, Two};
use crate::jobs::cost::metered;
use crate::jobs::intersect::within_budget;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::Reading;
use crate::jobs::restrict::Number;
use blossom::region::{boolean, boolean_work, BooleanOp};
use blossom::Error;
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Boolean<T> {
    /// The operation.
    op: Name<BooleanOp>,
    /// A and B.
    regions: Two<RegionShape<T>>,
}

impl<T: Number> Kind for Boolean<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [a, b] = self.regions.0.map(|r| r.0);
        within_budget("regions", boolean_work(&a, &b), context.limits.max_work)?;
        metered(&context.limits, "regions", || {
            let result = boolean(&a, &b, self.op.0).map_err(|e| at("regions", e))?;
            RegionAnswer::write("boolean", &result, false)
        })
    }
}
