//! The float path against the exact stages on the same inputs: the same loops of the same
//! edges (exact parameters compared exactly), the same holes, area enclosures that meet; and
//! the float path must answer the generic cases (else it would be dead code behind a
//! fallback).

use super::run;
use crate::region::boolean::{BooleanOp, RegionResult};
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
fn canonical(r: &RegionResult) -> Vec<(bool, Vec<Key>)> {
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
fn assert_same(fast: &RegionResult, exact: &RegionResult, what: &str) {
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

/// Runs both paths on every op; returns how many the float path answered.
fn compare(a: &Region, b: &Region, what: &str) -> usize {
    let mut answered = 0;
    for op in OPS {
        let exact = run_exact(&[a, b], op).expect("exact answer");
        if let Some(fast) = run(&[a, b], op) {
            answered += 1;
            assert_same(&fast, &exact, &format!("{what}, {op:?}"));
        }
    }
    answered
}

fn unit(rng: &mut XorShift) -> f64 {
    (rng.next() >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn random_star_pairs_agree_with_the_exact_stages() {
    let mut rng = XorShift(0x5eed_57a2);
    let (mut answered, mut total) = (0, 0);
    for i in 0..24 {
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

#[test]
fn degenerate_inputs_are_left_to_the_exact_stages() {
    let a = star(8, (0.0, 0.0), 0.0);
    // The same region: every curve overlaps its copy.
    assert!(run(&[&a, &a], BooleanOp::Union).is_none());
    // A vertex of B on an edge of A: a square whose corner is A's vertex (1, 0).
    let v = a.doubles().unwrap()[0][0][0];
    let square = |x: f64, y: f64| {
        let c = [[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]];
        Region::from_f64(
            vec![(0..4)
                .map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap())
                .collect()],
            FillRule::NonZero,
        )
        .unwrap()
    };
    let b = square(v[0], v[1]);
    assert!(run(&[&a, &b], BooleanOp::Union).is_none());
    // Squares sharing an edge.
    assert!(run(&[&square(0.0, 0.0), &square(1.0, 0.0)], BooleanOp::Union).is_none());
    // Crossing squares: generic.
    let r = run(&[&square(0.0, 0.0), &square(0.5, 0.25)], BooleanOp::Union)
        .expect("transversal crossings");
    assert!(r.area[0] <= 1.625 && 1.625 <= r.area[1]);
}

#[test]
#[ignore]
fn probe_triangles() {
    let text = std::fs::read_to_string("/work/targets/main/region/triangles.json").unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut stats = std::collections::HashMap::new();
    for p in v["pairs"].as_array().unwrap() {
        let t: Vec<Region> = p["triangles"]
            .as_array()
            .unwrap()
            .iter()
            .map(|t| {
                let nodes = t
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|xy| {
                        let f = |k: usize| {
                            crate::intersect::algebraic::exact_f64(xy[k].as_f64().unwrap())
                        };
                        [f(0), f(1)]
                    })
                    .collect();
                Region::triangle(2, nodes).unwrap()
            })
            .collect();
        let d = [
            t[0].doubles().unwrap().as_slice(),
            t[1].doubles().unwrap().as_slice(),
        ];
        let why = match super::split::Split::build(d, false) {
            None => "split",
            Some(s) => {
                let mut areas = super::measure::Areas::new(&s);
                match super::side::loop_windings(&s, &mut areas) {
                    None => "windings",
                    Some(w) => match super::walk::boundary(
                        &s,
                        &w,
                        [FillRule::NonZero; 2],
                        BooleanOp::Intersection,
                    ) {
                        None => "walk",
                        Some(l) => match super::measure::answer(
                            &mut areas,
                            l,
                            [t[0].doubles().unwrap(), t[1].doubles().unwrap()],
                        ) {
                            None => "answer",
                            Some(_) => "ok",
                        },
                    },
                }
            }
        };
        *stats.entry(why).or_insert(0) += 1;
    }
    eprintln!("{stats:?}");
}
