//! The `blossom restrict` command line, driven as a process exactly as the contract
//! (`cli.md`) describes: bad input of every class, hand-checked answers, and agreement of all
//! methods and both arithmetics on random jobs.

use crate::binary::{run_binary as run_bytes, Run};
use serde_json::{json, Value};

fn run(args: &[&str], input: &str) -> Run {
    run_bytes(args, input.as_bytes())
}

/// Runs `blossom restrict ARGS` on `job` and returns the parsed answer, checking that it is
/// one line of JSON on stdout, nothing on stderr, exit 0.
fn answer(args: &[&str], job: &Value) -> Value {
    let mut all = vec!["restrict"];
    all.extend_from_slice(args);
    let r = run(&all, &job.to_string());
    assert_eq!(r.code, 0, "job {job} args {args:?}: stderr {}", r.stderr);
    assert!(r.stderr.is_empty(), "{}", r.stderr);
    assert!(
        r.stdout.ends_with('\n') && r.stdout.lines().count() == 1,
        "{}",
        r.stdout
    );
    serde_json::from_str(&r.stdout).expect("the answer is JSON")
}

/// The raw answer text of `blossom restrict ARGS` on `job`.
fn answer_text(args: &[&str], job: &Value) -> String {
    let mut all = vec!["restrict"];
    all.extend_from_slice(args);
    let r = run(&all, &job.to_string());
    assert_eq!(r.code, 0, "job {job} args {args:?}: stderr {}", r.stderr);
    r.stdout
}

