//! The spline, rational and degree-change jobs of `blossom restrict`, driven as a process
//! exactly as `cli.md` describes: hand-checked answers, bad input of every class (exit 2, one
//! `error: FIELD: ...` line, empty stdout), and random jobs checked against each other.

use crate::binary::{restrict_answer, restrict_error};
use crate::common::Rng;
use serde_json::{json, Value};

fn answer_with(args: &[&str], job: &Value) -> Value {
    restrict_answer(args, job)
}

fn answer(job: &Value) -> Value {
    answer_with(&[], job)
}

fn error_with(args: &[&str], job: &Value) -> String {
    restrict_error(args, job)
}

fn error(job: &Value) -> String {
    error_with(&[], job)
}

#[test]
fn hand_checked_answers() {
    let bspline = answer(&json!({"kind": "bspline", "degree": 3, "pieces": [
        {"interval": [0, 1], "coefficients": [[0, 0], [1, 0], [0, 1]]},
        {"interval": [1, 2], "coefficients": [[0, 0], [1, 0], [0, 0], [0, 1]]},
        {"interval": [2, 3], "coefficients": [[0, -16], [1, 12]]}]}));
    let eval = answer(
        &json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
        "control_points": [[1, 1], [2, 3], [4, 3], [3, 1]], "at": ["0.8", "0,8".replace(',', "."), 0, 2]}),
    );
    assert_eq!(eval["points"][0], json!(["13/5", "73/25"]));
    let arc = answer(
        &json!({"kind": "rational-curve", "numerator": [[1, 0], [0, 2], [-1, 0]],
        "denominator": [1, 0, 1], "interval": [0, 1], "degree": 4}),
    );
    assert_eq!(arc["weights"], json!(["1", "1", "7/6", "3/2", "2"]));
    let quadratic = answer(
        &json!({"kind": "rational-curve", "numerator": [[1, 0], [0, 2], [-1, 0]],
        "denominator": [1, 0, 1], "interval": [0, 1]}),
    );
    assert_eq!(quadratic["degree"], json!(2));
    let elevate = answer(&json!({"kind": "elevate", "control_points": [[0], [3]], "to_degree": 3}));
    assert_eq!(
        elevate["control_points"],
        json!([["0"], ["1"], ["2"], ["3"]])
    );
    let bezier = answer(
        &json!({"kind": "bezier-curve", "control_points": [[0, 0], [1, 2], [3, 1]], "interval": ["1/2", 2]}),
    );
    assert_eq!(bezier["control_points"][0], json!(["5/4", "5/4"]));
    let reduce: Vec<Value> = ["interpolating", "least-squares", "least-squares-endpoints"]
        .iter()
        .map(|m| answer(&json!({"kind": "reduce", "control_points": [[0], [1], [0]], "to_degree": 1, "method": m})))
        .collect();
    // 2t(1 - t): interpolating and constrained give the zero line (error 4/30), least squares
    // the constant 1/3 (error 1/45).
    assert_eq!(reduce[0]["l2_error"], json!("2/15"));
    assert_eq!(reduce[1]["control_points"], json!([["1/3"], ["1/3"]]));
    assert_eq!(reduce[1]["l2_error"], json!("1/45"));
    assert_eq!(reduce[2]["l2_error"], json!("2/15"));
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("cli_spline_jobs_answers", [bspline, eval, arc, quadratic, elevate, bezier, reduce[0].clone(), reduce[1].clone(), reduce[2].clone()]
            .iter().map(|v| v.to_string()).collect::<Vec<_>>().join("\n"));
    });
}

