//! Stage 2 of the float path: the counter-clockwise order of the half-edges around every
//! vertex.
//!
//! A half-edge leaves its origin along its curve P at the parameter τ, toward increasing
//! parameters (σ = +1) or decreasing ones (σ = -1); its direction there is u = σ P'(τ). The
//! eight *classes* of `angle` (the four open quadrants and the four axis directions,
//! counter-clockwise from +x) come from the signs of u's coordinates, each enclosed in
//! [`BoundedF64`] (τ enters as its correctly rounded double with the width of its
//! enclosure): a sign is taken when the enclosure excludes zero, and a coordinate is zero
//! when it is computed exactly zero with a zero bound (a horizontal or vertical line of a
//! font). Two half-edges of different classes are ordered by class; two in the same open
//! quadrant by the sign of cross(u_a, u_b) when its enclosure excludes zero. Everything else
//! (a zero derivative, two half-edges tangent at the vertex, an undecided sign) is decided
//! exactly by `angle::compare` on those two half-edges only, whose curves are made exact on
//! demand. A vertex of two half-edges (a join of two curves) needs no comparison at all.

use super::graph::Graph;
use super::measure::tangent;
use crate::error::Result;
use crate::num::bounded::BoundedF64;
use crate::num::ring::Ring;
use crate::region::angle::{class, compare, Branch};
use std::cmp::Ordering;

/// The sign of an enclosure: `Some(±1)` when it excludes zero, `Some(0)` when it is exactly
/// zero, `None` when undecided.
fn sign(x: &BoundedF64) -> Option<i8> {
    let (v, e) = (x.value(), x.error_bound());
    if v - e > 0.0 {
        Some(1)
    } else if v + e < 0.0 {
        Some(-1)
    } else if v == 0.0 && e == 0.0 {
        Some(0)
    } else {
        None
    }
}

/// The class (0..8 counter-clockwise from +x) of the direction with coordinate signs
/// (sx, sy), `None` for the zero vector.
fn class_of(sx: i8, sy: i8) -> Option<u8> {
    Some(match (sx, sy) {
        (1, 0) => 0,
        (1, 1) => 1,
        (0, 1) => 2,
        (-1, 1) => 3,
        (-1, 0) => 4,
        (-1, -1) => 5,
        (0, -1) => 6,
        (1, -1) => 7,
        _ => return None,
    })
}

/// A half-edge's direction in floating point: its class when proved, and the enclosure.
#[derive(Clone, Copy)]
struct Direction {
    class: Option<u8>,
    u: [BoundedF64; 2],
}

/// The counter-clockwise order of the half-edges around each vertex.
pub(super) struct Around {
    /// The half-edges leaving vertex v, counter-clockwise: `order[start[v]..start[v + 1]]`.
    pub order: Vec<usize>,
    pub start: Vec<usize>,
    /// The position of each half-edge in `order`.
    pub pos: Vec<usize>,
    /// The comparisons decided exactly.
    pub exact: usize,
}

impl Around {
    /// The half-edges leaving vertex v, counter-clockwise.
    pub fn at(&self, v: usize) -> &[usize] {
        &self.order[self.start[v]..self.start[v + 1]]
    }

    /// The half-edge leaving the same vertex as `h` just clockwise of it.
    pub fn clockwise(&self, h: usize, origin: usize) -> usize {
        let (s, n) = (
            self.start[origin],
            self.start[origin + 1] - self.start[origin],
        );
        self.order[s + (self.pos[h] - s + n - 1) % n]
    }
}

/// The direction of half-edge h in floating point.
fn direction(graph: &Graph<'_>, h: usize) -> Direction {
    let (c, at, toward) = graph.branch(h);
    let mut u = tangent(graph.curves[c].points, &graph.params[c][at]);
    if toward < at {
        u = [u[0].neg(), u[1].neg()];
    }
    let class = match (sign(&u[0]), sign(&u[1])) {
        (Some(sx), Some(sy)) => class_of(sx, sy),
        _ => None,
    };
    Direction { class, u }
}

