//! The jobs of the spline, rational and degree-change work (`cli.md`, last section), read with
//! the same number rules and answered with the same one-line JSON as `curve`, `tensor` and
//! `triangle`:
//!
//! ```text
//! bezier-curve    {"control_points": [...], "interval": [a, b]}
//!                 -> {"kind", "degree", "control_points"}     (every --method applies)
//! bspline         {"degree": p, "pieces": [{"interval": [e0, e1], "coefficients": [...]}, ...]}
//!                 -> {"kind", "degree", "knots", "control_points"}
//! bspline-eval    {"degree": p, "knots": [...], "control_points": [...], "at": [t, ...]}
//!                 -> {"kind", "points"}
//! rational-curve  {"numerator": [...], "denominator": [...], "interval": [alpha, beta], "degree"?}
//!                 -> {"kind", "degree", "control_points", "weights"}
//! elevate         {"control_points": [...], "to_degree": m}  -> {"kind", "degree", "control_points"}
//! reduce          {"control_points": [...], "to_degree": m, "method": M}
//!                 -> {"kind", "degree", "control_points", "l2_error"}
//! ```
//!
//! Degrees are JSON integers (or strings of digits) up to [`MAX_DEGREE`], so that no input can
//! ask for an unbounded amount of work.
//!
//! # Methods
//!
//! `--method` selects the algorithm of a `bezier-curve` job, the one job here that is a
//! restriction: `pyramid` runs de Casteljau's pyramid on the blossom of the given control
//! points (eq. (2) of seed 004), `polarisation` samples the Bézier curve and applies the
//! inverse formula (22) of seed 004, `specialised` runs the carried Bézier-input evaluator that
//! `blossom::restriction!(shape = bezier_curve)` generated for the degree (1..=16), `bulk` (the
//! default) runs the restriction engine on the control points (never leaving the Bernstein basis, as
//! accurate in f64 as de Casteljau), and `taylor-shift`, `closed-form` and `definition` write
//! the curve in the power basis (exactly, the inverse of the Bernstein basis change) and
//! restrict it like a `curve` job. The other jobs
//! have one algorithm each and give the same answer under every method.
//!
//! # Exact decisions under `--arithmetic f64`
//!
//! Two jobs make discrete decisions that rounding would falsify: `bspline` chooses each knot's
//! multiplicity from the continuity that holds *exactly* at the breakpoint, and
//! `rational-curve` refuses a weight that is *exactly* zero. Under `f64` these two jobs read
//! the numbers as written (a JSON number such as `0.1` as the decimal 1/10, a string such as
//! `"1/3"` as the fraction), compute exactly, and round each number of the answer once to the
//! nearest double. The numbers are also read as doubles first, so that the errors of `f64`
//! input (a value out of range, say) are the same as for every other job, and a number whose
//! double is zero (`"1e-999999"`) is zero here too (`exact_spelling`).

use super::answer::{point_json, Answer};
use super::args::MethodChoice;
use super::job::{array, degree_value, field, number, numbers, points, Job};
use crate::number::{f64_from_json, format_rational, json_type, rational_from_json, JsonNumber};
use crate::repeated;
use blossom::bezier_curve_blossom;
use blossom::curve_control_points_from_samples;
use blossom::engine::bernstein_to_power;
use blossom::Field;
use blossom::Point;
use blossom::{bspline_from_pieces as from_pieces, BSpline, Piece};
use blossom::{elevate, reduce, squared_l2_distance, Reduction};
use blossom::{BezierCurve, Error, Method, PowerCurve, Rational};
use blossom::{RationalBezierCurve, RationalCurve};
use serde_json::{Map, Value};

/// The kinds answered here.
pub const KINDS: [&str; 6] = super::job::LATER_KINDS;

pub use super::job::MAX_DEGREE;

/// The job object and its kind when `document` is a job of this module.
pub fn recognise(document: &Value) -> Option<(&Map<String, Value>, &'static str)> {
    super::job::recognise_kind(document, &KINDS)
}

