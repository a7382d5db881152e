//! `Curve`: Python bezier's `Curve` over the library's `BezierCurve`, in float64 or exactly
//! (Fractions), with the certified intersections, bounding box and nearest point.

use crate::errors::{bad, call, call_detached, Rename};
use crate::numbers::{points_of_columns, positive_zero, read_array, Coords, Num};
use crate::records::{
    extremes_record, intersection_records, nearest_record, Extremes, IntersectionRecords,
    NearestPoint,
};
use blossom::budget::{curve_pair_work, self_intersection_work};
use blossom::{BezierCurve, Intersections, Rational, Reduction, RoundedIntersections};
use num_rational::Ratio;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// The default limit of `max_work` (estimated nanoseconds of exact work on a 2-core machine,
/// the library's `intersection_work` unit): about 10 seconds.
pub const DEFAULT_MAX_WORK: f64 = 1e10;

/// Degrees n m up to which an intersection is never estimated (the exact path answers in
/// milliseconds there): the estimate itself reads the curves exactly.
const ALWAYS_CHEAP: usize = 16;

/// A curve's control points in one of the two number types.
#[derive(Clone)]
pub enum CurveShape {
    F64(BezierCurve<f64>),
    Exact(BezierCurve<Rational>),
}

/// Runs `$body` with `$c` bound to the curve of either number type.
macro_rules! on_curve {
    ($shape:expr, $c:ident => $body:expr) => {
        match $shape {
            CurveShape::F64($c) => $body,
            CurveShape::Exact($c) => $body,
        }
    };
}

/// Wraps a curve of either number type.
pub trait WrapCurve: Num + Sized {
    fn wrap(c: BezierCurve<Self>) -> CurveShape;
}
impl WrapCurve for f64 {
    fn wrap(c: BezierCurve<f64>) -> CurveShape {
        CurveShape::F64(c)
    }
}
impl WrapCurve for Rational {
    fn wrap(c: BezierCurve<Rational>) -> CurveShape {
        CurveShape::Exact(c)
    }
}

/// A Bézier curve B(s) = sum_j C(n, j) (1 - s)^(n - j) s^j v_j, its nodes a `D x (n + 1)`
/// array whose columns are the control points v_j (as Python bezier's `Curve`). Built from
/// float64 nodes it computes in float64; built from nodes holding `fractions.Fraction` it is
/// exact (`exact` is True) and every answer is exact (Fractions, exact curves).
#[pyclass(module = "blossom", frozen)]
#[derive(Clone)]
pub struct Curve {
    pub shape: CurveShape,
}

impl Curve {
    /// A curve from a `D x N` nodes argument named `arg`.
    pub fn read(nodes: &Bound<'_, PyAny>, arg: &str) -> PyResult<Curve> {
        let read = read_array(nodes, arg, 2, "D x N, one column per control point")?;
        let (d, n) = (read.shape[0], read.shape[1]);
        if d == 0 || n == 0 {
            return Err(bad(
                arg,
                "Empty",
                format!("expected at least one dimension and one node, found shape ({d}, {n})"),
            ));
        }
        let renames = [Rename {
            rust: "coordinates",
            python: "nodes",
            points: false,
        }];
        let shape = match read.coords {
            Coords::F64(c) => CurveShape::F64(call(&renames, || {
                BezierCurve::from_coordinates(d, points_of_columns(&c, d, n))
            })?),
            Coords::Exact(c) => CurveShape::Exact(call(&renames, || {
                BezierCurve::from_coordinates(d, points_of_columns(&c, d, n))
            })?),
        };
        Ok(Curve { shape })
    }

    pub fn degree(&self) -> usize {
        on_curve!(&self.shape, c => c.degree())
    }

    pub fn dim(&self) -> usize {
        on_curve!(&self.shape, c => c.dim())
    }

    /// The control points as exact rationals (a float64 curve's doubles read exactly).
    pub fn exact_curve(&self) -> BezierCurve<Rational> {
        match &self.shape {
            CurveShape::Exact(c) => c.clone(),
            CurveShape::F64(c) => {
                let coords = c
                    .coordinates()
                    .iter()
                    .map(|&x| Ratio::from_float(x).expect("finite nodes (checked when built)"))
                    .collect();
                BezierCurve::from_coordinates(c.dim(), coords).expect("the shape of a curve")
            }
        }
    }

