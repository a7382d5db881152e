//! `"kind": "rational-curve"`: x(t) = (sum numerator_i t^i) / (sum w_i t^i) on [alpha, beta] in
//! rational Bézier form, from the blossoms of the homogeneous curve (the inverse formula (22) of
//! seed 004), computed exactly (a weight that is exactly zero is refused) and rounded once.

use super::{check_rounded_weights, exact, exact_points, rounded, Number, Restricted};
use crate::jobs::cost::curve_operations;
use crate::jobs::kind::prelude::*;

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
#[serde(bound = "T: Write")]
struct Answer<T: Write> {
    #[serde(flatten)]
    curve: Restricted<usize, Out<Vec<Point<T>>>>,
    weights: Out<Vec<T>>,
}

/// The up-front estimate, exact under both arithmetics.
impl<T: Reading> Estimate for RationalCurve<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let env = env.deciding_exactly();
        let [nu, de, i] = ["numerator", "denominator", "interval"].map(|f| env.numbers(f));
        let longest = self.numerator.0.len().max(self.denominator.0.len()) as f64;
        let n = self.degree.map_or(0.0, |d| d.0 as f64).max(longest - 1.0);
        let d = self.numerator.sizes().1 + 1.0;
        let bits = grown_bits(nu.max_bits.max(de.max_bits), i.max_bits, n);
        let ops = curve_operations(MethodChoice::Library(Method::Polarisation), n, d);
        let work = ops * operation(true, bits) * env.factor([7.0, 7.4]);
        Some((work + nu.and(de).and(i).reading, "numerator"))
    }
}

impl<T: Number> Kind for RationalCurve<Written<T>> {
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
                degree: bezier.degree(),
                control_points: Out(bezier.points().iter().map(|p| rounded(p)).collect()),
            },
            weights: Out(weights),
        })
    }
}
