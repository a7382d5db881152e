//! Unit tests of the region layer: degenerate configurations with answers known by
//! construction, identities of areas on curved cases, membership of sample points against
//! the exact winding numbers of the inputs, and bad input.

use super::{
    boolean, triangle_intersection, BooleanOp, FillRule, Position, Region, RegionResult, Winding,
};
use crate::error::ErrorKind;
use crate::num::ring::Rational;
use crate::shape::array::Bezier;

pub(super) fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

pub(super) fn pt(x: i64, y: i64) -> [Rational; 2] {
    [q(x, 1), q(y, 1)]
}

/// A closed polygon of straight curves through the points, in order.
pub(super) fn polygon(points: &[(i64, i64)]) -> Vec<Bezier<Rational, 2>> {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            Bezier::new(vec![pt(a.0, a.1), pt(b.0, b.1)]).unwrap()
        })
        .collect()
}

pub(super) fn region(loops: Vec<Vec<Bezier<Rational, 2>>>) -> Region {
    Region::new(loops, FillRule::NonZero).unwrap()
}

pub(super) fn square(x: i64, y: i64, s: i64) -> Region {
    region(vec![polygon(&[
        (x, y),
        (x + s, y),
        (x + s, y + s),
        (x, y + s),
    ])])
}

/// The exact area `num / den` lies in the enclosure, which is tight.
pub(super) fn assert_area(r: &RegionResult, num: i64, den: i64) {
    let a = num as f64 / den as f64;
    assert!(
        r.area[0] <= a && a <= r.area[1] && r.area[1] - r.area[0] < 1e-9,
        "area {:?}, expected {num}/{den}",
        r.area
    );
}

/// The point of an edge's input curve at a parameter, in doubles (for structural checks).
fn point_at(regions: &[&Region], e: &super::Edge, at: f64) -> [f64; 2] {
    let c = &regions[e.region].loops()[e.loop_index][e.curve];
    let pts: Vec<[f64; 2]> = c
        .points()
        .iter()
        .map(|p| [crate::rational_to_f64(&p[0]), crate::rational_to_f64(&p[1])])
        .collect();
    Bezier::new(pts).unwrap().eval(&at)
}

/// Structure every answer must have: loops closed, edges of positive length, holes
/// clockwise and outer loops counter-clockwise (by a float shoelace over sample points),
/// consecutive edges never continuing one curve.
pub(super) fn assert_well_formed(regions: &[&Region], r: &RegionResult) {
    for lp in &r.loops {
        let n = lp.edges.len();
        assert!(n > 0);
        let mut signed = 0.0;
        for (i, e) in lp.edges.iter().enumerate() {
            let f = &lp.edges[(i + 1) % n];
            let end = point_at(regions, e, e.to.to_f64());
            let start = point_at(regions, f, f.from.to_f64());
            assert!(
                (end[0] - start[0]).abs() < 1e-9 && (end[1] - start[1]).abs() < 1e-9,
                "edge {i} ends at {end:?}, the next starts at {start:?}"
            );
            assert!(e.from.compare(&e.to).unwrap().is_ne());
            let same_curve = (e.region, e.loop_index, e.curve) == (f.region, f.loop_index, f.curve);
            assert!(
                !(same_curve
                    && e.to.compare(&f.from).unwrap().is_eq()
                    && (e.from.compare(&e.to).unwrap() == f.from.compare(&f.to).unwrap())),
                "edges {i} and {} continue one curve",
                (i + 1) % n
            );
            let (a, b) = (e.from.to_f64(), e.to.to_f64());
            let steps = 64;
            for k in 0..steps {
                let t0 = a + (b - a) * k as f64 / steps as f64;
                let t1 = a + (b - a) * (k + 1) as f64 / steps as f64;
                let (p0, p1) = (point_at(regions, e, t0), point_at(regions, e, t1));
                signed += p0[0] * p1[1] - p1[0] * p0[1];
            }
        }
        assert_eq!(
            lp.hole,
            signed < 0.0,
            "hole flag against the loop's orientation"
        );
    }
}

