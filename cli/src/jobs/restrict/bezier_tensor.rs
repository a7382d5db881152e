//! `"kind": "bezier-tensor"`: the Bézier patch over [0, 1]^2 restricted to [a, b] x [c, d],
//! Q\[nu\]\[mu\] = b\[a^(n-nu), b^nu; c^(m-mu), d^mu\]. The methods as for `bezier-curve`: `bulk` on
//! the net, `pyramid` on its blossom, `polarisation` from samples (two passes of (22) of seed
//! 004), `specialised` carried, the others through the exact power form.

use super::{restricted, specialised, Number};
use crate::jobs::kind::prelude::*;
use crate::repeated;
use blossom::engine::tensor_bernstein_to_power;
use blossom::TensorPatch;
use blossom::{bezier_tensor_blossom, restrict_power_surface, tensor_control_points_from_samples};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct BezierTensor<T> {
    /// `control_points[i][j]` = b_ij.
    control_points: Rows<T>,
    /// [a, b, c, d].
    rectangle: Numbers<T, 4>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[9.8, 4.0], [8.9, 5.4], [2.6, 0.1], [11.0, 1.8], [8.0, 0.61], [5.2, 0.41]];

/// The up-front estimate: a `tensor`'s.
impl<T: Reading> Estimate for BezierTensor<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        super::tensor::estimate(env, (&self.control_points, "control_points"), &CALIBRATION)
    }
}

impl<T: Number> Kind for BezierTensor<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        rectangular(&self.control_points.0, "control_points", "point")?;
        let patch = TensorPatch::new(self.control_points.0)?;
        let rect = &self.rectangle.0;
        let (n, m) = patch.degree();
        let [a, b, c, d] = rect;
        let net: Vec<Vec<Point<T>>> = match context.method {
            MethodChoice::Library(Method::Bulk) => patch.restrict(rect).into_control_points(),
            MethodChoice::Library(Method::Pyramid) => {
                let nested = patch.to_nested();
                (0..=n)
                    .map(|nu| {
                        (0..=m)
                            .map(|mu| {
                                bezier_tensor_blossom(
                                    &nested,
                                    &repeated(a, n - nu, b, nu),
                                    &repeated(c, m - mu, d, mu),
                                )
                            })
                            .collect::<Result<_, _>>()
                    })
                    .collect::<Result<_, _>>()?
            }
            MethodChoice::Library(Method::Polarisation) => {
                tensor_control_points_from_samples((n, m), rect, &|u, v| patch.eval(u, v))
            }
            MethodChoice::Specialised => {
                specialised::bezier_tensor(&patch, rect)?.into_control_points()
            }
            MethodChoice::Library(method) => {
                restrict_power_surface(&tensor_bernstein_to_power(&patch), rect, method)
                    .into_control_points()
            }
        };
        restricted([n, m], Out(net))
    }
}
