//! The library's region layer (`blossom::region`) for Python: `CurvedRegion` (loops of planar
//! Curves with a fill rule) with the certified booleans, overlap removal (`simplify`) and
//! exact winding numbers, `BooleanResult` (the result's loops as `CurvedPolygon`s, their exact
//! edge records, the area enclosure, the library's geometry with shared ends, the result as a
//! region again, as SVG path data, and drawn into a fontTools pen: `crate::draw`), and
//! `Triangle.intersect` (bezier's return convention).
//!
//! Every decision is the library's, exact for the input numbers (float64 nodes are read
//! exactly). The result's edges are pieces of the input curves between exact parameters; a
//! piece is an exact Curve when the input curve is exact and both parameters are rational,
//! else a float64 Curve over the correctly rounded parameters.
//!
//! A `BooleanResult` keeps the library's `RegionResult` (which holds shared handles to its two
//! input regions) and the input curves (shared with the `CurvedRegion`s, not copied): the
//! Python objects it shows (polygons, edge records with `Algebraic` parameters) are built
//! when first read and then kept, so a boolean whose caller reads only `area` costs the
//! library's call and little more.

use crate::curve::{check_work, max_work_arg, Curve, CurveShape};
use crate::draw::{input_clockwise, is_input_outline, loop_commands, loop_starts, Command, Point};
use crate::errors::{bad, call, call_detached, from_lib, name_arg};
use crate::numbers::{read_array, rounded, Num};
use crate::records::Algebraic;
use crate::triangle::{to_bezier_order, CurvedPolygon, Triangle, TriangleShape};
use blossom::region::{
    boolean, boolean_work, simplify, simplify_work, triangle_intersection, BooleanOp, Edge,
    FillRule, Region, RegionResult, Winding,
};
use blossom::{AlgebraicReal, Bezier, BezierCurve, Rational};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyList, PyTuple};
use std::sync::{Arc, OnceLock};

/// A planar region bounded by closed loops of Curves (each curve starting exactly where the
/// previous one ends), filled by the rule `fill_rule`: `"nonzero"` (default) or `"evenodd"`,
/// as SVG's. Loops may cross themselves and each other and run either way.
#[pyclass(module = "blossom", frozen)]
#[derive(Clone)]
pub struct CurvedRegion {
    pub(crate) region: Region,
    /// The input curves as given (`loops[l][c]`), for the pieces of a result (shared with
    /// every result of the region).
    pub(crate) curves: Arc<Vec<Vec<Curve>>>,
}

/// A float64 planar Curve of control points.
fn curve_of_points(points: &[Point]) -> Curve {
    let coords = points.iter().flatten().copied().collect();
    Curve {
        shape: CurveShape::F64(
            BezierCurve::from_coordinates(2, coords).expect("a curve has a control point"),
        ),
    }
}

/// The region of loops of curves of doubles (`loops[l][c]` the control points of curve c of
/// loop l, at least one point each), each number read exactly: the library's float path reads
/// them as they are.
pub fn region_of_f64(loops: Vec<Vec<Vec<Point>>>, fill: FillRule) -> PyResult<CurvedRegion> {
    let curves: Vec<Vec<Curve>> = loops
        .iter()
        .map(|lp| lp.iter().map(|p| curve_of_points(p)).collect())
        .collect();
    let beziers = loops
        .into_iter()
        .map(|lp| {
            lp.into_iter()
                .map(|p| Bezier::new(p).expect("a curve has a control point"))
                .collect()
        })
        .collect();
    // The library's paths are relative to the region: `loops[l][c]`, as Python's.
    let region = call(&[], || Region::from_f64(beziers, fill))?;
    Ok(CurvedRegion {
        region,
        curves: Arc::new(curves),
    })
}

/// The exact planar control points of `c`, the argument at `path`.
fn planar_bezier(c: &Curve, path: &str) -> PyResult<Bezier<Rational, 2>> {
    if c.dim() != 2 {
        return Err(bad(
            path,
            "Dimension",
            format!(
                "regions are planar (dimension 2), found dimension {}",
                c.dim()
            ),
        ));
    }
    let points = c
        .exact_curve()
        .coordinates()
        .chunks_exact(2)
        .map(|p| [p[0].clone(), p[1].clone()])
        .collect();
    Bezier::new(points).map_err(|e| bad(path, &format!("{:?}", e.kind()), &e.message))
}

