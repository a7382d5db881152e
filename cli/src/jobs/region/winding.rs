//! `"kind": "winding"`: for each point its exact winding number around the region's loops and
//! where the fill rule puts it; a point on a loop is `"boundary"` with `"winding": null`.

use super::{Point2, RegionShape};
use crate::jobs::intersect::certified;
use crate::jobs::kind::prelude::*;
use crate::jobs::restrict::Number;
use blossom::region::Winding as Found;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Winding<T> {
    /// A.
    region: RegionShape<T>,
    /// The points.
    points: List<Point2<T>>,
}

/// The answer.
#[derive(Serialize)]
struct Answer {
    points: Vec<Position>,
}

#[derive(Serialize)]
struct Position {
    position: &'static str,
    winding: Option<i64>,
}

impl<T> Estimate for Winding<T> {}

impl<T: Number> Kind for Winding<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let region = self.region.0;
        let points: Vec<_> = self.points.0.into_iter().map(|p| p.0).collect();
        let fill = region.fill();
        let position = |w| match w {
            Found::Boundary => Position {
                position: "boundary",
                winding: None,
            },
            Found::Number(k) => Position {
                position: if fill.inside(k) { "inside" } else { "outside" },
                winding: Some(k),
            },
        };
        certified(context, "points", region.winding_work(points.len()), || {
            let points = region.windings(&points).into_iter().map(position).collect();
            write(&Answer { points })
        })
    }
}
