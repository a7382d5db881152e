//! The winding numbers along each loop: an exact ray count at one vertex of the loop
//! against every other loop, and the loop's own orientation.
//!
//! **The ray count.** The winding number of closed loops around a point X on none of them is
//! the signed number of times they pass between the half-planes y < X_y and y >= X_y at a
//! point with x > X_x (upwards +1). For one curve with control points of doubles, compared
//! exactly with X (a double vertex): when every control point has y >= X_y, or every one
//! y < X_y, or every one x < X_x, the curve (inside the hull of its control points) passes
//! no such point: 0. When every one has x > X_x, every passage counts, and their signed
//! number is fixed by the ends: [y_n >= X_y] - [y_0 >= X_y]. Otherwise the curve is
//! undecided in this direction. The same holds for the rays along -x, +y and -y after a
//! quarter turn of the plane (negations of doubles: exact; turns keep winding numbers);
//! the first direction that decides every curve gives the count, and if none does, the
//! next vertex of the loop is tried. (The tests on every control point are tests on the
//! sides of the curve's box.)

use super::area::{loop_area_sign, Areas};
use super::split::Split;
use crate::intersect::algebraic::exact_f64;
use crate::num::bounded::UNIT_ROUNDOFF;
use crate::num::ring::Rational;
use crate::region::filtered::side::windings_among;
use num_traits::Zero;
use std::cmp::Ordering;

/// The winding numbers around a loop L of region R: `own` = [left of L, right of L] for R,
/// and `other` = the winding number of the other region at the start of curve `start` of L.
pub(super) struct LoopWindings {
    pub own: [i64; 2],
    pub other: i64,
    pub start: usize,
}

/// The winding numbers of both regions at `x` around every loop but `skip`, or `None` when
/// no direction decides every curve.
fn windings_at(split: &Split<'_>, x: [f64; 2], skip: usize) -> Option<[i64; 2]> {
    windings_among(x, || {
        split
            .curves
            .iter()
            .filter(move |c| c.loop_no != skip)
            .map(|c| (c.points, &c.bbox, c.id.region))
    })
}

/// The exact sign of the turn a -> v -> b: cross(v - a, b - v) (a float filter with
/// Shewchuk's bound, exact rationals when it does not decide).
fn turn_sign(a: [f64; 2], v: [f64; 2], b: [f64; 2]) -> Ordering {
    let (l, r) = ((v[0] - a[0]) * (b[1] - v[1]), (v[1] - a[1]) * (b[0] - v[0]));
    let det = l - r;
    let bound = 4.0 * UNIT_ROUNDOFF * (l.abs() + r.abs());
    if det.is_finite() && det.abs() > bound && det.abs() > 1e-290 {
        return det.partial_cmp(&0.0).expect("finite");
    }
    let q = |p: [f64; 2]| [exact_f64(p[0]), exact_f64(p[1])];
    let (a, v, b) = (q(a), q(v), q(b));
    let det = (&v[0] - &a[0]) * (&b[1] - &v[1]) - (&v[1] - &a[1]) * (&b[0] - &v[0]);
    det.cmp(&Rational::zero())
}

/// The orientation (+1 counter-clockwise, -1 clockwise) of the simple loop `l` from one of
/// its extreme corners, or `None` when none decides it.
///
/// Let v be a join of two curves of the loop on a side of the box of every control point of
/// the loop (least or largest x or y), so the loop lies in the closed half-plane on the
/// box's side of the line through v along that side (hulls), and the points just beyond it
/// are outside the loop. Near v the loop is the arriving curve, coming in along d_in = v - a
/// (a its last control point other than v), and the leaving one, along d_out = b - v (b its
/// first other than v), both in that half-plane. When cross(d_in, d_out) is not zero, the
/// inside near v is the wedge of angle below 180 degrees between -d_in and d_out (the other
/// wedge holds points beyond the line), which is on the left of the loop exactly when
/// cross(d_in, d_out) > 0.
pub(super) fn corner_orientation(split: &Split<'_>, l: usize) -> Option<i64> {
    let lp = &split.loops[l];
    let curves = &split.curves[lp.first..lp.first + lp.len];
    let b = curves.iter().fold(curves[0].bbox, |b, c| {
        [
            b[0].min(c.bbox[0]),
            b[1].min(c.bbox[1]),
            b[2].max(c.bbox[2]),
            b[3].max(c.bbox[3]),
        ]
    });
    for (k, c) in curves.iter().enumerate() {
        let v = c.points[0];
        if !(v[0] == b[0] || v[1] == b[1] || v[0] == b[2] || v[1] == b[3]) {
            continue;
        }
        let before = &curves[(k + curves.len() - 1) % curves.len()].points;
        let a = before.iter().rev().find(|p| **p != v)?;
        let after = c.points.iter().find(|p| **p != v)?;
        match turn_sign(*a, v, *after) {
            Ordering::Greater => return Some(1),
            Ordering::Less => return Some(-1),
            Ordering::Equal => {}
        }
    }
    None
}

/// How many vertices of a loop are tried before the exact path is left to answer.
const VERTICES_TRIED: usize = 8;

/// The winding numbers around every loop (see [`LoopWindings`]), or `None` when a loop's
/// orientation or a ray count is not decided.
pub(super) fn loop_windings(
    split: &Split<'_>,
    areas: &mut Areas<'_, '_>,
) -> Option<Vec<LoopWindings>> {
    let orientation = (0..split.loops.len())
        .map(|l| corner_orientation(split, l).or_else(|| loop_area_sign(areas, l)))
        .collect::<Option<Vec<i64>>>()?;
    split
        .loops
        .iter()
        .enumerate()
        .map(|(l, lp)| {
            let (start, w) = (lp.first..lp.first + lp.len)
                .take(VERTICES_TRIED)
                .find_map(|c| Some((c, windings_at(split, split.curves[c].points[0], l)?)))?;
            let base = w[lp.region];
            // Left of a counter-clockwise loop is its inside (+1); right of a clockwise one.
            let own = if orientation[l] > 0 {
                [base + 1, base]
            } else {
                [base, base - 1]
            };
            Some(LoopWindings {
                own,
                other: w[1 - lp.region],
                start,
            })
        })
        .collect()
}
