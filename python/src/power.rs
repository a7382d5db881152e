//! The papers' operation and its batch form: power-form curves, tensor surfaces and
//! triangles restricted to an interval, rectangle or triangle by any of the library's methods
//! (`restrict_power_curve`, `restrict_power_surface`, `restrict_power_triangle`), the
//! `TensorPatch` type, many Bézier curves restricted at once with the GIL released
//! (`restrict_curves`), and the certified zeros of a Bernstein polynomial (`bezier_zeros`).

use crate::curve::{check_work, Curve, WrapCurve};
use crate::errors::{bad, call, call_detached, Rename};
use crate::numbers::{read_array, Coords, Num};
use crate::records::{zeros_record, Zeros};
use crate::triangle::{from_bezier_order, triangle_degree, Triangle, WrapTriangle};
use blossom::{
    bezier_zeros, bezier_zeros_f64, restrict_power_curve, restrict_power_surface,
    restrict_power_triangle, zeros_work, Method, PowerCurve, PowerSurface, PowerTriangle,
    Rational, TensorPatch,
};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray3, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// The most work a power-form restriction may take: a coarse operation count (points^2 times
/// the degree's square times the dimension, which bounds every method's count up to a small
/// factor) over this is refused.
pub const MAX_RESTRICTION_OPERATIONS: f64 = 1e10;

fn method_arg(name: &str) -> PyResult<Method> {
    Method::ALL
        .into_iter()
        .find(|m| m.name() == name)
        .ok_or_else(|| {
            let names: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
            bad(
                "method",
                "UnknownName",
                format!("expected one of {names:?}, found {name:?}"),
            )
        })
}

fn check_operations(points: usize, degree: usize, dim: usize) -> PyResult<()> {
    let (p, k) = (points as f64, degree as f64 + 1.0);
    let ops = p * p * k * k * dim as f64;
    if ops > MAX_RESTRICTION_OPERATIONS {
        return Err(bad(
            "coefficients",
            "TooLarge",
            format!(
                "a restriction of {points} points of degree {degree} is estimated at {ops:.2e} \
                 operations, over the limit of {MAX_RESTRICTION_OPERATIONS:.0e}"
            ),
        ));
    }
    Ok(())
}

const COEFFICIENTS: [Rename; 1] = [Rename {
    rust: "coordinates",
    python: "coefficients",
    points: false,
}];

fn power_curve<'py, T: Num + WrapCurve>(
    c: Vec<T>,
    d: usize,
    n: usize,
    start: &Bound<'py, PyAny>,
    end: &Bound<'py, PyAny>,
    method: Method,
) -> PyResult<Curve> {
    let a = T::arg(start, "start")?;
    let b = T::arg(end, "end")?;
    let coords = crate::numbers::points_of_columns(&c, d, n);
    let curve = call(&COEFFICIENTS, || PowerCurve::from_coordinates(d, coords))?;
    let r = call(&[], || Ok(restrict_power_curve(&curve, &a, &b, method)))?;
    Ok(Curve { shape: T::wrap(r) })
}

/// The power-form curve p(u) = sum_i c_i u^i (`coefficients` a `D x (n + 1)` array, column i
/// the vector c_i; floats, or Fractions for an exact answer) restricted to [start, end]: the
/// Bézier `Curve` of degree n over [0, 1] that traces p from start to end, by `method` (one
/// of "bulk" (default), "taylor-shift", "closed-form", "definition", "pyramid",
/// "polarisation").
#[pyfunction(name = "restrict_power_curve")]
#[pyo3(signature = (coefficients, start, end, *, method = "bulk"))]
pub fn restrict_power_curve_py(
    coefficients: &Bound<'_, PyAny>,
    start: &Bound<'_, PyAny>,
    end: &Bound<'_, PyAny>,
    method: &str,
) -> PyResult<Curve> {
    let method = method_arg(method)?;
    let read = read_array(coefficients, "coefficients", 2, "D x (n + 1), column i the coefficient of u^i")?;
    let (d, k) = (read.shape[0], read.shape[1]);
    if d == 0 || k == 0 {
        return Err(bad("coefficients", "Empty", "expected at least one dimension and one coefficient"));
    }
    check_operations(k, k - 1, d)?;
    match read.coords {
        Coords::F64(c) => power_curve(c, d, k, start, end, method),
        Coords::Exact(c) => power_curve(c, d, k, start, end, method),
    }
}

