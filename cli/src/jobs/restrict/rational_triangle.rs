//! `"kind": "rational-triangle"`: the quotient of two surfaces (rectangular grids, or
//! triangular arrays with `"total_degree"`) on a triangle as a rational triangular patch,
//! computed exactly and rounded once; a zero weight is an error.

use super::rational_tensor::{estimate, grids, sizes};
use super::{check_rounded_weights, entries, exact, exact_points, restricted, rounded, Number};
use crate::jobs::cost::triangle_operations;
use crate::jobs::kind::prelude::*;
use blossom::{RationalPowerTriangle, RationalSurface, TriangularPatch};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct RationalTriangle<T> {
    /// N for triangular arrays.
    total_degree: Option<Degree>,
    /// The numerator's grid or triangular array.
    numerator: Rows<T>,
    /// The denominator's.
    denominator: NumberRows<T>,
    /// The corners.
    triangle: Corners<T, 2>,
    /// N, by default the total degree of the grids.
    degree: Option<Degree>,
}

impl<T: Reading> Estimate for RationalTriangle<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let (rows, columns, d) = sizes(&self.numerator, &self.denominator);
        let (n, m) = ((rows - 1.0).max(0.0), (columns - 1.0).max(0.0));
        let total = if self.total_degree.is_some() {
            n
        } else {
            n + m
        };
        let big_n = self.degree.map_or(0.0, |d| d.0 as f64).max(total);
        let polarisation = MethodChoice::Library(Method::Polarisation);
        let ops = triangle_operations(polarisation, big_n, rows * columns.max(1.0), d);
        estimate(env, "triangle", big_n, ops, [1.7, 1.7])
    }
}

impl<T: Number> Kind for RationalTriangle<Written<T>> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let surface = match self.total_degree {
            Some(Degree(big_n)) => {
                triangular(&self.numerator.0, "numerator", big_n, "point")?;
                triangular(&self.denominator.0, "denominator", big_n, "number")?;
                let p: Vec<Vec<Point<_>>> =
                    self.numerator.0.iter().map(|r| exact_points(r)).collect();
                let w: Vec<Vec<_>> = self.denominator.0.iter().map(|r| exact(r)).collect();
                RationalPowerTriangle::new(&p, &w)?
            }
            None => {
                let (p, w) = grids(&self.numerator.0, &self.denominator.0)?;
                RationalPowerTriangle::from_surface(&RationalSurface::new(&p, &w)?)
            }
        };
        let corners = self.triangle.0.map(|c| [c[0].0.clone(), c[1].0.clone()]);
        let patch = surface.triangle(&corners, self.degree.map(|d| d.0))?;
        let points: Vec<Point<T>> = patch.points().iter().map(|p| rounded(p)).collect();
        let weights: Vec<T> = rounded(patch.weights());
        check_rounded_weights(
            weights
                .iter()
                .enumerate()
                .map(|(k, w)| (format!("control_points[{k}].weight"), w)),
        )?;
        let net = TriangularPatch::new(patch.degree(), points)?;
        restricted(patch.degree(), entries(&net, Some(&weights)))
    }
}
