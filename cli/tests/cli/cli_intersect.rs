//! `blossom intersect` driven as a process: answers derived by hand (not by the library), each
//! PARAM checked for correct rounding by an exact sign test written here, and every kind of bad
//! input refused in one line naming the field. The large independent corpus is
//! `intersect_corpus.rs`.

use super::binary::run_binary;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use serde_json::{json, Value};

fn answer(args: &[&str], job: &Value) -> Value {
    let mut all = vec!["intersect"];
    all.extend_from_slice(args);
    let r = run_binary(&all, job.to_string().as_bytes());
    assert_eq!(r.code, 0, "job {job}: {}", r.stderr);
    assert!(r.stderr.is_empty());
    assert_eq!(r.stdout.lines().count(), 1, "{}", r.stdout);
    serde_json::from_str(&r.stdout).expect("JSON")
}

fn error(args: &[&str], job: &str) -> String {
    let mut all = vec!["intersect"];
    all.extend_from_slice(args);
    let r = run_binary(&all, job.as_bytes());
    assert_eq!(r.code, 2, "job {job} was accepted: {}", r.stdout);
    assert!(r.stdout.is_empty());
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(r.stderr.starts_with("error: "), "{}", r.stderr);
    r.stderr.trim_end().to_string()
}

fn q(text: &str) -> BigRational {
    match text.split_once('/') {
        Some((p, d)) => BigRational::new(p.parse().unwrap(), d.parse().unwrap()),
        None => BigRational::from_integer(text.parse().unwrap()),
    }
}

/// p(x) for ascending integer coefficients.
fn eval(p: &[BigInt], x: &BigRational) -> BigRational {
    p.iter().rev().fold(BigRational::zero(), |acc, c| {
        acc * x + BigRational::from_integer(c.clone())
    })
}

/// Checks a PARAM: `value` is the double nearest to the root of `polynomial` in `interval`
/// (the polynomial changes sign, or vanishes, between the two half-way points around
/// `value`, which both lie in the interval or straddle it), and that it is `want` when given.
fn check_param(param: &Value, want: f64) {
    let value = param["value"].as_f64().expect("a number");
    assert_eq!(value.to_bits(), want.to_bits(), "{param}");
    let poly: Vec<BigInt> = param["polynomial"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap().parse().unwrap())
        .collect();
    let (lo, hi) = (
        q(param["interval"][0].as_str().unwrap()),
        q(param["interval"][1].as_str().unwrap()),
    );
    let v = BigRational::from_float(value).unwrap();
    if let Some(exact) = param["exact"].as_str() {
        assert!(eval(&poly, &q(exact)).is_zero(), "{param}");
        assert_eq!((lo.clone(), hi.clone()), (q(exact), q(exact)));
        return;
    }
    assert!(param["exact"].is_null());
    // The half-way points to the neighbouring doubles.
    let below = (v.clone() + BigRational::from_float(f64::from_bits(value.to_bits() - 1)).unwrap())
        / BigRational::from_integer(2.into());
    let above = (v.clone() + BigRational::from_float(f64::from_bits(value.to_bits() + 1)).unwrap())
        / BigRational::from_integer(2.into());
    let (fb, fa) = (eval(&poly, &below), eval(&poly, &above));
    assert!(
        fb.is_zero() || fa.is_zero() || fb.is_positive() != fa.is_positive(),
        "no root of the polynomial within half an ulp of {value}: {param}"
    );
    assert!(lo < hi && lo <= above && below <= hi, "{param}");
}

