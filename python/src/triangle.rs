//! `Triangle` (Python bezier's triangular Bézier patch, over the library's
//! `TriangularPatch`) and `CurvedPolygon`.
//!
//! bezier orders the nodes of a degree-n triangle by rows of the third barycentric weight:
//! node (i, j), the coefficient of lambda1^(n-i-j) lambda2^i lambda3^j, is column
//! j (n + 1) - j (j - 1) / 2 + i. The library orders its points (nu, mu) lexicographically,
//! nu the power of s = lambda2 and mu of t = lambda3; the binding permutes between the two.

use crate::area::chain_area;
use crate::args::bool_arg;
use crate::curve::{curves_tuple, Curve, CurveShape, WrapCurve};
use crate::errors::{bad, call, Rename};
use crate::numbers::{read_array, rounded, Coords, Num};
use blossom::{elevate_triangle, BezierCurve, Rational, TriangularPatch};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

/// A triangle's points in one of the two number types (library order).
#[derive(Clone)]
pub enum TriangleShape {
    F64(TriangularPatch<f64>),
    Exact(TriangularPatch<Rational>),
}

macro_rules! on_triangle {
    ($shape:expr, $p:ident => $body:expr) => {
        match $shape {
            TriangleShape::F64($p) => $body,
            TriangleShape::Exact($p) => $body,
        }
    };
}

/// Wraps a patch of either number type.
pub trait WrapTriangle: WrapCurve {
    fn wrap_triangle(p: TriangularPatch<Self>) -> TriangleShape;
}
impl WrapTriangle for f64 {
    fn wrap_triangle(p: TriangularPatch<f64>) -> TriangleShape {
        TriangleShape::F64(p)
    }
}
impl WrapTriangle for Rational {
    fn wrap_triangle(p: TriangularPatch<Rational>) -> TriangleShape {
        TriangleShape::Exact(p)
    }
}

/// bezier's column of node (i, j) of a degree-n triangle.
pub fn bezier_column(n: usize, i: usize, j: usize) -> usize {
    j * (n + 1) - j * j.saturating_sub(1) / 2 + i
}

/// The points (i, j) of a degree-n triangle in the library's order.
pub fn library_order(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=n).flat_map(move |i| (0..=n - i).map(move |j| (i, j)))
}

/// The degree of a triangle of `count` nodes, if `count` is (n + 1)(n + 2) / 2.
pub fn triangle_degree(count: usize) -> Option<usize> {
    (0..)
        .map(|n: usize| (n, (n + 1) * (n + 2) / 2))
        .take_while(|&(_, c)| c <= count)
        .find(|&(_, c)| c == count)
        .map(|(n, _)| n)
}

/// The library's coordinates (point-major, its order) of bezier's `d x count` nodes read in C
/// order.
pub fn from_bezier_order<T: Clone>(c: &[T], d: usize, count: usize, n: usize) -> Vec<T> {
    let mut out = Vec::with_capacity(c.len());
    for (i, j) in library_order(n) {
        let col = bezier_column(n, i, j);
        for x in 0..d {
            out.push(c[x * count + col].clone());
        }
    }
    out
}

/// bezier's point-major coordinates (its column order) of a library patch.
pub fn to_bezier_order<T: blossom::Ring>(p: &TriangularPatch<T>) -> Vec<T> {
    let (n, d) = (p.degree(), p.dim());
    let count = (n + 1) * (n + 2) / 2;
    let mut out: Vec<Option<T>> = vec![None; count * d];
    for ((i, j), q) in library_order(n).zip(p.control_points()) {
        let col = bezier_column(n, i, j);
        for x in 0..d {
            out[col * d + x] = Some(q[x].clone());
        }
    }
    out.into_iter()
        .map(|x| x.expect("every column filled"))
        .collect()
}

/// A triangular Bézier patch B(s, t) = sum C(n; i, j) lambda1^(n-i-j) lambda2^i lambda3^j
/// v_(i, j) with lambda2 = s, lambda3 = t (as Python bezier's `Triangle`): float64, or exact
/// when built from Fractions.
#[pyclass(module = "blossom", frozen)]
#[derive(Clone)]
pub struct Triangle {
    pub shape: TriangleShape,
    /// The triangle's region for `intersect`, made on first use and kept (the library also
    /// keeps on it the proof that its boundary is simple).
    pub region: std::sync::OnceLock<crate::region::CurvedRegion>,
}

