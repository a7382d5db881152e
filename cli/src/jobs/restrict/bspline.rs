//! `"kind": "bspline"`: consecutive polynomial pieces as a B-spline (Curry-Schoenberg, Theorem
//! 2.4 of seed 002), the de Boor points as blossoms of the pieces, each interior knot's
//! multiplicity p - r from the continuity r that holds exactly there (so computed exactly, and
//! rounded once under `f64`).

use super::{exact_points, rounded, Number};
use crate::jobs::kind::prelude::*;
use blossom::{bspline_from_pieces, Piece, PowerCurve};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct Bspline<T> {
    /// p.
    degree: Degree,
    /// The pieces, in order.
    pieces: Pieces<T>,
}

/// At least one piece.
#[derive(Debug)]
struct Pieces<T>(Vec<PieceJob<T>>);

impl<'de, T: Reading> Deserialize<'de> for Pieces<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| {
            items(v, "an array of pieces", not_empty("piece"), object)
        })
        .map(Pieces)
    }
}

/// One piece: its interval and its coefficients in the power basis of the global parameter.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading", expecting = "an object")]
struct PieceJob<T> {
    interval: Numbers<T, 2>,
    coefficients: Points<T>,
}

/// The answer.
#[derive(Serialize)]
#[serde(bound = "T: Write")]
struct Answer<T: Write> {
    degree: usize,
    knots: Out<Vec<T>>,
    control_points: Out<Vec<Point<T>>>,
}

/// The up-front estimate, exact under both arithmetics.
impl<T: Reading> Estimate for Bspline<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let env = env.deciding_exactly();
        let c = env.numbers("pieces");
        let (_, d) = self.pieces.0[0].coefficients.sizes();
        let p = self.degree.0 as f64;
        let q = p + 1.0;
        let ops = 4.0 * self.pieces.0.len() as f64 * q * q * (q + d);
        let bits = grown_bits(c.max_bits, c.max_bits, p);
        let work = ops * operation(true, bits) * env.factor([0.58, 0.81]);
        Some((work + c.reading, "pieces"))
    }
}

impl<T: Number> Kind for Bspline<Written<T>> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let mut pieces = Vec::with_capacity(self.pieces.0.len());
        let mut dim = None;
        let intervals: Vec<[Written<T>; 2]> =
            self.pieces.0.iter().map(|p| p.interval.0.clone()).collect();
        for (i, piece) in self.pieces.0.into_iter().enumerate() {
            let coefficients = exact_points(&piece.coefficients.0);
            let d = coefficients[0].len();
            if let Some(first) = dim.filter(|first| *first != d) {
                let message = format!("expected {}, found {d}", coordinates(first));
                return Err(Error::new(format!("pieces[{i}].coefficients[0]"), message));
            }
            dim = Some(d);
            pieces.push(Piece {
                interval: piece.interval.0.map(|x| x.0),
                curve: PowerCurve::new(coefficients)?,
            });
        }
        let f =
            bspline_from_pieces(self.degree.0, &pieces).map_err(|e| as_written(e, &intervals))?;
        write(&Answer {
            degree: f.degree(),
            knots: Out(rounded::<T>(f.knots())),
            control_points: Out(f.control_points().iter().map(|p| rounded(p)).collect()),
        })
    }
}

/// A refusal of piece i's interval (its ends out of order, or not meeting the previous
/// piece) with the ends quoted as written in the job (`0.1`, not `1/10`): each word of the
/// message that is the exact value of one of the interval's ends, or of the previous piece's
/// end, becomes that number's spelling.
fn as_written<T>(e: Error, intervals: &[[Written<T>; 2]]) -> Error {
    let Some(i) = (0..intervals.len()).find(|i| e.field == format!("pieces[{i}].interval")) else {
        return e;
    };
    let mut ends: Vec<&Written<T>> = intervals[i].iter().collect();
    if i > 0 {
        ends.push(&intervals[i - 1][1]);
    }
    let mut message = String::with_capacity(e.message.len());
    let mut word = String::new();
    let flush = |word: &mut String, message: &mut String| {
        let spelled = ends.iter().find(|x| x.0.to_string() == *word);
        message.push_str(spelled.map_or(word.as_str(), |x| x.spelling()));
        word.clear();
    };
    for c in e.message.chars() {
        if c.is_ascii_alphanumeric() || matches!(c, '/' | '-' | '_') {
            word.push(c);
        } else {
            flush(&mut word, &mut message);
            message.push(c);
        }
    }
    flush(&mut word, &mut message);
    Error::of(e.kind, e.field, message)
}
