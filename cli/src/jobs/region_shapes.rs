//! Reading the shapes of `blossom region` (the last section of `docs/cli.md`): CURVE, LOOP,
//! REGION and TRIANGLE, each number read exactly as the arithmetic says (under `exact` as
//! written, under `f64` rounded to the nearest double first and then taken exactly), every
//! error naming the offending field by its full path (`regions[1].loops[0][2][1][0]`).
//!
//! The JSON's form (arrays, points, numbers, the fill rule's name, unknown fields) is checked
//! here; what makes a region a region (loops not empty and closed, curve degrees in
//! 1..=[`MAX_REGION_DEGREE`], a triangle's node count) is checked once, by the library's
//! [`Region::new`] and [`Region::triangle`], whose errors name the field relative to the
//! region (`loops[0][2]`, `nodes`) and are re-addressed here under the job's path
//! (`regions[1].loops[0][2]: starts at (1, 0), the previous curve ends at (1, 1/2)`).

use super::args::Arithmetic;
use super::intersect_jobs::number;
use super::job::{array, expect_fields};
use super::names::{did_you_mean, listed, quoted};
use crate::number::json_type;
use blossom::region::{FillRule, Region, MAX_REGION_DEGREE};
use blossom::{Bezier, Error, Rational};
use serde_json::{Map, Value};

/// The names `fill` accepts, the default first.
pub const FILL_NAMES: [&str; 2] = ["nonzero", "evenodd"];

/// The field `name` of the object at `path`, or `error: PATH.NAME: missing field`.
pub fn member<'a>(
    object: &'a Map<String, Value>,
    path: &str,
    name: &str,
) -> Result<&'a Value, Error> {
    object
        .get(name)
        .ok_or_else(|| Error::new(joined(path, name), "missing field"))
}

/// `path.name`, or `name` at the top level.
pub fn joined(path: &str, name: &str) -> String {
    if path.is_empty() {
        name.to_string()
    } else {
        format!("{path}.{name}")
    }
}

/// The object at `path`, or an error saying what was expected.
pub fn object<'a>(
    value: &'a Value,
    path: &str,
    expected: &str,
) -> Result<&'a Map<String, Value>, Error> {
    match value {
        Value::Object(map) => Ok(map),
        other => Err(Error::new(
            path,
            format!("expected {expected}, found {}", json_type(other)),
        )),
    }
}

/// A 2-D point `[x, y]` at `path`.
pub fn point(value: &Value, path: &str, arithmetic: Arithmetic) -> Result<[Rational; 2], Error> {
    let coordinates = array(value, path, "a point [x, y]")?;
    if coordinates.len() != 2 {
        return Err(Error::new(
            path,
            format!(
                "expected 2 coordinates (regions are 2-D), found {}",
                coordinates.len()
            ),
        ));
    }
    Ok([
        number(&coordinates[0], &format!("{path}[0]"), arithmetic)?,
        number(&coordinates[1], &format!("{path}[1]"), arithmetic)?,
    ])
}

/// A CURVE at `path`: an array of 2-D control points (their number is checked by
/// [`Region::new`]).
pub fn curve(
    value: &Value,
    path: &str,
    arithmetic: Arithmetic,
) -> Result<Bezier<Rational, 2>, Error> {
    let items = array(value, path, "a curve (an array of 2-D control points)")?;
    if items.len() > MAX_REGION_DEGREE + 1 {
        // Refused before reading its numbers; Region::new would refuse it after.
        return Err(over_degree(path, items.len() - 1));
    }
    let points = items
        .iter()
        .enumerate()
        .map(|(i, p)| point(p, &format!("{path}[{i}]"), arithmetic))
        .collect::<Result<Vec<_>, Error>>()?;
    Bezier::new(points).map_err(|e| Error::of(e.kind, path, e.message))
}

/// The error of a degree over [`MAX_REGION_DEGREE`] at `path`.
fn over_degree(path: &str, degree: usize) -> Error {
    Error::of(
        blossom::ErrorKind::Degree,
        path,
        format!("degree {degree} is over the limit of {MAX_REGION_DEGREE} of blossom region"),
    )
}

/// `error` (whose field is relative to a region: `loops[0][2]`, `nodes`) under `path`.
fn under(path: &str, error: Error) -> Error {
    let field = if error.field.is_empty() {
        path.to_string()
    } else {
        joined(path, &error.field)
    };
    Error::of(error.kind, field, error.message)
}