/// The exact branch of half-edge h for `angle`.
fn exact_branch(graph: &Graph<'_>, h: usize) -> Result<Branch> {
    let (c, at, toward) = graph.branch(h);
    Ok(Branch {
        curve: c,
        at: graph.params[c][at].algebraic()?.clone(),
        toward: graph.params[c][toward].algebraic()?.clone(),
    })
}

/// The exact class of half-edge h (`angle::class` on its exact curve).
pub(super) fn exact_class(graph: &Graph<'_>, h: usize) -> Result<u8> {
    let b = exact_branch(graph, h)?;
    Ok(class(graph.curves[b.curve].exact(), &b).0)
}

/// The counter-clockwise order of half-edges a and b leaving one vertex, in floating point
/// when it decides, else exactly (`exact` counts those).
fn order(
    graph: &Graph<'_>,
    (a, da): (usize, &Direction),
    (b, db): (usize, &Direction),
    exact: &mut usize,
) -> Result<Ordering> {
    if let (Some(ca), Some(cb)) = (da.class, db.class) {
        if ca != cb {
            return Ok(ca.cmp(&cb));
        }
        if ca % 2 == 1 {
            let cross = da.u[0].mul(&db.u[1]).sub(&da.u[1].mul(&db.u[0]));
            match sign(&cross) {
                Some(1) => return Ok(Ordering::Less),
                Some(-1) => return Ok(Ordering::Greater),
                _ => {}
            }
        }
    }
    *exact += 1;
    let (ba, bb) = (exact_branch(graph, a)?, exact_branch(graph, b)?);
    Ok(compare(
        graph.curves[ba.curve].exact(),
        &ba,
        graph.curves[bb.curve].exact(),
        &bb,
    ))
}

/// The half-edges around every vertex in counter-clockwise order.
pub(super) fn around(graph: &Graph<'_>) -> Result<Around> {
    let n = graph.half_edges();
    let mut start = vec![0usize; graph.vertices + 1];
    for h in 0..n {
        start[graph.origin(h) + 1] += 1;
    }
    for v in 0..graph.vertices {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut ccw = vec![0usize; n];
    for h in 0..n {
        let v = graph.origin(h);
        ccw[fill[v]] = h;
        fill[v] += 1;
    }
    let mut exact = 0;
    let mut dirs: Vec<(usize, Direction)> = Vec::new();
    for v in 0..graph.vertices {
        let list = &mut ccw[start[v]..start[v + 1]];
        if list.len() <= 2 {
            continue;
        }
        // Only the half-edges at vertices of more than two need a direction.
        dirs.clear();
        dirs.extend(list.iter().map(|&h| (h, direction(graph, h))));
        let mut failed = None;
        dirs.sort_by(|(a, da), (b, db)| {
            order(graph, (*a, da), (*b, db), &mut exact).unwrap_or_else(|e| {
                failed.get_or_insert(e);
                Ordering::Equal
            })
        });
        for (slot, (h, _)) in list.iter_mut().zip(&dirs) {
            *slot = *h;
        }
        if let Some(e) = failed {
            return Err(e);
        }
    }
    let mut pos = vec![0usize; n];
    for (i, &h) in ccw.iter().enumerate() {
        pos[h] = i;
    }
    Ok(Around {
        order: ccw,
        start,
        pos,
        exact,
    })
}

/// The counter-clockwise order of two half-edges leaving one vertex (as the sort of
/// [`around`] decides it).
pub(super) fn ccw_order(graph: &Graph<'_>, a: usize, b: usize) -> Result<Ordering> {
    let (da, db) = (direction(graph, a), direction(graph, b));
    order(graph, (a, &da), (b, &db), &mut 0)
}

/// The class of every half-edge leaving vertex v, in floating point where proved, else
/// exactly.
pub(super) fn classes_at(graph: &Graph<'_>, around: &Around, v: usize) -> Result<Vec<u8>> {
    around
        .at(v)
        .iter()
        .map(|&h| match direction(graph, h).class {
            Some(c) => Ok(c),
            None => exact_class(graph, h),
        })
        .collect()
}
