//! Reading a job: from a parsed JSON document to a [`Job`] of the library's types, with the path
//! of the offending field in every error (`coefficients[2]`, `interval`, `triangle[1][0]`).
//!
//! Fields are checked in this order: the top level is an object, `kind`, the names of all
//! fields ([`check_fields`]), `coefficients`, then the domain (`interval`, `rectangle` or
//! `triangle`); within an array, element by element.
//!
//! # Unknown fields
//!
//! A field that the job's kind does not read is refused, at any depth of the job (the pieces of
//! a `bspline`, the entries of a `bezier-triangle`), with the nearest accepted name when one is
//! within a few typing slips: `control_point: unknown field "control_point" (did you mean
//! "control_points"?)`. A misspelt optional field would otherwise be ignored without a word,
//! and a misspelt required one reported as missing. [`check_fields`] runs on the whole document
//! before anything else is read, so that this error comes before a missing field's. The
//! accepted names are [`JOB_FIELDS`] and [`NESTED_FIELDS`]; [`expect_fields`] checks one object
//! and is what a reader of another kind of job calls.
//!
//! To support a new kind, add an arm to [`parse_job`] (and remove the name from
//! [`LATER_KINDS`]), a variant to [`Job`], its fields to [`JOB_FIELDS`], and its computation in
//! [`super::answer`].

use super::names::{did_you_mean, listed, quoted};
use crate::number::{json_type, JsonNumber};
use blossom::Point;
use blossom::{Error, PowerCurve, PowerSurface, PowerTriangle};
use serde_json::{Map, Value};

/// The kinds this version computes, as listed in messages.
pub const KINDS: [&str; 3] = ["curve", "tensor", "triangle"];

/// Kinds of the contract answered by [`super::spline_jobs`] (the command line dispatches them
/// there before calling [`parse_job`], which refuses them as jobs of another module).
pub const LATER_KINDS: [&str; 6] = [
    "bezier-curve",
    "bspline",
    "bspline-eval",
    "rational-curve",
    "elevate",
    "reduce",
];

/// Kinds of the contract answered by [`super::patch_jobs`] (dispatched there like
/// [`LATER_KINDS`]).
pub const PATCH_KINDS: [&str; 5] = [
    "bezier-tensor",
    "bezier-triangle",
    "derivative",
    "rational-tensor",
    "rational-triangle",
];

/// A restriction job, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub enum Job<T> {
    /// `"kind": "curve"`: C(u) on `interval = [a, b]`.
    Curve {
        /// C(u) = sum c_i u^i.
        curve: PowerCurve<T>,
        /// `[a, b]`.
        interval: [T; 2],
    },
    /// `"kind": "tensor"`: S(u, v) on `rectangle = [a, b, c, d]`, i.e. [a, b] x [c, d].
    Tensor {
        /// S(u, v) = sum c_ij u^i v^j.
        surface: PowerSurface<T>,
        /// `[a, b, c, d]`.
        rectangle: [T; 4],
    },
    /// `"kind": "triangle"`: S(u, v) of total degree n + m on the triangle with these corners.
    Triangle {
        /// S(u, v) = sum c_ij u^i v^j.
        surface: PowerSurface<T>,
        /// `[[a1, a2], [b1, b2], [c1, c2]]`.
        triangle: [[T; 2]; 3],
    },
    /// `"kind": "triangle"` with `"total_degree": N`: S(u, v) = sum_{i+j<=N} c_ij u^i v^j from
    /// its triangular array, at total degree N, on the triangle with these corners.
    TotalDegreeTriangle {
        /// The triangular array, `rows()[i][j]` = c_ij.
        surface: PowerTriangle<T>,
        /// `[[a1, a2], [b1, b2], [c1, c2]]`.
        triangle: [[T; 2]; 3],
    },
}

