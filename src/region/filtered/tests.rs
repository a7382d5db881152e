//! The float path against the exact stages on the same inputs: the same loops of the same
//! edges (exact parameters compared exactly), the same holes, area enclosures that meet; and
//! the float path must answer the generic cases (else it would be dead code behind a
//! fallback).

use super::run;
use crate::region::answer::{BooleanOp, Outline};
use crate::region::input::{FillRule, Region};
use crate::region::pipeline::run_exact;
use crate::region::tests::{star, wavy};
use crate::shape::array::Bezier;
use crate::test_rng::XorShift;
use std::cmp::Ordering;

const OPS: [BooleanOp; 4] = [
    BooleanOp::Intersection,
    BooleanOp::Union,
    BooleanOp::Difference,
    BooleanOp::Xor,
];

/// An edge as a comparable key: (region, loop, curve) and its two parameters' doubles.
type Key = (usize, usize, usize, u64, u64);

/// Each loop rotated to start at its least edge, with its hole flag, the loops sorted.
fn canonical(r: &Outline) -> Vec<(bool, Vec<Key>)> {
    let mut loops: Vec<(bool, Vec<Key>)> = r
        .loops
        .iter()
        .map(|lp| {
            let mut keys: Vec<Key> = lp
                .edges
                .iter()
                .map(|e| {
                    (
                        e.region,
                        e.loop_index,
                        e.curve,
                        e.from.to_f64().to_bits(),
                        e.to.to_f64().to_bits(),
                    )
                })
                .collect();
            let least = (0..keys.len()).min_by_key(|&i| keys[i]).unwrap_or(0);
            keys.rotate_left(least);
            (lp.hole, keys)
        })
        .collect();
    loops.sort();
    loops
}

/// Asserts that the two answers are the same answer, parameters compared exactly.
fn assert_same(fast: &Outline, exact: &Outline, what: &str) {
    assert_eq!(canonical(fast), canonical(exact), "{what}: loops differ");
    assert!(
        fast.area[0] <= exact.area[1] && exact.area[0] <= fast.area[1],
        "{what}: areas {:?} and {:?} do not meet",
        fast.area,
        exact.area
    );
    // The exact numbers behind the doubles: equal as algebraic numbers.
    for (lf, le) in fast.loops.iter().zip(&exact.loops) {
        let _ = le;
        for e in &lf.edges {
            for p in [&e.from, &e.to] {
                let x = p.algebraic().expect("exact on demand");
                assert_eq!(x.to_f64(), p.to_f64(), "{what}: rounding");
                let [lo, hi] = p.enclosure();
                assert!(
                    x.cmp_rational(&crate::intersect::algebraic::exact_f64(lo)) != Ordering::Less
                );
                assert!(
                    x.cmp_rational(&crate::intersect::algebraic::exact_f64(hi))
                        != Ordering::Greater
                );
            }
        }
    }
}

/// Runs the float path, its general stages alone (without the generic shortcut) and the
/// exact stages on every op; returns how many the general stages answered (the float path
/// must answer whenever they do).
fn compare(a: &Region, b: &Region, what: &str) -> usize {
    let mut answered = 0;
    let doubles = [a.doubles().unwrap(), b.doubles().unwrap()];
    for op in OPS {
        let exact = run_exact(&[a, b], op).expect("exact answer");
        if let Ok(general) = super::general(&[a, b], doubles, op) {
            answered += 1;
            assert_same(&general, &exact, &format!("{what}, {op:?}, general"));
            let fast = run(&[a, b], op).expect("the float path answers");
            assert_same(&fast, &exact, &format!("{what}, {op:?}"));
        }
    }
    answered
}

/// How many times the random tests repeat their corpus (`BLOSSOM_REGION_FUZZ`, default 1): a
/// longer search for a disagreement, run by hand.
fn rounds() -> usize {
    std::env::var("BLOSSOM_REGION_FUZZ")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1)
}

