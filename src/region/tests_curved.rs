//! Curved cases: identities between the areas of the four operations, and membership of
//! sample points in the result (a fine polyline of the result's loops, in doubles, away from
//! the boundary) against the exact positions of the points in the inputs.

use super::tests::{assert_well_formed, cup, q, wavy};
use super::{boolean, BooleanOp, FillRule, Position, Region, RegionResult};
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::array::Bezier;

fn p(x: Rational, y: Rational) -> [Rational; 2] {
    [x, y]
}

/// Four cubics close to the circle of centre (cx, cy) and radius r (all over d), rational.
fn circle(cx: i64, cy: i64, r: i64, d: i64) -> Region {
    let k = |v: i64| q(v, d);
    let m = r * 55 / 100; // the usual 0.55 r handle, truncated: still a smooth closed loop
    let pts = [
        [
            (cx + r, cy),
            (cx + r, cy + m),
            (cx + m, cy + r),
            (cx, cy + r),
        ],
        [
            (cx, cy + r),
            (cx - m, cy + r),
            (cx - r, cy + m),
            (cx - r, cy),
        ],
        [
            (cx - r, cy),
            (cx - r, cy - m),
            (cx - m, cy - r),
            (cx, cy - r),
        ],
        [
            (cx, cy - r),
            (cx + m, cy - r),
            (cx + r, cy - m),
            (cx + r, cy),
        ],
    ];
    let curves = pts
        .iter()
        .map(|c| Bezier::new(c.iter().map(|&(x, y)| p(k(x), k(y))).collect()).unwrap())
        .collect();
    Region::new(vec![curves], FillRule::NonZero).unwrap()
}

/// A closed cubic (a teardrop): one curve whose end is its start.
fn teardrop() -> Region {
    let c = Bezier::new(vec![
        p(q(0, 1), q(0, 1)),
        p(q(4, 1), q(4, 1)),
        p(q(-4, 1), q(4, 1)),
        p(q(0, 1), q(0, 1)),
    ])
    .unwrap();
    Region::new(vec![vec![c]], FillRule::NonZero).unwrap()
}

/// A cubic with a loop, closed by a line, under `fill`.
fn looped(fill: FillRule) -> Region {
    let c = Bezier::new(vec![
        p(q(0, 1), q(0, 1)),
        p(q(5, 1), q(4, 1)),
        p(q(-3, 1), q(4, 1)),
        p(q(2, 1), q(0, 1)),
    ])
    .unwrap();
    let l = Bezier::new(vec![p(q(2, 1), q(0, 1)), p(q(0, 1), q(0, 1))]).unwrap();
    Region::new(vec![vec![c, l]], fill).unwrap()
}

/// {y >= x^2, y <= 4, x >= 0}: shares the parabola's piece 0 <= x <= 1 with `cup(1, 1, false)`.
fn half_cup() -> Region {
    let quad = Bezier::new(vec![
        p(q(0, 1), q(0, 1)),
        p(q(1, 1), q(0, 1)),
        p(q(2, 1), q(4, 1)),
    ])
    .unwrap();
    let top = Bezier::new(vec![p(q(2, 1), q(4, 1)), p(q(0, 1), q(4, 1))]).unwrap();
    let side = Bezier::new(vec![p(q(0, 1), q(4, 1)), p(q(0, 1), q(0, 1))]).unwrap();
    Region::new(vec![vec![quad, top, side]], FillRule::NonZero).unwrap()
}

fn empty() -> Region {
    Region::new(Vec::new(), FillRule::NonZero).unwrap()
}

