//! `RegionPen`: a fontTools segment pen that records an outline into a `CurvedRegion`.
//!
//! The calls are fontTools' pen protocol (`moveTo`, `lineTo`, `qCurveTo`, `curveTo`,
//! `closePath`, `endPath`, `addComponent`), decomposed exactly as fontTools' `BasePen` does:
//! a run of quadratic off-curve points splits at the implied on-curve points
//! `(0.5 * (x + nx), 0.5 * (y + ny))`, a closed TrueType quadratic spline without on-curve
//! points (`qCurveTo(*offcurves, None)`) starts at the implied point between its last and
//! first off-curve points, and `curveTo` with more than two off-curve points is split by
//! `decomposeSuperBezierSegment`'s arithmetic. Components are decomposed through the glyph
//! set as `DecomposingPen` does: the base glyph drawn into the pen under the component's
//! transformation (composed as `TransformPen` composes nested ones). fontTools is not needed:
//! the pen is the protocol, any drawer calling it works.
//!
//! A contour is closed by a line back to its start (`closePath`; `endPath` too, as fills
//! close open contours); a contour without a curve (a single point, an anchor) is dropped.
//! The curves keep the numbers as doubles: the region reads them exactly.

use crate::errors::bad;
use crate::region::{fill_rule_arg, region_of_f64, CurvedRegion};
use blossom::region::FillRule;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyString, PyTuple};

type Point = [f64; 2];

/// An affine map (xx, xy, yx, yy, dx, dy) as fontTools' `Transform`: (x, y) goes to
/// (xx x + yx y + dx, xy x + yy y + dy).
type Affine = [f64; 6];

/// fontTools' `Transform.transformPoint`, the same operations in the same order.
fn apply(t: &Affine, p: Point) -> Point {
    let [xx, xy, yx, yy, dx, dy] = *t;
    [xx * p[0] + yx * p[1] + dx, xy * p[0] + yy * p[1] + dy]
}

/// fontTools' `Transform.transform`: `outer` after `inner` (`inner` applied first).
fn compose(outer: &Affine, inner: &Affine) -> Affine {
    let [xx1, xy1, yx1, yy1, dx1, dy1] = *inner;
    let [xx2, xy2, yx2, yy2, dx2, dy2] = *outer;
    [
        xx1 * xx2 + xy1 * yx2,
        xx1 * xy2 + xy1 * yy2,
        yx1 * xx2 + yy1 * yx2,
        yx1 * xy2 + yy1 * yy2,
        xx2 * dx1 + yx2 * dy1 + dx2,
        xy2 * dx1 + yy2 * dy1 + dy2,
    ]
}

const IDENTITY: Affine = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

/// The implied on-curve point between two quadratic off-curve points, as fontTools computes
/// it.
pub fn implied(a: Point, b: Point) -> Point {
    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
}

/// The contour being recorded.
struct Contour {
    start: Point,
    current: Point,
    /// The control points of each curve, the first the current point when it was drawn.
    curves: Vec<Vec<Point>>,
}

/// A fontTools pen recording an outline into a `CurvedRegion` under `fill_rule` (`"nonzero"`,
/// the default and TrueType's rule, or `"evenodd"`). `glyph_set` (a mapping from glyph
/// names to drawable glyphs, such as `TTFont.getGlyphSet()`) decomposes components;
/// without it `addComponent` raises. `region()` gives the region of what was drawn.
#[pyclass(module = "blossom")]
pub struct RegionPen {
    fill: FillRule,
    glyph_set: Option<Py<PyAny>>,
    /// The transformation of the component being drawn (None at the top level).
    transform: Option<Affine>,
    loops: Vec<Vec<Vec<Point>>>,
    contour: Option<Contour>,
}

