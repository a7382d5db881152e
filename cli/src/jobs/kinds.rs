//! The one list of job kinds: each line names a kind, its subcommand, the type that holds it
//! (one file per kind under `restrict/`, `intersect/`, `region/`) and its line of help. From
//! it come the [`Job`] enum (a variant per kind, tagged by `"kind"`), the reading of a job of a
//! kind ([`Job::read`]; as [`Job<Text>`] without its numbers, for the budget's estimate,
//! [`Job::estimate`]) and its answer ([`Job::solve`]), the kinds each subcommand accepts with their messages ([`kinds_of`]) and
//! the lists of kinds in the help texts and the docs ([`help_list`]). A new kind is one file
//! that implements [`Kind`] and [`Estimate`] plus one line here.

use super::cost::Env;
pub use super::kind::{Context, Estimate, Kind, Subcommand};
use super::read::{fields_of, read_job, Reading, Text, Written};
use super::{intersect, region, restrict};
use crate::names::{did_you_mean, quoted};
use blossom::Error;
use serde_json::{Map, Value};

/// One kind as the list declares it.
#[derive(Clone, Copy, Debug)]
pub struct KindInfo {
    /// The value of `"kind"`.
    pub name: &'static str,
    /// The subcommand that answers it.
    pub subcommand: Subcommand,
    /// Its job in one line of help, `{"kind": ...}` included.
    pub help: &'static str,
    /// The fields it reads, `kind` excluded.
    pub fields: fn() -> &'static [&'static str],
}

macro_rules! kinds {
    ($($sub:ident $name:literal => $variant:ident($($path:ident)::+ < $input:ty >) $help:literal;)*) => {
        /// A job of any kind, its numbers read as `T` ([`Reading`]).
        #[derive(Debug)]
        pub enum Job<T> {
            $(#[doc = $help] $variant($($path)::+<$input>),)*
        }

        /// Every kind, in the order of the help texts.
        pub const KINDS: &[KindInfo] = &[
            $(KindInfo {
                name: $name,
                subcommand: Subcommand::$sub,
                help: $help,
                fields: fields_of::<$($path)::+<Text>>,
            },)*
        ];

        impl<T: Reading> Job<T> {
            /// Reads the job object `job` of kind `kind` (one of [`KINDS`]).
            pub fn read(kind: &str, job: &Map<String, Value>) -> Result<Self, Error> {
                match kind {
                    $($name => read_job(job).map(Job::$variant),)*
                    other => Err(Error::new("kind", format!("unknown kind {}", quoted(other)))),
                }
            }
        }

        impl Job<Text> {
            /// The up-front estimate of a job read without its numbers ([`Estimate`]).
            pub fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
                match self {
                    $(Job::$variant(job) => job.estimate(env),)*
                }
            }
        }

        impl<T: restrict::Number> Job<T> where $($($path)::+<$input>: Kind,)* {
            /// The answer of the job.
            pub fn solve(self, context: &Context) -> Result<Value, Error> {
                match self {
                    $(Job::$variant(job) => job.solve(context),)*
                }
            }
        }
    };
}

