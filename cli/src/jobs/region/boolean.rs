//! `"kind": "boolean"`: the intersection, union, difference (A minus B) or xor of two regions
//! ([`blossom::region::boolean`]).

use super::{RegionAnswer, RegionShape, Two};
use crate::jobs::intersect::certified;
use crate::jobs::kind::prelude::*;
use crate::jobs::read::Name;
use crate::jobs::restrict::Number;
use blossom::region::{boolean, boolean_work, BooleanOp};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Boolean<T> {
    /// The operation.
    op: Name<BooleanOp>,
    /// A and B.
    regions: Two<RegionShape<T>>,
}

impl<T> Estimate for Boolean<T> {}

impl<T: Number> Kind for Boolean<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [a, b] = self.regions.0.map(|r| r.0);
        certified(context, "regions", boolean_work(&a, &b), || {
            let result = boolean(&a, &b, self.op.0).map_err(|e| under("regions", e))?;
            RegionAnswer::write(&result, false)
        })
    }
}
