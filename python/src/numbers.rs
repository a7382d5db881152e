//! Numbers in and out: numpy arrays of float64 (any memory order) and arrays or nested
//! sequences holding `fractions.Fraction`, read into the library's `f64` or exact
//! `Rational` coordinates, and answers written back as float64 arrays or object arrays of
//! `Fraction`.
//!
//! Reading follows Python bezier's `_lossless_to_float`: an integer array is taken as float64
//! only when every entry converts without rounding. A `Fraction` anywhere makes the whole
//! input exact (its floats are then read as the exact values of the doubles). NaN and
//! infinities are refused, naming the entry (`nodes[1, 3]`).

use crate::errors::bad;
use blossom::Rational;
use num_bigint::BigInt;
use num_rational::Ratio;
use num_traits::{ToPrimitive, Zero};
use numpy::ndarray::{Array2, ShapeBuilder};
use numpy::{IntoPyArray, PyArray2, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyFloat, PyInt, PyList, PyType};

/// Coordinates of one array, in the order the caller asked for.
#[derive(Clone, Debug)]
pub enum Coords {
    F64(Vec<f64>),
    Exact(Vec<Rational>),
}

/// An array read from Python: its shape and its entries in C (row-major) order.
pub struct Read {
    pub shape: Vec<usize>,
    pub coords: Coords,
}

static FRACTION: PyOnceLock<Py<PyType>> = PyOnceLock::new();

fn fraction_type(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    FRACTION.import(py, "fractions", "Fraction")
}

/// The numpy index of entry `flat` of an array of `shape` in C order, as `arg[i, j]`.
pub fn index_path(arg: &str, shape: &[usize], mut flat: usize) -> String {
    let mut index = vec![0; shape.len()];
    for (k, &n) in shape.iter().enumerate().rev() {
        if n > 0 {
            index[k] = flat % n;
            flat /= n;
        }
    }
    let parts: Vec<String> = index.iter().map(|i| i.to_string()).collect();
    format!("{arg}[{}]", parts.join(", "))
}

fn shape_error(arg: &str, ndim: usize, found: usize, what: &str) -> PyErr {
    bad(
        arg,
        "Shape",
        format!("expected a {ndim}-D array ({what}), found {found} dimension(s)"),
    )
}

/// The exact value of a finite double.
pub fn exact_of_f64(x: f64, path: &str) -> PyResult<Rational> {
    Ratio::from_float(x).ok_or_else(|| not_finite(path, x))
}

fn not_finite(path: &str, x: f64) -> PyErr {
    bad(
        path,
        "NotFinite",
        format!("expected a finite number, found {x}"),
    )
}

/// One entry of an object array or a scalar argument.
enum Entry {
    Float(f64),
    Int(BigInt),
    Fraction(Rational),
}

