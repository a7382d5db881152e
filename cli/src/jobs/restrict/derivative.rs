//! `"kind": "derivative"`: the control points of the k-th derivative of the Bézier curve over
//! [0, 1], n!/(n-k)! times the k-th forward differences of its control points.

use super::{Number, Restricted};
use crate::jobs::cost::{dimension, grown_bits, len, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Degree, Points, Reading};
use crate::jobs::write::{write, Out};
use blossom::{BezierCurve, Error};
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Derivative<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// k.
    order: Degree,
}

impl<T: Number> Kind for Derivative<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let c = env.numbers("control_points");
        let n = (len(env.get("control_points")) - 1.0).max(0.0);
        let d = dimension(env.get("control_points"));
        let bits = grown_bits(c.max_bits, 0.0, n);
        let ops = 4.0 * (n + 1.0) * (n + 1.0) * d;
        let work = ops * env.arith().operation(bits) * env.factor([0.27, 1.0]);
        Some((work + c.reading, "control_points"))
    }

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
        write(&Restricted {
            kind: "derivative",
            degree: n - k,
            control_points: Out(hodograph.control_points().to_vec()),
        })
    }
}
