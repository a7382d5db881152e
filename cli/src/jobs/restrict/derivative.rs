//! `"kind": "derivative"`: the control points of the k-th derivative of the Bézier curve over
//! [0, 1], n!/(n-k)! times the k-th forward differences of its control points.

use super::{restricted, Number};
use crate::jobs::kind::prelude::*;
use blossom::BezierCurve;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Derivative<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// k.
    order: Degree,
}

impl<T: Reading> Estimate for Derivative<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let c = env.numbers("control_points");
        let (n, d) = self.control_points.sizes();
        let ops = 4.0 * (n + 1.0) * (n + 1.0) * d;
        let work = ops * env.operation(grown_bits(c.max_bits, 0.0, n)) * env.factor([0.27, 1.0]);
        Some((work + c.reading, "control_points"))
    }
}

impl<T: Number> Kind for Derivative<T> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let curve = BezierCurve::new(self.control_points.0)?;
        let (n, Degree(k)) = (curve.degree(), self.order);
        if k > n {
            return Err(Error::new(
                "order",
                format!("expected an order of at most {n} (the curve's degree), found {k}"),
            ));
        }
        let hodograph = blossom::bezier_derivative(&curve, k)?;
        restricted(n - k, Out(hodograph.control_points().to_vec()))
    }
}
