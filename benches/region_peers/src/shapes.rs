//! The inputs of the region benchmarks, shared by `benches/region.rs` (blossom alone) and
//! `benches/region_peers` (blossom beside flo_curves): plain f64 loops of cubic Bézier curves
//! and quadratic Bézier triangles, every coordinate on the grid of 1/4096 (so that the exact
//! numbers the certified layer reads stay short, as a font's or an SVG's would).

use std::f64::consts::PI;

/// A cubic Bézier curve's four control points.
pub type Cubic = [[f64; 2]; 4];

/// The region of one loop of cubics, nonzero, for blossom.
pub fn region_of(curves: &[Cubic]) -> blossom::region::Region {
    let curves = curves
        .iter()
        .map(|c| blossom::Bezier::new(c.to_vec()).expect("four points"))
        .collect();
    blossom::region::Region::from_f64(vec![curves], blossom::region::FillRule::NonZero)
        .expect("a closed loop")
}

pub use crate::common::Rng;

/// `x` on the grid of 1/4096.
pub fn snap(x: f64) -> f64 {
    (x * 4096.0).round() / 4096.0
}

/// A closed loop of cubics through `vertices` (in order), each edge bulging to its right by
/// `bulge` times its length (negative: to its left), its handles at a third and two thirds.
pub fn cubic_loop(vertices: &[[f64; 2]], bulge: f64) -> Vec<Cubic> {
    let n = vertices.len();
    (0..n)
        .map(|i| {
            let (p, q) = (vertices[i], vertices[(i + 1) % n]);
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            // The right-hand normal (dy, -dx) times the bulge.
            let (nx, ny) = (dy * bulge, -dx * bulge);
            let at = |u: f64| [snap(p[0] + dx * u + nx), snap(p[1] + dy * u + ny)];
            [p, at(1.0 / 3.0), at(2.0 / 3.0), q]
        })
        .collect()
}

/// A star of `points` spikes around `centre`: 2 `points` vertices alternately at radius
/// `outer` and `inner`, turned by `phase`, joined by cubics; counter-clockwise.
pub fn star(centre: [f64; 2], points: usize, outer: f64, inner: f64, phase: f64) -> Vec<Cubic> {
    let vertices: Vec<[f64; 2]> = (0..2 * points)
        .map(|i| {
            let angle = phase + PI * i as f64 / points as f64;
            let r = if i % 2 == 0 { outer } else { inner };
            [
                snap(centre[0] + r * angle.cos()),
                snap(centre[1] + r * angle.sin()),
            ]
        })
        .collect();
    cubic_loop(&vertices, 0.08)
}

/// The two stars of 8 cubic edges each of the small benchmark: overlapping, turned against
/// each other.
pub fn star_pair() -> [Vec<Cubic>; 2] {
    [
        star([0.0, 0.0], 4, 1.0, 0.45, 0.0),
        star([0.3, 0.2], 4, 1.0, 0.45, 0.4),
    ]
}

/// A random gear of `edges` cubic edges around `centre`: vertices at evenly spaced angles and
/// radii in [0.95, 1.05], so that each edge is short and meets only its neighbours and the
/// few edges of another gear that cross it.
pub fn gear(rng: &mut Rng, centre: [f64; 2], edges: usize) -> Vec<Cubic> {
    let vertices: Vec<[f64; 2]> = (0..edges)
        .map(|i| {
            let angle = 2.0 * PI * i as f64 / edges as f64;
            let r = 0.95 + 0.1 * rng.unit();
            [
                snap(centre[0] + r * angle.cos()),
                snap(centre[1] + r * angle.sin()),
            ]
        })
        .collect();
    cubic_loop(&vertices, 0.05)
}

/// The pair of gears of the scale benchmark: `edges` edges each, the second moved by (0.3, 0.1)
/// (the boundaries cross at a few places; most edges meet no edge of the other gear).
pub fn gear_pair(edges: usize) -> [Vec<Cubic>; 2] {
    let mut rng = Rng(40 + edges as u64);
    [
        gear(&mut rng, [0.0, 0.0], edges),
        gear(&mut rng, [0.3, 0.1], edges),
    ]
}

/// A random star pair of the peers' corpus: 3 to 8 spikes each, random radii, centres and
/// turns, some edges straighter or rounder.
pub fn random_star_pair(rng: &mut Rng) -> [Vec<Cubic>; 2] {
    let one = |rng: &mut Rng| {
        let points = 3 + (rng.unit() * 6.0) as usize;
        let centre = [snap(rng.unit() * 0.6 - 0.3), snap(rng.unit() * 0.6 - 0.3)];
        let outer = 0.6 + 0.5 * rng.unit();
        let inner = outer * (0.3 + 0.5 * rng.unit());
        star(centre, points, outer, inner, rng.unit() * PI)
    };
    [one(rng), one(rng)]
}

