//! The region forms of the fifth round (the contract's last section), driven through the
//! binary: the empty region `{"loops": []}` in every job that takes a region, and `"kind":
//! "simplify"` (overlap removal) on overlapping and self-crossing loops under both fill rules,
//! its areas against values computed by hand, its answer checked as every region answer is
//! (`checked_loops`: PARAMs, chaining, orientation, area within the sampled loops).

use super::cli_region::{answer, area, check_boolean, checked_loops, error, polygon};
use serde_json::{json, Value};

/// `[lo, hi]` holds `exact`, and is as narrow as the contract promises for a box of area `b`.
fn holds(enclosure: (f64, f64), exact: f64, b: f64) {
    assert!(
        enclosure.0 <= exact && exact <= enclosure.1,
        "{enclosure:?} does not hold {exact}"
    );
    assert!(
        enclosure.1 - enclosure.0 <= b * 2f64.powi(-40),
        "{enclosure:?}"
    );
}

fn square(x: i64, y: i64, side: i64) -> Value {
    polygon(&[[x, y], [x + side, y], [x + side, y + side], [x, y + side]])
}

#[test]
fn the_empty_region_is_a_region_in_every_job() {
    let a = json!({"loops": [square(0, 0, 2)]});
    let empty = json!({"loops": []});
    // A = [0, 2]^2 of area 4 and E empty: A ∪ E = E ∪ A = A - E = A xor E = A; A ∩ E = E - A
    // = nothing.
    for (op, x, y, expected) in [
        ("union", &a, &empty, 4.0),
        ("union", &empty, &a, 4.0),
        ("intersection", &a, &empty, 0.0),
        ("intersection", &empty, &a, 0.0),
        ("difference", &a, &empty, 4.0),
        ("difference", &empty, &a, 0.0),
        ("xor", &a, &empty, 4.0),
        ("xor", &empty, &empty, 0.0),
    ] {
        let job = json!({"kind": "boolean", "op": op, "regions": [x, y]});
        let out = check_boolean(&[], &job);
        holds(area(&out), expected, 4.0);
        assert_eq!(
            out["loops"].as_array().unwrap().is_empty(),
            expected == 0.0,
            "{op}: {out}"
        );
        if expected == 0.0 {
            assert_eq!(out["area"], json!([0.0, 0.0]), "{op}");
        }
    }
    for fill in ["nonzero", "evenodd"] {
        let empty = json!({"loops": [], "fill": fill});
        let out = answer(&[], &json!({"kind": "simplify", "region": empty}));
        assert_eq!(
            out,
            json!({"kind": "simplify", "loops": [], "area": [0.0, 0.0], "svg": ""})
        );
        let out = answer(
            &[],
            &json!({"kind": "winding", "region": empty, "points": [[0, 0], ["1/3", 7]]}),
        );
        assert_eq!(
            out["points"],
            json!([{"position": "outside", "winding": 0}, {"position": "outside", "winding": 0}])
        );
    }
}

/// The simplify answer of `region`, checked like a boolean's (its one region as region 0).
fn simplified(region: &Value) -> Value {
    let out = answer(&[], &json!({"kind": "simplify", "region": region}));
    assert_eq!(out["kind"], "simplify");
    for l in out["loops"].as_array().unwrap() {
        for e in l["edges"].as_array().unwrap() {
            assert_eq!(e["region"], 0, "{e}");
        }
    }
    // The same checks as a boolean answer with the region as A (and an empty B).
    let as_boolean = json!({"kind": "boolean", "op": "union", "regions": [region, {"loops": []}]});
    let mut as_answer = out.clone();
    as_answer["kind"] = json!("boolean");
    checked_loops(&as_boolean, &as_answer);
    out
}

#[test]
fn simplify_merges_two_overlapping_squares() {
    // [0, 2]^2 and [1, 3]^2, both counter-clockwise: the union has area 4 + 4 - 1 = 7 and the
    // overlap [1, 2]^2 winding number 2, so under evenodd it is left out: 7 - 1 = 6.
    for (fill, expected) in [("nonzero", 7.0), ("evenodd", 6.0)] {
        let region = json!({"loops": [square(0, 0, 2), square(1, 1, 2)], "fill": fill});
        let out = simplified(&region);
        holds(area(&out), expected, 9.0);
        // Every loop of the answer is simple: overlap removed, one outer loop under nonzero.
        if fill == "nonzero" {
            assert_eq!(out["loops"].as_array().unwrap().len(), 1, "{out}");
        }
    }
}

