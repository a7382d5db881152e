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
use super::measure::{second_derivative, tangent};
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

/// The direction of half-edge h in floating point. At a curve's end, and anywhere on a
/// segment, the derivative is n (p1 - p0) (or n (p_n - p_(n-1))): the signs of its
/// coordinates, hence its class, come from comparisons of doubles, exactly, when those two
/// points differ (a zero first derivative is left to the exact order). A straight quadratic
/// (module `straight`) leaves every point of it along its chord, as a segment does, even at
/// the end where its derivative vanishes.
fn direction(graph: &Graph<'_>, h: usize) -> Direction {
    let (c, at, toward) = graph.branch(h);
    let points = graph.curves[c].points;
    let param = &graph.params[c][at];
    let backward = toward < at;
    let n = points.len() - 1;
    let chord = (n == 1 || graph.curves[c].straight.is_some()).then(|| (points[0], points[n]));
    let leg = || match param.curve_end() {
        Some(true) => Some((points[n - 1], points[n])),
        Some(false) => Some((points[0], points[1])),
        None => None,
    };
    if let Some((a, b)) = chord.or_else(leg) {
        if a != b {
            let cmp = |x: f64, y: f64| -> i8 {
                match x.partial_cmp(&y) {
                    Some(Ordering::Greater) => 1,
                    Some(Ordering::Less) => -1,
                    _ => 0,
                }
            };
            let flip = if backward { -1 } else { 1 };
            let (sx, sy) = (flip * cmp(b[0], a[0]), flip * cmp(b[1], a[1]));
            let d = |k: usize| {
                let v = BoundedF64::exact(b[k]).sub(&BoundedF64::exact(a[k]));
                if backward {
                    v.neg()
                } else {
                    v
                }
            };
            return Direction {
                class: class_of(sx, sy),
                u: [d(0), d(1)],
            };
        }
    }
    let mut u = tangent(points, param);
    if backward {
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

/// Two half-edges leaving a vertex along the same axis direction (the same even class: both
/// tangents exactly parallel; `axis` is the index of their nonzero coordinate) ordered by their signed curvatures there, when the enclosures decide:
/// with u = σ P' and a = P'' (σ² = 1), κ = cross(u, a) / |u|³, and near the vertex the branch
/// of larger κ turns further counter-clockwise, so the smaller κ comes first (the order of
/// `angle`: branches tangent to one axis direction from the clockwise side up). |u| is the
/// absolute value of u's one nonzero coordinate, so no square root is needed:
/// κ_a < κ_b exactly when cross(u_a, a_a) |u_b|³ - cross(u_b, a_b) |u_a|³ < 0.
fn by_curvature(
    graph: &Graph<'_>,
    (a, da): (usize, &Direction),
    (b, db): (usize, &Direction),
    axis: usize,
) -> Option<Ordering> {
    let second = |h: usize| {
        let (c, at, _) = graph.branch(h);
        second_derivative(graph.curves[c].points, &graph.params[c][at])
    };
    let (sa, sb) = (second(a), second(b));
    let cross = |u: &[BoundedF64; 2], w: &[BoundedF64; 2]| u[0].mul(&w[1]).sub(&u[1].mul(&w[0]));
    let cube = |u: &[BoundedF64; 2]| {
        let m = if u[axis].value() < 0.0 {
            u[axis].neg()
        } else {
            u[axis]
        };
        m.mul(&m).mul(&m)
    };
    let d = cross(&da.u, &sa)
        .mul(&cube(&db.u))
        .sub(&cross(&db.u, &sb).mul(&cube(&da.u)));
    match sign(&d) {
        Some(1) => Some(Ordering::Greater),
        Some(-1) => Some(Ordering::Less),
        _ => None,
    }
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
        } else if let Some(o) = by_curvature(graph, (a, da), (b, db), usize::from(ca / 2 % 2 == 1))
        {
            return Ok(o);
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
