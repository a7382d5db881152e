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
    assert!(enclosure.1 - enclosure.0 <= b * 2f64.powi(-40), "{enclosure:?}");
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
        assert_eq!(out["loops"].as_array().unwrap().is_empty(), expected == 0.0, "{op}: {out}");
        if expected == 0.0 {
            assert_eq!(out["area"], json!([0.0, 0.0]), "{op}");
        }
    }
    for fill in ["nonzero", "evenodd"] {
        let empty = json!({"loops": [], "fill": fill});
        let out = answer(&[], &json!({"kind": "simplify", "region": empty}));
        assert_eq!(out, json!({"kind": "simplify", "loops": [], "area": [0.0, 0.0]}));
        let out = answer(&[], &json!({"kind": "winding", "region": empty, "points": [[0, 0], ["1/3", 7]]}));
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
    let outline = polygon(&[[0, 0], [4, 0], [4, 3], [1, 3], [1, 1], [3, 1], [3, 2], [0, 2]]);
    for (fill, expected) in [("nonzero", 11.0), ("evenodd", 9.0)] {
        let region = json!({"loops": [outline], "fill": fill});
        let out = simplified(&region);
        holds(area(&out), expected, 12.0);
        let winding = answer(&[], &json!({"kind": "winding", "region": region,
            "points": [["3/2", "3/2"], ["1/2", "5/2"], ["1/2", "1/2"]]}));
        assert_eq!(
            winding["points"].as_array().unwrap().iter().map(|p| p["winding"].clone()).collect::<Vec<_>>(),
            vec![json!(2), json!(0), json!(1)]
        );
    }
}

#[test]
fn simplify_refuses_bad_regions_naming_the_field() {
    let open = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]]]]});
    let e = error(&[], &json!({"kind": "simplify", "region": open}).to_string());
    assert!(e.starts_with("error: region.loops[0][0]: starts at (0, 0)"), "{e}");
    let e = error(&[], &json!({"kind": "simplify", "regions": []}).to_string());
    assert!(e.starts_with("error: regions: unknown field \"regions\" (did you mean \"region\"?)"), "{e}");
    let e = error(&[], &json!({"kind": "simplify"}).to_string());
    assert_eq!(e, "error: region: missing field");
    let e = error(&[], &json!({"kind": "simplify", "region": {"loops": [[[[0, 2.5], [1, 0]]]]}}).to_string());
    assert!(e.starts_with("error: region.loops[0][0][0][1]: the JSON number 2.5"), "{e}");
    // The budget bounds simplify as it bounds the booleans.
    let region = json!({"loops": [square(0, 0, 2), square(1, 1, 2)]});
    let e = error(&["--max-work", "10"], &json!({"kind": "simplify", "region": region}).to_string());
    assert!(e.starts_with("error: region: the job's work is estimated at "), "{e}");
}