/// Checks the error contract: exit 2, empty stdout, one line `error: FIELD: ...` on stderr.
/// Returns the line without the `error: ` prefix.
fn assert_error_bytes(args: &[&str], input: &[u8], field: &str) -> String {
    let r = run_bytes(args, input);
    let shown = String::from_utf8_lossy(input);
    assert_eq!(
        r.code, 2,
        "args {args:?} input {shown}: stdout {} stderr {}",
        r.stdout, r.stderr
    );
    assert!(r.stdout.is_empty(), "stdout must stay empty: {}", r.stdout);
    assert!(r.stderr.ends_with('\n'), "{:?}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "one line: {:?}", r.stderr);
    let line = r.stderr.trim_end_matches('\n');
    let rest = line
        .strip_prefix("error: ")
        .unwrap_or_else(|| panic!("starts with `error: `: {line}"));
    assert!(
        rest.starts_with(&format!("{field}: ")),
        "the error names `{field}`: {line}"
    );
    rest.to_string()
}

fn assert_error(args: &[&str], input: &str, field: &str) -> String {
    assert_error_bytes(args, input.as_bytes(), field)
}

/// A bad job under `restrict` (default flags).
fn bad_job(job: &Value, field: &str) -> String {
    assert_error(&["restrict"], &job.to_string(), field)
}

fn curve_job(coefficients: Value, interval: Value) -> Value {
    json!({"kind": "curve", "coefficients": coefficients, "interval": interval})
}

// ---------------------------------------------------------------------------------------
// (a) Bad input of every class.

#[test]
fn malformed_json() {
    let msg = assert_error(&["restrict"], "{\"kind\": \"curve\",", "input");
    assert!(
        msg.starts_with("input: invalid JSON at line 1 column "),
        "{msg}"
    );
    assert_error(&["restrict"], "", "input");
    assert_error(&["restrict"], "   \n", "input");
    assert_error(&["restrict"], "{\"kind\": 'curve'}", "input");
    // Trailing garbage after a complete document.
    assert_error(
        &["restrict"],
        r#"{"kind": "curve", "coefficients": [[1]], "interval": [0, 1]} x"#,
        "input",
    );
    // Not UTF-8.
    assert_error_bytes(&["restrict"], b"{\"kind\": \"\xff\"}", "input");
    // Nesting deep enough to overflow a naive recursive parser.
    let deep = "[".repeat(100_000);
    assert_error(&["restrict"], &deep, "input");
}

#[test]
fn top_level_not_an_object() {
    for doc in ["[1, 2]", "3", "\"curve\"", "null"] {
        let msg = assert_error(&["restrict"], doc, "input");
        assert!(msg.contains("expected a JSON object"), "{msg}");
    }
}

#[test]
fn unknown_or_unsupported_kind() {
    assert_eq!(
        bad_job(&json!({"kind": "foo"}), "kind"),
        "kind: unknown kind \"foo\" (expected one of curve, tensor, triangle, bezier-curve, \
         bspline, bspline-eval, rational-curve, elevate, reduce, bezier-tensor, bezier-triangle, \
         derivative, rational-tensor, rational-triangle)"
    );
    // The spline, rational and degree-change kinds are answered (cli_spline_jobs.rs):
    // without their fields they are refused for the first missing one.
    for (kind, first) in [
        ("bezier-curve", "control_points"),
        ("bspline", "degree"),
        ("bspline-eval", "degree"),
        ("rational-curve", "numerator"),
        ("elevate", "control_points"),
        ("reduce", "control_points"),
        ("bezier-tensor", "control_points"),
        ("bezier-triangle", "control_points"),
        ("derivative", "control_points"),
        ("rational-tensor", "numerator"),
        ("rational-triangle", "numerator"),
    ] {
        assert_eq!(
            bad_job(&json!({"kind": kind}), first),
            format!("{first}: missing field")
        );
    }
    assert_eq!(
        bad_job(&json!({"coefficients": [[1]]}), "kind"),
        "kind: missing field"
    );
    bad_job(&json!({"kind": 3}), "kind");
    // A kind with a newline still gives one line.
    bad_job(&json!({"kind": "a\nb"}), "kind");
}

#[test]
fn missing_fields() {
    let cases = [
        (json!({"kind": "curve", "interval": [0, 1]}), "coefficients"),
        (json!({"kind": "curve", "coefficients": [[1]]}), "interval"),
        (
            json!({"kind": "tensor", "coefficients": [[[1]]]}),
            "rectangle",
        ),
        (
            json!({"kind": "tensor", "rectangle": [0, 1, 0, 1]}),
            "coefficients",
        ),
        (
            json!({"kind": "triangle", "coefficients": [[[1]]]}),
            "triangle",
        ),
        (
            json!({"kind": "triangle", "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "coefficients",
        ),
    ];
    for (job, field) in cases {
        assert_eq!(bad_job(&job, field), format!("{field}: missing field"));
    }
}

#[test]
fn points_of_different_lengths() {
    assert_eq!(
        bad_job(
            &curve_job(json!([[1, 2, 3], [4, 5, 6], [7, 8]]), json!([0, 1])),
            "coefficients[2]"
        ),
        "coefficients[2]: expected 3 coordinates, found 2"
    );
    bad_job(
        &curve_job(json!([[1], [2, 3]]), json!([0, 1])),
        "coefficients[1]",
    );
    // Across the rows of a grid, too.
    let job = json!({"kind": "tensor", "coefficients": [[[1, 2], [3, 4]], [[5, 6], [7]]],
                     "rectangle": [0, 1, 0, 1]});
    assert_eq!(
        bad_job(&job, "coefficients[1][1]"),
        "coefficients[1][1]: expected 2 coordinates, found 1"
    );
    let job = json!({"kind": "triangle", "coefficients": [[[1]], [[2, 3]]],
                     "triangle": [[0, 0], [1, 0], [0, 1]]});
    bad_job(&job, "coefficients[1][0]");
}

#[test]
fn empty_coefficient_lists_and_points() {
    bad_job(&curve_job(json!([]), json!([0, 1])), "coefficients");
    bad_job(&curve_job(json!([[]]), json!([0, 1])), "coefficients[0]");
    let rect = json!([0, 1, 0, 1]);
    bad_job(
        &json!({"kind": "tensor", "coefficients": [], "rectangle": rect}),
        "coefficients",
    );
    bad_job(
        &json!({"kind": "tensor", "coefficients": [[]], "rectangle": rect}),
        "coefficients[0]",
    );
    bad_job(
        &json!({"kind": "tensor", "coefficients": [[[]]], "rectangle": rect}),
        "coefficients[0][0]",
    );
    let tri = json!([[0, 0], [1, 0], [0, 1]]);
    bad_job(
        &json!({"kind": "triangle", "coefficients": [], "triangle": tri}),
        "coefficients",
    );
}

#[test]
fn wrong_json_types() {
    bad_job(&curve_job(json!({"0": [1]}), json!([0, 1])), "coefficients");
    bad_job(&curve_job(json!([1, 2]), json!([0, 1])), "coefficients[0]");
    bad_job(
        &curve_job(json!([[true]]), json!([0, 1])),
        "coefficients[0][0]",
    );
    bad_job(
        &curve_job(json!([[null]]), json!([0, 1])),
        "coefficients[0][0]",
    );
    bad_job(
        &curve_job(json!([[[1]]]), json!([0, 1])),
        "coefficients[0][0]",
    );
    bad_job(&curve_job(json!([[1]]), json!("0..1")), "interval");
    bad_job(
        &curve_job(json!([[1]]), json!([0, {"x": 1}])),
        "interval[1]",
    );
    let tri = json!({"kind": "triangle", "coefficients": [[[1]]], "triangle": [[0, 0], 5, [0, 1]]});
    bad_job(&tri, "triangle[1]");
    let rows = json!({"kind": "tensor", "coefficients": [[[1]], 2], "rectangle": [0, 1, 0, 1]});
    bad_job(&rows, "coefficients[1]");
}

#[test]
fn domains_of_the_wrong_size() {
    assert_eq!(
        bad_job(&curve_job(json!([[1]]), json!([0, 1, 2])), "interval"),
        "interval: expected 2 numbers, found 3"
    );
    bad_job(&curve_job(json!([[1]]), json!([0])), "interval");
    let job = json!({"kind": "tensor", "coefficients": [[[1]]], "rectangle": [0, 1, 2]});
    assert_eq!(
        bad_job(&job, "rectangle"),
        "rectangle: expected 4 numbers, found 3"
    );
    let job = json!({"kind": "tensor", "coefficients": [[[1]]], "rectangle": [0, 1, 2, "x"]});
    bad_job(&job, "rectangle[3]");
    let job = json!({"kind": "triangle", "coefficients": [[[1]]], "triangle": [[0, 0], [1, 0]]});
    bad_job(&job, "triangle");
    let job = json!({"kind": "triangle", "coefficients": [[[1]]],
                     "triangle": [[0, 0], [1, 0, 0], [0, 1]]});
    assert_eq!(
        bad_job(&job, "triangle[1]"),
        "triangle[1]: expected 2 coordinates, found 3"
    );
    let job = json!({"kind": "triangle", "coefficients": [[[1]]],
                     "triangle": [[0, 0], [1, 0], [0, "1/0"]]});
    bad_job(&job, "triangle[2][1]");
}

#[test]
fn non_finite_or_unparsable_numbers() {
    for bad in ["inf", "-inf", "Infinity", "NaN", "nan"] {
        let msg = bad_job(
            &curve_job(json!([[1], [bad]]), json!([0, 1])),
            "coefficients[1][0]",
        );
        assert!(msg.contains("not a finite number"), "{msg}");
        assert_error(
            &["restrict", "--arithmetic", "f64"],
            &curve_job(json!([[1]]), json!([0, bad])).to_string(),
            "interval[1]",
        );
    }
    for bad in [
        "abc", "1/", "/2", "", "1e", "1.2.3", "0x10", " 1", "1/2/3", "--1",
    ] {
        bad_job(
            &curve_job(json!([[1, bad]]), json!([0, 1])),
            "coefficients[0][1]",
        );
        assert_error(
            &["restrict", "--arithmetic", "f64"],
            &curve_job(json!([[1, bad]]), json!([0, 1])).to_string(),
            "coefficients[0][1]",
        );
    }
    // An exponent too large to expand exactly, and a value out of the range of f64.
    let msg = bad_job(
        &curve_job(json!([[1]]), json!([0, "1e999999999"])),
        "interval[1]",
    );
    assert!(msg.contains("exponent"), "{msg}");
    // ... unless the digits are all zero: zero with any exponent is zero.
    let r = run_bytes(
        &["restrict"],
        curve_job(
            json!([["0e999999999"], ["-0.00E-999999999"]]),
            json!([0, 1]),
        )
        .to_string()
        .as_bytes(),
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(
        r.stdout.trim_end(),
        r#"{"kind":"curve","degree":1,"control_points":[["0"],["0"]]}"#
    );
    assert_error(
        &["restrict", "--arithmetic", "f64"],
        &curve_job(json!([[1]]), json!([0, "1e400"])).to_string(),
        "interval[1]",
    );
    assert_error(
        &["restrict", "--arithmetic", "f64"],
        r#"{"kind": "curve", "coefficients": [[1e400]], "interval": [0, 1]}"#,
        "coefficients[0][0]",
    );
}

#[test]
fn zero_denominator() {
    let msg = bad_job(&curve_job(json!([[1]]), json!(["1/0", 1])), "interval[0]");
    assert!(msg.contains("zero denominator"), "{msg}");
    assert_error(
        &["restrict", "--arithmetic", "f64"],
        &curve_job(json!([["0/0"]]), json!([0, 1])).to_string(),
        "coefficients[0][0]",
    );
}

#[test]
fn non_rectangular_grids() {
    let job =
        json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3]]], "rectangle": [0, 1, 0, 1]});
    assert_eq!(
        bad_job(&job, "coefficients[1]"),
        "coefficients[1]: expected 2 points (the grid must be rectangular), found 1"
    );
    // A triangular array of coefficients is not a grid either.
    let job = json!({"kind": "triangle", "coefficients": [[[1], [2], [3]], [[4], [5]], [[6]]],
                     "triangle": [[0, 0], [1, 0], [0, 1]]});
    bad_job(&job, "coefficients[1]");
}