impl Triangle {
    /// A triangle of the shape `shape`.
    pub fn of_shape(shape: TriangleShape) -> Triangle {
        Triangle {
            shape,
            region: std::sync::OnceLock::new(),
        }
    }
}

fn triangle_of<T: WrapTriangle>(p: TriangularPatch<T>) -> Triangle {
    Triangle::of_shape(T::wrap_triangle(p))
}

impl Triangle {
    pub fn read(nodes: &Bound<'_, PyAny>, degree: Option<usize>) -> PyResult<Triangle> {
        let arg = "nodes";
        let read = read_array(nodes, arg, 2, "D x N, one column per control point")?;
        let (d, count) = (read.shape[0], read.shape[1]);
        if d == 0 || count == 0 {
            return Err(bad(
                arg,
                "Empty",
                format!("expected at least one dimension and one node, found shape ({d}, {count})"),
            ));
        }
        let n = match degree {
            Some(n) => {
                let want = n
                    .checked_add(1)
                    .and_then(|a| a.checked_mul(n + 2))
                    .map(|x| x / 2);
                if want != Some(count) {
                    return Err(bad(
                        "degree",
                        "Degree",
                        format!("a degree {n} triangle should have (n + 1)(n + 2) / 2 nodes, not {count}"),
                    ));
                }
                n
            }
            None => triangle_degree(count).ok_or_else(|| {
                bad(
                    arg,
                    "Shape",
                    format!("{count} nodes is not a triangular number (n + 1)(n + 2) / 2"),
                )
            })?,
        };
        let renames = [Rename {
            rust: "coordinates",
            python: "nodes",
            points: false,
        }];
        let shape = match read.coords {
            Coords::F64(c) => TriangleShape::F64(call(&renames, || {
                TriangularPatch::from_coordinates(n, d, from_bezier_order(&c, d, count, n))
            })?),
            Coords::Exact(c) => TriangleShape::Exact(call(&renames, || {
                TriangularPatch::from_coordinates(n, d, from_bezier_order(&c, d, count, n))
            })?),
        };
        Ok(Triangle::of_shape(shape))
    }

    pub fn degree(&self) -> usize {
        on_triangle!(&self.shape, p => p.degree())
    }

    pub fn dim(&self) -> usize {
        on_triangle!(&self.shape, p => p.dim())
    }

    /// The three edges as Curves, in bezier's order.
    pub fn edge_curves(&self) -> Vec<Curve> {
        on_triangle!(&self.shape, p => {
            edges_of(p).into_iter().map(|c| Curve { shape: WrapCurve::wrap(c) }).collect()
        })
    }

    pub fn exact_patch(&self) -> TriangularPatch<Rational> {
        match &self.shape {
            TriangleShape::Exact(p) => p.clone(),
            TriangleShape::F64(p) => {
                let coords = p
                    .coordinates()
                    .iter()
                    .map(|&x| num_rational::Ratio::from_float(x).expect("finite nodes"))
                    .collect();
                TriangularPatch::from_coordinates(p.degree(), p.dim(), coords)
                    .expect("the shape of a patch")
            }
        }
    }
}

/// The three edges of a patch (bezier's order: (0,0)->(1,0), (1,0)->(0,1), (0,1)->(0,0)).
fn edges_of<T: WrapCurve>(p: &TriangularPatch<T>) -> [BezierCurve<T>; 3] {
    let n = p.degree();
    let edge = |points: Vec<(usize, usize)>| {
        let coords = points
            .into_iter()
            .flat_map(|(i, j)| p.get(i, j).to_vec())
            .collect();
        BezierCurve::from_coordinates(p.dim(), coords).expect("n + 1 points")
    };
    [
        edge((0..=n).map(|k| (k, 0)).collect()),
        edge((0..=n).map(|k| (n - k, k)).collect()),
        edge((0..=n).map(|k| (0, n - k)).collect()),
    ]
}

/// bezier's subdivision: lower left, central, lower right, upper left triangles, each given by
/// the images of (0, 0), (1, 0), (0, 1) as (s, t) numerators over 2.
const QUARTERS: [[(i64, i64); 3]; 4] = [
    [(0, 0), (1, 0), (0, 1)],
    [(1, 1), (0, 1), (1, 0)],
    [(1, 0), (2, 0), (1, 1)],
    [(0, 1), (1, 1), (0, 2)],
];