/// A `D x r x c` array read in C order as the library's point-major grid (point (i, j) at
/// i c + j).
fn grid_points<T: Clone>(c: &[T], d: usize, rows: usize, cols: usize) -> Vec<T> {
    let mut out = Vec::with_capacity(c.len());
    for i in 0..rows {
        for j in 0..cols {
            for x in 0..d {
                out.push(c[(x * rows + i) * cols + j].clone());
            }
        }
    }
    out
}

/// The inverse of [`grid_points`]: C order of a `D x r x c` array.
fn grid_array<T: Clone>(p: &[T], d: usize, rows: usize, cols: usize) -> Vec<T> {
    let mut out = Vec::with_capacity(p.len());
    for x in 0..d {
        for i in 0..rows {
            for j in 0..cols {
                out.push(p[(i * cols + j) * d + x].clone());
            }
        }
    }
    out
}

fn rect_arg<T: Num>(obj: &Bound<'_, PyAny>) -> PyResult<[T; 4]> {
    let v = T::values(obj, "rect")?;
    if v.len() != 4 {
        return Err(bad(
            "rect",
            "Shape",
            format!("expected 4 values (s_start, s_end, t_start, t_end), found {}", v.len()),
        ));
    }
    Ok([v[0].clone(), v[1].clone(), v[2].clone(), v[3].clone()])
}

/// The shapes a tensor patch can hold.
#[derive(Clone)]
pub enum TensorShape {
    F64(TensorPatch<f64>),
    Exact(TensorPatch<Rational>),
}

macro_rules! on_tensor {
    ($shape:expr, $p:ident => $body:expr) => {
        match $shape {
            TensorShape::F64($p) => $body,
            TensorShape::Exact($p) => $body,
        }
    };
}

/// Wraps a tensor patch of either number type.
pub trait WrapTensor: Num {
    fn wrap_tensor(p: TensorPatch<Self>) -> TensorShape;
}
impl WrapTensor for f64 {
    fn wrap_tensor(p: TensorPatch<f64>) -> TensorShape {
        TensorShape::F64(p)
    }
}
impl WrapTensor for Rational {
    fn wrap_tensor(p: TensorPatch<Rational>) -> TensorShape {
        TensorShape::Exact(p)
    }
}

/// A tensor-product Bézier patch B(s, t) = sum_(i, j) B_i^n(s) B_j^m(t) v_(i, j) over
/// [0, 1]^2, its nodes a `D x (n + 1) x (m + 1)` array (`nodes[:, i, j]` is v_(i, j));
/// float64, or exact when built from Fractions.
#[pyclass(module = "blossom", name = "TensorPatch", frozen)]
#[derive(Clone)]
pub struct TensorPatchPy {
    shape: TensorShape,
}

fn tensor_of<T: WrapTensor>(p: TensorPatch<T>) -> TensorPatchPy {
    TensorPatchPy {
        shape: T::wrap_tensor(p),
    }
}

fn tensor_array<'py, T: Num>(py: Python<'py>, p: &TensorPatch<T>) -> PyResult<Bound<'py, PyAny>> {
    let (n, m) = p.degree();
    let (d, rows, cols) = (p.dim(), n + 1, m + 1);
    let c = grid_array(p.coordinates(), d, rows, cols);
    // A d x (rows cols) array of the C-order entries, reshaped.
    let flat = T::columns(py, 1, c.len(), c)?;
    flat.call_method1("reshape", ((d, rows, cols),))
}