/// The fields each kind of job reads, `kind` first (optional fields included).
pub const JOB_FIELDS: [(&str, &[&str]); 14] = [
    ("curve", &["kind", "coefficients", "interval"]),
    ("tensor", &["kind", "coefficients", "rectangle"]),
    (
        "triangle",
        &["kind", "coefficients", "triangle", "total_degree"],
    ),
    ("bezier-curve", &["kind", "control_points", "interval"]),
    ("bspline", &["kind", "degree", "pieces"]),
    (
        "bspline-eval",
        &["kind", "degree", "knots", "control_points", "at"],
    ),
    (
        "rational-curve",
        &["kind", "numerator", "denominator", "interval", "degree"],
    ),
    ("elevate", &["kind", "control_points", "to_degree"]),
    ("reduce", &["kind", "control_points", "to_degree", "method"]),
    ("bezier-tensor", &["kind", "control_points", "rectangle"]),
    ("bezier-triangle", &["kind", "control_points", "triangle"]),
    ("derivative", &["kind", "control_points", "order"]),
    (
        "rational-tensor",
        &["kind", "numerator", "denominator", "rectangle", "degree"],
    ),
    (
        "rational-triangle",
        &[
            "kind",
            "numerator",
            "denominator",
            "triangle",
            "degree",
            "total_degree",
        ],
    ),
];

/// The objects inside a job: (kind, field, the fields of each object in that field's array).
pub const NESTED_FIELDS: [(&str, &str, &[&str]); 2] = [
    ("bspline", "pieces", &["interval", "coefficients"]),
    (
        "bezier-triangle",
        "control_points",
        &["a", "b", "c", "point"],
    ),
];

/// Refuses a field of `object` (the object at `path`, `""` for the top level) that is not one
/// of `accepted`: `error: PATH.NAME: unknown field "NAME" (did you mean "..."?)`, or with the
/// accepted names listed when none is near. Fields are checked in the object's order.
pub fn expect_fields(
    object: &Map<String, Value>,
    path: &str,
    accepted: &[&str],
) -> Result<(), Error> {
    let Some(name) = object.keys().find(|k| !accepted.contains(&k.as_str())) else {
        return Ok(());
    };
    let at = if path.is_empty() {
        name.clone()
    } else {
        format!("{path}.{name}")
    };
    let hint = match did_you_mean(name, accepted) {
        near if !near.is_empty() => near,
        _ => format!(" (expected {})", listed(accepted)),
    };
    Err(Error::new(
        at,
        format!("unknown field {}{hint}", quoted(name)),
    ))
}

/// Refuses every field of the job `document` that its kind does not read ([`JOB_FIELDS`], and
/// inside the arrays of [`NESTED_FIELDS`]). What is not a job of a known kind passes (reading
/// refuses it with its own message), except that a job without `kind` is checked against the
/// fields of every kind, so that a misspelt `kind` is named as such.
pub fn check_fields(document: &Value) -> Result<(), Error> {
    let Value::Object(job) = document else {
        return Ok(());
    };
    let kind = match job.get("kind") {
        Some(Value::String(kind)) => kind.as_str(),
        Some(_) => return Ok(()),
        None => {
            let mut every: Vec<&str> = Vec::new();
            for name in JOB_FIELDS.iter().flat_map(|(_, fields)| fields.iter()) {
                if !every.contains(name) {
                    every.push(name);
                }
            }
            return expect_fields(job, "", &every);
        }
    };
    let Some((_, accepted)) = JOB_FIELDS.iter().find(|(k, _)| *k == kind) else {
        return Ok(());
    };
    expect_fields(job, "", accepted)?;
    for (_, name, inner) in NESTED_FIELDS.iter().filter(|(k, _, _)| *k == kind) {
        let Some(Value::Array(items)) = job.get(*name) else {
            continue;
        };
        for (i, item) in items.iter().enumerate() {
            if let Value::Object(object) = item {
                expect_fields(object, &format!("{name}[{i}]"), inner)?;
            }
        }
    }
    Ok(())
}