#[test]
fn json_floats_are_rejected_under_exact_only() {
    for text in ["0.1", "1.0", "1e3", "-2.5E-1"] {
        let input =
            format!(r#"{{"kind": "curve", "coefficients": [[{text}]], "interval": [0, 1]}}"#);
        let msg = assert_error(&["restrict"], &input, "coefficients[0][0]");
        assert!(msg.contains("already rounded"), "{msg}");
        let r = run(&["restrict", "--arithmetic", "f64"], &input);
        assert_eq!(r.code, 0, "{}", r.stderr);
    }
    let input = r#"{"kind": "curve", "coefficients": [[1]], "interval": [0, 0.5]}"#;
    assert_error(&["restrict"], input, "interval[1]");
}

#[test]
fn f64_overflow_is_an_error_not_null() {
    let job = curve_job(json!([["1e300"], ["1e300"]]), json!([0, "1e300"]));
    let msg = assert_error(
        &["restrict", "--arithmetic", "f64"],
        &job.to_string(),
        "control_points[1][0]",
    );
    assert!(msg.contains("not finite"), "{msg}");
    // The same job is fine exactly: C(10^300) = 10^300 + 10^600.
    let out = answer(&[], &job);
    assert_eq!(
        out["control_points"][1][0],
        json!(format!("1{}1{}", "0".repeat(299), "0".repeat(300)))
    );
}

#[test]
fn bad_arguments() {
    let job = curve_job(json!([[1]]), json!([0, 1])).to_string();
    assert_error(&["frobnicate"], &job, "frobnicate");
    assert_error(&["--frobnicate"], &job, "--frobnicate");
    assert_error(&["restrict", "--frobnicate"], &job, "--frobnicate");
    assert_error(&["restrict", "job.json"], &job, "job.json");
    assert_error(&["restrict", "--input"], &job, "--input");
    assert_error(&["restrict", "--method"], &job, "--method");
    assert_error(&["restrict", "--arithmetic"], &job, "--arithmetic");
    assert_error(
        &["restrict", "--input", "--method", "pyramid"],
        &job,
        "--input",
    );
    assert_error(&["restrict", "--arithmetic", "f32"], &job, "--arithmetic");
    assert_error(&["restrict", "--arithmetic", "EXACT"], &job, "--arithmetic");
    let msg = assert_error(&["restrict", "--method", "magic"], &job, "--method");
    assert!(msg.contains("closed-form") && msg.contains("bulk"), "{msg}");
    assert_error(&["restrict", "--method=", ""], &job, "--method");
    assert_error(
        &["restrict", "--method", "bulk", "--method", "pyramid"],
        &job,
        "--method",
    );
    assert_error(&["verify", "--frobnicate"], "", "--frobnicate");
    assert_error(&["verify", "extra"], "", "extra");
}

#[cfg(feature = "carried-grid")]
#[test]
fn specialised_refuses_degrees_it_does_not_carry() {
    let zero = || json!([1]);
    let grid = |n: usize, m: usize| json!(vec![vec![json!([1]); m + 1]; n + 1]);
    let rect = json!([0, 1, 0, 1]);
    let tri = json!([[0, 0], [1, 0], [0, 1]]);
    let curve = |n: usize| curve_job(json!(vec![zero(); n + 1]), json!([0, 1]));
    for job in [
        curve(0),
        curve(17),
        json!({"kind": "tensor", "coefficients": grid(0, 0), "rectangle": rect}),
        json!({"kind": "tensor", "coefficients": grid(6, 1), "rectangle": rect}),
        json!({"kind": "triangle", "coefficients": grid(0, 0), "triangle": tri}),
        json!({"kind": "triangle", "coefficients": grid(5, 0), "triangle": tri}),
        json!({"kind": "triangle", "coefficients": grid(1, 5), "triangle": tri}),
    ] {
        for arithmetic in ["exact", "f64"] {
            let msg = assert_error(
                &[
                    "restrict",
                    "--method",
                    "specialised",
                    "--arithmetic",
                    arithmetic,
                ],
                &job.to_string(),
                "--method",
            );
            assert!(
                msg.contains("carries curves of degree 1..=16") && msg.contains("(n, m)"),
                "{msg}"
            );
        }
    }
}

#[cfg(feature = "carried-grid")]
#[test]
fn specialised_at_the_largest_carried_degrees() {
    let mut rng = Rng(0x5EED_0FB1_0550);
    let rect = json!([rng.number(), rng.number(), rng.number(), rng.number()]);
    let tri = json!([rng.point(2), rng.point(2), rng.point(2)]);
    for job in [
        curve_job(
            json!((0..=16).map(|_| rng.point(2)).collect::<Vec<_>>()),
            json!(["-1/3", "5/2"]),
        ),
        json!({"kind": "tensor", "coefficients": rng.grid(5, 5, 2), "rectangle": rect}),
        json!({"kind": "tensor", "coefficients": rng.grid(0, 5, 1), "rectangle": rect}),
        json!({"kind": "triangle", "coefficients": rng.grid(4, 4, 2), "triangle": tri}),
        json!({"kind": "triangle", "coefficients": rng.grid(4, 0, 1), "triangle": tri}),
    ] {
        assert_eq!(
            answer_text(&["--method", "specialised"], &job),
            answer_text(&["--method", "bulk"], &job),
            "{job}"
        );
    }
}

#[test]
fn unreadable_input_file() {
    let missing = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("no-such-job.json");
    let missing = missing.to_str().expect("a UTF-8 path");
    let msg = assert_error(&["restrict", "--input", missing], "", "--input");
    assert!(msg.contains("no-such-job.json"), "{msg}");
    // A directory cannot be read as a file.
    assert_error(
        &["restrict", "--input", env!("CARGO_TARGET_TMPDIR")],
        "",
        "--input",
    );
}

// ---------------------------------------------------------------------------------------
// (b) Hand-checked answers.

#[test]
fn input_from_a_file_or_stdin() {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli_restrict_job.json");
    let job = curve_job(json!([[0], [0], [1]]), json!([0, 1]));
    std::fs::write(&path, job.to_string()).expect("write the job");
    let path = path.to_str().expect("a UTF-8 path");
    let from_file = run(&["restrict", "--input", path], "not JSON, not read");
    assert_eq!(from_file.code, 0, "{}", from_file.stderr);
    let with_equals = run(&["restrict", &format!("--input={path}")], "");
    let from_stdin = run(&["restrict", "--input", "-"], &job.to_string());
    assert_eq!(from_file.stdout, from_stdin.stdout);
    assert_eq!(from_file.stdout, with_equals.stdout);
}

#[test]
fn curve_u_squared_on_unit_interval() {
    // u^2 = B_2^2 on [0, 1]: control points 0, 0, 1 (w_1 = b(1, 0) = 1 * 0 = 0).
    let text = answer_text(&[], &curve_job(json!([[0], [0], [1]]), json!([0, 1])));
    assert_eq!(
        text,
        "{\"kind\":\"curve\",\"degree\":2,\"control_points\":[[\"0\"],[\"0\"],[\"1\"]]}\n"
    );
}

#[test]
fn curve_one_plus_u_on_two_three() {
    // 1 + u on [2, 3]: w_0 = C(2) = 3, w_1 = C(3) = 4.
    let out = answer(&[], &curve_job(json!([[1], [1]]), json!([2, 3])));
    assert_eq!(
        out,
        json!({"kind": "curve", "degree": 1, "control_points": [["3"], ["4"]]})
    );
    // The same in f64: JSON numbers.
    let out = answer(
        &["--arithmetic", "f64"],
        &curve_job(json!([[1], [1]]), json!([2, 3])),
    );
    assert_eq!(out["control_points"][0][0].as_f64(), Some(3.0));
    assert_eq!(out["control_points"][1][0].as_f64(), Some(4.0));
    assert!(out["control_points"][1][0].is_number());
}

#[test]
fn curve_with_fractions_in_3d() {
    // C(u) = (u, u^2, 1/2) on [1/2, 3/2], degree 2:
    // w_0 = C(1/2) = (1/2, 1/4, 1/2); w_2 = C(3/2) = (3/2, 9/4, 1/2);
    // w_1 = b(1/2, 3/2) = ((1/2 + 3/2)/2, (1/2)(3/2), 1/2) = (1, 3/4, 1/2).
    let job = curve_job(
        json!([[0, 0, "1/2"], [1, 0, 0], [0, 1, 0]]),
        json!(["0.5", "3/2"]),
    );
    let out = answer(&[], &job);
    assert_eq!(
        out["control_points"],
        json!([
            ["1/2", "1/4", "1/2"],
            ["1", "3/4", "1/2"],
            ["3/2", "9/4", "1/2"]
        ])
    );
}

#[test]
fn tensor_bilinear() {
    // S(u, v) = 1 + 2v + 3u + 4uv (c_00 = 1, c_01 = 2, c_10 = 3, c_11 = 4) on [1, 3] x [1/2, 2].
    // Bilinear, so p_{nu mu} = S(corner): p_00 = S(1, 1/2) = 1 + 1 + 3 + 2 = 7,
    // p_01 = S(1, 2) = 1 + 4 + 3 + 8 = 16, p_10 = S(3, 1/2) = 1 + 1 + 9 + 6 = 17,
    // p_11 = S(3, 2) = 1 + 4 + 9 + 24 = 38.
    let job = json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3], [4]]],
                     "rectangle": [1, 3, "1/2", 2]});
    let out = answer(&[], &job);
    assert_eq!(
        out,
        json!({"kind": "tensor", "degree": [1, 1],
               "control_points": [[["7"], ["16"]], [["17"], ["38"]]]})
    );
    // Degree (0, 1): S(u, v) = 5 - v on [0, 1] x [-1, 1] gives the row 6, 4.
    let job = json!({"kind": "tensor", "coefficients": [[[5], [-1]]], "rectangle": [0, 1, -1, 1]});
    let out = answer(&[], &job);
    assert_eq!(out["degree"], json!([0, 1]));
    assert_eq!(out["control_points"], json!([[["6"], ["4"]]]));
}

