//! `blossom region` driven as a process against the contract (the last section of
//! `docs/cli.md`), with every answer's invariants checked here, independently of the library:
//!
//! * every PARAM: `"value"` is the correctly rounded double of a root of `"polynomial"` in
//!   `"interval"` (an exact sign test at the half-way points to the neighbouring doubles), and
//!   `"exact"`, when given, is that root;
//! * the edges chain: the end of each edge (its input curve evaluated at `to`, by de
//!   Casteljau in exact rationals when the PARAM is rational, in doubles at the correctly
//!   rounded value otherwise) is where the next one starts, the last ending where the first
//!   starts; no edge is empty, and no two consecutive edges are pieces of one input curve that
//!   continue each other;
//! * `"hole"` agrees with the orientation (the shoelace of points sampled along the loop);
//! * `"area"` is `[lo, hi]` with `hi - lo <= 2^-40 B` and holds the area of the sampled loops
//!   (within the sampling error);
//! * membership of sample points in the answer (winding of the sampled loops) agrees with the
//!   operation applied to the inputs' memberships (winding of the sampled inputs), wherever a
//!   point is far enough from every boundary for the sampling not to matter;
//! * identities between the four booleans: |A - B| + |B - A| + |A ∩ B| = |A ∪ B| and
//!   xor = the two differences, as interval enclosures.
//!
//! Every kind of bad input is refused in one line naming the field, exit 2, nothing printed.
//! The exact oracle for straight-edged regions is `region_oracle.rs`.

use super::binary::{run_binary, Run};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde_json::{json, Value};

pub type Q = BigRational;

/// Runs `blossom region ARGS` on `input`.
pub fn run_region(args: &[&str], input: &str) -> Run {
    let mut all = vec!["region"];
    all.extend_from_slice(args);
    run_binary(&all, input.as_bytes())
}

/// The answer of `job`, checking the output contract: exit 0, one line of JSON, nothing on
/// standard error.
pub fn answer(args: &[&str], job: &Value) -> Value {
    let r = run_region(args, &job.to_string());
    assert_eq!(r.code, 0, "job {job} ({args:?}): {}", r.stderr);
    assert!(r.stderr.is_empty(), "{}", r.stderr);
    assert_eq!(r.stdout.lines().count(), 1, "{}", r.stdout);
    serde_json::from_str(&r.stdout).expect("JSON")
}

/// The error line of the refused `input`: exit 2, empty standard output, one line.
pub fn error(args: &[&str], input: &str) -> String {
    let r = run_region(args, input);
    assert_eq!(r.code, 2, "job {input} was accepted: {}", r.stdout);
    assert!(r.stdout.is_empty(), "{}", r.stdout);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(r.stderr.starts_with("error: "), "{}", r.stderr);
    r.stderr.trim_end().to_string()
}

/// An exact number of the job or the answer: an integer, `"p/q"`, `"p"`.
pub fn q(value: &Value) -> Q {
    match value {
        Value::Number(n) => Q::from_integer(n.to_string().parse().expect("an integer")),
        Value::String(text) => match text.split_once('/') {
            Some((p, d)) => Q::new(p.parse().unwrap(), d.parse().unwrap()),
            None => Q::from_integer(text.parse().unwrap()),
        },
        other => panic!("not a number: {other}"),
    }
}

pub fn int(n: i64) -> Q {
    Q::from_integer(n.into())
}

/// p(x) for ascending integer coefficients.
fn eval_poly(p: &[BigInt], x: &Q) -> Q {
    p.iter()
        .rev()
        .fold(Q::zero(), |acc, c| acc * x + Q::from_integer(c.clone()))
}

/// A PARAM, checked: its correctly rounded value and its exact value when rational.
#[derive(Clone, Debug)]
pub struct Param {
    pub value: f64,
    pub exact: Option<Q>,
    pub polynomial: Vec<BigInt>,
}

impl Param {
    /// Whether two PARAMs name the same number (decided exactly: equal rationals, or the
    /// same correctly rounded double, a common polynomial root and overlapping intervals is
    /// taken as the same root; the intervals of distinct roots of one square-free polynomial
    /// are disjoint).
    pub fn same(&self, other: &Param) -> bool {
        match (&self.exact, &other.exact) {
            (Some(a), Some(b)) => a == b,
            (None, None) => self.value == other.value && self.polynomial == other.polynomial,
            _ => false,
        }
    }
}

