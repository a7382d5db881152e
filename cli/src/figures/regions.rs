//! Issue 40: certified booleans in one picture, four panels, every filled result drawn from the
//! library's exact answer ([`boolean`]), nothing typed in but the two regions' control points:
//!
//! * A, a dome: the segment from (0, 0) to (4, 0) and the cubic (4, 0), (4, 4), (0, 4), (0, 0)
//!   back over it (its top, at s = 1/2, is (2, 3) with a horizontal tangent);
//! * B: the segment from (2, 0) to (6, 0), which overlaps A's base on [2, 4]; a cubic right
//!   side (6, 0), (7, 1), (7, 2), (6, 3); the top segment from (6, 3) to (1, 3), tangent to
//!   A's dome at (2, 3); and the segment from (1, 3) back to (2, 0), crossing the dome.
//!
//! The panels: the two regions with their control points; A ∪ B; A ∩ B; A - B. Each result
//! is drawn as its loops sampled along the input curves between the exact parameters of its
//! edges, outer loops filled, holes filled with the background after them, and outlined.

use super::mesh::sample;
use super::palette::{BACKGROUND, CURVE, DOTS, DOTS_2, FILL, FILL_2, MESH_2, TEXT};
use super::scene::{Figure, Layer, Point3, View};
use blossom::region::{boolean, BooleanOp, FillRule, Region, RegionResult};
use blossom::{Bezier, Error, Rational};

/// Samples along each drawn edge.
const SAMPLES: usize = 120;

/// Integer control points of the curves of one loop.
pub type Loop = &'static [&'static [[i64; 2]]];

/// Region A, the dome.
pub const A: Loop = &[&[[0, 0], [4, 0]], &[[4, 0], [4, 4], [0, 4], [0, 0]]];
/// Region B.
pub const B: Loop = &[
    &[[2, 0], [6, 0]],
    &[[6, 0], [7, 1], [7, 2], [6, 3]],
    &[[6, 3], [1, 3]],
    &[[1, 3], [2, 0]],
];
/// Where each panel's origin goes on the page (integers, so that the moved regions are
/// exact): the inputs, the union, the intersection, the difference.
pub const OFFSETS: [[i64; 2]; 4] = [[0, 5], [9, 5], [0, 0], [9, 0]];
/// The operation of each panel after the first.
pub const OPS: [(BooleanOp, &str); 3] = [
    (BooleanOp::Union, "A ∪ B"),
    (BooleanOp::Intersection, "A ∩ B"),
    (BooleanOp::Difference, "A - B"),
];

/// The curves of `curves` moved by `offset`, exactly.
fn placed(curves: Loop, offset: [i64; 2]) -> Result<Vec<Bezier<Rational, 2>>, Error> {
    curves
        .iter()
        .map(|c| {
            Bezier::new(
                c.iter()
                    .map(|p| {
                        [
                            Rational::from_integer((p[0] + offset[0]).into()),
                            Rational::from_integer((p[1] + offset[1]).into()),
                        ]
                    })
                    .collect(),
            )
        })
        .collect()
}

/// The curve as doubles, for drawing.
fn fast(curve: &Bezier<Rational, 2>) -> Result<Bezier<f64, 2>, Error> {
    Bezier::new(
        curve
            .points()
            .iter()
            .map(|p| p.each_ref().map(blossom::rational_to_f64))
            .collect(),
    )
}

/// The points of `curve` over [a, b] (or from a down to b).
fn polyline(curve: &Bezier<f64, 2>, a: f64, b: f64) -> Vec<Point3> {
    sample(a, b, SAMPLES, |s| {
        let [x, y] = curve.eval(&s);
        Some([x, y, 0.0])
    })
}

/// The loops of a result, sampled: (outer loops, holes). `inputs[r][c]` is curve c of the
/// one loop of region r.
fn result_polygons(
    result: &RegionResult,
    inputs: &[Vec<Bezier<f64, 2>>; 2],
) -> (Vec<Vec<Point3>>, Vec<Vec<Point3>>) {
    let (mut outer, mut holes) = (Vec::new(), Vec::new());
    for lp in &result.loops {
        let mut polygon = Vec::new();
        for e in &lp.edges {
            let curve = &inputs[e.region][e.curve];
            polygon.extend(polyline(curve, e.from.to_f64(), e.to.to_f64()));
        }
        if lp.hole {
            holes.push(polygon);
        } else {
            outer.push(polygon);
        }
    }
    (outer, holes)
}

