//! `"kind": "triangle"`: S(u, v) = sum c_ij u^i v^j of total degree N = n + m (a rectangular
//! grid), or sum_(i+j<=N) c_ij u^i v^j with `"total_degree": N` (a triangular array, row i
//! holding N + 1 - i points), on the triangle with the given corners, by every `--method`.

use super::{entries, restricted, specialised, Number};
use crate::jobs::cost::triangle_operations;
use crate::jobs::kind::prelude::*;
use blossom::{restrict_power_surface_to_triangle, restrict_power_triangle};
use blossom::{PowerSurface, PowerTriangle, TriangularPatch};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Triangle<T> {
    /// N for a triangular array.
    total_degree: Option<Degree>,
    /// `coefficients[i][j]` = c_ij.
    coefficients: Rows<T>,
    /// The corners `[[a1, a2], [b1, b2], [c1, c2]]`.
    triangle: Corners<T, 2>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[11.0, 12.0], [11.0, 1.6], [36.0, 0.35], [4.4, 0.35], [17.0, 0.56], [11.0, 0.79]];

/// The estimate of a triangle restriction of total degree N with `terms` coefficients of
/// dimension d, whose points are in the field `field`, calibrated by `row` (with the change of
/// basis from the power form).
pub fn estimate(
    env: &Env,
    field: &'static str,
    (big_n, terms, d): (f64, f64, f64),
    row: &Calibration,
) -> Option<(f64, &'static str)> {
    let ops = triangle_operations(env.method, big_n, terms, d) + 4.0 * terms * big_n * d;
    env.restriction((field, "triangle"), big_n, ops, row)
}

impl<T: Reading> Estimate for Triangle<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let (rows, columns, d) = self.coefficients.sizes();
        let (big_n, terms) = match self.total_degree {
            Some(_) => ((rows - 1.0).max(0.0), rows * (rows + 1.0) / 2.0),
            None => ((rows + columns - 2.0).max(0.0), rows * columns),
        };
        estimate(env, "coefficients", (big_n, terms, d), &CALIBRATION)
    }
}

impl<T: Number> Kind for Triangle<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let (rows, corners) = (self.coefficients.0, self.triangle.0);
        let patch: TriangularPatch<T> = match self.total_degree {
            Some(Degree(big_n)) => {
                triangular(&rows, "coefficients", big_n, "point")?;
                let surface = PowerTriangle::new(rows)?;
                match context.method {
                    MethodChoice::Library(m) => restrict_power_triangle(&surface, &corners, m),
                    MethodChoice::Specialised => specialised::total_triangle(&surface, &corners)?,
                }
            }
            None => {
                rectangular(&rows, "coefficients", "point")?;
                let surface = PowerSurface::new(rows)?;
                match context.method {
                    MethodChoice::Library(m) => {
                        restrict_power_surface_to_triangle(&surface, &corners, m)
                    }
                    MethodChoice::Specialised => specialised::triangle(&surface, &corners)?,
                }
            }
        };
        restricted(patch.degree(), entries(&patch, None))
    }
}