fn unit(rng: &mut XorShift) -> f64 {
    (rng.next() >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn random_star_pairs_agree_with_the_exact_stages() {
    let mut rng = XorShift(0x5eed_57a2);
    let (mut answered, mut total) = (0, 0);
    for i in 0..24 * rounds() {
        let n = 4 + 2 * (i % 4);
        let a = star(n, (0.0, 0.0), unit(&mut rng));
        let b = star(
            n + 2,
            (unit(&mut rng) - 0.5, unit(&mut rng) - 0.5),
            unit(&mut rng),
        );
        answered += compare(&a, &b, &format!("star pair {i}"));
        total += 4;
    }
    assert!(
        answered * 10 >= total * 9,
        "the float path answered {answered} of {total} generic cases"
    );
}

#[test]
fn nested_disjoint_holes_and_both_fill_rules() {
    // A wavy outline with a star hole (reversed), against a star crossing both.
    let outer = wavy(24, (0.0, 0.0), 0.3);
    // Half a star (radii 0.5 and 0.3, exact halving), inside the outline (radius >= 0.9).
    let half: Vec<Vec<[f64; 2]>> = star(10, (0.1, 0.0), 0.2).doubles().unwrap()[0]
        .iter()
        .map(|c| c.iter().map(|p| [p[0] / 2.0, p[1] / 2.0]).collect())
        .collect();
    let hole = Region::from_f64(
        vec![half
            .iter()
            .map(|c| Bezier::new(c.clone()).unwrap())
            .collect()],
        FillRule::NonZero,
    )
    .unwrap();
    let reversed: Vec<Bezier<f64, 2>> = hole.doubles().unwrap()[0]
        .iter()
        .rev()
        .map(|c| Bezier::new(c.iter().rev().copied().collect()).unwrap())
        .collect();
    let outer_curves: Vec<Bezier<f64, 2>> = outer.doubles().unwrap()[0]
        .iter()
        .map(|c| Bezier::new(c.clone()).unwrap())
        .collect();
    let mut answered = 0;
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        let holed = Region::from_f64(vec![outer_curves.clone(), reversed.clone()], fill).unwrap();
        let same_way = Region::from_f64(
            vec![
                outer_curves.clone(),
                hole.doubles().unwrap()[0]
                    .iter()
                    .map(|c| Bezier::new(c.clone()).unwrap())
                    .collect(),
            ],
            fill,
        )
        .unwrap();
        let crossing = star(8, (0.9, 0.2), 0.1);
        let far = star(6, (5.0, 5.0), 0.0);
        for (name, b) in [("crossing", &crossing), ("far", &far), ("inside", &hole)] {
            answered += compare(&holed, b, &format!("holed {fill:?} vs {name}"));
            answered += compare(&same_way, b, &format!("nested {fill:?} vs {name}"));
            answered += compare(b, &holed, &format!("{name} vs holed {fill:?}"));
        }
    }
    // "inside" shares its curves with the hole: those pairs are the exact path's.
    assert!(
        answered >= 2 * 3 * 2 * 4,
        "the float path answered {answered}"
    );
}

/// A unit square (side `s`) at (x, y), counter-clockwise.
fn square(x: f64, y: f64, s: f64) -> Region {
    let c = [[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
    Region::from_f64(
        vec![(0..4)
            .map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap())
            .collect()],
        FillRule::NonZero,
    )
    .unwrap()
}

#[test]
fn degenerate_inputs_take_the_float_path_and_agree() {
    let a = star(8, (0.0, 0.0), 0.0);
    // The same region: every curve overlaps its copy.
    assert_eq!(compare(&a, &a, "a star with itself"), 4);
    // A vertex of B on an edge of A: a square whose corner is A's vertex (1, 0).
    let v = a.doubles().unwrap()[0][0][0];
    assert_eq!(
        compare(&a, &square(v[0], v[1], 1.0), "a corner on a vertex"),
        4
    );
    // Squares sharing an edge, a corner, part of an edge; a square inside another touching it.
    for (b, what) in [
        (square(1.0, 0.0, 1.0), "a shared edge"),
        (square(1.0, 1.0, 1.0), "a shared corner"),
        (square(1.0, 0.5, 1.0), "part of an edge"),
        (square(0.25, 0.0, 0.5), "inside, touching"),
        (square(0.0, 0.0, 1.0), "the same square"),
        (square(0.5, 0.25, 1.0), "crossing"),
    ] {
        assert_eq!(compare(&square(0.0, 0.0, 1.0), &b, what), 4, "{what}");
    }
    // A circle of four cubics whose joins touch the square's edges (tangent branches ordered
    // by curvature), and the same circle moved off the edges.
    let k = 0.5522847498307936;
    let circle = |cx: f64, cy: f64| {
        let p = |x: f64, y: f64| [cx + x, cy + y];
        let arcs = [
            [p(1.0, 0.0), p(1.0, k), p(k, 1.0), p(0.0, 1.0)],
            [p(0.0, 1.0), p(-k, 1.0), p(-1.0, k), p(-1.0, 0.0)],
            [p(-1.0, 0.0), p(-1.0, -k), p(-k, -1.0), p(0.0, -1.0)],
            [p(0.0, -1.0), p(k, -1.0), p(1.0, -k), p(1.0, 0.0)],
        ];
        let curves = arcs.iter().map(|c| Bezier::new(c.to_vec()).unwrap());
        Region::from_f64(vec![curves.collect()], FillRule::NonZero).unwrap()
    };
    for (c, what) in [
        (circle(0.0, 0.0), "a circle inscribed in the square"),
        (
            circle(1.0, 0.0),
            "a circle through two corners, tangent at one join",
        ),
        (
            circle(0.0, 2.0),
            "a circle tangent to the square from outside",
        ),
    ] {
        assert_eq!(compare(&square(-1.0, -1.0, 2.0), &c, what), 4, "{what}");
    }
}

/// A quadratic Bézier triangle near the triangle (a, b, c): corners and edge midpoints
/// moved by up to 0.1, on the grid of 1/4096.
fn random_triangle(rng: &mut XorShift, corners: [[f64; 2]; 3]) -> Region {
    let snap = |x: f64| (x * 4096.0).round() / 4096.0;
    let mut jitter = |p: [f64; 2]| {
        [
            snap(p[0] + 0.2 * (unit(rng) - 0.5)),
            snap(p[1] + 0.2 * (unit(rng) - 0.5)),
        ]
    };
    let [a, b, c] = corners;
    let mid = |p: [f64; 2], q: [f64; 2]| [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
    // Node order p200, p110, p020, p101, p011, p002.
    let nodes = [a, mid(a, b), b, mid(a, c), mid(b, c), c].map(&mut jitter);
    let q = |x: f64| crate::intersect::algebraic::exact_f64(x);
    Region::triangle(2, nodes.iter().map(|p| [q(p[0]), q(p[1])]).collect()).unwrap()
}

#[test]
fn curved_triangle_pairs_take_the_float_path_and_agree() {
    let mut rng = XorShift(0x7e1a_4040);
    let (mut answered, total) = (0, 60 * rounds());
    for i in 0..total {
        let t1 = random_triangle(&mut rng, [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        let (dx, dy) = (0.5 * unit(&mut rng), 0.5 * unit(&mut rng));
        let t2 = random_triangle(
            &mut rng,
            [[1.0 + dx, 1.0 + dy], [dx, 1.0 + dy], [1.0 + dx, dy]],
        );
        let exact = run_exact(&[&t1, &t2], BooleanOp::Intersection).unwrap();
        if let Ok(fast) = run(&[&t1, &t2], BooleanOp::Intersection) {
            answered += 1;
            assert_same(&fast, &exact, &format!("triangle pair {i}"));
        }
    }
    assert!(
        answered * 20 >= total * 19,
        "the float path answered {answered} of {total} triangle pairs"
    );
}

/// A random loop of `n` cubics around `centre`: vertices at random radii in [0.5, 1] times
/// `size` at increasing angles, each edge bulging by a random fraction of its length, on
/// the grid of 2^-12; counter-clockwise unless `reverse`.
fn random_loop(
    rng: &mut XorShift,
    n: usize,
    centre: [f64; 2],
    size: f64,
    reverse: bool,
) -> Vec<Bezier<f64, 2>> {
    let snap = |x: f64| (x * 4096.0).round() / 4096.0;
    let vertices: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let angle = std::f64::consts::TAU * (k as f64 + 0.8 * unit(rng)) / n as f64;
            let r = size * (0.5 + 0.5 * unit(rng));
            [
                snap(centre[0] + r * angle.cos()),
                snap(centre[1] + r * angle.sin()),
            ]
        })
        .collect();
    let mut curves: Vec<Vec<[f64; 2]>> = (0..n)
        .map(|k| {
            let (p, q) = (vertices[k], vertices[(k + 1) % n]);
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let (b1, b2) = (0.4 * (unit(rng) - 0.5), 0.4 * (unit(rng) - 0.5));
            let c1 = [
                snap(p[0] + dx / 3.0 + dy * b1),
                snap(p[1] + dy / 3.0 - dx * b1),
            ];
            let c2 = [
                snap(p[0] + 2.0 * dx / 3.0 + dy * b2),
                snap(p[1] + 2.0 * dy / 3.0 - dx * b2),
            ];
            vec![p, c1, c2, q]
        })
        .collect();
    if reverse {
        curves.reverse();
        for c in &mut curves {
            c.reverse();
        }
    }
    curves
        .into_iter()
        .map(|c| Bezier::new(c).unwrap())
        .collect()
}

#[test]
fn random_blobs_with_holes_and_both_fill_rules_agree() {
    let mut rng = XorShift(0xb10b_5eed);
    let (mut answered, mut total) = (0, 0);
    for i in 0..20 * rounds() {
        let fill = |k: usize| {
            if k.is_multiple_of(2) {
                FillRule::NonZero
            } else {
                FillRule::EvenOdd
            }
        };
        // A: an outline with, every other time, a hole (reversed) or a nested same-way loop.
        let mut a = vec![random_loop(&mut rng, 3 + i % 6, [0.0, 0.0], 1.0, false)];
        if i % 2 == 1 {
            a.push(random_loop(
                &mut rng,
                3 + i % 4,
                [0.05, 0.0],
                0.3,
                i % 4 == 1,
            ));
        }
        let centre = [unit(&mut rng) - 0.5, unit(&mut rng) - 0.5];
        let b = vec![random_loop(&mut rng, 3 + i % 5, centre, 0.8, i % 3 == 0)];
        let (a, b) = (
            Region::from_f64(a, fill(i)).unwrap(),
            Region::from_f64(b, fill(i / 2)).unwrap(),
        );
        answered += compare(&a, &b, &format!("blobs {i}"));
        total += 4;
    }
    // Random bulges can make a loop cross itself (the exact path's case).
    assert!(
        answered * 2 >= total,
        "the float path answered {answered} of {total}"
    );
}

/// A square (side `s`) at (x, y) whose side k is a segment (`kinds[k]` = 0) or a straight
/// quadratic with its control point on its start (1), on its end (2), or inside the side at
/// 1/8, 1/2 or 5/8 of it (3, 4, 5), as fonts write them.
fn straight_square(x: f64, y: f64, s: f64, kinds: [u8; 4]) -> Vec<Bezier<f64, 2>> {
    let c = [[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
    (0..4)
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % 4]);
            let inside = |m: f64| [a[0] + m * (b[0] - a[0]), a[1] + m * (b[1] - a[1])];
            let points = match kinds[i] {
                0 => vec![a, b],
                1 => vec![a, a, b],
                2 => vec![a, b, b],
                3 => vec![a, inside(0.125), b],
                4 => vec![a, inside(0.5), b],
                _ => vec![a, inside(0.625), b],
            };
            Bezier::new(points).unwrap()
        })
        .collect()
}

/// Straight quadratics sharing stretches with segments and with each other (control points on an end or inside the chord),
/// within one region (overlapping copies, as in a union of shifted glyphs) and between two:
/// fixed width on their chords, parameters carried through φ⁻¹, the same answers as the exact
/// stages, parameter for parameter.
#[test]
fn straight_quadratics_on_shared_edges_agree_with_the_exact_stages() {
    let mut rng = XorShift(0x57a1);
    let mut kinds = || [0, 1, 2, 3].map(|_| (rng.next() % 6) as u8);
    let mut answered = 0;
    for round in 0..6 * rounds() {
        let step = [0.5, 1.0, 0.25][round % 3];
        let a = Region::from_f64(
            vec![straight_square(0.0, 0.0, 2.0, kinds())],
            FillRule::NonZero,
        )
        .unwrap();
        // Three copies moved along x: their horizontal sides overlap.
        let copies = (1..=3)
            .map(|k| straight_square(step * k as f64, 0.0, 2.0, kinds()))
            .collect();
        let b = Region::from_f64(copies, FillRule::NonZero).unwrap();
        answered += compare(&a, &b, &format!("round {round}: copies by {step}"));
        let beside = Region::from_f64(
            vec![straight_square(2.0, step, 2.0, kinds())],
            FillRule::EvenOdd,
        )
        .unwrap();
        answered += compare(&a, &beside, &format!("round {round}: beside at {step}"));
    }
    assert_eq!(
        answered,
        6 * rounds() * 2 * 4,
        "the general stages answer every case"
    );
}
