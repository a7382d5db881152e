//! Overlap removal (`simplify`) and unions on real glyph outlines (`tests/data/glyphs/`, eleven
//! glyphs of DejaVu Sans with overlapping, coincident, touching and abutting contours, and
//! straight quadratics), each
//! answer checked against computations that build no arrangement:
//!
//! * **inside iff the fill rule says so**: on a 40 x 40 grid of exact rational points over the
//!   input's box, offset by 1/3 unit so that no point lies on a curve of the font's grid, a point
//!   is inside the answer exactly when the input's fill rule puts it inside (`Region::windings`
//!   on the input: signed crossings of a ray), where the answer's inside is the winding number
//!   of the answer's own loops, counted here from the edges alone: the zeros of y(t) - y_p on
//!   each edge's input curve (`bezier_zeros`, exact), kept when they lie on the edge (compared
//!   exactly with the edge's `Parameter::algebraic` ends) and right of the point (an exact sign),
//!   counted half-open as the ray lifted by an infinitesimal. Every point must get 0 or 1: 1 on
//!   the inside also proves the outer loops counter-clockwise and the holes clockwise. The
//!   answer as a user chains it, `RegionResult::to_region` (its `geometry` pieces, rounded to
//!   doubles), must wind the same 0 or 1 around every point (`Region::windings` on it);
//! * **simple loops**: within a loop, two edges meet only where one ends and the next begins
//!   (every intersection of their input curves, `intersect_curves`, compared exactly with the
//!   edges' parameters); edges of different loops never cross transversally inside both and
//!   never run along each other;
//! * **area**: the area enclosure holds the area of the answer's pieces (Green's formula on
//!   each edge's curve cut at its parameters, in doubles), each loop's sign agrees with its
//!   `hole` flag, and for the glyphs whose contours neither cross nor touch (`oslash`, and the
//!   airplane `uni2708`, one contour) the enclosure holds the exact area of the input by
//!   Green's formula on its curves.
//!
//! The unions are the glyph with 3 copies moved by 20, 40, 60 units (the font bench's task)
//! and the glyph with itself (shift 0: every edge coincident with another).

#[path = "common/mod.rs"]
mod common;

use blossom::region::{
    boolean, simplify, BooleanOp, Edge, FillRule, Region, RegionResult, Winding,
};
use blossom::{bezier_zeros, intersect_curves, AlgebraicReal, Bezier, Intersections, Rational};
use common::exact;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::collections::HashMap;

/// The glyphs of `tests/data/glyphs/` (see its README for why each).
const GLYPHS: [&str; 11] = [
    "Ccedilla", "Aogonek", "Ohorn", "Iogonek", "uni1EC7", "uni259A", "uniF001", "uni04AA",
    "uni06B0", "oslash", "uni2708",
];

/// The glyphs whose contours neither cross nor touch themselves or each other: their
/// simplification is the input, and its area is Green's formula on the input.
const DISJOINT: [&str; 2] = ["oslash", "uni2708"];

const GRID: usize = 40;

type Contours = Vec<Vec<Vec<[f64; 2]>>>;

