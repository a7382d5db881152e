//! The generic configuration's answer: each boundary loop's edges, its orientation and the
//! enclosure of the result's area, from the area polynomials of `area` (the bounds
//! themselves are `bounds`').
//!
//! Everything is computed in [`BoundedF64`] (a double with a rigorous bound on its distance
//! to the exact value of the same operations on the same inputs). A parameter t* known to lie
//! in an enclosure [lo, hi] of doubles around its correctly rounded double m enters as m with
//! the bound hi - lo (rounded up), which covers |t* - m|; evaluations by de Casteljau's
//! pyramid in convex form ([`ConvexStep`]) are then enclosures of the exact values at t*.
//!
//! **Area.** The signed area of a closed loop is the sum over its pieces of the integral of
//! (x - o) dy, for any constant o (the integral of o dy over a closed loop is zero); o is a
//! double near the middle of the input, which keeps the terms small. For a curve of degree n
//! with control points (x_i, y_i), the integrand (x(t) - o) y'(t) is a Bernstein polynomial
//! of degree 2n - 1 with coefficients
//! c_k = sum over i + j = k of C(n, i) C(n - 1, j) / C(2n - 1, k) (x_i - o) n (y_(j+1) - y_j),
//! so its antiderivative F(t) from 0 is the Bernstein polynomial of degree 2n with
//! coefficients f_0 = 0, f_(k+1) = f_k + c_k / (2n), and F(1) = f_(2n). A piece from a to b
//! contributes F(b) - F(a).

use super::area::Areas;
use super::split::Split;
use super::walk::BoundaryLoop;
use crate::intersect::interval::{lower, upper};
use crate::num::bounded::{BoundedF64, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::region::answer::{Edge, Outline, ResultLoop};
use crate::region::filtered::bounds::sign;
use crate::region::input::Doubles;
use crate::region::parameter::{Crossings, Parameter};
use std::sync::Arc;

/// The parameter of position `k` of curve c, as the answer gives it (`all`: the crossings,
/// made once the answer has any).
fn parameter_at(
    split: &Split<'_>,
    all: &mut Option<Arc<Crossings>>,
    doubles: [&Arc<Doubles>; 2],
    c: usize,
    k: usize,
) -> Parameter {
    let marks = &split.marks[c];
    if k == 0 || k == marks.len() + 1 {
        return Parameter::end(k != 0);
    }
    let m = marks[k - 1];
    let x = &split.crossings[m.crossing];
    let all = all
        .get_or_insert_with(|| {
            Crossings::new(
                [doubles[0].clone(), doubles[1].clone()],
                split.pairs.clone(),
            )
        })
        .clone();
    Parameter::crossing(
        all,
        x.pair,
        m.side,
        x.enclosures[0],
        x.enclosures[1],
        x.nearest[m.side],
    )
}

/// The answer: each boundary loop's edges, whether it is a hole (the sign of its area), and
/// the enclosure of the total area; `None` when a loop's sign is not proved or the area
/// enclosure is wider than the promised 2^-40 B.
pub(super) fn answer(
    areas: &mut Areas<'_, '_>,
    loops: Vec<BoundaryLoop>,
    doubles: [&Arc<Doubles>; 2],
) -> Option<Outline> {
    let split = areas.split;
    let mut all = None;
    let mut total = BoundedF64::exact(0.0);
    let mut out = Vec::with_capacity(loops.len());
    for runs in &loops {
        let mut sum = BoundedF64::exact(0.0);
        let mut edges = Vec::with_capacity(runs.len());
        for r in runs {
            sum = sum.add(&areas.at(r.curve, r.to).sub(&areas.at(r.curve, r.from)));
            let id = split.curves[r.curve].id;
            edges.push(Edge {
                region: id.region,
                loop_index: id.loop_index,
                curve: id.curve,
                from: parameter_at(split, &mut all, doubles, r.curve, r.from),
                to: parameter_at(split, &mut all, doubles, r.curve, r.to),
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
    let b = split
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