fn entry(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Entry> {
    let py = obj.py();
    if obj.is_instance(fraction_type(py)?.as_any())? {
        return Ok(Entry::Fraction(obj.extract::<Ratio<BigInt>>()?));
    }
    if obj.is_instance_of::<PyFloat>() {
        return Ok(Entry::Float(obj.extract::<f64>()?));
    }
    if obj.is_instance_of::<pyo3::types::PyBool>() {
        return Err(bad(path, "Invalid", "expected a number, found a bool"));
    }
    if obj.is_instance_of::<PyInt>() {
        return Ok(Entry::Int(obj.extract::<BigInt>()?));
    }
    // numpy scalars: integers through __index__; floating types of at most 8 bytes through
    // __float__, exactly (a longdouble may not fit a double and is refused).
    if let Ok(i) = obj.extract::<BigInt>() {
        return Ok(Entry::Int(i));
    }
    let floating = py.import("numpy")?.getattr("floating")?;
    if obj.is_instance(&floating)? && obj.getattr("itemsize")?.extract::<usize>()? <= 8 {
        return Ok(Entry::Float(obj.extract::<f64>()?));
    }
    let type_name = obj.get_type().name()?.to_string();
    Err(bad(
        path,
        "Invalid",
        format!("expected a float, an int or a fractions.Fraction, found {type_name}"),
    ))
}

/// A double from an int, when it converts without rounding.
fn int_as_f64(i: &BigInt, path: &str) -> PyResult<f64> {
    let x = i.to_f64().unwrap_or(f64::INFINITY);
    if x.is_finite() && Ratio::from_float(x) == Some(Ratio::from_integer(i.clone())) {
        Ok(x)
    } else {
        Err(bad(
            path,
            "Invalid",
            format!("the integer {i} is not a double; give it as a fractions.Fraction to read it exactly"),
        ))
    }
}

/// Reads an array of `ndim` dimensions (`what` describes it for errors) from a numpy array or
/// nested sequences.
pub fn read_array(obj: &Bound<'_, PyAny>, arg: &str, ndim: usize, what: &str) -> PyResult<Read> {
    if let Ok(array) = obj.cast::<PyArrayDyn<f64>>() {
        return read_f64_array(array, arg, ndim, what);
    }
    let py = obj.py();
    let numpy = py.import("numpy")?;
    let array = numpy
        .call_method1("asarray", (obj,))
        .map_err(|e| bad(arg, "Invalid", format!("not an array of numbers: {e}")))?;
    let found: usize = array.getattr("ndim")?.extract()?;
    if found != ndim {
        return Err(shape_error(arg, ndim, found, what));
    }
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    match kind.as_str() {
        "f" | "i" | "u" => {
            // Converted and back, compared in the original type: numpy's own comparison of an
            // integer with a float array would compare them as floats (2^60 + 1 == 2^60).
            let converted = array.call_method1("astype", ("float64",))?;
            let back = converted.call_method1("astype", (array.getattr("dtype")?,))?;
            let equal: bool = numpy
                .call_method1("array_equal", (&array, &back))?
                .extract()?;
            if !equal {
                return Err(bad(
                    arg,
                    "Invalid",
                    "cannot be converted to float64 without rounding; give fractions.Fraction \
                     entries to read it exactly",
                ));
            }
            read_f64_array(converted.cast::<PyArrayDyn<f64>>()?, arg, ndim, what)
        }
        "O" => read_object_array(&array, arg),
        _ => Err(bad(
            arg,
            "Invalid",
            format!("expected real numbers, found an array of dtype kind '{kind}'"),
        )),
    }
}

fn read_f64_array(
    array: &Bound<'_, PyArrayDyn<f64>>,
    arg: &str,
    ndim: usize,
    what: &str,
) -> PyResult<Read> {
    if array.ndim() != ndim {
        return Err(shape_error(arg, ndim, array.ndim(), what));
    }
    let readonly = array.readonly();
    let view = readonly.as_array();
    let shape = view.shape().to_vec();
    let coords: Vec<f64> = match view.as_slice() {
        Some(s) => s.to_vec(),
        None => view.iter().copied().collect(),
    };
    if let Some(k) = coords.iter().position(|x| !x.is_finite()) {
        return Err(not_finite(&index_path(arg, &shape, k), coords[k]));
    }
    Ok(Read {
        shape,
        coords: Coords::F64(coords),
    })
}

fn read_object_array(array: &Bound<'_, PyAny>, arg: &str) -> PyResult<Read> {
    let shape: Vec<usize> = array.getattr("shape")?.extract()?;
    let flat = array.call_method0("ravel")?;
    let mut entries = Vec::new();
    for (k, item) in flat.try_iter()?.enumerate() {
        entries.push(entry(&item?, &index_path(arg, &shape, k))?);
    }
    let exact = entries.iter().any(|e| matches!(e, Entry::Fraction(_)));
    let coords = if exact {
        let mut out = Vec::with_capacity(entries.len());
        for (k, e) in entries.into_iter().enumerate() {
            out.push(match e {
                Entry::Fraction(r) => r,
                Entry::Int(i) => Ratio::from_integer(i),
                Entry::Float(x) => exact_of_f64(x, &index_path(arg, &shape, k))?,
            });
        }
        Coords::Exact(out)
    } else {
        let mut out = Vec::with_capacity(entries.len());
        for (k, e) in entries.into_iter().enumerate() {
            let path = index_path(arg, &shape, k);
            let x = match e {
                Entry::Float(x) => x,
                Entry::Int(i) => int_as_f64(&i, &path)?,
                Entry::Fraction(_) => unreachable!("no fraction in a float input"),
            };
            if !x.is_finite() {
                return Err(not_finite(&path, x));
            }
            out.push(x);
        }
        Coords::F64(out)
    };
    Ok(Read { shape, coords })
}

/// Permutes entries read in C order of `shape` = [d, n] into point-major order (point after
/// point, `d` coordinates each): the layout of the library's shapes.
pub fn points_of_columns<T: Clone>(c: &[T], d: usize, n: usize) -> Vec<T> {
    let mut out = Vec::with_capacity(c.len());
    for p in 0..n {
        for x in 0..d {
            out.push(c[x * n + p].clone());
        }
    }
    out
}

/// A finite double argument.
pub fn f64_arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<f64> {
    let x: f64 = obj.extract().map_err(|_| {
        if obj.is_instance_of::<PyInt>() {
            // float(i) overflows (OverflowError): an int beyond the doubles.
            return bad(
                path,
                "NotFinite",
                "expected a finite number, found an integer beyond the range of doubles",
            );
        }
        bad(
            path,
            "Invalid",
            format!(
                "expected a number, found {}",
                obj.get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_default()
            ),
        )
    })?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(not_finite(path, x))
    }
}