/// A point argument `(x, y)` (a tuple or any sequence of two numbers), finite.
fn point_arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Point> {
    let (x, y) = match obj.extract::<(f64, f64)>() {
        Ok(xy) => xy,
        Err(_) => {
            let n = obj.len().ok();
            if n != Some(2) || obj.is_instance_of::<PyString>() || obj.is_instance_of::<PyBytes>() {
                return Err(bad(
                    path,
                    "Shape",
                    format!(
                        "expected a point (x, y), found {}",
                        obj.repr().map_or("?".into(), |r| r.to_string())
                    ),
                ));
            }
            let item = |k: usize| {
                obj.get_item(k).map_err(|_| {
                    bad(
                        path,
                        "Shape",
                        format!(
                            "expected a point (x, y), found {}",
                            obj.repr().map_or("?".into(), |r| r.to_string())
                        ),
                    )
                })
            };
            (
                crate::numbers::f64_arg(&item(0)?, &format!("{path}[0]"))?,
                crate::numbers::f64_arg(&item(1)?, &format!("{path}[1]"))?,
            )
        }
    };
    for (k, v) in [x, y].iter().enumerate() {
        if !v.is_finite() {
            return Err(bad(
                format!("{path}[{k}]"),
                "NotFinite",
                format!("expected a finite number, found {v}"),
            ));
        }
    }
    Ok([x, y])
}

impl RegionPen {
    /// The point argument `obj` (named `path`) in the pen's coordinates.
    fn point(&self, obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Point> {
        let p = point_arg(obj, path)?;
        Ok(match &self.transform {
            Some(t) => apply(t, p),
            None => p,
        })
    }

    /// The points of a `*points` argument of the method `method`, each read as `point`.
    fn points(&self, points: &Bound<'_, PyTuple>, method: &str) -> PyResult<Vec<Point>> {
        points
            .iter()
            .enumerate()
            .map(|(k, p)| self.point(&p, &format!("{method}.points[{k}]")))
            .collect()
    }

    /// The open contour, for a drawing call `method`.
    fn open(&mut self, method: &str) -> PyResult<&mut Contour> {
        self.contour.as_mut().ok_or_else(|| {
            bad(
                method,
                "Shape",
                "no current point: a contour starts with moveTo (or qCurveTo(..., None))",
            )
        })
    }

    /// Adds the curve from the current point through `rest` to the open contour.
    fn add(&mut self, method: &str, rest: &[Point]) -> PyResult<()> {
        let contour = self.open(method)?;
        let mut points = Vec::with_capacity(rest.len() + 1);
        points.push(contour.current);
        points.extend_from_slice(rest);
        contour.current = *rest.last().expect("a curve has an end");
        contour.curves.push(points);
        Ok(())
    }

    /// A run of quadratic off-curve points ending at the on-curve point `points[last]`,
    /// split at the implied on-curve points (fontTools' `decomposeQuadraticSegment`).
    fn quadratics(&mut self, method: &str, points: &[Point]) -> PyResult<()> {
        let n = points.len();
        for i in 0..n.saturating_sub(2) {
            let mid = implied(points[i], points[i + 1]);
            self.add(method, &[points[i], mid])?;
        }
        self.add(method, &points[n - 2..])
    }

    /// Closes the open contour by a line back to its start, keeping it when it has a curve.
    fn close(&mut self) {
        if let Some(mut c) = self.contour.take() {
            if !c.curves.is_empty() && c.current != c.start {
                c.curves.push(vec![c.current, c.start]);
            }
            if !c.curves.is_empty() {
                self.loops.push(c.curves);
            }
        }
    }

    fn start(&mut self, p: Point) {
        self.close();
        self.contour = Some(Contour {
            start: p,
            current: p,
            curves: Vec::new(),
        });
    }
}

/// " (did you mean 'name'?)" for the glyph set's name nearest to `glyph_name` (a string),
/// when the glyph set lists its names (`keys()`) and one is near; else "".
fn nearest_glyph(glyph_set: &Bound<'_, PyAny>, glyph_name: &Bound<'_, PyAny>) -> String {
    let Ok(name) = glyph_name.extract::<String>() else {
        return String::new();
    };
    let names: Vec<String> = match glyph_set
        .call_method0("keys")
        .and_then(|k| k.try_iter()?.map(|n| n?.extract::<String>()).collect())
    {
        Ok(names) => names,
        Err(_) => return String::new(),
    };
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    crate::errors::nearest_name(&name, &refs)
        .map(|n| format!(" (did you mean {n:?}?)"))
        .unwrap_or_default()
}

/// The six numbers of a transformation argument (a tuple or fontTools' `Transform`).
fn affine_arg(obj: &Bound<'_, PyAny>) -> PyResult<Affine> {
    let values: Vec<f64> = obj
        .try_iter()
        .and_then(|it| {
            it.enumerate()
                .map(|(k, x)| crate::numbers::f64_arg(&x?, &format!("transformation[{k}]")))
                .collect()
        })
        .map_err(|e| {
            if e.is_instance_of::<crate::errors::Error>(obj.py()) {
                e
            } else {
                bad(
                    "transformation",
                    "Shape",
                    "expected six numbers (xx, xy, yx, yy, dx, dy)",
                )
            }
        })?;
    let t: Affine = values.try_into().map_err(|v: Vec<f64>| {
        bad(
            "transformation",
            "Shape",
            format!(
                "expected six numbers (xx, xy, yx, yy, dx, dy), found {}",
                v.len()
            ),
        )
    })?;
    if let Some(k) = t.iter().position(|x| !x.is_finite()) {
        return Err(bad(
            format!("transformation[{k}]"),
            "NotFinite",
            format!("expected a finite number, found {}", t[k]),
        ));
    }
    Ok(t)
}

#[pymethods]
impl RegionPen {
    #[new]
    #[pyo3(signature = (glyph_set = None, *, fill_rule = None))]
    fn new(glyph_set: Option<Py<PyAny>>, fill_rule: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        Ok(RegionPen {
            fill: fill_rule_arg(fill_rule)?,
            glyph_set,
            transform: None,
            loops: Vec::new(),
            contour: None,
        })
    }

