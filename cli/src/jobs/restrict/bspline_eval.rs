//! `"kind": "bspline-eval"`: points of a B-spline by de Boor's algorithm; a parameter outside
//! the knot range is an error, at the last knot the last span is used.

use super::Number;
use crate::jobs::cost::{degree_of, dimension, grown_bits, len, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Degree, NumberList, Points, Reading};
use crate::jobs::write::{write, Out};
use blossom::{BSpline, Error, Point};
use serde::{Deserialize, Serialize};
use serde_json::Value;

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
#[serde(bound = "T: crate::jobs::write::Write")]
struct Answer<T: crate::jobs::write::Write> {
    kind: &'static str,
    points: Out<Vec<Point<T>>>,
}

impl<T: Number> Kind for BsplineEval<T> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let (k, c, t) = (
            env.numbers("knots"),
            env.numbers("control_points"),
            env.numbers("at"),
        );
        let p = degree_of(env.get("degree"));
        let d = dimension(env.get("control_points"));
        let (at, knots) = (len(env.get("at")), len(env.get("knots")));
        let q = p + 1.0;
        let bits = grown_bits(c.max_bits, 2.0 * (k.max_bits + t.max_bits), p);
        let ops = at * (2.0 * q * q * (d + 1.0) + knots.log2().max(1.0))
            + 4.0 * (knots + len(env.get("control_points")) * d);
        let field = if at > q { "at" } else { "degree" };
        Some((
            ops * env.arith().operation(bits) + k.and(c).and(t).reading,
            field,
        ))
    }

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
            kind: "bspline-eval",
            points: Out(points),
        })
    }
}