fn run(a: &Region, b: &Region, op: BooleanOp) -> RegionResult {
    let r = boolean(a, b, op).unwrap();
    assert_well_formed(&[a, b], &r);
    r
}

fn holes(r: &RegionResult) -> usize {
    r.loops.iter().filter(|l| l.hole).count()
}

#[test]
fn overlapping_squares_all_four_ops() {
    let (a, b) = (square(0, 0, 2), square(1, 1, 2));
    let r = run(&a, &b, BooleanOp::Intersection);
    assert_eq!(r.loops.len(), 1);
    assert_eq!(r.loops[0].edges.len(), 4);
    assert_area(&r, 1, 1);
    let r = run(&a, &b, BooleanOp::Union);
    assert_eq!((r.loops.len(), r.loops[0].edges.len()), (1, 8));
    assert_area(&r, 7, 1);
    let r = run(&a, &b, BooleanOp::Difference);
    assert_eq!((r.loops.len(), r.loops[0].edges.len()), (1, 6));
    assert_area(&r, 3, 1);
    // The two L shapes touch at (2, 1) and (1, 2): two loops.
    let r = run(&a, &b, BooleanOp::Xor);
    assert_eq!((r.loops.len(), holes(&r)), (2, 0));
    assert_area(&r, 6, 1);
}

#[test]
fn identical_reversed_and_elevated_copies() {
    let a = square(0, 0, 2);
    // Reversed: clockwise, winding -1 inside, still inside under nonzero.
    let reversed = region(vec![polygon(&[(0, 2), (2, 2), (2, 0), (0, 0)])]);
    // Degree-elevated: each side a cubic with its control points at thirds.
    let elevated = region(vec![(0..4)
        .map(|i| {
            let c = [(0, 0), (2, 0), (2, 2), (0, 2)];
            let (p, r) = (c[i], c[(i + 1) % 4]);
            let at = |k: i64| [q(p.0 * (3 - k) + r.0 * k, 3), q(p.1 * (3 - k) + r.1 * k, 3)];
            Bezier::new((0..4).map(at).collect()).unwrap()
        })
        .collect()]);
    for b in [&a, &reversed, &elevated] {
        for op in [BooleanOp::Union, BooleanOp::Intersection] {
            let r = run(&a, b, op);
            assert_eq!(r.loops.len(), 1, "{op:?}");
            assert_eq!(r.loops[0].edges.len(), 4);
            assert!(
                r.loops[0].edges.iter().all(|e| e.region == 0),
                "reported from A"
            );
            assert_area(&r, 4, 1);
        }
        for op in [BooleanOp::Difference, BooleanOp::Xor] {
            let r = run(&a, b, op);
            assert!(r.loops.is_empty(), "{op:?}");
            assert_eq!(r.area, [0.0, 0.0]);
        }
    }
    // B - A with B the elevated copy: reported from B where A does not coincide: nowhere.
    let r = run(&elevated, &a, BooleanOp::Union);
    assert!(r.loops[0].edges.iter().all(|e| e.region == 0));
}

#[test]
fn shared_partial_edge_and_touching_regions() {
    // [0,2]^2 and [2,4]x[0,1] share the piece x = 2, 0 <= y <= 1.
    let (a, b) = (
        square(0, 0, 2),
        region(vec![polygon(&[(2, 0), (4, 0), (4, 1), (2, 1)])]),
    );
    let r = run(&a, &b, BooleanOp::Union);
    assert_eq!(r.loops.len(), 1);
    assert_area(&r, 6, 1);
    // A's side 0, B's sides 0, 1, 2, A's side 1 from y = 1 to 2, A's sides 2 and 3.
    assert_eq!(r.loops[0].edges.len(), 7);
    let r = run(&a, &b, BooleanOp::Intersection);
    assert!(r.loops.is_empty());
    let r = run(&a, &b, BooleanOp::Difference);
    assert_area(&r, 4, 1);
    assert_eq!(
        r.loops[0].edges.len(),
        4,
        "the shared piece and the rest of A's side merge"
    );
    // Squares touching at a corner: the union splits there.
    let (a, b) = (square(0, 0, 1), square(1, 1, 1));
    let r = run(&a, &b, BooleanOp::Union);
    assert_eq!((r.loops.len(), holes(&r)), (2, 0));
    assert_area(&r, 2, 1);
    assert!(run(&a, &b, BooleanOp::Intersection).loops.is_empty());
}