/// The job object of `document` (the whole parsed input) and its `"kind"` string, or the error
/// naming `input` (not an object) or `kind` (missing, not a string).
pub(super) fn object_and_kind(document: &Value) -> Result<(&Map<String, Value>, &str), Error> {
    let Value::Object(job) = document else {
        return Err(Error::new(
            "input",
            format!(
                "expected a JSON object (a job), found {}",
                json_type(document)
            ),
        ));
    };
    match field(job, "kind")? {
        Value::String(kind) => Ok((job, kind.as_str())),
        other => Err(Error::new(
            "kind",
            format!("expected a string, found {}", json_type(other)),
        )),
    }
}

/// Reads the job in `document`, the whole parsed input.
pub fn parse_job<T: JsonNumber>(document: &Value) -> Result<Job<T>, Error> {
    let (job, kind) = object_and_kind(document)?;
    match kind {
        "curve" => {
            let coefficients = points(field(job, "coefficients")?, "coefficients", None)?;
            let [a, b] = numbers::<T, 2>(field(job, "interval")?, "interval")?;
            Ok(Job::Curve {
                curve: PowerCurve::new(coefficients)?,
                interval: [a, b],
            })
        }
        "tensor" => Ok(Job::Tensor {
            surface: grid(field(job, "coefficients")?)?,
            rectangle: numbers::<T, 4>(field(job, "rectangle")?, "rectangle")?,
        }),
        "triangle" => match job.get("total_degree") {
            None | Some(Value::Null) => {
                let surface = grid(field(job, "coefficients")?)?;
                let triangle = corners::<T, 3>(field(job, "triangle")?, "triangle")?;
                Ok(Job::Triangle { surface, triangle })
            }
            Some(total) => {
                let big_n = degree_value(total, "total_degree")?;
                let rows = triangular_array(field(job, "coefficients")?, "coefficients", big_n)?;
                let surface = PowerTriangle::new(rows)?;
                let triangle = corners::<T, 3>(field(job, "triangle")?, "triangle")?;
                Ok(Job::TotalDegreeTriangle { surface, triangle })
            }
        },
        later if LATER_KINDS.contains(&later) || PATCH_KINDS.contains(&later) => Err(Error::new(
            "kind",
            format!("{} is not supported by this version", quoted(later)),
        )),
        unknown => {
            let kinds: Vec<&str> = KINDS
                .iter()
                .chain(&LATER_KINDS)
                .chain(&PATCH_KINDS)
                .copied()
                .collect();
            Err(Error::new(
                "kind",
                format!(
                    "unknown kind {}{} (expected one of {})",
                    quoted(unknown),
                    did_you_mean(unknown, &kinds),
                    kinds.join(", ")
                ),
            ))
        }
    }
}

/// The largest degree a job may name (`degree`, `to_degree`, `total_degree`, `order`, the
/// degree of a B-spline).
pub const MAX_DEGREE: usize = 200;

/// A degree: a non-negative JSON integer or a string of digits, at most [`MAX_DEGREE`].
pub(super) fn degree_value(value: &Value, path: &str) -> Result<usize, Error> {
    let text = match value {
        Value::Number(n) => n.to_string(),
        Value::String(s) => s.trim().to_string(),
        other => {
            return Err(Error::new(
                path,
                format!(
                    "expected a non-negative integer, found {}",
                    json_type(other)
                ),
            ))
        }
    };
    if text.is_empty() || !text.bytes().all(|b| b.is_ascii_digit()) {
        return Err(Error::new(
            path,
            format!("expected a non-negative integer, found {text:?}"),
        ));
    }
    match text.parse::<usize>() {
        Ok(d) if d <= MAX_DEGREE => Ok(d),
        _ => Err(Error::new(
            path,
            format!("expected a degree of at most {MAX_DEGREE}, found {text}"),
        )),
    }
}

/// The job object and its kind when `document` is an object whose `kind` is one of `kinds`.
pub(super) fn recognise_kind<'a>(
    document: &'a Value,
    kinds: &[&'static str],
) -> Option<(&'a Map<String, Value>, &'static str)> {
    let Value::Object(job) = document else {
        return None;
    };
    let Some(Value::String(kind)) = job.get("kind") else {
        return None;
    };
    kinds
        .iter()
        .find(|k| **k == kind.as_str())
        .map(|k| (job, *k))
}

