//! `"kind": "tensor"`: S(u, v) = sum c_ij u^i v^j restricted to [a, b] x [c, d], by every
//! `--method`.

use super::{specialised, Number, Restricted};
use crate::jobs::args::MethodChoice;
use crate::jobs::cost::{dimension, first_len, grown_bits, len, polar_bits, tensor_operations};
use crate::jobs::cost::{Calibration, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{rectangular, Numbers, Reading, Rows};
use crate::jobs::write::{write, Out};
use blossom::{restrict_power_surface, Error, PowerSurface};
use serde::Deserialize;
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Tensor<T> {
    /// `coefficients[i][j]` = c_ij.
    coefficients: Rows<T>,
    /// [a, b, c, d].
    rectangle: Numbers<T, 4>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[6.3, 4.8], [8.9, 14.0], [9.7, 0.15], [10.0, 0.49], [5.4, 0.44], [3.0, 0.51]];

/// The estimate of a tensor restriction whose grid is the field `grid`, calibrated by `row`.
pub fn estimate(env: &Env, grid: &'static str, row: &Calibration) -> Option<(f64, &'static str)> {
    let (c, r) = (env.numbers(grid), env.numbers("rectangle"));
    let n = (len(env.get(grid)) - 1.0).max(0.0);
    let m = (first_len(env.get(grid)) - 1.0).max(0.0);
    let d = dimension(env.get(grid));
    let polar = polar_bits(env.method);
    let bits = grown_bits(polar * c.max_bits, polar * r.max_bits, n + m);
    let conversion = 2.0 * (n + 1.0) * (m + 1.0) * (n + m + 2.0) * d;
    let ops = tensor_operations(env.method, n, m, d) + conversion;
    let work = ops * env.arith().operation(bits) * env.calibrated(row);
    Some((work + c.and(r).reading, grid))
}

impl<T: Number> Kind for Tensor<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        estimate(env, "coefficients", &CALIBRATION)
    }

    fn solve(self, context: &Context) -> Result<Value, Error> {
        rectangular(&self.coefficients.0, "coefficients", "point")?;
        let surface = PowerSurface::new(self.coefficients.0)?;
        let rectangle = &self.rectangle.0;
        let patch = match context.method {
            MethodChoice::Library(method) => restrict_power_surface(&surface, rectangle, method),
            MethodChoice::Specialised => specialised::tensor(&surface, rectangle)?,
        };
        let (n, m) = patch.degree();
        write(&Restricted {
            kind: "tensor",
            degree: [n, m],
            control_points: Out(patch.to_nested()),
        })
    }
}
