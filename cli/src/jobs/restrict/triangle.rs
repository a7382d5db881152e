//! `"kind": "triangle"`: S(u, v) = sum c_ij u^i v^j of total degree N = n + m (a rectangular
//! grid), or sum_(i+j<=N) c_ij u^i v^j with `"total_degree": N` (a triangular array, row i
//! holding N + 1 - i points), on the triangle with the given corners, by every `--method`.

use super::{entries, specialised, Number};
use crate::jobs::args::MethodChoice;
use crate::jobs::cost::{dimension, first_len, grown_bits, len, polar_bits, triangle_operations};
use crate::jobs::cost::{Calibration, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{rectangular, triangular, Corners, Degree, Reading, Rows};
use crate::jobs::write::write;
use blossom::{restrict_power_surface_to_triangle, restrict_power_triangle, Error};
use blossom::{PowerSurface, PowerTriangle, TriangularPatch};
use serde::{Deserialize, Serialize};
use serde_json::Value;

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

/// The answer of a triangular restriction.
#[derive(Serialize)]
pub struct TriangleAnswer<E: Serialize> {
    /// The kind of the job.
    pub kind: &'static str,
    /// N.
    pub degree: usize,
    /// The entries `{"a", "b", "c", "point"}` in lexicographic order of (a, b).
    pub control_points: Vec<E>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[11.0, 12.0], [11.0, 1.6], [36.0, 0.35], [4.4, 0.35], [17.0, 0.56], [11.0, 0.79]];

/// The estimate of a triangle restriction of total degree N with `terms` coefficients, whose
/// points are in the field `grid`, calibrated by `row`.
pub fn estimate(
    env: &Env,
    grid: &'static str,
    (big_n, terms): (f64, f64),
    row: &Calibration,
) -> Option<(f64, &'static str)> {
    let (c, t) = (env.numbers(grid), env.numbers("triangle"));
    let d = dimension(env.get(grid));
    let polar = polar_bits(env.method);
    let bits = grown_bits(polar * c.max_bits, polar * t.max_bits, big_n);
    let ops = triangle_operations(env.method, big_n, terms, d) + 4.0 * terms * big_n * d;
    let work = ops * env.arith().operation(bits) * env.calibrated(row);
    Some((work + c.and(t).reading, grid))
}

impl<T: Number> Kind for Triangle<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let grid = env.get("coefficients");
        let sizes = if env.get("total_degree").is_some_and(|v| !v.is_null()) {
            let rows = len(grid);
            ((rows - 1.0).max(0.0), rows * (rows + 1.0) / 2.0)
        } else {
            let (rows, columns) = (len(grid), first_len(grid));
            ((rows + columns - 2.0).max(0.0), rows * columns)
        };
        estimate(env, "coefficients", sizes, &CALIBRATION)
    }

    fn solve(self, context: &Context) -> Result<Value, Error> {
        let rows = self.coefficients.0;
        let corners = self.triangle.0;
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
        write(&TriangleAnswer {
            kind: "triangle",
            degree: patch.degree(),
            control_points: entries(&patch, None),
        })
    }
}
