//! The jobs of `blossom region` (the last section of `docs/cli.md`): the intersection of two
//! Bézier triangles (`triangle-triangle`), the booleans of two regions (`boolean`) and exact
//! winding numbers (`winding`), every answer certified by the library's region layer
//! ([`blossom::region`]): every decision in it is exact for the input numbers as read.
//!
//! The job is read by [`super::region_shapes`] (every error naming its field), its work
//! estimated and refused over the limit before anything is computed, then computed and written
//! by [`super::region_answer`].
//!
//! # Limits
//!
//! * Curve and triangle degrees 1..=[`MAX_REGION_DEGREE`] (the contract asks for 10); a
//!   longer curve is refused before its numbers are read.
//! * The work of a `boolean` or `triangle-triangle` job is [`boolean_work`], in nanoseconds
//!   of a 2-core machine: for regions of doubles with simple loops the library's float path
//!   (a few microseconds per close pair of curves across the regions), else the float filter
//!   and the exact intersections of every pair of curves whose boxes meet, the
//!   self-intersections of every curve and the classification of the pieces. A job whose
//!   estimate is over twice `--max-work` is refused up front (`within_budget`) naming
//!   `regions` (or `triangles`), as `intersect` refuses its curves; what the estimate lets
//!   through then runs under the work meter ([`super::budget::metered`], charged by the exact
//!   arithmetic and the intersection loops), which stops it at `--max-work` naming the same
//!   field. The answer is written under the meter as well: the exact parameters of the
//!   crossings the float path proved are computed there (the contract prints each one's
//!   polynomial and isolating interval).
//! * The work of a `winding` job is [`blossom::region::Region::winding_work`] (each curve's monotone breaks
//!   once, then per point a box test against every curve and exact tests on the curves its
//!   ray meets), refused over twice `--max-work` naming `points`, and metered the same way.

use super::args::Arithmetic;
use super::budget::{metered, Limits};
use super::intersect_jobs::within_budget;
use super::job::{array, expect_fields, field, object_and_kind};
use super::names::{did_you_mean, listed, quoted};
use super::region_answer::{region_result, windings};
use super::region_shapes::{points, region, triangle};
use crate::number::json_type;
use blossom::region::{boolean, boolean_work, triangle_intersection, BooleanOp};
use blossom::Error;
use serde_json::{Map, Value};

pub use blossom::region::MAX_REGION_DEGREE;

/// The kinds of `blossom region` and the fields each reads.
pub const REGION_FIELDS: [(&str, &[&str]); 3] = [
    ("triangle-triangle", &["kind", "triangles"]),
    ("boolean", &["kind", "op", "regions"]),
    ("winding", &["kind", "region", "points"]),
];

/// The names `op` accepts and the operations they name.
pub const OPS: [(&str, BooleanOp); 4] = [
    ("intersection", BooleanOp::Intersection),
    ("union", BooleanOp::Union),
    ("difference", BooleanOp::Difference),
    ("xor", BooleanOp::Xor),
];

/// Help for `blossom region`.
pub const REGION_HELP: &str = "\
blossom region: certified booleans of regions bounded by Bezier curves

Usage: blossom region [--input FILE] [--arithmetic exact|f64] [--max-work UNITS]
                      [--max-input BYTES]