    /// The planar control points, for the intersection layer; `arg` names the curve.
    fn planar<T: Num>(c: &BezierCurve<T>, arg: &'static str) -> PyResult<Vec<[T; 2]>> {
        if c.dim() != 2 {
            return Err(bad(
                format!("{arg}.nodes"),
                "Dimension",
                format!(
                    "intersections are defined for planar curves (dimension 2), found dimension {}",
                    c.dim()
                ),
            ));
        }
        Ok(c.coordinates()
            .chunks_exact(2)
            .map(|p| [p[0].clone(), p[1].clone()])
            .collect())
    }

    fn planar_exact(&self, arg: &'static str) -> PyResult<Vec<[Rational; 2]>> {
        Self::planar(&self.exact_curve(), arg)
    }

    fn both_f64<'a>(
        &'a self,
        other: &'a Curve,
    ) -> Option<(&'a BezierCurve<f64>, &'a BezierCurve<f64>)> {
        match (&self.shape, &other.shape) {
            (CurveShape::F64(a), CurveShape::F64(b)) => Some((a, b)),
            _ => None,
        }
    }

    /// Refuses a pair whose estimated exact work is over `max_work`.
    fn check_pair_work(
        &self,
        other: &Curve,
        p: &[[Rational; 2]],
        q: &[[Rational; 2]],
        max_work: Option<f64>,
    ) -> PyResult<()> {
        if self.degree() * other.degree() <= ALWAYS_CHEAP {
            return Ok(());
        }
        check_work(curve_pair_work(p, q), max_work)
    }

    /// Every intersection with `other`, exactly.
    fn exact_intersections(
        &self,
        py: Python<'_>,
        other: &Curve,
        max_work: Option<f64>,
    ) -> PyResult<Intersections> {
        let p = self.planar_exact("self")?;
        let q = other.planar_exact("other")?;
        self.check_pair_work(other, &p, &q, max_work)?;
        let (a, b) = (self.exact_curve(), other.exact_curve());
        call_detached(py, &PAIR, || a.intersect(&b))
    }

    /// Every self-intersection, exactly.
    fn exact_self_intersections(
        &self,
        py: Python<'_>,
        max_work: Option<f64>,
    ) -> PyResult<Intersections> {
        let p = self.planar_exact("self")?;
        if self.degree() * self.degree() > ALWAYS_CHEAP {
            check_work(self_intersection_work(&p), max_work)?;
        }
        let a = self.exact_curve();
        call_detached(py, &SELF, || a.self_intersections())
    }
}

/// The Rust names of `BezierCurve::intersect`'s arguments as Python's.
const PAIR: [Rename; 2] = [
    Rename {
        rust: "control_points",
        python: "self.nodes",
        points: true,
    },
    Rename {
        rust: "other.control_points",
        python: "other.nodes",
        points: true,
    },
];
const SELF: [Rename; 1] = [Rename {
    rust: "control_points",
    python: "self.nodes",
    points: true,
}];

/// The `max_work` argument: a positive number of nanoseconds (or None for the default).
pub fn max_work_arg(max_work: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    let Some(obj) = max_work else {
        return Ok(None);
    };
    let x: f64 = obj.extract().map_err(|_| {
        bad(
            "max_work",
            "Invalid",
            format!(
                "expected a number of nanoseconds, found {}",
                crate::args::type_name(obj)
            ),
        )
    })?;
    if x.is_nan() || x <= 0.0 {
        return Err(bad(
            "max_work",
            "Domain",
            format!("expected a positive number of nanoseconds, found {x}"),
        ));
    }
    Ok(Some(x))
}

/// Refuses an estimated work over the limit (`max_work`, default [`DEFAULT_MAX_WORK`]).
pub fn check_work(estimate: u128, max_work: Option<f64>) -> PyResult<()> {
    let limit = max_work.unwrap_or(DEFAULT_MAX_WORK);
    if (estimate as f64) > limit {
        return Err(bad(
            "max_work",
            "TooLarge",
            format!(
                "the exact computation is estimated at {:.3e} ns of work, over the limit of \
                 {limit:.3e} (pass a larger max_work to run it)",
                estimate as f64
            ),
        ));
    }
    Ok(())
}