#[test]
fn a_vertex_on_an_edge_and_a_hole_touching_the_outer_loop() {
    // A diamond with its lowest vertex on the bottom side of the square.
    let a = square(0, 0, 4);
    let b = region(vec![polygon(&[(2, 0), (3, 1), (2, 2), (1, 1)])]);
    let r = run(&a, &b, BooleanOp::Difference);
    assert_eq!((r.loops.len(), holes(&r)), (2, 1));
    assert_area(&r, 14, 1);
    let outer = r.loops.iter().find(|l| !l.hole).unwrap();
    assert_eq!(outer.edges.len(), 4, "the bottom side is one edge again");
    let r = run(&a, &b, BooleanOp::Union);
    assert_eq!(r.loops.len(), 1);
    assert_area(&r, 16, 1);
    let r = run(&a, &b, BooleanOp::Intersection);
    assert_eq!(r.loops.len(), 1);
    assert_area(&r, 2, 1);
}

#[test]
fn nested_disjoint_and_holes() {
    let outer = square(0, 0, 10);
    let inner = square(2, 2, 2);
    let far = square(20, 0, 1);
    let r = run(&outer, &inner, BooleanOp::Difference);
    assert_eq!((r.loops.len(), holes(&r)), (2, 1));
    assert_area(&r, 96, 1);
    let r = run(&outer, &far, BooleanOp::Union);
    assert_eq!((r.loops.len(), holes(&r)), (2, 0));
    assert_area(&r, 101, 1);
    assert!(run(&outer, &far, BooleanOp::Intersection).loops.is_empty());
    // A region with a hole (the inner loop reversed), and a square that fills the hole.
    let ring = region(vec![
        polygon(&[(0, 0), (10, 0), (10, 10), (0, 10)]),
        polygon(&[(2, 2), (2, 8), (8, 8), (8, 2)]),
    ]);
    assert_eq!(ring.winding(&pt(5, 5)), Winding::Number(0));
    assert_eq!(ring.winding(&pt(1, 1)), Winding::Number(1));
    let plug = square(2, 2, 6);
    let r = run(&ring, &plug, BooleanOp::Union);
    assert_eq!(r.loops.len(), 1, "the plug fills the hole exactly");
    assert_area(&r, 100, 1);
    assert!(run(&ring, &plug, BooleanOp::Intersection).loops.is_empty());
    let smaller = square(3, 3, 2);
    let r = run(&ring, &smaller, BooleanOp::Union);
    assert_eq!((r.loops.len(), holes(&r)), (3, 1));
    assert_area(&r, 68, 1);
}

#[test]
fn self_intersecting_loops_under_both_fill_rules() {
    let empty = Region::new(Vec::new(), FillRule::NonZero).unwrap();
    // A bow tie: two triangles of opposite orientation meeting at (1, 1).
    let bow = region(vec![polygon(&[(0, 0), (2, 2), (2, 0), (0, 2)])]);
    assert_eq!(bow.winding(&q2(1, 2, 1, 1)), Winding::Number(1));
    assert_eq!(bow.winding(&q2(3, 2, 1, 1)), Winding::Number(-1));
    let r = run(&bow, &empty, BooleanOp::Union);
    assert_eq!((r.loops.len(), holes(&r)), (2, 0));
    assert_area(&r, 2, 1);
    // A pentagram: the middle pentagon has winding 2 (nonzero: inside; even-odd: outside).
    let star = [(0, 10), (6, -8), (-10, 3), (10, 3), (-6, -8)];
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        let a = Region::new(vec![polygon(&star)], fill).unwrap();
        let w = a.winding(&pt(0, 0));
        assert!(
            matches!(w, Winding::Number(2) | Winding::Number(-2)),
            "{w:?}"
        );
        let r = run(&a, &empty, BooleanOp::Union);
        match fill {
            FillRule::NonZero => assert_eq!((r.loops.len(), r.loops[0].edges.len()), (1, 10)),
            FillRule::EvenOdd => {
                assert_eq!(
                    (r.loops.len(), holes(&r)),
                    (5, 0),
                    "five tips touching at corners"
                )
            }
        }
    }
}

