//! `"kind": "bspline-eval"`: points of a B-spline by de Boor's algorithm; a parameter outside
//! the knot range is an error, at the last knot the last span is used.

use super::Number;
use crate::jobs::kind::prelude::*;
use blossom::BSpline;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct BsplineEval<T> {
    /// p.
    degree: Degree,
    /// The knot vector.
    knots: NumberList<T>,
    /// The de Boor points.
    control_points: Points<T>,
    /// The parameters.
    at: NumberList<T>,
}

/// The answer.
#[derive(Serialize)]
#[serde(bound = "T: Write")]
struct Answer<T: Write> {
    points: Out<Vec<Point<T>>>,
}

impl<T: Reading> Estimate for BsplineEval<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let [k, c, t] = ["knots", "control_points", "at"].map(|field| env.numbers(field));
        let (n, d) = self.control_points.sizes();
        let (at, knots) = (self.at.0.len() as f64, self.knots.0.len() as f64);
        let p = self.degree.0 as f64;
        let q = p + 1.0;
        let bits = grown_bits(c.max_bits, 2.0 * (k.max_bits + t.max_bits), p);
        let ops =
            at * (2.0 * q * q * (d + 1.0) + knots.log2().max(1.0)) + 4.0 * (knots + (n + 1.0) * d);
        let field = if at > q { "at" } else { "degree" };
        Some((ops * env.operation(bits) + k.and(c).and(t).reading, field))
    }
}

impl<T: Number> Kind for BsplineEval<T> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let f = BSpline::new(self.degree.0, self.knots.0, self.control_points.0)?;
        let points = self
            .at
            .0
            .iter()
            .enumerate()
            .map(|(i, t)| {
                f.eval(t)
                    .map_err(|e| Error::new(format!("at[{i}]"), e.message))
            })
            .collect::<Result<Vec<Point<T>>, Error>>()?;
        write(&Answer {
            points: Out(points),
        })
    }
}