/// The planar control points of a float64 curve (None for an exact curve; the dimension is
/// checked when the curve is read).
fn planar_f64(c: &Curve) -> Option<Bezier<f64, 2>> {
    match &c.shape {
        CurveShape::F64(x) => {
            let points = x
                .coordinates()
                .chunks_exact(2)
                .map(|p| [p[0], p[1]])
                .collect();
            Bezier::new(points).ok()
        }
        CurveShape::Exact(_) => None,
    }
}

/// The `fill_rule` argument: `"nonzero"` or `"evenodd"` (SVG's names).
pub fn fill_rule_arg(name: Option<&Bound<'_, PyAny>>) -> PyResult<FillRule> {
    let name = crate::args::str_arg(name, "fill_rule", "nonzero")?;
    name_arg(
        "fill_rule",
        &name,
        &[
            ("nonzero", FillRule::NonZero),
            ("evenodd", FillRule::EvenOdd),
        ],
    )
}

/// A Curve argument, or a `2 x N` nodes array, at `path`.
fn curve_arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Curve> {
    match obj.cast::<Curve>() {
        Ok(c) => Ok(c.get().clone()),
        Err(_) => Curve::read(obj, path),
    }
}

/// The exact number of an edge's parameter (computed on demand by the library).
fn exact_parameter(p: &blossom::region::Parameter) -> PyResult<&AlgebraicReal> {
    p.algebraic().map_err(|e| from_lib(&e, &[]))
}

/// The piece of `c` from `e.from` to `e.to`, traversed that way.
fn piece(c: &Curve, e: &Edge) -> Curve {
    let reversed = |coords: &[f64], dim: usize| -> Vec<f64> {
        coords.chunks_exact(dim).rev().flatten().copied().collect()
    };
    let ends = (e.from.curve_end(), e.to.curve_end());
    if ends == (Some(false), Some(true)) {
        return c.clone();
    }
    if ends == (Some(true), Some(false)) {
        let shape = match &c.shape {
            CurveShape::F64(x) => CurveShape::F64(
                BezierCurve::from_coordinates(x.dim(), reversed(x.coordinates(), x.dim()))
                    .expect("the shape of a curve"),
            ),
            CurveShape::Exact(x) => {
                let coords = x
                    .coordinates()
                    .chunks_exact(x.dim())
                    .rev()
                    .flatten()
                    .cloned()
                    .collect();
                CurveShape::Exact(
                    BezierCurve::from_coordinates(x.dim(), coords).expect("the shape of a curve"),
                )
            }
        };
        return Curve { shape };
    }
    // An exact curve is cut exactly at rational parameters (made exact on demand).
    let rational = |p: &blossom::region::Parameter| match c.shape {
        CurveShape::Exact(_) => p.algebraic().ok().and_then(|a| a.exact().cloned()),
        CurveShape::F64(_) => None,
    };
    let shape = match (&c.shape, rational(&e.from), rational(&e.to)) {
        (CurveShape::Exact(x), Some(a), Some(b)) => CurveShape::Exact(x.subsegment(a..b)),
        (CurveShape::F64(x), _, _) => CurveShape::F64(x.subsegment(e.from.to_f64()..e.to.to_f64())),
        (CurveShape::Exact(x), _, _) => {
            let rounded_curve = BezierCurve::from_coordinates(x.dim(), rounded(x.coordinates()))
                .expect("the shape of a curve");
            CurveShape::F64(rounded_curve.subsegment(e.from.to_f64()..e.to.to_f64()))
        }
    };
    Curve { shape }
}

