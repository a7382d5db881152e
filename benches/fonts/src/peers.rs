//! The two libraries on one task, each from the neutral [`Outline`]s to a consumed answer:
//! the input converted into the library's own form, the boolean, and the answer walked as a
//! user reads it, into a kurbo `BezPath` whose area is taken.
//!
//! * blossom: `Region::from_f64` of the curves, then `simplify` (one outline) or `boolean`
//!   with `Union` (two); each edge of each loop is its input curve cut by `Bezier::subsegment`
//!   between the edges' parameters (`Parameter::to_f64`), appended to the path.
//! * linesweeper: a `BezPath` per outline, then `binary_op` with `Union` and `NonZero` (the
//!   second path empty for one outline, as blossom's `simplify` is a union with the empty
//!   region); every contour of its answer walked (its area summed).

use crate::outline::Outline;
use blossom::region::{boolean, simplify, BooleanOp, FillRule, Region, RegionResult};
use blossom::Bezier;
use kurbo::{BezPath, ParamCurve, Shape};

/// The curves of an outline in blossom's form, `[contour][curve]`.
pub type Curves = Vec<Vec<Bezier<f64, 2>>>;

pub fn curves_of(outline: &Outline) -> Curves {
    outline
        .iter()
        .map(|contour| {
            contour
                .iter()
                .map(|c| Bezier::new(c.clone()).expect("2 to 4 control points"))
                .collect()
        })
        .collect()
}

/// What blossom answered, with the curves its edges name (kept for the checks).
pub struct BlossomAnswer {
    pub result: RegionResult,
    pub curves: [Curves; 2],
    /// The area of the consumed answer (from the cut pieces, in doubles).
    pub path_area: f64,
}

/// blossom on `a` alone (`simplify`) or on `a` and `b` (`boolean` with `Union`), the answer
/// consumed.
pub fn blossom(a: &Outline, b: Option<&Outline>) -> Result<BlossomAnswer, blossom::Error> {
    let ca = curves_of(a);
    let ra = Region::from_f64(ca.clone(), FillRule::NonZero)?;
    let (result, cb) = match b {
        None => (simplify(&ra)?, Curves::new()),
        Some(b) => {
            let cb = curves_of(b);
            let rb = Region::from_f64(cb.clone(), FillRule::NonZero)?;
            (boolean(&ra, &rb, BooleanOp::Union)?, cb)
        }
    };
    let curves = [ca, cb];
    let path = blossom_path(&result, &curves);
    Ok(BlossomAnswer {
        path_area: path.area(),
        result,
        curves,
    })
}

/// The piece of its input curve that `edge` is, as doubles.
pub fn piece(curves: &[Curves; 2], e: &blossom::region::Edge) -> Bezier<f64, 2> {
    curves[e.region][e.loop_index][e.curve].subsegment(e.from.to_f64()..e.to.to_f64())
}

/// A piece as a kurbo segment of its own degree.
pub fn segment(c: &Bezier<f64, 2>) -> kurbo::PathSeg {
    let p: Vec<kurbo::Point> = c.points().iter().map(|q| (q[0], q[1]).into()).collect();
    match p.len() {
        2 => kurbo::Line::new(p[0], p[1]).into(),
        3 => kurbo::QuadBez::new(p[0], p[1], p[2]).into(),
        4 => kurbo::CubicBez::new(p[0], p[1], p[2], p[3]).into(),
        n => unreachable!("font curves have 2 to 4 control points, not {n}"),
    }
}

/// The answer's loops as one path, each edge's piece appended with its own degree.
pub fn blossom_path(r: &RegionResult, curves: &[Curves; 2]) -> BezPath {
    let mut path = BezPath::new();
    for l in &r.loops {
        for (k, e) in l.edges.iter().enumerate() {
            let s = segment(&piece(curves, e));
            if k == 0 {
                path.move_to(s.start());
            }
            path.push(s.as_path_el());
        }
        path.close_path();
    }
    path
}

/// An outline as a kurbo path.
pub fn bez_path(outline: &Outline) -> BezPath {
    let mut path = BezPath::new();
    let point = |q: &[f64; 2]| kurbo::Point::new(q[0], q[1]);
    for contour in outline {
        path.move_to(point(&contour[0][0]));
        for c in contour {
            match c.len() {
                2 => path.line_to(point(&c[1])),
                3 => path.quad_to(point(&c[1]), point(&c[2])),
                4 => path.curve_to(point(&c[1]), point(&c[2]), point(&c[3])),
                n => unreachable!("font curves have 2 to 4 control points, not {n}"),
            }
        }
        path.close_path();
    }
    path
}

/// What linesweeper answered, consumed: the area of its contours.
pub struct LinesweeperAnswer {
    pub area: f64,
}

/// linesweeper on `a` alone (union with the empty path) or on `a` and `b`.
pub fn linesweeper(
    a: &Outline,
    b: Option<&Outline>,
) -> Result<LinesweeperAnswer, linesweeper::Error> {
    let pa = bez_path(a);
    let pb = b.map_or_else(BezPath::new, bez_path);
    let answer = linesweeper::binary_op(
        &pa,
        &pb,
        linesweeper::FillRule::NonZero,
        linesweeper::BinaryOp::Union,
    )?;
    let area: f64 = answer.contours().map(|c| c.path.area()).sum();
    Ok(LinesweeperAnswer {
        // Its contours run clockwise around the set in y-up font units: the signed sum is
        // minus the area.
        area: area.abs(),
    })
}
