//! A boolean's result as pen commands (`BooleanResult.draw`), the orientation convention of
//! its input, and whether the result is its input's own outline (`remove_overlaps` keeps such
//! glyphs as they are).
//!
//! The pieces are the library's `RegionResult::geometry`: one curve per edge, of its input
//! curve's degree, consecutive pieces sharing their end point bit for bit and loops closing
//! exactly. Drawn into a pen: a line as `lineTo`, a cubic as `curveTo`, and a run of quadratics
//! as one `qCurveTo` of its off-curve points, the on-curve points between them left implied
//! where each is exactly (in exact arithmetic) the midpoint of its two neighbouring off-curve
//! points, as TrueType stores them; a loop of quadratics whose on-curve points are all implied
//! is `qCurveTo(*offcurves, None)` (TrueType's contour without on-curve points). A pen that
//! decomposes `qCurveTo` as fontTools' `BasePen` does (midpoints `0.5 * (a + b)`, exact for
//! such points) reads back the same pieces bit for bit.

use crate::area::edge_area_f64;
use crate::curve::{Curve, CurveShape};
use crate::numbers::rounded;
use blossom::region::RegionResult;

pub type Point = [f64; 2];

/// One pen call.
#[derive(Debug, PartialEq)]
pub enum Command {
    MoveTo(Point),
    LineTo(Point),
    /// Off-curve points then the on-curve end point.
    QCurveTo(Vec<Point>),
    /// The off-curve points of a closed contour without on-curve points (drawn
    /// `qCurveTo(*points, None)`).
    QCurveClosed(Vec<Point>),
    CurveTo([Point; 3]),
    ClosePath,
}

/// Whether `m` is exactly the midpoint of `a` and `b` (a + b == 2 m in exact arithmetic).
fn exact_midpoint(a: Point, b: Point, m: Point) -> bool {
    (0..2).all(|k| {
        let (x, y) = (a[k], b[k]);
        let s = x + y;
        // Knuth's two-sum: the rounding error of x + y, zero when the sum is exact.
        let yy = s - x;
        let error = (x - (s - yy)) + (y - yy);
        let twice = 2.0 * m[k];
        error == 0.0 && twice.is_finite() && s == twice
    })
}

/// The pen calls drawing one closed loop of pieces (each its control points, 2 to 4 of them,
/// each starting where the previous ends, the last ending where the first starts). The loop
/// starts at the first on-curve point that is one of `starts` (the input contours' starting
/// points, so that a contour the operation left alone keeps its start), else at the first
/// on-curve point that is not implied.
pub fn loop_commands(pieces: &[Vec<Point>], starts: &[Point], out: &mut Vec<Command>) {
    let k = pieces.len();
    // Join i is where piece i starts; implied when both neighbours are quadratics and it is
    // the exact midpoint of their off-curve points.
    let implied = |i: usize| {
        let (a, b) = (&pieces[(i + k - 1) % k], &pieces[i]);
        a.len() == 3 && b.len() == 3 && exact_midpoint(a[1], b[1], b[0])
    };
    let explicit = || (0..k).filter(|&i| !implied(i));
    let preferred = explicit().find(|&i| starts.contains(&pieces[i][0]));
    let Some(start) = preferred.or_else(|| explicit().next()) else {
        out.push(Command::QCurveClosed(pieces.iter().map(|p| p[1]).collect()));
        out.push(Command::ClosePath);
        return;
    };
    out.push(Command::MoveTo(pieces[start][0]));
    let mut offs = Vec::new();
    for step in 0..k {
        let i = (start + step) % k;
        let p = &pieces[i];
        let last = step + 1 == k;
        match p.len() {
            // The closing line is closePath's.
            2 if last => {}
            2 => out.push(Command::LineTo(p[1])),
            3 => {
                offs.push(p[1]);
                if last || !implied((i + 1) % k) {
                    let mut points = std::mem::take(&mut offs);
                    points.push(p[2]);
                    out.push(Command::QCurveTo(points));
                }
            }
            _ => out.push(Command::CurveTo([p[1], p[2], p[3]])),
        }
    }
    out.push(Command::ClosePath);
}

/// The control points of a curve as doubles (an exact curve's rounded).
fn points_f64(c: &Curve) -> Vec<Point> {
    let coords = match &c.shape {
        CurveShape::F64(x) => x.coordinates().to_vec(),
        CurveShape::Exact(x) => rounded(x.coordinates()),
    };
    coords.chunks_exact(2).map(|p| [p[0], p[1]]).collect()
}

/// The starting point of every loop of the inputs (as doubles).
pub fn loop_starts(inputs: [&[Vec<Curve>]; 2]) -> Vec<Point> {
    inputs
        .iter()
        .flat_map(|loops| loops.iter())
        .filter_map(|lp| lp.first().map(|c| points_f64(c)[0]))
        .collect()
}

/// The signed area (Green's theorem, in doubles) enclosed by loops of planar curves.
pub fn signed_area(loops: &[Vec<Curve>]) -> f64 {
    loops
        .iter()
        .flatten()
        .map(|c| edge_area_f64(&points_f64(c)))
        .sum()
}

/// Whether an outline runs clockwise by the convention of its input regions: the sign of the
/// signed area of the first region's loops (negative: clockwise, TrueType's convention for
/// outer contours), or of the second's when that is zero (an empty region); counter-clockwise
/// when both are zero.
pub fn input_clockwise(inputs: [&[Vec<Curve>]; 2]) -> bool {
    inputs
        .iter()
        .map(|loops| signed_area(loops))
        .find(|&a| a != 0.0)
        .is_some_and(|a| a < 0.0)
}

/// Whether the result's loops are exactly the loops of input region 0, each of them one whole
/// input loop (all its curves, whole, in order), traversed the input's way when drawn
/// (`reverse`: the result's loops drawn reversed), every input loop once: the outline drawn is
/// then the input's own.
pub fn is_input_outline(result: &RegionResult, input: &[Vec<Curve>], reverse: bool) -> bool {
    let whole = if reverse {
        (Some(true), Some(false))
    } else {
        (Some(false), Some(true))
    };
    let mut covered = vec![false; input.len()];
    for l in &result.loops {
        let Some(first) = l.edges.first() else {
            return false;
        };
        let index = first.loop_index;
        let Some(curves) = input.get(index) else {
            return false;
        };
        if covered[index] || l.edges.len() != curves.len() {
            return false;
        }
        let n = curves.len();
        let step = if reverse { n - 1 } else { 1 };
        for (k, e) in l.edges.iter().enumerate() {
            let next = &l.edges[(k + 1) % n];
            if e.region != 0
                || e.loop_index != index
                || (e.from.curve_end(), e.to.curve_end()) != whole
                || next.curve != (e.curve + step) % n
            {
                return false;
            }
        }
        covered[index] = true;
    }
    covered.iter().all(|&c| c)
}
