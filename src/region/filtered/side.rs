//! The winding numbers of both regions at a point of doubles, counted exactly on the boxes
//! of the curves (a seed of stage 3, `faces`).
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
//! caller tries another point. (The tests on every control point are tests on the sides of
//! the curve's box.)

use super::graph::Graph;

/// The point p turned so that the ray along direction `d` (0: +x, 1: +y, 2: -x, 3: -y) runs
/// along +x.
fn turn(p: [f64; 2], d: usize) -> [f64; 2] {
    match d {
        0 => p,
        1 => [p[1], -p[0]],
        2 => [-p[0], -p[1]],
        _ => [-p[1], p[0]],
    }
}

/// The signed number of passages of the curve across the ray from x along direction `d`,
/// or `None` when the control points do not decide it (module docs). The tests on every
/// control point are tests on the sides of their box `bbox` (`[x_lo, y_lo, x_hi, y_hi]`),
/// turned with the plane.
fn ray_passages(x: [f64; 2], points: &[[f64; 2]], bbox: &[f64; 4], d: usize) -> Option<i64> {
    // The turned box: the least and largest turned coordinates.
    let (lo, hi) = {
        let (a, b) = (turn([bbox[0], bbox[1]], d), turn([bbox[2], bbox[3]], d));
        (
            [a[0].min(b[0]), a[1].min(b[1])],
            [a[0].max(b[0]), a[1].max(b[1])],
        )
    };
    let x = turn(x, d);
    if lo[1] >= x[1] || hi[1] < x[1] || hi[0] < x[0] {
        return Some(0);
    }
    if lo[0] > x[0] {
        let up = |p: [f64; 2]| i64::from(turn(p, d)[1] >= x[1]);
        return Some(up(points[points.len() - 1]) - up(points[0]));
    }
    None
}

/// The winding numbers of both regions at `x` around the curves `curves()` yields (as
/// control points, box and region; together whole loops, none through x), or `None` when no
/// direction decides every curve.
pub(super) fn windings_among<'c, I>(x: [f64; 2], curves: impl Fn() -> I) -> Option<[i64; 2]>
where
    I: Iterator<Item = (&'c [[f64; 2]], &'c [f64; 4], usize)>,
{
    'directions: for d in 0..4 {
        let mut w = [0, 0];
        for (points, bbox, region) in curves() {
            match ray_passages(x, points, bbox, d) {
                Some(k) => w[region] += k,
                None => continue 'directions,
            }
        }
        return Some(w);
    }
    None
}

/// [`windings_among`] every curve of the graph but those `skip` names.
pub(super) fn windings_at(
    graph: &Graph<'_>,
    x: [f64; 2],
    skip: impl Fn(usize) -> bool,
) -> Option<[i64; 2]> {
    windings_among(x, || {
        graph
            .curves
            .iter()
            .enumerate()
            .filter(|(i, _)| !skip(*i))
            .map(|(_, c)| (c.points, &c.bbox, c.id.region))
    })
}