/// The value of a required field.
pub(super) fn field<'a>(job: &'a Map<String, Value>, name: &str) -> Result<&'a Value, Error> {
    job.get(name)
        .ok_or_else(|| Error::new(name, "missing field"))
}

/// The elements of an array-valued field, or an error saying what was expected.
pub(super) fn array<'a>(
    value: &'a Value,
    path: &str,
    expected: &str,
) -> Result<&'a [Value], Error> {
    match value {
        Value::Array(items) => Ok(items),
        other => Err(Error::new(
            path,
            format!("expected {expected}, found {}", json_type(other)),
        )),
    }
}

/// One number at `path`.
pub(super) fn number<T: JsonNumber>(value: &Value, path: &str) -> Result<T, Error> {
    T::from_json(value).map_err(|message| Error::new(path, message))
}

/// Exactly `N` numbers at `path` (an interval or a rectangle).
pub(super) fn numbers<T: JsonNumber, const N: usize>(
    value: &Value,
    path: &str,
) -> Result<[T; N], Error> {
    let items = array(value, path, &format!("an array of {N} numbers"))?;
    if items.len() != N {
        return Err(Error::new(
            path,
            format!("expected {N} numbers, found {}", items.len()),
        ));
    }
    let parsed = items
        .iter()
        .enumerate()
        .map(|(k, x)| number(x, &format!("{path}[{k}]")))
        .collect::<Result<Vec<T>, Error>>()?;
    parsed
        .try_into()
        .map_err(|_| Error::new(path, format!("expected {N} numbers")))
}

/// Exactly `N` corners of two coordinates each at `path` (a triangle).
pub(super) fn corners<T: JsonNumber, const N: usize>(
    value: &Value,
    path: &str,
) -> Result<[[T; 2]; N], Error> {
    let items = array(value, path, &format!("an array of {N} corners"))?;
    if items.len() != N {
        return Err(Error::new(
            path,
            format!("expected {N} corners, found {}", items.len()),
        ));
    }
    let mut out = Vec::with_capacity(N);
    for (k, item) in items.iter().enumerate() {
        let corner_path = format!("{path}[{k}]");
        let coordinates = array(item, &corner_path, "a corner (an array of 2 numbers)")?;
        if coordinates.len() != 2 {
            return Err(Error::new(
                &corner_path,
                format!("expected 2 coordinates, found {}", coordinates.len()),
            ));
        }
        out.push(numbers::<T, 2>(item, &corner_path)?);
    }
    out.try_into()
        .map_err(|_| Error::new(path, format!("expected {N} corners")))
}

/// "1 coordinate", "3 coordinates".
fn coordinates_count(d: usize) -> String {
    if d == 1 {
        String::from("1 coordinate")
    } else {
        format!("{d} coordinates")
    }
}

/// A point (an array of numbers) at `path`; `dim` is the dimension of the job's points when
/// known (the first point fixes it).
pub(super) fn point<T: JsonNumber>(
    value: &Value,
    path: &str,
    dim: Option<usize>,
) -> Result<Point<T>, Error> {
    let coordinates = array(value, path, "a point (an array of numbers)")?;
    match dim {
        Some(d) if coordinates.len() != d => {
            return Err(Error::new(
                path,
                format!(
                    "expected {}, found {}",
                    coordinates_count(d),
                    coordinates.len()
                ),
            ))
        }
        None if coordinates.is_empty() => {
            return Err(Error::new(path, "expected at least 1 coordinate, found 0"))
        }
        _ => {}
    }
    coordinates
        .iter()
        .enumerate()
        .map(|(k, x)| number(x, &format!("{path}[{k}]")))
        .collect()
}

/// A non-empty list of points of one dimension at `path` (the coefficients of a curve, or a
/// row of a grid). `dim` as for [`point`].
pub(super) fn points<T: JsonNumber>(
    value: &Value,
    path: &str,
    dim: Option<usize>,
) -> Result<Vec<Point<T>>, Error> {
    let items = array(value, path, "an array of points")?;
    if items.is_empty() {
        return Err(Error::new(path, "expected at least one point, found none"));
    }
    let mut out: Vec<Point<T>> = Vec::with_capacity(items.len());
    let mut dim = dim;
    for (k, item) in items.iter().enumerate() {
        let p = point(item, &format!("{path}[{k}]"), dim)?;
        dim = Some(p.len());
        out.push(p);
    }
    Ok(out)
}