/// Reads and checks a PARAM (see the module documentation).
pub fn param(v: &Value) -> Param {
    let value = v["value"].as_f64().unwrap_or_else(|| panic!("value: {v}"));
    assert!(
        (0.0..=1.0).contains(&value),
        "a parameter outside [0, 1]: {v}"
    );
    let polynomial: Vec<BigInt> = v["polynomial"]
        .as_array()
        .unwrap_or_else(|| panic!("polynomial: {v}"))
        .iter()
        .map(|c| c.as_str().unwrap().parse().unwrap())
        .collect();
    assert!(polynomial.iter().any(|c| !c.is_zero()), "{v}");
    let (lo, hi) = (q(&v["interval"][0]), q(&v["interval"][1]));
    assert!(lo <= hi, "{v}");
    let exact = v["exact"].as_str().map(|_| q(&v["exact"]));
    if let Some(x) = &exact {
        assert!(eval_poly(&polynomial, x).is_zero(), "{v}");
        assert_eq!((&lo, &hi), (x, x), "{v}");
        assert_eq!(x.to_f64().unwrap(), value, "not the nearest double: {v}");
        // to_f64 of num-rational rounds correctly; the check above is an exact equality.
    } else {
        assert!(v["exact"].is_null(), "{v}");
        assert!(lo < hi, "{v}");
        let x = Q::from_float(value).unwrap();
        let neighbour = |bits: u64| Q::from_float(f64::from_bits(bits)).unwrap();
        let two = int(2);
        let below = if value > 0.0 {
            (x.clone() + neighbour(value.to_bits() - 1)) / &two
        } else {
            x.clone() - Q::new(1.into(), BigInt::from(2).pow(1100))
        };
        let above = (x.clone() + neighbour(value.to_bits() + 1)) / &two;
        let (fb, fa) = (
            eval_poly(&polynomial, &below),
            eval_poly(&polynomial, &above),
        );
        assert!(
            fb.is_zero() || fa.is_zero() || fb.is_positive() != fa.is_positive(),
            "no root within half an ulp of {value}: {v}"
        );
        assert!(lo <= above && below <= hi, "{v}");
    }
    Param {
        value,
        exact,
        polynomial,
    }
}

/// De Casteljau in exact rationals.
pub fn point_at(curve: &[[Q; 2]], t: &Q) -> [Q; 2] {
    let mut p: Vec<[Q; 2]> = curve.to_vec();
    let s = Q::one() - t;
    for level in (1..p.len()).rev() {
        for i in 0..level {
            let next = p[i + 1].clone();
            p[i] = [&p[i][0] * &s + &next[0] * t, &p[i][1] * &s + &next[1] * t];
        }
    }
    p[0].clone()
}

/// De Casteljau in doubles.
pub fn point_at_f64(curve: &[[f64; 2]], t: f64) -> [f64; 2] {
    let mut p = curve.to_vec();
    for level in (1..p.len()).rev() {
        for i in 0..level {
            p[i] = [
                p[i][0] * (1.0 - t) + p[i + 1][0] * t,
                p[i][1] * (1.0 - t) + p[i + 1][1] * t,
            ];
        }
    }
    p[0]
}

/// The control points of a curve of the job, exact.
pub fn curve_of(value: &Value) -> Vec<[Q; 2]> {
    value
        .as_array()
        .unwrap()
        .iter()
        .map(|p| [q(&p[0]), q(&p[1])])
        .collect()
}

pub fn to_f64(curve: &[[Q; 2]]) -> Vec<[f64; 2]> {
    curve
        .iter()
        .map(|p| [p[0].to_f64().unwrap(), p[1].to_f64().unwrap()])
        .collect()
}

/// The three edges of a TRIANGLE of the job, built here from the contract's node order: the
/// nodes are listed by increasing k, within it by increasing j (i = n - j - k).
pub fn triangle_edges(triangle: &Value) -> [Vec<[Q; 2]>; 3] {
    let n = triangle["degree"].as_u64().unwrap() as usize;
    let nodes = triangle["nodes"].as_array().unwrap();
    let mut by_jk = std::collections::HashMap::new();
    let mut listed = nodes.iter();
    for k in 0..=n {
        for j in 0..=n - k {
            let p = listed.next().expect("enough nodes");
            by_jk.insert((j, k), [q(&p[0]), q(&p[1])]);
        }
    }
    let at = |j: usize, k: usize| by_jk[&(j, k)].clone();
    [
        (0..=n).map(|j| at(j, 0)).collect(),
        (0..=n).map(|k| at(n - k, k)).collect(),
        (0..=n).map(|i| at(0, n - i)).collect(),
    ]
}

/// Every input curve of a job with its identifier in the answer's terms: `[i]` for
/// `triangle-triangle`, `[r, l, c]` for `boolean`.
pub fn input_curves(job: &Value) -> Vec<(Vec<u64>, Vec<[Q; 2]>)> {
    let mut out = Vec::new();
    if job["kind"] == "triangle-triangle" {
        for (t, triangle) in job["triangles"].as_array().unwrap().iter().enumerate() {
            for (e, edge) in triangle_edges(triangle).into_iter().enumerate() {
                out.push((vec![(3 * t + e) as u64], edge));
            }
        }
    } else {
        for (r, region) in job["regions"].as_array().unwrap().iter().enumerate() {
            for (l, lp) in region["loops"].as_array().unwrap().iter().enumerate() {
                for (c, curve) in lp.as_array().unwrap().iter().enumerate() {
                    out.push((vec![r as u64, l as u64, c as u64], curve_of(curve)));
                }
            }
        }
    }
    out
}

/// The identifier of an answer's edge.
fn edge_id(edge: &Value) -> Vec<u64> {
    if edge.get("region").is_some() {
        vec![
            edge["region"].as_u64().unwrap(),
            edge["loop"].as_u64().unwrap(),
            edge["curve"].as_u64().unwrap(),
        ]
    } else {
        vec![edge["curve"].as_u64().unwrap()]
    }
}

/// One edge of an answer, read and checked.
#[derive(Clone, Debug)]
pub struct Piece {
    pub id: Vec<u64>,
    pub curve: Vec<[Q; 2]>,
    pub from: Param,
    pub to: Param,
}

impl Piece {
    /// The point at a PARAM: exact when it is rational.
    fn at(&self, p: &Param) -> ([f64; 2], Option<[Q; 2]>) {
        match &p.exact {
            Some(t) => {
                let e = point_at(&self.curve, t);
                ([e[0].to_f64().unwrap(), e[1].to_f64().unwrap()], Some(e))
            }
            None => (point_at_f64(&to_f64(&self.curve), p.value), None),
        }
    }