/// Reads, computes and writes the job `job` of kind `kind` in the arithmetic `T`.
pub fn solve<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    kind: &'static str,
    method: MethodChoice,
) -> Result<Value, Error> {
    let mut out = Map::new();
    out.insert("kind".into(), Value::from(kind));
    match kind {
        "bezier-curve" => bezier_curve::<T>(job, method, &mut out)?,
        "bspline" => {
            bspline_input::<T>(job)?;
            bspline_answer::<T>(bspline_exact(&exact_spelling::<T>(job))?, &mut out)?;
        }
        "bspline-eval" => bspline_eval::<T>(job, &mut out)?,
        "rational-curve" => {
            rational_input::<T>(job)?;
            rational_answer::<T>(rational_exact(&exact_spelling::<T>(job))?, &mut out)?;
        }
        "elevate" => {
            let curve = control_points::<T>(job)?;
            let m = degree_field(job, "to_degree")?;
            let elevated = elevate(&curve, m)?;
            out.insert("degree".into(), Value::from(m));
            out.insert(
                "control_points".into(),
                points_json(&elevated.control_points().to_vec(), "control_points")?,
            );
        }
        "reduce" => reduce_job::<T>(job, &mut out)?,
        other => {
            return Err(Error::new(
                "kind",
                format!("{other:?} is not a job of this module"),
            ))
        }
    }
    Ok(Value::Object(out))
}

pub(super) fn degree_field(job: &Map<String, Value>, name: &str) -> Result<usize, Error> {
    degree_value(field(job, name)?, name)
}

/// `control_points` as a Bézier curve over [0, 1].
pub(super) fn control_points<T: JsonNumber>(
    job: &Map<String, Value>,
) -> Result<BezierCurve<T>, Error> {
    BezierCurve::new(points(
        field(job, "control_points")?,
        "control_points",
        None,
    )?)
}

/// Points as a JSON array; `path` names them in errors (a non-finite f64, say).
pub(super) fn points_json<T: JsonNumber>(pts: &[Point<T>], path: &str) -> Result<Value, Error> {
    pts.iter()
        .enumerate()
        .map(|(k, p)| point_json(p, &format!("{path}[{k}]")))
        .collect::<Result<Vec<Value>, Error>>()
        .map(Value::Array)
}

pub(super) fn numbers_json<T: JsonNumber>(xs: &[T], path: &str) -> Result<Value, Error> {
    point_json(xs, path)
}

/// The Bézier curve over [0, 1] restricted to [a, b]: the control points
/// w_v = b[a^(n-v), b^v] of its blossom.
///
/// `pyramid` evaluates the blossom of the given control points by de Casteljau's pyramid
/// (eq. (2) of seed 004), `polarisation` samples the curve (by de Casteljau) and applies the
/// inverse formula (22) of seed 004, `bulk` runs the restriction engine on the control points;
/// every other method writes the curve in the power basis and restricts it exactly like a
/// `curve` job (Theorem 1, eq. (3), and the rest).
fn bezier_curve<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    method: MethodChoice,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let curve = control_points::<T>(job)?;
    let [a, b] = numbers::<T, 2>(field(job, "interval")?, "interval")?;
    let n = curve.degree();
    let restricted: Vec<Point<T>> = match method {
        MethodChoice::Library(Method::Pyramid) => (0..=n)
            .map(|v| {
                bezier_curve_blossom(
                    &curve.control_points().to_vec(),
                    &repeated(&a, n - v, &b, v),
                )
            })
            .collect::<Result<_, _>>()?,
        MethodChoice::Library(Method::Polarisation) => {
            curve_control_points_from_samples(n, &a, &b, &|t| curve.eval(t))
        }
        MethodChoice::Library(Method::Bulk) => {
            curve.subsegment(a.clone()..b.clone()).into_control_points()
        }
        MethodChoice::Specialised => {
            match super::specialised::specialised_bezier_curve(&curve, &a, &b) {
                Some(result) => result?.into_control_points(),
                None => return Err(Error::new("--method", super::specialised::NOT_BUILT_IN)),
            }
        }
        MethodChoice::Library(method) => {
            let power = PowerCurve::new(bernstein_to_power(&curve.control_points().to_vec()))?;
            let as_curve = Job::Curve {
                curve: power,
                interval: [a, b],
            };
            let Answer::Curve(restricted) = super::answer::compute(&as_curve, method) else {
                return Err(Error::new(
                    "internal",
                    "a curve job gave another kind of answer",
                ));
            };
            restricted.into_control_points()
        }
    };
    out.insert("degree".into(), Value::from(n));
    out.insert(
        "control_points".into(),
        points_json(&restricted, "control_points")?,
    );
    Ok(())
}