Reads one job (JSON) and prints its exact answer as one line of JSON; exit code 0.
  {\"kind\": \"boolean\", \"op\": OP, \"regions\": [A, B]}
      OP one of \"intersection\", \"union\", \"difference\" (A minus B), \"xor\"
  {\"kind\": \"triangle-triangle\", \"triangles\": [T1, T2]}
      the intersection of two planar Bezier triangles
  {\"kind\": \"winding\", \"region\": A, \"points\": [[x, y], ...]}
      the exact winding number of each point and where it lies (inside, outside, boundary)
A region is {\"loops\": [LOOP, ...], \"fill\": \"nonzero\" (default) | \"evenodd\"}; a loop is a
list of curves [[x0, y0], ..., [xn, yn]], each starting exactly where the previous one ends
and the last ending where the first starts; loops may cross, touch, overlap and run either
way. A triangle is {\"degree\": n, \"nodes\": [...]}: (n + 1)(n + 2)/2 nodes by increasing k,
within it increasing j (p_n00, p_(n-1)10, ..., p_0n0, p_(n-1)01, ..., p_00n); its edges are
curves 0, 1, 2 (the second triangle's 3, 4, 5). Curve degrees 1 to 20.

The answer of boolean and triangle-triangle: {\"kind\": K, \"loops\": [{\"hole\": bool, \"edges\":
[EDGE, ...]}, ...], \"area\": [lo, hi]}: the regularized result as simple loops with the
result on their left (holes clockwise), each edge a piece of one input curve
{\"region\": r, \"loop\": l, \"curve\": c, \"from\": PARAM, \"to\": PARAM} (triangle-triangle:
{\"curve\": i, \"from\", \"to\"}); area: doubles enclosing the exact area, hi - lo <= 2^-40 B
(B the area of the box of every input control point). A PARAM is {\"value\": the correctly
rounded double, \"exact\": \"p/q\" or null, \"interval\": [lo, hi], \"polynomial\": [...]}.

Options:
  --input FILE         read the job from FILE (default, or `-`: standard input)
  --arithmetic exact   read the numbers as written (default; \"1/3\" is one third)
  --arithmetic f64     round each input number to the nearest double first; the answer
                       is still the exact one for those doubles
  --max-work UNITS     refuse a job whose work, estimated before computing, is over twice
                       UNITS (default 1e9, about a second)
  --max-input BYTES    the longest input read (default 1048576)
  -h, --help           print this help

On bad input one line `error: FIELD: ...` on standard error, exit code 2.
";

/// Answers the `blossom region` job `document` as one JSON value.
pub fn answer(document: &Value, arithmetic: Arithmetic, limits: &Limits) -> Result<Value, Error> {
    let (job, kind) = object_and_kind(document)?;
    let Some((kind, accepted)) = REGION_FIELDS.iter().find(|(k, _)| *k == kind) else {
        let kinds: Vec<&str> = REGION_FIELDS.iter().map(|(k, _)| *k).collect();
        return Err(Error::new(
            "kind",
            format!(
                "unknown kind {}{} (expected one of {})",
                quoted(kind),
                did_you_mean(kind, &kinds),
                listed(&kinds)
            ),
        ));
    };
    expect_fields(job, "", accepted)?;
    match *kind {
        "triangle-triangle" => triangle_triangle(job, arithmetic, limits),
        "boolean" => boolean_job(job, arithmetic, limits),
        _ => winding_job(job, arithmetic, limits),
    }
}

/// Exactly two of something at `name` (`regions`, `triangles`).
fn pair<'a>(job: &'a Map<String, Value>, name: &str, what: &str) -> Result<&'a [Value], Error> {
    let items = array(field(job, name)?, name, &format!("an array of two {what}"))?;
    if items.len() != 2 {
        return Err(Error::new(
            name,
            format!("expected 2 {what}, found {}", items.len()),
        ));
    }
    Ok(items)
}

/// `"triangle-triangle"`.
fn triangle_triangle(
    job: &Map<String, Value>,
    arithmetic: Arithmetic,
    limits: &Limits,
) -> Result<Value, Error> {
    let items = pair(job, "triangles", "triangles")?;
    let t1 = triangle(&items[0], "triangles[0]", arithmetic)?;
    let t2 = triangle(&items[1], "triangles[1]", arithmetic)?;
    within_budget("triangles", boolean_work(&t1, &t2), limits.max_work)?;
    // The answer is written under the meter too: its exact parameters are computed there.
    metered(limits, "triangles", || {
        let result = triangle_intersection(&t1, &t2).map_err(|e| at("triangles", e))?;
        region_result("triangle-triangle", &result, true)
    })
}

/// `"boolean"`.
fn boolean_job(
    job: &Map<String, Value>,
    arithmetic: Arithmetic,
    limits: &Limits,
) -> Result<Value, Error> {
    let op = op(field(job, "op")?)?;
    let items = pair(job, "regions", "regions")?;
    let a = region(&items[0], "regions[0]", arithmetic)?;
    let b = region(&items[1], "regions[1]", arithmetic)?;
    within_budget("regions", boolean_work(&a, &b), limits.max_work)?;
    metered(limits, "regions", || {
        let result = boolean(&a, &b, op).map_err(|e| at("regions", e))?;
        region_result("boolean", &result, false)
    })
}

/// The operation named at `op`.
fn op(value: &Value) -> Result<BooleanOp, Error> {
    let names: Vec<&str> = OPS.iter().map(|(n, _)| *n).collect();
    match value {
        Value::String(name) => OPS
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, op)| *op)
            .ok_or_else(|| {
                Error::new(
                    "op",
                    format!(
                        "unknown op {}{} (expected {})",
                        quoted(name),
                        did_you_mean(name, &names),
                        listed(&names)
                    ),
                )
            }),
        other => Err(Error::new(
            "op",
            format!(
                "expected a string ({}), found {}",
                listed(&names),
                json_type(other)
            ),
        )),
    }
}

/// `"winding"`.
fn winding_job(
    job: &Map<String, Value>,
    arithmetic: Arithmetic,
    limits: &Limits,
) -> Result<Value, Error> {
    let r = region(field(job, "region")?, "region", arithmetic)?;
    let points = points(field(job, "points")?, "points", arithmetic)?;
    within_budget("points", r.winding_work(points.len()), limits.max_work)?;
    metered(limits, "points", || windings(&r, &points))
}

/// `error` re-addressed to `path` (the library names its own arguments).
fn at(path: &str, error: Error) -> Error {
    let field = if error.field.is_empty() {
        path.to_string()
    } else {
        format!("{path}.{}", error.field)
    };
    Error::of(error.kind, field, error.message)
}