fn q2(a: i64, b: i64, c: i64, d: i64) -> [Rational; 2] {
    [q(a, b), q(c, d)]
}

/// The cup {y >= x^2 / s, y <= w^2 / s} for |x| <= w, as a quadratic and a line (s > 0),
/// mirrored in y = 0 when `down`.
pub(super) fn cup(w: i64, s: i64, down: bool) -> Region {
    let sign = if down { -1 } else { 1 };
    let top = q(sign * w * w, s);
    let ctrl = q(-sign * w * w, s);
    let quad = Bezier::new(vec![
        [q(-w, 1), top.clone()],
        [q(0, 1), ctrl],
        [q(w, 1), top.clone()],
    ])
    .unwrap();
    let line = Bezier::new(vec![[q(w, 1), top.clone()], [q(-w, 1), top]]).unwrap();
    let lp = if down {
        // Keep it counter-clockwise: reverse both.
        let rev = |b: &Bezier<Rational, 2>| {
            Bezier::new(b.points().iter().rev().cloned().collect()).unwrap()
        };
        vec![rev(&line), rev(&quad)]
    } else {
        vec![quad, line]
    };
    region(vec![lp])
}

#[test]
fn tangent_contacts_from_outside_and_inside() {
    // y >= x^2 (|x| <= 1) and its mirror y <= -x^2 touch at the origin, tangentially.
    let (a, b) = (cup(1, 1, false), cup(1, 1, true));
    assert_eq!(a.contains(&q2(0, 1, 1, 2)), Position::Inside);
    assert_eq!(b.contains(&q2(0, 1, -1, 2)), Position::Inside);
    let r = run(&a, &b, BooleanOp::Union);
    assert_eq!(
        (r.loops.len(), holes(&r)),
        (2, 0),
        "split at the tangent point"
    );
    assert_area(&r, 8, 3);
    assert!(run(&a, &b, BooleanOp::Intersection).loops.is_empty());
    // y >= 2 x^2 (|x| <= 1/2) inside y >= x^2 (|x| <= 1), touching at the origin.
    let small = {
        let quad = Bezier::new(vec![q2(-1, 2, 1, 2), q2(0, 1, -1, 2), q2(1, 2, 1, 2)]).unwrap();
        let line = Bezier::new(vec![q2(1, 2, 1, 2), q2(-1, 2, 1, 2)]).unwrap();
        region(vec![vec![quad, line]])
    };
    let r = run(&a, &small, BooleanOp::Difference);
    assert_eq!(
        (r.loops.len(), holes(&r)),
        (2, 1),
        "the hole touching the outer loop is split off"
    );
    assert_area(&r, 1, 1);
    let r = run(&a, &small, BooleanOp::Intersection);
    assert_eq!(r.loops.len(), 1);
    assert_area(&r, 1, 3);
    let r = run(&a, &small, BooleanOp::Union);
    assert_eq!(r.loops.len(), 1);
    assert_area(&r, 4, 3);
}

#[test]
fn triangles_sharing_only_an_edge_or_overlapping() {
    let t1 = Region::triangle(1, vec![pt(0, 0), pt(2, 0), pt(0, 2)]).unwrap();
    let t2 = Region::triangle(1, vec![pt(2, 2), pt(0, 2), pt(2, 0)]).unwrap();
    let r = triangle_intersection(&t1, &t2).unwrap();
    assert!(r.loops.is_empty());
    let t3 = Region::triangle(1, vec![pt(1, 0), pt(3, 0), pt(1, 2)]).unwrap();
    let r = triangle_intersection(&t1, &t3).unwrap();
    assert_well_formed(&[&t1, &t3], &r);
    assert_eq!(r.loops.len(), 1);
    assert_eq!(r.loops[0].edges.len(), 3);
    assert_area(&r, 1, 2);
    // Quadratic triangle: edges are quadratics; its region by the winding number.
    let curved = Region::triangle(
        2,
        vec![pt(0, 0), pt(2, -1), pt(4, 0), pt(1, 2), pt(3, 2), pt(2, 4)],
    )
    .unwrap();
    assert_eq!(curved.loops()[0].len(), 3);
    assert_eq!(curved.loops()[0][1].points()[0], pt(4, 0));
    assert_eq!(curved.loops()[0][1].points()[2], pt(2, 4));
    assert_eq!(curved.loops()[0][2].points()[1], pt(1, 2));
    assert_eq!(curved.contains(&pt(2, 1)), Position::Inside);
}