#[test]
fn triangle_degree_one() {
    // S(u, v) = 1 + 2v (n = 0, m = 1, N = 1) on a = (1, 2), b = (3, -1), c = (0, 1/2):
    // the control points are the values at the corners: q_100 = S(a) = 5, q_010 = S(b) = -1,
    // q_001 = S(c) = 2, listed in lexicographic order of (a, b): (0,0,1), (0,1,0), (1,0,0).
    let job = json!({"kind": "triangle", "coefficients": [[[1], [2]]],
                     "triangle": [[1, 2], [3, -1], [0, "1/2"]]});
    let text = answer_text(&[], &job);
    assert_eq!(
        text,
        "{\"kind\":\"triangle\",\"degree\":1,\"control_points\":[\
         {\"a\":0,\"b\":0,\"c\":1,\"point\":[\"2\"]},\
         {\"a\":0,\"b\":1,\"c\":0,\"point\":[\"-1\"]},\
         {\"a\":1,\"b\":0,\"c\":0,\"point\":[\"5\"]}]}\n"
    );
}

#[test]
fn triangle_bilinear_is_degree_two() {
    // S = 1 + 2v + 3u + 4uv on a = (1, 0), b = (0, 1), c = (0, 0), N = 2. With the blossom
    // b(x, y) = 1 + (v_x + v_y) + 3 (u_x + u_y) / 2 + 2 (u_x v_y + u_y v_x):
    // q_002 = S(c) = 1, q_011 = b(b, c) = 2, q_020 = S(b) = 3, q_101 = b(a, c) = 5/2,
    // q_110 = b(a, b) = 1 + 1 + 3/2 + 2 = 11/2, q_200 = S(a) = 4.
    let job = json!({"kind": "triangle", "coefficients": [[[1], [2]], [[3], [4]]],
                     "triangle": [[1, 0], [0, 1], [0, 0]]});
    let out = answer(&[], &job);
    assert_eq!(out["degree"], json!(2));
    let got: Vec<(u64, u64, u64, Value)> = out["control_points"]
        .as_array()
        .expect("entries")
        .iter()
        .map(|e| {
            let k = |f: &str| e[f].as_u64().expect("an index");
            (k("a"), k("b"), k("c"), e["point"][0].clone())
        })
        .collect();
    assert_eq!(
        got,
        vec![
            (0, 0, 2, json!("1")),
            (0, 1, 1, json!("2")),
            (0, 2, 0, json!("3")),
            (1, 0, 1, json!("5/2")),
            (1, 1, 0, json!("11/2")),
            (2, 0, 0, json!("4")),
        ]
    );
}

