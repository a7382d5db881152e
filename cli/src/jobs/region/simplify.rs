//! `"kind": "simplify"`: a region under its own fill rule as regularized, simple, oriented
//! loops (overlap removal, [`blossom::region::simplify`]), answered in the form of a `boolean`
//! answer whose edges all name `"region": 0`.

use super::{RegionAnswer, RegionShape};
use crate::jobs::intersect::certified;
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;
use blossom::region::{simplify, simplify_work};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Simplify<T> {
    /// A.
    region: RegionShape<T>,
}

impl<T> Estimate for Simplify<T> {}

impl<T: Number> Kind for Simplify<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let a = self.region.0;
        certified(context, "region", simplify_work(&a), || {
            let result = simplify(&a).map_err(|e| under("region", e))?;
            RegionAnswer::write(&result, false)
        })
    }
}
