//! The papers' operation: power-form curves, tensor surfaces and triangles restricted to an
//! interval, rectangle or triangle by any of the library's methods (`restrict_power_curve`,
//! `restrict_power_surface`, `restrict_power_triangle`).

use crate::curve::{Curve, WrapCurve};
use crate::errors::{bad, call, Rename};
use crate::numbers::{read_array, Coords, Num};
use crate::tensor::{grid_points, rect_arg, tensor_of, TensorPatchPy, WrapTensor};
use crate::triangle::{from_bezier_order, triangle_degree, Triangle, WrapTriangle};
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_triangle, Method, PowerCurve,
    PowerSurface, PowerTriangle,
};
use pyo3::prelude::*;

/// The most work a power-form restriction may take: a coarse operation count (points^2 times
/// the degree's square times the dimension, which bounds every method's count up to a small
/// factor) over this is refused.
pub const MAX_RESTRICTION_OPERATIONS: f64 = 1e10;

fn method_arg(name: &str) -> PyResult<Method> {
    let named: Vec<(&str, Method)> = Method::ALL.into_iter().map(|m| (m.name(), m)).collect();
    crate::errors::name_arg("method", name, &named)
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
#[pyo3(signature = (coefficients, start, end, *, method = None))]
pub fn restrict_power_curve_py(
    coefficients: &Bound<'_, PyAny>,
    start: &Bound<'_, PyAny>,
    end: &Bound<'_, PyAny>,
    method: Option<&Bound<'_, PyAny>>,
) -> PyResult<Curve> {
    let method = method_arg(&crate::args::str_arg(method, "method", "bulk")?)?;
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
#[pyo3(signature = (coefficients, rect, *, method = None))]
pub fn restrict_power_surface_py(
    coefficients: &Bound<'_, PyAny>,
    rect: &Bound<'_, PyAny>,
    method: Option<&Bound<'_, PyAny>>,
) -> PyResult<TensorPatchPy> {
    let method = method_arg(&crate::args::str_arg(method, "method", "bulk")?)?;
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
    Ok(Triangle::of_shape(T::wrap_triangle(patch)))
}

/// The power-form polynomial p(s, t) = sum_(i + j <= N) c_ij s^i t^j (`coefficients` a
/// `D x (N + 1)(N + 2) / 2` array in the column order of `Triangle` nodes: c_ij in column
/// j (N + 1) - j (j - 1) / 2 + i) restricted to the triangle whose vertices are `corners` (a
/// `3 x 2` array: the (s, t) images of (0, 0), (1, 0), (0, 1)): a `Triangle` of degree N, by
/// `method`.
#[pyfunction(name = "restrict_power_triangle")]
#[pyo3(signature = (coefficients, corners, *, method = None))]
pub fn restrict_power_triangle_py(
    coefficients: &Bound<'_, PyAny>,
    corners: &Bound<'_, PyAny>,
    method: Option<&Bound<'_, PyAny>>,
) -> PyResult<Triangle> {
    let method = method_arg(&crate::args::str_arg(method, "method", "bulk")?)?;
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