/// The patch over the sub-triangle whose vertices (images of (0, 0), (1, 0), (0, 1)) are
/// `corners`: the library's corners are the images of (1, 0), (0, 1), (0, 0).
fn specialize_patch<T: Num>(
    p: &TriangularPatch<T>,
    corners: [[T; 2]; 3],
) -> PyResult<TriangularPatch<T>> {
    let [c0, c1, c2] = corners;
    call(&[], || Ok(p.restrict(&[c1, c2, c0])))
}

fn check_barycentric(l: [f64; 3]) -> PyResult<()> {
    let total = l[0] + l[1] + l[2];
    if (total - 1.0).abs() > 1e-5 {
        return Err(bad(
            "lambda1 + lambda2 + lambda3",
            "Domain",
            format!("weights do not sum to 1 (found {total}); pass verify=False to evaluate the homogeneous form"),
        ));
    }
    if l.iter().any(|&x| x < 0.0) {
        return Err(bad(
            "lambda1, lambda2, lambda3",
            "Domain",
            format!("weights must be non-negative, found {l:?}"),
        ));
    }
    Ok(())
}

fn check_cartesian(s: f64, t: f64) -> PyResult<()> {
    if s < 0.0 || t < 0.0 || s + t > 1.0 {
        return Err(bad(
            "s, t",
            "Domain",
            format!("point ({s}, {t}) lies outside the reference triangle; pass verify=False to extrapolate"),
        ));
    }
    Ok(())
}

/// B at barycentric weights (the homogeneous form when they do not sum to 1: the library's
/// blossom at (lambda2, lambda3, lambda1) n times).
fn barycentric<T: Num>(p: &TriangularPatch<T>, l: [T; 3]) -> PyResult<Vec<T>> {
    let [l1, l2, l3] = l;
    let args = vec![[l2, l3, l1]; p.degree()];
    call(&[], || p.blossom(&args))
}

fn param_rows<T: Num>(obj: &Bound<'_, PyAny>, cols: usize) -> PyResult<Vec<Vec<T>>> {
    let what = if cols == 3 {
        "N x 3 barycentric weights"
    } else {
        "N x 2 (s, t) values"
    };
    let read = read_array(obj, "param_vals", 2, what)?;
    if read.shape[1] != cols {
        return Err(bad(
            "param_vals",
            "Shape",
            format!("expected {cols} columns ({what}), found {}", read.shape[1]),
        ));
    }
    let v = T::of_coords(read.coords, "param_vals")?;
    Ok(v.chunks(cols).map(|r| r.to_vec()).collect())
}

pub fn corners_arg<T: Num>(obj: &Bound<'_, PyAny>) -> PyResult<[[T; 2]; 3]> {
    let read = read_array(
        obj,
        "corners",
        2,
        "3 x 2, the (s, t) images of (0, 0), (1, 0), (0, 1)",
    )?;
    if read.shape != [3, 2] {
        return Err(bad(
            "corners",
            "Shape",
            format!(
                "expected shape (3, 2): the (s, t) images of (0, 0), (1, 0), (0, 1), found {:?}",
                read.shape
            ),
        ));
    }
    let v = T::of_coords(read.coords, "corners")?;
    Ok([
        [v[0].clone(), v[1].clone()],
        [v[2].clone(), v[3].clone()],
        [v[4].clone(), v[5].clone()],
    ])
}

fn eval_barycentric<'py, T: Num>(
    py: Python<'py>,
    p: &TriangularPatch<T>,
    lambdas: [&Bound<'py, PyAny>; 3],
    verify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let l: [T; 3] = [
        T::arg(lambdas[0], "lambda1")?,
        T::arg(lambdas[1], "lambda2")?,
        T::arg(lambdas[2], "lambda3")?,
    ];
    if verify {
        check_barycentric([l[0].to_f64(), l[1].to_f64(), l[2].to_f64()])?;
    }
    let q = barycentric(p, l)?;
    T::columns(py, p.dim(), 1, q)
}

fn eval_barycentric_multi<'py, T: Num>(
    py: Python<'py>,
    p: &TriangularPatch<T>,
    param_vals: &Bound<'py, PyAny>,
    verify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let rows = param_rows::<T>(param_vals, 3)?;
    let mut out = Vec::with_capacity(rows.len() * p.dim());
    for r in rows {
        let l = [r[0].clone(), r[1].clone(), r[2].clone()];
        if verify {
            check_barycentric([l[0].to_f64(), l[1].to_f64(), l[2].to_f64()])?;
        }
        out.extend(barycentric(p, l)?);
    }
    let m = out.len() / p.dim();
    T::columns(py, p.dim(), m, out)
}

