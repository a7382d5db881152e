//! `"kind": "tensor"`: S(u, v) = sum c_ij u^i v^j restricted to [a, b] x [c, d], by every
//! `--method`.

use super::{restricted, specialised, Number};
use crate::jobs::cost::tensor_operations;
use crate::jobs::kind::prelude::*;
use blossom::{restrict_power_surface, PowerSurface};

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

/// The estimate of a tensor restriction whose grid is `grid`, the field `field`, calibrated
/// by `row` (with the change of basis from the power form).
pub fn estimate<T>(
    env: &Env,
    (grid, field): (&Rows<T>, &'static str),
    row: &Calibration,
) -> Option<(f64, &'static str)> {
    let (rows, columns, d) = grid.sizes();
    let (n, m) = ((rows - 1.0).max(0.0), (columns - 1.0).max(0.0));
    let conversion = 2.0 * (n + 1.0) * (m + 1.0) * (n + m + 2.0) * d;
    let ops = tensor_operations(env.method, n, m, d) + conversion;
    env.restriction((field, "rectangle"), n + m, ops, row)
}

impl<T: Reading> Estimate for Tensor<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        estimate(env, (&self.coefficients, "coefficients"), &CALIBRATION)
    }
}

impl<T: Number> Kind for Tensor<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        rectangular(&self.coefficients.0, "coefficients", "point")?;
        let surface = PowerSurface::new(self.coefficients.0)?;
        let rectangle = &self.rectangle.0;
        let patch = match context.method {
            MethodChoice::Library(method) => restrict_power_surface(&surface, rectangle, method),
            MethodChoice::Specialised => specialised::tensor(&surface, rectangle)?,
        };
        let (n, m) = patch.degree();
        restricted([n, m], Out(patch.to_nested()))
    }
}
