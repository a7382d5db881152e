//! The jobs of `blossom restrict` read through their serde types, in process: every field of
//! every kind read, the field of an error named, unknown fields refused at any depth with the
//! nearest accepted name, a job without its kind checked against every kind.

use blossom_cli::jobs::kinds::{kinds_of, Subcommand};
use blossom_cli::jobs::shape;
use blossom_cli::names::listed;
use serde_json::{json, Map, Value};

/// The fields each kind of `restrict` reads, `kind` first, from the list of kinds.
#[allow(non_snake_case)]
fn JOB_FIELDS() -> Vec<(&'static str, Vec<&'static str>)> {
    kinds_of(Subcommand::Restrict)
        .map(|k| {
            let mut fields = vec!["kind"];
            fields.extend((k.fields)());
            (k.name, fields)
        })
        .collect()
}

fn error(job: Value) -> String {
    let line = restrict(&job).unwrap_err();
    line.strip_prefix("error: ").unwrap_or(&line).to_string()
}

#[test]
fn messages_name_the_field() {
    assert_eq!(
        error(
            json!({"kind": "curve", "coefficients": [[1, 2, 3], [1, 2, 3], [1, 2]], "interval": [0, 1]})
        ),
        "coefficients[2]: expected 3 coordinates, found 2"
    );
    assert_eq!(
        error(json!({"kind": "curve", "coefficients": [[1]], "interval": [0, 1, 2]})),
        "interval: expected 2 numbers, found 3"
    );
    assert_eq!(
        error(json!({"kind": "foo"})),
        "kind: unknown kind \"foo\" (expected one of curve, tensor, triangle, bezier-curve, \
         bspline, bspline-eval, rational-curve, elevate, reduce, bezier-tensor, bezier-triangle, \
         derivative, rational-tensor, rational-triangle)"
    );
    assert_eq!(error(json!({"kind": "bspline"})), "degree: missing field");
    assert_eq!(
        error(json!({"kind": "curve", "coefficients": [[1]]})),
        "interval: missing field"
    );
    assert_eq!(
        error(json!({"kind": "tensor", "coefficients": [[[1]]], "rectangle": [0, 1, 2, "x"]})),
        "rectangle[3]: cannot read \"x\" as a number (expected an integer such as \"-7\", a \
         fraction such as \"3/4\" or a decimal such as \"0.125\")"
    );
    assert_eq!(
        error(
            json!({"kind": "triangle", "coefficients": [[[1]]], "triangle": [[0, 0], [1, 0, 0], [0, 1]]})
        ),
        "triangle[1]: expected 2 coordinates, found 3"
    );
    assert_eq!(
        error(
            json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3]]], "rectangle": [0, 1, 0, 1]})
        ),
        "coefficients[1]: expected 2 points (the grid must be rectangular), found 1"
    );
    assert_eq!(
        error(
            json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3], [4, 5]]], "rectangle": [0, 1, 0, 1]})
        ),
        "coefficients[1][1]: expected 1 coordinate, found 2"
    );
    assert_eq!(
        error(json!([1])),
        "input: expected a JSON object (a job), found an array"
    );
}

/// A job of every kind that answers, using every field its kind accepts.
fn every_kind() -> Vec<Value> {
    let tri = json!([[0, 0], [1, 0], [0, 1]]);
    let entry = |a: u32, b: u32, c: u32, p: i32| json!({"a": a, "b": b, "c": c, "point": [p]});
    vec![
        json!({"kind": "curve", "coefficients": [[1], [2]], "interval": [0, 1]}),
        json!({"kind": "tensor", "coefficients": [[[1], [2]], [[3], [4]]], "rectangle": [0, 1, 0, 1]}),
        json!({"kind": "triangle", "total_degree": 1, "coefficients": [[[0], [1]], [[1]]], "triangle": tri}),
        json!({"kind": "bezier-curve", "control_points": [[0], [1]], "interval": [0, "1/2"]}),
        json!({"kind": "bspline", "degree": 1, "pieces": [{"interval": [0, 1], "coefficients": [[0], [1]]}]}),
        json!({"kind": "bspline-eval", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0], [1]], "at": ["1/2"]}),
        json!({"kind": "rational-curve", "numerator": [[0], [1]], "denominator": [1, 1], "interval": [0, 1], "degree": 2}),
        json!({"kind": "elevate", "control_points": [[0], [1]], "to_degree": 2}),
        json!({"kind": "reduce", "control_points": [[0], [1], [3]], "to_degree": 1, "method": "least-squares"}),
        json!({"kind": "bezier-tensor", "control_points": [[[0], [1]], [[2], [3]]], "rectangle": [0, 1, 0, 1]}),
        json!({"kind": "bezier-triangle", "control_points": [entry(1, 0, 0, 1), entry(0, 1, 0, 2), entry(0, 0, 1, 3)],
               "triangle": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}),
        json!({"kind": "derivative", "control_points": [[0], [1], [3]], "order": 1}),
        json!({"kind": "rational-tensor", "numerator": [[[1]], [[1]]], "denominator": [[1], [1]], "rectangle": [0, 1, 0, 1], "degree": [1, 0]}),
        json!({"kind": "rational-triangle", "total_degree": 1, "numerator": [[[0], [1]], [[1]]], "denominator": [[1, 0], [1]],
               "triangle": tri, "degree": 1}),
    ]
}

