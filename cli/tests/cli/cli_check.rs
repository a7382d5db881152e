//! `blossom check`: bad input is refused with one line naming the field (exit 2), and the
//! errors it reports are right: blossom's own `f64` answer is within its `"error_bound"`, the
//! exact answer rounded to doubles is within half an ulp per point, and a perturbation is
//! measured exactly. Runs in-process through `blossom_cli::jobs::run`.

use crate::common::Rng;
use blossom::{rational_to_f64, Rational};
use blossom_cli::number::{format_rational, parse_rational};
use serde_json::{json, Value};
use std::ffi::OsString;

fn run(args: &[&str], input: &str) -> blossom_cli::jobs::Outcome {
    let args: Vec<OsString> = args.iter().map(OsString::from).collect();
    blossom_cli::jobs::run(&args, &mut input.as_bytes())
}

/// The report of `blossom check ARGS` on `document`: exit 0, one line of JSON.
fn check(args: &[&str], document: &Value) -> Value {
    let mut all = vec!["check"];
    all.extend_from_slice(args);
    let out = run(&all, &document.to_string());
    assert_eq!(out.code, 0, "{document}: {}", out.stderr);
    assert!(out.stderr.is_empty());
    assert_eq!(out.stdout.lines().count(), 1, "{}", out.stdout);
    serde_json::from_str(&out.stdout).expect("JSON")
}

/// The error line of `blossom check ARGS` on `input`: exit 2, nothing on standard output.
fn check_error(args: &[&str], input: &str) -> String {
    let mut all = vec!["check"];
    all.extend_from_slice(args);
    let out = run(&all, input);
    assert_eq!(out.code, 2, "{input} was accepted: {}", out.stdout);
    assert!(out.stdout.is_empty());
    assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
    out.stderr.trim_end().to_string()
}

/// The answer of `blossom restrict ARGS` on `job`.
fn restrict(args: &[&str], job: &Value) -> Value {
    let mut all = vec!["restrict"];
    all.extend_from_slice(args);
    let out = run(&all, &job.to_string());
    assert_eq!(out.code, 0, "{job}: {}", out.stderr);
    serde_json::from_str(&out.stdout).expect("JSON")
}

fn exact(value: &Value) -> Rational {
    parse_rational(value.as_str().expect("an exact number")).expect("an exact number")
}

