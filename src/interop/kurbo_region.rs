//! Feature `kurbo`: regions from kurbo's `BezPath` ([`Region::from_bez_path`]), a boolean's
//! answer as a `BezPath` ([`RegionResult::to_bez_path`]), and [`binary_op`], linesweeper's
//! one call (same name, arguments and order) answered by the certified [`boolean`].

use crate::error::{Error, ErrorKind, Result};
use crate::region::{boolean, BooleanOp, FillRule, Region, RegionResult, Subpaths};
use kurbo::{BezPath, PathEl, Point};

/// The error `error` of an argument of [`binary_op`] under its name.
fn under(argument: &str, error: Error) -> Error {
    let field = if error.field.is_empty() {
        argument.to_string()
    } else {
        format!("{argument}.{}", error.field)
    };
    Error::of(error.kind, field, error.message)
}

impl Region {
    /// The region of a kurbo `BezPath` under `fill`: each subpath a loop of lines, quadratics
    /// and cubics in order, every coordinate read exactly as the double it is. A `MoveTo`
    /// starts a subpath, a `ClosePath` or the next `MoveTo` ends it; a subpath that does not
    /// end where it started is closed by a line (kurbo and SVG fill it so); one none of whose
    /// segments moves (a lone `MoveTo`, `MoveTo` then `ClosePath`) is dropped; after a
    /// `ClosePath` a segment starts a new subpath at the closed one's start (kurbo's rule).
    /// Loop l is the l-th kept subpath, curve c its c-th segment, the closing line last.
    ///
    /// ```
    /// use blossom::region::{FillRule, Position, Region};
    /// use blossom::Rational;
    /// let mut path = kurbo::BezPath::new();
    /// path.move_to((0.0, 0.0));
    /// path.line_to((2.0, 0.0));
    /// path.quad_to((3.0, 1.0), (2.0, 2.0));
    /// path.line_to((0.0, 2.0)); // not closed: the closing line is added
    /// let r = Region::from_bez_path(&path, FillRule::NonZero)?;
    /// assert_eq!(r.loops()[0].len(), 4);
    /// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    /// assert_eq!(r.contains(&[q(5, 2), q(1, 1)]), Position::Inside);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Shape`] on `elements[k]` for a segment or close before the first `MoveTo`;
    /// [`ErrorKind::NotFinite`] on `elements[k]` for a NaN or an infinity.
    pub fn from_bez_path(path: &BezPath, fill: FillRule) -> Result<Region> {
        let mut paths = Subpaths::<f64>::new();
        let mut started = false;
        for (k, element) in path.elements().iter().enumerate() {
            let field = || format!("elements[{k}]");
            let xy = |p: &Point| [p.x, p.y];
            let points: Vec<[f64; 2]> = match element {
                PathEl::MoveTo(p) | PathEl::LineTo(p) => vec![xy(p)],
                PathEl::QuadTo(p, q) => vec![xy(p), xy(q)],
                PathEl::CurveTo(p, q, r) => vec![xy(p), xy(q), xy(r)],
                PathEl::ClosePath => Vec::new(),
            };
            if points.iter().flatten().any(|x| !x.is_finite()) {
                return Err(Error::of(
                    ErrorKind::NotFinite,
                    field(),
                    format!("expected finite coordinates, found {element:?}"),
                ));
            }
            match element {
                PathEl::MoveTo(_) => {
                    started = true;
                    paths.move_to(points[0]);
                }
                _ if !started => {
                    return Err(Error::of(
                        ErrorKind::Shape,
                        field(),
                        format!("a path starts with MoveTo, found {element:?}"),
                    ))
                }
                PathEl::ClosePath => paths.close(),
                _ => paths.segment(points),
            }
        }
        Region::from_f64(paths.finish(), fill)
    }
}

