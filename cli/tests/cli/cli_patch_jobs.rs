//! The patch, derivative and rational-surface jobs of `blossom restrict` (the last section of
//! `cli.md`), driven as a process: hand-checked answers, every method against every other on
//! random jobs in both arithmetics, checks of the answers by evaluation (corners of a
//! restriction are values of the input, computed here by Horner's rule or de Casteljau, which
//! the restriction does not call), and bad input of every class the jobs add.

use crate::binary::{restrict_answer, restrict_error};
use crate::common::Rng;
use blossom::{Rational, Ring};
use serde_json::{json, Value};

const METHODS: [&str; 7] = [
    "bulk",
    "taylor-shift",
    "closed-form",
    "definition",
    "pyramid",
    "polarisation",
    "specialised",
];

fn answer_with(args: &[&str], job: &Value) -> Value {
    restrict_answer(args, job)
}

fn answer(job: &Value) -> Value {
    answer_with(&[], job)
}

fn error_with(args: &[&str], job: &Value) -> String {
    restrict_error(args, job)
}

fn q(v: &Value) -> Rational {
    v.as_str().expect("a string").parse().expect("a fraction")
}

fn s(x: &Rational) -> Value {
    Value::String(x.to_string())
}

fn point_json(p: &[Rational]) -> Value {
    Value::Array(p.iter().map(s).collect())
}

fn point_of(v: &Value) -> Vec<Rational> {
    v.as_array().expect("a point").iter().map(q).collect()
}

/// Every number of `float` within a relative 1e-9 of the exact number at the same place.
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
            let (x, y) = (blossom::rational_to_f64(&q(exact)), float.as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1.0),
                "{exact} vs {float}"
            );
        }
        _ => assert_eq!(exact, float),
    }
}

/// The answer of `job` under every method, checked equal to the default's, and the f64 answer
/// of every method checked close to it.
fn all_methods_agree(job: &Value) -> Value {
    let exact = answer(job);
    for m in METHODS {
        assert_eq!(answer_with(&["--method", m], job), exact, "{m} on {job}");
        let float = answer_with(&["--method", m, "--arithmetic", "f64"], job);
        close(&exact, &float);
    }
    exact
}

/// A de Casteljau value of the tensor net at (s, t), for the checks.
fn tensor_value(net: &[Vec<Vec<Rational>>], s: &Rational, t: &Rational) -> Vec<Rational> {
    let rows: Vec<Vec<Rational>> = net.iter().map(|row| curve_value(row, t)).collect();
    curve_value(&rows, s)
}

fn curve_value(points: &[Vec<Rational>], t: &Rational) -> Vec<Rational> {
    let mut level = points.to_vec();
    while level.len() > 1 {
        level = level
            .windows(2)
            .map(|w| {
                w[0].iter()
                    .zip(&w[1])
                    .map(|(x, y)| x.add(&t.mul(&y.sub(x))))
                    .collect()
            })
            .collect();
    }
    level.remove(0)
}

#[test]
fn bezier_tensor_restriction_by_every_method() {
    let mut rng = Rng(0x7e5012);
    for (n, m) in [(1, 1), (2, 1), (1, 3), (3, 2), (4, 4), (5, 2)] {
        let net: Vec<Vec<Vec<Rational>>> = (0..=n)
            .map(|_| (0..=m).map(|_| rng.point(2)).collect())
            .collect();
        let rect: Vec<Rational> = (0..4).map(|_| rng.rational()).collect();
        let job = json!({"kind": "bezier-tensor",
            "control_points": net.iter().map(|r| r.iter().map(|p| point_json(p)).collect::<Vec<_>>()).collect::<Vec<_>>(),
            "rectangle": rect.iter().map(s).collect::<Vec<_>>()});
        let got = if (n, m) == (5, 2) {
            // (5, 2) is not carried: every other method, and `specialised` names what is.
            let e = error_with(&["--method", "specialised"], &job);
            assert!(e.starts_with("error: --method: no specialised evaluator for a Bézier tensor-product patch of degree (5, 2)"), "{e}");
            answer(&job)
        } else {
            all_methods_agree(&job)
        };
        assert_eq!(got["degree"], json!([n, m]));
        // The corners of the answer are values of the patch at the rectangle's corners.
        let q_net = got["control_points"].as_array().unwrap();
        for (nu, x) in [(0, &rect[0]), (n, &rect[1])] {
            for (mu, y) in [(0, &rect[2]), (m, &rect[3])] {
                assert_eq!(
                    point_of(&q_net[nu][mu]),
                    tensor_value(&net, x, y),
                    "({n}, {m})"
                );
            }
        }
    }
}

