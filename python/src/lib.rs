//! `blossom` for Python: certified Bézier curves for numpy users, with Python bezier's names.
//!
//! A thin PyO3 layer over the `blossom` library: it converts numpy arrays (and
//! `fractions.Fraction`) to the library's shapes and back, releases the GIL for long and batch
//! work, and maps the library's errors (and any panic) to `blossom.Error`, a `ValueError`.
//! Nothing here depends on Python at the library's side: the library never sees this crate.
//!
//! Modules, one job each: `errors` (exceptions, panics), `args` (scalar arguments read so
//! that every bad one is a `blossom.Error`), `numbers` (arrays and Fractions in and out), `curve` (`Curve`), `triangle` (`Triangle`, `CurvedPolygon`), `tensor` (`TensorPatch`),
//! `records` (the certified answers), `power` (the power-form restrictions), `batch`
//! (`restrict_curves`), `zeros` (`bezier_zeros`), `area` (exact signed areas), `length` (arc
//! length by quadrature), `validity` (the exact sign of a triangle's Jacobian), `region`
//! (`CurvedRegion`, `BooleanResult`, `Triangle.intersect`: the library's region booleans),
//! `pen` (`RegionPen`: a fontTools pen recording an outline into a region), `draw` (a result
//! as pen calls: `BooleanResult.draw`).

// The pyclasses' methods are called from Python only.
#![allow(clippy::new_ret_no_self)]

mod area;
mod args;
mod batch;
mod curve;
mod draw;
mod errors;
mod length;
mod numbers;
mod pen;
mod power;
mod records;
mod region;
mod tensor;
mod triangle;
mod validity;
mod zeros;

use pyo3::prelude::*;

/// Panics inside the library-call guard: the one way to check from Python (the tests) that a
/// Rust panic surfaces as `blossom.Error` (kind `Panic`) instead of aborting the interpreter.
#[pyfunction]
fn _panic_for_tests() -> PyResult<()> {
    errors::call(&[], || -> Result<(), ::blossom::Error> {
        panic!("a deliberate panic (blossom._panic_for_tests)")
    })
}

/// The extension module `blossom._blossom` (the package `blossom`, python/blossom/__init__.py,
/// re-exports it).
#[pymodule]
#[pyo3(name = "_blossom")]
fn blossom(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("Error", py.get_type::<errors::Error>())?;
    m.add_class::<curve::Curve>()?;
    m.add_class::<triangle::Triangle>()?;
    m.add_class::<triangle::CurvedPolygon>()?;
    m.add_class::<region::CurvedRegion>()?;
    m.add_class::<region::BooleanResult>()?;
    m.add_class::<pen::RegionPen>()?;
    m.add_class::<tensor::TensorPatchPy>()?;
    m.add_class::<records::Algebraic>()?;
    m.add_class::<records::IntersectionPoint>()?;
    m.add_class::<records::Overlap>()?;
    m.add_class::<records::IntersectionRecords>()?;
    m.add_class::<records::Zero>()?;
    m.add_class::<records::Zeros>()?;
    m.add_class::<records::Extreme>()?;
    m.add_class::<records::Extremes>()?;
    m.add_class::<records::NearestPoint>()?;
    m.add_function(wrap_pyfunction!(power::restrict_power_curve_py, m)?)?;
    m.add_function(wrap_pyfunction!(power::restrict_power_surface_py, m)?)?;
    m.add_function(wrap_pyfunction!(power::restrict_power_triangle_py, m)?)?;
    m.add_function(wrap_pyfunction!(batch::restrict_curves, m)?)?;
    m.add_function(wrap_pyfunction!(zeros::bezier_zeros_py, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_tests, m)?)?;
    m.add("DEFAULT_MAX_WORK", curve::DEFAULT_MAX_WORK)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // Every name above: the package re-exports the extension with `import *`, which takes
    // `__all__` (and would otherwise drop `__version__` and `_panic_for_tests`).
    let names: Vec<String> = m
        .dict()
        .keys()
        .iter()
        .map(|k| k.extract::<String>())
        .collect::<PyResult<_>>()?;
    let all: Vec<String> = names
        .into_iter()
        .filter(|n| !n.starts_with("__") || n == "__version__")
        .collect();
    m.add("__all__", all)?;
    Ok(())
}
