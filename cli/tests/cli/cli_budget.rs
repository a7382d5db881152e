//! The work budget (`--max-work`, `--max-input`): adversarial inputs of at most a few KB are
//! refused at once with one `error: FIELD: ...` line naming the limit, the flags change the
//! limits, and (an ignored sweep, run on request) every input of up to 10 KB of every job kind,
//! method and arithmetic is answered or refused within 2 s.

use crate::binary::{run_binary, Run};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

/// A refusal takes no computation; this margin only guards against a refusal that came after
/// computing (the slow inputs below ran for 30 to 60 s before the budget).
const REFUSAL_MARGIN: Duration = Duration::from_secs(5);

fn timed(args: &[&str], input: &[u8]) -> (Run, Duration) {
    let mut all = vec!["restrict"];
    all.extend_from_slice(args);
    let start = Instant::now();
    let run = run_binary(&all, input);
    (run, start.elapsed())
}

/// Checks that `job` is refused by the budget within the margin, naming `field`.
fn assert_over_budget(args: &[&str], job: &Value, field: &str) {
    let text = job.to_string();
    assert!(text.len() <= 10_240, "an input of {} bytes", text.len());
    let (run, time) = timed(args, text.as_bytes());
    assert_eq!(
        run.code,
        2,
        "{args:?} {}: accepted: {}",
        short(&text),
        run.stdout
    );
    assert!(run.stdout.is_empty());
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    let expected = format!("error: {field}: the job's estimated work is ");
    assert!(
        run.stderr.starts_with(&expected) && run.stderr.contains("--max-work"),
        "{args:?} {}: {}",
        short(&text),
        run.stderr
    );
    assert!(time < REFUSAL_MARGIN, "{args:?}: refused after {time:?}");
}

fn short(text: &str) -> String {
    text.chars().take(120).collect()
}

fn ones(count: usize) -> Vec<Value> {
    vec![json!([1]); count]
}

/// The inputs of the issue, and more of the same kind: huge exponents, degrees, pieces,
/// parameters and dimensions.
#[test]
fn adversarial_inputs_are_refused_at_once() {
    let exact = ["--arithmetic", "exact"];
    let f64 = ["--arithmetic", "f64"];
    // Huge decimal exponents: 332,000-bit numbers.
    let huge = json!({"kind": "curve", "coefficients": [[1], [1], [1]], "interval": ["1e100000", "1e-100000"]});
    for method in [
        "bulk",
        "closed-form",
        "definition",
        "pyramid",
        "polarisation",
        "taylor-shift",
    ] {
        assert_over_budget(&["--method", method], &huge, "interval");
    }
    assert_over_budget(
        &exact,
        &json!({"kind": "elevate", "control_points": [["1e100000"], ["1e100000"], ["1e100000"], ["1e100000"], ["1e100000"]], "to_degree": 200}),
        "control_points",
    );
    // A 16 x 16 triangle under the closed form, and tensors of high degree.
    let grid16: Vec<Vec<Value>> = vec![vec![json!([1, 2]); 16]; 16];
    let triangle =
        json!({"kind": "triangle", "coefficients": grid16, "triangle": [[0, 0], [1, 0], [0, 1]]});
    for args in [&exact, &f64] {
        assert_over_budget(args, &triangle, "coefficients");
    }
    assert_over_budget(
        &["--method", "polarisation"],
        &json!({"kind": "tensor", "coefficients": vec![vec![json!([1]); 12]; 12], "rectangle": [0, 1, 0, 1]}),
        "coefficients",
    );
    // High degrees: 2000 coefficients.
    for (method, arithmetic) in [
        ("definition", "exact"),
        ("polarisation", "f64"),
        ("pyramid", "exact"),
    ] {
        assert_over_budget(
            &["--method", method, "--arithmetic", arithmetic],
            &json!({"kind": "curve", "coefficients": ones(2000), "interval": ["1/3", "2/7"]}),
            "coefficients",
        );
    }
    assert_over_budget(
        &exact,
        &json!({"kind": "bezier-curve", "control_points": ones(2000), "interval": ["1/3", "2/7"]}),
        "control_points",
    );
    // A B-spline of degree 200 with 4 pieces (202 bytes in the version).
    let pieces: Vec<Value> = (0..4)
        .map(|i| json!({"interval": [i, i + 1], "coefficients": [[1], [2], [3]]}))
        .collect();
    assert_over_budget(
        &f64,
        &json!({"kind": "bspline", "degree": 200, "pieces": pieces}),
        "pieces",
    );
    // Many parameters at a high degree.
    let knots: Vec<Value> = (0..402).map(|i| json!(i)).collect();
    let at: Vec<Value> = (0..500)
        .map(|i| json!(format!("{}/7", 200 * 7 + i % 7)))
        .collect();
    assert_over_budget(
        &exact,
        &json!({"kind": "bspline-eval", "degree": 200, "knots": knots, "control_points": ones(201), "at": at}),
        "at",
    );
    // A huge dimension: 13 points of 300 coordinates, a curve of degree 12 under polarisation.
    let wide: Vec<Value> = (0..13).map(|_| json!(vec![json!(1); 300])).collect();
    assert_over_budget(
        &["--method", "polarisation"],
        &json!({"kind": "curve", "coefficients": wide, "interval": ["1/3", "2/7"]}),
        "coefficients",
    );
    // Rational jobs of high degree, and reduction from degree 200.
    assert_over_budget(
        &f64,
        &json!({"kind": "rational-curve", "numerator": ones(201), "denominator": [1], "interval": [0, 1]}),
        "numerator",
    );
    assert_over_budget(
        &exact,
        &json!({"kind": "rational-tensor", "numerator": vec![vec![json!([1]); 15]; 15], "denominator": [[1]], "rectangle": [0, 1, 0, 1]}),
        "numerator",
    );
    let points: Vec<Value> = (0..201).map(|i| json!([format!("{i}/7")])).collect();
    assert_over_budget(
        &exact,
        &json!({"kind": "reduce", "control_points": points, "to_degree": 199, "method": "least-squares"}),
        "control_points",
    );
}