/// The entries of a triangular net in a shuffled order.
fn shuffled_entries(rng: &mut Rng, big_n: usize, points: &[Vec<Rational>]) -> Vec<Value> {
    let mut entries: Vec<Value> = Vec::new();
    let mut k = 0;
    for i in 0..=big_n {
        for j in 0..=big_n - i {
            entries
                .push(json!({"a": i, "b": j, "c": big_n - i - j, "point": point_json(&points[k])}));
            k += 1;
        }
    }
    for i in (1..entries.len()).rev() {
        let j = (rng.next() % (i as u64 + 1)) as usize;
        entries.swap(i, j);
    }
    entries
}

#[test]
fn bezier_triangle_restriction_by_every_method() {
    let mut rng = Rng(0x74a1);
    for big_n in [1, 2, 3, 5, 6, 7] {
        let points: Vec<Vec<Rational>> = (0..(big_n + 1) * (big_n + 2) / 2)
            .map(|_| rng.point(3))
            .collect();
        let patch = blossom::TriangularPatch::new(big_n, points.clone()).unwrap();
        // Corners: two coordinates at random, the third 1 minus them.
        let corners: Vec<[Rational; 3]> = (0..3)
            .map(|_| {
                let (r, t) = (rng.rational(), rng.rational());
                let third = Rational::one().sub(&r).sub(&t);
                [r, t, third]
            })
            .collect();
        let job = json!({"kind": "bezier-triangle",
            "control_points": shuffled_entries(&mut rng, big_n, &points),
            "triangle": corners.iter().map(|c| point_json(c)).collect::<Vec<_>>()});
        let got = if big_n == 7 {
            let e = error_with(&["--method", "specialised"], &job);
            assert!(e.contains("Bézier triangular patch of degree 7"), "{e}");
            answer(&job)
        } else {
            all_methods_agree(&job)
        };
        assert_eq!(got["degree"], json!(big_n));
        let entries = got["control_points"].as_array().unwrap();
        // Lexicographic order of (a, b), and the corners are values of the patch.
        let order: Vec<(u64, u64)> = entries
            .iter()
            .map(|e| (e["a"].as_u64().unwrap(), e["b"].as_u64().unwrap()))
            .collect();
        let mut sorted = order.clone();
        sorted.sort();
        assert_eq!(order, sorted);
        for e in entries {
            let (a, b, c) = (
                e["a"].as_u64().unwrap(),
                e["b"].as_u64().unwrap(),
                e["c"].as_u64().unwrap(),
            );
            let corner = if a == big_n as u64 {
                0
            } else if b == big_n as u64 {
                1
            } else if c == big_n as u64 {
                2
            } else {
                continue;
            };
            assert_eq!(
                point_of(&e["point"]),
                patch.eval(&[corners[corner][0].clone(), corners[corner][1].clone()]),
                "N = {big_n}"
            );
        }
    }
}