    /// `count + 1` points along the piece, from `from` to `to`, in doubles.
    pub fn samples(&self, count: usize) -> Vec<[f64; 2]> {
        let curve = to_f64(&self.curve);
        (0..=count)
            .map(|i| {
                let u = i as f64 / count as f64;
                point_at_f64(
                    &curve,
                    self.from.value + (self.to.value - self.from.value) * u,
                )
            })
            .collect()
    }
}

/// The smallest box of every input control point: its width, height and area B.
pub fn input_box(job: &Value) -> (f64, f64, f64) {
    let curves = input_curves(job);
    let points = curves.iter().flat_map(|(_, c)| to_f64(c));
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    (w, h, w * h)
}

/// The loops of an answer as pieces, every invariant of the module documentation checked
/// except memberships; `tolerance` is the distance in doubles allowed between two chained
/// points of which one is at an irrational parameter.
pub fn checked_loops(job: &Value, answer: &Value) -> Vec<(bool, Vec<Piece>)> {
    assert_eq!(answer["kind"], job["kind"], "{answer}");
    let curves = input_curves(job);
    let (w, h, b) = input_box(job);
    let tolerance = 1e-9 * (w + h).max(1.0);
    let mut loops = Vec::new();
    for lp in answer["loops"].as_array().expect("loops") {
        let hole = lp["hole"].as_bool().expect("hole");
        let edges = lp["edges"].as_array().expect("edges");
        assert!(!edges.is_empty(), "an empty loop: {answer}");
        let pieces: Vec<Piece> = edges
            .iter()
            .map(|e| {
                let id = edge_id(e);
                let curve = curves
                    .iter()
                    .find(|(c, _)| *c == id)
                    .unwrap_or_else(|| panic!("no input curve {id:?}: {e}"))
                    .1
                    .clone();
                let piece = Piece {
                    id,
                    curve,
                    from: param(&e["from"]),
                    to: param(&e["to"]),
                };
                assert!(!piece.from.same(&piece.to), "an empty edge: {e}");
                piece
            })
            .collect();
        for (i, piece) in pieces.iter().enumerate() {
            let next = &pieces[(i + 1) % pieces.len()];
            let (end, end_exact) = piece.at(&piece.to);
            let (start, start_exact) = next.at(&next.from);
            match (end_exact, start_exact) {
                (Some(a), Some(b)) => {
                    assert_eq!(a, b, "edges {i} and {} do not chain: {answer}", i + 1)
                }
                _ => assert!(
                    (end[0] - start[0]).abs() <= tolerance
                        && (end[1] - start[1]).abs() <= tolerance,
                    "edges {i} and {} do not chain ({end:?} vs {start:?}): {answer}",
                    i + 1
                ),
            }
            if pieces.len() > 1 {
                let continues = piece.id == next.id
                    && piece.to.same(&next.from)
                    && ((piece.from.value < piece.to.value) == (next.from.value < next.to.value));
                assert!(
                    !continues,
                    "edges {i} and {} are one piece: {answer}",
                    i + 1
                );
            }
        }
        let area = sampled_area(&pieces);
        if area.abs() > 1e-6 * b.max(1e-300) {
            assert_eq!(
                hole,
                area < 0.0,
                "hole flag {hole} but signed area {area}: {answer}"
            );
        }
        loops.push((hole, pieces));
    }
    let area = &answer["area"];
    let (lo, hi) = (area[0].as_f64().unwrap(), area[1].as_f64().unwrap());
    assert!(lo <= hi, "{answer}");
    let allowed = if loops.is_empty() {
        0.0
    } else {
        b * 2f64.powi(-40)
    };
    assert!(
        hi - lo <= allowed,
        "area enclosure [{lo}, {hi}] wider than 2^-40 B = {allowed}"
    );
    let sampled: f64 = loops.iter().map(|(_, p)| sampled_area(p)).sum();
    assert!(
        sampled >= lo - 1e-4 * b - 1e-12 && sampled <= hi + 1e-4 * b + 1e-12,
        "sampled area {sampled} outside [{lo}, {hi}]: {answer}"
    );
    loops
}

/// The signed area of a loop of pieces, sampled (256 points a piece).
pub fn sampled_area(pieces: &[Piece]) -> f64 {
    shoelace(&sampled_polygon(pieces, 256))
}

pub fn sampled_polygon(pieces: &[Piece], per_piece: usize) -> Vec<[f64; 2]> {
    pieces
        .iter()
        .flat_map(|p| {
            let mut s = p.samples(per_piece);
            s.pop();
            s
        })
        .collect()
}

pub fn shoelace(polygon: &[[f64; 2]]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum::<f64>()
        / 2.0
}

