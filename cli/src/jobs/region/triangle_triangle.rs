//! `"kind": "triangle-triangle"`: the intersection of two planar Bézier triangles' regions
//! ([`blossom::region::triangle_intersection`]), the operation of Python `bezier`'s
//! `Triangle.intersect`, certified; edges numbered 0, 1, 2 for the first triangle's, 3, 4, 5
//! for the second's.

use super::{RegionAnswer, TriangleShape, Two};
use crate::jobs::intersect::certified;
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;
use blossom::region::{boolean_work, triangle_intersection};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct TriangleTriangle<T> {
    /// T1 and T2.
    triangles: Two<TriangleShape<T>>,
}

impl<T> Estimate for TriangleTriangle<T> {}

impl<T: Number> Kind for TriangleTriangle<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let [t1, t2] = self.triangles.0.map(|t| t.0);
        certified(context, "triangles", boolean_work(&t1, &t2), || {
            let result = triangle_intersection(&t1, &t2).map_err(|e| under("triangles", e))?;
            RegionAnswer::write(&result, true)
        })
    }
}