#[test]
fn triangles_of_a_given_total_degree() {
    let mut rng = Rng(0x707a1);
    for big_n in [0, 1, 2, 4, 6] {
        let rows: Vec<Vec<Vec<Rational>>> = (0..=big_n)
            .map(|i| (0..=big_n - i).map(|_| rng.point(2)).collect())
            .collect();
        let tri: Vec<[Rational; 2]> = (0..3).map(|_| [rng.rational(), rng.rational()]).collect();
        let job = json!({"kind": "triangle", "total_degree": big_n,
            "coefficients": rows.iter().map(|r| r.iter().map(|p| point_json(p)).collect::<Vec<_>>()).collect::<Vec<_>>(),
            "triangle": tri.iter().map(|c| point_json(c)).collect::<Vec<_>>()});
        let exact = answer(&job);
        for m in METHODS.iter().filter(|m| **m != "specialised") {
            assert_eq!(answer_with(&["--method", m], &job), exact, "{m}");
            close(
                &exact,
                &answer_with(&["--method", m, "--arithmetic", "f64"], &job),
            );
        }
        assert_eq!(exact["degree"], json!(big_n));
        let surface = blossom::PowerTriangle::new(rows.clone()).unwrap();
        let entries = exact["control_points"].as_array().unwrap();
        assert_eq!(entries.len(), (big_n + 1) * (big_n + 2) / 2);
        // q_(N00) = S(a), q_(0N0) = S(b), q_(00N) = S(c).
        for (corner, e) in [
            (0, &entries[entries.len() - 1]),
            (1, &entries[big_n]),
            (2, &entries[0]),
        ] {
            assert_eq!(
                point_of(&e["point"]),
                surface.eval(&tri[corner][0], &tri[corner][1])
            );
        }
    }
    // The same surface as a grid and as a triangular array: u + v.
    let grid = answer(
        &json!({"kind": "triangle", "coefficients": [[[0], [1]], [[1], [0]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
    );
    let array = answer(
        &json!({"kind": "triangle", "total_degree": 1, "coefficients": [[[0], [1]], [[1]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
    );
    assert_eq!(grid["degree"], json!(2));
    assert_eq!(array["degree"], json!(1));
    assert_eq!(
        array["control_points"],
        json!([{"a": 0, "b": 0, "c": 1, "point": ["1"]}, {"a": 0, "b": 1, "c": 0, "point": ["1"]}, {"a": 1, "b": 0, "c": 0, "point": ["0"]}])
    );
}

#[test]
fn rational_patches_reproduce_their_surfaces() {
    // A quarter of the unit cylinder: ((1 - u^2), 2u, v (1 + u^2)) / (1 + u^2) on [0, 1]^2.
    let cylinder = json!({"kind": "rational-tensor",
        "numerator": [[[1, 0, 0], [0, 0, 1]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 1]]],
        "denominator": [[1], [0], [1]], "rectangle": [0, 1, 0, 1]});
    let got = answer(&cylinder);
    assert_eq!(got["degree"], json!([2, 1]));
    assert_eq!(got["weights"], json!([["1", "1"], ["1", "1"], ["2", "2"]]));
    assert_eq!(got["control_points"][1][0], json!(["1", "1", "0"]));
    for row in got["control_points"].as_array().unwrap() {
        for p in row.as_array().unwrap() {
            let p = point_of(p);
            // The corner points of the net lie on x^2 + y^2 = 1 (the middle one is the corner
            // of the control polygon, (1, 1)).
            let r = p[0].mul(&p[0]).add(&p[1].mul(&p[1]));
            assert!(
                r == Rational::one() || r == Rational::from_integer(2.into()),
                "{r}"
            );
        }
    }
    close(&got, &answer_with(&["--arithmetic", "f64"], &cylinder));
    // An elevated degree describes the same surface: its corners are unchanged.
    let elevated = answer(&json!({"kind": "rational-tensor",
        "numerator": cylinder["numerator"], "denominator": cylinder["denominator"],
        "rectangle": [0, 1, 0, 1], "degree": [3, 2]}));
    assert_eq!(elevated["degree"], json!([3, 2]));
    assert_eq!(
        elevated["control_points"][0][0],
        got["control_points"][0][0]
    );
    assert_eq!(
        elevated["control_points"][3][2],
        got["control_points"][2][1]
    );
    // Grids of different shapes are padded: numerator (1, 0), denominator (0, 1).
    let padded = answer(
        &json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]],
        "denominator": [[1, 1]], "rectangle": [0, 1, 0, 1]}),
    );
    assert_eq!(padded["degree"], json!([1, 1]));
    // (1 + u) / (1 + v) at (1, 1) is 1 with weight 2.
    assert_eq!(padded["control_points"][1][1], json!(["1"]));
    assert_eq!(padded["weights"][1][1], json!("2"));

    // The triangle: x = (u + v) / (1 + u), at its true degree 1 from a (1, 1) grid, and from
    // its triangular arrays.
    let tri = json!([[0, 0], [1, 0], [0, 1]]);
    let from_grid = answer(&json!({"kind": "rational-triangle",
        "numerator": [[[0], [1]], [[1], [0]]], "denominator": [[1, 0], [1, 0]], "triangle": tri, "degree": 1}));
    let from_array = answer(&json!({"kind": "rational-triangle", "total_degree": 1,
        "numerator": [[[0], [1]], [[1]]], "denominator": [[1, 0], [1]], "triangle": tri}));
    assert_eq!(from_grid, from_array);
    assert_eq!(
        from_array["control_points"],
        json!([{"a": 0, "b": 0, "c": 1, "point": ["1"], "weight": "1"},
               {"a": 0, "b": 1, "c": 0, "point": ["1/2"], "weight": "2"},
               {"a": 1, "b": 0, "c": 0, "point": ["0"], "weight": "1"}])
    );
    let default = answer(&json!({"kind": "rational-triangle",
        "numerator": [[[0], [1]], [[1], [0]]], "denominator": [[1, 0], [1, 0]], "triangle": tri}));
    assert_eq!(default["degree"], json!(2));
    close(
        &default,
        &answer_with(
            &["--arithmetic", "f64"],
            &json!({"kind": "rational-triangle",
        "numerator": [[[0], [1]], [[1], [0]]], "denominator": [[1, 0], [1, 0]], "triangle": tri}),
        ),
    );
    // Every method answers the same (one algorithm).
    for m in METHODS {
        assert_eq!(answer_with(&["--method", m], &cylinder), got, "{m}");
    }
}

#[test]
fn bad_input_is_refused_with_the_field() {
    let entry = |a: u64, b: u64, c: u64| json!({"a": a, "b": b, "c": c, "point": [1]});
    let full = json!([entry(1, 0, 0), entry(0, 1, 0), entry(0, 0, 1)]);
    let tri = json!([[1, 0, 0], [0, 1, 0], [0, 0, 1]]);
    let cases: Vec<(&[&str], Value, &str)> = vec![
        // Indices missing, repeated, inconsistent, or not indices.
        (&[], json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0), entry(0, 1, 0)], "triangle": tri}),
            "error: control_points: the control point with indices (0, 0, 1) is missing"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0), entry(0, 1, 0), entry(1, 0, 0)], "triangle": tri}),
            "error: control_points[2]: indices (1, 0, 0) repeat those of control_points[0]"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0), entry(0, 2, 0), entry(0, 0, 1)], "triangle": tri}),
            "error: control_points[1]: indices (0, 2, 0) add up to 2, but those of control_points[0] add up to 1"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [{"a": 1, "b": 0, "point": [1]}], "triangle": tri}),
            "error: control_points[0].c: missing field"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [{"a": -1, "b": 1, "c": 1, "point": [1]}], "triangle": tri}),
            "error: control_points[0].a: expected a non-negative integer"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [{"a": 1, "b": 0, "c": 0}], "triangle": tri}),
            "error: control_points[0].point: missing field"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0), {"a": 0, "b": 1, "c": 0, "point": [1, 2]}, entry(0, 0, 1)], "triangle": tri}),
            "error: control_points[1].point: expected 1 coordinate, found 2"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [[1]], "triangle": tri}),
            "error: control_points[0]: expected an object"),
        (&[], json!({"kind": "bezier-triangle", "control_points": [], "triangle": tri}),
            "error: control_points: expected at least one control point"),
        // Barycentric coordinates that do not add up to 1.
        (&[], json!({"kind": "bezier-triangle", "control_points": full, "triangle": [[1, 0, 0], ["1/2", "1/2", "1/1000000000000"], [0, 0, 1]]}),
            "error: triangle[1]: barycentric coordinates must add up to 1 (exactly)"),
        (&["--arithmetic", "f64"], json!({"kind": "bezier-triangle", "control_points": full, "triangle": [[1, 0, 0], [0.5, 0.5, 1e-6], [0, 0, 1]]}),
            "error: triangle[1]: barycentric coordinates must add up to 1 (within 1e-9)"),
        (&[], json!({"kind": "bezier-triangle", "control_points": full, "triangle": [[1, 0], [0, 1, 0], [0, 0, 1]]}),
            "error: triangle[0]: expected 3 barycentric coordinates, found 2"),
        (&[], json!({"kind": "bezier-triangle", "control_points": full, "triangle": [[1, 0, 0], [0, 1, 0]]}),
            "error: triangle: expected 3 corners, found 2"),
        // Bézier tensor nets.
        (&[], json!({"kind": "bezier-tensor", "control_points": [[[1], [2]], [[3]]], "rectangle": [0, 1, 0, 1]}),
            "error: control_points[1]: expected 2 points (the grid must be rectangular), found 1"),
        (&[], json!({"kind": "bezier-tensor", "control_points": [[[1]]], "rectangle": [0, 1, 0]}),
            "error: rectangle: expected 4 numbers, found 3"),
        (&[], json!({"kind": "bezier-tensor", "control_points": [], "rectangle": [0, 1, 0, 1]}),
            "error: control_points: expected at least one row"),
        // Triangular arrays of the wrong shape.
        (&[], json!({"kind": "triangle", "total_degree": 2, "coefficients": [[[1], [2], [3]], [[4], [5]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: coefficients: expected 3 rows (a triangular array of total degree 2), found 2"),
        (&[], json!({"kind": "triangle", "total_degree": 2, "coefficients": [[[1], [2], [3]], [[4], [5], [6]], [[7]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: coefficients[1]: expected 2 points (row 1 of a triangular array of total degree 2 holds N + 1 - i), found 3"),
        (&[], json!({"kind": "triangle", "total_degree": "two", "coefficients": [[[1]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: total_degree: expected a non-negative integer"),
        (&[], json!({"kind": "triangle", "total_degree": 1, "coefficients": [[[1], [2]], [[3, 4]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: coefficients[1][0]: expected 1 coordinate, found 2"),
        (&["--method", "specialised"], json!({"kind": "triangle", "total_degree": 7,
            "coefficients": (0..=7).map(|i| vec![json!([1]); 8 - i]).collect::<Vec<_>>(), "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: --method: no specialised evaluator for a triangular array of total degree 7"),
        // Derivatives of an order above the degree, or not an order.
        (&[], json!({"kind": "derivative", "control_points": [[0], [1], [3]], "order": 3}),
            "error: order: expected an order of at most 2 (the curve's degree), found 3"),
        (&[], json!({"kind": "derivative", "control_points": [[0], [1], [3]], "order": -1}),
            "error: order: expected a non-negative integer"),
        (&[], json!({"kind": "derivative", "control_points": [[0], [1], [3]]}),
            "error: order: missing field"),
        (&[], json!({"kind": "derivative", "control_points": [[0], [1, 2]], "order": 1}),
            "error: control_points[1]: expected 1 coordinate, found 2"),
        (&[], json!({"kind": "rational-triangle", "total_degree": 1, "numerator": [[[0], [1]], [[1]]], "denominator": [[1, 0], [1, 0]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: denominator[1]: expected 1 numbers (row 1 of a triangular array of total degree 1"),
        // Zero weights.
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]], "denominator": [[1], [-1]], "rectangle": [0, 1, 0, 1]}),
            "error: denominator: weight w_10 is zero"),
        (&["--arithmetic", "f64"], json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]], "denominator": [[1], [-1]], "rectangle": [0, 1, 0, 1]}),
            "error: denominator: weight w_10 is zero"),
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]]], "denominator": [[0]], "rectangle": [0, 1, 0, 1]}),
            "error: denominator: the denominator is the zero polynomial"),
        (&[], json!({"kind": "rational-triangle", "total_degree": 1, "numerator": [[[0], [1]], [[1]]], "denominator": [[1, 0], [-1]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
            "error: denominator: weight w_010 is zero"),
        // Degrees below the surface's.
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]], "denominator": [[1]], "rectangle": [0, 1, 0, 1], "degree": [0, 0]}),
            "error: degree[0]: expected a degree >= 1"),
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]]], "denominator": [[1]], "rectangle": [0, 1, 0, 1], "degree": [1]}),
            "error: degree: expected 2 degrees, found 1"),
        (&[], json!({"kind": "rational-triangle", "numerator": [[[0], [1]], [[1], [1]]], "denominator": [[1]], "triangle": [[0, 0], [1, 0], [0, 1]], "degree": 1}),
            "error: degree: expected a total degree >= 2 (the surface's true total degree), found 1"),
        // Shapes of the rational grids.
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1], [2]], [[3]]], "denominator": [[1]], "rectangle": [0, 1, 0, 1]}),
            "error: numerator[1]: expected 2 points (the grid must be rectangular), found 1"),
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]]], "denominator": [[1, 2], [3]], "rectangle": [0, 1, 0, 1]}),
            "error: denominator[1]: expected 2 numbers (the grid must be rectangular), found 1"),
        (&[], json!({"kind": "rational-tensor", "numerator": [[[1]]], "denominator": [[1, "x"]], "rectangle": [0, 1, 0, 1]}),
            "error: denominator[0][1]: cannot read \"x\" as a number"),
        (&[], json!({"kind": "rational-triangle", "numerator": [[[1]]], "denominator": [[1]], "triangle": [[0, 0], [1, 0]]}),
            "error: triangle: expected 3 corners, found 2"),
    ];
    for (args, job, want) in cases {
        let got = error_with(args, &job);
        assert!(
            got.starts_with(want),
            "job {job}\n  got  {got}\n  want {want}"
        );
    }
    // Within 1e-9 under f64 is accepted.
    let ok = answer_with(
        &["--arithmetic", "f64"],
        &json!({"kind": "bezier-triangle", "control_points": full, "triangle": [[1, 0, 0], [0.5, 0.5, 1e-12], [0, 0, 1]]}),
    );
    assert_eq!(ok["degree"], json!(1));
}