/// The input loops of `curves` as one polyline.
fn outline(curves: &[Bezier<f64, 2>]) -> Vec<Point3> {
    curves.iter().flat_map(|c| polyline(c, 0.0, 1.0)).collect()
}

/// The picture.
pub fn figure() -> Result<Figure, Error> {
    let mut layers = Vec::new();
    let mut outlines = Vec::new();
    let mut captions = Vec::new();
    // The inputs: A and B filled (B over A), outlined, with their control points.
    let (a, b) = (placed(A, OFFSETS[0])?, placed(B, OFFSETS[0])?);
    let (fa, fb) = (
        a.iter().map(fast).collect::<Result<Vec<_>, _>>()?,
        b.iter().map(fast).collect::<Result<Vec<_>, _>>()?,
    );
    layers.push(Layer::Fill {
        polygons: vec![outline(&fa)],
        colour: FILL,
    });
    outlines.push(outline(&fa));
    outlines.push(outline(&fb));
    captions.push((label_at(OFFSETS[0]), "A (dome) and B".to_string()));
    let dots = |curves: &[Bezier<f64, 2>]| -> Vec<Point3> {
        let mut points: Vec<Point3> = Vec::new();
        for c in curves {
            for p in c.points() {
                let p = [p[0], p[1], 0.0];
                if !points.contains(&p) {
                    points.push(p);
                }
            }
        }
        points
    };
    let (dots_a, dots_b) = (dots(&fa), dots(&fb));
    let mut second_outlines = vec![outline(&fb)];

    // The results.
    let mut fills = Vec::new();
    let mut holes = Vec::new();
    for (k, (op, name)) in OPS.iter().enumerate() {
        let offset = OFFSETS[k + 1];
        let (a, b) = (placed(A, offset)?, placed(B, offset)?);
        let regions = [
            Region::new(vec![a.clone()], FillRule::NonZero)?,
            Region::new(vec![b.clone()], FillRule::NonZero)?,
        ];
        let result = boolean(&regions[0], &regions[1], *op)?;
        let inputs = [
            a.iter().map(fast).collect::<Result<Vec<_>, _>>()?,
            b.iter().map(fast).collect::<Result<Vec<_>, _>>()?,
        ];
        let (outer, inner) = result_polygons(&result, &inputs);
        outlines.extend(outer.iter().cloned());
        outlines.extend(inner.iter().cloned());
        fills.extend(outer);
        holes.extend(inner);
        second_outlines.push(outline(&inputs[1]));
        second_outlines.push(outline(&inputs[0]));
        captions.push((
            label_at(offset),
            format!(
                "{name}: {} loop(s), area in [{:.6}, {:.6}]",
                result.loops.len(),
                result.area[0],
                result.area[1]
            ),
        ));
    }
    // B of the input panel over A; then the results; the inputs' outlines faint, the
    // results' outlines strong; dots on top.
    layers.push(Layer::Fill {
        polygons: vec![outline(&fb)],
        colour: FILL_2,
    });
    layers.push(Layer::Fill {
        polygons: fills,
        colour: FILL_2,
    });
    layers.push(Layer::Fill {
        polygons: holes,
        colour: BACKGROUND,
    });
    layers.push(Layer::lines(second_outlines, MESH_2, 1));
    layers.push(Layer::lines(outlines, CURVE, 2));
    layers.push(Layer::dots(dots_a, DOTS, 5));
    layers.push(Layer::dots(dots_b, DOTS_2, 5));
    layers.push(Layer::Labels {
        items: captions,
        colour: TEXT,
        offset: (0, 0),
    });
    Ok(Figure {
        file: "regions.svg",
        title: "Certified booleans: a shared edge, a tangency, a crossing".into(),
        legend: vec![
            (FILL, "region A".into()),
            (FILL_2, "region B; each result".into()),
            (CURVE, "boundaries (exact edge ends)".into()),
            (MESH_2, "the inputs under each result".into()),
            (DOTS, "control points of A".into()),
            (DOTS_2, "control points of B".into()),
        ],
        view: View::plane_around(&layers, true),
        layers,
    })
}

/// Where a panel's caption goes: above its regions (whose control points reach y = 4).
fn label_at(offset: [i64; 2]) -> Point3 {
    [offset[0] as f64, offset[1] as f64 + 4.4, 0.0]
}