#[test]
fn the_flags_move_the_limits() {
    let job = json!({"kind": "curve", "coefficients": [[1], [2]], "interval": [0, 1]});
    assert_over_budget(&["--max-work", "0"], &job, "coefficients");
    let (run, _) = timed(&["--max-work", "1e12"], job.to_string().as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    // The input limit: one byte too many is refused, never truncated.
    let text = job.to_string();
    let limit = text.len().to_string();
    let (run, _) = timed(&["--max-input", &limit], text.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let smaller = (text.len() - 1).to_string();
    let (run, _) = timed(&["--max-input", &smaller], text.as_bytes());
    assert_eq!(run.code, 2);
    assert!(
        run.stderr
            .starts_with("error: input: the input is longer than the limit of"),
        "{}",
        run.stderr
    );
    // The default input limit: 2 MiB of spaces on standard input.
    let (run, _) = timed(&[], &vec![b' '; 2 << 20]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("1048576 bytes"), "{}", run.stderr);
    // Bad values name the flag.
    for (flag, value) in [
        ("--max-work", "-1"),
        ("--max-work", "many"),
        ("--max-work", "1.5"),
        ("--max-input", "1e400"),
        ("--max-input", ""),
    ] {
        let (run, _) = timed(&[flag, value], text.as_bytes());
        assert_eq!(run.code, 2, "{flag} {value:?}");
        assert!(
            run.stderr.starts_with(&format!("error: {flag}: ")),
            "{flag} {value:?}: {}",
            run.stderr
        );
    }
}

/// The largest input of at most 10 KB of each shape for a size `n` (or `None` when the job of
/// size `n` is over 10 KB).
fn sweep_job(kind: &str, n: usize, long_numbers: bool) -> Value {
    let x = |k: usize| -> Value {
        if long_numbers {
            json!(format!("{}/{}", "7".repeat(40 + k % 3), "3".repeat(38)))
        } else {
            json!(format!("{}/{}", (k * 37) % 19 + 1, (k * 11) % 7 + 1))
        }
    };
    let point = |k: usize| json!([x(k), x(k + 1)]);
    let list = |count: usize| -> Vec<Value> { (0..count).map(point).collect() };
    let grid = |rows: usize, columns: usize| -> Vec<Vec<Value>> {
        (0..rows)
            .map(|i| (0..columns).map(|j| point(i * columns + j)).collect())
            .collect()
    };
    let interval = json!([x(3), x(5)]);
    match kind {
        "curve" => json!({"kind": "curve", "coefficients": list(n + 1), "interval": interval}),
        "bezier-curve" => {
            json!({"kind": "bezier-curve", "control_points": list(n + 1), "interval": interval})
        }
        "derivative" => {
            json!({"kind": "derivative", "control_points": list(n + 1), "order": n / 2})
        }
        "elevate" => json!({"kind": "elevate", "control_points": list(4), "to_degree": n.min(200)}),
        "reduce" => {
            json!({"kind": "reduce", "control_points": list(n.min(200) + 1), "to_degree": n.min(200) / 2, "method": "least-squares"})
        }
        "tensor" => {
            json!({"kind": "tensor", "coefficients": grid(n + 1, n + 1), "rectangle": [x(1), x(2), x(3), x(4)]})
        }
        "bezier-tensor" => {
            json!({"kind": "bezier-tensor", "control_points": grid(n + 1, n + 1), "rectangle": [x(1), x(2), x(3), x(4)]})
        }
        "triangle" => {
            json!({"kind": "triangle", "coefficients": grid(n + 1, n + 1), "triangle": [[x(1), x(2)], [x(3), x(4)], [x(5), x(6)]]})
        }
        "bezier-triangle" => {
            let entries: Vec<Value> = (0..=n)
                .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
                .map(|(i, j)| json!({"a": i, "b": j, "c": n - i - j, "point": point(i + j)}))
                .collect();
            json!({"kind": "bezier-triangle", "control_points": entries, "triangle": [["1/2", "1/4", "1/4"], ["1/3", "1/3", "1/3"], [0, 1, 0]]})
        }
        "bspline" => {
            let p = n.min(200);
            let pieces: Vec<Value> = (0..3)
                .map(|i| json!({"interval": [i, i + 1], "coefficients": list(p + 1)}))
                .collect();
            json!({"kind": "bspline", "degree": p, "pieces": pieces})
        }
        "bspline-eval" => {
            let p = n.min(200);
            let knots: Vec<Value> = (0..2 * p + 2).map(|i| json!(i)).collect();
            let at: Vec<Value> = (0..n)
                .map(|i| json!(format!("{}/3", 3 * p + i % 3)))
                .collect();
            json!({"kind": "bspline-eval", "degree": p, "knots": knots, "control_points": list(p + 1), "at": at})
        }
        "rational-curve" => {
            json!({"kind": "rational-curve", "numerator": list(n + 1), "denominator": [1, x(2)], "interval": [0, "1/2"]})
        }
        "rational-tensor" => {
            json!({"kind": "rational-tensor", "numerator": grid(n + 1, n + 1), "denominator": [[1]], "rectangle": [0, "1/2", 0, "1/3"]})
        }
        "rational-triangle" => {
            json!({"kind": "rational-triangle", "numerator": grid(n + 1, n + 1), "denominator": [[1]], "triangle": [[0, 0], [1, 0], [0, 1]]})
        }
        other => panic!("no sweep for {other}"),
    }
}

/// Every job kind, method and arithmetic at every size whose input fits in 10 KB: answered or
/// refused within 2 s (asserted with a margin for a loaded machine), the slowest printed.
/// Run on request: `cargo test --release -p blossom-cli --test cli budget_sweep -- --ignored --nocapture`.
#[test]
#[ignore = "a sweep of a few minutes; run on request"]
fn budget_sweep() {
    let kinds = [
        "curve",
        "bezier-curve",
        "derivative",
        "elevate",
        "reduce",
        "tensor",
        "bezier-tensor",
        "triangle",
        "bezier-triangle",
        "bspline",
        "bspline-eval",
        "rational-curve",
        "rational-tensor",
        "rational-triangle",
    ];
    let methods = blossom_cli::jobs::args::METHOD_NAMES.map(|(name, _)| name);
    for kind in kinds {
        let mut slowest = (Duration::ZERO, String::new());
        for method in methods {
            for arithmetic in ["exact", "f64"] {
                for long_numbers in [false, true] {
                    let mut n = 1;
                    loop {
                        let text = sweep_job(kind, n, long_numbers).to_string();
                        if text.len() > 10_240 {
                            break;
                        }
                        let (run, time) = timed(
                            &["--method", method, "--arithmetic", arithmetic],
                            text.as_bytes(),
                        );
                        assert!(
                            run.code == 0 || run.code == 2,
                            "{kind} {method} {arithmetic} n={n}: {}",
                            run.stderr
                        );
                        assert!(
                            time < Duration::from_secs(6),
                            "{kind} {method} {arithmetic} n={n} long={long_numbers}: {time:?}"
                        );
                        if time > slowest.0 {
                            slowest = (time, format!("{method} {arithmetic} n={n} long={long_numbers} exit {} ({} bytes)", run.code, text.len()));
                        }
                        // Refused by the budget, or a size the job caps (degrees at 200).
                        if (run.code == 2 && run.stderr.contains("estimated work")) || n > 4000 {
                            break;
                        }
                        n = (n + 1).max(n * 5 / 4);
                    }
                }
            }
        }
        println!(
            "{kind:18} slowest {:>8.3} s: {}",
            slowest.0.as_secs_f64(),
            slowest.1
        );
    }
}