/// A `bspline` job read in the arithmetic `U`: the degree p and the pieces.
fn bspline_input<U: JsonNumber + Field>(
    job: &Map<String, Value>,
) -> Result<(usize, Vec<Piece<U>>), Error> {
    let p = degree_field(job, "degree")?;
    let items = array(field(job, "pieces")?, "pieces", "an array of pieces")?;
    if items.is_empty() {
        return Err(Error::new(
            "pieces",
            "expected at least one piece, found none",
        ));
    }
    let mut pieces = Vec::with_capacity(items.len());
    let mut dim = None;
    for (i, item) in items.iter().enumerate() {
        let path = format!("pieces[{i}]");
        let Value::Object(piece) = item else {
            return Err(Error::new(
                path,
                format!("expected an object, found {}", json_type(item)),
            ));
        };
        let get = |name: &str| {
            piece
                .get(name)
                .ok_or_else(|| Error::new(format!("{path}.{name}"), "missing field"))
        };
        let interval = numbers::<U, 2>(get("interval")?, &format!("{path}.interval"))?;
        let coefficients = points::<U>(get("coefficients")?, &format!("{path}.coefficients"), dim)?;
        dim = coefficients.first().map(Vec::len);
        pieces.push(Piece {
            interval,
            curve: PowerCurve::new(coefficients)?,
        });
    }
    Ok((p, pieces))
}

/// The B-spline of a `bspline` job (Curry-Schoenberg, Theorem 2.4 of seed 002), computed
/// exactly: the knot multiplicities come from exact continuity.
fn bspline_exact(job: &Map<String, Value>) -> Result<BSpline<Rational>, Error> {
    let (p, pieces) = bspline_input::<Rational>(job)?;
    from_pieces(p, &pieces)
}

fn bspline_answer<T: JsonNumber>(
    f: BSpline<Rational>,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    out.insert("degree".into(), Value::from(f.degree()));
    out.insert(
        "knots".into(),
        numbers_json(&rounded::<T>(f.knots()), "knots")?,
    );
    let points: Vec<Point<T>> = f.control_points().iter().map(|p| rounded(p)).collect();
    out.insert(
        "control_points".into(),
        points_json(&points, "control_points")?,
    );
    Ok(())
}

/// Exact numbers in the arithmetic `T` (rounded once to the nearest double under `f64`).
pub(super) fn rounded<T: JsonNumber>(xs: &[Rational]) -> Vec<T> {
    xs.iter().map(T::from_rational).collect()
}

/// The job as exact reading should see it under the arithmetic `T` (see the module
/// documentation): unchanged under `exact`; under `f64`, every number as written (a JSON number
/// with a fraction part or an exponent, `0.1`, becomes the string of its spelling, which exact
/// reading takes as the decimal written), except that a number whose nearest double is zero is
/// zero, as it is in every other `f64` job (`"1e-999999"` underflows), and a number that exact
/// reading cannot take (an exponent beyond [`crate::number::MAX_EXPONENT`] in a long spelling)
/// is its double's exact value.
pub(super) fn exact_spelling<T: JsonNumber + Field>(
    job: &Map<String, Value>,
) -> Map<String, Value> {
    fn convert(value: &Value) -> Value {
        match value {
            Value::Number(_) | Value::String(_) => {
                let Ok(double) = f64_from_json(value) else {
                    // Not a number (a name such as a `method`), or refused by the first reading.
                    return value.clone();
                };
                let spelling = match value {
                    Value::Number(n) => Value::String(n.to_string()),
                    other => other.clone(),
                };
                if double == 0.0 {
                    Value::from(0)
                } else if rational_from_json(&spelling).is_ok() {
                    spelling
                } else {
                    Value::String(
                        Rational::from_float(double)
                            .and_then(|q| format_rational(&q).ok())
                            .unwrap_or_else(|| String::from("0")),
                    )
                }
            }
            Value::Array(items) => Value::Array(items.iter().map(convert).collect()),
            Value::Object(map) => {
                Value::Object(map.iter().map(|(k, v)| (k.clone(), convert(v))).collect())
            }
            other => other.clone(),
        }
    }
    if T::EXACT {
        return job.clone();
    }
    job.iter().map(|(k, v)| (k.clone(), convert(v))).collect()
}