/// An exact argument: a Fraction or an int as it is, a float as the exact value of the double.
pub fn exact_arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Rational> {
    match entry(obj, path)? {
        Entry::Fraction(r) => Ok(r),
        Entry::Int(i) => Ok(Ratio::from_integer(i)),
        Entry::Float(x) => exact_of_f64(x, path),
    }
}

/// A 1-D float64 sequence argument (parameters).
pub fn f64_values(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<f64>> {
    match read_array(obj, arg, 1, "one value per entry")?.coords {
        Coords::F64(v) => Ok(v),
        Coords::Exact(v) => Ok(v.iter().map(blossom::rational_to_f64).collect()),
    }
}

/// A 1-D sequence argument read exactly.
pub fn exact_values(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<Rational>> {
    match read_array(obj, arg, 1, "one value per entry")?.coords {
        Coords::Exact(v) => Ok(v),
        Coords::F64(v) => v
            .iter()
            .enumerate()
            .map(|(k, &x)| exact_of_f64(x, &format!("{arg}[{k}]")))
            .collect(),
    }
}

/// The index of the first NaN or infinity. The common case, all finite, is one pass the
/// compiler vectorises: x - x is 0 for a finite x and NaN otherwise, summed in eight lanes.
pub fn first_not_finite(v: &[f64]) -> Option<usize> {
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

/// A `d x n` float64 array (Fortran order, as bezier's nodes) from point-major coordinates.
pub fn f64_columns(
    py: Python<'_>,
    d: usize,
    n: usize,
    coords: Vec<f64>,
) -> Bound<'_, PyArray2<f64>> {
    let zeroed: Vec<f64> = coords.into_iter().map(positive_zero).collect();
    Array2::from_shape_vec((d, n).f(), zeroed)
        .expect("d * n coordinates")
        .into_pyarray(py)
}

/// `x`, with -0.0 made +0.0 (the package's convention for every answer).
pub fn positive_zero(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

/// A `Fraction`.
pub fn fraction<'py>(py: Python<'py>, r: &Rational) -> PyResult<Bound<'py, PyAny>> {
    r.into_pyobject(py)
}

/// A `d x n` object array of `Fraction` from point-major coordinates.
pub fn exact_columns<'py>(
    py: Python<'py>,
    d: usize,
    n: usize,
    coords: &[Rational],
) -> PyResult<Bound<'py, PyAny>> {
    let rows = PyList::empty(py);
    for x in 0..d {
        let row = PyList::empty(py);
        for p in 0..n {
            row.append(fraction(py, &coords[p * d + x])?)?;
        }
        rows.append(row)?;
    }
    object_array(py, rows.as_any())
}