#[pymethods]
impl TensorPatchPy {
    /// `TensorPatch(nodes)`: nodes a `D x (n + 1) x (m + 1)` array.
    #[new]
    fn new(nodes: &Bound<'_, PyAny>) -> PyResult<Self> {
        let read = read_array(nodes, "nodes", 3, "D x (n + 1) x (m + 1)")?;
        let (d, rows, cols) = (read.shape[0], read.shape[1], read.shape[2]);
        if d == 0 || rows == 0 || cols == 0 {
            return Err(bad("nodes", "Empty", format!("expected no zero extent, found shape {:?}", read.shape)));
        }
        let renames = [Rename { rust: "coordinates", python: "nodes", points: false }];
        Ok(match read.coords {
            Coords::F64(c) => tensor_of(call(&renames, || {
                TensorPatch::from_coordinates((rows - 1, cols - 1), d, grid_points(&c, d, rows, cols))
            })?),
            Coords::Exact(c) => tensor_of(call(&renames, || {
                TensorPatch::from_coordinates((rows - 1, cols - 1), d, grid_points(&c, d, rows, cols))
            })?),
        })
    }

    /// The `D x (n + 1) x (m + 1)` nodes (float64, or Fractions for an exact patch).
    #[getter]
    fn nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on_tensor!(&self.shape, p => tensor_array(py, p))
    }

    #[getter]
    fn exact(&self) -> bool {
        matches!(self.shape, TensorShape::Exact(_))
    }

    /// The bidegree (n, m).
    #[getter]
    fn degree(&self) -> (usize, usize) {
        on_tensor!(&self.shape, p => p.degree())
    }

    #[getter]
    fn dimension(&self) -> usize {
        on_tensor!(&self.shape, p => p.dim())
    }

    /// B(s, t), a `D x 1` array.
    fn evaluate<'py>(&self, py: Python<'py>, s: &Bound<'py, PyAny>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on_tensor!(&self.shape, p => {
            let (s, t) = (Num::arg(s, "s")?, Num::arg(t, "t")?);
            Num::columns(py, p.dim(), 1, p.eval(&s, &t))
        })
    }

    /// The patch over `rect = (s_start, s_end, t_start, t_end)` reparametrised to [0, 1]^2.
    fn specialize(&self, rect: &Bound<'_, PyAny>) -> PyResult<TensorPatchPy> {
        on_tensor!(&self.shape, p => {
            let r = rect_arg(rect)?;
            Ok(tensor_of(p.restrict(&r)))
        })
    }

    fn __repr__(&self) -> String {
        let (n, m) = self.degree();
        format!("<TensorPatch (degree=({n}, {m}), dimension={})>", self.dimension())
    }
}

fn power_surface<T: WrapTensor>(
    c: Vec<T>,
    d: usize,
    rows: usize,
    cols: usize,
    rect: &Bound<'_, PyAny>,
    method: Method,
) -> PyResult<TensorPatchPy> {
    let r = rect_arg::<T>(rect)?;
    let points = grid_points(&c, d, rows, cols);
    let nested: Vec<Vec<Vec<T>>> = points
        .chunks(cols * d)
        .map(|row| row.chunks(d).map(|p| p.to_vec()).collect())
        .collect();
    let surface = call(&COEFFICIENTS, || PowerSurface::new(nested))?;
    let patch = call(&[], || Ok(restrict_power_surface(&surface, &r, method)))?;
    Ok(tensor_of(patch))
}