#[test]
fn number_formatting() {
    // A constant curve returns its coefficient, written in lowest terms.
    let cases = [
        (json!("-22/7"), "-22/7"),
        (json!("6/8"), "3/4"),
        (json!("-6/3"), "-2"),
        (json!("0/5"), "0"),
        (json!("-0"), "0"),
        (json!("0.125"), "1/8"),
        (json!("-1e-3"), "-1/1000"),
        (json!("2.5E+3"), "2500"),
        (json!(".5"), "1/2"),
        (json!(-7), "-7"),
        (json!("+7"), "7"),
    ];
    for (input, want) in cases {
        let out = answer(&[], &curve_job(json!([[input.clone()]]), json!([0, 1])));
        assert_eq!(out["control_points"][0][0], json!(want), "input {input}");
    }
    // Integers of any size are exact, as JSON numbers or strings.
    let big = "123456789012345678901234567890123456789";
    let input = format!(
        r#"{{"kind": "curve", "coefficients": [[{big}], ["-{big}"]], "interval": [0, 1]}}"#
    );
    let r = run(&["restrict"], &input);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let out: Value = serde_json::from_str(&r.stdout).expect("JSON");
    assert_eq!(out["control_points"], json!([[big], ["0"]]));
    // -1/3 + 1/3 u on [1, 2] is 0, then 1/3.
    let out = answer(&[], &curve_job(json!([["-1/3"], ["1/3"]]), json!([1, 2])));
    assert_eq!(out["control_points"], json!([["0"], ["1/3"]]));
}