/// `numpy.array(nested, dtype=object)`.
pub fn object_array<'py>(
    py: Python<'py>,
    nested: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let kwargs = pyo3::types::PyDict::new(py);
    kwargs.set_item("dtype", "object")?;
    py.import("numpy")?
        .call_method("array", (nested,), Some(&kwargs))
}

/// The exact values `v` rounded to the nearest doubles (+0.0 for zero).
pub fn rounded(v: &[Rational]) -> Vec<f64> {
    v.iter()
        .map(|r| {
            if r.is_zero() {
                0.0
            } else {
                blossom::rational_to_f64(r)
            }
        })
        .collect()
}

/// The two number types of the package: `f64` (float64 arrays in and out) and the library's
/// exact `Rational` (Fractions in and out). Every shape method is written once over it.
pub trait Num: blossom::Ring + Send + Sync + 'static {
    /// A scalar argument.
    fn arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Self>;
    /// A 1-D sequence argument.
    fn values(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<Self>>;
    /// Coordinates read by [`read_array`] in this type (floats read exactly for `Rational`).
    fn of_coords(c: Coords, arg: &str) -> PyResult<Vec<Self>>;
    /// A `d x n` array from point-major coordinates.
    fn columns<'py>(
        py: Python<'py>,
        d: usize,
        n: usize,
        coords: Vec<Self>,
    ) -> PyResult<Bound<'py, PyAny>>;
    /// The nearest double.
    fn to_f64(&self) -> f64;
    /// The number `k / 2^e` exactly (`k` small).
    fn dyadic(k: i64, e: u32) -> Self;
}

impl Num for f64 {
    fn arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Self> {
        f64_arg(obj, path)
    }
    fn values(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<Self>> {
        f64_values(obj, arg)
    }
    fn of_coords(c: Coords, _arg: &str) -> PyResult<Vec<Self>> {
        Ok(match c {
            Coords::F64(v) => v,
            Coords::Exact(v) => rounded(&v),
        })
    }
    fn columns<'py>(
        py: Python<'py>,
        d: usize,
        n: usize,
        coords: Vec<Self>,
    ) -> PyResult<Bound<'py, PyAny>> {
        Ok(f64_columns(py, d, n, coords).into_any())
    }
    fn to_f64(&self) -> f64 {
        positive_zero(*self)
    }
    fn dyadic(k: i64, e: u32) -> Self {
        k as f64 / (1u64 << e) as f64
    }
}

impl Num for Rational {
    fn arg(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Self> {
        exact_arg(obj, path)
    }
    fn values(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<Self>> {
        exact_values(obj, arg)
    }
    fn of_coords(c: Coords, arg: &str) -> PyResult<Vec<Self>> {
        match c {
            Coords::Exact(v) => Ok(v),
            Coords::F64(v) => v.iter().map(|&x| exact_of_f64(x, arg)).collect(),
        }
    }
    fn columns<'py>(
        py: Python<'py>,
        d: usize,
        n: usize,
        coords: Vec<Self>,
    ) -> PyResult<Bound<'py, PyAny>> {
        exact_columns(py, d, n, &coords)
    }
    fn to_f64(&self) -> f64 {
        rounded(std::slice::from_ref(self))[0]
    }
    fn dyadic(k: i64, e: u32) -> Self {
        Ratio::new(BigInt::from(k), BigInt::from(1u64 << e))
    }
}