#[test]
fn derivatives_are_scaled_forward_differences() {
    // The contract's formula, computed here: n!/(n-k)! times the k-th forward differences.
    let mut rng = Rng(0xde71);
    for n in [0usize, 1, 3, 6, 11] {
        let b: Vec<Vec<Rational>> = (0..=n).map(|_| rng.point(2)).collect();
        let pts: Vec<Value> = b.iter().map(|p| point_json(p)).collect();
        for k in 0..=n {
            let job = json!({"kind": "derivative", "control_points": pts, "order": k});
            let got = answer(&job);
            assert_eq!(got["degree"], json!(n - k));
            let mut diff = b.clone();
            for _ in 0..k {
                diff = diff
                    .windows(2)
                    .map(|w| w[1].iter().zip(&w[0]).map(|(x, y)| x.sub(y)).collect())
                    .collect();
            }
            let scale = Rational::from_integer(((n - k + 1)..=n).product::<usize>().into());
            let want: Vec<Value> = diff
                .iter()
                .map(|p| point_json(&p.iter().map(|x| x.mul(&scale)).collect::<Vec<_>>()))
                .collect();
            assert_eq!(got["control_points"], json!(want), "n = {n}, k = {k}");
            close(&got, &answer_with(&["--arithmetic", "f64"], &job));
        }
    }
}

