//! `"kind": "curve"`: C(u) = sum_i c_i u^i restricted to [a, b], by every `--method`.

use super::{specialised, Number, Restricted};
use crate::jobs::args::MethodChoice;
use crate::jobs::cost::{
    curve_operations, dimension, grown_bits, len, polar_bits, Calibration, Env,
};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Numbers, Points, Reading};
use crate::jobs::write::{write, Out};
use blossom::{restrict_power_curve, Error, PowerCurve};
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Curve<T> {
    /// c_0, ..., c_n.
    coefficients: Points<T>,
    /// [a, b].
    interval: Numbers<T, 2>,
}

/// The measured factors of [`Curve::estimate`] ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[2.4, 36.0], [3.9, 1.5], [22.0, 0.66], [7.5, 1.7], [3.9, 0.89], [1.6, 0.09]];

/// The estimate of a curve restriction whose points are the field `points`, with `conversion`
/// more operations per (n + 1)^2 d (the change of basis of `bezier-curve`), calibrated by `row`.
pub fn estimate(
    env: &Env,
    points: &'static str,
    conversion: f64,
    row: &Calibration,
) -> Option<(f64, &'static str)> {
    let (c, i) = (env.numbers(points), env.numbers("interval"));
    let n = (len(env.get(points)) - 1.0).max(0.0);
    let d = dimension(env.get(points));
    let polar = polar_bits(env.method);
    let bits = grown_bits(polar * c.max_bits, polar * i.max_bits, n);
    let ops = curve_operations(env.method, n, d) + conversion * (n + 1.0) * (n + 1.0) * d;
    let work = ops * env.arith().operation(bits) * env.calibrated(row);
    Some((work + c.and(i).reading, points))
}

impl<T: Number> Kind for Curve<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        estimate(env, "coefficients", 0.0, &CALIBRATION)
    }

    fn solve(self, context: &Context) -> Result<Value, Error> {
        let curve = PowerCurve::new(self.coefficients.0)?;
        let [a, b] = &self.interval.0;
        let restricted = match context.method {
            MethodChoice::Library(method) => restrict_power_curve(&curve, a, b, method),
            MethodChoice::Specialised => specialised::curve(&curve, a, b)?,
        };
        write(&Restricted {
            kind: "curve",
            degree: restricted.degree(),
            control_points: Out(restricted.into_control_points()),
        })
    }
}
