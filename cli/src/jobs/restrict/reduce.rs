//! `"kind": "reduce"`: the Bézier curve at the lower degree m by one of the library's
//! [`Reduction`]s, with the squared L2 distance of the two curves over [0, 1].

use super::{Number, Restricted};
use crate::jobs::kind::prelude::*;
use blossom::{reduce, squared_l2_distance, BezierCurve, Reduction};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Reduce<T> {
    /// b_0, ..., b_n.
    control_points: Points<T>,
    /// m < n.
    to_degree: Degree,
    /// The name of the [`Reduction`].
    method: Value,
}

/// The answer: a restriction's, and the squared L2 error.
#[derive(Serialize)]
#[serde(bound = "T: Write")]
struct Reduced<T: Write> {
    #[serde(flatten)]
    curve: Restricted<usize, Out<Vec<Vec<T>>>>,
    l2_error: Out<T>,
}

impl<T: Reading> Estimate for Reduce<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let c = env.numbers("control_points");
        let (n, d) = self.control_points.sizes();
        let m = (self.to_degree.0 as f64).min(n);
        // The Gram matrices and the solve, exact; their entries grow like a Hilbert matrix's,
        // about 4 n log2 n bits.
        let (k, l) = (n + 1.0, m + 1.0);
        let matrices =
            4.0 * (k * k * k + l * l * l) * operation(true, grown_bits(0.0, 0.0, 4.0 * n));
        let bits = grown_bits(c.max_bits, 0.0, 4.0 * n);
        let application = 8.0 * k * l * d * env.operation(bits);
        let work = (matrices + application) * env.factor([1.7, 0.35]);
        Some((work + c.reading, "control_points"))
    }
}

impl<T: Number> Kind for Reduce<T> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let curve = BezierCurve::new(self.control_points.0)?;
        if curve.degree() > MAX_DEGREE {
            return Err(Error::new(
                "control_points",
                format!(
                    "expected a degree of at most {MAX_DEGREE} (at most {} points)",
                    MAX_DEGREE + 1
                ),
            ));
        }
        let m = self.to_degree.0;
        let method = match &self.method {
            Value::String(name) => Reduction::from_name(name)?,
            other => {
                return Err(Error::new(
                    "method",
                    format!(
                        "expected a string, found {}",
                        crate::number::json_type(other)
                    ),
                ))
            }
        };
        let reduced = reduce(&curve, m, method)?;
        let error = squared_l2_distance(&reduced, &curve)?;
        write(&Reduced {
            curve: Restricted {
                degree: m,
                control_points: Out(reduced.control_points().to_vec()),
            },
            l2_error: Out(error),
        })
    }
}