#[test]
fn winding_numbers_against_an_exact_polygon_count() {
    // A self-overlapping polygon and a single-point curve at (7, 7) in a loop of its own.
    let star = [(0, 10), (6, -8), (-10, 3), (10, 3), (-6, -8)];
    let dot = Bezier::new(vec![pt(7, 7), pt(7, 7)]).unwrap();
    let r = Region::new(vec![polygon(&star), vec![dot]], FillRule::EvenOdd).unwrap();
    // Independent: the polygon's winding at (x + 1/4, y + 1/3) by the classic test on
    // integers (the offsets keep the points off every edge and vertex of this star).
    let independent = |x: i64, y: i64| {
        let (px, py) = (q(4 * x + 1, 4), q(3 * y + 1, 3));
        let mut w = 0i64;
        for i in 0..5 {
            let (a, b) = (star[i], star[(i + 1) % 5]);
            let (ay, by) = (q(a.1, 1), q(b.1, 1));
            if (ay <= py) != (by <= py) {
                let t = (&py - &ay) / (&by - &ay);
                let cx = q(a.0, 1) + t * q(b.0 - a.0, 1);
                if cx > px {
                    w += if by > ay { 1 } else { -1 };
                }
            }
        }
        w
    };
    for x in -11..11 {
        for y in -9..11 {
            let p = [q(4 * x + 1, 4), q(3 * y + 1, 3)];
            assert_eq!(
                r.winding(&p),
                Winding::Number(independent(x, y)),
                "({x}, {y})"
            );
        }
    }
    assert_eq!(r.winding(&pt(7, 7)), Winding::Boundary);
    assert_eq!(r.contains(&pt(6, -8)), Position::Boundary);
    assert_eq!(r.contains(&pt(0, 3)), Position::Boundary);
    assert_eq!(
        r.contains(&pt(0, 0)),
        Position::Outside,
        "winding 2 under even-odd"
    );
    assert!(r.winding_work(10) > 0);
}