/// The winding number of `p` around a closed polygon, and its distance to it.
pub fn winding_and_distance(polygon: &[[f64; 2]], p: [f64; 2]) -> (i64, f64) {
    let n = polygon.len();
    let mut winding = 0;
    let mut distance = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len2 = dx * dx + dy * dy;
        let u = if len2 > 0.0 {
            (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let (cx, cy) = (a[0] + u * dx - p[0], a[1] + u * dy - p[1]);
        distance = distance.min((cx * cx + cy * cy).sqrt());
        let cross = dx * (p[1] - a[1]) - dy * (p[0] - a[0]);
        if a[1] <= p[1] && b[1] > p[1] && cross > 0.0 {
            winding += 1;
        } else if a[1] > p[1] && b[1] <= p[1] && cross < 0.0 {
            winding -= 1;
        }
    }
    (winding, distance)
}

/// The sampled loops of a REGION of the job, its fill rule.
pub fn sampled_region(region: &Value) -> (Vec<Vec<[f64; 2]>>, bool) {
    let evenodd = region["fill"] == "evenodd";
    let loops = region["loops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|lp| {
            lp.as_array()
                .unwrap()
                .iter()
                .flat_map(|c| {
                    let curve = to_f64(&curve_of(c));
                    (0..256).map(move |i| point_at_f64(&curve, i as f64 / 256.0))
                })
                .collect()
        })
        .collect();
    (loops, evenodd)
}

/// Membership of `p` in sampled loops under a fill rule, or `None` when `p` is within
/// `margin` of a loop.
pub fn member(loops: &[Vec<[f64; 2]>], evenodd: bool, p: [f64; 2], margin: f64) -> Option<bool> {
    let mut winding = 0;
    for lp in loops {
        let (w, d) = winding_and_distance(lp, p);
        if d < margin {
            return None;
        }
        winding += w;
    }
    Some(if evenodd {
        winding % 2 != 0
    } else {
        winding != 0
    })
}

/// Whether the operation keeps a point of the given memberships.
pub fn op_keeps(op: &str, a: bool, b: bool) -> bool {
    match op {
        "intersection" => a && b,
        "union" => a || b,
        "difference" => a && !b,
        "xor" => a != b,
        other => panic!("op {other}"),
    }
}

/// Checks a `boolean` job's answer: the invariants, then membership of a grid of points.
pub fn check_boolean(args: &[&str], job: &Value) -> Value {
    let out = answer(args, job);
    let loops = checked_loops(job, &out);
    let result: Vec<Vec<[f64; 2]>> = loops.iter().map(|(_, p)| sampled_polygon(p, 256)).collect();
    let (a, fa) = sampled_region(&job["regions"][0]);
    let (b, fb) = sampled_region(&job["regions"][1]);
    let (w, h, _) = input_box(job);
    let margin = 1e-3 * (w + h);
    let origin = {
        let all = input_curves(job);
        let pts: Vec<[f64; 2]> = all.iter().flat_map(|(_, c)| to_f64(c)).collect();
        [
            pts.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min),
            pts.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min),
        ]
    };
    let op = job["op"].as_str().unwrap();
    for i in 0..=40 {
        for j in 0..=40 {
            let p = [
                origin[0] + w * (i as f64 + 0.37) / 40.0,
                origin[1] + h * (j as f64 + 0.61) / 40.0,
            ];
            let (Some(in_a), Some(in_b), Some(in_r)) = (
                member(&a, fa, p, margin),
                member(&b, fb, p, margin),
                member(&result, false, p, margin),
            ) else {
                continue;
            };
            assert_eq!(
                in_r,
                op_keeps(op, in_a, in_b),
                "{op}: the point {p:?} (in A: {in_a}, in B: {in_b}) is wrongly placed: {out}"
            );
        }
    }
    out
}

/// The `[lo, hi]` area enclosure of an answer.
pub fn area(answer: &Value) -> (f64, f64) {
    (
        answer["area"][0].as_f64().unwrap(),
        answer["area"][1].as_f64().unwrap(),
    )
}

/// Runs the four booleans of `a` and `b` (checked each) and checks the identities of their
/// areas as enclosures.
pub fn check_all_ops(a: &Value, b: &Value) -> [(f64, f64); 5] {
    let run = |op: &str, x: &Value, y: &Value| {
        area(&check_boolean(
            &[],
            &json!({"kind": "boolean", "op": op, "regions": [x, y]}),
        ))
    };
    let i = run("intersection", a, b);
    let u = run("union", a, b);
    let ab = run("difference", a, b);
    let ba = run("difference", b, a);
    let x = run("xor", a, b);
    let sum = |parts: &[(f64, f64)]| parts.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
    let slack = 1e-12 * (u.1.abs() + 1.0);
    let three = sum(&[i, ab, ba]);
    assert!(
        three.0 <= u.1 + slack && u.0 <= three.1 + slack,
        "|A∩B| + |A-B| + |B-A| = {three:?}, |A∪B| = {u:?}"
    );
    let two = sum(&[ab, ba]);
    assert!(
        two.0 <= x.1 + slack && x.0 <= two.1 + slack,
        "|A-B| + |B-A| = {two:?}, |A xor B| = {x:?}"
    );
    [i, u, ab, ba, x]
}

// ---------------------------------------------------------------------------------------------
// Shapes.

/// A polygon's loop of degree-1 curves through integer vertices.
pub fn polygon(vertices: &[[i64; 2]]) -> Value {
    let n = vertices.len();
    Value::Array(
        (0..n)
            .map(|i| json!([vertices[i], vertices[(i + 1) % n]]))
            .collect(),
    )
}

/// A rounded blob around (cx, cy) of radius r: four cubics through the points on the axes,
/// each handle 4r/7 long along the tangent (close to a circle; smooth and convex).
pub fn blob(cx: i64, cy: i64, r: i64) -> Value {
    // Sevenths: the centre and radius scaled by 7, then a handle of 4r.
    let (x, y, r) = (7 * cx, 7 * cy, 7 * r);
    let h = 4 * r / 7;
    let p = |a: i64, b: i64| json!([format!("{a}/7"), format!("{b}/7")]);
    json!([
        [p(x + r, y), p(x + r, y + h), p(x + h, y + r), p(x, y + r)],
        [p(x, y + r), p(x - h, y + r), p(x - r, y + h), p(x - r, y)],
        [p(x - r, y), p(x - r, y - h), p(x - h, y - r), p(x, y - r)],
        [p(x, y - r), p(x + h, y - r), p(x + r, y - h), p(x + r, y)]
    ])
}

