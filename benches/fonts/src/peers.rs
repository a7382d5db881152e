//! The two libraries on one task, each from the neutral [`Outline`]s to a consumed answer:
//! a kurbo `BezPath` per outline (the same paths for both), the boolean, and the answer as
//! kurbo paths whose area is taken (every element walked).
//!
//! * blossom (feature `kurbo`): `Region::from_bez_path`, then `simplify` (one outline) or
//!   `boolean` with `Union` (two), then `RegionResult::to_bez_path` (the pieces of
//!   `RegionResult::geometry`): what its `binary_op` does, split so that the checks get the
//!   `RegionResult`.
//! * linesweeper: `binary_op` with `Union` and `NonZero` (the second path empty for one
//!   outline, as blossom's `simplify` is a union with the empty region), every contour of its
//!   answer walked.

use crate::outline::Outline;
use blossom::region::{boolean, simplify, BooleanOp, FillRule, Region, RegionResult};
use blossom::Bezier;
use kurbo::{BezPath, Shape};

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

/// What blossom answered, with the curves its edges name (for the checks).
pub struct BlossomAnswer {
    pub result: RegionResult,
    /// The area of the consumed answer (its `BezPath`).
    pub path_area: f64,
}

/// blossom on `a` alone (`simplify`) or on `a` and `b` (`boolean` with `Union`), the answer
/// consumed.
pub fn blossom(a: &Outline, b: Option<&Outline>) -> Result<BlossomAnswer, blossom::Error> {
    let ra = Region::from_bez_path(&bez_path(a), FillRule::NonZero)?;
    let result = match b {
        None => simplify(&ra)?,
        Some(b) => {
            let rb = Region::from_bez_path(&bez_path(b), FillRule::NonZero)?;
            boolean(&ra, &rb, BooleanOp::Union)?
        }
    };
    let path = result.to_bez_path()?;
    Ok(BlossomAnswer {
        path_area: path.area(),
        result,
    })
}

/// The piece of its input curve that `edge` is, cut here from the curves of the outlines
/// (`curves[e.region]`) at the edge's rounded parameters (the checks' own cut, not the
/// library's `geometry`).
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