/// The result of a boolean: `polygons[k]` is loop k as a `CurvedPolygon` of pieces of the
/// input curves (the result lies to its left: outer loops counter-clockwise), `holes[k]`
/// whether it bounds a hole, `edges[k]` its exact edge records
/// `(region, loop_index, curve, from, to)` (region 0 for `self`, 1 for `other`; `from`, `to`
/// `Algebraic` parameters on that input curve), and `area` = `(lo, hi)`, a certified
/// enclosure of the exact area (lo <= area <= hi, hi - lo <= 2^-40 times the area of the box
/// of every input node; `(0.0, 0.0)` for an empty result).
///
/// `polygons` and `edges` are built on first reading, then kept (the same list each time).
#[pyclass(module = "blossom", frozen)]
pub struct BooleanResult {
    pub(crate) result: RegionResult,
    /// The input curves of the two operands, `sources[e.region][e.loop_index][e.curve]`.
    pub(crate) sources: [Arc<Vec<Vec<Curve>>>; 2],
    polygons: PyOnceLock<Py<PyList>>,
    edges: PyOnceLock<Py<PyList>>,
    /// The library's `geometry()` as control points, made once.
    pieces: OnceLock<Vec<Vec<Vec<Point>>>>,
    geometry: PyOnceLock<Py<PyList>>,
}

impl BooleanResult {
    pub(crate) fn new(result: RegionResult, sources: [Arc<Vec<Vec<Curve>>>; 2]) -> Self {
        BooleanResult {
            result,
            sources,
            polygons: PyOnceLock::new(),
            edges: PyOnceLock::new(),
            pieces: OnceLock::new(),
            geometry: PyOnceLock::new(),
        }
    }

    fn sources(&self) -> [&[Vec<Curve>]; 2] {
        [&self.sources[0], &self.sources[1]]
    }

    /// The pieces of every loop (`RegionResult::geometry`), as control points.
    fn pieces(&self) -> &Vec<Vec<Vec<Point>>> {
        self.pieces.get_or_init(|| {
            self.result
                .geometry()
                .into_iter()
                .map(|l| l.into_iter().map(|c| c.points().to_vec()).collect())
                .collect()
        })
    }

    /// Whether the loops are drawn reversed (clockwise outer loops) for `clockwise`, or by the
    /// input's convention when it is None.
    fn reversed(&self, clockwise: Option<bool>) -> bool {
        clockwise.unwrap_or_else(|| input_clockwise(self.sources()))
    }

    /// The pen calls of the whole result, loops reversed when `reverse`; a piece of degree
    /// over 3 or with a coordinate that overflowed raises, naming it.
    fn commands(&self, reverse: bool) -> PyResult<Vec<Command>> {
        let mut out = Vec::new();
        let starts = loop_starts(self.sources());
        for (l, pieces) in self.pieces().iter().enumerate() {
            for (e, p) in pieces.iter().enumerate() {
                let path = || format!("geometry[{l}][{e}]");
                if p.len() > 4 {
                    return Err(bad(
                        path(),
                        "Degree",
                        format!(
                            "a piece of degree {} has no pen command (lines, quadratics and \
                             cubics only)",
                            p.len() - 1
                        ),
                    ));
                }
                if p.iter().flatten().any(|x| !x.is_finite()) {
                    return Err(bad(
                        path(),
                        "NotFinite",
                        "a coordinate overflowed the range of doubles",
                    ));
                }
            }
            if reverse {
                let back: Vec<Vec<Point>> = pieces
                    .iter()
                    .rev()
                    .map(|p| p.iter().rev().copied().collect())
                    .collect();
                loop_commands(&back, &starts, &mut out);
            } else {
                loop_commands(pieces, &starts, &mut out);
            }
        }
        Ok(out)
    }
}

#[pymethods]
impl BooleanResult {
    /// One `CurvedPolygon` per loop.
    #[getter]
    fn polygons(&self, py: Python<'_>) -> PyResult<Py<PyList>> {
        let list = self
            .polygons
            .get_or_try_init(py, || -> PyResult<Py<PyList>> {
                let polygons = self
                    .result
                    .loops
                    .iter()
                    .map(|l| loop_polygon(py, &l.edges, self.sources()))
                    .collect::<PyResult<Vec<_>>>()?;
                Ok(PyList::new(py, polygons)?.unbind())
            })?;
        Ok(list.clone_ref(py))
    }

