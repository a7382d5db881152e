//! `bezier_zeros`: the certified zeros of a polynomial in Bernstein form.

use crate::curve::check_work;
use crate::errors::{call_detached, Rename};
use crate::numbers::{read_array, Coords, Num};
use crate::records::{zeros_record, Zeros};
use blossom::budget::bezier_zeros_work;
use blossom::{bezier_zeros, bezier_zeros_f64, Rational};
use pyo3::prelude::*;

/// The zeros in [0, 1] of the polynomial sum_i b_i B_i^n(t) (`coefficients` the b_i; floats
/// read exactly, or Fractions), each an Algebraic with its multiplicity, certified.
#[pyfunction(name = "bezier_zeros")]
#[pyo3(signature = (coefficients, *, max_work = None))]
pub fn bezier_zeros_py(
    py: Python<'_>,
    coefficients: &Bound<'_, PyAny>,
    max_work: Option<&Bound<'_, PyAny>>,
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
                check_work(bezier_zeros_work(&exact), max_work)?;
            }
            call_detached(py, &renames, || bezier_zeros_f64(&c))?
        }
        Coords::Exact(c) => {
            if c.len() > 17 {
                check_work(bezier_zeros_work(&c), max_work)?;
            }
            call_detached(py, &renames, || bezier_zeros(&c))?
        }
    };
    zeros_record(py, &z)
}
