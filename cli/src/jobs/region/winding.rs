//! `"kind": "winding"`: for each point its exact winding number around the region's loops and
//! where the fill rule puts it; a point on a loop is `"boundary"` with `"winding": null`.

use super::{Points, RegionShape};
use crate::jobs::cost::metered;
use crate::jobs::intersect::within_budget;
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::Reading;
use crate::jobs::restrict::Number;
use crate::jobs::write::write;
use blossom::region::Winding as Found;
use blossom::Error;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Winding<T> {
    /// A.
    region: RegionShape<T>,
    /// The points.
    points: Points<T>,
}

/// The answer.
#[derive(Serialize)]
struct Answer {
    kind: &'static str,
    points: Vec<Position>,
}

#[derive(Serialize)]
struct Position {
    position: &'static str,
    winding: Option<i64>,
}

impl<T: Number> Kind for Winding<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let region = self.region.0;
        let points: Vec<_> = self.points.into_iter().map(|p| p.0).collect();
        within_budget(
            "points",
            region.winding_work(points.len()),
            context.limits.max_work,
        )?;
        let fill = region.fill();
        metered(&context.limits, "points", || {
            let points = region
                .windings(&points)
                .into_iter()
                .map(|w| match w {
                    Found::Boundary => Position {
                        position: "boundary",
                        winding: None,
                    },
                    Found::Number(k) => Position {
                        position: if fill.inside(k) { "inside" } else { "outside" },
                        winding: Some(k),
                    },
                })
                .collect();
            write(&Answer {
                kind: "winding",
                points,
            })
        })
    }
}