/// `blossom restrict` on `job`, in process: the answer, or the error line.
fn restrict(job: &Value) -> Result<Value, String> {
    let out = blossom_cli::jobs::run(&["restrict".into()], &mut job.to_string().as_bytes());
    if out.code == 0 {
        Ok(serde_json::from_str(&out.stdout).expect("JSON"))
    } else {
        assert_eq!(out.code, 2);
        assert!(out.stdout.is_empty());
        assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
        Err(out.stderr.trim_end().to_string())
    }
}

#[test]
fn every_kind_and_field_is_listed_and_read() {
    let jobs = every_kind();
    assert_eq!(jobs.len(), JOB_FIELDS().len());
    for ((kind, fields), job) in JOB_FIELDS().iter().zip(&jobs) {
        assert_eq!(job["kind"], json!(kind));
        let names: Vec<&str> = job
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        let mut sorted = names.clone();
        sorted.sort_unstable();
        let mut expected = fields.to_vec();
        expected.sort_unstable();
        assert_eq!(sorted, expected, "{kind}: the test job uses every field");
        assert!(shape(job).is_ok(), "{kind}");
        assert!(restrict(job).is_ok(), "{kind}: {:?}", restrict(job));
    }
    let kinds: Vec<&str> = kinds_of(Subcommand::Restrict).map(|k| k.name).collect();
    let mut listed: Vec<&str> = JOB_FIELDS().iter().map(|(k, _)| *k).collect();
    let mut all = kinds.clone();
    listed.sort_unstable();
    all.sort_unstable();
    assert_eq!(listed, all, "JOB_FIELDS lists every kind once");
}

#[test]
fn an_unknown_field_is_refused_in_every_kind() {
    for job in every_kind() {
        let kind = job["kind"].as_str().unwrap().to_string();
        // A field that no kind reads: the accepted names are listed.
        let mut extra = job.clone();
        extra["comment"] = json!("x");
        let line = restrict(&extra).unwrap_err();
        let all = JOB_FIELDS();
        let (_, fields) = all.iter().find(|(k, _)| *k == kind).unwrap();
        assert_eq!(
            line,
            format!(
                "error: comment: unknown field \"comment\" (expected {})",
                listed(fields)
            ),
            "{kind}"
        );
    }
}

#[test]
fn a_misspelt_field_is_named_before_it_is_missed() {
    for job in every_kind() {
        let kind = job["kind"].as_str().unwrap().to_string();
        for (name, value) in job.as_object().unwrap() {
            if name == "kind" {
                continue;
            }
            // The field with its last letter dropped: now it is missing too.
            let typo = &name[..name.len() - 1];
            let mut misspelt = Map::new();
            for (k, v) in job.as_object().unwrap() {
                let key = if k == name { typo } else { k.as_str() };
                misspelt.insert(key.to_string(), v.clone());
            }
            let misspelt = Value::Object(misspelt);
            let line = restrict(&misspelt).unwrap_err();
            assert_eq!(
                line,
                format!("error: {typo}: unknown field \"{typo}\" (did you mean \"{name}\"?)"),
                "{kind}: {value}"
            );
            // The same through the reader alone.
            let error = shape(&misspelt).unwrap_err();
            assert_eq!(error.field, typo);
        }
    }
}

#[test]
fn nested_objects_refuse_unknown_fields() {
    let jobs = every_kind();
    let find = |kind: &str| {
        jobs.iter()
            .find(|j| j["kind"] == json!(kind))
            .unwrap()
            .clone()
    };
    let mut spline = find("bspline");
    spline["pieces"][0]["coeficients"] = spline["pieces"][0]["coefficients"].take();
    spline["pieces"][0]
        .as_object_mut()
        .unwrap()
        .remove("coefficients");
    assert_eq!(
        restrict(&spline).unwrap_err(),
        "error: pieces[0].coeficients: unknown field \"coeficients\" (did you mean \"coefficients\"?)"
    );
    let mut net = find("bezier-triangle");
    net["control_points"][1]["weight"] = json!(1);
    assert_eq!(
        restrict(&net).unwrap_err(),
        "error: control_points[1].weight: unknown field \"weight\" (expected a, b, c or point)"
    );
    let mut net = find("bezier-triangle");
    let point = net["control_points"][2]["point"].take();
    net["control_points"][2]
        .as_object_mut()
        .unwrap()
        .remove("point");
    net["control_points"][2]["pont"] = point;
    assert_eq!(
        restrict(&net).unwrap_err(),
        "error: control_points[2].pont: unknown field \"pont\" (did you mean \"point\"?)"
    );
    // An entry that is not an object is the reader's to refuse, with its own message.
    net["control_points"][2] = json!([1]);
    assert!(shape(&net)
        .unwrap_err()
        .to_string()
        .starts_with("control_points[2]: expected an object"));
}

