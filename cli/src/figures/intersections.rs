//! Issue 26: certified intersections in one picture, four panels side by side, every mark
//! placed from the library's exact answer ([`intersect_curves`], [`self_intersections`]),
//! nothing typed in but the control points:
//!
//! * crossing: a cubic P and its mirror image Q in the line y = 1 (three transversal
//!   crossings, two at irrational parameters 1/2 -+ sqrt(15)/10);
//! * touching: two parabolic arcs, one opening down, one up, that touch at one point with a
//!   common tangent (intersection multiplicity 2);
//! * overlap: two stretches of one cubic C, P = C on [0, 2/3] and Q = C on [1/3, 1], that
//!   coincide on C over [1/3, 2/3]; the common stretch, whose ends the library finds
//!   exactly, is drawn highlighted over both curves;
//! * loop: a cubic crossing itself once.
//!
//! Isolated points flagged tangent by the library are drawn in the tangency colour, the others
//! in the crossing colour, self-intersections in a third; each panel's caption gives the
//! parameters the library computed (each the correctly rounded double of the exact value).

use super::mesh::sample;
use super::palette::{CURVE, DOTS, DOTS_3, DOTS_4, HIGHLIGHT, MESH_2, TEXT};
use super::scene::{Figure, Layer, Point3, View};
use blossom::{
    intersect_curves, self_intersections, AlgebraicReal, Bezier, Error, Intersections, Rational,
    Ring,
};

/// Samples of each drawn curve.
const SAMPLES: usize = 300;
/// The radius of the marks in pixels.
const MARK: u32 = 6;
/// The stroke width of the overlap's highlight in pixels.
const HIGHLIGHT_WIDTH: u32 = 7;

/// Integer control points, each panel's own coordinates.
pub type Control = &'static [[i64; 2]];

/// The crossing pair: P, and Q = P mirrored in y = 1 (P's x is increasing, so P(s) = Q(t)
/// exactly when s = t and y_P(s) = 1).
pub const CROSSING: [Control; 2] = [
    &[[0, 0], [1, 4], [3, -2], [4, 2]],
    &[[0, 2], [1, -2], [3, 4], [4, 0]],
];
/// The touching pair: (4s, 8s(1 - s)) and (4t, 4 - 8t(1 - t)), meeting only at s = t = 1/2.
pub const TOUCHING: [Control; 2] = [&[[0, 0], [2, 4], [4, 0]], &[[0, 4], [2, 0], [4, 4]]];
/// The cubic C of which the overlapping pair are stretches.
pub const OVERLAP_BASE: Control = &[[0, 0], [1, 3], [3, 3], [4, 0]];
/// The stretches of C: P = C on [0, 2/3], Q = C on [1/3, 1], ends as (numerator,
/// denominator).
pub const OVERLAP_RANGES: [[(i64, i64); 2]; 2] = [[(0, 1), (2, 3)], [(1, 3), (1, 1)]];
/// The cubic with a loop (symmetric about x = 2).
pub const LOOP: Control = &[[0, 0], [8, 4], [-4, 4], [4, 0]];
/// Where each panel's origin goes on the page: crossing, touching, overlap, loop.
pub const OFFSETS: [[f64; 2]; 4] = [[0.0, 5.0], [8.5, 4.5], [0.0, 0.0], [8.5, 0.0]];

type Exact = Vec<[Rational; 2]>;