fn load(name: &str) -> Contours {
    let path = format!(
        "{}/tests/data/glyphs/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(json["glyph"], name);
    assert_eq!(json["fill"], "nonzero");
    let number = |v: &serde_json::Value| v.as_f64().expect("a number");
    json["contours"]
        .as_array()
        .expect("contours")
        .iter()
        .map(|c| {
            c.as_array()
                .expect("a contour")
                .iter()
                .map(|curve| {
                    curve
                        .as_array()
                        .expect("a curve")
                        .iter()
                        .map(|p| [number(&p[0]), number(&p[1])])
                        .collect()
                })
                .collect()
        })
        .collect()
}

fn moved(contours: &Contours, dx: f64) -> Contours {
    contours
        .iter()
        .map(|c| {
            c.iter()
                .map(|curve| curve.iter().map(|p| [p[0] + dx, p[1]]).collect())
                .collect()
        })
        .collect()
}

fn region(contours: &Contours) -> Region {
    let loops = contours
        .iter()
        .map(|c| c.iter().map(|p| Bezier::new(p.clone()).unwrap()).collect())
        .collect();
    Region::from_f64(loops, FillRule::NonZero).unwrap()
}

/// The grid: 40 x 40 points (x0 + i + 1/3, y0 + j + 1/3) with whole offsets spread over the
/// box of the control points.
fn grid(contours: &[&Contours]) -> (Vec<Rational>, Vec<Rational>) {
    let points = contours.iter().flat_map(|c| c.iter().flatten().flatten());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let third = Rational::new(1.into(), 3.into());
    let axis = |k: usize| -> Vec<Rational> {
        (0..GRID)
            .map(|i| {
                let x = lo[k] + ((i as f64 + 0.5) * (hi[k] - lo[k]) / GRID as f64).floor();
                exact(x.floor()) + &third
            })
            .collect()
    };
    (axis(0), axis(1))
}

/// The power coefficients (ascending) of the Bézier function with coefficients `b`.
fn power(b: &[Rational]) -> Vec<Rational> {
    let n = b.len() - 1;
    let binom = |n: usize, k: usize| -> BigInt {
        (0..k).fold(BigInt::one(), |acc, i| acc * (n - i) / (i + 1))
    };
    (0..=n)
        .map(|k| {
            let sum = (0..=k).fold(Rational::zero(), |acc, i| {
                let term = &b[i] * Rational::from_integer(binom(k, i));
                if (k - i) % 2 == 0 {
                    acc + term
                } else {
                    acc - term
                }
            });
            sum * Rational::from_integer(binom(n, k))
        })
        .collect()
}

/// A positive multiple of a rational polynomial with integer coefficients.
fn integer(p: &[Rational]) -> Vec<BigInt> {
    let l = p.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    p.iter()
        .map(|c| (c * Rational::from_integer(l.clone())).to_integer())
        .collect()
}

fn derivative(p: &[Rational]) -> Vec<Rational> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| c * Rational::from_integer(k.into()))
        .collect()
}

/// The exact curves of the two inputs of a result, `[region][loop][curve]`.
fn exact_curves(r: &RegionResult) -> [Vec<Vec<Bezier<Rational, 2>>>; 2] {
    [0, 1].map(|k| r.inputs()[k].loops().to_vec())
}

fn curve_of<'a>(
    curves: &'a [Vec<Vec<Bezier<Rational, 2>>>; 2],
    e: &Edge,
) -> &'a Bezier<Rational, 2> {
    &curves[e.region][e.loop_index][e.curve]
}

/// A zero t of y(t) - y_p on a curve: whether y - y_p is positive just after and just before t
/// (in increasing t), and a rational box [lo, hi] holding x(t).
struct RowZero {
    t: AlgebraicReal,
    above_after: bool,
    above_before: bool,
    x: [Rational; 2],
    /// x(t) - x_p is decided exactly from these when the box does not decide.
    x_power: Vec<Rational>,
}

fn zeros_at(curve: &Bezier<Rational, 2>, y: &Rational) -> Vec<RowZero> {
    let ys: Vec<Rational> = curve.points().iter().map(|p| &p[1] - y).collect();
    if ys.iter().all(|v| v > &Rational::zero()) || ys.iter().all(|v| v < &Rational::zero()) {
        return Vec::new();
    }
    let found = bezier_zeros(&ys).unwrap();
    if found.identically_zero {
        // Along the line y = y_p: the lifted ray misses it, and its ends count on the
        // neighbouring edges.
        return Vec::new();
    }
    let g = power(&ys);
    let xs: Vec<Rational> = curve.points().iter().map(|p| p[0].clone()).collect();
    let x_power = power(&xs);
    found
        .zeros
        .into_iter()
        .map(|z| {
            let mut h = g.clone();
            for _ in 0..z.multiplicity {
                h = derivative(&h);
            }
            let mut t = z.t;
            let after = t.sign_of(&integer(&h));
            assert_ne!(after, Ordering::Equal, "multiplicity is exact");
            let odd = z.multiplicity % 2 == 1;
            t.refine_to(&Rational::new(1.into(), BigInt::one() << 40));
            let (lo, hi) = t.interval();
            let piece = curve.subsegment(lo.clone()..hi.clone());
            let px = piece.points().iter().map(|p| p[0].clone());
            let x = [px.clone().min().expect("points"), px.max().expect("points")];
            RowZero {
                above_after: after == Ordering::Greater,
                above_before: (after == Ordering::Greater) != odd,
                t,
                x,
                x_power: x_power.clone(),
            }
        })
        .collect()
}

