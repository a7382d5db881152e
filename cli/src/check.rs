//! `blossom check`: the exact error of somebody else's `f64` answer to a restriction job
//! (`docs/cli.md`, section "Checking another program's answer").
//!
//! The input is `{"job": JOB, "answer": ANSWER}`. The reference is the exact answer for the
//! doubles the other program had: every number of JOB is read as its nearest double (the
//! reading of `--arithmetic f64`, [`f64_from_json`]) and that double is then taken exactly
//! ([`exact_doubles`]); the job so rewritten goes through the work budget and the exact solver
//! of `blossom restrict` (`jobs::solve` in [`Rational`], its default method `bulk`). The
//! answer's `control_points` are walked against the exact ones (`walk`) and the points
//! compared by [`blossom::exact_error`], whose definitions the output follows.
//!
//! A field of the document other than `job` and `answer`, or one that JOB's kind does not read,
//! is refused before anything else is read; the fields of ANSWER other than
//! `control_points` (and those of a triangle's entries other than `a`, `b`, `c`, `point`) are
//! ignored, as the contract says: an answer is another program's output and may carry more.

use crate::names::expect_fields;
use crate::number::{f64_from_json, f64_to_json, format_rational, json_type, rational_from_json};
use blossom::{exact_error, rational_to_f64, Error, Point, Rational};
use serde_json::{json, Map, Value};

/// The report of `blossom check` on `document` (`{"job": ..., "answer": ...}`): one line of
/// JSON, without the newline.
///
/// `shape` checks a job's kind and fields (the names of all of them first) without reading its
/// numbers; `exact` computes its exact answer within the work budget (both are `blossom
/// restrict`'s, passed in by the command line).
pub fn check_command(
    document: &Value,
    per_point: bool,
    shape: &dyn Fn(&Value) -> Result<(), Error>,
    exact: &dyn Fn(&Value) -> Result<Value, Error>,
) -> Result<String, Error> {
    let Value::Object(top) = document else {
        return Err(Error::new(
            "input",
            format!(
                "expected an object {{\"job\": ..., \"answer\": ...}}, found {}",
                json_type(document)
            ),
        ));
    };
    expect_fields(top, "", &["job", "answer"])?;
    let job = top
        .get("job")
        .ok_or_else(|| Error::new("job", "missing field"))?;
    shape(job).map_err(in_job)?;
    let answer = top
        .get("answer")
        .ok_or_else(|| Error::new("answer", "missing field"))?;
    let Value::Object(answer) = answer else {
        return Err(Error::new(
            "answer",
            format!(
                "expected an object with \"control_points\", found {}",
                json_type(answer)
            ),
        ));
    };
    let answer_points = answer
        .get("control_points")
        .ok_or_else(|| Error::new("answer.control_points", "missing field"))?;

    let job = exact_doubles(job, "job")?;
    let exact = exact(&job).map_err(in_job)?;
    let Some(exact_points) = exact.get("control_points") else {
        return Err(Error::new(
            "job.kind",
            "the answer of this job has no \"control_points\" to check",
        ));
    };

    let mut points = Points::default();
    walk(
        exact_points,
        answer_points,
        "answer.control_points".into(),
        &mut Vec::new(),
        &mut points,
    )?;
    let error = exact_error(&points.exact, &points.answer).map_err(|e| Error {
        field: format!("answer.{}", e.field),
        ..e
    })?;

    let at = |i: usize| json!(points.at.get(i).cloned().unwrap_or_default());
    let mut out = Map::new();
    out.insert("points".into(), json!(points.exact.len()));
    out.insert("max_abs_error".into(), exact_json(&error.max_abs)?);
    out.insert("max_abs_error_f64".into(), nearest_json(&error.max_abs));
    out.insert("max_abs_at".into(), at(error.max_abs_at));
    out.insert("max_rel_error".into(), exact_json(&error.max_rel)?);
    out.insert("max_rel_error_f64".into(), nearest_json(&error.max_rel));
    out.insert("max_rel_at".into(), at(error.max_rel_at));
    if per_point {
        let per_point = error
            .per_point
            .iter()
            .enumerate()
            .map(|(i, p)| {
                Ok(json!({
                    "at": at(i),
                    "abs": exact_json(&p.abs)?,
                    "abs_f64": nearest_json(&p.abs),
                    "rel": exact_json(&p.rel)?,
                    "rel_f64": nearest_json(&p.rel),
                }))
            })
            .collect::<Result<Vec<Value>, Error>>()?;
        out.insert("per_point".into(), Value::Array(per_point));
    }
    serde_json::to_string(&Value::Object(out))
        .map_err(|e| Error::new("internal", format!("cannot write the report: {e}")))
}

/// An error of the job, its field under `job.` (the job as a whole, `input`, is `job`).
fn in_job(error: Error) -> Error {
    let field = match error.field.as_str() {
        "" | "input" => String::from("job"),
        f if f.starts_with('-') => f.to_string(),
        f => format!("job.{f}"),
    };
    Error { field, ..error }
}

/// An exact number as the contract writes it (`"p/q"` in lowest terms).
fn exact_json(q: &Rational) -> Result<Value, Error> {
    format_rational(q)
        .map(Value::String)
        .map_err(|e| Error::new("internal", e))
}

/// The nearest double of `q` as a JSON number, `null` when it is out of the range of doubles.
fn nearest_json(q: &Rational) -> Value {
    f64_to_json(rational_to_f64(q)).unwrap_or(Value::Null)
}