/// Small worked answers of every job of this section, for review in the snapshot.
#[test]
fn answers_snapshot() {
    let jobs = [
        json!({"kind": "bezier-tensor", "control_points": [[[0, 0], [1, 2]], [[2, 1], [3, 3]]], "rectangle": ["1/2", 1, 0, "1/3"]}),
        json!({"kind": "bezier-triangle", "control_points": [
            {"a": 2, "b": 0, "c": 0, "point": [1]}, {"a": 0, "b": 2, "c": 0, "point": [2]},
            {"a": 0, "b": 0, "c": 2, "point": [3]}, {"a": 1, "b": 1, "c": 0, "point": [4]},
            {"a": 1, "b": 0, "c": 1, "point": [5]}, {"a": 0, "b": 1, "c": 1, "point": [6]}],
            "triangle": [["1/2", "1/4", "1/4"], [0, 1, 0], [0, 0, 1]]}),
        json!({"kind": "triangle", "total_degree": 2, "coefficients": [[[1], [2], [3]], [[4], [5]], [[6]]], "triangle": [[0, 0], [1, 0], [0, 1]]}),
        json!({"kind": "derivative", "control_points": [[0, 0], [1, 2], [3, 3], [4, 0]], "order": 1}),
        json!({"kind": "rational-tensor", "numerator": [[[1, 0, 0], [0, 0, 1]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 1]]],
            "denominator": [[1], [0], [1]], "rectangle": [0, 1, 0, 1]}),
        json!({"kind": "rational-triangle", "numerator": [[[0], [1]], [[1], [0]]], "denominator": [[1, 0], [1, 0]],
            "triangle": [[0, 0], [1, 0], [0, 1]], "degree": 1}),
    ];
    let text: Vec<String> = jobs.iter().map(|j| answer(j).to_string()).collect();
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("cli_patch_jobs_answers", text.join("\n"));
    });
}