/// The power-form surface p(u, v) = sum c_ij u^i v^j (`coefficients` a `D x (n + 1) x (m + 1)`
/// array, `coefficients[:, i, j]` = c_ij) restricted to `rect = (u_start, u_end, v_start,
/// v_end)`: a `TensorPatch` of bidegree (n, m), by `method`.
#[pyfunction(name = "restrict_power_surface")]
#[pyo3(signature = (coefficients, rect, *, method = "bulk"))]
pub fn restrict_power_surface_py(
    coefficients: &Bound<'_, PyAny>,
    rect: &Bound<'_, PyAny>,
    method: &str,
) -> PyResult<TensorPatchPy> {
    let method = method_arg(method)?;
    let read = read_array(coefficients, "coefficients", 3, "D x (n + 1) x (m + 1)")?;
    let (d, rows, cols) = (read.shape[0], read.shape[1], read.shape[2]);
    if d == 0 || rows == 0 || cols == 0 {
        return Err(bad("coefficients", "Empty", format!("expected no zero extent, found shape {:?}", read.shape)));
    }
    check_operations(rows * cols, rows + cols, d)?;
    match read.coords {
        Coords::F64(c) => power_surface(c, d, rows, cols, rect, method),
        Coords::Exact(c) => power_surface(c, d, rows, cols, rect, method),
    }
}

fn power_triangle<T: WrapTriangle>(
    c: Vec<T>,
    d: usize,
    count: usize,
    n: usize,
    corners: &Bound<'_, PyAny>,
    method: Method,
) -> PyResult<Triangle> {
    let coords = from_bezier_order(&c, d, count, n);
    let surface = call(&COEFFICIENTS, || PowerTriangle::from_coordinates(n, d, coords))?;
    let [c0, c1, c2] = crate::triangle::corners_arg::<T>(corners)?;
    // The library's corners are the images of (1, 0), (0, 1), (0, 0).
    let patch = call(&[], || Ok(restrict_power_triangle(&surface, &[c1, c2, c0], method)))?;
    Ok(Triangle {
        shape: T::wrap_triangle(patch),
    })
}

/// The power-form polynomial p(s, t) = sum_(i + j <= N) c_ij s^i t^j (`coefficients` a
/// `D x (N + 1)(N + 2) / 2` array in the column order of `Triangle` nodes: c_ij in column
/// j (N + 1) - j (j - 1) / 2 + i) restricted to the triangle whose vertices are `corners` (a
/// `3 x 2` array: the (s, t) images of (0, 0), (1, 0), (0, 1)): a `Triangle` of degree N, by
/// `method`.
#[pyfunction(name = "restrict_power_triangle")]
#[pyo3(signature = (coefficients, corners, *, method = "bulk"))]
pub fn restrict_power_triangle_py(
    coefficients: &Bound<'_, PyAny>,
    corners: &Bound<'_, PyAny>,
    method: &str,
) -> PyResult<Triangle> {
    let method = method_arg(method)?;
    let read = read_array(coefficients, "coefficients", 2, "D x (N + 1)(N + 2) / 2")?;
    let (d, count) = (read.shape[0], read.shape[1]);
    let n = triangle_degree(count).filter(|_| d > 0).ok_or_else(|| {
        bad(
            "coefficients",
            "Shape",
            format!("{count} columns is not a triangular number (N + 1)(N + 2) / 2"),
        )
    })?;
    check_operations(count, n, d)?;
    match read.coords {
        Coords::F64(c) => power_triangle(c, d, count, n, corners, method),
        Coords::Exact(c) => power_triangle(c, d, count, n, corners, method),
    }
}