fn cubic() -> Value {
    json!({"kind": "bezier-curve", "control_points": [[0, 0], [1, 2], [3, 3], [4, 0]], "interval": [0.1, 0.7]})
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    let with = |answer: Value| json!({"job": cubic(), "answer": answer}).to_string();
    let points = |p: Value| with(json!({"control_points": p}));
    let triangle = json!({"kind": "triangle", "coefficients": [[[1], [2]]], "triangle": [[0, 0], [1, 0], [0, 1]]});
    let cases: Vec<(String, &str)> = vec![
        ("[1]".into(), "error: input: expected an object"),
        ("{".into(), "error: input: invalid JSON"),
        (json!({"answer": {}}).to_string(), "error: job: missing field"),
        (json!({"job": cubic()}).to_string(), "error: answer: missing field"),
        (with(json!(3)), "error: answer: expected an object"),
        (with(json!({"points": []})), "error: answer.control_points: missing field"),
        (points(json!(7)), "error: answer.control_points: expected an array of 4 entries"),
        (points(json!([[0, 0], [1, 2], [3, 3]])), "error: answer.control_points: expected 4 entries, found 3"),
        (points(json!([[0, 0], [1, 2, 3], [3, 3], [4, 0]])), "error: answer.control_points[1]: expected 2 coordinates, found 3"),
        (points(json!([[0, 0], [1, 2], 3, [4, 0]])), "error: answer.control_points[2]: expected a point of 2 numbers"),
        (points(json!([[0, 0], [1, 2], [3, [3]], [4, 0]])), "error: answer.control_points[2][1]: expected a number"),
        (points(json!([[0, true], [1, 2], [3, 3], [4, 0]])), "error: answer.control_points[0][1]: expected a number"),
        (points(json!([["NaN", 0], [1, 2], [3, 3], [4, 0]])), "error: answer.control_points[0][0]: "),
        (points(json!([["-inf", 0], [1, 2], [3, 3], [4, 0]])), "error: answer.control_points[0][0]: "),
        (points(json!([[0, 0], [1, 2], [3, "1e400"], [4, 0]])), "error: answer.control_points[2][1]: "),
        (
            json!({"job": triangle, "answer": {"control_points": [{"a": 0, "b": 0, "c": 1, "point": [1]}, {"a": 1, "b": 0, "c": 0, "point": [1]}, {"a": 0, "b": 1, "c": 0, "point": [1]}]}}).to_string(),
            "error: answer.control_points[1].a: expected 0, found 1",
        ),
        (
            json!({"job": triangle, "answer": {"control_points": [[1], [1], [1]]}}).to_string(),
            "error: answer.control_points[0]: expected an object",
        ),
        (
            json!({"job": {"kind": "bezier-curve", "control_points": [[0, 0], [1]], "interval": [0, 1]}, "answer": {"control_points": []}}).to_string(),
            "error: job.control_points[1]: ",
        ),
        (
            json!({"job": {"kind": "spiral"}, "answer": {"control_points": []}}).to_string(),
            "error: job.kind: ",
        ),
        (
            json!({"job": {"kind": "bezier-curve", "control_points": [[0], [1]], "interval": [0, "1e400"]}, "answer": {"control_points": []}}).to_string(),
            "error: job.interval[1]: ",
        ),
        (
            json!({"job": {"kind": "bezier-curve", "control_points": [[0], [1]]}, "answer": {"control_points": []}}).to_string(),
            "error: job.interval: ",
        ),
        (
            json!({"job": 5, "answer": {"control_points": []}}).to_string(),
            "error: job: ",
        ),
        // Unknown fields of the document and of the job, named before anything else.
        (
            json!({"jbo": cubic(), "answer": {"control_points": []}}).to_string(),
            "error: jbo: unknown field \"jbo\" (did you mean \"job\"?)",
        ),
        (
            json!({"job": cubic(), "answer": {"control_points": []}, "per_point": true}).to_string(),
            "error: per_point: unknown field \"per_point\" (expected job or answer)",
        ),
        (
            json!({"job": {"kind": "bezier-curve", "control_point": [[0], [1]], "interval": [0, 1]}, "answer": {"control_points": []}}).to_string(),
            "error: job.control_point: unknown field \"control_point\" (did you mean \"control_points\"?)",
        ),
        (
            json!({"job": {"kind": "bezier-curve", "control_points": [[0], [1]], "interval": [0, 1], "note": "1e400"}, "answer": {"control_points": []}}).to_string(),
            "error: job.note: unknown field \"note\" (expected kind, control_points or interval)",
        ),
        (
            json!({"job": {"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0], [1]], "weight": 1}]}, "answer": {"control_points": []}}).to_string(),
            "error: job.pieces[0].weight: unknown field \"weight\" (expected interval or coefficients)",
        ),
        (
            json!({"job": {"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": [0.5]}, "answer": {"control_points": []}}).to_string(),
            "error: job.kind: the answer of this job has no \"control_points\"",
        ),
    ];
    for (input, expected) in &cases {
        let line = check_error(&[], input);
        assert!(
            line.starts_with(expected),
            "{input}: {line} (expected {expected})"
        );
    }
    // The work budget applies to the job, its field under `job.`.
    let line = check_error(&["--max-work", "10"], &points(json!([])));
    assert!(
        line.starts_with("error: job.control_points: the job's estimated work"),
        "{line}"
    );
}

/// Random doubles of every magnitude class the jobs meet: decimals (not dyadic) and integers.
fn double(r: &mut Rng) -> f64 {
    match r.next() % 3 {
        0 => (r.next() % 20001) as f64 / 1000.0 - 10.0,
        1 => ((r.next() % 2001) as f64 - 1000.0) / 7.0,
        _ => (r.next() % 21) as f64 - 10.0,
    }
}

fn doubles(r: &mut Rng, count: usize) -> Vec<f64> {
    (0..count).map(|_| double(r)).collect()
}

/// A random restriction job in doubles (JSON numbers) of one of the kinds with control points.
fn random_job(r: &mut Rng, round: usize) -> Value {
    let d = 1 + (r.next() % 3) as usize;
    let points = |r: &mut Rng, count: usize| -> Vec<Vec<f64>> {
        (0..count).map(|_| doubles(r, d)).collect()
    };
    let end = |r: &mut Rng| (r.next() % 3001) as f64 / 1000.0 - 1.0;
    match round % 4 {
        0 => {
            let n = 1 + (r.next() % 10) as usize;
            json!({"kind": "bezier-curve", "control_points": points(r, n + 1), "interval": [end(r), end(r)]})
        }
        1 => {
            let n = 1 + (r.next() % 10) as usize;
            json!({"kind": "curve", "coefficients": points(r, n + 1), "interval": [end(r), end(r)]})
        }
        2 => {
            let (n, m) = (1 + (r.next() % 4) as usize, (r.next() % 4) as usize);
            let grid: Vec<Vec<Vec<f64>>> = (0..=n).map(|_| points(r, m + 1)).collect();
            json!({"kind": "bezier-tensor", "control_points": grid, "rectangle": [end(r), end(r), end(r), end(r)]})
        }
        _ => {
            let (n, m) = (1 + (r.next() % 3) as usize, (r.next() % 3) as usize);
            let grid: Vec<Vec<Vec<f64>>> = (0..=n).map(|_| points(r, m + 1)).collect();
            json!({"kind": "triangle", "coefficients": grid, "triangle": [[end(r), end(r)], [end(r), end(r)], [end(r), end(r)]]})
        }
    }
}

/// `value` with every JSON number that is not an integer replaced by the exact value of its
/// double as a string, so that `restrict --arithmetic exact` computes the exact answer for the
/// job's doubles (the reference `check` should use).
fn exact_job(value: &Value) -> Value {
    match value {
        Value::Number(n) if n.as_i64().is_none() => {
            let x = n.as_f64().expect("a double");
            json!(format_rational(&Rational::from_float(x).expect("finite")).expect("exact"))
        }
        Value::Array(items) => Value::Array(items.iter().map(exact_job).collect()),
        Value::Object(map) => {
            Value::Object(map.iter().map(|(k, v)| (k.clone(), exact_job(v))).collect())
        }
        other => other.clone(),
    }
}

/// Every number of an exact answer's `control_points` rounded to its nearest double.
fn rounded(value: &Value) -> Value {
    match value {
        Value::String(_) => json!(rational_to_f64(&exact(value))),
        Value::Array(items) => Value::Array(items.iter().map(rounded).collect()),
        Value::Object(map) => {
            Value::Object(map.iter().map(|(k, v)| (k.clone(), rounded(v))).collect())
        }
        other => other.clone(),
    }
}

#[test]
fn own_f64_answer_is_within_its_error_bound() {
    let mut r = Rng(0xC0FFEE);
    for round in 0..80 {
        let job = random_job(&mut r, round);
        let answer = restrict(&["--arithmetic", "f64"], &job);
        let bound =
            Rational::from_float(answer["error_bound"].as_f64().expect("a bound")).expect("finite");
        let report = check(&[], &json!({"job": job, "answer": answer}));
        let error = exact(&report["max_abs_error"]);
        assert!(
            error <= bound,
            "{job}: error {report} over the bound {bound}"
        );
        assert!(report["max_abs_error_f64"].as_f64().is_some());
    }
}

#[test]
fn rounded_exact_answer_is_within_half_an_ulp() {
    let half_ulp = Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 53));
    let mut r = Rng(0xBEEF);
    for round in 0..40 {
        let job = random_job(&mut r, round);
        let exact_answer = restrict(&[], &exact_job(&job));
        let answer = json!({"control_points": rounded(&exact_answer["control_points"])});
        let report = check(&["--per-point"], &json!({"job": job, "answer": answer}));
        let per_point = report["per_point"].as_array().expect("per_point");
        assert_eq!(per_point.len() as u64, report["points"].as_u64().unwrap());
        for p in per_point {
            assert!(exact(&p["rel"]) <= half_ulp, "{job}: {p}");
            // Nesting of "at": one index per array level of the answer.
            let depth = if job["kind"] == "bezier-tensor" { 2 } else { 1 };
            assert_eq!(p["at"].as_array().unwrap().len(), depth, "{p}");
        }
        assert!(exact(&report["max_rel_error"]) <= half_ulp);
    }
}

#[test]
fn a_perturbation_is_measured_exactly() {
    // The cubic 0, 8, 16, 64 on [0, 1/2]: 0, 4, 8, 17, all doubles.
    let job = json!({"kind": "bezier-curve", "control_points": [[0, 1], [8, 1], [16, 1], [64, 1]], "interval": [0, 0.5]});
    let mut answer = restrict(&["--arithmetic", "f64"], &job);
    assert_eq!(
        answer["control_points"],
        json!([[0.0, 1.0], [4.0, 1.0], [8.0, 1.0], [17.0, 1.0]])
    );
    let report = check(&[], &json!({"job": job, "answer": answer}));
    assert_eq!(report["max_abs_error"], "0");
    assert_eq!(report["max_rel_error"], "0");
    answer["control_points"][2][0] = json!(8.0 + 1.0 / 1024.0);
    answer["control_points"][0][1] = json!(1.0 - 1.0 / 4096.0);
    let report = check(&["--per-point"], &json!({"job": job, "answer": answer}));
    assert_eq!(report["points"], 4);
    assert_eq!(report["max_abs_error"], "1/1024");
    assert_eq!(report["max_abs_error_f64"], 1.0 / 1024.0);
    assert_eq!(report["max_abs_at"], json!([2]));
    // Relative: 1/4096 against max(|0|, |1|) = 1 at point 0; 1/1024 against 8 at point 2.
    assert_eq!(report["max_rel_error"], "1/4096");
    assert_eq!(report["max_rel_at"], json!([0]));
    assert_eq!(report["per_point"][2]["rel"], "1/8192");
    assert_eq!(
        report["per_point"][1],
        json!({"at": [1], "abs": "0", "abs_f64": 0.0, "rel": "0", "rel_f64": 0.0})
    );
    // Extra fields of the answer are ignored; per_point only on request.
    assert!(report.get("per_point").is_some());
    answer["anything"] = json!("else");
    assert!(check(&[], &json!({"job": job, "answer": answer}))
        .get("per_point")
        .is_none());
}