#[test]
fn simplify_of_a_self_crossing_loop_under_both_fill_rules() {
    // The loop (0,0) (4,0) (4,3) (1,3) (1,1) (3,1) (3,2) (0,2) crosses itself at (1, 2). By
    // rays to the right: [1, 3] x [1, 2] has winding number 2 (it crosses x = 3 and x = 4
    // upwards), [0, 1] x [2, 3] has 0 (down at x = 1, up at x = 4), the rest of the box
    // [0, 4] x [0, 3] (area 12) has 1, area 12 - 2 - 1 = 9. Shoelace: 9 + 2 * 2 = 13 = 26 / 2.
    // So nonzero keeps 9 + 2 = 11, evenodd 9.
    let outline = polygon(&[
        [0, 0],
        [4, 0],
        [4, 3],
        [1, 3],
        [1, 1],
        [3, 1],
        [3, 2],
        [0, 2],
    ]);
    for (fill, expected) in [("nonzero", 11.0), ("evenodd", 9.0)] {
        let region = json!({"loops": [outline], "fill": fill});
        let out = simplified(&region);
        holds(area(&out), expected, 12.0);
        let winding = answer(
            &[],
            &json!({"kind": "winding", "region": region,
            "points": [["3/2", "3/2"], ["1/2", "5/2"], ["1/2", "1/2"]]}),
        );
        assert_eq!(
            winding["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| p["winding"].clone())
                .collect::<Vec<_>>(),
            vec![json!(2), json!(0), json!(1)]
        );
    }
}

#[test]
fn simplify_refuses_bad_regions_naming_the_field() {
    let open = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]]]]});
    let e = error(
        &[],
        &json!({"kind": "simplify", "region": open}).to_string(),
    );
    assert!(
        e.starts_with("error: region.loops[0][0]: starts at (0, 0)"),
        "{e}"
    );
    let e = error(&[], &json!({"kind": "simplify", "regions": []}).to_string());
    assert!(
        e.starts_with("error: regions: unknown field \"regions\" (did you mean \"region\"?)"),
        "{e}"
    );
    let e = error(&[], &json!({"kind": "simplify"}).to_string());
    assert_eq!(e, "error: region: missing field");
    let e = error(
        &[],
        &json!({"kind": "simplify", "region": {"loops": [[[[0, 2.5], [1, 0]]]]}}).to_string(),
    );
    assert!(
        e.starts_with("error: region.loops[0][0][0][1]: the JSON number 2.5"),
        "{e}"
    );
    // The budget bounds simplify as it bounds the booleans.
    let region = json!({"loops": [square(0, 0, 2), square(1, 1, 2)]});
    let e = error(
        &["--max-work", "10"],
        &json!({"kind": "simplify", "region": region}).to_string(),
    );
    assert!(
        e.starts_with("error: region: the job's work is estimated at "),
        "{e}"
    );
}

/// The area of the simplify answer of the region of SVG path data `d` under `args`.
fn path_area(args: &[&str], d: &str) -> ((f64, f64), Value) {
    let out = answer(args, &json!({"kind": "simplify", "region": {"path": d}}));
    (area(&out), out)
}