#[test]
fn f64_output_is_json_numbers() {
    let job = curve_job(json!([["1/4"], [0.5]]), json!(["1/2", 1]));
    let r = run(&["restrict", "--arithmetic", "f64"], &job.to_string());
    assert_eq!(r.code, 0, "{}", r.stderr);
    let out: Value = serde_json::from_str(&r.stdout).expect("JSON");
    // 1/4 + u/2 at 1/2 and 1.
    assert_eq!(out["control_points"], json!([[0.5], [0.75]]));
    assert!(out["control_points"][0][0].is_number());
    assert!(!r.stdout.contains("\"0.5\""), "{}", r.stdout);
}

#[test]
fn unknown_fields_are_refused() {
    // A misspelt field is named, with the field it was meant to be, before it is missed.
    let job = json!({"kind": "bezier-curve", "control_point": [[0], [1]], "interval": [0, 1]});
    assert_eq!(
        bad_job(&job, "control_point"),
        "error: control_point: unknown field \"control_point\" (did you mean \"control_points\"?)"
    );
    // A field no kind reads: the accepted ones are listed.
    let job = json!({"kind": "curve", "coefficients": [[1], [1]], "interval": [2, 3],
                     "comment": "x"});
    assert_eq!(
        bad_job(&job, "comment"),
        "error: comment: unknown field \"comment\" (expected kind, coefficients or interval)"
    );
    // A field of another kind is unknown to this one.
    let job = json!({"kind": "curve", "coefficients": [[1]], "interval": [0, 1], "rectangle": [0, 1, 0, 1]});
    bad_job(&job, "rectangle");
    // An optional field, misspelt, is no longer ignored.
    let job = json!({"kind": "triangle", "totaldegree": 1, "coefficients": [[[0], [1]], [[1]]],
                     "triangle": [[0, 0], [1, 0], [0, 1]]});
    assert!(bad_job(&job, "totaldegree").ends_with("(did you mean \"total_degree\"?)"));
    // Inside a job: the entries of a Bézier triangle, the pieces of a B-spline.
    let entry = |a: u32, b: u32, c: u32| json!({"a": a, "b": b, "c": c, "point": [1]});
    let mut entries = vec![entry(1, 0, 0), entry(0, 1, 0), entry(0, 0, 1)];
    entries[2]["weight"] = json!(2);
    let job = json!({"kind": "bezier-triangle", "control_points": entries,
                     "triangle": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]});
    bad_job(&job, "control_points[2].weight");
    let job = json!({"kind": "bspline", "degree": 1,
                     "pieces": [{"interval": [0, 1], "coeficients": [[0], [1]]}]});
    bad_job(&job, "pieces[0].coeficients");
    // Under every method and arithmetic, before the budget.
    let job = json!({"kind": "tensor", "coefficients": [[[1]]], "rectangle": [0, 1, 0, 1], "x": 1});
    for args in [
        &["restrict", "--arithmetic", "f64"][..],
        &["restrict", "--method", "pyramid"],
        &["restrict", "--max-work", "0"],
    ] {
        assert_error(args, &job.to_string(), "x");
    }
}