/// The result's loops as closed polylines of doubles.
fn polylines(regions: &[&Region], r: &RegionResult) -> Vec<Vec<[f64; 2]>> {
    r.loops
        .iter()
        .map(|lp| {
            let mut out = Vec::new();
            for e in &lp.edges {
                let c = &regions[e.region].loops()[e.loop_index][e.curve];
                let f: Vec<[f64; 2]> = c
                    .points()
                    .iter()
                    .map(|p| p.clone().map(|v| rational_to_f64(&v)))
                    .collect();
                let f = Bezier::new(f).unwrap();
                let (a, b) = (e.from.to_f64(), e.to.to_f64());
                for k in 0..512 {
                    out.push(f.eval(&(a + (b - a) * k as f64 / 512.0)));
                }
            }
            out
        })
        .collect()
}

/// Winding number of the polylines around x, or `None` within `near` of a segment.
fn polyline_winding(lines: &[Vec<[f64; 2]>], x: [f64; 2], near: f64) -> Option<i64> {
    let mut w = 0;
    for l in lines {
        for i in 0..l.len() {
            let (a, b) = (l[i], l[(i + 1) % l.len()]);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len2 = dx * dx + dy * dy;
            let t = if len2 > 0.0 {
                (((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            if (a[0] + t * dx - x[0]).hypot(a[1] + t * dy - x[1]) < near {
                return None;
            }
            if (a[1] <= x[1]) != (b[1] <= x[1]) {
                let cx = a[0] + (x[1] - a[1]) / dy * dx;
                if cx > x[0] {
                    w += if b[1] > a[1] { 1 } else { -1 };
                }
            }
        }
    }
    Some(w)
}

fn area(r: &RegionResult) -> (f64, f64) {
    (r.area[0], r.area[1])
}

fn check_pair(a: &Region, b: &Region, name: &str) {
    let ops = [
        BooleanOp::Intersection,
        BooleanOp::Union,
        BooleanOp::Difference,
        BooleanOp::Xor,
    ];
    let results: Vec<RegionResult> = ops
        .iter()
        .map(|&op| {
            let r = boolean(a, b, op).unwrap();
            assert_well_formed(&[a, b], &r);
            r
        })
        .collect();
    let ba = boolean(b, a, BooleanOp::Difference).unwrap();
    let alone_a = boolean(a, &empty(), BooleanOp::Union).unwrap();
    let alone_b = boolean(b, &empty(), BooleanOp::Union).unwrap();
    let [i, u, d, x] = [0, 1, 2, 3].map(|k| area(&results[k]));
    let e = area(&ba);
    let (aa, bb) = (area(&alone_a), area(&alone_b));
    let tol = 1e-9;
    // U = (A - B) + (B - A) + (A ∩ B); X = (A - B) + (B - A); U + I = A + B.
    assert!(
        u.0 <= d.1 + e.1 + i.1 + tol && d.0 + e.0 + i.0 <= u.1 + tol,
        "{name}: union {u:?} vs {d:?} {e:?} {i:?}"
    );
    assert!(
        x.0 <= d.1 + e.1 + tol && d.0 + e.0 <= x.1 + tol,
        "{name}: xor {x:?} vs {d:?} {e:?}"
    );
    assert!(
        u.0 + i.0 <= aa.1 + bb.1 + tol && aa.0 + bb.0 <= u.1 + i.1 + tol,
        "{name}: {u:?} + {i:?} vs {aa:?} + {bb:?}"
    );
    // Membership on a grid over the inputs' box.
    let pts: Vec<[f64; 2]> = [a, b]
        .iter()
        .flat_map(|r| r.loops().iter().flatten())
        .flat_map(|c| {
            c.points()
                .iter()
                .map(|p| p.clone().map(|v| rational_to_f64(&v)))
        })
        .collect();
    let (x0, x1) = pts
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p[0]), h.max(p[0])));
    let (y0, y1) = pts
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p[1]), h.max(p[1])));
    let lines: Vec<_> = results.iter().map(|r| polylines(&[a, b], r)).collect();
    let mut tested = 0;
    for gx in 0..23 {
        for gy in 0..23 {
            // Points at odd multiples of 1/46 of the box, exact rationals.
            let fx = Rational::new((2 * gx + 1).into(), 46.into());
            let fy = Rational::new((2 * gy + 1).into(), 46.into());
            let span = |lo: f64, hi: f64, f: &Rational| {
                Rational::from_float(lo).unwrap()
                    + (Rational::from_float(hi).unwrap() - Rational::from_float(lo).unwrap()) * f
            };
            let point = [span(x0, x1, &fx), span(y0, y1, &fy)];
            let (pa, pb) = (a.contains(&point), b.contains(&point));
            if pa == Position::Boundary || pb == Position::Boundary {
                continue;
            }
            let xf = point.clone().map(|v| rational_to_f64(&v));
            for (k, op) in ops.iter().enumerate() {
                let expected = op.keeps(pa == Position::Inside, pb == Position::Inside);
                if let Some(w) = polyline_winding(&lines[k], xf, 1e-3) {
                    assert_eq!(w, expected as i64, "{name} {op:?} at {xf:?}");
                    tested += 1;
                }
            }
        }
    }
    assert!(tested > 500, "{name}: only {tested} points tested");
}