/// Many Bézier curves restricted to one interval: `nodes` an `N x D x (n + 1)` float64 array
/// (curve k's nodes `nodes[k]`, as a `Curve`'s), answer the same shape, curve k over
/// [start, end] reparametrised to [0, 1]. Each coordinate row of each curve is restricted by
/// the library's engine with the dimension fixed at 1 (the batch of planar curves is a batch of
/// 2N one-dimensional ones), bit for bit the answer of `Curve.specialize`; the GIL is released
/// while it runs.
#[pyfunction]
pub fn restrict_curves<'py>(
    py: Python<'py>,
    nodes: &Bound<'py, PyAny>,
    start: f64,
    end: f64,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    for (name, x) in [("start", start), ("end", end)] {
        if !x.is_finite() {
            return Err(bad(name, "NotFinite", format!("expected a finite number, found {x}")));
        }
    }
    let numpy = py.import("numpy")?;
    let array = if let Ok(a) = nodes.cast::<PyArray3<f64>>() {
        if a.is_c_contiguous() {
            a.clone()
        } else {
            numpy.call_method1("ascontiguousarray", (a,))?.cast_into::<PyArray3<f64>>()?
        }
    } else {
        let read = read_array(nodes, "nodes", 3, "N x D x (n + 1)")?;
        let Coords::F64(c) = read.coords else {
            return Err(bad("nodes", "Invalid", "the batch restriction is float64 only; give floats"));
        };
        let shape = (read.shape[0], read.shape[1], read.shape[2]);
        Array3::from_shape_vec(shape, c).expect("the shape read").into_pyarray(py)
    };
    if array.ndim() != 3 {
        return Err(bad("nodes", "Shape", format!("expected a 3-D array N x D x (n + 1), found {} dimension(s)", array.ndim())));
    }
    let shape = array.shape().to_vec();
    let k = shape[2];
    if k == 0 {
        return Err(bad("nodes", "Empty", "expected at least one node per curve"));
    }
    let readonly = array.readonly();
    let input = readonly.as_slice().expect("C-contiguous");
    if let Some(i) = input.iter().position(|x| !x.is_finite()) {
        return Err(bad(
            crate::numbers::index_path("nodes", &shape, i),
            "NotFinite",
            format!("expected a finite number, found {}", input[i]),
        ));
    }
    let output = call_detached(py, &[], || {
        let mut out = vec![0.0; input.len()];
        let mut scratch = Vec::new();
        let (rows, _) = input.as_chunks::<1>();
        let (out_rows, _) = out.as_chunks_mut::<1>();
        for (row, answer) in rows.chunks_exact(k).zip(out_rows.chunks_exact_mut(k)) {
            blossom::engine::subsegment_into::<f64, 1>(row, &start, &end, answer, &mut scratch)?;
        }
        Ok(out)
    })?;
    Ok(Array3::from_shape_vec((shape[0], shape[1], k), output)
        .expect("the input's shape")
        .into_pyarray(py))
}

/// The zeros in [0, 1] of the polynomial sum_i b_i B_i^n(t) (`coefficients` the b_i; floats
/// read exactly, or Fractions), each an Algebraic with its multiplicity, certified.
#[pyfunction(name = "bezier_zeros")]
#[pyo3(signature = (coefficients, *, max_work = None))]
pub fn bezier_zeros_py(
    py: Python<'_>,
    coefficients: &Bound<'_, PyAny>,
    max_work: Option<f64>,
) -> PyResult<Zeros> {
    let read = read_array(coefficients, "coefficients", 1, "the Bernstein coefficients")?;
    let renames = [Rename { rust: "coefficients", python: "coefficients", points: false }];
    let z = match read.coords {
        Coords::F64(c) => {
            if c.len() > 17 {
                let exact = Rational::of_coords(Coords::F64(c.clone()), "coefficients")?;
                check_work(zeros_work(c.len() - 1, bits(&exact)), max_work)?;
            }
            call_detached(py, &renames, || bezier_zeros_f64(&c))?
        }
        Coords::Exact(c) => {
            if c.len() > 17 {
                check_work(zeros_work(c.len() - 1, bits(&c)), max_work)?;
            }
            call_detached(py, &renames, || bezier_zeros(&c))?
        }
    };
    zeros_record(py, &z)
}

/// The bits of the coefficients for the work estimate: the longest numerator plus the longest
/// denominator (exactly the common-denominator size for doubles, whose denominators are powers
/// of two).
fn bits(c: &[Rational]) -> usize {
    let numer = c.iter().map(|r| r.numer().bits()).max().unwrap_or(0);
    let denom = c.iter().map(|r| r.denom().bits()).max().unwrap_or(0);
    (numer + denom) as usize
}