impl RowZero {
    /// Whether x(t) > x_p (x(t) = x_p would put the point on the curve).
    fn right_of(&self, x: &Rational) -> bool {
        if x < &self.x[0] {
            return true;
        }
        if x > &self.x[1] {
            return false;
        }
        let mut shifted = self.x_power.clone();
        shifted[0] -= x;
        match self.t.clone().sign_of(&integer(&shifted)) {
            Ordering::Greater => true,
            Ordering::Less => false,
            Ordering::Equal => panic!("a grid point lies on the answer's boundary"),
        }
    }
}

/// The winding numbers of the answer's loops around the grid points, `[row][column]`, from the
/// edges alone.
fn answer_windings(r: &RegionResult, xs: &[Rational], ys: &[Rational]) -> Vec<Vec<i64>> {
    let curves = exact_curves(r);
    let edges: Vec<&Edge> = r.loops.iter().flat_map(|l| &l.edges).collect();
    let ends: Vec<[AlgebraicReal; 2]> = edges
        .iter()
        .map(|e| {
            [
                e.from.algebraic().unwrap().clone(),
                e.to.algebraic().unwrap().clone(),
            ]
        })
        .collect();
    ys.iter()
        .map(|y| {
            let mut zeros: HashMap<(usize, usize, usize), Vec<RowZero>> = HashMap::new();
            // (contribution, the zero) of every crossing of an edge with the line.
            let mut crossings: Vec<(i64, (usize, usize, usize), usize)> = Vec::new();
            for (e, [a, b]) in edges.iter().zip(&ends) {
                let id = (e.region, e.loop_index, e.curve);
                let list = zeros
                    .entry(id)
                    .or_insert_with(|| zeros_at(curve_of(&curves, e), y));
                let forward = a.compare(b) == Ordering::Less;
                let (lo, hi) = if forward { (a, b) } else { (b, a) };
                for (k, z) in list.iter().enumerate() {
                    if z.t.compare(lo) == Ordering::Less || z.t.compare(hi) == Ordering::Greater {
                        continue;
                    }
                    let (after, before) = if forward {
                        (z.above_after, z.above_before)
                    } else {
                        (z.above_before, z.above_after)
                    };
                    let at_start = z.t.compare(a) == Ordering::Equal;
                    let at_end = z.t.compare(b) == Ordering::Equal;
                    let c = i64::from(!at_end && after) - i64::from(!at_start && before);
                    if c != 0 {
                        crossings.push((c, id, k));
                    }
                }
            }
            xs.iter()
                .map(|x| {
                    crossings
                        .iter()
                        .filter(|(_, id, k)| zeros[id][*k].right_of(x))
                        .map(|(c, _, _)| c)
                        .sum()
                })
                .collect()
        })
        .collect()
}

/// Checks that a grid point (`points`, row by row over `xs` x `ys`) is inside the answer `r`
/// (its loops wind once around it, counted from the edges and by `to_region`) exactly when
/// `inside` (given the point's index) says it is inside the input; returns the number of grid
/// points checked (those off the input's curves).
fn check_inside(
    what: &str,
    r: &RegionResult,
    (xs, ys): &(Vec<Rational>, Vec<Rational>),
    points: &[[Rational; 2]],
    inside: impl Fn(usize) -> Option<bool>,
) -> usize {
    let w = answer_windings(r, xs, ys);
    let chained = r.to_region().unwrap().windings(points);
    let mut checked = 0;
    let mut inner = 0;
    for (j, y) in ys.iter().enumerate() {
        for (i, x) in xs.iter().enumerate() {
            let Some(expected) = inside(j * xs.len() + i) else {
                continue;
            };
            let got = w[j][i];
            assert!(
                got == i64::from(expected),
                "{what}: at ({x}, {y}) the answer's loops wind {got} times, the input's fill \
                 rule says {}",
                if expected { "inside" } else { "outside" }
            );
            let k = j * xs.len() + i;
            assert_eq!(
                chained[k],
                Winding::Number(got),
                "{what}: at ({x}, {y}) to_region winds otherwise"
            );
            checked += 1;
            inner += usize::from(expected);
        }
    }
    assert!(
        inner > 0 && inner < checked,
        "{what}: the grid misses the shape"
    );
    checked
}

