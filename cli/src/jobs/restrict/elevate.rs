//! `"kind": "elevate"`: the Bézier curve's control points at the higher degree m.

use super::{Number, Restricted};
use crate::jobs::cost::{degree_of, dimension, grown_bits, len, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Degree, Points, Reading};
use crate::jobs::write::{write, Out};
use blossom::{elevate, BezierCurve, Error};
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Elevate<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// m >= n.
    to_degree: Degree,
}

impl<T: Number> Kind for Elevate<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let c = env.numbers("control_points");
        let n = (len(env.get("control_points")) - 1.0).max(0.0);
        let m = degree_of(env.get("to_degree")).max(n);
        let d = dimension(env.get("control_points"));
        let bits = grown_bits(c.max_bits, 0.0, m);
        let ops = 4.0 * (n + 1.0) * (m + 1.0) * d;
        Some((ops * env.arith().operation(bits) + c.reading, "to_degree"))
    }

    fn solve(self, _: &Context) -> Result<Value, Error> {
        let curve = BezierCurve::new(self.control_points.0)?;
        let m = self.to_degree.0;
        let elevated = elevate(&curve, m)?;
        write(&Restricted {
            kind: "elevate",
            degree: m,
            control_points: Out(elevated.control_points().to_vec()),
        })
    }
}