/// The `2 x K` float64 array of parameter pairs, sorted by s then t.
fn pairs_array<'py>(py: Python<'py>, mut pairs: Vec<(f64, f64)>) -> PyResult<Bound<'py, PyAny>> {
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    pairs.dedup();
    let k = pairs.len();
    let coords = pairs.into_iter().flat_map(|(s, t)| [s, t]).collect();
    f64::columns(py, 2, k, coords)
}

/// The isolated points and each overlap's two end pairs of a rounded answer.
fn rounded_pairs(x: &RoundedIntersections) -> Vec<(f64, f64)> {
    let mut pairs: Vec<(f64, f64)> = x.points.iter().map(|p| (p.s, p.t)).collect();
    for o in &x.overlaps {
        pairs.push((o.s[0], o.t[0]));
        pairs.push((o.s[1], o.t[1]));
    }
    pairs
        .into_iter()
        .map(|(s, t)| (positive_zero(s), positive_zero(t)))
        .collect()
}

/// A point argument: `D x 1` (as bezier's) or a length-`D` sequence.
fn point_arg(point: &Bound<'_, PyAny>, d: usize) -> PyResult<Coords> {
    let numpy = point.py().import("numpy")?;
    let array = numpy
        .call_method1("asarray", (point,))
        .map_err(|e| bad("point", "Invalid", format!("not an array of numbers: {e}")))?;
    let shape: Vec<usize> = array.getattr("shape")?.extract()?;
    if shape != [d, 1] && shape != [d] {
        return Err(bad(
            "point",
            "Dimension",
            format!("expected a {d} x 1 point (the curve's dimension), found shape {shape:?}"),
        ));
    }
    let flat = array.call_method0("ravel")?;
    Ok(read_array(&flat, "point", 1, "the point's coordinates")?.coords)
}

/// Degrees up to which `Curve.evaluate_multi` of a float64 curve runs de Casteljau's
/// algorithm (`BezierCurve::eval_many`), faster than the O(n) method at these degrees
/// (`benches/python/evaluate_multi.rs`).
const DE_CASTELJAU_DEGREES: usize = 4;

/// `Curve.evaluate_multi` of a float64 curve: B at every value of `s` (refused, naming the
/// entry, when one is not finite) written straight into a new `D x M` Fortran-order array
/// (point after point, the library's layout), -0.0 made +0.0.
fn evaluate_f64<'py>(
    py: Python<'py>,
    c: &BezierCurve<f64>,
    s: &[f64],
) -> PyResult<Bound<'py, PyAny>> {
    if let Some(k) = crate::numbers::first_not_finite(s) {
        return Err(bad(
            format!("s_vals[{k}]"),
            "NotFinite",
            format!("expected a finite number, found {}", s[k]),
        ));
    }
    let d = c.dim();
    // SAFETY: every entry of the new array is written below before it is read or returned.
    #[allow(unsafe_code)]
    let answer = unsafe { PyArray2::<f64>::new(py, [d, s.len()], true) };
    {
        let mut writable = answer.readwrite();
        let out = writable.as_slice_mut().expect("a new contiguous array");
        call(&[], || {
            if c.degree() <= DE_CASTELJAU_DEGREES {
                c.eval_many(s, out)
            } else {
                c.eval_many_linear(s, out)
            }
        })?;
        for x in out.iter_mut() {
            // x + 0.0 is x, except that -0.0 becomes +0.0.
            *x += 0.0;
        }
    }
    Ok(answer.into_any())
}

fn evaluate_multi<'py, T: Num>(
    py: Python<'py>,
    c: &BezierCurve<T>,
    s_vals: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let s = T::values(s_vals, "s_vals")?;
    let d = c.dim();
    let mut out = vec![T::zero(); d * s.len()];
    call(&[], || {
        let mut level = Vec::new();
        for (si, o) in s.iter().zip(out.chunks_exact_mut(d)) {
            c.eval_into(si, o, &mut level);
        }
        Ok(())
    })?;
    T::columns(py, d, s.len(), out)
}