/// Where an exact parameter lies relative to the closed range of an edge: `Some(true)` at one
/// of its ends, `Some(false)` strictly inside, `None` outside.
fn on_edge(t: &AlgebraicReal, [a, b]: &[AlgebraicReal; 2]) -> Option<bool> {
    let (lo, hi) = if a.compare(b) == Ordering::Less {
        (a, b)
    } else {
        (b, a)
    };
    match (t.compare(lo), t.compare(hi)) {
        (Ordering::Less, _) | (_, Ordering::Greater) => None,
        (Ordering::Equal, _) | (_, Ordering::Equal) => Some(true),
        _ => Some(false),
    }
}

/// The box of an edge's piece in doubles, widened by `pad`.
fn piece_box(c: &Bezier<Rational, 2>, e: &Edge, pad: f64) -> [f64; 4] {
    let f = Bezier::new(
        c.points()
            .iter()
            .map(|p| {
                [
                    blossom::rational_to_f64(&p[0]),
                    blossom::rational_to_f64(&p[1]),
                ]
            })
            .collect(),
    )
    .unwrap()
    .subsegment(e.from.to_f64()..e.to.to_f64());
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in f.points() {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    [b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad]
}

/// The loops are simple (see the module docs), and no two edges run along each other.
fn check_simple(what: &str, r: &RegionResult) {
    let curves = exact_curves(r);
    let mut found: HashMap<[(usize, usize, usize); 2], Intersections> = HashMap::new();
    let edges: Vec<(usize, usize, &Edge)> = r
        .loops
        .iter()
        .enumerate()
        .flat_map(|(l, lp)| lp.edges.iter().enumerate().map(move |(k, e)| (l, k, e)))
        .collect();
    let ends: Vec<[AlgebraicReal; 2]> = edges
        .iter()
        .map(|(_, _, e)| {
            [
                e.from.algebraic().unwrap().clone(),
                e.to.algebraic().unwrap().clone(),
            ]
        })
        .collect();
    let boxes: Vec<[f64; 4]> = edges
        .iter()
        .map(|(_, _, e)| piece_box(curve_of(&curves, e), e, 1e-6))
        .collect();
    let id = |e: &Edge| (e.region, e.loop_index, e.curve);
    for i in 0..edges.len() {
        for j in i + 1..edges.len() {
            let (bi, bj) = (boxes[i], boxes[j]);
            if bi[0] > bj[2] || bj[0] > bi[2] || bi[1] > bj[3] || bj[1] > bi[3] {
                continue;
            }
            let ((li, ki, ei), (lj, kj, ej)) = (edges[i], edges[j]);
            let same_loop = li == lj;
            let n = r.loops[li].edges.len();
            // The joins the two edges may share: (parameter on ei, parameter on ej).
            let mut joins: Vec<(&AlgebraicReal, &AlgebraicReal)> = Vec::new();
            if same_loop && kj == ki + 1 {
                joins.push((&ends[i][1], &ends[j][0]));
            }
            if same_loop && ki == 0 && kj == n - 1 {
                joins.push((&ends[i][0], &ends[j][1]));
            }
            let allowed = |s: &AlgebraicReal, t: &AlgebraicReal| {
                joins.iter().any(|(a, b)| {
                    s.compare(a) == Ordering::Equal && t.compare(b) == Ordering::Equal
                })
            };
            if id(ei) == id(ej) {
                // One curve: the ranges share at most a join.
                let (lo_i, hi_i) = sorted(&ends[i]);
                let (lo_j, hi_j) = sorted(&ends[j]);
                let lo = if lo_i.compare(lo_j) == Ordering::Less {
                    lo_j
                } else {
                    lo_i
                };
                let hi = if hi_i.compare(hi_j) == Ordering::Less {
                    hi_i
                } else {
                    hi_j
                };
                match lo.compare(hi) {
                    Ordering::Greater => {}
                    Ordering::Equal => assert!(
                        allowed(lo, lo) || !same_loop,
                        "{what}: edges {li}.{ki} and {lj}.{kj} of one loop meet at {lo:?} of one curve"
                    ),
                    Ordering::Less => {
                        panic!("{what}: edges {li}.{ki} and {lj}.{kj} overlap on one curve")
                    }
                }
                continue;
            }
            let key = [id(ei), id(ej)];
            let x = found.entry(key).or_insert_with(|| {
                intersect_curves(
                    curve_of(&curves, ei).points(),
                    curve_of(&curves, ej).points(),
                )
                .unwrap()
            });
            for p in &x.points {
                let (Some(end_i), Some(end_j)) = (on_edge(&p.s, &ends[i]), on_edge(&p.t, &ends[j]))
                else {
                    continue;
                };
                if same_loop {
                    assert!(
                        allowed(&p.s, &p.t),
                        "{what}: edges {li}.{ki} and {lj}.{kj} of one loop meet at {:?}, not at \
                         a join",
                        p.point
                    );
                } else {
                    assert!(
                        end_i || end_j || p.tangent,
                        "{what}: edges {li}.{ki} and {lj}.{kj} of two loops cross at {:?}",
                        p.point
                    );
                }
            }
            for o in &x.overlaps {
                // The stretch of the common piece inside edge i, carried to curve j, must
                // not enter edge j (to within rounding: the exact map is affine).
                let (s0, s1) = (o.s[0].to_f64(), o.s[1].to_f64());
                let (t0, t1) = (o.t[0].to_f64(), o.t[1].to_f64());
                let (a, b) = range(ei);
                let (lo, hi) = (a.max(s0), b.min(s1));
                if hi - lo <= 1e-9 {
                    continue;
                }
                let map = |s: f64| t0 + (s - s0) * (t1 - t0) / (s1 - s0);
                let (u, v) = (map(lo).min(map(hi)), map(lo).max(map(hi)));
                let (c, d) = range(ej);
                assert!(
                    v.min(d) - u.max(c) <= 1e-9,
                    "{what}: edges {li}.{ki} and {lj}.{kj} run along each other"
                );
            }
        }
    }
}

fn sorted(e: &[AlgebraicReal; 2]) -> (&AlgebraicReal, &AlgebraicReal) {
    if e[0].compare(&e[1]) == Ordering::Less {
        (&e[0], &e[1])
    } else {
        (&e[1], &e[0])
    }
}

fn range(e: &Edge) -> (f64, f64) {
    let (a, b) = (e.from.to_f64(), e.to.to_f64());
    (a.min(b), a.max(b))
}

/// The integral of x dy over a Bézier curve of doubles, by Green's formula on its control
/// points: sum x_i (y_(j+1) - y_j) n C(n-1, j) C(n, i) / (2n C(2n-1, i+j)).
fn green_f64(p: &[[f64; 2]]) -> f64 {
    let n = p.len() - 1;
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    };
    let mut sum = 0.0;
    for (i, pi) in p.iter().enumerate() {
        for j in 0..n {
            sum += pi[0] * (p[j + 1][1] - p[j][1]) * n as f64 * binom(n - 1, j) * binom(n, i)
                / (2.0 * n as f64 * binom(2 * n - 1, i + j));
        }
    }
    sum
}

