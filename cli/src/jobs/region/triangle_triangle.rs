//! `"kind": "triangle-triangle"`: the intersection of two planar Bézier triangles' regions
//! ([`blossom::region::triangle_intersection`]), the operation of Python `bezier`'s
//! `Triangle.intersect`, certified; edges numbered 0, 1, 2 for the first triangle's, 3, 4, 5
//! for the second's.

use super::{at, RegionAnswer, TriangleShape, Two};
use crate::jobs::cost::metered;
use crate::jobs::intersect::within_budget;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::Reading;
use crate::jobs::restrict::Number;
use blossom::region::{boolean_work, triangle_intersection};
use blossom::Error;
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct TriangleTriangle<T> {
    /// T1 and T2.
    triangles: Two<TriangleShape<T>>,
}

impl<T: Number> Kind for TriangleTriangle<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [t1, t2] = self.triangles.0.map(|t| t.0);
        within_budget("triangles", boolean_work(&t1, &t2), context.limits.max_work)?;
        metered(&context.limits, "triangles", || {
            let result = triangle_intersection(&t1, &t2).map_err(|e| at("triangles", e))?;
            RegionAnswer::write("triangle-triangle", &result, true)
        })
    }
}