/// The job `value` (at `path`) with every number replaced by the exact value of its nearest
/// double, written as an exact number (`"p/q"`): a JSON number or a string that `--arithmetic
/// f64` reads as the double x becomes the exact rational x. JSON integers of at most 15 digits
/// (exact doubles already, and the only spelling of sizes, degrees and indices) stay as they
/// are; other strings (`"curve"`, `"least-squares"`) too. A number that has no nearest double
/// (`"1e400"`, `"-inf"`) is an error at its path.
pub fn exact_doubles(value: &Value, path: &str) -> Result<Value, Error> {
    match value {
        Value::Number(n) => {
            let text = n.to_string();
            let digits = text.trim_start_matches('-');
            if digits.len() <= 15 && digits.bytes().all(|b| b.is_ascii_digit()) {
                return Ok(value.clone());
            }
            exact_double_json(value, path)
        }
        Value::String(s) => {
            let numeric = s
                .bytes()
                .next()
                .is_some_and(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.'));
            if numeric {
                exact_double_json(value, path)
            } else {
                Ok(value.clone())
            }
        }
        Value::Array(items) => items
            .iter()
            .enumerate()
            .map(|(i, item)| exact_doubles(item, &format!("{path}[{i}]")))
            .collect::<Result<Vec<_>, _>>()
            .map(Value::Array),
        Value::Object(map) => map
            .iter()
            .map(|(k, v)| Ok((k.clone(), exact_doubles(v, &format!("{path}.{k}"))?)))
            .collect::<Result<Map<_, _>, Error>>()
            .map(Value::Object),
        other => Ok(other.clone()),
    }
}

/// The number `value` read as its nearest double, as the exact string of that double.
fn exact_double_json(value: &Value, path: &str) -> Result<Value, Error> {
    let double = f64_from_json(value).map_err(|e| Error::new(path, e))?;
    let exact =
        Rational::from_float(double).ok_or_else(|| Error::new(path, "not a finite double"))?;
    exact_json(&exact)
}

/// The control points found by [`walk`], in order: where each is (`at`, its indices in the
/// nested arrays), its exact coordinates and the answer's.
#[derive(Default)]
struct Points {
    at: Vec<Vec<usize>>,
    exact: Vec<Point<Rational>>,
    answer: Vec<Point<f64>>,
}

/// Whether `value` is a point of an exact answer: an array of numbers (strings).
fn is_point(value: &[Value]) -> bool {
    !value.is_empty() && value.iter().all(|x| !(x.is_array() || x.is_object()))
}

/// Walks the answer's `answer` (at `path`, indices `at`) against the exact answer's `exact`,
/// which has the same nesting: arrays of arrays down to the points (arrays of numbers), or, for
/// triangles, entries `{"a", "b", "c", "point"}` whose integer fields must be equal in the
/// answer and whose `"point"` is compared (other fields, such as a weight, are not).
fn walk(
    exact: &Value,
    answer: &Value,
    path: String,
    at: &mut Vec<usize>,
    out: &mut Points,
) -> Result<(), Error> {
    match exact {
        Value::Array(items) if is_point(items) => {
            let Value::Array(coords) = answer else {
                return Err(Error::new(
                    path,
                    format!(
                        "expected a point of {} numbers, found {}",
                        items.len(),
                        json_type(answer)
                    ),
                ));
            };
            if coords.len() != items.len() {
                return Err(Error::new(
                    path,
                    format!(
                        "expected {} coordinates, found {}",
                        items.len(),
                        coords.len()
                    ),
                ));
            }
            let answer = coords
                .iter()
                .enumerate()
                .map(|(k, x)| f64_from_json(x).map_err(|e| Error::new(format!("{path}[{k}]"), e)))
                .collect::<Result<Point<f64>, Error>>()?;
            let exact = items
                .iter()
                .map(|x| rational_from_json(x).map_err(|e| Error::new("internal", e)))
                .collect::<Result<Point<Rational>, Error>>()?;
            out.at.push(at.clone());
            out.exact.push(exact);
            out.answer.push(answer);
            Ok(())
        }
        Value::Array(items) => {
            let Value::Array(entries) = answer else {
                return Err(Error::new(
                    path,
                    format!(
                        "expected an array of {} entries, found {}",
                        items.len(),
                        json_type(answer)
                    ),
                ));
            };
            if entries.len() != items.len() {
                return Err(Error::new(
                    path,
                    format!("expected {} entries, found {}", items.len(), entries.len()),
                ));
            }
            for (i, (e, a)) in items.iter().zip(entries).enumerate() {
                at.push(i);
                walk(e, a, format!("{path}[{i}]"), at, out)?;
                at.pop();
            }
            Ok(())
        }
        Value::Object(fields) => {
            let Value::Object(given) = answer else {
                return Err(Error::new(
                    path,
                    format!("expected an object, found {}", json_type(answer)),
                ));
            };
            for (key, value) in fields {
                if key == "point" {
                    let point = given
                        .get(key)
                        .ok_or_else(|| Error::new(format!("{path}.point"), "missing field"))?;
                    walk(value, point, format!("{path}.point"), at, out)?;
                } else if let Some(index) = value.as_u64() {
                    let found = given.get(key);
                    if found.and_then(|v| f64_from_json(v).ok()) != Some(index as f64) {
                        return Err(Error::new(
                            format!("{path}.{key}"),
                            format!(
                                "expected {index}, found {}",
                                found.map_or_else(|| String::from("nothing"), |v| v.to_string())
                            ),
                        ));
                    }
                }
            }
            Ok(())
        }
        _ => Err(Error::new(
            "internal",
            format!("unexpected {} in an exact answer", json_type(exact)),
        )),
    }
}