/// The same, exactly.
fn green_exact(p: &[[Rational; 2]]) -> Rational {
    let n = p.len() - 1;
    let binom = |n: usize, k: usize| -> Rational {
        Rational::from_integer((0..k).fold(BigInt::one(), |acc, i| acc * (n - i) / (i + 1)))
    };
    let mut sum = Rational::zero();
    for (i, pi) in p.iter().enumerate() {
        for j in 0..n {
            sum += &pi[0] * (&p[j + 1][1] - &p[j][1]) * binom(n, 1) * binom(n - 1, j) * binom(n, i)
                / (binom(2 * n, 1) * binom(2 * n - 1, i + j));
        }
    }
    sum
}

/// The area of the answer's pieces agrees with its enclosure and its loops' hole flags.
fn check_area(what: &str, r: &RegionResult, box_area: f64) {
    let curves = exact_curves(r);
    let [lo, hi] = r.area;
    assert!(lo <= hi, "{what}: area enclosure [{lo}, {hi}]");
    let mut total = 0.0;
    for (l, lp) in r.loops.iter().enumerate() {
        let area: f64 = lp
            .edges
            .iter()
            .map(|e| {
                let c = curve_of(&curves, e);
                let f: Vec<[f64; 2]> = c
                    .points()
                    .iter()
                    .map(|p| {
                        [
                            blossom::rational_to_f64(&p[0]),
                            blossom::rational_to_f64(&p[1]),
                        ]
                    })
                    .collect();
                let piece = Bezier::new(f)
                    .unwrap()
                    .subsegment(e.from.to_f64()..e.to.to_f64());
                green_f64(piece.points())
            })
            .sum();
        assert_eq!(
            area < 0.0,
            lp.hole,
            "{what}: loop {l} of signed area {area}, hole {}",
            lp.hole
        );
        total += area;
    }
    let slack = 1e-9 * box_area;
    assert!(
        lo - slack <= total && total <= hi + slack,
        "{what}: the pieces enclose {total}, outside [{lo}, {hi}]"
    );
}