    /// Starts a contour at `pt` (closing an open one by a line, as `endPath`).
    #[pyo3(name = "moveTo")]
    fn move_to(&mut self, pt: &Bound<'_, PyAny>) -> PyResult<()> {
        let p = self.point(pt, "moveTo.pt")?;
        self.start(p);
        Ok(())
    }

    /// A line from the current point to `pt`.
    #[pyo3(name = "lineTo")]
    fn line_to(&mut self, pt: &Bound<'_, PyAny>) -> PyResult<()> {
        let p = self.point(pt, "lineTo.pt")?;
        self.add("lineTo", &[p])
    }

    /// Quadratic off-curve points then the on-curve end point, split at the implied on-curve
    /// points; with `None` as the last point, a closed contour of off-curve points only (it
    /// starts at the implied point between the last and the first).
    #[pyo3(name = "qCurveTo", signature = (*points))]
    fn q_curve_to(&mut self, points: &Bound<'_, PyTuple>) -> PyResult<()> {
        let n = points.len();
        if n == 0 {
            return Err(bad(
                "qCurveTo.points",
                "Empty",
                "expected at least one point",
            ));
        }
        if points.get_item(n - 1)?.is_none() {
            let offs = self.points(&points.get_slice(0, n - 1), "qCurveTo")?;
            let (Some(&first), Some(&last)) = (offs.first(), offs.last()) else {
                return Err(bad(
                    "qCurveTo.points",
                    "Empty",
                    "a contour of off-curve points (ending in None) needs at least one",
                ));
            };
            let start = implied(last, first);
            self.start(start);
            let mut all = offs;
            all.push(start);
            return self.quadratics("qCurveTo", &all);
        }
        let pts = self.points(points, "qCurveTo")?;
        if n == 1 {
            return self.add("qCurveTo", &pts);
        }
        self.quadratics("qCurveTo", &pts)
    }

    /// Cubic off-curve points then the end point: two make a cubic; more are split into
    /// cubics as fontTools' `decomposeSuperBezierSegment` splits them; one makes a quadratic,
    /// none a line.
    #[pyo3(name = "curveTo", signature = (*points))]
    fn curve_to(&mut self, points: &Bound<'_, PyTuple>) -> PyResult<()> {
        let pts = self.points(points, "curveTo")?;
        match pts.len() {
            0 => Err(bad(
                "curveTo.points",
                "Empty",
                "expected at least one point",
            )),
            1..=3 => self.add("curveTo", &pts),
            _ => {
                for [p1, p2, p3] in super_bezier(&pts) {
                    self.add("curveTo", &[p1, p2, p3])?;
                }
                Ok(())
            }
        }
    }