    /// Whether each loop bounds a hole (runs clockwise).
    #[getter]
    fn holes(&self) -> Vec<bool> {
        self.result.loops.iter().map(|l| l.hole).collect()
    }

    /// Per loop, the records `(region, loop_index, curve, from, to)` of its edges, the
    /// parameters exact (`Algebraic`; made exact on this first reading).
    #[getter]
    fn edges(&self, py: Python<'_>) -> PyResult<Py<PyList>> {
        let list = self.edges.get_or_try_init(py, || -> PyResult<Py<PyList>> {
            let edges = PyList::empty(py);
            for l in &self.result.loops {
                let records = PyList::empty(py);
                for e in &l.edges {
                    let record = (
                        e.region,
                        e.loop_index,
                        e.curve,
                        algebraic(py, exact_parameter(&e.from)?)?,
                        algebraic(py, exact_parameter(&e.to)?)?,
                    );
                    records.append(record)?;
                }
                edges.append(records)?;
            }
            Ok(edges.unbind())
        })?;
        Ok(list.clone_ref(py))
    }

    /// `(lo, hi)`: lo <= the exact area <= hi.
    #[getter]
    fn area(&self) -> (f64, f64) {
        (self.result.area[0], self.result.area[1])
    }

    /// The loops as float64 Curves (the library's `RegionResult::geometry`): `geometry[k][e]`
    /// is edge e of loop k, the piece of its input curve in the edge's direction, of the
    /// input curve's degree; each piece starts bit for bit where the previous one ends and
    /// each loop closes exactly (every coordinate within 17 n 2^-53 M of the exact piece's,
    /// M the largest input coordinate).
    #[getter]
    fn geometry(&self, py: Python<'_>) -> PyResult<Py<PyList>> {
        let list = self
            .geometry
            .get_or_try_init(py, || -> PyResult<Py<PyList>> {
                let loops = PyList::empty(py);
                for pieces in self.pieces() {
                    let curves: Vec<Curve> = pieces.iter().map(|p| curve_of_points(p)).collect();
                    loops.append(PyList::new(py, curves)?)?;
                }
                Ok(loops.unbind())
            })?;
        Ok(list.clone_ref(py))
    }

    /// The result as a `CurvedRegion` (fill nonzero; its loops the `geometry`: outer loops
    /// counter-clockwise, holes clockwise), so that booleans chain.
    fn to_region(&self) -> PyResult<CurvedRegion> {
        region_of_f64(self.pieces().clone(), FillRule::NonZero)
    }

    /// The result as SVG path data (the library's `RegionResult::svg`: subpath k for loop k,
    /// `M`, then `L`, `Q`, `C` by the input curves' kinds, `Z`; numbers in the shortest form
    /// that reads back as the same double), `""` for an empty result, None when a piece has
    /// degree over 3.
    #[getter]
    fn svg(&self) -> Option<String> {
        self.result.svg()
    }