#[test]
fn bad_input_names_the_field() {
    let line =
        |a: (i64, i64), b: (i64, i64)| Bezier::new(vec![pt(a.0, a.1), pt(b.0, b.1)]).unwrap();
    let e = Region::new(
        vec![vec![
            line((0, 0), (1, 0)),
            line((1, 0), (1, 1)),
            line((1, 1), (0, 0)),
        ]],
        FillRule::NonZero,
    );
    assert!(e.is_ok());
    let e = Region::new(
        vec![vec![
            line((0, 0), (1, 0)),
            Bezier::new(vec![q2(1, 1, 1, 2), pt(0, 0)]).unwrap(),
        ]],
        FillRule::NonZero,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "loops[0][1]: starts at (1, 1/2), the previous curve ends at (1, 0)"
    );
    let e = Region::new(
        vec![
            polygon(&[(0, 0), (1, 0), (0, 1)]),
            vec![line((0, 0), (1, 0)), line((1, 0), (1, 1))],
        ],
        FillRule::NonZero,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "loops[1][0]: starts at (0, 0), the previous curve ends at (1, 1)"
    );
    let e = Region::new(vec![Vec::new()], FillRule::NonZero).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("loops[0]", ErrorKind::Empty));
    let high = Bezier::new(vec![pt(0, 0); 22]).unwrap();
    let e = Region::new(vec![vec![high]], FillRule::NonZero).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("loops[0][0]", ErrorKind::Degree));
    let e = Region::triangle(2, vec![pt(0, 0); 5]).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("nodes", ErrorKind::Shape));
    let e = Region::triangle(0, vec![pt(0, 0)]).unwrap_err();
    assert_eq!(e.path(), "degree");
    let e = Region::from_f64(
        vec![vec![Bezier::new(vec![[0.0, 0.0], [f64::NAN, 1.0]]).unwrap()]],
        FillRule::NonZero,
    )
    .unwrap_err();
    assert_eq!(
        (e.path(), e.kind()),
        ("loops[0][0][1]", ErrorKind::NotFinite)
    );
    // The same checks on doubles: an open loop, a degree, a triangle's node.
    let open = Region::from_f64(
        vec![vec![
            Bezier::new(vec![[0.0, 0.0], [1.0, 0.0]]).unwrap(),
            Bezier::new(vec![[1.0, 0.5], [0.0, 0.0]]).unwrap(),
        ]],
        FillRule::NonZero,
    )
    .unwrap_err();
    assert_eq!(
        open.to_string(),
        "loops[0][1]: starts at (1, 1/2), the previous curve ends at (1, 0)"
    );
    let high = Bezier::new(vec![[0.0, 0.0]; 22]).unwrap();
    let e = Region::from_f64(vec![vec![high]], FillRule::NonZero).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("loops[0][0]", ErrorKind::Degree));
    let mut nodes = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    nodes[2][1] = f64::INFINITY;
    let e = Region::triangle_f64(1, nodes).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("nodes[2]", ErrorKind::NotFinite));
    let e = Region::triangle_f64(2, vec![[0.0, 0.0]; 5]).unwrap_err();
    assert_eq!((e.path(), e.kind()), ("nodes", ErrorKind::Shape));
}

#[test]
fn regions_of_doubles_equal_their_exact_copies() {
    // A curved triangle from doubles and from the same numbers as rationals: the same region
    // (its exact curves made on demand), the same booleans.
    let nodes = [
        [0.0, 0.0],
        [0.5, -0.25],
        [1.0, 0.0],
        [0.0, 0.5],
        [0.5, 0.5],
        [0.0, 1.0],
    ];
    let exact: Vec<[Rational; 2]> = nodes
        .iter()
        .map(|p| p.map(|x| Rational::from_float(x).unwrap()))
        .collect();
    let (a, b) = (
        Region::triangle_f64(2, nodes.to_vec()).unwrap(),
        Region::triangle(2, exact).unwrap(),
    );
    assert_eq!(a, b);
    assert_eq!(a.loops(), b.loops());
    let other = Region::triangle_f64(1, vec![[0.25, -0.5], [1.5, 0.25], [0.25, 1.0]]).unwrap();
    let (ra, rb) = (
        crate::region::boolean(&a, &other, BooleanOp::Union).unwrap(),
        crate::region::boolean(&b, &other, BooleanOp::Union).unwrap(),
    );
    assert_eq!(ra.loops.len(), rb.loops.len());
    assert_eq!(ra.area, rb.area);
}

/// A star of `n` cubic edges around `centre`: vertices alternately at radius 1 and 0.6,
/// rotated by `phase`, each edge bulging outwards a little; coordinates rounded to
/// multiples of 2^-20 (exact doubles).
pub(super) fn star(n: usize, centre: (f64, f64), phase: f64) -> Region {
    let round = |x: f64| (x * 1048576.0).round() / 1048576.0;
    let vertex = |k: usize| {
        let a = phase + std::f64::consts::TAU * k as f64 / n as f64;
        let r = if k.is_multiple_of(2) { 1.0 } else { 0.6 };
        [round(centre.0 + r * a.cos()), round(centre.1 + r * a.sin())]
    };
    let curves = (0..n)
        .map(|k| {
            let (p, r) = (vertex(k), vertex((k + 1) % n));
            let (dx, dy) = (r[0] - p[0], r[1] - p[1]);
            // Control points at thirds, pushed outward (to the right of the edge) by 1/10.
            let c1 = [
                round(p[0] + dx / 3.0 + dy / 10.0),
                round(p[1] + dy / 3.0 - dx / 10.0),
            ];
            let c2 = [
                round(p[0] + 2.0 * dx / 3.0 + dy / 10.0),
                round(p[1] + 2.0 * dy / 3.0 - dx / 10.0),
            ];
            Bezier::new(vec![p, c1, c2, r]).unwrap()
        })
        .collect();
    Region::from_f64(vec![curves], FillRule::NonZero).unwrap()
}