/// The triangular array of a surface of total degree `big_n` at `path`: N + 1 rows, row i holding
/// the N + 1 - i points c_i0 .. c_i(N-i), all of one dimension.
pub(super) fn triangular_array<T: JsonNumber>(
    value: &Value,
    path: &str,
    big_n: usize,
) -> Result<Vec<Vec<Point<T>>>, Error> {
    let rows = array(value, path, "an array of rows of points")?;
    if rows.len() != big_n + 1 {
        return Err(Error::new(
            path,
            format!(
                "expected {} rows (a triangular array of total degree {big_n}), found {}",
                big_n + 1,
                rows.len()
            ),
        ));
    }
    let mut out: Vec<Vec<Point<T>>> = Vec::with_capacity(rows.len());
    let mut dim: Option<usize> = None;
    for (i, row) in rows.iter().enumerate() {
        let row_path = format!("{path}[{i}]");
        let items = array(row, &row_path, "a row of points (an array)")?;
        if items.len() != big_n + 1 - i {
            return Err(Error::new(
                &row_path,
                format!(
                    "expected {} points (row {i} of a triangular array of total degree {big_n} \
                     holds N + 1 - i), found {}",
                    big_n + 1 - i,
                    items.len()
                ),
            ));
        }
        let parsed = points(row, &row_path, dim)?;
        dim = parsed.first().map(Vec::len);
        out.push(parsed);
    }
    Ok(out)
}

/// The rectangular coefficient grid of a surface: `coefficients[i][j]` = c_ij.
fn grid<T: JsonNumber>(value: &Value) -> Result<PowerSurface<T>, Error> {
    PowerSurface::new(point_grid(value, "coefficients")?)
}

/// A non-empty rectangular grid of points of one dimension at `path` (`[i][j]`).
pub(super) fn point_grid<T: JsonNumber>(
    value: &Value,
    path: &str,
) -> Result<Vec<Vec<Point<T>>>, Error> {
    let rows = array(value, path, "an array of rows of points")?;
    if rows.is_empty() {
        return Err(Error::new(path, "expected at least one row, found none"));
    }
    let mut out: Vec<Vec<Point<T>>> = Vec::with_capacity(rows.len());
    let mut dim: Option<usize> = None;
    for (i, row) in rows.iter().enumerate() {
        let row_path = format!("{path}[{i}]");
        let items = array(row, &row_path, "a row of points (an array)")?;
        if let Some(first) = out.first() {
            if items.len() != first.len() {
                return Err(Error::new(
                    &row_path,
                    format!(
                        "expected {} points (the grid must be rectangular), found {}",
                        first.len(),
                        items.len()
                    ),
                ));
            }
        }
        let parsed = points(row, &row_path, dim)?;
        dim = parsed.first().map(Vec::len);
        out.push(parsed);
    }
    Ok(out)
}

/// A non-empty rectangular grid of numbers at `path` (`[i][j]`, a scalar denominator).
pub(super) fn number_grid<T: JsonNumber>(value: &Value, path: &str) -> Result<Vec<Vec<T>>, Error> {
    let rows = array(value, path, "an array of rows of numbers")?;
    if rows.is_empty() {
        return Err(Error::new(path, "expected at least one row, found none"));
    }
    let mut out: Vec<Vec<T>> = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let row_path = format!("{path}[{i}]");
        let parsed = number_row(row, &row_path)?;
        if let Some(first) = out.first() {
            if parsed.len() != first.len() {
                return Err(Error::new(
                    &row_path,
                    format!(
                        "expected {} numbers (the grid must be rectangular), found {}",
                        first.len(),
                        parsed.len()
                    ),
                ));
            }
        }
        out.push(parsed);
    }
    Ok(out)
}

