//! `blossom region` on straight-edged regions against an independent exact oracle written
//! here, sharing nothing with the library:
//!
//! **Slab decomposition in exact rationals.** Cut the plane at the x-coordinate of every
//! vertex and of every crossing of two segments. Inside one slab no two segments cross, so the
//! segments spanning it are ordered by their height at the slab's middle, and between two
//! consecutive ones lies a trapezoid with constant winding numbers around A and around B
//! (going up across a segment directed left to right adds one, right to left subtracts one).
//! The fill rules decide membership in A and B, the operation membership in the result, and
//! the result's area is the exact sum of its trapezoids. Vertical segments bound slabs and
//! add nothing.
//!
//! Against it, for every case: the answer's edges are pieces of the input segments between
//! rational parameters (a straight input curve, even degree-elevated, is linear in its
//! parameter, so every crossing is rational), so the answer is an exact polygon: its exact
//! area (the shoelace sum over all edges) must equal the oracle's area exactly and lie in the
//! answer's `"area"` enclosure; its loops must be simple (no two edges of a loop meet except
//! consecutive ones at their common end, no two loops share a stretch or cross); and the
//! membership of sample points in it (its exact winding number) must be the operation on the
//! inputs' exact memberships (the winding number by a downward ray, half-open at vertices).
//! The `winding` job's numbers are compared with the same exact ray count.
//!
//! The random polygons have their vertices on a small integer grid, so that shared edges,
//! collinear overlaps, vertices on edges, touching corners and spikes retracing themselves are
//! common; some curves are degree-elevated (their control points evenly spaced on the segment)
//! or split in two at a grid point. `REGION_ORACLE_CASES=N` runs N random cases instead of 300.

use super::cli_region::{answer, checked_loops, int, q, Q};
use super::common::Rng;
use num_traits::{Signed, Zero};
use serde_json::{json, Value};
use std::cmp::Ordering;

/// The vertices of a polygon on the grid.
type Vertices = Vec<[i64; 2]>;

/// A directed segment of region `region` (0 for A, 1 for B).
#[derive(Clone, Debug)]
struct Seg {
    a: [Q; 2],
    b: [Q; 2],
    region: usize,
}

/// (b - a) x (c - a).
fn cross(a: &[Q; 2], b: &[Q; 2], c: &[Q; 2]) -> Q {
    (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])
}

/// The crossing point of two non-parallel segments' lines, if it lies on both segments.
fn crossing(s: &Seg, t: &Seg) -> Option<[Q; 2]> {
    let d1 = [&s.b[0] - &s.a[0], &s.b[1] - &s.a[1]];
    let d2 = [&t.b[0] - &t.a[0], &t.b[1] - &t.a[1]];
    let den = &d1[0] * &d2[1] - &d1[1] * &d2[0];
    if den.is_zero() {
        return None;
    }
    let w = [&t.a[0] - &s.a[0], &t.a[1] - &s.a[1]];
    let u = (&w[0] * &d2[1] - &w[1] * &d2[0]) / &den;
    let v = (&w[0] * &d1[1] - &w[1] * &d1[0]) / &den;
    let unit = |x: &Q| !x.is_negative() && *x <= int(1);
    (unit(&u) && unit(&v)).then(|| [&s.a[0] + &d1[0] * &u, &s.a[1] + &d1[1] * &u])
}

/// The height of a non-vertical segment at x.
fn height(s: &Seg, x: &Q) -> Q {
    &s.a[1] + (&s.b[1] - &s.a[1]) * (x - &s.a[0]) / (&s.b[0] - &s.a[0])
}

fn inside(winding: i64, evenodd: bool) -> bool {
    if evenodd {
        winding % 2 != 0
    } else {
        winding != 0
    }
}

fn keeps(op: &str, a: bool, b: bool) -> bool {
    match op {
        "intersection" => a && b,
        "union" => a || b,
        "difference" => a && !b,
        "xor" => a != b,
        _ => unreachable!(),
    }
}