impl RegionResult {
    /// The result as a kurbo `BezPath`: subpath i for `loops[i]`, a `MoveTo` where its first
    /// edge starts, each edge as a `LineTo`, `QuadTo` or `CurveTo` of its input curve's degree
    /// with the control points of [`RegionResult::geometry`] (consecutive edges sharing their
    /// end point bit for bit, within the error bound stated there of the exact pieces), and a
    /// `ClosePath` ending every subpath. Outer loops run counter-clockwise and holes clockwise
    /// in a y-up frame (clockwise and counter-clockwise on a y-down screen); the nonzero and
    /// the even-odd rule both fill exactly the result. An empty result is the empty path.
    ///
    /// ```
    /// use blossom::region::{boolean, BooleanOp, FillRule, Region};
    /// let a = Region::from_svg_path("M 0 0 H 2 V 2 H 0 Z", FillRule::NonZero)?;
    /// let b = Region::from_svg_path("M 1 1 H 3 V 3 H 1 Z", FillRule::NonZero)?;
    /// let path = boolean(&a, &b, BooleanOp::Union)?.to_bez_path()?;
    /// // One subpath of eight lines.
    /// assert_eq!(path.elements().len(), 1 + 8 + 1);
    /// assert!((kurbo::Shape::area(&path) - 7.0).abs() < 1e-12);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Degree`] on `loops[l].edges[e]` for an edge of degree over 3 (kurbo has
    /// no segment for it; input from a `BezPath` or SVG never has one), and
    /// [`ErrorKind::NotFinite`] there for a coordinate that overflowed (input coordinates near
    /// the largest double only). An error rather than an `Option` so that the caller learns
    /// which edge; [`RegionResult::svg`] answers `None` in the same cases.
    pub fn to_bez_path(&self) -> Result<BezPath> {
        let point = |p: &[f64; 2]| Point::new(p[0], p[1]);
        let mut path = BezPath::new();
        for pieces in self.drawable()? {
            path.move_to(point(&pieces[0].points()[0]));
            for piece in &pieces {
                path.push(match piece.points() {
                    [_, p] => PathEl::LineTo(point(p)),
                    [_, p, q] => PathEl::QuadTo(point(p), point(q)),
                    [_, p, q, r] => PathEl::CurveTo(point(p), point(q), point(r)),
                    _ => unreachable!("drawable pieces have degree 1, 2 or 3"),
                });
            }
            path.close_path();
        }
        Ok(path)
    }
}

/// The boolean `op` of two kurbo paths, each read under `fill_rule` by
/// [`Region::from_bez_path`], answered by the certified [`boolean`] and returned by
/// [`RegionResult::to_bez_path`]: linesweeper's `binary_op` (0.5) with the same name,
/// arguments and order, so that a caller switches by changing the import (and `BinaryOp` to
/// [`BooleanOp`], whose variants have the same names).
///
/// Differences from linesweeper's: the answer is one `BezPath` (closed subpaths, outer loops
/// counter-clockwise in a y-up frame, holes clockwise; filled exactly by either fill rule), not
/// its `Contours` with parent links (each loop's `hole` flag and the nesting are in
/// [`boolean`]'s [`RegionResult`] for who needs them); every decision is exact for the input
/// doubles and the output's pieces are the input curves' own pieces, of their degrees,
/// within the error bound of [`RegionResult::geometry`] (linesweeper approximates within an
/// accuracy eps); an open subpath is closed by a line (linesweeper refuses it); errors are
/// the crate's [`Error`] naming `set_a.elements[k]` or `set_b.elements[k]`.
///
/// ```
/// use blossom::region::{binary_op, BooleanOp, FillRule};
/// use kurbo::Shape;
/// let square = kurbo::Rect::new(-1.0, -1.0, 1.0, 1.0).to_path(1e-6);
/// let circle = kurbo::Circle::new((0.0, 0.0), 1.2).to_path(1e-6);
/// let both = binary_op(&square, &circle, FillRule::EvenOdd, BooleanOp::Intersection)?;
/// // The square with its corners cut by the circle's cubics.
/// let area = both.area().abs();
/// assert!(3.0 < area && area < 4.0);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// Those of [`Region::from_bez_path`] under `set_a` or `set_b`, and those of [`boolean`].
pub fn binary_op(
    set_a: &BezPath,
    set_b: &BezPath,
    fill_rule: FillRule,
    op: BooleanOp,
) -> Result<BezPath> {
    let a = Region::from_bez_path(set_a, fill_rule).map_err(|e| under("set_a", e))?;
    let b = Region::from_bez_path(set_b, fill_rule).map_err(|e| under("set_b", e))?;
    boolean(&a, &b, op)?.to_bez_path()
}