#[test]
fn circles_cups_and_waves() {
    check_pair(
        &circle(0, 0, 100, 100),
        &circle(120, 50, 100, 100),
        "two circles",
    );
    check_pair(
        &circle(0, 0, 100, 100),
        &circle(0, 0, 50, 100),
        "nested circles",
    );
    check_pair(&cup(1, 1, false), &circle(0, 50, 60, 100), "cup and circle");
    check_pair(&cup(1, 1, false), &cup(1, 1, true), "tangent cups");
    check_pair(
        &wavy(12, (0.0, 0.0), 0.0),
        &wavy(12, (0.3, 0.1), 0.2),
        "two waves",
    );
}

#[test]
fn self_intersecting_and_closed_single_curves() {
    check_pair(
        &teardrop(),
        &circle(0, 200, 150, 100),
        "teardrop and circle",
    );
    check_pair(
        &looped(FillRule::NonZero),
        &circle(100, 150, 100, 100),
        "loop nonzero",
    );
    check_pair(
        &looped(FillRule::EvenOdd),
        &circle(100, 150, 100, 100),
        "loop evenodd",
    );
    check_pair(
        &looped(FillRule::EvenOdd),
        &looped(FillRule::NonZero),
        "loop with itself",
    );
}

#[test]
fn a_shared_piece_of_parabola_is_reported_once_from_the_first_region() {
    let (a, b) = (cup(1, 1, false), half_cup());
    check_pair(&a, &b, "cups sharing a parabola");
    let r = boolean(&a, &b, BooleanOp::Intersection).unwrap();
    assert_eq!(r.loops.len(), 1);
    // {0 <= x <= 1, x^2 <= y <= 1}: area 2/3; edges: the parabola from A (x in [0, 1] is
    // t in [1/2, 1] on A's quadratic), A's top from x = 1 to 0, B's side from y = 1 to 0.
    assert!(r.area[0] <= 2.0 / 3.0 && 2.0 / 3.0 <= r.area[1]);
    assert_eq!(r.loops[0].edges.len(), 3);
    let parabola = r.loops[0].edges.iter().find(|e| e.curve == 0).unwrap();
    assert_eq!(parabola.region, 0);
    assert_eq!(
        (
            parabola.from.algebraic().unwrap().exact(),
            parabola.to.algebraic().unwrap().exact()
        ),
        (Some(&q(1, 2)), Some(&q(1, 1)))
    );
    let r = boolean(&a, &b, BooleanOp::Union).unwrap();
    assert!(r.area[0] <= 6.0 && 6.0 <= r.area[1]);
}