    /// Draws the loops into a fontTools pen (`moveTo`, `lineTo`, `qCurveTo`, `curveTo`,
    /// `closePath`): lines as `lineTo`, cubics as `curveTo`, runs of quadratics as one
    /// `qCurveTo` with the on-curve points that are exactly the midpoints of their neighbours
    /// left implied (`qCurveTo(*offcurves, None)` for a loop of only such points); a loop
    /// starts at an input contour's starting point where it passes one. The outer
    /// loops run clockwise when `clockwise` is True (TrueType's convention), counter-clockwise
    /// when False (PostScript's, CFF's), and by the input's convention when None (clockwise
    /// when the signed area of `self`'s loops, else of `other`'s, is negative).
    #[pyo3(signature = (pen, *, clockwise = None))]
    fn draw(&self, pen: &Bound<'_, PyAny>, clockwise: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let clockwise = crate::args::optional_bool_arg(clockwise, "clockwise")?;
        let py = pen.py();
        let point = |p: &Point| (p[0], p[1]);
        let commands = self.commands(self.reversed(clockwise))?;
        // The pen's methods, checked before anything is drawn.
        for c in &commands {
            let name = match c {
                Command::MoveTo(_) => "moveTo",
                Command::LineTo(_) => "lineTo",
                Command::QCurveTo(_) | Command::QCurveClosed(_) => "qCurveTo",
                Command::CurveTo(_) => "curveTo",
                Command::ClosePath => "closePath",
            };
            if !pen.hasattr(name)? {
                return Err(bad(
                    "pen",
                    "Invalid",
                    format!("expected a fontTools pen, found no method {name}"),
                ));
            }
        }
        for c in commands {
            match c {
                Command::MoveTo(p) => pen.call_method1("moveTo", (point(&p),))?,
                Command::LineTo(p) => pen.call_method1("lineTo", (point(&p),))?,
                Command::QCurveTo(ps) => {
                    let args = PyTuple::new(py, ps.iter().map(point))?;
                    pen.call_method1("qCurveTo", args)?
                }
                Command::QCurveClosed(ps) => {
                    let mut args: Vec<Bound<'_, PyAny>> = Vec::with_capacity(ps.len() + 1);
                    for p in &ps {
                        args.push(point(p).into_pyobject(py)?.into_any());
                    }
                    args.push(py.None().into_bound(py));
                    pen.call_method1("qCurveTo", PyTuple::new(py, args)?)?
                }
                Command::CurveTo(ps) => {
                    pen.call_method1("curveTo", PyTuple::new(py, ps.iter().map(point))?)?
                }
                Command::ClosePath => pen.call_method0("closePath")?,
            };
        }
        Ok(())
    }

    /// Whether drawing the result (`draw(pen, clockwise=clockwise)`) draws `self`'s own
    /// contours: each loop one whole loop of region 0 (all its curves, whole, in order, the
    /// input's way round), each of them once (the test `remove_overlaps` makes to keep a
    /// glyph that has nothing to remove).
    #[pyo3(signature = (*, clockwise = None))]
    fn _draws_input(&self, clockwise: Option<bool>) -> bool {
        is_input_outline(&self.result, &self.sources[0], self.reversed(clockwise))
    }

    fn __repr__(&self) -> String {
        format!(
            "<BooleanResult (loops={}, area in [{:e}, {:e}])>",
            self.result.loops.len(),
            self.result.area[0],
            self.result.area[1]
        )
    }
}

fn algebraic(py: Python<'_>, a: &AlgebraicReal) -> PyResult<Py<Algebraic>> {
    Py::new(py, Algebraic { inner: a.clone() })
}

/// The pieces of one result loop, with the input curves of the two operands.
fn loop_polygon(
    py: Python<'_>,
    edges: &[Edge],
    sources: [&[Vec<Curve>]; 2],
) -> PyResult<Py<CurvedPolygon>> {
    let pieces = edges
        .iter()
        .map(|e| piece(&sources[e.region][e.loop_index][e.curve], e))
        .collect();
    Py::new(py, CurvedPolygon::of_pieces(pieces))
}

/// The `other` argument of a boolean.
fn region_arg<'a>(other: &'a Bound<'_, PyAny>) -> PyResult<&'a CurvedRegion> {
    crate::args::class_arg::<CurvedRegion>(other, "other", "a CurvedRegion").map(|r| r.get())
}

impl CurvedRegion {
    fn run(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        op: BooleanOp,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        let max_work = max_work_arg(max_work)?;
        let other = region_arg(other)?;
        let (a, b) = (&self.region, &other.region);
        check_region_work(&[self, other], max_work, || boolean_work(a, b))?;
        let r = call_detached(py, &[], || boolean(a, b, op))?;
        Ok(BooleanResult::new(
            r,
            [self.curves.clone(), other.curves.clone()],
        ))
    }