kinds! {
    Restrict "curve" => Curve(restrict::curve::Curve<T>)
        r#"{"kind": "curve", "coefficients": [c0, ..., cn], "interval": [a, b]}"#;
    Restrict "tensor" => Tensor(restrict::tensor::Tensor<T>)
        r#"{"kind": "tensor", "coefficients": [[c00, ..., c0m], ...], "rectangle": [a, b, c, d]}"#;
    Restrict "triangle" => Triangle(restrict::triangle::Triangle<T>)
        r#"{"kind": "triangle", "coefficients": [[c00, ..., c0m], ...], "triangle": [[a1, a2], [b1, b2], [c1, c2]], "total_degree": N (optional: a triangular array, row i holding N + 1 - i points)}"#;
    Restrict "bezier-curve" => BezierCurve(restrict::bezier_curve::BezierCurve<T>)
        r#"{"kind": "bezier-curve", "control_points": [b0, ..., bn], "interval": [a, b]}"#;
    Restrict "bspline" => Bspline(restrict::bspline::Bspline<Written<T>>)
        r#"{"kind": "bspline", "degree": p, "pieces": [{"interval": [e0, e1], "coefficients": [c0, ..., cp]}, ...]}"#;
    Restrict "bspline-eval" => BsplineEval(restrict::bspline_eval::BsplineEval<T>)
        r#"{"kind": "bspline-eval", "degree": p, "knots": [...], "control_points": [...], "at": [t, ...]}"#;
    Restrict "rational-curve" => RationalCurve(restrict::rational_curve::RationalCurve<Written<T>>)
        r#"{"kind": "rational-curve", "numerator": [c0, ...], "denominator": [w0, ...], "interval": [alpha, beta], "degree": n (optional)}"#;
    Restrict "elevate" => Elevate(restrict::elevate::Elevate<T>)
        r#"{"kind": "elevate", "control_points": [...], "to_degree": m}"#;
    Restrict "reduce" => Reduce(restrict::reduce::Reduce<T>)
        r#"{"kind": "reduce", "control_points": [...], "to_degree": m, "method": "interpolating" | "least-squares" | "least-squares-endpoints"}"#;
    Restrict "bezier-tensor" => BezierTensor(restrict::bezier_tensor::BezierTensor<T>)
        r#"{"kind": "bezier-tensor", "control_points": [[b00, ..., b0m], ...], "rectangle": [a, b, c, d]}"#;
    Restrict "bezier-triangle" => BezierTriangle(restrict::bezier_triangle::BezierTriangle<T>)
        r#"{"kind": "bezier-triangle", "control_points": [{"a": i, "b": j, "c": k, "point": p}, ...], "triangle": [P, Q, R] (corners by 3 barycentric coordinates adding up to 1)}"#;
    Restrict "derivative" => Derivative(restrict::derivative::Derivative<T>)
        r#"{"kind": "derivative", "control_points": [b0, ..., bn], "order": k}"#;
    Restrict "rational-tensor" => RationalTensor(restrict::rational_tensor::RationalTensor<Written<T>>)
        r#"{"kind": "rational-tensor", "numerator": [[p00, ...], ...], "denominator": [[w00, ...], ...], "rectangle": [a, b, c, d], "degree": [n, m] (optional)}"#;
    Restrict "rational-triangle" => RationalTriangle(restrict::rational_triangle::RationalTriangle<Written<T>>)
        r#"{"kind": "rational-triangle", "numerator": ..., "denominator": ..., "triangle": [...], "degree": N (optional), "total_degree": N (optional: triangular arrays)}"#;
    Intersect "roots" => Roots(intersect::roots::Roots<T>)
        "{\"kind\": \"roots\", \"control_points\": [b0, ..., bn]}
      every distinct zero in [0, 1] of the Bezier function with these coefficients, with
      its multiplicity (\"identically_zero\": true for the zero function)";
    Intersect "curve-curve" => CurveCurve(intersect::curve_curve::CurveCurve<T>)
        "{\"kind\": \"curve-curve\", \"curves\": [P, Q]}
      every isolated intersection P(s) = Q(t) with an exact tangency flag, and every
      overlap (common stretch), of two 2-D Bezier curves over [0, 1]";
    Intersect "self" => SelfIntersections(intersect::self_intersections::SelfIntersections<T>)
        "{\"kind\": \"self\", \"curve\": P}
      every pair s < t with P(s) = P(t), and the stretches a curve retraces";
    Region "triangle-triangle" => TriangleTriangle(region::triangle_triangle::TriangleTriangle<T>)
        "{\"kind\": \"triangle-triangle\", \"triangles\": [T1, T2]}
      the intersection of two planar Bezier triangles";
    Region "boolean" => Boolean(region::boolean::Boolean<T>)
        "{\"kind\": \"boolean\", \"op\": OP, \"regions\": [A, B]}
      OP one of \"intersection\", \"union\", \"difference\" (A minus B), \"xor\"";
    Region "simplify" => Simplify(region::simplify::Simplify<T>)
        "{\"kind\": \"simplify\", \"region\": A}
      A under its own fill rule as simple oriented loops: overlapping and self-crossing
      loops merged (remove overlaps), answered as a boolean (edges of region 0)";
    Region "winding" => Winding(region::winding::Winding<T>)
        "{\"kind\": \"winding\", \"region\": A, \"points\": [[x, y], ...]}
      the exact winding number of each point and where it lies (inside, outside, boundary)";
}

/// The kinds of `subcommand`.
pub fn kinds_of(subcommand: Subcommand) -> impl Iterator<Item = &'static KindInfo> {
    KINDS.iter().filter(move |k| k.subcommand == subcommand)
}

/// The lines of help of the kinds of `subcommand`, each indented by two spaces.
pub fn help_list(subcommand: Subcommand) -> String {
    kinds_of(subcommand)
        .map(|k| format!("  {}\n", k.help))
        .collect()
}

/// The job object of `document` (the whole parsed input) and its kind, one of those of
/// `subcommand`; the errors name `input` (not an object) or `kind` (missing, not a string, not
/// a kind of the subcommand, with the nearest one). A job without `kind` has its fields checked
/// against those of every kind first, so that a misspelt `kind` is named as such.
pub fn job_and_kind(
    document: &Value,
    subcommand: Subcommand,
) -> Result<(&Map<String, Value>, &'static KindInfo), Error> {
    let Value::Object(job) = document else {
        return Err(Error::new(
            "input",
            format!(
                "expected a JSON object (a job), found {}",
                crate::number::json_type(document)
            ),
        ));
    };
    let names: Vec<&str> = kinds_of(subcommand).map(|k| k.name).collect();
    let kind = match job.get("kind") {
        Some(Value::String(kind)) => kind,
        Some(other) => {
            return Err(Error::new(
                "kind",
                format!(
                    "expected a string, found {}",
                    crate::number::json_type(other)
                ),
            ))
        }
        None => {
            let mut every = vec!["kind"];
            for field in kinds_of(subcommand).flat_map(|k| (k.fields)().iter()) {
                if !every.contains(field) {
                    every.push(field);
                }
            }
            crate::names::expect_fields(job, "", &every)?;
            return Err(Error::new("kind", "missing field"));
        }
    };
    kinds_of(subcommand)
        .find(|k| k.name == kind)
        .map(|info| (job, info))
        .ok_or_else(|| {
            Error::new(
                "kind",
                format!(
                    "unknown kind {}{} (expected one of {})",
                    quoted(kind),
                    did_you_mean(kind, &names),
                    names.join(", ")
                ),
            )
        })
}