#[test]
fn bad_input_is_refused_with_the_field() {
    let pts = json!([[1, 1], [2, 3], [4, 3], [3, 1]]);
    let cases: Vec<(Value, &str)> = vec![
        // Bad knot vectors.
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 2, 1, 2, 2], "control_points": pts, "at": [1]}), "error: knots[4]: knots must be non-decreasing"),
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 0, 2, 2, 2], "control_points": pts, "at": [1]}), "error: knots[3]: the knot 0 has multiplicity above p + 1 = 3"),
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, 2], "control_points": pts, "at": [1]}), "error: knots: 4 de Boor points of degree 2 need m + p + 1 = 7 knots, found 6"),
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, "x", 2], "control_points": pts, "at": [1]}), "error: knots[5]: "),
        (json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 1, 1, 2], "control_points": [[0], [1]], "at": [1]}), "error: knots: the domain [t_2, t_3] = [1, 1] is empty"),
        // Parameters outside the knots.
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": pts, "at": [1, "-1/2"]}), "error: at[1]: the parameter -1/2 is outside the domain [0, 2]"),
        (json!({"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": pts, "at": ["2.001"]}), "error: at[0]: the parameter 2001/1000 is outside"),
        // Zero weights, empty or zero denominators.
        (json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [0, 1], "interval": [0, 1]}), "error: denominator: weight w_0 is zero"),
        (json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [-1, 1], "interval": [0, 1], "degree": 3}), "error: denominator: weight w_3 is zero"),
        (json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [0, 0], "interval": [0, 1]}), "error: denominator: the denominator is the zero polynomial"),
        (json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [], "interval": [0, 1]}), "error: denominator: expected at least one coefficient"),
        (json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [1, 1], "interval": [0, 1], "degree": 0}), "error: degree: expected a degree >= 1"),
        // Target degrees out of range.
        (json!({"kind": "elevate", "control_points": [[0], [1], [2]], "to_degree": 1}), "error: to_degree: elevation needs to_degree >= 2"),
        (json!({"kind": "elevate", "control_points": [[0], [1]], "to_degree": -1}), "error: to_degree: expected a non-negative integer"),
        (json!({"kind": "elevate", "control_points": [[0], [1]], "to_degree": 100000}), "error: to_degree: expected a degree of at most 200"),
        (json!({"kind": "elevate", "control_points": [[0], [1]], "to_degree": 2.5}), "error: to_degree: expected a non-negative integer"),
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 2, "method": "least-squares"}), "error: to_degree: reduction needs to_degree < 2"),
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 0, "method": "interpolating"}), "error: to_degree: the interpolating reduction needs to_degree >= 1"),
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 0, "method": "least-squares-endpoints"}), "error: to_degree: the least-squares-endpoints reduction needs to_degree >= 1"),
        // Unknown or missing methods.
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 1, "method": "chebyshev"}), "error: method: unknown method \"chebyshev\""),
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 1}), "error: method: missing field"),
        (json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 1, "method": 3}), "error: method: expected a string"),
        // Pieces with gaps, overlaps, empty intervals, too high degree, ragged points.
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0]]}, {"interval": [2, 3], "coefficients": [[0]]}]}), "error: pieces[1].interval: starts at 2, which leaves a gap after the previous piece ending at 1"),
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 2], "coefficients": [[0]]}, {"interval": [1, 3], "coefficients": [[0]]}]}), "error: pieces[1].interval: starts at 1, which overlaps the previous piece ending at 2"),
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [1, 1], "coefficients": [[0]]}]}), "error: pieces[0].interval: expected e_0 < e_1, found [1, 1]"),
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0], [0], [1]]}]}), "error: pieces[0].coefficients[2]: the piece has degree above p = 1"),
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0]]}, {"interval": [1, 2], "coefficients": [[0, 1]]}]}), "error: pieces[1].coefficients[0]: expected 1 coordinate, found 2"),
        (json!({"kind": "bspline", "degree": 1, "pieces": []}), "error: pieces: expected at least one piece"),
        (json!({"kind": "bspline", "degree": 1, "pieces": [{"coefficients": [[0]]}]}), "error: pieces[0].interval: missing field"),
        (json!({"kind": "bspline", "pieces": [{"interval": [0, 1], "coefficients": [[0]]}]}), "error: degree: missing field"),
        // Shapes and numbers.
        (json!({"kind": "bezier-curve", "control_points": [], "interval": [0, 1]}), "error: control_points: expected at least one point"),
        (json!({"kind": "bezier-curve", "control_points": [[0, 1], [2]], "interval": [0, 1]}), "error: control_points[1]: expected 2 coordinates, found 1"),
        (json!({"kind": "bezier-curve", "control_points": [[0]], "interval": [0, "1/0"]}), "error: interval[1]: "),
        (json!({"kind": "elevate", "control_points": [["0.5"], [0.5]], "to_degree": 2}), "error: control_points[1][0]: "),
    ];
    for (job, want) in cases {
        let got = error(&job);
        assert!(
            got.starts_with(want),
            "job {job}\n  got  {got}\n  want {want}"
        );
    }
}

/// `Value` strings to exact rationals.
fn q(v: &Value) -> blossom::Rational {
    v.as_str().expect("a string").parse().expect("a fraction")
}