fn eval_cartesian<'py, T: Num>(
    py: Python<'py>,
    p: &TriangularPatch<T>,
    s: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    verify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let at: [T; 2] = [T::arg(s, "s")?, T::arg(t, "t")?];
    if verify {
        check_cartesian(at[0].to_f64(), at[1].to_f64())?;
    }
    let q = call(&[], || Ok(p.eval(&at)))?;
    T::columns(py, p.dim(), 1, q)
}

fn eval_cartesian_multi<'py, T: Num>(
    py: Python<'py>,
    p: &TriangularPatch<T>,
    param_vals: &Bound<'py, PyAny>,
    verify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let rows = param_rows::<T>(param_vals, 2)?;
    let mut out = Vec::with_capacity(rows.len() * p.dim());
    for r in rows {
        let at = [r[0].clone(), r[1].clone()];
        if verify {
            check_cartesian(at[0].to_f64(), at[1].to_f64())?;
        }
        out.extend(call(&[], || Ok(p.eval(&at)))?);
    }
    let m = out.len() / p.dim();
    T::columns(py, p.dim(), m, out)
}

#[pymethods]
impl Triangle {
    /// `Triangle(nodes, degree, *, copy=True, verify=True)`: nodes `D x (n + 1)(n + 2) / 2`
    /// in bezier's order; float64, or exact when holding Fractions.
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
        Triangle::read(nodes, Some(degree))
    }

    #[staticmethod]
    #[pyo3(signature = (nodes, copy = None))]
    fn from_nodes(nodes: &Bound<'_, PyAny>, copy: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let _ = copy;
        Triangle::read(nodes, None)
    }

    /// The float64 nodes in bezier's order (an exact triangle's rounded).
    #[getter]
    fn nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let count = (self.degree() + 1) * (self.degree() + 2) / 2;
        let coords = match &self.shape {
            TriangleShape::F64(p) => to_bezier_order(p),
            TriangleShape::Exact(p) => rounded(&to_bezier_order(p)),
        };
        f64::columns(py, self.dim(), count, coords)
    }

    /// The nodes as an object array of Fractions.
    #[getter]
    fn exact_nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let p = self.exact_patch();
        let count = (p.degree() + 1) * (p.degree() + 2) / 2;
        Rational::columns(py, p.dim(), count, to_bezier_order(&p))
    }

    #[getter]
    fn exact(&self) -> bool {
        matches!(self.shape, TriangleShape::Exact(_))
    }

    #[getter(degree)]
    fn get_degree(&self) -> usize {
        self.degree()
    }

    #[getter]
    fn dimension(&self) -> usize {
        self.dim()
    }

    fn copy(&self) -> Self {
        self.clone()
    }

    fn __repr__(&self) -> String {
        format!(
            "<Triangle (degree={}, dimension={}{})>",
            self.degree(),
            self.dim(),
            if self.exact() { ", exact" } else { "" }
        )
    }

    /// B at barycentric weights, a `D x 1` array; `verify` checks that they are non-negative
    /// and sum to 1 (within 1e-5, as bezier's), else the homogeneous form is evaluated.
    #[pyo3(signature = (lambda1, lambda2, lambda3, verify = None))]
    fn evaluate_barycentric<'py>(
        &self,
        py: Python<'py>,
        lambda1: &Bound<'py, PyAny>,
        lambda2: &Bound<'py, PyAny>,
        lambda3: &Bound<'py, PyAny>,
        verify: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let verify = bool_arg(verify, "verify", true)?;
        on_triangle!(&self.shape, p => eval_barycentric(py, p, [lambda1, lambda2, lambda3], verify))
    }

    /// B at each row of the `N x 3` weights, a `D x N` array.
    #[pyo3(signature = (param_vals, verify = None))]
    fn evaluate_barycentric_multi<'py>(
        &self,
        py: Python<'py>,
        param_vals: &Bound<'py, PyAny>,
        verify: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let verify = bool_arg(verify, "verify", true)?;
        on_triangle!(&self.shape, p => eval_barycentric_multi(py, p, param_vals, verify))
    }

    /// B(s, t), a `D x 1` array; `verify` checks that (s, t) is in the reference triangle.
    #[pyo3(signature = (s, t, verify = None))]
    fn evaluate_cartesian<'py>(
        &self,
        py: Python<'py>,
        s: &Bound<'py, PyAny>,
        t: &Bound<'py, PyAny>,
        verify: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let verify = bool_arg(verify, "verify", true)?;
        on_triangle!(&self.shape, p => eval_cartesian(py, p, s, t, verify))
    }

    /// B at each row (s, t) of the `N x 2` array, a `D x N` array.
    #[pyo3(signature = (param_vals, verify = None))]
    fn evaluate_cartesian_multi<'py>(
        &self,
        py: Python<'py>,
        param_vals: &Bound<'py, PyAny>,
        verify: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let verify = bool_arg(verify, "verify", true)?;
        on_triangle!(&self.shape, p => eval_cartesian_multi(py, p, param_vals, verify))
    }

    /// The four sub-triangles of the midpoint subdivision, in bezier's order: lower left,
    /// central, lower right, upper left.
    fn subdivide(&self) -> PyResult<(Triangle, Triangle, Triangle, Triangle)> {
        on_triangle!(&self.shape, p => {
            let [a, b, c, d] = QUARTERS.map(|q| {
                let corners = q.map(|(s, t)| [Num::dyadic(s, 1), Num::dyadic(t, 1)]);
                specialize_patch(p, corners).map(triangle_of)
            });
            Ok((a?, b?, c?, d?))
        })
    }

    /// The patch over the sub-triangle whose vertices are `corners` (a `3 x 2` array: the
    /// (s, t) images of the reference vertices (0, 0), (1, 0), (0, 1)), reparametrised over
    /// the reference triangle: exact for an exact triangle.
    fn specialize(&self, corners: &Bound<'_, PyAny>) -> PyResult<Triangle> {
        on_triangle!(&self.shape, p => {
            let c = corners_arg(corners)?;
            Ok(triangle_of(specialize_patch(p, c)?))
        })
    }

    /// The same patch at degree n + 1, computed exactly (a float64 triangle's nodes then
    /// rounded to the nearest doubles).
    fn elevate(&self) -> PyResult<Triangle> {
        let p = self.exact_patch();
        let e = call(&[], || elevate_triangle(&p, p.degree() + 1))?;
        Ok(match self.shape {
            TriangleShape::Exact(_) => triangle_of(e),
            TriangleShape::F64(_) => triangle_of(
                TriangularPatch::from_coordinates(e.degree(), e.dim(), rounded(e.coordinates()))
                    .expect("the shape of a patch"),
            ),
        })
    }

    /// The three edges as Curves: (0, 0) to (1, 0), (1, 0) to (0, 1), (0, 1) to (0, 0).
    #[getter]
    fn edges<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let curves: Vec<Curve> = on_triangle!(&self.shape, p => {
            edges_of(p).into_iter().map(|c| Curve { shape: WrapCurve::wrap(c) }).collect()
        });
        curves_tuple(py, curves)
    }

    /// The signed area (planar triangles), exact then correctly rounded: positive when the
    /// edges run counterclockwise, as bezier's.
    #[getter]
    fn area(&self) -> PyResult<f64> {
        if self.dim() != 2 {
            return Err(bad(
                "self.nodes",
                "Dimension",
                format!(
                    "area is defined for planar triangles (dimension 2), found dimension {}",
                    self.dim()
                ),
            ));
        }
        let edges = edges_of(&self.exact_patch());
        Ok(Rational::to_f64(&call(&[], || Ok(chain_area(&edges)))?))
    }

    /// Whether the (planar) triangle is valid: the Jacobian of its map from the reference
    /// triangle is positive on the whole closed triangle, decided exactly for every degree.
    /// Raises `blossom.Error` (kind `Undecided`) in the one case the subdivision cannot settle,
    /// a Jacobian >= 0 that touches 0 inside without changing sign.
    #[getter]
    fn is_valid(&self, py: Python<'_>) -> PyResult<bool> {
        let p = self.exact_patch();
        let answer = crate::errors::call_detached(py, &[], || crate::validity::is_valid(&p))?;
        answer.ok_or_else(|| {
            bad(
                "self",
                "Undecided",
                format!(
                    "the sign of the Jacobian was not decided within {} sub-triangles (it \
                     touches 0 without changing sign)",
                    crate::validity::MAX_PIECES
                ),
            )
        })
    }

    /// The intersection with the planar triangle `other`, certified (the library's region
    /// booleans, exact for the nodes), as Python bezier returns it: a list, `[]` when the
    /// triangles do not overlap (also when they only touch along an edge or at a point, where
    /// bezier may raise), `[self]` or `[other]` when one lies inside the other, else one
    /// `CurvedPolygon` per component of the intersection (counter-clockwise), its edges the
    /// pieces of the triangles' edges. `strategy` and `verify` are accepted for bezier's
    /// signature and ignored (there is one, exact, method). Refused over `max_work`.
    #[pyo3(signature = (other, strategy = None, verify = None, *, max_work = None))]
    fn intersect(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        strategy: Option<&Bound<'_, PyAny>>,
        verify: Option<&Bound<'_, PyAny>>,
        max_work: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyList>> {
        let _ = (strategy, verify);
        let max_work = crate::curve::max_work_arg(max_work)?;
        let other = crate::args::class_arg::<Triangle>(other, "other", "a Triangle")?;
        crate::region::triangle_intersect(py, self, other.get(), max_work)
    }
}