/// Relative distance within which `Curve.locate` of a float64 curve and point takes the point
/// as on the curve: 2^-40 of the largest magnitude among the nodes, the point and 1.
pub const LOCATE_TOLERANCE: f64 = 1.0 / (1u64 << 40) as f64;

impl Curve {
    /// The certified nearest point to `point`, and for a float64 curve and point the scale
    /// of their numbers (the largest magnitude, at least 1); `None` for exact input.
    fn nearest(
        &self,
        py: Python<'_>,
        point: &Bound<'_, PyAny>,
    ) -> PyResult<(blossom::NearestPoint, Option<f64>)> {
        let q = point_arg(point, self.dim())?;
        let renames = [
            Rename {
                rust: "control_points",
                python: "self.nodes",
                points: true,
            },
            Rename {
                rust: "point",
                python: "point",
                points: false,
            },
        ];
        match (&self.shape, q) {
            (CurveShape::F64(c), Coords::F64(qf)) => {
                let scale = c
                    .coordinates()
                    .iter()
                    .chain(&qf)
                    .fold(1.0f64, |m, x| m.max(x.abs()));
                let near = call_detached(py, &renames, || c.nearest_point(&qf))?;
                Ok((near, Some(scale)))
            }
            (_, q) => {
                let ce = self.exact_curve();
                let qe = Rational::of_coords(q, "point")?;
                let near = call_detached(py, &renames, || ce.nearest_point(&qe))?;
                Ok((near, None))
            }
        }
    }

    fn locate_point(&self, py: Python<'_>, point: &Bound<'_, PyAny>) -> PyResult<Option<f64>> {
        let (near, scale) = self.nearest(py, point)?;
        let tolerance = scale.map(|s| LOCATE_TOLERANCE * s);
        // On the curve: exactly for exact input; for float64 within the tolerance (a point
        // evaluated in float64 is off the curve by its rounding).
        let on_curve = match tolerance {
            None => near
                .squared_distance
                .exact()
                .is_some_and(num_traits::Zero::is_zero),
            Some(tol) => near.squared_distance.to_f64() <= tol * tol,
        };
        if !on_curve {
            return Ok(None);
        }
        if near.everywhere {
            return Err(bad(
                "point",
                "Invalid",
                "the curve is this single point: every parameter locates it",
            ));
        }
        let at: Vec<f64> = near.at.iter().map(|a| positive_zero(a.to_f64())).collect();
        if at.len() > 1 {
            return Err(bad(
                "point",
                "Invalid",
                format!("the point is on the curve at several parameters: {at:?}"),
            ));
        }
        Ok(at.first().copied())
    }
}

fn curve_of<T: WrapCurve>(c: BezierCurve<T>) -> Curve {
    Curve { shape: T::wrap(c) }
}

fn degree_error(degree: usize, nodes: usize) -> PyErr {
    bad(
        "degree",
        "Degree",
        format!(
            "a degree {degree} curve should have {} nodes, not {nodes}",
            degree + 1
        ),
    )
}

#[pymethods]
impl Curve {
    /// `Curve(nodes, degree, *, copy=True, verify=True)`: nodes a `D x (degree + 1)` array
    /// (columns are control points) of float64, or holding Fractions for an exact curve. The
    /// nodes are always copied, and the degree always checked (`copy` and `verify` are taken
    /// for bezier's signature).
    #[new]
    #[pyo3(signature = (nodes, degree, *, copy = None, verify = None))]
    fn new(
        nodes: &Bound<'_, PyAny>,
        degree: &Bound<'_, PyAny>,
        copy: Option<&Bound<'_, PyAny>>,
        verify: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let _ = (copy, verify);
        let degree = crate::args::degree_arg(degree, "degree")?;
        let curve = Curve::read(nodes, "nodes")?;
        if curve.degree() != degree {
            return Err(degree_error(degree, curve.degree() + 1));
        }
        Ok(curve)
    }

    /// The curve of `nodes`, its degree their number minus one.
    #[staticmethod]
    #[pyo3(signature = (nodes, copy = None))]
    fn from_nodes(nodes: &Bound<'_, PyAny>, copy: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let _ = copy;
        Curve::read(nodes, "nodes")
    }