/// A REGION at `path`: `{"loops": [LOOP, ...], "fill": "nonzero" | "evenodd"}`.
pub fn region(value: &Value, path: &str, arithmetic: Arithmetic) -> Result<Region, Error> {
    let map = object(value, path, "a region {\"loops\": [...], \"fill\": ...}")?;
    expect_fields(map, path, &["loops", "fill"])?;
    let loops_path = joined(path, "loops");
    let items = array(
        member(map, path, "loops")?,
        &loops_path,
        "an array of loops",
    )?;
    if items.is_empty() {
        return Err(Error::new(
            &loops_path,
            "expected at least one loop (a region without loops is empty: give it one)",
        ));
    }
    let loops = items
        .iter()
        .enumerate()
        .map(|(l, item)| {
            let here = format!("{loops_path}[{l}]");
            array(item, &here, "a loop (an array of curves)")?
                .iter()
                .enumerate()
                .map(|(c, value)| curve(value, &format!("{here}[{c}]"), arithmetic))
                .collect::<Result<Vec<_>, Error>>()
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let fill = match map.get("fill") {
        None => FillRule::NonZero,
        Some(value) => fill(value, &joined(path, "fill"))?,
    };
    Region::new(loops, fill).map_err(|e| under(path, e))
}

/// The fill rule at `path`.
fn fill(value: &Value, path: &str) -> Result<FillRule, Error> {
    match value {
        Value::String(name) if name == "nonzero" => Ok(FillRule::NonZero),
        Value::String(name) if name == "evenodd" => Ok(FillRule::EvenOdd),
        Value::String(name) => Err(Error::new(
            path,
            format!(
                "unknown fill rule {}{} (expected {})",
                quoted(name),
                did_you_mean(name, &FILL_NAMES),
                listed(&FILL_NAMES)
            ),
        )),
        other => Err(Error::new(
            path,
            format!(
                "expected \"nonzero\" or \"evenodd\", found {}",
                json_type(other)
            ),
        )),
    }
}

/// A TRIANGLE at `path`: `{"degree": n, "nodes": [...]}`, the region of its loop of three
/// edges ([`Region::triangle`]: curves 0, 1, 2 of loop 0 are edges 0, 1, 2).
pub fn triangle(value: &Value, path: &str, arithmetic: Arithmetic) -> Result<Region, Error> {
    let map = object(value, path, "a triangle {\"degree\": n, \"nodes\": [...]}")?;
    expect_fields(map, path, &["degree", "nodes"])?;
    let degree_path = joined(path, "degree");
    let degree = match member(map, path, "degree")? {
        Value::Number(number) => number.as_u64().ok_or_else(|| {
            Error::new(
                &degree_path,
                format!("expected an integer n >= 1, found {number}"),
            )
        })?,
        other => {
            return Err(Error::new(
                &degree_path,
                format!("expected an integer n >= 1, found {}", json_type(other)),
            ))
        }
    };
    if degree > MAX_REGION_DEGREE as u64 {
        return Err(over_degree(&degree_path, degree as usize));
    }
    let nodes_path = joined(path, "nodes");
    let nodes = array(
        member(map, path, "nodes")?,
        &nodes_path,
        "an array of 2-D nodes",
    )?
    .iter()
    .enumerate()
    .map(|(i, p)| point(p, &format!("{nodes_path}[{i}]"), arithmetic))
    .collect::<Result<Vec<_>, Error>>()?;
    Region::triangle(degree as usize, nodes).map_err(|e| under(path, e))
}

/// A list of 2-D points at `path` (the points of a `winding` job).
pub fn points(
    value: &Value,
    path: &str,
    arithmetic: Arithmetic,
) -> Result<Vec<[Rational; 2]>, Error> {
    array(value, path, "an array of 2-D points")?
        .iter()
        .enumerate()
        .map(|(i, p)| point(p, &format!("{path}[{i}]"), arithmetic))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn an_open_loop_names_the_later_curve_under_the_job_path() {
        let r = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, "1/2"], [0, 0]]]]});
        let e = region(&r, "regions[1]", Arithmetic::Exact).unwrap_err();
        assert_eq!(
            e.to_string(),
            "regions[1].loops[0][2]: starts at (1, 1/2), the previous curve ends at (1, 1)"
        );
        let r = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [0, 1]]]]});
        let e = region(&r, "region", Arithmetic::Exact).unwrap_err();
        assert_eq!(
            e.to_string(),
            "region.loops[0][0]: starts at (0, 0), the previous curve ends at (0, 1)"
        );
    }

    #[test]
    fn a_triangle_with_too_few_nodes_names_its_nodes() {
        let t = json!({"degree": 2, "nodes": [[0, 0], [1, 0], [0, 1]]});
        let e = triangle(&t, "triangles[1]", Arithmetic::Exact).unwrap_err();
        assert!(e.to_string().starts_with("triangles[1].nodes: "), "{e}");
        let t = json!({"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]], "node": 1});
        let e = triangle(&t, "triangles[0]", Arithmetic::Exact).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("triangles[0].node: unknown field"),
            "{e}"
        );
    }
}