/// A curved polygon bounded by planar Curves, each ending where the next starts (as Python
/// bezier's `CurvedPolygon(*edges, metadata=None, verify=True)`).
#[pyclass(module = "blossom", frozen)]
pub struct CurvedPolygon {
    edges: Vec<Curve>,
    metadata: Option<Py<PyAny>>,
}

/// Whether two points match within 2^-40 relative (bezier's `vector_close`).
fn close(a: &[f64], b: &[f64]) -> bool {
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let diff: Vec<f64> = a.iter().zip(b).map(|(x, y)| x - y).collect();
    let size = norm(a).min(norm(b));
    let eps = 1.0 / (1u64 << 40) as f64;
    norm(&diff) <= eps * size.max(eps)
}

fn end_points(c: &Curve) -> (Vec<f64>, Vec<f64>) {
    let coords: Vec<f64> = match &c.shape {
        CurveShape::F64(c) => c.coordinates().to_vec(),
        CurveShape::Exact(c) => rounded(c.coordinates()),
    };
    let d = c.dim();
    (coords[..d].to_vec(), coords[coords.len() - d..].to_vec())
}

impl CurvedPolygon {
    /// A polygon of the pieces of a region result (closed exactly by construction).
    pub fn of_pieces(edges: Vec<Curve>) -> CurvedPolygon {
        CurvedPolygon {
            edges,
            metadata: None,
        }
    }
}

