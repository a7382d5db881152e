//! `"kind": "rational-curve"`: x(t) = (sum numerator_i t^i) / (sum w_i t^i) on [alpha, beta] in
//! rational Bézier form, from the blossoms of the homogeneous curve (the inverse formula (22) of
//! seed 004), computed exactly (a weight that is exactly zero is refused) and rounded once.

use super::{check_rounded_weights, exact, exact_points, rounded, Number, Restricted};
use crate::jobs::args::MethodChoice;
use crate::jobs::cost::{curve_operations, degree_of, dimension, grown_bits, len, Arith, Env};
use crate::jobs::kind::{Context, Kind};
use crate::jobs::read::{Degree, NumberList, Numbers, Points, Reading, Written, MAX_DEGREE};
use crate::jobs::write::{write, Out};
use blossom::{Error, Method, Point};
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct RationalCurve<T> {
    /// The numerator's coefficients.
    numerator: Points<T>,
    /// The denominator's coefficients w_i.
    denominator: NumberList<T>,
    /// [alpha, beta].
    interval: Numbers<T, 2>,
    /// n, by default the larger of the two degrees.
    degree: Option<Degree>,
}

/// The answer.
#[derive(Serialize)]
#[serde(bound = "T: crate::jobs::write::Write")]
struct Answer<T: crate::jobs::write::Write> {
    #[serde(flatten)]
    curve: Restricted<usize, Vec<Point<T>>>,
    weights: Out<Vec<T>>,
}

impl<T: Number> Kind for RationalCurve<Written<T>> {
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let env = env.deciding_exactly();
        let (nu, de, i) = (
            env.numbers("numerator"),
            env.numbers("denominator"),
            env.numbers("interval"),
        );
        let longest = len(env.get("numerator")).max(len(env.get("denominator")));
        let n = degree_of(env.get("degree")).max((longest - 1.0).max(0.0));
        let d = dimension(env.get("numerator")) + 1.0;
        let bits = grown_bits(nu.max_bits.max(de.max_bits), i.max_bits, n);
        let ops = curve_operations(MethodChoice::Library(Method::Polarisation), n, d);
        let work = ops * Arith { exact: true }.operation(bits) * env.factor([7.0, 7.4]);
        Some((work + nu.and(de).and(i).reading, "numerator"))
    }

    fn solve(self, _: &Context) -> Result<Value, Error> {
        if self.numerator.0.len().max(self.denominator.0.len()) > MAX_DEGREE + 1 {
            return Err(Error::new(
                "numerator",
                format!(
                    "expected a degree of at most {MAX_DEGREE} (at most {} coefficients)",
                    MAX_DEGREE + 1
                ),
            ));
        }
        let [alpha, beta] = &self.interval.0;
        let curve = blossom::RationalCurve::new(
            &exact_points(&self.numerator.0),
            &exact(&self.denominator.0),
        )?;
        let bezier = curve.bezier(&alpha.0, &beta.0, self.degree.map(|d| d.0))?;
        let weights = rounded::<T>(bezier.weights());
        // The weights are non-zero exactly (checked before); one that rounds to zero would make
        // its rounded control point meaningless (checked first: that point may overflow).
        check_rounded_weights(
            weights
                .iter()
                .enumerate()
                .map(|(k, w)| (format!("weights[{k}]"), w)),
        )?;
        write(&Answer {
            curve: Restricted {
                kind: "rational-curve",
                degree: bezier.degree(),
                control_points: Out(bezier.points().iter().map(|p| rounded(p)).collect()),
            },
            weights: Out(weights),
        })
    }
}