/// A quadratic Bézier triangle: its 6 nodes in the contract's order p200, p110, p020, p101,
/// p011, p002.
pub type Triangle = [[f64; 2]; 6];

/// A random quadratic triangle near the one with corners `a`, `b`, `c`: corners moved by up to
/// 0.1, edge midpoints bent by up to 0.12 (small enough that the patch stays one-to-one).
pub fn random_triangle(rng: &mut Rng, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Triangle {
    let mut jiggle = |p: [f64; 2], by: f64| {
        [
            snap(p[0] + by * (2.0 * rng.unit() - 1.0)),
            snap(p[1] + by * (2.0 * rng.unit() - 1.0)),
        ]
    };
    let (a, b, c) = (jiggle(a, 0.1), jiggle(b, 0.1), jiggle(c, 0.1));
    let mid = |p: [f64; 2], q: [f64; 2]| [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
    let (ab, ac, bc) = (mid(a, b), mid(a, c), mid(b, c));
    [
        a,
        jiggle(ab, 0.12),
        b,
        jiggle(ac, 0.12),
        jiggle(bc, 0.12),
        c,
    ]
}

/// The triangle pairs of the triangle benchmark: the first near the unit right triangle, the
/// second near it too, turned half a turn and moved by up to (0.5, 0.5), so that most pairs overlap.
pub fn triangle_pairs(count: usize) -> Vec<[Triangle; 2]> {
    let mut rng = Rng(4040);
    (0..count)
        .map(|_| {
            let t1 = random_triangle(&mut rng, [0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
            let (dx, dy) = (0.5 * rng.unit(), 0.5 * rng.unit());
            let t2 = random_triangle(
                &mut rng,
                [1.0 + dx, 1.0 + dy],
                [dx, 1.0 + dy],
                [1.0 + dx, dy],
            );
            [t1, t2]
        })
        .collect()
}

/// A quadratic triangle with straight edges through the corners `a`, `b`, `c` (its edge
/// nodes the midpoints, exact for corners on the grid).
pub fn flat_triangle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Triangle {
    let mid = |p: [f64; 2], q: [f64; 2]| [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
    [a, mid(a, b), b, mid(a, c), mid(b, c), c]
}

/// Degenerate pairs of quadratic triangles, the configurations that break float-only
/// intersectors, each named: identical triangles, a shared edge (the mirror image across
/// it), half of an edge shared, a corner touching an edge from outside, a corner on a corner,
/// one triangle inside the other touching its edge, nested with a shared corner, a curved
/// edge tangent to a straight one from outside, and a triangle against a copy with its nodes
/// listed from another corner (the same region).
pub fn degenerate_triangle_pairs() -> Vec<(&'static str, [Triangle; 2])> {
    let unit = flat_triangle([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
    // The unit triangle with its edge 0 (along y = 0) bent down to the node (0.5, -0.25).
    let mut bent = unit;
    bent[1] = [0.5, -0.25];
    vec![
        ("identical", [unit, unit]),
        (
            "shared edge",
            [unit, flat_triangle([1.0, 0.0], [1.0, 1.0], [0.0, 1.0])],
        ),
        (
            "half an edge shared",
            [unit, flat_triangle([0.5, 0.0], [1.5, -1.0], [1.5, 0.0])],
        ),
        (
            "corner on an edge",
            [unit, flat_triangle([0.5, 0.5], [1.0, 0.5], [1.0, 1.0])],
        ),
        (
            "corner on a corner",
            [unit, flat_triangle([1.0, 0.0], [2.0, 0.0], [1.0, 1.0])],
        ),
        (
            "inside, touching an edge",
            [unit, flat_triangle([0.25, 0.0], [0.5, 0.0], [0.25, 0.25])],
        ),
        (
            "nested, a corner shared",
            [unit, flat_triangle([0.0, 0.0], [0.5, 0.0], [0.0, 0.5])],
        ),
        (
            "curved edge tangent to a straight one",
            [
                bent,
                flat_triangle([0.0, -0.125], [1.0, -0.125], [0.5, -0.5]),
            ],
        ),
        (
            "the same triangle from another corner",
            [unit, flat_triangle([1.0, 0.0], [0.0, 1.0], [0.0, 0.0])],
        ),
    ]
}
