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
    /// assert_eq!(r.contains(&[q(9, 4), q(1, 1)]), Position::Inside);
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

#[cfg(test)]
mod tests {
    use super::binary_op;
    use crate::error::ErrorKind;
    use crate::region::{boolean, BooleanOp, FillRule, Position, Region};
    use crate::shape::array::Bezier;
    use crate::Rational;
    use kurbo::{BezPath, PathEl, Point, Shape};

    fn path(elements: Vec<PathEl>) -> BezPath {
        BezPath::from_vec(elements)
    }

    fn m(x: f64, y: f64) -> PathEl {
        PathEl::MoveTo(Point::new(x, y))
    }

    fn l(x: f64, y: f64) -> PathEl {
        PathEl::LineTo(Point::new(x, y))
    }

    fn square(x: f64, y: f64, s: f64) -> BezPath {
        path(vec![
            m(x, y),
            l(x + s, y),
            l(x + s, y + s),
            l(x, y + s),
            PathEl::ClosePath,
        ])
    }

    fn curve(points: &[[f64; 2]]) -> Bezier<f64, 2> {
        Bezier::new(points.to_vec()).unwrap()
    }

    /// The region's curves as doubles (its inputs were doubles).
    fn doubles(r: &Region) -> Vec<Vec<Bezier<f64, 2>>> {
        r.loops()
            .iter()
            .map(|curves| {
                curves
                    .iter()
                    .map(|c| {
                        let points = c
                            .points()
                            .iter()
                            .map(|p| p.clone().map(|x| crate::rational_to_f64(&x)));
                        Bezier::new(points.collect()).unwrap()
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn paths_become_loops_as_svg_fills_them() {
        let p = path(vec![
            m(0.0, 0.0),
            l(2.0, 0.0),
            PathEl::QuadTo(Point::new(3.0, 1.0), Point::new(2.0, 2.0)),
            PathEl::CurveTo(
                Point::new(1.5, 3.0),
                Point::new(0.5, 3.0),
                Point::new(0.0, 2.0),
            ),
            // Not closed: the line back to (0, 0) is added.
            m(5.0, 5.0),
            // A lone MoveTo and a MoveTo-ClosePath are dropped.
            m(7.0, 7.0),
            PathEl::ClosePath,
            m(10.0, 0.0),
            l(11.0, 0.0),
            l(10.0, 1.0),
            PathEl::ClosePath,
            // After ClosePath a segment starts at the closed subpath's start (10, 0).
            l(9.0, 0.0),
            l(10.0, -1.0),
            l(10.0, 0.0),
            PathEl::ClosePath,
        ]);
        let r = Region::from_bez_path(&p, FillRule::EvenOdd).unwrap();
        assert_eq!(r.fill(), FillRule::EvenOdd);
        assert!(r.doubles().is_some());
        let want = vec![
            vec![
                curve(&[[0.0, 0.0], [2.0, 0.0]]),
                curve(&[[2.0, 0.0], [3.0, 1.0], [2.0, 2.0]]),
                curve(&[[2.0, 2.0], [1.5, 3.0], [0.5, 3.0], [0.0, 2.0]]),
                curve(&[[0.0, 2.0], [0.0, 0.0]]),
            ],
            vec![
                curve(&[[10.0, 0.0], [11.0, 0.0]]),
                curve(&[[11.0, 0.0], [10.0, 1.0]]),
                curve(&[[10.0, 1.0], [10.0, 0.0]]),
            ],
            // Ends at its start: no closing line.
            vec![
                curve(&[[10.0, 0.0], [9.0, 0.0]]),
                curve(&[[9.0, 0.0], [10.0, -1.0]]),
                curve(&[[10.0, -1.0], [10.0, 0.0]]),
            ],
        ];
        assert_eq!(doubles(&r), want);
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        assert_eq!(r.contains(&[q(9, 4), q(1, 1)]), Position::Inside);
        assert_eq!(r.contains(&[q(5, 2), q(1, 1)]), Position::Boundary);
        assert!(Region::from_bez_path(&BezPath::new(), FillRule::NonZero)
            .unwrap()
            .loops()
            .is_empty());
    }

    #[test]
    fn bad_paths_name_the_element() {
        // kurbo's constructors refuse such a path in debug builds only; write it in place.
        let mut headless = path(vec![m(0.0, 0.0), l(1.0, 0.0)]);
        headless.elements_mut()[0] = l(1.0, 1.0);
        let e = Region::from_bez_path(&headless, FillRule::NonZero).unwrap_err();
        assert_eq!(
            (e.kind, e.field.as_str()),
            (ErrorKind::Shape, "elements[0]")
        );
        let e = Region::from_bez_path(
            &path(vec![m(0.0, 0.0), l(1.0, 0.0), l(f64::NAN, 1.0)]),
            FillRule::NonZero,
        )
        .unwrap_err();
        assert_eq!(
            (e.kind, e.field.as_str()),
            (ErrorKind::NotFinite, "elements[2]")
        );
        let e = binary_op(
            &square(0.0, 0.0, 1.0),
            &path(vec![m(0.0, f64::INFINITY)]),
            FillRule::NonZero,
            BooleanOp::Union,
        )
        .unwrap_err();
        assert_eq!(e.field, "set_b.elements[0]");
    }

    #[test]
    fn results_become_paths() {
        let (a, b) = (square(0.0, 0.0, 4.0), square(1.0, 1.0, 2.0));
        let ra = Region::from_bez_path(&a, FillRule::NonZero).unwrap();
        let rb = Region::from_bez_path(&b, FillRule::NonZero).unwrap();
        let r = boolean(&ra, &rb, BooleanOp::Difference).unwrap();
        let p = r.to_bez_path().unwrap();
        // kurbo's own signed area: the outer loop counter-clockwise (+16), the hole clockwise
        // (-4).
        assert_eq!(p.area(), 12.0);
        // The elements are the geometry's pieces, each subpath closed.
        let geometry = r.geometry();
        let mut expected = Vec::new();
        for pieces in &geometry {
            let pt = |p: [f64; 2]| Point::new(p[0], p[1]);
            expected.push(PathEl::MoveTo(pt(pieces[0].points()[0])));
            for piece in pieces {
                expected.push(PathEl::LineTo(pt(piece.points()[1])));
            }
            expected.push(PathEl::ClosePath);
        }
        assert_eq!(p.elements(), expected.as_slice());
        // Curves keep their kind: the intersection of a circle of cubics with a square.
        let circle = kurbo::Circle::new((0.0, 0.0), 1.2).to_path(1e-6);
        let cubics = circle
            .elements()
            .iter()
            .filter(|e| matches!(e, PathEl::CurveTo(..)))
            .count();
        assert!(cubics >= 4);
        let both = binary_op(
            &square(-1.0, -1.0, 2.0),
            &circle,
            FillRule::NonZero,
            BooleanOp::Intersection,
        )
        .unwrap();
        let kinds =
            |p: &BezPath, f: fn(&PathEl) -> bool| p.elements().iter().filter(|e| f(e)).count();
        // Four sides cut short by four arcs of the circle (each corner cut by one arc, which
        // may span two of the circle's cubics).
        assert_eq!(kinds(&both, |e| matches!(e, PathEl::LineTo(..))), 4);
        assert!(kinds(&both, |e| matches!(e, PathEl::CurveTo(..))) >= 4);
        assert_eq!(kinds(&both, |e| matches!(e, PathEl::QuadTo(..))), 0);
        // The area by kurbo against the certified enclosure of the same boolean.
        let exact = boolean(
            &Region::from_bez_path(&square(-1.0, -1.0, 2.0), FillRule::NonZero).unwrap(),
            &Region::from_bez_path(&circle, FillRule::NonZero).unwrap(),
            BooleanOp::Intersection,
        )
        .unwrap();
        let area = both.area();
        assert!(exact.area[0] - 1e-12 <= area && area <= exact.area[1] + 1e-12);
        // Union of the two squares' paths through binary_op: area 7.
        let u = binary_op(
            &square(0.0, 0.0, 2.0),
            &square(1.0, 1.0, 2.0),
            FillRule::EvenOdd,
            BooleanOp::Union,
        )
        .unwrap();
        assert_eq!(u.area(), 7.0);
        assert_eq!(u.elements().len(), 10);
        // An empty answer is the empty path.
        let none = binary_op(
            &square(0.0, 0.0, 1.0),
            &square(5.0, 5.0, 1.0),
            FillRule::NonZero,
            BooleanOp::Intersection,
        )
        .unwrap();
        assert!(none.elements().is_empty());
    }

    #[test]
    fn degree_over_three_is_an_error_naming_the_edge() {
        let quartic = Region::from_f64(
            vec![vec![
                curve(&[[0.0, 0.0], [1.0, -1.0], [2.0, 1.0], [3.0, -1.0], [4.0, 0.0]]),
                curve(&[[4.0, 0.0], [4.0, 2.0]]),
                curve(&[[4.0, 2.0], [0.0, 2.0]]),
                curve(&[[0.0, 2.0], [0.0, 0.0]]),
            ]],
            FillRule::NonZero,
        )
        .unwrap();
        let r = boolean(
            &quartic,
            &Region::empty(FillRule::NonZero),
            BooleanOp::Union,
        )
        .unwrap();
        let e = r.to_bez_path().unwrap_err();
        assert_eq!(e.kind, ErrorKind::Degree);
        let quartic_edge = r.loops[0].edges.iter().position(|e| e.curve == 0).unwrap();
        assert_eq!(e.field, format!("loops[0].edges[{quartic_edge}]"));
    }
}