/// The exact area of `op` applied to the regions of `segs` (fill rules `evenodd[r]`).
fn oracle_area(segs: &[Seg], evenodd: [bool; 2], op: &str) -> Q {
    let mut xs: Vec<Q> = segs
        .iter()
        .flat_map(|s| [s.a[0].clone(), s.b[0].clone()])
        .collect();
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            if let Some(p) = crossing(&segs[i], &segs[j]) {
                xs.push(p[0].clone());
            }
        }
    }
    xs.sort();
    xs.dedup();
    let mut total = Q::zero();
    for w in xs.windows(2) {
        let (x0, x1) = (&w[0], &w[1]);
        let xm = (x0 + x1) / int(2);
        // (height at the middle, at the left, at the right, region, direction)
        let mut spanning: Vec<(Q, Q, Q, usize, i64)> = segs
            .iter()
            .filter(|s| s.a[0] != s.b[0])
            .filter(|s| {
                let (lo, hi) = if s.a[0] < s.b[0] {
                    (&s.a[0], &s.b[0])
                } else {
                    (&s.b[0], &s.a[0])
                };
                lo <= x0 && x1 <= hi
            })
            .map(|s| {
                let dir = if s.a[0] < s.b[0] { 1 } else { -1 };
                (height(s, &xm), height(s, x0), height(s, x1), s.region, dir)
            })
            .collect();
        spanning.sort_by(|p, q| p.0.cmp(&q.0));
        let mut winding = [0i64; 2];
        let mut k = 0;
        while k < spanning.len() {
            let mut next = k;
            while next < spanning.len() && spanning[next].0 == spanning[k].0 {
                winding[spanning[next].3] += spanning[next].4;
                next += 1;
            }
            if next < spanning.len() {
                let kept = keeps(
                    op,
                    inside(winding[0], evenodd[0]),
                    inside(winding[1], evenodd[1]),
                );
                if kept {
                    let (lo, hi) = (&spanning[k], &spanning[next]);
                    total += (x1 - x0) * ((&hi.1 - &lo.1) + (&hi.2 - &lo.2)) / int(2);
                }
            }
            k = next;
        }
    }
    total
}

/// Whether `p` lies on the segment `s`.
fn on_segment(s: &Seg, p: &[Q; 2]) -> bool {
    cross(&s.a, &s.b, p).is_zero()
        && (p[0] >= s.a[0].clone().min(s.b[0].clone()))
        && (p[0] <= s.a[0].clone().max(s.b[0].clone()))
        && (p[1] >= s.a[1].clone().min(s.b[1].clone()))
        && (p[1] <= s.a[1].clone().max(s.b[1].clone()))
}

/// The exact winding number of `p` around the segments of `region` (a downward ray,
/// half-open in x at vertices), or `None` when `p` lies on one of them.
fn ray_winding(segs: &[Seg], region: usize, p: &[Q; 2]) -> Option<i64> {
    let mut w = 0;
    for s in segs.iter().filter(|s| s.region == region) {
        if on_segment(s, p) {
            return None;
        }
        if s.a[0] == s.b[0] {
            continue;
        }
        let (lo, hi, dir) = if s.a[0] < s.b[0] {
            (&s.a[0], &s.b[0], 1)
        } else {
            (&s.b[0], &s.a[0], -1)
        };
        if *lo <= p[0] && p[0] < *hi && height(s, &p[0]) < p[1] {
            w += dir;
        }
    }
    Some(w)
}

/// How two segments meet: not at all, at one point, or along a stretch.
#[derive(PartialEq, Debug)]
enum Meeting {
    Apart,
    Point([Q; 2]),
    Stretch,
}