fn rational(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// Integer control points moved to `offset` (a multiple of 1/2), exactly.
fn placed(points: &[[i64; 2]], offset: [f64; 2]) -> Exact {
    let half = |v: f64| rational((2.0 * v).round() as i64, 2);
    points
        .iter()
        .map(|p| {
            [
                Rational::from_int(p[0]) + half(offset[0]),
                Rational::from_int(p[1]) + half(offset[1]),
            ]
        })
        .collect()
}

/// The two stretches of [`OVERLAP_BASE`], exactly, by the library's subdivision.
pub fn overlap_pair(offset: [f64; 2]) -> Result<[Exact; 2], Error> {
    let base = Bezier::new(placed(OVERLAP_BASE, offset))?;
    Ok(OVERLAP_RANGES.map(|[(a, b), (c, d)]| {
        base.subsegment(rational(a, b)..rational(c, d))
            .into_points()
    }))
}

/// The polyline of the curve with control points `exact` over [a, b].
fn polyline(exact: &Exact, a: f64, b: f64) -> Result<Vec<Point3>, Error> {
    let fast = Bezier::new(
        exact
            .iter()
            .map(|p| p.each_ref().map(blossom::rational_to_f64))
            .collect(),
    )?;
    Ok(sample(a, b, SAMPLES, |s| {
        let [x, y] = fast.eval(&s);
        Some([x, y, 0.0])
    }))
}

fn f(x: &AlgebraicReal) -> f64 {
    x.to_f64()
}

/// The marks of a result: (crossings, tangencies) as points of the picture.
fn marks(found: &Intersections) -> (Vec<Point3>, Vec<Point3>) {
    let at = |p: &blossom::IntersectionPoint| [p.point[0], p.point[1], 0.0];
    let crossing = found.points.iter().filter(|p| !p.tangent).map(at).collect();
    let tangent = found.points.iter().filter(|p| p.tangent).map(at).collect();
    (crossing, tangent)
}

/// The parameters of isolated points as text, `(s, t)` to 4 decimals.
fn parameters(found: &Intersections) -> String {
    let pairs: Vec<String> = found
        .points
        .iter()
        .map(|p| format!("({:.4}, {:.4})", f(&p.s), f(&p.t)))
        .collect();
    pairs.join(", ")
}

/// A caption above a panel whose top is at `top`.
fn caption(offset: [f64; 2], top: f64, text: String) -> (Point3, String) {
    ([offset[0], offset[1] + top + 0.7, 0.0], text)
}

/// The picture.
pub fn figure() -> Result<Figure, Error> {
    let mut firsts = Vec::new();
    let mut seconds = Vec::new();
    let mut crossings = Vec::new();
    let mut tangencies = Vec::new();
    let mut highlights = Vec::new();
    let mut captions = Vec::new();

    let mut pair = |k: usize, p: Exact, q: Exact, top: f64, name: &str| -> Result<(), Error> {
        let found = intersect_curves(&p, &q)?;
        let (c, t) = marks(&found);
        crossings.extend(c);
        tangencies.extend(t);
        for o in &found.overlaps {
            highlights.push(polyline(&p, f(&o.s[0]), f(&o.s[1]))?);
        }
        let text = if found.overlaps.is_empty() {
            format!("{name}: (s, t) = {}", parameters(&found))
        } else {
            let o = &found.overlaps[0];
            format!(
                "{name}: s in [{:.4}, {:.4}] = t in [{:.4}, {:.4}]",
                f(&o.s[0]),
                f(&o.s[1]),
                f(&o.t[0]),
                f(&o.t[1])
            )
        };
        captions.push(caption(OFFSETS[k], top, text));
        firsts.push(polyline(&p, 0.0, 1.0)?);
        seconds.push(polyline(&q, 0.0, 1.0)?);
        Ok(())
    };
    pair(
        0,
        placed(CROSSING[0], OFFSETS[0]),
        placed(CROSSING[1], OFFSETS[0]),
        2.0,
        "crossing",
    )?;
    pair(
        1,
        placed(TOUCHING[0], OFFSETS[1]),
        placed(TOUCHING[1], OFFSETS[1]),
        4.0,
        "touching",
    )?;
    let [p, q] = overlap_pair(OFFSETS[2])?;
    pair(2, p, q, 2.25, "overlap")?;

    let looped = placed(LOOP, OFFSETS[3]);
    let found = self_intersections(&looped)?;
    let loops: Vec<Point3> = found
        .points
        .iter()
        .map(|p| [p.point[0], p.point[1], 0.0])
        .collect();
    captions.push(caption(
        OFFSETS[3],
        3.0,
        format!("loop: P(s) = P(t) at (s, t) = {}", parameters(&found)),
    ));
    firsts.push(polyline(&looped, 0.0, 1.0)?);

    let layers = vec![
        Layer::lines(firsts, CURVE, 2),
        Layer::lines(seconds, MESH_2, 2),
        Layer::lines(highlights, HIGHLIGHT, HIGHLIGHT_WIDTH),
        Layer::dots(crossings, DOTS, MARK),
        Layer::dots(tangencies, DOTS_4, MARK),
        Layer::dots(loops, DOTS_3, MARK),
        Layer::Labels {
            items: captions,
            colour: TEXT,
            offset: (0, 0),
        },
    ];
    Ok(Figure {
        file: "intersections.svg",
        title: "Certified intersections: crossing, touching, overlap, loop".into(),
        legend: vec![
            (CURVE, "first curve P (and the loop)".into()),
            (MESH_2, "second curve Q".into()),
            (HIGHLIGHT, "overlap, exact ends".into()),
            (DOTS, "transversal crossing".into()),
            (DOTS_4, "tangency (exact flag)".into()),
            (DOTS_3, "self-intersection".into()),
        ],
        view: View::plane_around(&layers, true),
        layers,
    })
}