    /// The `D x (n + 1)` float64 nodes (an exact curve's rounded to the nearest doubles).
    #[getter]
    fn nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (d, n) = (self.dim(), self.degree() + 1);
        match &self.shape {
            CurveShape::F64(c) => f64::columns(py, d, n, c.coordinates().to_vec()),
            CurveShape::Exact(c) => {
                f64::columns(py, d, n, crate::numbers::rounded(c.coordinates()))
            }
        }
    }

    /// The nodes as a `D x (n + 1)` object array of Fractions (a float64 curve's doubles read
    /// exactly).
    #[getter]
    fn exact_nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let c = self.exact_curve();
        Rational::columns(py, c.dim(), c.degree() + 1, c.into_coordinates())
    }

    /// Whether the curve computes exactly (built from Fractions).
    #[getter]
    fn exact(&self) -> bool {
        matches!(self.shape, CurveShape::Exact(_))
    }

    #[getter(degree)]
    fn get_degree(&self) -> usize {
        self.degree()
    }

    #[getter]
    fn dimension(&self) -> usize {
        self.dim()
    }

    /// The arc length: adaptive Gauss-Legendre quadrature of |B'(s)| over [0, 1] in float64
    /// (relative error about 1e-13; not certified).
    #[getter]
    fn length(&self) -> PyResult<f64> {
        let c = match &self.shape {
            CurveShape::F64(c) => c.clone(),
            CurveShape::Exact(c) => {
                BezierCurve::from_coordinates(c.dim(), crate::numbers::rounded(c.coordinates()))
                    .expect("the shape of a curve")
            }
        };
        call(&[], || Ok(crate::length::arc_length(&c)))
    }

    fn copy(&self) -> Self {
        self.clone()
    }

    fn __repr__(&self) -> String {
        format!(
            "<Curve (degree={}, dimension={}{})>",
            self.degree(),
            self.dim(),
            if self.exact() { ", exact" } else { "" }
        )
    }

    /// B(s) as a `D x 1` array (s outside [0, 1] extrapolates, as bezier's).
    fn evaluate<'py>(&self, py: Python<'py>, s: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on_curve!(&self.shape, c => {
            let t = Num::arg(s, "s")?;
            let p = call(&[], || Ok(c.eval(&t)))?;
            Num::columns(py, c.dim(), 1, p)
        })
    }

    /// B at every value of the 1-D `s_vals`, a `D x M` array. A float64 curve of degree
    /// n > 4 takes O(n) operations per value in [0, 1] (`BezierCurve::eval_many_linear`: a
    /// running convex combination of the nodes, its error bound of the order of de
    /// Casteljau's and its measured error within 1.5 times it), de Casteljau's algorithm
    /// (`eval_many`, faster at these degrees) up to degree 4 and outside [0, 1]. `evaluate`
    /// is de Casteljau's at every degree: above degree 4 the two may differ in the last
    /// places. An exact curve answers exactly.
    fn evaluate_multi<'py>(
        &self,
        py: Python<'py>,
        s_vals: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        match &self.shape {
            CurveShape::F64(c) => {
                // The common case, a contiguous float64 array, read where it lies.
                if let Ok(array) = s_vals.cast::<PyArray1<f64>>() {
                    if let Ok(readonly) = array.try_readonly() {
                        if let Ok(s) = readonly.as_slice() {
                            return evaluate_f64(py, c, s);
                        }
                    }
                }
                let s = f64::values(s_vals, "s_vals")?;
                evaluate_f64(py, c, &s)
            }
            CurveShape::Exact(c) => evaluate_multi(py, c, s_vals),
        }
    }

    /// B'(s) as a `D x 1` array.
    fn evaluate_hodograph<'py>(
        &self,
        py: Python<'py>,
        s: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        on_curve!(&self.shape, c => {
            let t = Num::arg(s, "s")?;
            let p = call(&[], || Ok(c.deriv().eval(&t)))?;
            Num::columns(py, c.dim(), 1, p)
        })
    }

    /// The halves over [0, 1/2] and [1/2, 1].
    fn subdivide(&self) -> PyResult<(Curve, Curve)> {
        on_curve!(&self.shape, c => {
            let (left, right) = call(&[], || Ok(c.split(&Num::dyadic(1, 1))))?;
            Ok((curve_of(left), curve_of(right)))
        })
    }

    /// The curve over [start, end] reparametrised to [0, 1] (any start, end: extrapolates).
    fn specialize(&self, start: &Bound<'_, PyAny>, end: &Bound<'_, PyAny>) -> PyResult<Curve> {
        on_curve!(&self.shape, c => {
            let a = Num::arg(start, "start")?;
            let b = Num::arg(end, "end")?;
            Ok(curve_of(call(&[], || Ok(c.subsegment(a..b)))?))
        })
    }

    /// The same curve at degree n + 1, computed exactly (a float64 curve's nodes then rounded
    /// to the nearest doubles).
    fn elevate(&self) -> PyResult<Curve> {
        let c = self.exact_curve();
        let e = call(&[], || c.elevate(c.degree() + 1))?;
        Ok(self.like(e))
    }

    /// A curve of degree n - 1, computed exactly (a float64 curve's nodes then rounded to the
    /// nearest doubles): the least-squares approximation in L2 on [0, 1]
    /// (`method="least-squares"`, the default), with both end points kept
    /// (`"least-squares-endpoints"`), or by interpolation (`"interpolating"`). Exact for a
    /// curve that is a degree-elevated one (then equal to bezier's); bezier's pseudo-inverse
    /// of the elevation matrix differs otherwise.
    #[pyo3(signature = (method = None))]
    fn reduce_(&self, method: Option<&Bound<'_, PyAny>>) -> PyResult<Curve> {
        let method = crate::args::str_arg(method, "method", "least-squares")?;
        let method = crate::errors::name_arg(
            "method",
            &method,
            &[
                ("least-squares", Reduction::LeastSquares),
                ("least-squares-endpoints", Reduction::LeastSquaresEndpoints),
                ("interpolating", Reduction::Interpolating),
            ],
        )?;
        if self.degree() == 0 {
            return Err(bad(
                "self",
                "Degree",
                "a curve of degree 0 has no lower degree",
            ));
        }
        let c = self.exact_curve();
        let r = call(&[], || blossom::reduce(&c, c.degree() - 1, method))?;
        Ok(self.like(r))
    }

    /// The parameter s with B(s) = point (`D x 1`), or None when the point is not on the curve:
    /// the certified nearest point, on the curve exactly for exact input, within 2^-40 of the
    /// numbers' magnitude for float64. Raises when the point is on the curve at several
    /// parameters.
    fn locate(&self, py: Python<'_>, point: &Bound<'_, PyAny>) -> PyResult<Option<f64>> {
        self.locate_point(py, point)
    }

    /// Every intersection with `other` (both planar), certified: a `2 x K` float64 array, row 0
    /// the parameters on this curve, row 1 on `other`, each the nearest double to the exact
    /// parameter; isolated points, and each overlap as its two end pairs, sorted by s then t.
    /// `strategy` is taken for bezier's signature (there is one, exact, method).
    #[pyo3(signature = (other, strategy = None, verify = None, *, max_work = None))]
    fn intersect<'py>(
        &self,
        py: Python<'py>,
        other: &Bound<'py, PyAny>,
        strategy: Option<&Bound<'py, PyAny>>,
        verify: Option<&Bound<'py, PyAny>>,
        max_work: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let max_work = max_work_arg(max_work)?;
        let _ = (strategy, verify);
        let other = crate::args::class_arg::<Curve>(other, "other", "a Curve")?.get();
        if let Some((a, b)) = self.both_f64(other) {
            Self::planar(a, "self")?;
            Self::planar(b, "other")?;
            if self.degree() * other.degree() > ALWAYS_CHEAP {
                let (pe, qe) = (self.planar_exact("self")?, other.planar_exact("other")?);
                self.check_pair_work(other, &pe, &qe, max_work)?;
            }
            let x = call_detached(py, &PAIR, || a.intersect_rounded(b))?;
            return pairs_array(py, rounded_pairs(&x));
        }
        let x = self.exact_intersections(py, other, max_work)?;
        pairs_array(py, rounded_pairs(&RoundedIntersections::from(&x)))
    }

    /// Every pair s < t with B(s) = B(t) (planar curve), certified, as a `2 x K` float64 array
    /// sorted by s; a retracing stretch as its end pairs.
    #[pyo3(signature = (strategy = None, verify = None, *, max_work = None))]
    fn self_intersections<'py>(
        &self,
        py: Python<'py>,
        strategy: Option<&Bound<'py, PyAny>>,
        verify: Option<&Bound<'py, PyAny>>,
        max_work: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let max_work = max_work_arg(max_work)?;
        let _ = (strategy, verify);
        let x = self.exact_self_intersections(py, max_work)?;
        let pairs = rounded_pairs(&RoundedIntersections::from(&x))
            .into_iter()
            .filter(|(s, t)| s != t)
            .map(|(s, t)| if s < t { (s, t) } else { (t, s) })
            .collect();
        pairs_array(py, pairs)
    }

    /// The full certified records of the intersections with `other`: `points` (each with
    /// `s`, `t` as Algebraic, `tangent`, `point`) and `overlaps`.
    #[pyo3(signature = (other, *, max_work = None))]
    fn intersections(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<IntersectionRecords> {
        let max_work = max_work_arg(max_work)?;
        let other = crate::args::class_arg::<Curve>(other, "other", "a Curve")?.get();
        let x = self.exact_intersections(py, other, max_work)?;
        intersection_records(py, &x)
    }

    /// The full certified records of the self-intersections (pairs s < t) and retracing
    /// overlaps.
    #[pyo3(signature = (*, max_work = None))]
    fn self_intersection_records(
        &self,
        py: Python<'_>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<IntersectionRecords> {
        let max_work = max_work_arg(max_work)?;
        let x = self.exact_self_intersections(py, max_work)?;
        intersection_records(py, &x)
    }

    /// The tight bounding box, a `D x 2` float64 array (column 0 the least, column 1 the
    /// greatest value of each coordinate over the curve), rounded outward: the exact box is
    /// inside it, and each bound is within one double of the exact extreme.
    fn bounding_box<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let b = self.tight_box(py)?;
        let (lo, hi) = b.outward();
        let coords = lo.into_iter().chain(hi).collect();
        f64::columns(py, self.dim(), 2, coords)
    }

    /// The exact extremes of every coordinate (`min`, `max`, each with `value` and the
    /// parameters `at`).
    fn extremes(&self, py: Python<'_>) -> PyResult<Extremes> {
        extremes_record(py, &self.tight_box(py)?)
    }

    /// The points of the curve nearest to `point`, certified (a float64 curve and point are
    /// read exactly).
    fn nearest_point(&self, py: Python<'_>, point: &Bound<'_, PyAny>) -> PyResult<NearestPoint> {
        let (near, _) = self.nearest(py, point)?;
        nearest_record(py, &near)
    }
}

impl Curve {
    /// The exact curve `c` in this curve's number type: as it is for an exact curve, its
    /// coordinates rounded to the nearest doubles for a float64 one.
    fn like(&self, c: BezierCurve<Rational>) -> Curve {
        match self.shape {
            CurveShape::Exact(_) => curve_of(c),
            CurveShape::F64(_) => curve_of(
                BezierCurve::from_coordinates(c.dim(), crate::numbers::rounded(c.coordinates()))
                    .expect("the shape of a curve"),
            ),
        }
    }

    fn tight_box(&self, py: Python<'_>) -> PyResult<blossom::TightBox> {
        let renames = [Rename {
            rust: "control_points",
            python: "self.nodes",
            points: true,
        }];
        match &self.shape {
            CurveShape::F64(c) => call_detached(py, &renames, || c.bounding_box()),
            CurveShape::Exact(c) => call_detached(py, &renames, || c.bounding_box()),
        }
    }
}

/// The Curve arguments of a function, for `CurvedPolygon` and `Triangle.edges`.
pub fn curves_tuple<'py>(py: Python<'py>, curves: Vec<Curve>) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(py, curves)
}