#[test]
fn roots_with_multiplicities_and_surds() {
    // 1 (1-t)^2 - 2 t (1-t) + t^2 / 3 = (10 t^2 - 12 t + 3) / 3: t = 3/5 -+ sqrt(6)/10.
    let a = answer(
        &[],
        &json!({"kind": "roots", "control_points": ["1", "-1", "1/3"]}),
    );
    assert_eq!(a["identically_zero"], json!(false));
    let roots = a["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 2);
    // The neighbours of 3/5 -+ sqrt(6)/10 rounded: the exact sign test in check_param decides.
    for (r, approx) in roots
        .iter()
        .zip([0.355_051_025_721_682_2, 0.844_948_974_278_317_8])
    {
        assert_eq!(r["multiplicity"], json!(1));
        check_param(&r["t"], approx);
    }
    // (t - 1/2)^3 in Bernstein form: one root of multiplicity 3.
    let a = answer(
        &[],
        &json!({"kind": "roots", "control_points": ["-1/8", "1/8", "-1/8", "1/8"]}),
    );
    assert_eq!(a["roots"].as_array().unwrap().len(), 1);
    assert_eq!(a["roots"][0]["multiplicity"], json!(3));
    assert_eq!(a["roots"][0]["t"]["exact"], json!("1/2"));
    check_param(&a["roots"][0]["t"], 0.5);
    // 2 t (1 - t): both end points.
    let a = answer(&[], &json!({"kind": "roots", "control_points": [0, 1, 0]}));
    let ts: Vec<&Value> = a["roots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| &r["t"]["exact"])
        .collect();
    assert_eq!(ts, [&json!("0"), &json!("1")]);
    // The zero function; a function without zeros.
    let a = answer(&[], &json!({"kind": "roots", "control_points": [0, 0, 0]}));
    assert_eq!(
        (&a["identically_zero"], &a["roots"]),
        (&json!(true), &json!([]))
    );
    let a = answer(&[], &json!({"kind": "roots", "control_points": [1, 2, 1]}));
    assert_eq!(
        (&a["identically_zero"], &a["roots"]),
        (&json!(false), &json!([]))
    );
    // Under f64 the numbers are doubles: 0.1 is the double nearest to 1/10, so the root of
    // (1 - t) 0.1 - t 0.3 (t = 0.1 / 0.4 exactly in those doubles) is that ratio.
    let a = answer(
        &["--arithmetic", "f64"],
        &json!({"kind": "roots", "control_points": [0.1, -0.3]}),
    );
    let exact = BigRational::from_float(0.1).unwrap()
        / (BigRational::from_float(0.1).unwrap() + BigRational::from_float(0.3).unwrap());
    let r = &a["roots"][0]["t"];
    assert_eq!(q(r["exact"].as_str().unwrap()), exact);
}

#[test]
fn two_curves_cross_touch_and_overlap() {
    // The diagonals of the square [0, 2]^2 cross at their midpoints.
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [2, 2]], [[0, 2], [2, 0]]]}),
    );
    assert_eq!(a["points"].as_array().unwrap().len(), 1);
    let p = &a["points"][0];
    assert_eq!(
        (&p["s"]["exact"], &p["t"]["exact"]),
        (&json!("1/2"), &json!("1/2"))
    );
    assert_eq!(
        (&p["tangent"], &p["point"]),
        (&json!(false), &json!([1.0, 1.0]))
    );
    // y = 4 s (1 - s) touches y = 1 at s = 1/2.
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [1, 2], [2, 0]], [[0, 1], [2, 1]]]}),
    );
    assert_eq!(a["points"].as_array().unwrap().len(), 1);
    assert_eq!(a["points"][0]["tangent"], json!(true));
    // Lifted by 1/1000 it misses the line.
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [1, "1999/1000"], [2, 0]], [[0, 1], [2, 1]]]}),
    );
    assert_eq!(a["points"], json!([]));
    // Two segments meeting at an end point of each.
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [1, 0]], [[1, 0], [1, 1]]]}),
    );
    let p = &a["points"][0];
    assert_eq!(
        (&p["s"]["exact"], &p["t"]["exact"]),
        (&json!("1"), &json!("0"))
    );
    // Collinear segments: [1, 2] of the x axis in common, same way and opposite ways.
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [2, 0]], [[1, 0], [3, 0]]]}),
    );
    assert_eq!(a["points"], json!([]));
    let o = &a["overlaps"][0];
    let ends = |v: &Value| [v[0]["exact"].clone(), v[1]["exact"].clone()];
    assert_eq!(ends(&o["s"]), [json!("1/2"), json!("1")]);
    assert_eq!(ends(&o["t"]), [json!("0"), json!("1/2")]);
    let a = answer(
        &[],
        &json!({"kind": "curve-curve", "curves": [[[0, 0], [2, 0]], [[3, 0], [1, 0]]]}),
    );
    let o = &a["overlaps"][0];
    assert_eq!(ends(&o["s"]), [json!("1/2"), json!("1")]);
    assert_eq!(ends(&o["t"]), [json!("1"), json!("1/2")]);
}