#[test]
fn the_default_method_is_bulk_for_every_restriction() {
    // f64 answers differ between methods in their last bits and in their error bounds: the
    // answer without --method is that of bulk, bit for bit, for every kind that has methods.
    let tri = json!([["1/10", "1/5"], ["9/10", "1/7"], ["1/3", "7/8"]]);
    let bary = json!([
        ["1/10", "3/10", "3/5"],
        ["7/10", "1/5", "1/10"],
        ["1/4", "1/2", "1/4"]
    ]);
    let points = |count: usize, seed: &mut u64| -> Vec<Value> {
        (0..count)
            .map(|_| {
                *seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                json!([
                    format!("{}/97", (*seed >> 40) % 200),
                    format!("-{}/89", (*seed >> 20) % 100)
                ])
            })
            .collect()
    };
    let mut seed = 7u64;
    let grid = |pts: Vec<Value>, cols: usize| -> Vec<Value> {
        pts.chunks(cols)
            .map(|row| Value::from(row.to_vec()))
            .collect()
    };
    let triangular = |pts: Vec<Value>, n: usize| -> Vec<Value> {
        let mut rows = Vec::new();
        let mut it = pts.into_iter();
        for i in 0..=n {
            rows.push(Value::from(it.by_ref().take(n + 1 - i).collect::<Vec<_>>()));
        }
        rows
    };
    let mut entries = Vec::new();
    let net = points(15, &mut seed);
    let mut k = 0;
    for a in 0..=4u32 {
        for b in 0..=4 - a {
            entries.push(json!({"a": a, "b": b, "c": 4 - a - b, "point": net[k]}));
            k += 1;
        }
    }
    let jobs = [
        json!({"kind": "curve", "coefficients": points(9, &mut seed), "interval": ["1/3", "5/7"]}),
        json!({"kind": "tensor", "coefficients": grid(points(12, &mut seed), 4), "rectangle": ["1/3", "5/7", "-1/9", "2/3"]}),
        json!({"kind": "triangle", "coefficients": grid(points(12, &mut seed), 4), "triangle": tri}),
        json!({"kind": "triangle", "total_degree": 4, "coefficients": triangular(points(15, &mut seed), 4), "triangle": tri}),
        json!({"kind": "bezier-curve", "control_points": points(9, &mut seed), "interval": ["1/3", "5/7"]}),
        json!({"kind": "bezier-tensor", "control_points": grid(points(12, &mut seed), 4), "rectangle": ["1/3", "5/7", "-1/9", "2/3"]}),
        json!({"kind": "bezier-triangle", "control_points": entries, "triangle": bary}),
    ];
    for job in &jobs {
        for arithmetic in ["exact", "f64"] {
            let default = answer_text(&["--arithmetic", arithmetic], job);
            assert_eq!(
                default,
                answer_text(&["--arithmetic", arithmetic, "--method", "bulk"], job),
                "{arithmetic}: {job}"
            );
        }
    }
    // The measurement of issue 24: a degree-24 Bézier curve in f64 on an interval of length
    // 1e-3. The engine's answer keeps about 15 digits; that of the former default, closed-form,
    // lost about 10 of them (its relative error was 2.3e-6).
    let mut seed = 24u64;
    let job = json!({"kind": "bezier-curve", "control_points": points(25, &mut seed),
                     "interval": ["0.4", "0.401"]});
    let exact = answer(&[], &job);
    let relative_error = |args: &[&str]| -> f64 {
        let float = answer(&[args, &["--arithmetic", "f64"]].concat(), &job);
        let mut exact_numbers = Vec::new();
        numbers(&exact["control_points"], &mut exact_numbers);
        let mut float_numbers = Vec::new();
        numbers(&float["control_points"], &mut float_numbers);
        let exact_f64: Vec<f64> = exact_numbers
            .iter()
            .map(|v| blossom_cli::number::parse_f64(v.as_str().unwrap()).unwrap())
            .collect();
        let scale = exact_f64.iter().fold(0.0f64, |s, x| s.max(x.abs()));
        float_numbers
            .iter()
            .zip(&exact_f64)
            .map(|(f, e)| (f.as_f64().unwrap() - e).abs() / scale)
            .fold(0.0, f64::max)
    };
    let default = relative_error(&[]);
    let closed_form = relative_error(&["--method", "closed-form"]);
    assert!(default < 1e-14, "the default lost digits: {default:e}");
    assert!(
        closed_form > 1e3 * default,
        "closed-form {closed_form:e}, default {default:e}"
    );
}

#[test]
fn help_and_verify_entry_points() {
    for args in [
        &["--help"][..],
        &["restrict", "--help"],
        &["verify", "--help"],
        &["-h"],
    ] {
        let r = run(args, "");
        assert_eq!(r.code, 0, "{args:?}");
        assert!(r.stdout.contains("Usage"), "{args:?}");
        assert!(r.stderr.is_empty());
    }
    // Every method is listed by `restrict --help` and by the contract document.
    let restrict_help = run(&["restrict", "--help"], "").stdout;
    let contract = include_str!("../../../docs/cli.md");
    for name in blossom::Method::ALL
        .iter()
        .map(|m| m.name())
        .chain(["specialised"])
    {
        assert!(
            restrict_help.contains(&format!("\n      {name} ")),
            "restrict --help: {name}"
        );
        assert!(
            contract.contains(&format!("    - `{name}`")),
            "docs/cli.md: {name}"
        );
    }
    assert!(restrict_help
        .contains("bulk             the restriction engine, in the input's own basis (default)"));
    assert!(contract.contains("    - `bulk` (default"));
    assert!(!contract.contains("`closed-form` (default)"));
    let help = run(&["--help"], "").stdout;
    assert!(
        help.contains("blossom verify [--json] [--verbose]"),
        "{help}"
    );
    for sub in ["check", "figures", "expand"] {
        let r = run(&[sub, "--help"], "");
        assert_eq!(r.code, 0, "{sub}");
        assert!(r.stdout.contains(&format!("Usage: blossom {sub}")), "{sub}");
    }
    // `blossom` and `blossom verify` print the same report and exit 0 or 1.
    let plain = run(&[], "");
    let verify = run(&["verify"], "");
    assert!(plain.code == 0 || plain.code == 1);
    assert_eq!(plain.code, verify.code);
    assert_eq!(plain.stdout, verify.stdout);
}

// ---------------------------------------------------------------------------------------
// (c) Every method and both arithmetics agree on random jobs.