#[test]
fn a_job_without_its_kind_is_checked_against_every_kind() {
    let line = restrict(&json!({"knd": "curve", "coefficients": [[1]], "interval": [0, 1]}));
    assert_eq!(
        line.unwrap_err(),
        "error: knd: unknown field \"knd\" (did you mean \"kind\"?)"
    );
    // Fields of some kind, but no kind: the kind is what is missing.
    let line = restrict(&json!({"coefficients": [[1]], "interval": [0, 1]}));
    assert_eq!(line.unwrap_err(), "error: kind: missing field");
    // An unknown kind is named as such, whatever its fields.
    let line = restrict(&json!({"kind": "curv", "coefficients": [[1]], "whatever": 1}));
    assert!(line
        .unwrap_err()
        .starts_with("error: kind: unknown kind \"curv\" (did you mean \"curve\"?)"));
}

/// `blossom region` on `job`, in process: the error line.
fn region_error(job: &Value) -> String {
    let out = blossom_cli::jobs::run(&["region".into()], &mut job.to_string().as_bytes());
    assert_eq!(out.code, 2, "{}", out.stdout);
    out.stderr.trim_end().to_string()
}

#[test]
fn an_open_loop_names_the_later_curve_under_the_job_path() {
    let square = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, 1], [0, 0]]]]});
    let r = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, "1/2"], [0, 0]]]]});
    let job = json!({"kind": "boolean", "op": "union", "regions": [square, r]});
    assert_eq!(
        region_error(&job),
        "error: regions[1].loops[0][2]: starts at (1, 1/2), the previous curve ends at (1, 1)"
    );
    let r = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [0, 1]]]]});
    let job = json!({"kind": "winding", "region": r, "points": []});
    assert_eq!(
        region_error(&job),
        "error: region.loops[0][0]: starts at (0, 0), the previous curve ends at (0, 1)"
    );
}

/// Issue 47 (a friction): an open loop is quoted with its numbers as written in the job, not
/// as the exact value of the double nearest to them (`0.1`, not
/// `3602879701896397/36028797018963968`), under either arithmetic.
#[test]
fn an_open_loop_quotes_its_numbers_as_written() {
    let region = |args: &[&str], job: &Value| {
        let args: Vec<std::ffi::OsString> = args.iter().map(Into::into).collect();
        let out = blossom_cli::jobs::run(&args, &mut job.to_string().as_bytes());
        assert_eq!(out.code, 2, "{}", out.stdout);
        out.stderr.trim_end().to_string()
    };
    let r = json!({"loops": [[[[0, 0], [1, 0]], [[1, 0.1], [0, 0]]]]});
    let job = json!({"kind": "simplify", "region": r});
    assert_eq!(
        region(&["region", "--arithmetic", "f64"], &job),
        "error: region.loops[0][1]: starts at (1, 0.1), the previous curve ends at (1, 0)"
    );
    let r = json!({"loops": [[[["0.50", 0], [1, 0]], [[1, 0], [0, "1e-1"]]]]});
    let job = json!({"kind": "winding", "region": r, "points": []});
    let expected =
        "error: region.loops[0][0]: starts at (0.50, 0), the previous curve ends at (0, 1e-1)";
    assert_eq!(region(&["region"], &job), expected);
    assert_eq!(region(&["region", "--arithmetic", "f64"], &job), expected);
}

#[test]
fn a_triangle_with_too_few_nodes_names_its_nodes() {
    let good = json!({"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]]});
    let t = json!({"degree": 2, "nodes": [[0, 0], [1, 0], [0, 1]]});
    let job = json!({"kind": "triangle-triangle", "triangles": [good, t]});
    let e = region_error(&job);
    assert!(e.starts_with("error: triangles[1].nodes: "), "{e}");
    let t = json!({"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]], "node": 1});
    let job = json!({"kind": "triangle-triangle", "triangles": [t, good]});
    let e = region_error(&job);
    assert!(
        e.starts_with("error: triangles[0].node: unknown field"),
        "{e}"
    );
}