#[test]
fn a_cubic_loop_crosses_itself() {
    // Symmetric about x = 1 (x -> 2 - x swaps the control points), so the crossing has
    // s + t = 1 on x = 1: 3 s (1-s)^2 3 + 3 s^2 (1-s) (-1) + 2 s^3 = 1 gives 7 s^2 - 7 s + 1 = 0.
    let a = answer(
        &[],
        &json!({"kind": "self", "curve": [[0, 0], [3, 3], [-1, 3], [2, 0]]}),
    );
    let points = a["points"].as_array().unwrap();
    assert_eq!(points.len(), 1);
    let p = &points[0];
    let s = p["s"]["value"].as_f64().unwrap();
    let t = p["t"]["value"].as_f64().unwrap();
    assert!(s < t && (s + t - 1.0).abs() < 1e-15);
    assert!((7.0 * s * s - 7.0 * s + 1.0).abs() < 1e-14);
    check_param(&p["s"], s);
    check_param(&p["t"], t);
    assert_eq!(p["tangent"], json!(false));
    assert_eq!(p["point"][0], json!(1.0));
    // No loop: a convex arc.
    let a = answer(
        &[],
        &json!({"kind": "self", "curve": [[0, 0], [1, 2], [2, 0]]}),
    );
    assert_eq!((&a["points"], &a["overlaps"]), (&json!([]), &json!([])));
}