/// A wavy closed curve of `n` cubic edges around `centre`: radius 1 + 0.1 sin(7 θ), each
/// edge the cubic Hermite interpolant of the arc over its angle step, coordinates rounded to
/// multiples of 2^-20 (exact doubles). Short edges: each box meets only its neighbours'.
pub(super) fn wavy(n: usize, centre: (f64, f64), phase: f64) -> Region {
    let round = |x: f64| (x * 1048576.0).round() / 1048576.0;
    let h = std::f64::consts::TAU / n as f64;
    let point = |a: f64| {
        let r = 1.0 + 0.1 * (7.0 * (a + phase)).sin();
        [centre.0 + r * a.cos(), centre.1 + r * a.sin()]
    };
    let derivative = |a: f64| {
        let r = 1.0 + 0.1 * (7.0 * (a + phase)).sin();
        let dr = 0.7 * (7.0 * (a + phase)).cos();
        [dr * a.cos() - r * a.sin(), dr * a.sin() + r * a.cos()]
    };
    let vertex = |k: usize| point(h * (k % n) as f64).map(round);
    let curves = (0..n)
        .map(|k| {
            let (a0, a1) = (h * k as f64, h * (k + 1) as f64);
            let (d0, d1) = (derivative(a0), derivative(a1));
            let (p0, p3) = (vertex(k), vertex(k + 1));
            let c1 = [
                round(p0[0] + h * d0[0] / 3.0),
                round(p0[1] + h * d0[1] / 3.0),
            ];
            let c2 = [
                round(p3[0] - h * d1[0] / 3.0),
                round(p3[1] - h * d1[1] / 3.0),
            ];
            Bezier::new(vec![p0, c1, c2, p3]).unwrap()
        })
        .collect();
    Region::from_f64(vec![curves], FillRule::NonZero).unwrap()
}

/// Times booleans of two stars of n cubic edges each (run in release with --ignored
/// --nocapture); prints, asserts nothing about speed.
#[test]
#[ignore]
fn scale_of_star_booleans() {
    let sizes: Vec<usize> = std::env::var("REGION_SCALE_SIZES")
        .map(|v| v.split(',').map(|x| x.parse().unwrap()).collect())
        .unwrap_or_else(|_| vec![64, 128, 256, 512, 1000]);
    // Two 8-edge stars (the comparison with flo_curves): mean of 20 runs.
    let (a, b) = (star(8, (0.0, 0.0), 0.0), star(8, (0.3, 0.2), 0.2));
    for op in [BooleanOp::Intersection, BooleanOp::Union] {
        let t = std::time::Instant::now();
        for _ in 0..20 {
            boolean(&a, &b, op).unwrap();
        }
        println!(
            "8-edge stars {op:?}: {:.3} ms",
            t.elapsed().as_secs_f64() * 1e3 / 20.0
        );
    }
    for n in sizes {
        let shape = std::env::var("REGION_SCALE_SHAPE").unwrap_or_default();
        let (a, b) = if shape == "star" {
            (star(n, (0.0, 0.0), 0.0), star(n, (0.37, 0.21), 0.013))
        } else {
            (wavy(n, (0.0, 0.0), 0.0), wavy(n, (0.37, 0.21), 0.3))
        };
        for op in [BooleanOp::Intersection, BooleanOp::Union] {
            let t = std::time::Instant::now();
            let r = boolean(&a, &b, op).unwrap();
            let took = t.elapsed();
            println!(
                "n = {n} {op:?}: {:.3} ms, {} loops, {} edges, area {:?}, estimate {:.3} s",
                took.as_secs_f64() * 1e3,
                r.loops.len(),
                r.loops.iter().map(|l| l.edges.len()).sum::<usize>(),
                r.area,
                super::boolean_work(&a, &b) as f64 * 1e-9
            );
        }
    }
}
