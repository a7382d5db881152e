//! The jobs of `blossom intersect` (the last section of `docs/cli.md`): zeros of a Bézier
//! function (`roots`), the intersections of two curves (`curve-curve`) and of a curve with
//! itself (`self`), every answer certified by the library's exact methods
//! ([`blossom::bezier_zeros`], [`blossom::intersect_curves`], [`blossom::self_intersections`]).
//!
//! The arithmetic names only how the input numbers are read: under `exact` as written, under
//! `f64` each rounded to the nearest double first; either way the answer is the exact one for
//! the numbers so read, and every parameter is written as a PARAM object: the correctly
//! rounded double (`"value"`), the exact rational when there is one, an isolating interval
//! with exact ends and the square-free integer polynomial it isolates a root of.
//!
//! # Limits
//!
//! Exact intersection costs grow with the product of the degrees (the resultant of two curves
//! of degrees n and m has degree n m) and with the bit length of the input numbers, so a job
//! is refused up front when a curve's degree is over [`MAX_CURVE_DEGREE`] or a Bézier
//! function's over [`MAX_FUNCTION_DEGREE`] (naming the field), and a curve job whose estimated
//! work ([`blossom::curve_pair_work`]: the float filter runs first, and when it decides only
//! the two resultants and one Descartes test per crossing remain) is over twice `--max-work`
//! is refused before computing, naming `curves` or `curve`.

use super::args::Arithmetic;
use super::job::{array, expect_fields, field, object_and_kind};
use crate::number::{f64_from_json, f64_to_json, format_rational, rational_from_json};
use blossom::{AlgebraicReal, Error, Intersections, Rational};
use serde_json::{json, Map, Value};

/// The kinds of `blossom intersect` and the fields each reads.
pub const INTERSECT_FIELDS: [(&str, &[&str]); 3] = [
    ("roots", &["kind", "control_points"]),
    ("curve-curve", &["kind", "curves"]),
    ("self", &["kind", "curve"]),
];

/// The largest degree of a curve of a `curve-curve` or `self` job. Below it the work budget
/// decides: under the default `--max-work`, degree-20 pairs and loops are answered (the
/// spec's minimum), degrees 21-24 when their estimate allows (1-3 s), and degree 28 and up
/// are refused unless the limit is raised (they take 4-15 s on a 2-core machine).
pub const MAX_CURVE_DEGREE: usize = 40;

/// The largest degree of the Bézier function of a `roots` job.
pub const MAX_FUNCTION_DEGREE: usize = 200;

/// Answers the `blossom intersect` job `document` as one JSON value.
pub fn answer(document: &Value, arithmetic: Arithmetic, max_work: u64) -> Result<Value, Error> {
    let (job, kind) = object_and_kind(document)?;
    let Some((kind, accepted)) = INTERSECT_FIELDS.iter().find(|(k, _)| *k == kind) else {
        let kinds: Vec<&str> = INTERSECT_FIELDS.iter().map(|(k, _)| *k).collect();
        return Err(Error::new(
            "kind",
            format!(
                "unknown kind \"{}\"{} (expected one of {})",
                kind.escape_default(),
                super::names::did_you_mean(kind, &kinds),
                kinds.join(", ")
            ),
        ));
    };
    expect_fields(job, "", accepted)?;
    match *kind {
        "roots" => roots(job, arithmetic),
        "curve-curve" => curve_curve(job, arithmetic, max_work),
        _ => self_job(job, arithmetic, max_work),
    }
}

/// One number of the job, exactly as the arithmetic reads it.
pub(super) fn number(value: &Value, path: &str, arithmetic: Arithmetic) -> Result<Rational, Error> {
    match arithmetic {
        Arithmetic::Exact => rational_from_json(value).map_err(|m| Error::new(path, m)),
        Arithmetic::F64 => {
            let x = f64_from_json(value).map_err(|m| Error::new(path, m))?;
            Rational::from_float(x)
                .ok_or_else(|| Error::new(path, format!("expected a finite number, found {x}")))
        }
    }
}

/// `"roots"`: the zeros of a 1-D Bézier function.
fn roots(job: &Map<String, Value>, arithmetic: Arithmetic) -> Result<Value, Error> {
    let items = array(
        field(job, "control_points")?,
        "control_points",
        "an array of numbers",
    )?;
    if items.is_empty() {
        return Err(Error::new(
            "control_points",
            "expected at least one number (a Bézier function of degree n has n + 1)",
        ));
    }
    if items.len() - 1 > MAX_FUNCTION_DEGREE {
        return Err(Error::new(
            "control_points",
            format!(
                "degree {} is over the limit of {MAX_FUNCTION_DEGREE} of blossom intersect",
                items.len() - 1
            ),
        ));
    }
    let coefficients = items
        .iter()
        .enumerate()
        .map(|(i, v)| number(v, &format!("control_points[{i}]"), arithmetic))
        .collect::<Result<Vec<_>, _>>()?;
    let zeros = blossom::bezier_zeros(&coefficients).map_err(|e| at("control_points", e))?;
    let roots = zeros
        .zeros
        .iter()
        .map(|z| Ok(json!({"t": param(&z.t)?, "multiplicity": z.multiplicity})))
        .collect::<Result<Vec<Value>, Error>>()?;
    Ok(json!({
        "kind": "roots",
        "identically_zero": zeros.identically_zero,
        "roots": roots,
    }))
}