fn meet(s: &Seg, t: &Seg) -> Meeting {
    if cross(&s.a, &s.b, &t.a).is_zero() && cross(&s.a, &s.b, &t.b).is_zero() {
        // Collinear: the common part of the two ranges along the line.
        let axis = if s.a[0] != s.b[0] { 0 } else { 1 };
        let range = |g: &Seg| {
            if g.a[axis] < g.b[axis] {
                (g.a.clone(), g.b.clone())
            } else {
                (g.b.clone(), g.a.clone())
            }
        };
        let ((s0, s1), (t0, t1)) = (range(s), range(t));
        let lo = if s0[axis] > t0[axis] { s0 } else { t0 };
        let hi = if s1[axis] < t1[axis] { s1 } else { t1 };
        return match lo[axis].cmp(&hi[axis]) {
            Ordering::Less => Meeting::Stretch,
            Ordering::Equal => Meeting::Point(lo),
            Ordering::Greater => Meeting::Apart,
        };
    }
    match crossing(s, t) {
        Some(p) => Meeting::Point(p),
        None => Meeting::Apart,
    }
}

/// The answer's loops as exact segments, simplicity checked: within a loop only consecutive
/// edges meet, at their common end; two loops share no stretch and never cross (they may
/// touch at a point).
fn answer_polygon(job: &Value, out: &Value) -> Vec<Vec<Seg>> {
    let loops = checked_loops(job, out);
    let polygon: Vec<Vec<Seg>> = loops
        .iter()
        .map(|(_, pieces)| {
            pieces
                .iter()
                .map(|p| {
                    let (from, to) = (
                        p.from
                            .exact
                            .clone()
                            .expect("a rational parameter on a straight curve"),
                        p.to.exact
                            .clone()
                            .expect("a rational parameter on a straight curve"),
                    );
                    Seg {
                        a: super::cli_region::point_at(&p.curve, &from),
                        b: super::cli_region::point_at(&p.curve, &to),
                        region: 0,
                    }
                })
                .collect()
        })
        .collect();
    for (l, lp) in polygon.iter().enumerate() {
        let n = lp.len();
        for i in 0..n {
            for j in i + 1..n {
                let m = meet(&lp[i], &lp[j]);
                let adjacent = j == i + 1 || (i == 0 && j == n - 1);
                if adjacent && n > 2 {
                    let common = if j == i + 1 { &lp[i].b } else { &lp[j].b };
                    assert!(
                        m == Meeting::Point(common.clone()) || (n == 2 && m == Meeting::Stretch),
                        "loop {l}: edges {i} and {j} meet as {m:?}: {out}"
                    );
                } else if n > 2 {
                    assert_eq!(m, Meeting::Apart, "loop {l}: edges {i} and {j}: {out}");
                }
            }
        }
        assert!(n >= 3, "a loop of {n} straight edges has no area: {out}");
    }
    for (l, a) in polygon.iter().enumerate() {
        for b in &polygon[l + 1..] {
            for s in a {
                for t in b {
                    match meet(s, t) {
                        Meeting::Stretch => panic!("loops share a stretch: {out}"),
                        // Loops may touch at a point, never cross: two segments meeting at
                        // a point inside both (not collinear) cross.
                        Meeting::Point(p) => {
                            let end = |g: &Seg| g.a == p || g.b == p;
                            assert!(end(s) || end(t), "loops cross at {p:?}: {out}");
                        }
                        Meeting::Apart => {}
                    }
                }
            }
        }
    }
    polygon
}

/// The exact area of a polygon's loops (shoelace over every edge).
fn polygon_area(polygon: &[Vec<Seg>]) -> Q {
    polygon
        .iter()
        .flatten()
        .map(|s| &s.a[0] * &s.b[1] - &s.a[1] * &s.b[0])
        .fold(Q::zero(), |acc, x| acc + x)
        / int(2)
}