    /// Closes the contour (by a line back to its start where it ends elsewhere).
    #[pyo3(name = "closePath")]
    fn close_path(&mut self) {
        self.close();
    }

    /// Ends an open contour: closed by a line as a fill closes it.
    #[pyo3(name = "endPath")]
    fn end_path(&mut self) {
        self.close();
    }

    /// Draws the glyph `glyphName` of the glyph set into the pen under `transformation` (six
    /// numbers, fontTools' `Transform` order), as fontTools' `DecomposingPen` does.
    #[pyo3(name = "addComponent")]
    fn add_component(
        slf: &Bound<'_, Self>,
        glyph_name: &Bound<'_, PyAny>,
        transformation: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let py = slf.py();
        let m = affine_arg(transformation)?;
        let glyph_set = match &slf.borrow().glyph_set {
            Some(g) => g.clone_ref(py),
            None => {
                return Err(bad(
                    "addComponent",
                    "Invalid",
                    format!(
                        "the component {} needs a glyph set to be decomposed: \
                         RegionPen(glyph_set=font.getGlyphSet())",
                        glyph_name.repr()?
                    ),
                ))
            }
        };
        let glyph = glyph_set.bind(py).get_item(glyph_name).map_err(|e| {
            // A missing name (KeyError), or one the glyph set cannot look up (an unhashable
            // list: TypeError).
            if e.is_instance_of::<pyo3::exceptions::PyKeyError>(py)
                || e.is_instance_of::<pyo3::exceptions::PyTypeError>(py)
            {
                bad(
                    "addComponent.glyphName",
                    "Invalid",
                    format!(
                        "the component {} is not in the glyph set{}",
                        glyph_name.repr().map_or("?".into(), |r| r.to_string()),
                        nearest_glyph(glyph_set.bind(py), glyph_name)
                    ),
                )
            } else {
                e
            }
        })?;
        let saved = {
            let mut pen = slf.borrow_mut();
            let outer = pen.transform.unwrap_or(IDENTITY);
            let t = compose(&outer, &m);
            std::mem::replace(&mut pen.transform, (t != IDENTITY).then_some(t))
        };
        let drawn = glyph.call_method1("draw", (slf,));
        slf.borrow_mut().transform = saved;
        drawn.map(|_| ())
    }

    /// The region of the contours drawn so far (an open contour closed by a line), under the
    /// pen's fill rule.
    fn region(&mut self) -> PyResult<CurvedRegion> {
        self.close();
        region_of_f64(self.loops.clone(), self.fill)
    }

    fn __repr__(&self) -> String {
        format!("<RegionPen (contours={})>", self.loops.len())
    }
}

/// fontTools' `decomposeSuperBezierSegment`: the off-curve points `points[..n]` and the end
/// point `points[n]` (n >= 3) as n - 1 cubics (each its two off-curve points and its end; the
/// first starts at the current point), the same operations in the same order.
fn super_bezier(points: &[Point]) -> Vec<[Point; 3]> {
    let n = points.len() - 1;
    let mut out = Vec::with_capacity(n);
    let mut pt1 = points[0];
    let mut pt2: Option<Point> = None;
    for i in 2..=n {
        let divisions = i.min(3).min(n - i + 2);
        for j in 1..divisions {
            let factor = j as f64 / divisions as f64;
            let (a, b) = (points[i - 1], points[i - 2]);
            let temp = [b[0] + factor * (a[0] - b[0]), b[1] + factor * (a[1] - b[1])];
            match pt2 {
                None => pt2 = Some(temp),
                Some(p2) => {
                    let pt3 = implied(p2, temp);
                    out.push([pt1, p2, pt3]);
                    pt1 = temp;
                    pt2 = None;
                }
            }
        }
    }
    out.push([pt1, points[n - 1], points[n]]);
    out
}