/// A tiny deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `lo..=hi`.
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }

    /// A small number in one of the accepted spellings.
    fn number(&mut self) -> Value {
        let p = self.range(-9, 9);
        match self.range(0, 3) {
            0 => json!(p),
            1 => json!(format!("{p}/{}", self.range(1, 7))),
            2 => json!(format!("{p}.{}", self.range(0, 99))),
            _ => json!(p.to_string()),
        }
    }

    fn point(&mut self, dim: usize) -> Value {
        Value::Array((0..dim).map(|_| self.number()).collect())
    }

    fn grid(&mut self, n: usize, m: usize, dim: usize) -> Value {
        Value::Array(
            (0..=n)
                .map(|_| Value::Array((0..=m).map(|_| self.point(dim)).collect()))
                .collect(),
        )
    }

    fn job(&mut self, kind: &str) -> Value {
        let dim = self.range(1, 3) as usize;
        match kind {
            "curve" => {
                let n = self.range(0, 6) as usize;
                json!({"kind": "curve",
                       "coefficients": (0..=n).map(|_| self.point(dim)).collect::<Vec<_>>(),
                       "interval": [self.number(), self.number()]})
            }
            "tensor" => {
                let (n, m) = (self.range(0, 3) as usize, self.range(0, 3) as usize);
                json!({"kind": "tensor", "coefficients": self.grid(n, m, dim),
                       "rectangle": (0..4).map(|_| self.number()).collect::<Vec<_>>()})
            }
            _ => {
                let (n, m) = (self.range(0, 3) as usize, self.range(0, 2) as usize);
                json!({"kind": "triangle", "coefficients": self.grid(n, m, dim),
                       "triangle": (0..3).map(|_| self.point(2)).collect::<Vec<_>>()})
            }
        }
    }
}

/// Every `--method`; the answer without one (the default, `bulk`) is the reference.
const METHODS: [&str; 7] = [
    "bulk",
    "taylor-shift",
    "closed-form",
    "definition",
    "pyramid",
    "polarisation",
    "specialised",
];

/// Whether the binary carries a specialised evaluator for the degree of `job` (spec/cli.md:
/// curves 1..=16, tensors and triangles with n, m <= 5 and 4, (0, 0) excepted). A binary
/// built without the feature `carried-grid` carries none.
fn carried(job: &Value) -> bool {
    if !cfg!(feature = "carried-grid") {
        return false;
    }
    let coefficients = job["coefficients"].as_array().expect("coefficients");
    let n = coefficients.len() - 1;
    let m = || coefficients[0].as_array().expect("a grid row").len() - 1;
    match job["kind"].as_str() {
        Some("curve") => (1..=16).contains(&n),
        Some("tensor") => n <= 5 && m() <= 5 && (n, m()) != (0, 0),
        _ => n <= 4 && m() <= 4 && (n, m()) != (0, 0),
    }
}

/// Every number of an answer, in order, with the shape around them replaced by a skeleton.
fn numbers(value: &Value, out: &mut Vec<Value>) {
    match value {
        Value::Array(items) => items.iter().for_each(|v| numbers(v, out)),
        Value::Object(map) => {
            if let Some(p) = map.get("point") {
                numbers(p, out);
            } else {
                map.values().for_each(|v| numbers(v, out));
            }
        }
        other => out.push(other.clone()),
    }
}

fn check_random_jobs(kind: &str, seed: u64, count: usize) {
    let mut rng = Rng(seed);
    for _ in 0..count {
        let job = rng.job(kind);
        let reference = answer_text(&[], &job);
        let methods: Vec<&str> = METHODS
            .into_iter()
            .filter(|&m| m != "specialised" || carried(&job))
            .collect();
        if !carried(&job) {
            assert_error(
                &["restrict", "--method", "specialised"],
                &job.to_string(),
                "--method",
            );
        }
        for &method in &methods {
            assert_eq!(
                answer_text(&["--method", method], &job),
                reference,
                "method {method} on {job}"
            );
        }
        let exact: Value = serde_json::from_str(&reference).expect("JSON");
        assert_eq!(exact["kind"], json!(kind));
        let mut exact_numbers = Vec::new();
        numbers(&exact["control_points"], &mut exact_numbers);
        let exact_f64: Vec<f64> = exact_numbers
            .iter()
            .map(|v| {
                let text = v.as_str().expect("exact numbers are strings");
                blossom_cli::number::parse_f64(text).expect("an exact number")
            })
            .collect();
        let scale = exact_f64.iter().fold(1.0f64, |s, x| s.max(x.abs()));
        for &method in &methods {
            let float = answer(&["--arithmetic", "f64", "--method", method], &job);
            assert_eq!(float["kind"], exact["kind"]);
            assert_eq!(float["degree"], exact["degree"]);
            let mut float_numbers = Vec::new();
            numbers(&float["control_points"], &mut float_numbers);
            assert_eq!(float_numbers.len(), exact_f64.len());
            for (f, e) in float_numbers.iter().zip(&exact_f64) {
                let f = f.as_f64().expect("f64 numbers are JSON numbers");
                assert!(
                    (f - e).abs() <= 1e-9 * scale,
                    "method {method} on {job}: f64 {f} against exact {e}"
                );
            }
        }
    }
}

#[test]
fn random_curves_agree() {
    check_random_jobs("curve", 0x9E37_79B9_7F4A_7C15, 8);
}

#[test]
fn random_tensors_agree() {
    check_random_jobs("tensor", 0xD1B5_4A32_D192_ED03, 6);
}

#[test]
fn random_triangles_agree() {
    check_random_jobs("triangle", 0x8CB9_2BA7_2F3D_8DD7, 6);
}
