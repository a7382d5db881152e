//! `"kind": "elevate"`: the Bézier curve's control points at the higher degree m.

use super::{restricted, Number};
use crate::jobs::kind::prelude::*;
use blossom::{elevate, BezierCurve};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Elevate<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// m >= n.
    to_degree: Degree,
}

impl<T: Reading> Estimate for Elevate<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let c = env.numbers("control_points");
        let (n, d) = self.control_points.sizes();
        let m = (self.to_degree.0 as f64).max(n);
        let ops = 4.0 * (n + 1.0) * (m + 1.0) * d;
        let bits = grown_bits(c.max_bits, 0.0, m);
        Some((ops * env.operation(bits) + c.reading, "to_degree"))
    }
}

impl<T: Number> Kind for Elevate<T> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let curve = BezierCurve::new(self.control_points.0)?;
        let m = self.to_degree.0;
        let elevated = elevate(&curve, m)?;
        restricted(m, Out(elevated.control_points().to_vec()))
    }
}