#[test]
fn svg_path_data_reads_every_command() {
    // Areas by hand. A square, absolute and relative, closed or left open (closed by a line).
    for d in [
        "M0 0 H2 V2 H0 Z",
        "m 0 0 h 2 v 2 h -2 z",
        "M0,0 2,0 2,2 0,2",
        "M 0 0 L 2 0 L 2 2 L 0 2",
    ] {
        holds(path_area(&[], d).0, 4.0, 4.0);
    }
    // A quadratic bulge over the top side, control point 1 above the chord: 2/3 x 2 x 1/2.
    holds(
        path_area(&[], "M0,0 2,0 2,2 Q1,3 0,2z").0,
        4.0 + 2.0 / 3.0,
        6.0,
    );
    // T reflects the control point (1.5, 3) about (1, 2) to (0.5, 1): a bump of 1/3 out, then
    // one of 1/3 in; without the reflection the area would be 4 + 1/3.
    holds(
        path_area(&[], "M0 0 L2 0 L2 2 Q 1.5 3 1 2 T 0 2 Z").0,
        4.0,
        6.0,
    );
    // A cubic whose x runs linearly from 3 to 0 and y = 3 + 3t(1 - t): a bump of
    // integral 3t(1 - t) 3 dt = 3/2 over the 3 x 3 square.
    holds(path_area(&[], "M0 0 H3 V3 C 2 4 1 4 0 3 Z").0, 10.5, 12.0);
    // C then S (the first control point (8, 9) reflected about (6, 6) to (4, 3)): a bump of 9
    // out and one of 9 in over the 12 x 6 rectangle; absolute and relative.
    for d in [
        "M0 0 H12 V6 C10 9 8 9 6 6 S2 3 0 6 Z",
        "m0 0 h12 v6 c-2 3 -4 3 -6 0 s-4 -3 -6 0 z",
    ] {
        holds(path_area(&[], d).0, 72.0, 12.0 * 9.0);
    }
    // Subpaths of zero length are dropped; loop l is the l-th kept subpath, curve c its c-th
    // segment with the closing line last.
    let (_, out) = path_area(&[], "M 5 5 M0 0 H1 V1 H0 M 9 9 Z");
    let edges = out["loops"][0]["edges"].as_array().unwrap();
    let mut curves: Vec<u64> = edges.iter().map(|e| e["curve"].as_u64().unwrap()).collect();
    curves.sort_unstable();
    assert_eq!(curves, [0, 1, 2, 3]);
    assert!(edges.iter().all(|e| e["loop"] == 0), "{out}");
    // A path without a kept subpath is the empty region.
    let (a, out) = path_area(&[], "M 1 2");
    assert_eq!((a, out["loops"].clone()), ((0.0, 0.0), json!([])));
    // A path region in a boolean, beside a region of loops: [0, 2]^2 and [1, 3]^2.
    let job = json!({"kind": "boolean", "op": "union",
        "regions": [{"path": "M0 0 H2 V2 H0 Z"}, {"loops": [square(1, 1, 2)]}]});
    holds(area(&answer(&[], &job)), 7.0, 9.0);
}

#[test]
fn svg_numbers_follow_the_arithmetic() {
    // Under f64 0.1 and 0.2 are the nearest doubles and the relative h adds them exactly: the
    // right side is at 0.1d + 0.2d = 0.3000000000000000166..., left of the double
    // 0.30000000000000004 (the doubles' rounded sum) and right of 0.299999999999999988...
    // (the double nearest 0.3).
    let region = json!({"path": "M 0.1 0 h 0.2 v 1 h -0.2 z"});
    let job = json!({"kind": "winding", "region": region,
        "points": [["0.30000000000000004", "0.5"], ["0.3", "0.5"]]});
    let f64_answer = answer(&["--arithmetic", "f64"], &job);
    assert_eq!(
        f64_answer["points"][0]["position"], "outside",
        "{f64_answer}"
    );
    assert_eq!(
        f64_answer["points"][1]["position"], "inside",
        "{f64_answer}"
    );
    // Exactly, 0.1 + 0.2 is 3/10: the point 0.3 is on the boundary.
    let exact = answer(&[], &job);
    assert_eq!(exact["points"][1]["position"], "boundary", "{exact}");
}

#[test]
fn bad_svg_path_data_names_the_field_and_the_offset() {
    let simplify = |d: Value| json!({"kind": "simplify", "region": {"path": d}}).to_string();
    let d = "M 0 0 L 1 0 A 1 1 0 0 1 0 0 Z";
    let at = d.find('A').unwrap();
    assert_eq!(
        error(&[], &simplify(json!(d))),
        format!("error: region.path: at {at}: arcs (A) are not polynomial curves; convert them to cubics")
    );
    let e = error(&[], &simplify(json!("M 0 0 L 1 0 X 1 1 Z")));
    assert!(e.starts_with("error: region.path: at 12: "), "{e}");
    let e = error(&[], &simplify(json!("L 1 0 1 1 Z")));
    assert!(e.starts_with("error: region.path: "), "{e}");
    let e = error(&[], &simplify(json!("M 0 0 L 1")));
    assert!(e.starts_with("error: region.path: "), "{e}");
    let e = error(&[], &simplify(json!(7)));
    assert!(e.starts_with("error: region.path: "), "{e}");
    let job = json!({"kind": "boolean", "op": "union",
        "regions": [{"loops": []}, {"path": "M0 0 H1 V1 Z", "loops": []}]});
    let e = error(&[], &job.to_string());
    assert!(e.starts_with("error: regions[1].path: "), "{e}");
    let job =
        json!({"kind": "boolean", "op": "union", "regions": [{"fill": "evenodd"}, {"loops": []}]});
    let e = error(&[], &job.to_string());
    assert!(
        e.starts_with("error: regions[0].loops: missing field"),
        "{e}"
    );
    // A JSON-looking number in path data is read as written, exactly.
    let e = error(&[], &simplify(json!("M 0 0 L 1e999999 0 L 0 1 Z")));
    assert!(
        e.starts_with("error: region.path: at 8: ") && e.contains("exponent"),
        "{e}"
    );
    // The budget bounds path regions too.
    let e = error(
        &["--max-work", "10"],
        &simplify(json!("M0 0 H2 V2 H0 Z M1 1 H3 V3 H1 Z")),
    );
    assert!(
        e.starts_with("error: region: the job's work is estimated at "),
        "{e}"
    );
}

