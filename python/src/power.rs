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
    restrict_power_triangle, zeros_work, Method, PowerCurve, PowerSurface, PowerTriangle, Rational,
    RestrictionMap, TensorPatch,
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
    let read = read_array(
        coefficients,
        "coefficients",
        2,
        "D x (n + 1), column i the coefficient of u^i",
    )?;
    let (d, k) = (read.shape[0], read.shape[1]);
    if d == 0 || k == 0 {
        return Err(bad(
            "coefficients",
            "Empty",
            "expected at least one dimension and one coefficient",
        ));
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
            format!(
                "expected 4 values (s_start, s_end, t_start, t_end), found {}",
                v.len()
            ),
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
            return Err(bad(
                "nodes",
                "Empty",
                format!("expected no zero extent, found shape {:?}", read.shape),
            ));
        }
        let renames = [Rename {
            rust: "coordinates",
            python: "nodes",
            points: false,
        }];
        Ok(match read.coords {
            Coords::F64(c) => tensor_of(call(&renames, || {
                TensorPatch::from_coordinates(
                    (rows - 1, cols - 1),
                    d,
                    grid_points(&c, d, rows, cols),
                )
            })?),
            Coords::Exact(c) => tensor_of(call(&renames, || {
                TensorPatch::from_coordinates(
                    (rows - 1, cols - 1),
                    d,
                    grid_points(&c, d, rows, cols),
                )
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
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        s: &Bound<'py, PyAny>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        on_tensor!(&self.shape, p => {
            let (s, t) = (Num::arg(s, "s")?, Num::arg(t, "t")?);
            let q = call(&[], || Ok(p.eval(&s, &t)))?;
            Num::columns(py, p.dim(), 1, q)
        })
    }

    /// The patch over `rect = (s_start, s_end, t_start, t_end)` reparametrised to [0, 1]^2.
    fn specialize(&self, rect: &Bound<'_, PyAny>) -> PyResult<TensorPatchPy> {
        on_tensor!(&self.shape, p => {
            let r = rect_arg(rect)?;
            Ok(tensor_of(call(&[], || Ok(p.restrict(&r)))?))
        })
    }

    fn __repr__(&self) -> String {
        let (n, m) = self.degree();
        format!(
            "<TensorPatch (degree=({n}, {m}), dimension={})>",
            self.dimension()
        )
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
        return Err(bad(
            "coefficients",
            "Empty",
            format!("expected no zero extent, found shape {:?}", read.shape),
        ));
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
    let surface = call(&COEFFICIENTS, || {
        PowerTriangle::from_coordinates(n, d, coords)
    })?;
    let [c0, c1, c2] = crate::triangle::corners_arg::<T>(corners)?;
    // The library's corners are the images of (1, 0), (0, 1), (0, 0).
    let patch = call(&[], || {
        Ok(restrict_power_triangle(&surface, &[c1, c2, c0], method))
    })?;
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
/// [start, end] reparametrised to [0, 1], bit for bit `Curve.specialize`'s answer, in the
/// layout of `nodes` (or written into `out`, an array of that shape and layout). The library's
/// batch call (`RestrictionMap::restrict_arrays`) does the work where the numbers lie, with the
/// GIL released: on `[[f64; D]; n + 1]` curves when the array's memory holds each curve point
/// after point (strides (8 D (n + 1), 8, 8 D): the `(N, D, n + 1)` view of an `(N, n + 1, D)`
/// array, the layout of the Rust call), else on the N D coordinate rows as one-dimensional
/// curves (C order). Any other layout is first copied to C order.
#[pyfunction]
#[pyo3(signature = (nodes, start, end, *, out = None))]
pub fn restrict_curves<'py>(
    py: Python<'py>,
    nodes: &Bound<'py, PyAny>,
    start: f64,
    end: f64,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    for (name, x) in [("start", start), ("end", end)] {
        if !x.is_finite() {
            return Err(bad(
                name,
                "NotFinite",
                format!("expected a finite number, found {x}"),
            ));
        }
    }
    let array = batch_array(py, nodes)?;
    let shape = array.shape().to_vec();
    let (n, d, k) = (shape[0], shape[1], shape[2]);
    if d == 0 || k == 0 {
        return Err(bad(
            "nodes",
            "Empty",
            format!(
                "expected at least one coordinate and one node per curve, found shape {shape:?}"
            ),
        ));
    }
    let point_major = is_point_major(&array);
    // The memory as it is when it holds the curves point after point or in C order; any other
    // layout is copied to C order first.
    let array = if point_major || array.is_c_contiguous() {
        array
    } else {
        py.import("numpy")?
            .call_method1("ascontiguousarray", (&array,))?
            .cast_into::<PyArray3<f64>>()?
    };
    let answer = match out {
        Some(o) => {
            let o = o.cast::<PyArray3<f64>>().map_err(|_| {
                bad(
                    "out",
                    "Invalid",
                    "expected a float64 array of three dimensions",
                )
            })?;
            let same_layout = if point_major {
                is_point_major(o)
            } else {
                o.is_c_contiguous()
            };
            if o.shape() != shape.as_slice() || !same_layout {
                return Err(bad(
                    "out",
                    "Shape",
                    format!(
                        "expected an array of shape {shape:?} laid out as nodes ({})",
                        if point_major {
                            "point after point"
                        } else {
                            "C order"
                        }
                    ),
                ));
            }
            o.clone()
        }
        None if point_major => {
            // Allocated (n, k, d) in C order, answered as its (n, d, k) view.
            let buffer = PyArray3::<f64>::zeros(py, [n, k, d], false);
            buffer
                .call_method1("transpose", ((0, 2, 1),))?
                .cast_into::<PyArray3<f64>>()?
        }
        None => PyArray3::<f64>::zeros(py, [n, d, k], false),
    };
    let readonly = array.readonly();
    let input = readonly.as_array();
    let input = input.as_slice_memory_order().expect("contiguous");
    if let Some(i) = first_not_finite(input) {
        let logical = if point_major {
            (i / (d * k)) * d * k + (i % d) * k + (i % (d * k)) / d
        } else {
            i
        };
        return Err(bad(
            crate::numbers::index_path("nodes", &shape, logical),
            "NotFinite",
            format!("expected a finite number, found {}", input[i]),
        ));
    }
    let mut writable = answer.try_readwrite().map_err(|_| {
        bad(
            "out",
            "Invalid",
            "expected a writable array not in use elsewhere",
        )
    })?;
    let mut output = writable.as_array_mut();
    let output = output.as_slice_memory_order_mut().expect("contiguous");
    call_detached(py, &[], || {
        restrict_batch(input, output, d, k, start, end, point_major)
    })?;
    drop(writable);
    Ok(answer.into_any())
}

/// Whether the array's memory holds each curve's points one after the other (strides
/// (8 D (n + 1), 8, 8 D) of an `N x D x (n + 1)` array).
fn is_point_major(a: &Bound<'_, PyArray3<f64>>) -> bool {
    let shape = a.shape();
    let item = std::mem::size_of::<f64>() as isize;
    let (d, k) = (shape[1] as isize, shape[2] as isize);
    shape[0] > 0 && shape[1] > 1 && a.strides() == [item * d * k, item, item * d]
}

/// The index of the first NaN or infinity. The common case, all finite, is one pass the
/// compiler vectorises: x - x is 0 for a finite x and NaN otherwise, summed in eight lanes.
fn first_not_finite(v: &[f64]) -> Option<usize> {
    let mut lanes = [0.0f64; 8];
    let (blocks, rest) = v.as_chunks::<8>();
    for block in blocks {
        for (lane, x) in lanes.iter_mut().zip(block) {
            // x - x: zero exactly when x is finite (the point of the expression).
            #[allow(clippy::eq_op)]
            let zero_if_finite = x - x;
            *lane += zero_if_finite;
        }
    }
    let finite = lanes.iter().sum::<f64>() == 0.0 && rest.iter().all(|x| x.is_finite());
    if finite {
        None
    } else {
        v.iter().position(|x| !x.is_finite())
    }
}

/// The `nodes` argument of `restrict_curves` as a float64 array of three dimensions.
fn batch_array<'py>(
    py: Python<'py>,
    nodes: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    if let Ok(a) = nodes.cast::<PyArray3<f64>>() {
        return Ok(a.clone());
    }
    let read = read_array(nodes, "nodes", 3, "N x D x (n + 1)")?;
    let Coords::F64(c) = read.coords else {
        return Err(bad(
            "nodes",
            "Invalid",
            "the batch restriction is float64 only; give floats",
        ));
    };
    let shape = (read.shape[0], read.shape[1], read.shape[2]);
    Ok(Array3::from_shape_vec(shape, c)
        .expect("the shape read")
        .into_pyarray(py))
}

/// Restricts every curve of `input` (point-major curves, or C order `N x D x K`) into `output`
/// in the same layout, by the library's `RestrictionMap::restrict_arrays`: point-major curves
/// as they are (`[[f64; D]; K]`, D = 2, 3), C order as N D one-dimensional curves (each
/// coordinate row; de Casteljau's steps act on each coordinate alone, so the answer is the
/// same bit for bit). Other sizes go through the engine row by row.
fn restrict_batch(
    input: &[f64],
    output: &mut [f64],
    d: usize,
    k: usize,
    start: f64,
    end: f64,
    point_major: bool,
) -> Result<(), blossom::Error> {
    if !point_major {
        return restrict_rows(input, output, k, start, end);
    }
    macro_rules! fixed {
        ($(($dd:literal, $kk:literal)),*) => {
            match (d, k) {
                $(($dd, $kk) => return restrict_points::<$kk, $dd>(input, output, start, end),)*
                _ => {}
            }
        };
    }
    fixed!(
        (2, 2),
        (2, 3),
        (2, 4),
        (2, 5),
        (2, 6),
        (2, 7),
        (2, 8),
        (2, 9),
        (3, 2),
        (3, 3),
        (3, 4),
        (3, 5),
        (3, 6),
        (3, 7),
        (3, 8),
        (3, 9)
    );
    let c_order = transpose_curves(input, k, d);
    let mut answer = vec![0.0; c_order.len()];
    restrict_rows(&c_order, &mut answer, k, start, end)?;
    output.copy_from_slice(&transpose_curves(&answer, d, k));
    Ok(())
}

/// Restricts every run of `k` numbers of `input` as a one-dimensional curve.
fn restrict_rows(
    input: &[f64],
    output: &mut [f64],
    k: usize,
    start: f64,
    end: f64,
) -> Result<(), blossom::Error> {
    macro_rules! fixed {
        ($($kk:literal),*) => {
            match k {
                $($kk => return restrict_points::<$kk, 1>(input, output, start, end),)*
                _ => {}
            }
        };
    }
    fixed!(2, 3, 4, 5, 6, 7, 8, 9);
    let (rows_in, _) = input.as_chunks::<1>();
    let (rows_out, _) = output.as_chunks_mut::<1>();
    let mut scratch = Vec::new();
    for (row, answer) in rows_in.chunks_exact(k).zip(rows_out.chunks_exact_mut(k)) {
        blossom::engine::subsegment_into::<f64, 1>(row, &start, &end, answer, &mut scratch)?;
    }
    Ok(())
}

/// Each curve's `a x b` block of `v` transposed to `b x a`.
fn transpose_curves(v: &[f64], a: usize, b: usize) -> Vec<f64> {
    let mut out = vec![0.0; v.len()];
    for (curve, t) in v.chunks_exact(a * b).zip(out.chunks_exact_mut(a * b)) {
        for i in 0..a {
            for j in 0..b {
                t[j * a + i] = curve[i * b + j];
            }
        }
    }
    out
}

/// Curves of `K` points of dimension `D`, point after point, restricted by the library's
/// `restrict_arrays` where they lie.
fn restrict_points<const K: usize, const D: usize>(
    input: &[f64],
    output: &mut [f64],
    start: f64,
    end: f64,
) -> Result<(), blossom::Error> {
    let map = RestrictionMap::curve(K - 1, start, end)?;
    let (points_in, _) = input.as_chunks::<D>();
    let (curves_in, _) = points_in.as_chunks::<K>();
    let (points_out, _) = output.as_chunks_mut::<D>();
    let (curves_out, _) = points_out.as_chunks_mut::<K>();
    map.restrict_arrays(curves_in, curves_out)
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
    let max_work = crate::curve::max_work_arg(max_work)?;
    let read = read_array(
        coefficients,
        "coefficients",
        1,
        "the Bernstein coefficients",
    )?;
    let renames = [Rename {
        rust: "coefficients",
        python: "coefficients",
        points: false,
    }];
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