fn num_json(x: &blossom::Rational) -> Value {
    Value::String(x.to_string())
}

#[test]
fn random_jobs_agree_across_algorithms() {
    let mut rng = Rng(80);
    for round in 0..4 {
        // bezier-curve: every method gives the same answer, and f64 follows.
        let n = 1 + round;
        let pts: Vec<Value> = (0..=n)
            .map(|_| json!([num_json(&rng.rational()), num_json(&rng.rational())]))
            .collect();
        let job = json!({"kind": "bezier-curve", "control_points": pts, "interval": [num_json(&rng.rational()), num_json(&rng.rational())]});
        let exact = answer(&job);
        // The answer without --method is bulk's: every other method against it.
        for m in [
            "taylor-shift",
            "closed-form",
            "definition",
            "pyramid",
            "polarisation",
        ] {
            assert_eq!(answer_with(&["--method", m], &job), exact, "{m}");
        }
        let float = answer_with(&["--arithmetic", "f64"], &job);
        for (e, f) in exact["control_points"]
            .as_array()
            .unwrap()
            .iter()
            .zip(float["control_points"].as_array().unwrap())
        {
            for (x, y) in e.as_array().unwrap().iter().zip(f.as_array().unwrap()) {
                let (x, y) = (blossom::rational_to_f64(&q(x)), y.as_f64().unwrap());
                assert!((x - y).abs() <= 1e-9 * (1.0 + x.abs()), "{x} vs {y}");
            }
        }
        // elevate then reduce (every method) gives the curve back, with zero error.
        let elevated =
            answer(&json!({"kind": "elevate", "control_points": pts, "to_degree": n + 2}));
        for m in ["interpolating", "least-squares", "least-squares-endpoints"] {
            let back = answer(
                &json!({"kind": "reduce", "control_points": elevated["control_points"], "to_degree": n, "method": m}),
            );
            assert_eq!(back["l2_error"], json!("0"), "{m}");
            let want: Vec<Value> = pts
                .iter()
                .map(|p| {
                    json!(p
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|x| num_json(&q(x)))
                        .collect::<Vec<_>>())
                })
                .collect();
            assert_eq!(back["control_points"], json!(want), "{m}");
        }
        // bspline then bspline-eval: the B-spline equals each piece at its start and middle.
        let p = 1 + round % 3;
        let mut pieces = Vec::new();
        let mut at = Vec::new();
        let mut want = Vec::new();
        for k in 0..3i64 {
            let c = rng.curve(p, 2);
            let (a, b) = (
                blossom::Rational::from_integer(k.into()),
                blossom::Rational::from_integer((k + 1).into()),
            );
            let mid = (&a + &b) / blossom::Rational::from_integer(2.into());
            for t in [a.clone(), mid] {
                at.push(num_json(&t));
                want.push(json!(c.eval(&t).iter().map(num_json).collect::<Vec<_>>()));
            }
            let coefficients: Vec<Value> = c
                .coefficients()
                .iter()
                .map(|pt| json!(pt.iter().map(num_json).collect::<Vec<_>>()))
                .collect();
            pieces.push(
                json!({"interval": [num_json(&a), num_json(&b)], "coefficients": coefficients}),
            );
        }
        let bs = answer(&json!({"kind": "bspline", "degree": p, "pieces": pieces}));
        let ev = answer(
            &json!({"kind": "bspline-eval", "degree": p, "knots": bs["knots"], "control_points": bs["control_points"], "at": at}),
        );
        assert_eq!(ev["points"], json!(want), "p = {p}");
    }
}

fn as_f64(v: &Value) -> f64 {
    match v {
        Value::String(_) => blossom::rational_to_f64(&q(v)),
        _ => v.as_f64().expect("a number"),
    }
}

/// Every number of `float` within a relative 1e-12 of the exact number at the same place.
fn close(exact: &Value, float: &Value) {
    match (exact, float) {
        (Value::Array(e), Value::Array(f)) => {
            assert_eq!(e.len(), f.len(), "{exact} vs {float}");
            e.iter().zip(f).for_each(|(x, y)| close(x, y));
        }
        (Value::Object(e), Value::Object(f)) => {
            // An f64 answer has one more field, its "error_bound".
            let extra =
                usize::from(f.contains_key("error_bound") && !e.contains_key("error_bound"));
            assert_eq!(e.len() + extra, f.len(), "{exact} vs {float}");
            for (k, x) in e {
                close(x, &f[k]);
            }
        }
        (Value::String(_), Value::Number(_)) => {
            let (x, y) = (as_f64(exact), as_f64(float));
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(1.0),
                "{exact} vs {float}"
            );
        }
        _ => assert_eq!(exact, float),
    }
}