/// A region bounded by the piece t in [0, 1/5] of the looped cubic and its chord. The
/// cubic's own crossing (s ≈ 0.084, t ≈ 0.916, at x = 1) lies on that piece, so the cubic's
/// other pass crosses the shared stretch there: the intersector does not list that crossing
/// inside the overlap, and the arrangement must carry the irrational parameter across.
fn sliver() -> Region {
    let c = Bezier::new(vec![
        p(q(0, 1), q(0, 1)),
        p(q(5, 1), q(4, 1)),
        p(q(-3, 1), q(4, 1)),
        p(q(2, 1), q(0, 1)),
    ])
    .unwrap();
    let piece = c.subsegment(q(0, 1)..q(1, 5));
    let end = piece.points()[3].clone();
    let chord = Bezier::new(vec![end, p(q(0, 1), q(0, 1))]).unwrap();
    Region::new(vec![vec![piece, chord]], FillRule::NonZero).unwrap()
}

#[test]
fn a_self_crossing_on_a_shared_stretch() {
    check_pair(
        &looped(FillRule::NonZero),
        &sliver(),
        "loop and sliver, nonzero",
    );
    check_pair(
        &looped(FillRule::EvenOdd),
        &sliver(),
        "loop and sliver, even-odd",
    );
    check_pair(&sliver(), &looped(FillRule::EvenOdd), "sliver and loop");
}

#[test]
fn degree_elevated_and_reversed_curved_copies() {
    let a = cup(1, 1, false);
    let elevate = |b: &Bezier<Rational, 2>| {
        let c = b.points();
        let mix = |u: &[Rational; 2], v: &[Rational; 2], wu: i64, wv: i64| {
            [
                (&u[0] * q(wu, 3)) + (&v[0] * q(wv, 3)),
                (&u[1] * q(wu, 3)) + (&v[1] * q(wv, 3)),
            ]
        };
        Bezier::new(vec![
            c[0].clone(),
            mix(&c[0], &c[1], 1, 2),
            mix(&c[1], &c[2], 2, 1),
            c[2].clone(),
        ])
        .unwrap()
    };
    let reverse =
        |b: &Bezier<Rational, 2>| Bezier::new(b.points().iter().rev().cloned().collect()).unwrap();
    let lp = &a.loops()[0];
    let elevated = Region::new(
        vec![vec![elevate(&lp[0]), lp[1].clone()]],
        FillRule::NonZero,
    )
    .unwrap();
    let reversed = Region::new(
        vec![vec![reverse(&lp[1]), reverse(&lp[0])]],
        FillRule::NonZero,
    )
    .unwrap();
    for b in [&elevated, &reversed] {
        for op in [BooleanOp::Union, BooleanOp::Intersection] {
            let r = boolean(&a, b, op).unwrap();
            assert_well_formed(&[&a, b], &r);
            assert_eq!(r.loops.len(), 1);
            assert_eq!(r.loops[0].edges.len(), 2);
            assert!(r.loops[0].edges.iter().all(|e| e.region == 0));
            assert!(r.area[0] <= 4.0 / 3.0 && 4.0 / 3.0 <= r.area[1]);
        }
        for op in [BooleanOp::Difference, BooleanOp::Xor] {
            assert!(boolean(&a, b, op).unwrap().loops.is_empty());
            assert!(boolean(b, &a, op).unwrap().loops.is_empty());
        }
    }
}

/// The sliver's curve is split where the loop's other pass crosses it, at u = 5 s for the
/// loop's own crossing s ≈ 0.0838: a parameter only the carrying across the overlap gives.
#[test]
fn the_crossing_on_the_shared_stretch_splits_both_curves() {
    let (a, b) = (looped(FillRule::NonZero), sliver());
    let (curves, ids, next) = super::pipeline::collect(&[&a, &b]);
    let arr = super::arrangement::Arrangement::build(curves, ids, &next).unwrap();
    let sliver_curve = arr
        .ids
        .iter()
        .position(|id| id.region == 1 && id.curve == 0)
        .unwrap();
    let inner: Vec<f64> = arr.params[sliver_curve]
        .iter()
        .map(|t| t.to_f64())
        .collect();
    assert!(
        inner.iter().any(|&u| (u - 0.419).abs() < 0.01),
        "the sliver's parameters {inner:?}"
    );
    // And the pieces on both sides of the overlap pair up into groups of two.
    let shared = arr.groups.iter().filter(|g| g.members.len() == 2).count();
    assert!(shared >= 2, "{shared} shared groups");
}