#[test]
fn bad_input_names_the_field() {
    let cases = [
        (
            r#"{"kind": "roots", "control_points": []}"#,
            "control_points",
        ),
        (
            r#"{"kind": "roots", "control_points": ["x"]}"#,
            "control_points[0]",
        ),
        (
            r#"{"kind": "roots", "control_points": [0.5]}"#,
            "control_points[0]",
        ),
        (
            r#"{"kind": "roots", "control_point": [1]}"#,
            "control_point",
        ),
        (r#"{"kind": "root", "control_points": [1]}"#, "kind"),
        (r#"{"control_points": [1]}"#, "kind"),
        (r#"{"kind": "self", "curve": [[0, 0]]}"#, "curve"),
        (
            r#"{"kind": "self", "curve": [[0, 0], [1, 1, 1]]}"#,
            "curve[1]",
        ),
        (
            r#"{"kind": "self", "curve": [[0, 0], [1, "1/0"]]}"#,
            "curve[1][1]",
        ),
        (
            r#"{"kind": "curve-curve", "curves": [[[0, 0], [1, 1]]]}"#,
            "curves",
        ),
        (
            r#"{"kind": "curve-curve", "curves": [[[0, 0], [1, 1]], [[0, 1], [1, true]]]}"#,
            "curves[1][1][1]",
        ),
        (r#"[1, 2]"#, "input"),
        (r#"{"kind": "self""#, "input"),
    ];
    for (job, field) in cases {
        let e = error(&[], job);
        assert!(e.starts_with(&format!("error: {field}: ")), "{job}: {e}");
    }
    assert!(error(&[], r#"{"kind": "root", "control_points": [1]}"#)
        .contains("did you mean \"roots\"?"));
    // A curve of degree 45 is over the documented limit of 40.
    let long: Vec<Value> = (0..46).map(|i| json!([i, i * i % 7])).collect();
    let e = error(&[], &json!({"kind": "self", "curve": long}).to_string());
    assert!(
        e.starts_with("error: curve: degree 45 is over the limit of 40"),
        "{e}"
    );
    // Under the degree limit, a loop of degree 30 is refused by the default budget (its
    // estimate, some 7e9 units, is over twice the default 1e9) before computing.
    let loop30: Vec<Value> = (0..31)
        .map(|i| json!([(i * 7) % 11 - 5, (i * i * 3) % 13 - 6]))
        .collect();
    let e = error(&[], &json!({"kind": "self", "curve": loop30}).to_string());
    assert!(
        e.starts_with("error: curve: the job's work is estimated at"),
        "{e}"
    );
    // Options.
    let r = run_binary(&["intersect", "--method", "bulk"], b"{}");
    assert_eq!(r.code, 2);
    assert!(
        r.stderr
            .starts_with("error: --method: unknown option for intersect"),
        "{}",
        r.stderr
    );
    let r = run_binary(&["intersect", "--help"], b"");
    assert_eq!(r.code, 0);
    for word in ["roots", "curve-curve", "self", "--arithmetic"] {
        assert!(r.stdout.contains(word), "{word}");
    }
}

#[test]
fn degree_20_pairs_and_loops_are_answered_and_the_budget_refuses_up_front() {
    // Two degree-20 curves with small random integer coordinates (xorshift): the float
    // filter decides, and the answer comes back within the default budget. Every reported
    // point must be a common point: P(s) and Q(t) evaluated here (Horner on the Bernstein
    // form in f64 at the reported values) agree to rounding.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let mut curve = || -> Vec<[i64; 2]> {
        (0..=20)
            .map(|_| [0, 1].map(|_| (next() % 21) as i64 - 10))
            .collect()
    };
    let (p, qq) = (curve(), curve());
    let job = json!({"kind": "curve-curve", "curves": [p, qq]});
    let floats =
        |c: &[[i64; 2]]| -> Vec<[f64; 2]> { c.iter().map(|xy| xy.map(|v| v as f64)).collect() };
    let (pf, qf) = (floats(&p), floats(&qq));
    let x = answer(&[], &job);
    let points = x["points"].as_array().unwrap();
    assert!(!points.is_empty());
    let at = |c: &[[f64; 2]], t: f64| -> [f64; 2] {
        // de Casteljau in f64.
        let mut level: Vec<[f64; 2]> = c.to_vec();
        while level.len() > 1 {
            level = level
                .windows(2)
                .map(|w| [0, 1].map(|k| (1.0 - t) * w[0][k] + t * w[1][k]))
                .collect();
        }
        level[0]
    };
    for pt in points {
        let (s, t) = (
            pt["s"]["value"].as_f64().unwrap(),
            pt["t"]["value"].as_f64().unwrap(),
        );
        assert!((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t));
        let (a, b) = (at(&pf, s), at(&qf, t));
        for k in 0..2 {
            assert!((a[k] - b[k]).abs() < 1e-9, "{pt}");
            assert!(
                (a[k] - pt["point"][k].as_f64().unwrap()).abs() < 1e-9,
                "{pt}"
            );
        }
    }
    // The degree-20 self-intersection (exact solver) is answered within the default budget
    // (the spec: degree 20 at least), each pair s < t a double point of P.
    let x = answer(&[], &json!({"kind": "self", "curve": p}));
    for pt in x["points"].as_array().unwrap() {
        let (s, t) = (
            pt["s"]["value"].as_f64().unwrap(),
            pt["t"]["value"].as_f64().unwrap(),
        );
        assert!((0.0..=1.0).contains(&s) && s < t && t <= 1.0, "{pt}");
        let (a, b) = (at(&pf, s), at(&pf, t));
        for k in 0..2 {
            assert!((a[k] - b[k]).abs() < 1e-9, "{pt}");
        }
    }
    // The pair and the loop under a small budget are refused before computing, naming the
    // field; so is a curve of degree 41, over the degree limit.
    let e = error(&["--max-work", "1000"], &job.to_string());
    assert!(
        e.starts_with("error: curves: the job's work is estimated at"),
        "{e}"
    );
    let loop_job = json!({"kind": "self", "curve": p}).to_string();
    let e = error(&["--max-work", "1000"], &loop_job);
    assert!(
        e.starts_with("error: curve: the job's work is estimated at"),
        "{e}"
    );
    let long: Vec<[i64; 2]> = p.iter().chain(qq.iter()).copied().collect();
    let e = error(&[], &json!({"kind": "self", "curve": long}).to_string());
    assert!(
        e.starts_with("error: curve: degree 41 is over the limit"),
        "{e}"
    );
}
