//! The areas of the general float path: each curve's area polynomial evaluated at its
//! parameters' enclosures (the bounds of `bounds`), a face's or a loop's signed area, and the
//! assembled answer.

use super::bounds::{evaluate, hodograph, parameter, sign, AreaPolynomials, LEVEL};
use super::graph::Graph;
use crate::intersect::interval::{lower, upper};
use crate::num::bounded::{BoundedF64, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::region::answer::{Edge, Outline, ResultLoop};
use crate::region::chain::Run;
use crate::region::parameter::Parameter;

/// The area polynomials of the curves, evaluated at their parameters.
pub(super) struct Areas<'g, 'a> {
    graph: &'g Graph<'a>,
    polynomials: AreaPolynomials,
}

impl<'g, 'a> Areas<'g, 'a> {
    pub(super) fn new(graph: &'g Graph<'a>) -> Self {
        let boxes = graph.curves.iter().map(|c| &c.bbox);
        Areas {
            graph,
            polynomials: AreaPolynomials::new(graph.curves.len(), boxes),
        }
    }

    /// F_c at parameter index `k` of curve c.
    fn at(&mut self, c: usize, k: usize) -> BoundedF64 {
        let f = self.polynomials.of(c, self.graph.curves[c].points);
        let params = &self.graph.params[c];
        if k == 0 {
            return f[0];
        }
        if k == params.len() - 1 {
            return f[f.len() - 1];
        }
        evaluate(f, 1, bounded(&params[k]))[0]
    }
}

impl Areas<'_, '_> {
    /// An enclosure of the integral of (x - o) dy along curve c from parameter index
    /// `from` to `to` (either way).
    pub(super) fn piece(&mut self, c: usize, from: usize, to: usize) -> BoundedF64 {
        self.at(c, to).sub(&self.at(c, from))
    }
}

/// The parameter as a double in its enclosure with the enclosure's width as the bound.
fn bounded(p: &Parameter) -> BoundedF64 {
    parameter(p.approx(), p.enclosure())
}

/// An enclosure of the derivative P'(t) of the curve with control points `points` at the
/// parameter t.
pub(super) fn tangent(points: &[[f64; 2]], t: &Parameter) -> [BoundedF64; 2] {
    let mut h = [BoundedF64::default(); LEVEL];
    let len = hodograph(points, &mut h);
    evaluate(&h[..len], 2, bounded(t))
}

/// An enclosure of the second derivative P''(t): the Bernstein coefficients
/// n (n - 1) (p_(i+2) - 2 p_(i+1) + p_i) evaluated at t (zero for a segment).
pub(super) fn second_derivative(points: &[[f64; 2]], t: &Parameter) -> [BoundedF64; 2] {
    let n = points.len() - 1;
    if n < 2 {
        return [BoundedF64::exact(0.0), BoundedF64::exact(0.0)];
    }
    let mut h = [BoundedF64::default(); LEVEL];
    let scale = BoundedF64::exact((n * (n - 1)) as f64);
    let two = BoundedF64::exact(2.0);
    for (i, w) in points.windows(3).enumerate() {
        for a in 0..2 {
            let (p0, p1, p2) = (
                BoundedF64::exact(w[0][a]),
                BoundedF64::exact(w[1][a]),
                BoundedF64::exact(w[2][a]),
            );
            h[2 * i + a] = p2.sub(&p1.mul(&two)).add(&p0).mul(&scale);
        }
    }
    evaluate(&h[..2 * (n - 1)], 2, bounded(t))
}

/// The answer: each boundary loop's edges, whether it is a hole (the sign of its area), and
/// the enclosure of the total area; `None` when a loop's sign is not proved or the area
/// enclosure is wider than the promised 2^-40 B.
pub(super) fn answer(areas: &mut Areas<'_, '_>, loops: Vec<Vec<Run>>) -> Option<Outline> {
    let graph = areas.graph;
    let mut total = BoundedF64::exact(0.0);
    let mut out = Vec::with_capacity(loops.len());
    for runs in &loops {
        let mut sum = BoundedF64::exact(0.0);
        let mut edges = Vec::with_capacity(runs.len());
        for r in runs {
            sum = sum.add(&areas.at(r.curve, r.to).sub(&areas.at(r.curve, r.from)));
            let id = graph.curves[r.curve].id;
            edges.push(Edge {
                region: id.region,
                loop_index: id.loop_index,
                curve: id.curve,
                from: graph.params[r.curve][r.from].clone(),
                to: graph.params[r.curve][r.to].clone(),
            });
        }
        let hole = sign(&sum)? < 0;
        total = total.add(&sum);
        out.push(ResultLoop { hole, edges });
    }
    if out.is_empty() {
        return Some(Outline {
            loops: out,
            area: [0.0, 0.0],
            report: Default::default(),
        });
    }
    let area = [lower(&total), upper(&total)];
    // B, the input box's area, rounded down.
    let b = graph
        .curves
        .iter()
        .fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, c| {
            [
                b[0].min(c.bbox[0]),
                b[1].min(c.bbox[1]),
                b[2].max(c.bbox[2]),
                b[3].max(c.bbox[3]),
            ]
        });
    let big_b = (b[2] - b[0]) * (b[3] - b[1]) * (1.0 - 4.0 * UNIT_ROUNDOFF);
    (area[1] - area[0] <= big_b * 2f64.powi(-40)).then_some(Outline {
        loops: out,
        area,
        report: Default::default(),
    })
}