    /// Curve arguments at `loops[l][c]`, read; a curve that is not planar raises there.
    fn read_loops(loops: &Bound<'_, PyAny>) -> PyResult<Vec<Vec<Curve>>> {
        let mut curves = Vec::new();
        let not_a_sequence = |path: &str, obj: &Bound<'_, PyAny>| {
            bad(
                path,
                "Invalid",
                format!(
                    "expected a sequence of loops, each a sequence of curves, found {}",
                    crate::args::type_name(obj)
                ),
            )
        };
        let outer = loops
            .try_iter()
            .map_err(|_| not_a_sequence("loops", loops))?;
        for (l, lp) in outer.enumerate() {
            let mut row = Vec::new();
            let lp = lp?;
            let path = format!("loops[{l}]");
            let inner = lp.try_iter().map_err(|_| not_a_sequence(&path, &lp))?;
            for (c, obj) in inner.enumerate() {
                let path = format!("loops[{l}][{c}]");
                let curve = curve_arg(&obj?, &path)?;
                if curve.dim() != 2 {
                    return Err(bad(
                        &path,
                        "Dimension",
                        format!(
                            "regions are planar (dimension 2), found dimension {}",
                            curve.dim()
                        ),
                    ));
                }
                row.push(curve);
            }
            curves.push(row);
        }
        Ok(curves)
    }
}

#[pymethods]
impl CurvedRegion {
    /// The region of `loops` (each a sequence of Curves or `2 x N` node arrays, each curve
    /// starting exactly where the previous one ends; none for the empty region) under
    /// `fill_rule`. Float64 curves stay doubles (read exactly by the library); a region with an
    /// exact curve is exact.
    #[new]
    #[pyo3(signature = (loops, fill_rule = None))]
    fn new(loops: &Bound<'_, PyAny>, fill_rule: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let fill = fill_rule_arg(fill_rule)?;
        let curves = Self::read_loops(loops)?;
        let doubles: Option<Vec<Vec<Bezier<f64, 2>>>> = curves
            .iter()
            .map(|row| row.iter().map(planar_f64).collect())
            .collect();
        // The library's paths are relative to the region: `loops[l][c]`, as Python's.
        let region = match doubles {
            Some(d) => call(&[], || Region::from_f64(d, fill))?,
            None => {
                let exact = curves
                    .iter()
                    .enumerate()
                    .map(|(l, row)| {
                        row.iter()
                            .enumerate()
                            .map(|(c, curve)| planar_bezier(curve, &format!("loops[{l}][{c}]")))
                            .collect::<PyResult<Vec<_>>>()
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                call(&[], || Region::new(exact, fill))?
            }
        };
        Ok(CurvedRegion {
            region,
            curves: Arc::new(curves),
        })
    }

    /// `(xmin, ymin, xmax, ymax)`: a box holding every control point (exact for float64
    /// curves, rounded outward for exact ones), so the region lies in it; None without
    /// curves. (For quick rejections, such as `remove_overlaps`' test of components.)
    fn _control_box(&self) -> Option<(f64, f64, f64, f64)> {
        let mut out: Option<(f64, f64, f64, f64)> = None;
        for c in self.curves.iter().flatten() {
            let (coords, widen) = match &c.shape {
                CurveShape::F64(x) => (x.coordinates().to_vec(), false),
                CurveShape::Exact(x) => (rounded(x.coordinates()), true),
            };
            for p in coords.chunks_exact(2) {
                let (lo, hi) = if widen {
                    (
                        [p[0].next_down(), p[1].next_down()],
                        [p[0].next_up(), p[1].next_up()],
                    )
                } else {
                    ([p[0], p[1]], [p[0], p[1]])
                };
                out = Some(match out {
                    None => (lo[0], lo[1], hi[0], hi[1]),
                    Some((a, b, c, d)) => (a.min(lo[0]), b.min(lo[1]), c.max(hi[0]), d.max(hi[1])),
                });
            }
        }
        out
    }

    /// The fill rule: `"nonzero"` or `"evenodd"`.
    #[getter]
    fn fill_rule(&self) -> &'static str {
        match self.region.fill() {
            FillRule::NonZero => "nonzero",
            FillRule::EvenOdd => "evenodd",
        }
    }

    /// The region under its own fill rule as simple oriented loops (overlap removal, the
    /// library's `simplify`): loops that overlap or cross themselves merged, the parts the
    /// fill rule leaves out removed, parts of zero area dropped. A `BooleanResult` whose
    /// edges all name region 0 (`self`).
    #[pyo3(signature = (*, max_work = None))]
    fn simplify(
        &self,
        py: Python<'_>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        let max_work = max_work_arg(max_work)?;
        let a = &self.region;
        check_region_work(&[self], max_work, || simplify_work(a))?;
        let r = call_detached(py, &[], || simplify(a))?;
        Ok(BooleanResult::new(
            r,
            [self.curves.clone(), Arc::new(Vec::new())],
        ))
    }

    /// The region of a planar `Triangle` (the loop of its three edges, fill nonzero).
    #[staticmethod]
    fn from_triangle(triangle: &Bound<'_, PyAny>) -> PyResult<Self> {
        let t = crate::args::class_arg::<Triangle>(triangle, "triangle", "a Triangle")?;
        triangle_region(t.get(), "triangle")
    }

    /// The number of loops.
    #[getter]
    fn num_loops(&self) -> usize {
        self.curves.len()
    }

    /// The loops as tuples of Curves.
    #[getter]
    fn loops<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for row in self.curves.iter() {
            out.append(crate::curve::curves_tuple(py, row.clone())?)?;
        }
        Ok(out)
    }