/// Compares one job's answer with the oracle; `regions` as segments with their fill rules.
/// Returns the oracle's area.
fn compare(job: &Value, segs: &[Seg], evenodd: [bool; 2], op: &str, samples: &[[Q; 2]]) -> Q {
    let out = answer(&[], job);
    let polygon = answer_polygon(job, &out);
    let want = oracle_area(segs, evenodd, op);
    let got = polygon_area(&polygon);
    assert_eq!(
        got, want,
        "area {got} but the oracle says {want}: {job} -> {out}"
    );
    let (lo, hi) = (
        Q::from_float(out["area"][0].as_f64().unwrap()).unwrap(),
        Q::from_float(out["area"][1].as_f64().unwrap()).unwrap(),
    );
    assert!(
        lo <= want && want <= hi,
        "the enclosure misses {want}: {out}"
    );
    let result: Vec<Seg> = polygon.into_iter().flatten().collect();
    for p in samples {
        let (Some(wa), Some(wb), Some(wr)) = (
            ray_winding(segs, 0, p),
            ray_winding(segs, 1, p),
            ray_winding(&result, 0, p),
        ) else {
            continue;
        };
        let expected = keeps(op, inside(wa, evenodd[0]), inside(wb, evenodd[1]));
        assert!(
            wr == 0 || wr == 1,
            "winding {wr} of the answer's simple loops at {p:?}: {out}"
        );
        assert_eq!(
            wr == 1,
            expected,
            "{p:?} (A: {wa}, B: {wb}) misplaced: {job} -> {out}"
        );
    }
    want
}

/// A straight curve from a to b as degree `degree` control points, evenly spaced.
fn straight(a: [i64; 2], b: [i64; 2], degree: usize) -> Value {
    Value::Array(
        (0..=degree)
            .map(|i| {
                let at = |k: usize| {
                    let v = a[k] * (degree - i) as i64 + b[k] * i as i64;
                    json!(format!("{v}/{degree}"))
                };
                json!([at(0), at(1)])
            })
            .collect(),
    )
}

/// A random loop on the grid: its vertices and its curves (some degree-elevated, some split).
fn random_loop(rng: &mut Rng, grid: i64, region: usize, segs: &mut Vec<Seg>) -> Value {
    let count = 3 + (rng.next() % 4) as usize;
    let mut vertices: Vec<[i64; 2]> = Vec::new();
    while vertices.len() < count {
        let v = [
            (rng.next() % (grid as u64 + 1)) as i64,
            (rng.next() % (grid as u64 + 1)) as i64,
        ];
        if vertices.last() != Some(&v) {
            vertices.push(v);
        }
    }
    if vertices[0] == vertices[count - 1] {
        vertices.pop();
    }
    let n = vertices.len();
    let mut curves = Vec::new();
    for i in 0..n {
        let (a, b) = (vertices[i], vertices[(i + 1) % n]);
        let pt = |v: [i64; 2]| [int(v[0]), int(v[1])];
        segs.push(Seg {
            a: pt(a),
            b: pt(b),
            region,
        });
        let degree = [1, 1, 1, 2, 3][(rng.next() % 5) as usize];
        let mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
        let splits = rng.next().is_multiple_of(4)
            && (a[0] + b[0]) % 2 == 0
            && (a[1] + b[1]) % 2 == 0
            && mid != a
            && mid != b;
        if splits {
            curves.push(straight(a, mid, degree));
            curves.push(straight(mid, b, 1));
        } else {
            curves.push(straight(a, b, degree));
        }
    }
    Value::Array(curves)
}

/// Points of the grid's cells at thirds and sevenths: on no grid line, often on slanted ones.
fn sample_points(grid: i64) -> Vec<[Q; 2]> {
    let mut out = Vec::new();
    for i in 0..=(3 * grid) {
        for j in 0..=(7 * grid) {
            out.push([Q::new(i.into(), 3.into()), Q::new(j.into(), 7.into())]);
        }
    }
    out
}