#[test]
fn f64_decisions_are_exact() {
    // C^1 at the breakpoint 1/3 (not a double): u^2 on [0, 1/3], then its tangent line
    // 2u/3 - 1/9 on [1/3, 1]. Knot 1/3 has multiplicity 2 - 1 = 1 in both arithmetics.
    let job = json!({"kind": "bspline", "degree": 2, "pieces": [
        {"interval": [0, "1/3"], "coefficients": [[0], [0], [1]]},
        {"interval": ["1/3", 1], "coefficients": [["-1/9"], ["2/3"]]}]});
    let exact = answer(&job);
    assert_eq!(exact["knots"], json!(["0", "0", "0", "1/3", "1", "1", "1"]));
    let float = answer_with(&["--arithmetic", "f64"], &job);
    close(&exact, &float);
    // The same with JSON decimals, read as the decimals written: breakpoint 0.1, C^0.
    let decimals = json!({"kind": "bspline", "degree": 1, "pieces": [
        {"interval": [0, 0.1], "coefficients": [[0], [1]]},
        {"interval": [0.1, 0.3], "coefficients": [[0.2], [-1]]}]});
    let float = answer_with(&["--arithmetic", "f64"], &decimals);
    assert_eq!(float["knots"], json!([0.0, 0.0, 0.1, 0.3, 0.3]));
    assert_eq!(float["control_points"], json!([[0.0], [0.1], [-0.1]]));
    // An interior weight that is exactly zero although no input is a double:
    // w = 1 + t^2 on [-1/3, 3] has w_1 = 1 + (-1/3)(3) = 0.
    let zero = json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [1, 0, 1],
        "interval": ["-1/3", 3]});
    for arithmetic in ["exact", "f64"] {
        let e = error_with(&["--arithmetic", arithmetic], &zero);
        assert!(
            e.starts_with("error: denominator: weight w_1 is zero"),
            "{arithmetic}: {e}"
        );
    }
    // A weight that is not zero exactly but underflows in f64 is refused there (its rounded
    // control point would be meaningless), and answered exactly: w(t) = 1e-200 t on
    // [1e-200, 2e-200] has weights 1e-400 and 2e-400.
    let tiny = json!({"kind": "rational-curve", "numerator": [[1]],
        "denominator": [0, "1e-200"], "interval": ["1e-200", "2e-200"]});
    let e = error_with(&["--arithmetic", "f64"], &tiny);
    assert!(
        e.starts_with("error: weights[0]: the weight is not zero but rounds to zero"),
        "{e}"
    );
    let weight = format!("1/1{}", "0".repeat(400));
    assert_eq!(answer(&tiny)["weights"][0], json!(weight));
    // A number whose nearest double is zero is zero under f64, as in every other job: the
    // weight 1e-330 is then zero (and exactly 10^-330 under exact).
    let underflow = json!({"kind": "rational-curve", "numerator": [["1e-300"]],
        "denominator": ["1e-330"], "interval": [0, 1]});
    let e = error_with(&["--arithmetic", "f64"], &underflow);
    assert!(e.starts_with("error: denominator: "), "{e}");
    assert!(e.contains("zero"), "{e}");
    assert_eq!(
        answer(&underflow)["weights"],
        json!([format!("1/1{}", "0".repeat(330))])
    );
    // Out-of-range doubles are refused as in every other f64 job.
    let big = json!({"kind": "bspline", "degree": 0, "pieces": [
        {"interval": [0, "1e400"], "coefficients": [[0]]}]});
    let e = error_with(&["--arithmetic", "f64"], &big);
    assert!(e.starts_with("error: pieces[0].interval[1]: "), "{e}");
}