/// The triangular array of numbers of total degree `big_n` at `path`: N + 1 rows, row i
/// holding N + 1 - i numbers.
pub(super) fn number_triangular_array<T: JsonNumber>(
    value: &Value,
    path: &str,
    big_n: usize,
) -> Result<Vec<Vec<T>>, Error> {
    let rows = array(value, path, "an array of rows of numbers")?;
    if rows.len() != big_n + 1 {
        return Err(Error::new(
            path,
            format!(
                "expected {} rows (a triangular array of total degree {big_n}), found {}",
                big_n + 1,
                rows.len()
            ),
        ));
    }
    rows.iter()
        .enumerate()
        .map(|(i, row)| {
            let row_path = format!("{path}[{i}]");
            let parsed = number_row(row, &row_path)?;
            if parsed.len() != big_n + 1 - i {
                return Err(Error::new(
                    &row_path,
                    format!(
                        "expected {} numbers (row {i} of a triangular array of total degree \
                         {big_n} holds N + 1 - i), found {}",
                        big_n + 1 - i,
                        parsed.len()
                    ),
                ));
            }
            Ok(parsed)
        })
        .collect()
}

/// A non-empty row of numbers at `path`.
fn number_row<T: JsonNumber>(value: &Value, path: &str) -> Result<Vec<T>, Error> {
    let items = array(value, path, "a row of numbers (an array)")?;
    if items.is_empty() {
        return Err(Error::new(path, "expected at least one number, found none"));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, x)| number(x, &format!("{path}[{k}]")))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use blossom::Rational;
    use serde_json::json;

    fn error(job: Value) -> String {
        parse_job::<Rational>(&job).unwrap_err().to_string()
    }

    #[test]
    fn messages_name_the_field() {
        assert_eq!(
            error(
                json!({"kind": "curve", "coefficients": [[1, 2, 3], [1, 2, 3], [1, 2]], "interval": [0, 1]})
            ),
            "coefficients[2]: expected 3 coordinates, found 2"
        );
        assert_eq!(
            error(json!({"kind": "curve", "coefficients": [[1]], "interval": [0, 1, 2]})),
            "interval: expected 2 numbers, found 3"
        );
        assert_eq!(
            error(json!({"kind": "foo"})),
            "kind: unknown kind \"foo\" (expected one of curve, tensor, triangle, bezier-curve, \
             bspline, bspline-eval, rational-curve, elevate, reduce, bezier-tensor, bezier-triangle, \
             derivative, rational-tensor, rational-triangle)"
        );
        assert_eq!(
            error(json!({"kind": "bspline"})),
            "kind: \"bspline\" is not supported by this version"
        );
        assert_eq!(
            error(json!({"kind": "curve", "coefficients": [[1]]})),
            "interval: missing field"
        );
        assert_eq!(
            error(json!({"kind": "tensor", "coefficients": [[[1]]], "rectangle": [0, 1, 2, "x"]})),
            "rectangle[3]: cannot read \"x\" as a number (expected an integer such as \"-7\", a \
             fraction such as \"3/4\" or a decimal such as \"0.125\")"
        );
        assert_eq!(
            error(
                json!({"kind": "triangle", "coefficients": [[[1]]], "triangle": [[0, 0], [1, 0, 0], [0, 1]]})
            ),
            "triangle[1]: expected 2 coordinates, found 3"
        );
        assert_eq!(
            error(
                json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3]]], "rectangle": [0, 1, 0, 1]})
            ),
            "coefficients[1]: expected 2 points (the grid must be rectangular), found 1"
        );
        assert_eq!(
            error(
                json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3], [4, 5]]], "rectangle": [0, 1, 0, 1]})
            ),
            "coefficients[1][1]: expected 1 coordinate, found 2"
        );
        assert_eq!(
            error(json!([1])),
            "input: expected a JSON object (a job), found an array"
        );
    }

    /// A job of every kind that answers, using every field its kind accepts.
    fn every_kind() -> Vec<Value> {
        let tri = json!([[0, 0], [1, 0], [0, 1]]);
        let entry = |a: u32, b: u32, c: u32, p: i32| json!({"a": a, "b": b, "c": c, "point": [p]});
        vec![
            json!({"kind": "curve", "coefficients": [[1], [2]], "interval": [0, 1]}),
            json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3], [4]]], "rectangle": [0, 1, 0, 1]}),
            json!({"kind": "triangle", "total_degree": 1, "coefficients": [[[0], [1]], [[1]]], "triangle": tri}),
            json!({"kind": "bezier-curve", "control_points": [[0], [1]], "interval": [0, "1/2"]}),
            json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0], [1]]}]}),
            json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": ["1/2"]}),
            json!({"kind": "rational-curve", "numerator": [[0], [1]], "denominator": [1, 1], "interval": [0, 1], "degree": 2}),
            json!({"kind": "elevate", "control_points": [[0], [1]], "to_degree": 2}),
            json!({"kind": "reduce", "control_points": [[0], [1], [3]], "to_degree": 1, "method": "least-squares"}),
            json!({"kind": "bezier-tensor", "control_points": [[[0], [1]], [[2], [3]]], "rectangle": [0, 1, 0, 1]}),
            json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0, 1), entry(0, 1, 0, 2), entry(0, 0, 1, 3)],
                   "triangle": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}),
            json!({"kind": "derivative", "control_points": [[0], [1], [3]], "order": 1}),
            json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]], "denominator": [[1], [1]], "rectangle": [0, 1, 0, 1], "degree": [1, 0]}),
            json!({"kind": "rational-triangle", "total_degree": 1, "numerator": [[[0], [1]], [[1]]], "denominator": [[1, 0], [1]],
                   "triangle": tri, "degree": 1}),
        ]
    }

    /// `blossom restrict` on `job`, in process: the answer, or the error line.
    fn restrict(job: &Value) -> Result<Value, String> {
        let out = crate::jobs::run(&["restrict".into()], &mut job.to_string().as_bytes());
        if out.code == 0 {
            Ok(serde_json::from_str(&out.stdout).expect("JSON"))
        } else {
            assert_eq!(out.code, 2);
            assert!(out.stdout.is_empty());
            assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
            Err(out.stderr.trim_end().to_string())
        }
    }

    #[test]
    fn every_kind_and_field_is_listed_and_read() {
        let jobs = every_kind();
        assert_eq!(jobs.len(), JOB_FIELDS.len());
        for ((kind, fields), job) in JOB_FIELDS.iter().zip(&jobs) {
            assert_eq!(job["kind"], json!(kind));
            let names: Vec<&str> = job
                .as_object()
                .unwrap()
                .keys()
                .map(String::as_str)
                .collect();
            let mut sorted = names.clone();
            sorted.sort_unstable();
            let mut expected = fields.to_vec();
            expected.sort_unstable();
            assert_eq!(sorted, expected, "{kind}: the test job uses every field");
            assert!(check_fields(job).is_ok(), "{kind}");
            assert!(restrict(job).is_ok(), "{kind}: {:?}", restrict(job));
        }
        let kinds: Vec<&str> = KINDS
            .iter()
            .chain(&LATER_KINDS)
            .chain(&PATCH_KINDS)
            .copied()
            .collect();
        let mut listed: Vec<&str> = JOB_FIELDS.iter().map(|(k, _)| *k).collect();
        let mut all = kinds.clone();
        listed.sort_unstable();
        all.sort_unstable();
        assert_eq!(listed, all, "JOB_FIELDS lists every kind once");
    }

    #[test]
    fn an_unknown_field_is_refused_in_every_kind() {
        for job in every_kind() {
            let kind = job["kind"].as_str().unwrap().to_string();
            // A field that no kind reads: the accepted names are listed.
            let mut extra = job.clone();
            extra["comment"] = json!("x");
            let line = restrict(&extra).unwrap_err();
            let (_, fields) = JOB_FIELDS.iter().find(|(k, _)| *k == kind).unwrap();
            assert_eq!(
                line,
                format!(
                    "error: comment: unknown field \"comment\" (expected {})",
                    listed(fields)
                ),
                "{kind}"
            );
        }
    }

    #[test]
    fn a_misspelt_field_is_named_before_it_is_missed() {
        for job in every_kind() {
            let kind = job["kind"].as_str().unwrap().to_string();
            for (name, value) in job.as_object().unwrap() {
                if name == "kind" {
                    continue;
                }
                // The field with its last letter dropped: now it is missing too.
                let typo = &name[..name.len() - 1];
                let mut misspelt = Map::new();
                for (k, v) in job.as_object().unwrap() {
                    let key = if k == name { typo } else { k.as_str() };
                    misspelt.insert(key.to_string(), v.clone());
                }
                let misspelt = Value::Object(misspelt);
                let line = restrict(&misspelt).unwrap_err();
                assert_eq!(
                    line,
                    format!("error: {typo}: unknown field \"{typo}\" (did you mean \"{name}\"?)"),
                    "{kind}: {value}"
                );
                // The same through the reader alone.
                let error = check_fields(&misspelt).unwrap_err();
                assert_eq!(error.field, typo);
            }
        }
    }

    #[test]
    fn nested_objects_refuse_unknown_fields() {
        let jobs = every_kind();
        let find = |kind: &str| {
            jobs.iter()
                .find(|j| j["kind"] == json!(kind))
                .unwrap()
                .clone()
        };
        let mut spline = find("bspline");
        spline["pieces"][0]["coeficients"] = spline["pieces"][0]["coefficients"].take();
        spline["pieces"][0]
            .as_object_mut()
            .unwrap()
            .remove("coefficients");
        assert_eq!(
            restrict(&spline).unwrap_err(),
            "error: pieces[0].coeficients: unknown field \"coeficients\" (did you mean \"coefficients\"?)"
        );
        let mut net = find("bezier-triangle");
        net["control_points"][1]["weight"] = json!(1);
        assert_eq!(
            restrict(&net).unwrap_err(),
            "error: control_points[1].weight: unknown field \"weight\" (expected a, b, c or point)"
        );
        let mut net = find("bezier-triangle");
        let point = net["control_points"][2]["point"].take();
        net["control_points"][2]
            .as_object_mut()
            .unwrap()
            .remove("point");
        net["control_points"][2]["pont"] = point;
        assert_eq!(
            restrict(&net).unwrap_err(),
            "error: control_points[2].pont: unknown field \"pont\" (did you mean \"point\"?)"
        );
        // An entry that is not an object is the reader's to refuse, with its own message.
        net["control_points"][2] = json!([1]);
        assert!(check_fields(&net).is_ok());
    }

    #[test]
    fn a_job_without_its_kind_is_checked_against_every_kind() {
        let line = restrict(&json!({"knd": "curve", "coefficients": [[1]], "interval": [0, 1]}));
        assert_eq!(
            line.unwrap_err(),
            "error: knd: unknown field \"knd\" (did you mean \"kind\"?)"
        );
        // Fields of some kind, but no kind: the kind is what is missing.
        let line = restrict(&json!({"coefficients": [[1]], "interval": [0, 1]}));
        assert_eq!(line.unwrap_err(), "error: kind: missing field");
        // An unknown kind is named as such, whatever its fields.
        let line = restrict(&json!({"kind": "curv", "coefficients": [[1]], "whatever": 1}));
        assert!(line
            .unwrap_err()
            .starts_with("error: kind: unknown kind \"curv\" (did you mean \"curve\"?)"));
    }

    #[test]
    fn expect_fields_names_the_path() {
        let object = json!({"s": 1, "tt": 2});
        let Value::Object(object) = object else {
            unreachable!()
        };
        assert!(expect_fields(&object, "x", &["s", "tt"]).is_ok());
        let error = expect_fields(&object, "points[3]", &["s", "t"]).unwrap_err();
        assert_eq!(
            error.to_string(),
            "points[3].tt: unknown field \"tt\" (did you mean \"t\"?)"
        );
        let error = expect_fields(&object, "", &["s"]).unwrap_err();
        assert_eq!(error.to_string(), "tt: unknown field \"tt\" (expected s)");
    }
}