    /// `self ∩ other`, certified (see `BooleanResult`).
    #[pyo3(signature = (other, *, max_work = None))]
    fn intersection(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        self.run(py, other, BooleanOp::Intersection, max_work)
    }

    /// `self ∪ other`, certified.
    #[pyo3(signature = (other, *, max_work = None))]
    fn union(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        self.run(py, other, BooleanOp::Union, max_work)
    }

    /// `self - other`, certified.
    #[pyo3(signature = (other, *, max_work = None))]
    fn difference(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        self.run(py, other, BooleanOp::Difference, max_work)
    }

    /// `(self - other) ∪ (other - self)`, certified.
    #[pyo3(signature = (other, *, max_work = None))]
    fn xor(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BooleanResult> {
        self.run(py, other, BooleanOp::Xor, max_work)
    }

    /// The exact winding number of each column of the `2 x M` array `points` (floats read
    /// exactly, or Fractions): an int, or None for a point on a loop.
    #[pyo3(signature = (points, *, max_work = None))]
    fn winding<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        max_work: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyList>> {
        let max_work = max_work_arg(max_work)?;
        let read = read_array(points, "points", 2, "2 x M, one column per point")?;
        if read.shape[0] != 2 {
            return Err(bad(
                "points",
                "Dimension",
                format!("expected 2 rows (x, y), found {}", read.shape[0]),
            ));
        }
        let m = read.shape[1];
        let c = Rational::of_coords(read.coords, "points")?;
        let pts: Vec<[Rational; 2]> = (0..m).map(|k| [c[k].clone(), c[m + k].clone()]).collect();
        check_work(self.region.winding_work(m), max_work)?;
        let region = &self.region;
        let w = call_detached(py, &[], || Ok(region.windings(&pts)))?;
        let out = PyList::empty(py);
        for x in w {
            match x {
                Winding::Boundary => out.append(py.None())?,
                Winding::Number(n) => out.append(n)?,
            }
        }
        Ok(out)
    }

    fn __repr__(&self) -> String {
        format!("<CurvedRegion (num_loops={})>", self.curves.len())
    }
}

/// Curves (both regions together) up to which a boolean is never estimated, when every
/// degree is at most [`SMALL_DEGREE`]: two triangles of degree <= 4 answer in milliseconds,
/// and `boolean_work` itself (the float filter on every close pair) would cost a large part
/// of that.
const SMALL_CURVES: usize = 8;
const SMALL_DEGREE: usize = 4;

/// Refuses a boolean of `regions` whose estimated work (`estimate`: `boolean_work` or
/// `simplify_work`) is over `max_work`; small inputs (bounded by [`SMALL_CURVES`] and
/// [`SMALL_DEGREE`]) are not estimated unless `max_work` is given.
fn check_region_work(
    regions: &[&CurvedRegion],
    max_work: Option<f64>,
    estimate: impl FnOnce() -> u128,
) -> PyResult<()> {
    // The curves as given (the library's exact curves of a region of doubles are made only
    // when needed).
    let curves = || regions.iter().flat_map(|r| r.curves.iter().flatten());
    let small = curves().count() <= SMALL_CURVES && curves().all(|c| c.degree() <= SMALL_DEGREE);
    if small && max_work.is_none() {
        return Ok(());
    }
    check_work(estimate(), max_work)
}

/// The region of a planar triangle, the argument `arg`, made once and kept on the triangle.
fn cached_region<'t>(t: &'t Triangle, arg: &str) -> PyResult<&'t CurvedRegion> {
    if let Some(r) = t.region.get() {
        return Ok(r);
    }
    let r = triangle_region(t, arg)?;
    Ok(t.region.get_or_init(|| r))
}