#[pymethods]
impl CurvedPolygon {
    #[new]
    #[pyo3(signature = (*edges, metadata = None, verify = None))]
    fn new(
        edges: &Bound<'_, PyTuple>,
        metadata: Option<Py<PyAny>>,
        verify: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let verify = bool_arg(verify, "verify", true)?;
        let mut curves = Vec::new();
        for (k, e) in edges.iter().enumerate() {
            let c = crate::args::class_arg::<Curve>(&e, &format!("edges[{k}]"), "a Curve")?;
            curves.push(c.get().clone());
        }
        if verify {
            if curves.len() < 2 {
                return Err(bad("edges", "Shape", "at least two sides required"));
            }
            for (k, c) in curves.iter().enumerate() {
                if c.dim() != 2 {
                    return Err(bad(
                        format!("edges[{k}]"),
                        "Dimension",
                        format!("expected a planar curve, found dimension {}", c.dim()),
                    ));
                }
                let next = (k + 1) % curves.len();
                let (_, end) = end_points(c);
                let (start, _) = end_points(&curves[next]);
                if !close(&end, &start) {
                    return Err(bad(
                        format!("edges[{k}]"),
                        "Invalid",
                        format!("ends at {end:?}, but edges[{next}] starts at {start:?}"),
                    ));
                }
            }
        }
        Ok(CurvedPolygon {
            edges: curves,
            metadata,
        })
    }

    #[getter]
    fn num_sides(&self) -> usize {
        self.edges.len()
    }

    #[getter]
    fn edges<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        curves_tuple(py, self.edges.clone())
    }

    #[getter]
    fn metadata(&self, py: Python<'_>) -> Option<Py<PyAny>> {
        self.metadata.as_ref().map(|m| m.clone_ref(py))
    }

    /// The signed area (Green's theorem on the edges), exact then correctly rounded.
    #[getter]
    fn area(&self) -> PyResult<f64> {
        for (k, c) in self.edges.iter().enumerate() {
            if c.dim() != 2 {
                return Err(bad(
                    format!("edges[{k}]"),
                    "Dimension",
                    "area needs planar edges",
                ));
            }
        }
        let exact: Vec<BezierCurve<Rational>> = self.edges.iter().map(Curve::exact_curve).collect();
        Ok(Rational::to_f64(&call(&[], || Ok(chain_area(&exact)))?))
    }

    fn __repr__(&self) -> String {
        format!("<CurvedPolygon (num_sides={})>", self.edges.len())
    }
}