fn region(loops: Vec<Value>) -> Value {
    json!({ "loops": loops })
}

fn square(x: i64, y: i64, side: i64) -> Value {
    polygon(&[[x, y], [x + side, y], [x + side, y + side], [x, y + side]])
}

// ---------------------------------------------------------------------------------------------
// Jobs.

#[test]
fn booleans_of_two_squares_have_the_areas_known_by_construction() {
    let a = region(vec![square(0, 0, 2)]);
    let b = region(vec![square(1, 1, 2)]);
    let [i, u, ab, ba, x] = check_all_ops(&a, &b);
    for (name, got, want) in [
        ("intersection", i, 1.0),
        ("union", u, 7.0),
        ("A - B", ab, 3.0),
        ("B - A", ba, 3.0),
        ("xor", x, 6.0),
    ] {
        assert!(
            got.0 <= want && want <= got.1,
            "{name}: {got:?}, want {want}"
        );
    }
    // The intersection is the square [1, 2]^2, one counter-clockwise loop of four edges.
    let out = answer(
        &[],
        &json!({"kind": "boolean", "op": "intersection", "regions": [a, b]}),
    );
    let loops = out["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 1, "{out}");
    assert_eq!(loops[0]["hole"], json!(false));
    assert_eq!(loops[0]["edges"].as_array().unwrap().len(), 4, "{out}");
}

#[test]
fn curved_regions_keep_every_invariant_and_identity() {
    let a = region(vec![blob(0, 0, 7)]);
    let b = region(vec![blob(5, 2, 6)]);
    check_all_ops(&a, &b);
    // A blob and a square that cuts it.
    let c = region(vec![square(-3, -10, 20)]);
    check_all_ops(&a, &c);
}

#[test]
fn nested_regions_give_a_hole_and_disjoint_ones_nothing() {
    let big = region(vec![square(0, 0, 10)]);
    let small = region(vec![square(3, 3, 2)]);
    let out = check_boolean(
        &[],
        &json!({"kind": "boolean", "op": "difference", "regions": [big, small]}),
    );
    let holes: Vec<bool> = out["loops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["hole"].as_bool().unwrap())
        .collect();
    assert_eq!(holes.len(), 2, "{out}");
    assert!(holes.contains(&true) && holes.contains(&false), "{out}");
    let (lo, hi) = area(&out);
    assert!(lo <= 96.0 && 96.0 <= hi, "{out}");
    // Disjoint: the intersection is empty, with the area [0, 0].
    let far = region(vec![square(20, 0, 2)]);
    let out = check_boolean(
        &[],
        &json!({"kind": "boolean", "op": "intersection", "regions": [big, far]}),
    );
    assert_eq!(out["loops"], json!([]), "{out}");
    assert_eq!(area(&out), (0.0, 0.0));
}

#[test]
fn regions_that_only_touch_have_an_empty_intersection_and_a_union_of_one_loop() {
    let a = region(vec![square(0, 0, 2)]);
    let b = region(vec![square(2, 0, 2)]);
    let out = check_boolean(
        &[],
        &json!({"kind": "boolean", "op": "intersection", "regions": [a, b]}),
    );
    assert_eq!(out["loops"], json!([]), "{out}");
    let out = check_boolean(
        &[],
        &json!({"kind": "boolean", "op": "union", "regions": [a, b]}),
    );
    assert_eq!(out["loops"].as_array().unwrap().len(), 1, "{out}");
    // Corner to corner: the union splits at the common point into two loops.
    let c = region(vec![square(2, 2, 2)]);
    let out = check_boolean(
        &[],
        &json!({"kind": "boolean", "op": "union", "regions": [a, c]}),
    );
    assert_eq!(out["loops"].as_array().unwrap().len(), 2, "{out}");
}

#[test]
fn identical_and_reversed_copies_are_reported_from_the_first_region() {
    let a = region(vec![blob(0, 0, 7)]);
    let reversed: Vec<Value> = blob(0, 0, 7)
        .as_array()
        .unwrap()
        .iter()
        .rev()
        .map(|c| Value::Array(c.as_array().unwrap().iter().rev().cloned().collect()))
        .collect();
    let b = region(vec![Value::Array(reversed)]);
    for other in [&a, &b] {
        for op in ["intersection", "union"] {
            let out = check_boolean(
                &[],
                &json!({"kind": "boolean", "op": op, "regions": [a, other]}),
            );
            let loops = out["loops"].as_array().unwrap();
            assert_eq!(loops.len(), 1, "{op}: {out}");
            for e in loops[0]["edges"].as_array().unwrap() {
                assert_eq!(e["region"], json!(0), "{op}: {out}");
            }
        }
        let out = check_boolean(
            &[],
            &json!({"kind": "boolean", "op": "xor", "regions": [a, other]}),
        );
        assert_eq!(out["loops"], json!([]), "{out}");
    }
}

#[test]
fn fill_rules_decide_a_doubly_wound_loop() {
    // The square's loop twice: winding 2 inside.
    let twice: Vec<Value> = square(0, 0, 2)
        .as_array()
        .unwrap()
        .iter()
        .chain(square(0, 0, 2).as_array().unwrap().iter())
        .cloned()
        .collect();
    let points = json!([[1, 1], [3, 3], [2, 1], ["1/2", "1/3"]]);
    let nonzero = answer(
        &[],
        &json!({"kind": "winding", "region": {"loops": [twice]}, "points": points}),
    );
    assert_eq!(
        nonzero,
        json!({"kind": "winding", "points": [
            {"position": "inside", "winding": 2},
            {"position": "outside", "winding": 0},
            {"position": "boundary", "winding": null},
            {"position": "inside", "winding": 2}
        ]})
    );
    let evenodd = answer(
        &[],
        &json!({"kind": "winding", "region": {"loops": [twice], "fill": "evenodd"}, "points": points}),
    );
    assert_eq!(
        evenodd["points"][0],
        json!({"position": "outside", "winding": 2})
    );
    // A clockwise loop: winding -1, inside under both rules.
    let clockwise = polygon(&[[0, 0], [0, 2], [2, 2], [2, 0]]);
    let out = answer(
        &[],
        &json!({"kind": "winding", "region": {"loops": [clockwise], "fill": "evenodd"}, "points": [[1, 1]]}),
    );
    assert_eq!(
        out["points"][0],
        json!({"position": "inside", "winding": -1})
    );
}

#[test]
fn winding_of_curved_loops_matches_sampled_loops_away_from_the_boundary() {
    let loops = vec![blob(0, 0, 7), blob(3, 1, 3), square(-2, -2, 3)];
    let r = json!({"loops": loops});
    let (sampled, _) = sampled_region(&r);
    let mut points = Vec::new();
    for i in 0..15 {
        for j in 0..15 {
            points.push(json!([
                format!("{}/3", 3 * i - 22),
                format!("{}/5", 5 * j - 37)
            ]));
        }
    }
    let out = answer(
        &[],
        &json!({"kind": "winding", "region": r, "points": points}),
    );
    let listed = out["points"].as_array().unwrap();
    assert_eq!(listed.len(), points.len());
    let mut compared = 0;
    for (p, entry) in points.iter().zip(listed) {
        let xy = [q(&p[0]).to_f64().unwrap(), q(&p[1]).to_f64().unwrap()];
        let mut winding = 0;
        let mut near = false;
        for lp in &sampled {
            let (w, d) = winding_and_distance(lp, xy);
            near |= d < 1e-2;
            winding += w;
        }
        if near {
            continue;
        }
        compared += 1;
        assert_eq!(entry["winding"], json!(winding), "{p}: {entry}");
        let position = if winding != 0 { "inside" } else { "outside" };
        assert_eq!(entry["position"], json!(position), "{p}: {entry}");
    }
    assert!(compared > 150, "only {compared} points compared");
}

#[test]
fn triangle_triangle_of_curved_triangles_keeps_every_invariant() {
    // Quadratic triangles with curved edges (nodes p200 p110 p020 p101 p011 p002).
    let t1 = json!({"degree": 2, "nodes": [[0, 0], [4, -1], [8, 0], [1, 4], [5, 3], [2, 8]]});
    let t2 = json!({"degree": 2, "nodes": [[3, -2], [7, 1], [9, 6], [1, 2], [6, 6], [2, 9]]});
    let job = json!({"kind": "triangle-triangle", "triangles": [t1, t2]});
    let out = answer(&[], &job);
    let loops = checked_loops(&job, &out);
    assert!(!loops.is_empty(), "{out}");
    // The answer against the two triangles' loops, sampled.
    let loop_of = |t: &Value| {
        let edges = triangle_edges(t);
        json!({"loops": [edges.iter().map(|e| e.iter().map(|p| json!([p[0].to_string(), p[1].to_string()])).collect::<Vec<_>>()).collect::<Vec<_>>()]})
    };
    let (a, _) = sampled_region(&loop_of(&t1));
    let (b, _) = sampled_region(&loop_of(&t2));
    let result: Vec<Vec<[f64; 2]>> = loops.iter().map(|(_, p)| sampled_polygon(p, 256)).collect();
    let mut compared = 0;
    for i in 0..50 {
        for j in 0..50 {
            let p = [
                -1.0 + 11.0 * (i as f64 + 0.3) / 50.0,
                -3.0 + 13.0 * (j as f64 + 0.7) / 50.0,
            ];
            if let (Some(x), Some(y), Some(z)) = (
                member(&a, false, p, 0.02),
                member(&b, false, p, 0.02),
                member(&result, false, p, 0.02),
            ) {
                compared += 1;
                assert_eq!(z, x && y, "{p:?}: {out}");
            }
        }
    }
    assert!(compared > 2000);
    // Under f64 the same numbers (integers) give the same answer.
    assert_eq!(answer(&["--arithmetic", "f64"], &job), out);
}

#[test]
fn triangle_triangle_edges_are_numbered_zero_to_five() {
    // Two linear triangles: [0, 4]^2 cut by its diagonal, and a triangle poking through it.
    let t1 = json!({"degree": 1, "nodes": [[0, 0], [4, 0], [0, 4]]});
    let t2 = json!({"degree": 1, "nodes": [[1, -1], [3, -1], [2, 6]]});
    let job = json!({"kind": "triangle-triangle", "triangles": [t1, t2]});
    let out = answer(&[], &job);
    let loops = checked_loops(&job, &out);
    assert_eq!(loops.len(), 1, "{out}");
    let ids: std::collections::BTreeSet<u64> = loops[0].1.iter().map(|p| p.id[0]).collect();
    // The bottom edge of T1 (0), its hypotenuse (1), and T2's two slanted sides (4, 5).
    assert_eq!(ids, [0, 1, 4, 5].into_iter().collect(), "{out}");
    for e in out["loops"][0]["edges"].as_array().unwrap() {
        assert!(e.get("region").is_none(), "{e}");
    }
}

#[test]
fn f64_arithmetic_reads_json_fractions_and_exact_refuses_them() {
    let a = json!({"loops": [[[[0, 0], [1.5, 0]], [[1.5, 0], [0, 1.5]], [[0, 1.5], [0, 0]]]]});
    let job = json!({"kind": "winding", "region": a, "points": [[0.25, 0.25]]});
    let out = answer(&["--arithmetic", "f64"], &job);
    assert_eq!(
        out["points"][0],
        json!({"position": "inside", "winding": 1})
    );
    let e = error(&[], &job.to_string());
    assert!(e.starts_with("error: region.loops[0][0][1][0]: "), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Bad input.

fn boolean_with(b: Value) -> String {
    json!({"kind": "boolean", "op": "union", "regions": [{"loops": [square(0, 0, 1)]}, b]})
        .to_string()
}

#[test]
fn every_kind_of_bad_input_is_named() {
    let cases: Vec<(String, &str)> = vec![
        ("{".into(), "error: input: invalid JSON"),
        ("[]".into(), "error: input: expected a JSON object"),
        (json!({"kind": "blob"}).to_string(), "error: kind: unknown kind \"blob\""),
        (json!({"kind": "boolean", "op": "union"}).to_string(), "error: regions: missing field"),
        (
            json!({"kind": "boolean", "op": "unoin", "regions": [{"loops": [square(0, 0, 1)]}, {"loops": [square(0, 0, 1)]}]}).to_string(),
            "error: op: unknown op \"unoin\" (did you mean \"union\"?)",
        ),
        (
            json!({"kind": "boolean", "op": "union", "regions": [{"loops": [square(0, 0, 1)]}]}).to_string(),
            "error: regions: expected 2 regions, found 1",
        ),
        (
            boolean_with(json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, "1/2"], [0, 0]]]]})),
            "error: regions[1].loops[0][2]: starts at (1, 1/2), the previous curve ends at (1, 1)",
        ),
        (
            boolean_with(json!({"loops": [[[[0, 0], [1, 0]], [[1, 0], [1, 1]]]]})),
            "error: regions[1].loops[0][0]: starts at (0, 0), the previous curve ends at (1, 1)",
        ),
        (boolean_with(json!({"loops": [[]]})), "error: regions[1].loops[0]: "),
        (boolean_with(json!({"loops": [square(0, 0, 1)], "fill": "odd"})), "error: regions[1].fill: unknown fill rule \"odd\""),
        (boolean_with(json!({"loops": [square(0, 0, 1)], "fil": "evenodd"})), "error: regions[1].fil: unknown field"),
        (boolean_with(json!({"loops": [[[[0, 0]]]]})), "error: regions[1].loops[0][0]: degree 0 is outside"),
        (boolean_with(json!({"loops": [[[[0, 0, 0], [1, 0, 0]]]]})), "error: regions[1].loops[0][0][0]: expected 2 coordinates"),
        (boolean_with(json!({"loops": [[[[0, "x"], [0, 0]]]]})), "error: regions[1].loops[0][0][0][1]: "),
        (boolean_with(json!({"loops": [[[[0, "1/0"], [0, 0]]]]})), "error: regions[1].loops[0][0][0][1]: "),
        (
            boolean_with(json!({"loops": [[(0..=21).map(|i| json!([i % 2, 0])).collect::<Vec<_>>()]]})),
            "error: regions[1].loops[0][0]: degree 21 is over the limit of 20",
        ),
        (
            json!({"kind": "triangle-triangle", "triangles": [{"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]]}, {"degree": 2, "nodes": [[0, 0], [1, 0], [0, 1]]}]}).to_string(),
            "error: triangles[1].nodes: ",
        ),
        (
            json!({"kind": "triangle-triangle", "triangles": [{"degree": 0, "nodes": [[0, 0]]}, {"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]]}]}).to_string(),
            "error: triangles[0].degree: degree 0 is outside",
        ),
        (
            json!({"kind": "triangle-triangle", "triangles": [{"degree": 21, "nodes": []}, {"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]]}]}).to_string(),
            "error: triangles[0].degree: degree 21 is over the limit of 20",
        ),
        (
            json!({"kind": "triangle-triangle", "triangles": [{"degree": 1, "nodes": [[0, 0], [1, 0], [0, 1]]}]}).to_string(),
            "error: triangles: expected 2 triangles, found 1",
        ),
        (
            json!({"kind": "winding", "region": {"loops": [square(0, 0, 1)]}, "points": [[0]]}).to_string(),
            "error: points[0]: expected 2 coordinates",
        ),
        (
            json!({"kind": "winding", "region": {"loops": [square(0, 0, 1)]}, "points": [[0, 0]], "extra": 1}).to_string(),
            "error: extra: unknown field",
        ),
    ];
    for (input, want) in cases {
        let e = error(&[], &input);
        assert!(e.starts_with(want), "{input}: {e}, want {want}");
    }
    // Bad arguments.
    let e = error(&["--arithmetic", "f32"], "{}");
    assert!(e.starts_with("error: --arithmetic: "), "{e}");
    let e = error(&["--bogus"], "{}");
    assert!(
        e.starts_with("error: --bogus: unknown option for region"),
        "{e}"
    );
}

#[test]
fn degree_ten_is_answered() {
    // A degree-10 lens: the curve (x(t), y(t)) over a line, against a square.
    let n = 10;
    let upper: Vec<Value> = (0..=n)
        .map(|i| {
            json!([
                i,
                if i == 0 || i == n {
                    0
                } else {
                    3 + (i % 3) as i64
                }
            ])
        })
        .collect();
    let lens = json!([upper, [[n, 0], [0, 0]]]);
    let a = json!({"loops": [lens]});
    let b = json!({"loops": [square(2, -1, 5)]});
    check_all_ops(&a, &b);
}

#[test]
fn work_over_the_budget_is_refused_naming_the_field() {
    let a = json!({"loops": [blob(0, 0, 7)]});
    let b = json!({"loops": [blob(5, 2, 6)]});
    let job = json!({"kind": "boolean", "op": "union", "regions": [a, b]});
    let e = error(&["--max-work", "1000"], &job.to_string());
    assert!(
        e.starts_with("error: regions: the job's work is estimated at ")
            && e.contains("--max-work"),
        "{e}"
    );
    answer(&[], &job);
    let e = error(&["--max-input", "10"], &job.to_string());
    assert!(
        e.starts_with("error: input: the input is longer than the limit"),
        "{e}"
    );
}

#[test]
fn winding_jobs_are_estimated_before_they_run() {
    // A loop of two degree-16 curves and 200 points: milliseconds, answered by default.
    let upper: Vec<Value> = (0..=16)
        .map(|i| {
            json!([
                i,
                if i == 0 || i == 16 {
                    0
                } else {
                    2 + (i % 5) as i64
                }
            ])
        })
        .collect();
    let lower: Vec<Value> = (0..=16)
        .map(|i| {
            json!([
                16 - i,
                if i == 0 || i == 16 {
                    0
                } else {
                    -1 - (i % 3) as i64
                }
            ])
        })
        .collect();
    let points: Vec<Value> = (0..200)
        .map(|i| json!([format!("{}/7", i % 20 * 6), format!("{}/5", i / 20 - 4)]))
        .collect();
    let job = json!({"kind": "winding", "region": {"loops": [[upper, lower]]}, "points": points});
    let out = answer(&[], &job);
    assert_eq!(out["points"].as_array().unwrap().len(), 200);
    let e = error(&["--max-work", "1000"], &job.to_string());
    assert!(
        e.starts_with("error: points: the job's work is estimated at ") && e.contains("--max-work"),
        "{e}"
    );
}

#[test]
fn inputs_up_to_10_kb_are_answered_or_refused_within_two_seconds() {
    // Two stars of cubic edges, as many as fit in 10 KB.
    let star = |cx: i64, k: usize| {
        let points: Vec<[i64; 2]> = (0..2 * k)
            .map(|i| {
                let angle = std::f64::consts::PI * i as f64 / k as f64;
                let r = if i % 2 == 0 { 100.0 } else { 45.0 };
                [
                    cx + (r * angle.cos()).round() as i64,
                    (r * angle.sin()).round() as i64,
                ]
            })
            .collect();
        let n = points.len();
        let curves: Vec<Value> = (0..n)
            .map(|i| {
                let (p, q) = (points[i], points[(i + 1) % n]);
                json!([
                    p,
                    [(2 * p[0] + q[0]) / 3 + 1, (2 * p[1] + q[1]) / 3],
                    [(p[0] + 2 * q[0]) / 3, (p[1] + 2 * q[1]) / 3 - 1],
                    q
                ])
            })
            .collect();
        json!({"loops": [curves]})
    };
    let mut k = 4;
    loop {
        let job =
            json!({"kind": "boolean", "op": "xor", "regions": [star(0, k + 1), star(30, k + 1)]});
        if job.to_string().len() > 10_240 {
            break;
        }
        k += 1;
    }
    let job = json!({"kind": "boolean", "op": "xor", "regions": [star(0, k), star(30, k)]});
    let text = job.to_string();
    assert!(text.len() <= 10_240);
    // In this process, timed by the thread's CPU time: the helpers and builds that share the
    // machine's 2 cores slow the wall clock by 2 to 8 times.
    let args: Vec<std::ffi::OsString> = vec!["region".into()];
    let cpu = super::cli_budget::thread_cpu();
    let outcome = blossom_cli::jobs::run(&args, &mut text.as_bytes());
    let took = super::cli_budget::thread_cpu().saturating_sub(cpu);
    assert!(
        outcome.code == 0 || outcome.stderr.contains("--max-work"),
        "{}",
        outcome.stderr
    );
    assert!(
        took.as_secs_f64() < 2.0,
        "{k} points a star: {took:?} of CPU time"
    );
}

#[test]
fn help_describes_the_jobs() {
    let r = run_region(&["--help"], "");
    assert_eq!(r.code, 0);
    for needle in [
        "triangle-triangle",
        "boolean",
        "winding",
        "--max-work",
        "evenodd",
        "degree",
    ] {
        assert!(r.stdout.contains(needle), "{needle}: {}", r.stdout);
    }
    let r = run_binary(&["--help"], b"");
    assert!(r.stdout.contains("blossom region"), "{}", r.stdout);
}