#[test]
fn random_grid_polygons_match_the_slab_oracle() {
    let cases: usize = std::env::var("REGION_ORACLE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300);
    let mut rng = Rng(0x5eed_0040);
    let ops = ["intersection", "union", "difference", "xor"];
    let mut answered_with_area = 0;
    for case in 0..cases {
        let grid = 3 + (case % 3) as i64;
        let mut segs = Vec::new();
        let mut regions = Vec::new();
        let mut evenodd = [false; 2];
        for (r, flag) in evenodd.iter_mut().enumerate() {
            let loops_count = 1 + rng.next().is_multiple_of(3) as usize;
            let loops: Vec<Value> = (0..loops_count)
                .map(|_| random_loop(&mut rng, grid, r, &mut segs))
                .collect();
            *flag = rng.next().is_multiple_of(2);
            regions
                .push(json!({"loops": loops, "fill": if *flag { "evenodd" } else { "nonzero" }}));
        }
        let op = ops[case % 4];
        let job = json!({"kind": "boolean", "op": op, "regions": regions});
        if !compare(&job, &segs, evenodd, op, &sample_points(grid)).is_zero() {
            answered_with_area += 1;
        }
    }
    // Not a vacuous comparison of empty answers.
    assert!(
        answered_with_area * 2 > cases,
        "only {answered_with_area} of {cases} results have an area"
    );
}

#[test]
fn shared_edges_reversed_copies_and_vertices_on_edges_match_the_oracle() {
    let square = |x: i64, y: i64, s: i64| vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
    let cases: Vec<(Vertices, Vertices)> = vec![
        // The same square; its reversed copy; a half sharing two edges; a T-junction.
        (square(0, 0, 4), square(0, 0, 4)),
        (square(0, 0, 4), square(0, 0, 4).into_iter().rev().collect()),
        (square(0, 0, 4), vec![[0, 0], [2, 0], [2, 4], [0, 4]]),
        (square(0, 0, 4), vec![[4, 1], [6, 1], [6, 3], [4, 3]]),
        // Collinear partial overlap of the bottom edges, and a vertex on an edge.
        (square(0, 0, 4), vec![[2, 0], [6, 0], [6, -2], [2, -2]]),
        (square(0, 0, 4), vec![[2, 4], [1, 6], [3, 6]]),
        // A spike that retraces itself, and a bow tie crossing itself.
        (
            vec![[0, 0], [4, 0], [4, 4], [2, 2], [4, 4], [0, 4]],
            square(1, 1, 2),
        ),
        (vec![[0, 0], [4, 4], [4, 0], [0, 4]], square(1, 0, 2)),
    ];
    for (a, b) in cases {
        for op in ["intersection", "union", "difference", "xor"] {
            for degree in [1, 3] {
                for (fa, fb) in [(false, false), (true, false), (false, true)] {
                    let mut segs = Vec::new();
                    let mut regions = Vec::new();
                    for (r, (poly, eo)) in [(&a, fa), (&b, fb)].into_iter().enumerate() {
                        let n = poly.len();
                        let curves: Vec<Value> = (0..n)
                            .map(|i| {
                                let (p, q) = (poly[i], poly[(i + 1) % n]);
                                segs.push(Seg {
                                    a: [int(p[0]), int(p[1])],
                                    b: [int(q[0]), int(q[1])],
                                    region: r,
                                });
                                straight(p, q, degree)
                            })
                            .collect();
                        regions.push(json!({"loops": [curves], "fill": if eo { "evenodd" } else { "nonzero" }}));
                    }
                    let job = json!({"kind": "boolean", "op": op, "regions": regions});
                    let samples: Vec<[Q; 2]> = (0..=24)
                        .flat_map(|i| {
                            (0..=21).map(move |j| {
                                [
                                    Q::new((i - 3).into(), 3.into()),
                                    Q::new((j - 7).into(), 2.into()),
                                ]
                            })
                        })
                        .filter(|p| p[1] != Q::zero())
                        .collect();
                    compare(&job, &segs, [fa, fb], op, &samples);
                }
            }
        }
    }
}

#[test]
fn straight_triangles_match_the_oracle() {
    let mut rng = Rng(0x7417_0040);
    for case in 0..120 {
        let mut segs = Vec::new();
        let mut triangles = Vec::new();
        for r in 0..2 {
            // Three grid corners (possibly clockwise, possibly degenerate) and a degree.
            let corner = |rng: &mut Rng| [(rng.next() % 5) as i64, (rng.next() % 5) as i64];
            let (a, b, c) = (corner(&mut rng), corner(&mut rng), corner(&mut rng));
            let n = 1 + (case % 3);
            // Node p_ijk = (i A + j B + k C) / n, listed by increasing k, then j.
            let mut nodes = Vec::new();
            for k in 0..=n {
                for j in 0..=n - k {
                    let i = n - j - k;
                    let at = |d: usize| {
                        let v = a[d] * i as i64 + b[d] * j as i64 + c[d] * k as i64;
                        json!(format!("{v}/{n}"))
                    };
                    nodes.push(json!([at(0), at(1)]));
                }
            }
            for (p, q) in [(a, b), (b, c), (c, a)] {
                segs.push(Seg {
                    a: [int(p[0]), int(p[1])],
                    b: [int(q[0]), int(q[1])],
                    region: r,
                });
            }
            triangles.push(json!({"degree": n, "nodes": nodes}));
        }
        let job = json!({"kind": "triangle-triangle", "triangles": triangles});
        compare(
            &job,
            &segs,
            [false, false],
            "intersection",
            &sample_points(4),
        );
    }
}

#[test]
fn the_winding_job_matches_the_exact_ray_count() {
    let mut rng = Rng(0x3141_0040);
    for _ in 0..60 {
        let mut segs = Vec::new();
        let loops: Vec<Value> = (0..2)
            .map(|_| random_loop(&mut rng, 4, 0, &mut segs))
            .collect();
        let evenodd = rng.next().is_multiple_of(2);
        let samples: Vec<[Q; 2]> = (0..=8)
            .flat_map(|i| {
                (0..=8).map(move |j| [Q::new(i.into(), 2.into()), Q::new(j.into(), 2.into())])
            })
            .collect();
        let points: Vec<Value> = samples
            .iter()
            .map(|p| json!([p[0].to_string(), p[1].to_string()]))
            .collect();
        let job = json!({"kind": "winding", "region": {"loops": loops, "fill": if evenodd { "evenodd" } else { "nonzero" }}, "points": points});
        let out = answer(&[], &job);
        for (p, entry) in samples.iter().zip(out["points"].as_array().unwrap()) {
            match ray_winding(&segs, 0, p) {
                None => assert_eq!(
                    entry,
                    &json!({"position": "boundary", "winding": null}),
                    "{p:?}: {job}"
                ),
                Some(w) => {
                    let position = if inside(w, evenodd) {
                        "inside"
                    } else {
                        "outside"
                    };
                    assert_eq!(
                        entry,
                        &json!({"position": position, "winding": w}),
                        "{p:?}: {job}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_oracle_itself_on_hand_computed_cases() {
    // Two squares overlapping in a unit square; a bow tie of two triangles of area 1 each.
    let seg = |a: [i64; 2], b: [i64; 2], region| Seg {
        a: [int(a[0]), int(a[1])],
        b: [int(b[0]), int(b[1])],
        region,
    };
    let square = |x: i64, y: i64, r| {
        vec![
            seg([x, y], [x + 2, y], r),
            seg([x + 2, y], [x + 2, y + 2], r),
            seg([x + 2, y + 2], [x, y + 2], r),
            seg([x, y + 2], [x, y], r),
        ]
    };
    let mut segs = square(0, 0, 0);
    segs.extend(square(1, 1, 1));
    assert_eq!(oracle_area(&segs, [false, false], "intersection"), int(1));
    assert_eq!(oracle_area(&segs, [false, false], "union"), int(7));
    assert_eq!(oracle_area(&segs, [false, false], "xor"), int(6));
    assert_eq!(oracle_area(&segs, [false, false], "difference"), int(3));
    let bow = vec![
        seg([0, 0], [2, 2], 0),
        seg([2, 2], [2, 0], 0),
        seg([2, 0], [0, 2], 0),
        seg([0, 2], [0, 0], 0),
    ];
    assert_eq!(oracle_area(&bow, [false, false], "difference"), int(2));
    // The left triangle runs counter-clockwise, the right one clockwise.
    assert_eq!(
        ray_winding(&bow, 0, &[q(&json!("1/2")), q(&json!(1))]),
        Some(1)
    );
    assert_eq!(
        ray_winding(&bow, 0, &[q(&json!("3/2")), q(&json!(1))]),
        Some(-1)
    );
    assert_eq!(ray_winding(&bow, 0, &[int(1), int(1)]), None);
}