/// The region of a planar triangle, the argument `arg`.
fn triangle_region(t: &Triangle, arg: &str) -> PyResult<CurvedRegion> {
    let (n, d) = (t.degree(), t.dim());
    if d != 2 {
        return Err(bad(
            format!("{arg}.nodes"),
            "Dimension",
            format!("triangle intersection is defined for planar triangles (dimension 2), found dimension {d}"),
        ));
    }
    // Doubles stay doubles (the library makes exact curves only if it needs them).
    let region = match &t.shape {
        TriangleShape::F64(p) => {
            let coords = to_bezier_order(p);
            Region::triangle_f64(n, coords.chunks_exact(2).map(|p| [p[0], p[1]]).collect())
        }
        TriangleShape::Exact(p) => {
            let coords = to_bezier_order(p);
            let nodes = coords
                .chunks_exact(2)
                .map(|p| [p[0].clone(), p[1].clone()])
                .collect();
            Region::triangle(n, nodes)
        }
    };
    let region = region.map_err(|e| {
        let path = match e.path() {
            "" => format!("{arg}.nodes"),
            "degree" => format!("{arg}.degree"),
            "nodes" => format!("{arg}.nodes"),
            p => format!("{arg}.{p}"),
        };
        bad(path, &format!("{:?}", e.kind()), &e.message)
    })?;
    let edges = t.edge_curves();
    Ok(CurvedRegion {
        region,
        curves: Arc::new(vec![edges]),
    })
}

/// `Triangle.intersect`: bezier's convention. `[]` when the (regularized) intersection is
/// empty, also when the triangles only touch; `[self]` or `[other]` (the `Triangle`) when one
/// lies inside the other (its three whole edges are the answer); otherwise one
/// `CurvedPolygon` per component, its edges the pieces of the triangles' edges.
/// (`max_work` read by the caller.)
pub fn triangle_intersect(
    py: Python<'_>,
    t1: &Triangle,
    t2: &Triangle,
    max_work: Option<f64>,
) -> PyResult<Py<PyList>> {
    let a = cached_region(t1, "self")?;
    let b = cached_region(t2, "other")?;
    let (ra, rb) = (&a.region, &b.region);
    check_region_work(&[a, b], max_work, || boolean_work(ra, rb))?;
    // Small pairs (the float path: microseconds) keep the GIL: releasing it costs more.
    let r = if boolean_work(ra, rb) < 100_000 {
        call(&[], || triangle_intersection(ra, rb))?
    } else {
        call_detached(py, &[], || triangle_intersection(ra, rb))?
    };
    let out = PyList::empty(py);
    if let Some(which) = whole_triangle(&r) {
        let t = if which == 0 { t1 } else { t2 };
        out.append(Py::new(py, t.clone())?)?;
        return Ok(out.unbind());
    }
    for l in &r.loops {
        out.append(loop_polygon(
            py,
            &l.edges,
            [a.curves.as_slice(), b.curves.as_slice()],
        )?)?;
    }
    Ok(out.unbind())
}

/// The triangle (0 or 1) whose three whole edges are the one loop of `r`, if so.
fn whole_triangle(r: &RegionResult) -> Option<usize> {
    let [l] = r.loops.as_slice() else {
        return None;
    };
    let whole = |e: &Edge| e.from.curve_end() == Some(false) && e.to.curve_end() == Some(true);
    let region = l.edges.first()?.region;
    let mut seen = [false; 3];
    for e in &l.edges {
        if e.region != region || !whole(e) {
            return None;
        }
        seen[e.curve] = true;
    }
    (l.edges.len() == 3 && seen == [true; 3] && !l.hole).then_some(region)
}