fn bspline_eval<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let p = degree_field(job, "degree")?;
    let knots = number_list::<T>(field(job, "knots")?, "knots")?;
    let pts = points::<T>(field(job, "control_points")?, "control_points", None)?;
    let at = number_list::<T>(field(job, "at")?, "at")?;
    let f = BSpline::new(p, knots, pts)?;
    let values = at
        .iter()
        .enumerate()
        .map(|(i, t)| {
            f.eval(t)
                .map_err(|e| Error::new(format!("at[{i}]"), e.message))
        })
        .collect::<Result<Vec<Point<T>>, Error>>()?;
    out.insert("points".into(), points_json(&values, "points")?);
    Ok(())
}

/// A (possibly empty) array of numbers at `path`.
fn number_list<T: JsonNumber>(value: &Value, path: &str) -> Result<Vec<T>, Error> {
    array(value, path, "an array of numbers")?
        .iter()
        .enumerate()
        .map(|(k, x)| number(x, &format!("{path}[{k}]")))
        .collect()
}

/// A `rational-curve` job read in the arithmetic `U`.
struct RationalJob<U> {
    numerator: Vec<Point<U>>,
    denominator: Vec<U>,
    interval: [U; 2],
    degree: Option<usize>,
}

fn rational_input<U: JsonNumber>(job: &Map<String, Value>) -> Result<RationalJob<U>, Error> {
    let numerator = points::<U>(field(job, "numerator")?, "numerator", None)?;
    let denominator = number_list::<U>(field(job, "denominator")?, "denominator")?;
    let interval = numbers::<U, 2>(field(job, "interval")?, "interval")?;
    let degree = match job.get("degree") {
        None | Some(Value::Null) => None,
        Some(v) => Some(degree_value(v, "degree")?),
    };
    if numerator.len().max(denominator.len()) > MAX_DEGREE + 1 {
        return Err(Error::new(
            "numerator",
            format!(
                "expected a degree of at most {MAX_DEGREE} (at most {} coefficients)",
                MAX_DEGREE + 1
            ),
        ));
    }
    Ok(RationalJob {
        numerator,
        denominator,
        interval,
        degree,
    })
}

/// The rational Bézier form of a `rational-curve` job, computed exactly: the blossoms of the
/// homogeneous curve (numerator, denominator) by the inverse formula (22) of seed 004, with a
/// weight that is exactly zero refused.
fn rational_exact(job: &Map<String, Value>) -> Result<RationalBezierCurve<Rational>, Error> {
    let RationalJob {
        numerator,
        denominator,
        interval: [alpha, beta],
        degree,
    } = rational_input::<Rational>(job)?;
    RationalCurve::new(&numerator, &denominator)?.bezier(&alpha, &beta, degree)
}

fn rational_answer<T: JsonNumber>(
    bez: RationalBezierCurve<Rational>,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    out.insert("degree".into(), Value::from(bez.degree()));
    let weights = rounded::<T>(bez.weights());
    // The weights are non-zero exactly (checked before); one that rounds to zero would make
    // its rounded control point meaningless (checked first: that point may overflow).
    if let Some(k) = weights.iter().position(blossom::Ring::is_zero) {
        return Err(Error::new(
            format!("weights[{k}]"),
            "the weight is not zero but rounds to zero in f64 (underflow)",
        ));
    }
    let points: Vec<Point<T>> = bez.points().iter().map(|p| rounded(p)).collect();
    out.insert(
        "control_points".into(),
        points_json(&points, "control_points")?,
    );
    out.insert("weights".into(), numbers_json(&weights, "weights")?);
    Ok(())
}

fn reduce_job<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let curve = control_points::<T>(job)?;
    if curve.degree() > MAX_DEGREE {
        return Err(Error::new(
            "control_points",
            format!(
                "expected a degree of at most {MAX_DEGREE} (at most {} points)",
                MAX_DEGREE + 1
            ),
        ));
    }
    let m = degree_field(job, "to_degree")?;
    let method = match field(job, "method")? {
        Value::String(name) => Reduction::from_name(name)?,
        other => {
            return Err(Error::new(
                "method",
                format!("expected a string, found {}", json_type(other)),
            ))
        }
    };
    let reduced = reduce(&curve, m, method)?;
    let error = squared_l2_distance(&reduced, &curve)?;
    out.insert("degree".into(), Value::from(m));
    out.insert(
        "control_points".into(),
        points_json(&reduced.control_points().to_vec(), "control_points")?,
    );
    out.insert(
        "l2_error".into(),
        error
            .to_json()
            .map_err(|message| Error::new("l2_error", message))?,
    );
    Ok(())
}