#[test]
fn more_bad_input() {
    let cases: Vec<(Value, &str)> = vec![
        (
            json!({"kind": "bspline-eval", "degree": 3, "knots": [0, 0, 0, 1, 1, 1], "control_points": [[0], [1]], "at": [0]}),
            "error: control_points: a B-spline of degree 3 needs at least p + 1 = 4 de Boor points",
        ),
        (
            json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": 0}),
            "error: at: expected an array of numbers",
        ),
        (
            json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": [null]}),
            "error: at[0]: ",
        ),
        (
            json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]]}),
            "error: at: missing field",
        ),
        (
            json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0]]}, {"interval": [1, "1/2"], "coefficients": [[0]]}]}),
            "error: pieces[1].interval: expected e_0 < e_1",
        ),
        (
            json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0]]}, {"interval": ["-1", 2], "coefficients": [[0]]}]}),
            "error: pieces[1].interval: starts at -1, which overlaps",
        ),
        (
            json!({"kind": "bspline", "degree": 1, "pieces": [3]}),
            "error: pieces[0]: expected an object",
        ),
        (
            json!({"kind": "bspline", "degree": "x", "pieces": []}),
            "error: degree: expected a non-negative integer",
        ),
        (
            json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [1], "interval": [0]}),
            "error: interval: expected 2 numbers, found 1",
        ),
        (
            json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [1, "a"], "interval": [0, 1]}),
            "error: denominator[1]: ",
        ),
        (
            json!({"kind": "rational-curve", "numerator": [[1]], "denominator": [1], "interval": [0, 1], "degree": 201}),
            "error: degree: expected a degree of at most 200",
        ),
        (
            json!({"kind": "reduce", "control_points": [[0], [1], [2]], "to_degree": 1, "method": "Least-Squares"}),
            "error: method: unknown method",
        ),
        (
            json!({"kind": "reduce", "control_points": [[0]], "to_degree": 0, "method": "least-squares"}),
            "error: to_degree: reduction needs to_degree < 0",
        ),
        (
            json!({"kind": "elevate", "control_points": [[0], [1]]}),
            "error: to_degree: missing field",
        ),
        (
            json!({"kind": "bezier-curve", "control_points": [[0], [1]], "interval": [0, 1, 2]}),
            "error: interval: expected 2 numbers, found 3",
        ),
    ];
    for (job, want) in cases {
        for arithmetic in ["exact", "f64"] {
            let e = error_with(&["--arithmetic", arithmetic], &job);
            assert!(
                e.starts_with(want),
                "job {job} ({arithmetic})\n  got  {e}\n  want {want}"
            );
        }
    }
}

#[test]
fn every_method_and_both_arithmetics_agree_on_every_job() {
    let mut rng = Rng(81);
    let s = |rng: &mut Rng| num_json(&rng.rational());
    let jobs = vec![
        json!({"kind": "bezier-curve", "control_points": (0..6).map(|_| json!([s(&mut rng), s(&mut rng)])).collect::<Vec<_>>(), "interval": ["-1/2", "7/3"]}),
        json!({"kind": "bspline", "degree": 2, "pieces": [
            {"interval": [0, 1], "coefficients": [[1, 0], [0, 1], [2, 2]]},
            {"interval": [1, 3], "coefficients": [[3, 3], [0, 0], ["1/2", "1/7"]]}]}),
        json!({"kind": "bspline", "degree": 0, "pieces": [
            {"interval": [0, 1], "coefficients": [[1]]},
            {"interval": [1, 2], "coefficients": [[1]]},
            {"interval": [2, 3], "coefficients": [[2]]}]}),
        json!({"kind": "bspline-eval", "degree": 3, "knots": [0, 1, 2, 3, 4, 5, 6, 7],
            "control_points": [[0, 0], [3, 9], [6, 3], [9, 6]], "at": [3, "7/2", 4]}),
        json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": []}),
        json!({"kind": "rational-curve", "numerator": [[1, 0], [0, 2], [-1, 0]], "denominator": [1, 0, 1], "interval": ["-1/3", "1/2"], "degree": 5}),
        json!({"kind": "elevate", "control_points": (0..5).map(|_| json!([s(&mut rng)])).collect::<Vec<_>>(), "to_degree": 9}),
        json!({"kind": "reduce", "control_points": (0..9).map(|_| json!([s(&mut rng), s(&mut rng)])).collect::<Vec<_>>(), "to_degree": 5, "method": "least-squares"}),
        json!({"kind": "reduce", "control_points": (0..9).map(|_| json!([s(&mut rng)])).collect::<Vec<_>>(), "to_degree": 4, "method": "least-squares-endpoints"}),
        json!({"kind": "reduce", "control_points": (0..9).map(|_| json!([s(&mut rng)])).collect::<Vec<_>>(), "to_degree": 4, "method": "interpolating"}),
    ];
    for job in &jobs {
        let exact = answer(job);
        for m in [
            "bulk",
            "taylor-shift",
            "closed-form",
            "definition",
            "pyramid",
            "polarisation",
        ] {
            assert_eq!(answer_with(&["--method", m], job), exact, "{m}: {job}");
        }
        close(&exact, &answer_with(&["--arithmetic", "f64"], job));
    }
    // Degree 0: equal constants merge, the jump at 2 keeps a knot.
    let merged = answer(&jobs[2]);
    assert_eq!(merged["knots"], json!(["0", "2", "3"]));
    assert_eq!(merged["control_points"], json!([["1"], ["2"]]));
    // The uniform cubic at the ends of its domain [3, 4]: (d1 + 4 d2 + d3) / 6 and
    // (d2 + 4 d3 + d4) / 6.
    let eval = answer(&jobs[3]);
    assert_eq!(eval["points"][0], json!(["3", "13/2"]));
    assert_eq!(eval["points"][2], json!(["6", "9/2"]));
    assert_eq!(answer(&jobs[4])["points"], json!([]));
}

