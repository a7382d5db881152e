//! `"kind": "curve"`: C(u) = sum_i c_i u^i restricted to [a, b], by every `--method`.

use super::{restricted, specialised, Number};
use crate::jobs::cost::curve_operations;
use crate::jobs::kind::prelude::*;
use blossom::{restrict_power_curve, PowerCurve};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Curve<T> {
    /// c_0, ..., c_n.
    coefficients: Points<T>,
    /// [a, b].
    interval: Numbers<T, 2>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[2.4, 36.0], [3.9, 1.5], [22.0, 0.66], [7.5, 1.7], [3.9, 0.89], [1.6, 0.09]];

impl<T: Reading> Estimate for Curve<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let (n, d) = self.coefficients.sizes();
        let ops = curve_operations(env.method, n, d);
        env.restriction(("coefficients", "interval"), n, ops, &CALIBRATION)
    }
}

impl<T: Number> Kind for Curve<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let curve = PowerCurve::new(self.coefficients.0)?;
        let [a, b] = &self.interval.0;
        let bezier = match context.method {
            MethodChoice::Library(method) => restrict_power_curve(&curve, a, b, method),
            MethodChoice::Specialised => specialised::curve(&curve, a, b)?,
        };
        restricted(bezier.degree(), Out(bezier.into_control_points()))
    }
}
