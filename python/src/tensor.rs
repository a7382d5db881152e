//! `TensorPatch`: a tensor-product Bézier patch (nodes `D x (n + 1) x (m + 1)`) over the
//! library's `TensorPatch`, in float64 or exactly.

use crate::errors::{bad, call, Rename};
use crate::numbers::{read_array, Coords, Num};
use blossom::{Rational, TensorPatch};
use pyo3::prelude::*;

/// A `D x r x c` array read in C order as the library's point-major grid (point (i, j) at
/// i c + j).
pub fn grid_points<T: Clone>(c: &[T], d: usize, rows: usize, cols: usize) -> Vec<T> {
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

pub fn rect_arg<T: Num>(obj: &Bound<'_, PyAny>) -> PyResult<[T; 4]> {
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

pub fn tensor_of<T: WrapTensor>(p: TensorPatch<T>) -> TensorPatchPy {
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