/// `bezier-curve --method specialised` runs the carried Bézier-input evaluators (degrees
/// 1..=16): the same exact answer as de Casteljau's pyramid at every carried degree, f64
/// close to it, and a clear refusal above.
#[cfg(feature = "carried-grid")]
#[test]
fn bezier_curve_specialised_at_every_carried_degree() {
    let mut rng = Rng(4242);
    for n in 1..=16 {
        let pts: Vec<Value> = (0..=n)
            .map(|_| json!([num_json(&rng.rational()), num_json(&rng.rational())]))
            .collect();
        let job = json!({"kind": "bezier-curve", "control_points": pts, "interval": [num_json(&rng.rational()), num_json(&rng.rational())]});
        let exact = answer_with(&["--method", "pyramid"], &job);
        assert_eq!(
            answer_with(&["--method", "specialised"], &job),
            exact,
            "degree {n}"
        );
        let float = answer_with(&["--method", "specialised", "--arithmetic", "f64"], &job);
        assert_eq!(float["degree"], json!(n));
    }
    let pts: Vec<Value> = (0..=17).map(|i| json!([i])).collect();
    let job = json!({"kind": "bezier-curve", "control_points": pts, "interval": [0, 1]});
    let e = error_with(&["--method", "specialised"], &job);
    assert!(
        e.starts_with("error: --method: no specialised evaluator for a Bézier curve of degree 17"),
        "{e}"
    );
}

/// Issue 47 (a friction): a bspline's pieces that do not meet are quoted with their ends as
/// written in the job (`0.1`, not the exact `1/10` the job computes with), under either
/// arithmetic; the numbers of the message that are not the job's stay exact.
#[test]
fn pieces_that_do_not_meet_quote_their_ends_as_written() {
    let piece = |a: Value, b: Value| json!({"interval": [a, b], "coefficients": [[0, 0], [1, 1]]});
    let job = |pieces: Vec<Value>| json!({"kind": "bspline", "degree": 1, "pieces": pieces});
    let f64 = ["--arithmetic", "f64"];
    let gap = job(vec![
        piece(json!(0), json!(0.1)),
        piece(json!(0.2), json!(0.3)),
    ]);
    assert_eq!(
        error_with(&f64, &gap),
        "error: pieces[1].interval: starts at 0.2, which leaves a gap after the previous piece ending at 0.1"
    );
    let overlap = job(vec![
        piece(json!(0), json!(0.1)),
        piece(json!(0.05), json!(0.3)),
    ]);
    assert_eq!(
        error_with(&f64, &overlap),
        "error: pieces[1].interval: starts at 0.05, which overlaps the previous piece ending at 0.1"
    );
    let reversed = job(vec![piece(json!(0.5), json!(0.1))]);
    assert_eq!(
        error_with(&f64, &reversed),
        "error: pieces[0].interval: expected e_0 < e_1, found [0.5, 0.1]"
    );
    // Exact arithmetic: strings as written, fractions included.
    let exact = job(vec![piece(json!("0.50"), json!("1/3"))]);
    assert_eq!(
        error(&exact),
        "error: pieces[0].interval: expected e_0 < e_1, found [0.50, 1/3]"
    );
    let exact_gap = job(vec![
        piece(json!("1/4"), json!("0.5")),
        piece(json!("3/4"), json!(1)),
    ]);
    assert_eq!(
        error(&exact_gap),
        "error: pieces[1].interval: starts at 3/4, which leaves a gap after the previous piece ending at 0.5"
    );
}
