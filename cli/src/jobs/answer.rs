//! Computing and writing the answer of a job: the Bézier object by the chosen method, then the
//! JSON shape of the contract.
//!
//! ```text
//! {"kind": "curve", "degree": n, "control_points": [w_0, ..., w_n]}
//! {"kind": "tensor", "degree": [n, m], "control_points": [[p_00, ..., p_0m], ...]}
//! {"kind": "triangle", "degree": N, "control_points": [{"a": nu, "b": mu, "c": lambda, "point": q}, ...]}
//! ```
//!
//! Keys appear in this order. Every number goes through [`JsonNumber::to_json`], so an `f64`
//! answer with an infinity or NaN anywhere is an error naming the first such coordinate
//! (for example `control_points[2][0]`), never a partial or `null`-filled answer.

use super::job::Job;
use crate::number::JsonNumber;

use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle,
    restrict_power_triangle, BezierCurve, Error, Method, Ring, TensorPatch, TriangularPatch,
};
use serde_json::{Map, Value};

/// The Bézier object that answers a [`Job`].
#[derive(Clone, Debug, PartialEq)]
pub enum Answer<T: Ring> {
    /// The answer of a `curve` job.
    Curve(BezierCurve<T>),
    /// The answer of a `tensor` job.
    Tensor(TensorPatch<T>),
    /// The answer of a `triangle` job.
    Triangle(TriangularPatch<T>),
}

/// Restricts the job's curve or surface to its domain by `method`.
pub fn compute<T: Ring>(job: &Job<T>, method: Method) -> Answer<T> {
    match job {
        Job::Curve {
            curve,
            interval: [a, b],
        } => Answer::Curve(restrict_power_curve(curve, a, b, method)),
        Job::Tensor { surface, rectangle } => {
            Answer::Tensor(restrict_power_surface(surface, rectangle, method))
        }
        Job::Triangle { surface, triangle } => Answer::Triangle(
            restrict_power_surface_to_triangle(surface, triangle, method),
        ),
        Job::TotalDegreeTriangle { surface, triangle } => {
            Answer::Triangle(restrict_power_triangle(surface, triangle, method))
        }
    }
}

/// A point as a JSON array; `path` names it in errors.
pub(super) fn point_json<T: JsonNumber>(p: &[T], path: &str) -> Result<Value, Error> {
    p.iter()
        .enumerate()
        .map(|(k, x)| {
            x.to_json()
                .map_err(|message| Error::new(format!("{path}[{k}]"), message))
        })
        .collect::<Result<Vec<Value>, Error>>()
        .map(Value::Array)
}

/// The entries `{"a", "b", "c", "point"(, "weight")}` of a triangular net in lexicographic
/// order of (a, b).
pub(super) fn triangle_entries<T: JsonNumber>(
    net: &TriangularPatch<T>,
    weights: Option<&[T]>,
) -> Result<Vec<Value>, Error> {
    net.entries()
        .enumerate()
        .map(|(k, (nu, mu, lambda, q))| {
            let mut entry = Map::new();
            entry.insert("a".into(), Value::from(nu));
            entry.insert("b".into(), Value::from(mu));
            entry.insert("c".into(), Value::from(lambda));
            entry.insert(
                "point".into(),
                point_json(q, &format!("control_points[{k}].point"))?,
            );
            if let Some(w) = weights {
                entry.insert(
                    "weight".into(),
                    w[k].to_json()
                        .map_err(|m| Error::new(format!("control_points[{k}].weight"), m))?,
                );
            }
            Ok(Value::Object(entry))
        })
        .collect()
}

/// The answer as the JSON object of the contract.
pub fn to_json<T: JsonNumber>(answer: &Answer<T>) -> Result<Value, Error> {
    let (kind, degree, control_points) = match answer {
        Answer::Curve(curve) => {
            let points = curve
                .control_points()
                .iter()
                .enumerate()
                .map(|(v, p)| point_json(p, &format!("control_points[{v}]")))
                .collect::<Result<Vec<Value>, Error>>()?;
            ("curve", Value::from(curve.degree()), points)
        }
        Answer::Tensor(patch) => {
            let (n, m) = patch.degree();
            let rows = patch
                .to_nested()
                .iter()
                .enumerate()
                .map(|(nu, row)| {
                    row.iter()
                        .enumerate()
                        .map(|(mu, p)| point_json(p, &format!("control_points[{nu}][{mu}]")))
                        .collect::<Result<Vec<Value>, Error>>()
                        .map(Value::Array)
                })
                .collect::<Result<Vec<Value>, Error>>()?;
            ("tensor", Value::from(vec![n, m]), rows)
        }
        Answer::Triangle(patch) => {
            let entries = triangle_entries(patch, None)?;
            ("triangle", Value::from(patch.degree()), entries)
        }
    };
    let mut object = Map::new();
    object.insert("kind".into(), Value::from(kind));
    object.insert("degree".into(), degree);
    object.insert("control_points".into(), Value::Array(control_points));
    Ok(Value::Object(object))
}