#[test]
fn every_region_answer_has_svg_that_reads_back() {
    // Two overlapping squares as loops; the boolean's svg, read back as a path region, has the
    // same area.
    let a = json!({"loops": [square(0, 0, 2)]});
    let b = json!({"loops": [square(1, 1, 2)]});
    for (op, expected) in [("union", 7.0), ("intersection", 1.0), ("xor", 6.0)] {
        let out = answer(
            &[],
            &json!({"kind": "boolean", "op": op, "regions": [a, b]}),
        );
        let svg = out["svg"].as_str().unwrap_or_else(|| panic!("{out}"));
        assert!(svg.starts_with('M') && svg.ends_with('Z'), "{svg}");
        assert_eq!(
            svg.matches('M').count(),
            out["loops"].as_array().unwrap().len(),
            "{svg}"
        );
        let (back, _) = path_area(&[], svg);
        holds(back, expected, 9.0);
        holds(area(&out), expected, 9.0);
    }
    // simplify and triangle-triangle have it too; an empty result has the empty string.
    let out = answer(
        &[],
        &json!({"kind": "simplify", "region": {"path": "M0 0 H3 V3 C 2 4 1 4 0 3 Z"}}),
    );
    assert!(out["svg"].as_str().unwrap().contains('C'), "{out}");
    let t1 = json!({"degree": 2, "nodes": [[0, 0], [2, 0], [4, 0], [0, 2], [2, 2], [0, 4]]});
    let t2 = json!({"degree": 1, "nodes": [[1, 1], [5, 1], [1, 5]]});
    let out = answer(
        &[],
        &json!({"kind": "triangle-triangle", "triangles": [t1, t2]}),
    );
    let svg = out["svg"].as_str().unwrap();
    let (back, exact) = (path_area(&[], svg).0, area(&out));
    assert!(
        (back.0 - exact.0).abs() < 1e-9 && exact.0 > 1.0,
        "{back:?} {exact:?}"
    );
    let out = answer(&[], &json!({"kind": "simplify", "region": {"loops": []}}));
    assert_eq!(out["svg"], "");
    // An edge of degree 4 has no SVG command: "svg" is null.
    let quartic = json!([
        [[0, 0], [1, -1], [2, 1], [3, -1], [4, 0]],
        [[4, 0], [0, 4]],
        [[0, 4], [0, 0]]
    ]);
    let out = answer(
        &[],
        &json!({"kind": "simplify", "region": {"loops": [quartic]}}),
    );
    assert!(out["svg"].is_null(), "{out}");
}

#[test]
fn region_help_says_how_numbers_are_read_and_lists_the_new_forms() {
    let help = super::binary::run_binary(&["region", "--help"], b"").stdout;
    let help = help.split_whitespace().collect::<Vec<_>>().join(" ");
    for needle in [
        "A JSON number with a fraction part or an exponent (2.7) is refused under the default --arithmetic exact",
        "\"kind\": \"simplify\"",
        "{\"loops\": []} is the empty region",
        "{\"path\":",
        "\"svg\"",
    ] {
        assert!(help.contains(needle), "{needle}: {help}");
    }
    // And it is so: 2.7 refused, "2.7" read.
    let job = |x: Value| json!({"kind": "winding", "region": {"loops": [square(0, 0, 3)]}, "points": [[x, 1]]});
    let e = error(&[], &job(json!(2.7)).to_string());
    assert!(
        e.starts_with("error: points[0][0]: the JSON number 2.7"),
        "{e}"
    );
    assert_eq!(
        answer(&[], &job(json!("2.7")))["points"][0]["position"],
        "inside"
    );
}
