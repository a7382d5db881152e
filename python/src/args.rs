//! Scalar arguments read by the binding itself, so that every bad one raises `blossom.Error`
//! naming it: PyO3's own extraction of a typed parameter (`usize`, `f64`, `&str`, `bool`, a
//! pyclass) raises `TypeError` or `OverflowError` with PyO3's wording instead. The methods
//! take such arguments as Python objects and read them here.

use crate::errors::bad;
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyInt};

/// The name of the Python type of `obj`, for messages.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".to_string())
}

/// A non-negative integer argument (a degree): a Python int or anything with `__index__`
/// (numpy integers), not a bool or a float. Negative: kind `Degree`; beyond `usize`:
/// `TooLarge`; any other type: `Invalid`.
pub fn degree_arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<usize> {
    if obj.is_instance_of::<PyBool>() {
        return Err(bad(path, "Invalid", "expected an integer, found a bool"));
    }
    let i: BigInt = if obj.is_instance_of::<PyInt>() {
        obj.extract()?
    } else {
        obj.call_method0("__index__")
            .and_then(|i| i.extract())
            .map_err(|_| {
                bad(
                    path,
                    "Invalid",
                    format!("expected an integer, found {}", type_name(obj)),
                )
            })?
    };
    if i.is_negative() {
        return Err(bad(
            path,
            "Degree",
            format!("expected a non-negative integer, found {i}"),
        ));
    }
    i.to_usize().ok_or_else(|| {
        bad(
            path,
            "TooLarge",
            format!("{i} is beyond any degree a curve can have"),
        )
    })
}

/// A string argument, `default` when not given (None).
pub fn str_arg(obj: Option<&Bound<'_, PyAny>>, path: &str, default: &str) -> PyResult<String> {
    match obj {
        None => Ok(default.to_string()),
        Some(o) => o.extract::<String>().map_err(|_| {
            bad(
                path,
                "Invalid",
                format!("expected a string, found {}", type_name(o)),
            )
        }),
    }
}

/// A flag argument: True or False (or a numpy bool), `default` when not given (None).
pub fn bool_arg(obj: Option<&Bound<'_, PyAny>>, path: &str, default: bool) -> PyResult<bool> {
    match obj {
        None => Ok(default),
        Some(o) => o.extract::<bool>().map_err(|_| {
            bad(
                path,
                "Invalid",
                format!("expected True or False, found {}", type_name(o)),
            )
        }),
    }
}

/// An optional flag argument: None, True or False.
pub fn optional_bool_arg(obj: Option<&Bound<'_, PyAny>>, path: &str) -> PyResult<Option<bool>> {
    obj.map(|o| bool_arg(Some(o), path, false)).transpose()
}

/// An argument that must be an instance of the pyclass `T` (`what` names it in the message).
pub fn class_arg<'a, 'py, T: pyo3::PyTypeInfo>(
    obj: &'a Bound<'py, PyAny>,
    path: &str,
    what: &str,
) -> PyResult<&'a Bound<'py, T>> {
    obj.cast::<T>().map_err(|_| {
        bad(
            path,
            "Invalid",
            format!("expected {what}, found {}", type_name(obj)),
        )
    })
}