/// `"curve-curve"`: two curves.
fn curve_curve(
    job: &Map<String, Value>,
    arithmetic: Arithmetic,
    max_work: u64,
) -> Result<Value, Error> {
    let items = array(field(job, "curves")?, "curves", "an array of two curves")?;
    if items.len() != 2 {
        return Err(Error::new(
            "curves",
            format!("expected 2 curves, found {}", items.len()),
        ));
    }
    let p = curve(&items[0], "curves[0]", arithmetic)?;
    let q = curve(&items[1], "curves[1]", arithmetic)?;
    within_budget("curves", blossom::curve_pair_work(&p, &q), max_work)?;
    let found = blossom::intersect_curves(&p, &q).map_err(|e| {
        let path = match e.path() {
            "p" => "curves[0]",
            "q" => "curves[1]",
            _ => "curves",
        };
        at(path, e)
    })?;
    intersections("curve-curve", &found)
}

/// `"self"`: one curve with itself.
fn self_job(
    job: &Map<String, Value>,
    arithmetic: Arithmetic,
    max_work: u64,
) -> Result<Value, Error> {
    let p = curve(field(job, "curve")?, "curve", arithmetic)?;
    within_budget("curve", blossom::self_intersection_work(&p), max_work)?;
    let found = blossom::self_intersections(&p).map_err(|e| at("curve", e))?;
    intersections("self", &found)
}

/// Refuses a job whose estimated work (nanoseconds of a 2-core machine, see
/// [`blossom::curve_pair_work`]) is over twice the limit: the estimates are within a factor
/// of about two of the measured time at the degrees the limit lets through, and the exact
/// solver is not metered as it runs, so the check is made up front only.
pub(super) fn within_budget(path: &str, work: u128, max_work: u64) -> Result<(), Error> {
    if work <= 2 * u128::from(max_work) {
        return Ok(());
    }
    Err(Error::new(
        path,
        format!(
            "the job's work is estimated at {:.1e} units, over the limit of {:.1e} units \
             (about a nanosecond each; raise it with --max-work if you mean it)",
            work as f64, max_work as f64
        ),
    ))
}

/// A 2-D curve's control points.
fn curve(value: &Value, path: &str, arithmetic: Arithmetic) -> Result<Vec<[Rational; 2]>, Error> {
    let items = array(value, path, "an array of 2-D points")?;
    if items.len() < 2 {
        return Err(Error::new(
            path,
            format!(
                "expected at least 2 control points (a curve of degree n >= 1 has n + 1), found {}",
                items.len()
            ),
        ));
    }
    if items.len() - 1 > MAX_CURVE_DEGREE {
        return Err(Error::new(
            path,
            format!(
                "degree {} is over the limit of {MAX_CURVE_DEGREE} of blossom intersect",
                items.len() - 1
            ),
        ));
    }
    items
        .iter()
        .enumerate()
        .map(|(i, point)| {
            let here = format!("{path}[{i}]");
            let coordinates = array(point, &here, "a point [x, y]")?;
            if coordinates.len() != 2 {
                return Err(Error::new(
                    &here,
                    format!(
                        "expected 2 coordinates (curves are 2-D), found {}",
                        coordinates.len()
                    ),
                ));
            }
            Ok([
                number(&coordinates[0], &format!("{here}[0]"), arithmetic)?,
                number(&coordinates[1], &format!("{here}[1]"), arithmetic)?,
            ])
        })
        .collect()
}

/// The answer of a `curve-curve` or `self` job.
fn intersections(kind: &str, found: &Intersections) -> Result<Value, Error> {
    let points = found
        .points
        .iter()
        .map(|p| {
            Ok(json!({
                "s": param(&p.s)?,
                "t": param(&p.t)?,
                "tangent": p.tangent,
                "point": [double(p.point[0])?, double(p.point[1])?],
            }))
        })
        .collect::<Result<Vec<Value>, Error>>()?;
    let overlaps = found
        .overlaps
        .iter()
        .map(|o| {
            Ok(json!({
                "s": [param(&o.s[0])?, param(&o.s[1])?],
                "t": [param(&o.t[0])?, param(&o.t[1])?],
            }))
        })
        .collect::<Result<Vec<Value>, Error>>()?;
    Ok(json!({"kind": kind, "points": points, "overlaps": overlaps}))
}

/// A PARAM object: the correctly rounded double, the exact value when rational, an isolating
/// interval and the square-free integer polynomial.
pub(super) fn param(x: &AlgebraicReal) -> Result<Value, Error> {
    let (lo, hi) = x.interval();
    let exact = match x.exact() {
        Some(r) => Value::String(text(r)?),
        None => Value::Null,
    };
    Ok(json!({
        "value": double(x.to_f64())?,
        "exact": exact,
        "interval": [text(lo)?, text(hi)?],
        "polynomial": x.polynomial().iter().map(ToString::to_string).collect::<Vec<_>>(),
    }))
}

fn text(r: &Rational) -> Result<String, Error> {
    format_rational(r).map_err(|m| Error::new("internal", m))
}

pub(super) fn double(x: f64) -> Result<Value, Error> {
    f64_to_json(x).map_err(|m| Error::new("internal", m))
}

/// `error` re-addressed to `path` (the library names its own arguments).
fn at(path: &str, error: Error) -> Error {
    Error::of(error.kind, path, error.message)
}