fn box_area(contours: &[&Contours]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in contours.iter().flat_map(|c| c.iter().flatten().flatten()) {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (hi[0] - lo[0]) * (hi[1] - lo[1])
}

/// Every check of an answer of nonzero fill whose input is `inputs`, the point inside the input
/// when inside one of the regions.
fn check(what: &str, r: &RegionResult, inputs: &[&Region], contours: &[&Contours]) {
    let g = grid(contours);
    let points: Vec<[Rational; 2]> =
        g.1.iter()
            .flat_map(|y| g.0.iter().map(move |x| [x.clone(), y.clone()]))
            .collect();
    let windings: Vec<Vec<Winding>> = inputs.iter().map(|r| r.windings(&points)).collect();
    let checked = check_inside(what, r, &g, &points, |k| {
        let mut inside = false;
        for w in &windings {
            match w[k] {
                Winding::Boundary => return None,
                Winding::Number(n) => inside |= FillRule::NonZero.inside(n),
            }
        }
        Some(inside)
    });
    assert!(
        checked > GRID * GRID * 9 / 10,
        "{what}: {checked} grid points off the curves"
    );
    check_simple(what, r);
    check_area(what, r, box_area(contours));
}

#[test]
fn simplify_agrees_with_the_fill_rule() {
    for name in GLYPHS {
        let c = load(name);
        let a = region(&c);
        let r = simplify(&a).unwrap();
        check(&format!("simplify {name}"), &r, &[&a], &[&c]);
        let curves: usize = c.iter().map(Vec::len).sum();
        let edges: usize = r.loops.iter().map(|l| l.edges.len()).sum();
        if DISJOINT.contains(&name) {
            // Nothing to remove: the answer is the input's curves, whole.
            assert_eq!(edges, curves, "{name}");
            let exact_area = exact_area(&a);
            let [lo, hi] = r.area;
            assert!(
                exact(lo) <= exact_area && exact_area <= exact(hi),
                "{name}: [{lo}, {hi}]"
            );
        } else {
            let whole = r.loops.iter().flat_map(|l| &l.edges).all(
                |e| matches!((e.from.curve_end(), e.to.curve_end()), (Some(a), Some(b)) if a != b),
            );
            assert!(
                !(whole && edges == curves),
                "{name}: the overlaps are not removed"
            );
        }
    }
}

/// The exact area of a region whose contours neither cross nor touch, drawn clockwise as
/// TrueType draws outer contours: minus Green's formula on its curves.
fn exact_area(a: &Region) -> Rational {
    -a.loops()
        .iter()
        .flatten()
        .map(|c| green_exact(c.points()))
        .sum::<Rational>()
}

/// The union of the glyph `name` with `others` (one region), checked, and no smaller than the
/// glyph (for the disjoint glyph, than its exact area).
fn check_union(name: &str, what: &str, others: &Contours) -> RegionResult {
    let c = load(name);
    let (a, b) = (region(&c), region(others));
    let r = boolean(&a, &b, BooleanOp::Union).unwrap();
    check(what, &r, &[&a, &b], &[&c, others]);
    let alone = simplify(&a).unwrap();
    assert!(
        r.area[1] >= alone.area[0],
        "{what}: the union is smaller than the glyph"
    );
    if DISJOINT.contains(&name) {
        assert!(exact(r.area[1]) >= exact_area(&a), "{what}");
    }
    r
}

#[test]
fn union_with_shifted_copies() {
    for name in GLYPHS {
        let c = load(name);
        let copies: Contours = (1..=3)
            .flat_map(|k| moved(&c, 20.0 * f64::from(k)))
            .collect();
        check_union(
            name,
            &format!("{name} united with 3 copies shifted by 20"),
            &copies,
        );
    }
}

#[test]
fn union_with_itself() {
    for name in GLYPHS {
        let c = load(name);
        let r = check_union(name, &format!("{name} united with itself"), &c);
        // A ∪ A = A: the same area as the glyph's overlap removal.
        let alone = simplify(&region(&c)).unwrap();
        assert!(
            r.area[0] <= alone.area[1] && alone.area[0] <= r.area[1],
            "{name}: A ∪ A has area {:?}, A {:?}",
            r.area,
            alone.area
        );
        if DISJOINT.contains(&name) {
            let exact_area = exact_area(&region(&c));
            assert!(exact(r.area[0]) <= exact_area && exact_area <= exact(r.area[1]));
        }
    }
}

/// The checks are not vacuous: they refuse answers with a loop left out, a loop reversed, a
/// loop given twice, a wrong hole flag and an area enclosure off the answer, and the simplicity
/// and area checks alone refuse what they are for.
#[test]
fn the_checks_catch_wrong_answers() {
    let c = load("Ohorn");
    let a = region(&c);
    let right = simplify(&a).unwrap();
    assert!(right.loops.len() >= 2, "Ohorn has a hole");
    let refused = |what: &str, f: &dyn Fn()| {
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        assert!(caught.is_err(), "{what}: accepted");
    };
    let mut r = right.clone();
    let hole = r.loops.iter().position(|l| l.hole).expect("a hole");
    r.loops.remove(hole);
    refused("hole left out", &|| {
        check("hole left out", &r, &[&a], &[&c])
    });
    let mut r = right.clone();
    let l = &mut r.loops[0];
    l.edges.reverse();
    for e in &mut l.edges {
        std::mem::swap(&mut e.from, &mut e.to);
    }
    refused("loop reversed", &|| {
        check("loop reversed", &r, &[&a], &[&c])
    });
    let mut r = right.clone();
    let twice = r.loops[0].clone();
    r.loops.push(twice);
    refused("loop twice", &|| check("loop twice", &r, &[&a], &[&c]));
    refused("loop twice, simple", &|| check_simple("loop twice", &r));
    let mut r = right.clone();
    let k = r.loops[0].edges.len() / 2;
    r.loops[0].edges.swap(0, k);
    refused("edges swapped, simple", &|| {
        check_simple("edges swapped", &r)
    });
    let mut r = right.clone();
    r.loops[0].hole = !r.loops[0].hole;
    refused("hole flag", &|| check_area("hole flag", &r, 1e6));
    let mut r = right.clone();
    r.area = [r.area[0] + 1.0, r.area[1] + 1.0];
    refused("area off", &|| check("area off", &r, &[&a], &[&c]));
}
