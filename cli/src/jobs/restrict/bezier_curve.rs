//! `"kind": "bezier-curve"`: the Bézier curve over [0, 1] restricted to [a, b], the control
//! points w_v = b[a^(n-v), b^v] of its blossom. `bulk` runs the restriction engine on the
//! control points, `pyramid` evaluates the blossom of the given control points by de
//! Casteljau's pyramid (eq. (2) of seed 004), `polarisation` samples the curve and applies the
//! inverse formula (22) of seed 004, `specialised` the carried Bézier-input evaluator; the
//! other methods write the curve in the power basis (exactly) and restrict it like a `curve`.

use super::{restricted, specialised, Number};
use crate::jobs::cost::curve_operations;
use crate::jobs::kind::prelude::*;
use crate::repeated;
use blossom::engine::bernstein_to_power;
use blossom::PowerCurve;
use blossom::{bezier_curve_blossom, curve_control_points_from_samples, restrict_power_curve};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct BezierCurve<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// [a, b].
    interval: Numbers<T, 2>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[3.1, 26.0], [3.2, 1.4], [4.5, 0.66], [61.0, 10.0], [5.2, 0.075], [2.6, 0.06]];

/// The up-front estimate: a `curve`'s, with the change of basis.
impl<T: Reading> Estimate for BezierCurve<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let (n, d) = self.control_points.sizes();
        let ops = curve_operations(env.method, n, d) + 2.0 * (n + 1.0) * (n + 1.0) * d;
        env.restriction(("control_points", "interval"), n, ops, &CALIBRATION)
    }
}

impl<T: Number> Kind for BezierCurve<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let curve = blossom::BezierCurve::new(self.control_points.0)?;
        let [a, b] = &self.interval.0;
        let n = curve.degree();
        let points: Vec<Point<T>> = match context.method {
            MethodChoice::Library(Method::Bulk) => {
                curve.subsegment(a.clone()..b.clone()).into_control_points()
            }
            MethodChoice::Library(Method::Pyramid) => {
                let points = curve.control_points().to_vec();
                (0..=n)
                    .map(|v| bezier_curve_blossom(&points, &repeated(a, n - v, b, v)))
                    .collect::<Result<_, _>>()?
            }
            MethodChoice::Library(Method::Polarisation) => {
                curve_control_points_from_samples(n, a, b, &|t| curve.eval(t))
            }
            MethodChoice::Specialised => {
                specialised::bezier_curve(&curve, a, b)?.into_control_points()
            }
            MethodChoice::Library(method) => {
                let power = PowerCurve::new(bernstein_to_power(&curve.control_points().to_vec()))?;
                restrict_power_curve(&power, a, b, method).into_control_points()
            }
        };
        restricted(n, Out(points))
    }
}