/// A triangle from doubles (exact dyadic nodes).
fn triangle(degree: usize, nodes: &[[f64; 2]]) -> Region {
    let exact = nodes
        .iter()
        .map(|n| {
            [
                Rational::from_float(n[0]).unwrap(),
                Rational::from_float(n[1]).unwrap(),
            ]
        })
        .collect();
    Region::triangle(degree, exact).unwrap()
}

#[test]
fn curved_triangles() {
    // Quadratic triangles in the manner of Python bezier's examples.
    let t1 = triangle(
        2,
        &[
            [0.0, 0.0],
            [0.5, -0.25],
            [1.0, 0.0],
            [0.125, 0.5],
            [0.75, 0.75],
            [0.25, 1.0],
        ],
    );
    let t2 = triangle(
        2,
        &[
            [-0.125, 0.25],
            [0.5, -0.5],
            [1.125, 0.25],
            [0.0, 0.75],
            [0.75, 0.625],
            [0.375, 1.25],
        ],
    );
    check_pair(&t1, &t2, "quadratic triangles");
    // A cubic triangle and a linear one sharing a corner.
    let t3 = triangle(
        3,
        &[
            [0.0, 0.0],
            [1.0, 0.25],
            [2.0, -0.25],
            [3.0, 0.0],
            [0.25, 1.0],
            [1.5, 1.25],
            [2.75, 1.0],
            [0.5, 2.0],
            [2.0, 2.25],
            [1.0, 3.0],
        ],
    );
    let t4 = triangle(1, &[[3.0, 0.0], [0.5, 2.5], [0.0, 0.5]]);
    check_pair(&t3, &t4, "cubic and linear triangles");
    // A triangle with itself: the answer is the triangle, reported from the first.
    let r = super::triangle_intersection(&t1, &t1).unwrap();
    assert_eq!(r.loops.len(), 1);
    assert!(r.loops[0].edges.iter().all(|e| e.triangle_edge() < 3));
}

#[test]
fn zero_area_loops_and_non_dyadic_numbers() {
    let line = |a: [Rational; 2], b: [Rational; 2]| Bezier::new(vec![a, b]).unwrap();
    let (o, x, y) = (
        p(q(0, 1), q(0, 1)),
        p(q(1, 3), q(0, 1)),
        p(q(1, 3), q(1, 7)),
    );
    // A spike (out and back) and a single point: no area at all.
    let spike = Region::new(
        vec![
            vec![line(o.clone(), x.clone()), line(x.clone(), o.clone())],
            vec![line(y.clone(), y.clone())],
        ],
        FillRule::NonZero,
    )
    .unwrap();
    for op in [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Xor] {
        let r = boolean(&spike, &spike, op).unwrap();
        assert!(r.loops.is_empty() && r.area == [0.0, 0.0], "{op:?}");
    }
    // A triangle of thirds and sevenths with the spike along its side: the spike vanishes.
    let tri = Region::new(
        vec![vec![
            line(o.clone(), x.clone()),
            line(x, y.clone()),
            line(y, o),
        ]],
        FillRule::NonZero,
    )
    .unwrap();
    let r = boolean(&tri, &spike, BooleanOp::Union).unwrap();
    assert_well_formed(&[&tri, &spike], &r);
    assert_eq!((r.loops.len(), r.loops[0].edges.len()), (1, 3));
    let exact = 1.0 / 42.0;
    assert!(r.area[0] <= exact && exact <= r.area[1]);
    check_pair(&tri, &circle(20, 5, 10, 100), "thirds and a circle");
}
