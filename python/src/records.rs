//! The certified answers as Python objects: `Algebraic` (a real algebraic number: its
//! correctly rounded `value`, its `exact` Fraction when rational, its `polynomial` and
//! isolating `interval`), and the records of intersections, zeros, extremes and nearest
//! points built from it. Every field is decided exactly by the library; only `value` rounds
//! (to the nearest double, ties to even, +0.0 for zero).

use crate::numbers::{fraction, positive_zero};
use blossom::{AlgebraicReal, Intersections};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// A real algebraic number, exactly: the root of `polynomial` (square-free, primitive, integer
/// coefficients in ascending powers) isolated by `interval` (a pair of Fractions, equal exactly
/// when the number is rational, then also `exact`). `value` is the nearest double.
#[pyclass(module = "blossom", frozen)]
pub struct Algebraic {
    pub inner: AlgebraicReal,
}

#[pymethods]
impl Algebraic {
    /// The nearest double (ties to even), +0.0 for zero.
    #[getter]
    fn value(&self) -> f64 {
        positive_zero(self.inner.to_f64())
    }

    /// The number as a Fraction when it is rational, else None.
    #[getter]
    fn exact<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.inner.exact().map(|r| fraction(py, r)).transpose()
    }

    /// Integer coefficients, ascending powers, of the square-free polynomial it is a root of.
    #[getter]
    fn polynomial<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(self
            .inner
            .polynomial()
            .to_vec()
            .into_pyobject(py)?
            .into_any())
    }

    /// The isolating interval (lo, hi), two Fractions: the number is the one root of
    /// `polynomial` in [lo, hi].
    #[getter]
    fn interval<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let (lo, hi) = self.inner.interval();
        PyTuple::new(py, [fraction(py, lo)?, fraction(py, hi)?])
    }

    fn __float__(&self) -> f64 {
        self.value()
    }

    fn __repr__(&self) -> String {
        match self.inner.exact() {
            Some(r) => format!("Algebraic({r})"),
            None => format!(
                "Algebraic({:?}, polynomial={:?})",
                self.value(),
                self.inner.polynomial()
            ),
        }
    }
}

fn algebraic(py: Python<'_>, a: &AlgebraicReal) -> PyResult<Py<Algebraic>> {
    Py::new(py, Algebraic { inner: a.clone() })
}

/// One isolated intersection P(s) = Q(t): `s`, `t` (Algebraic), `tangent` (P'(s) and Q'(t)
/// parallel, decided exactly), `point` (the common point, each coordinate correctly rounded).
#[pyclass(module = "blossom", frozen, get_all)]
pub struct IntersectionPoint {
    s: Py<Algebraic>,
    t: Py<Algebraic>,
    tangent: bool,
    point: (f64, f64),
}

#[pymethods]
impl IntersectionPoint {
    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "IntersectionPoint(s={}, t={}, tangent={}, point={:?})",
            self.s.get().__repr__(),
            self.t.bind(py).get().__repr__(),
            if self.tangent { "True" } else { "False" },
            self.point
        )
    }
}

/// One maximal common stretch: P over [s[0], s[1]] (s[0] < s[1]) traces what Q traces from t[0]
/// to t[1] (decreasing when the curves run opposite ways); decided exactly.
#[pyclass(module = "blossom", frozen, get_all)]
pub struct Overlap {
    s: (Py<Algebraic>, Py<Algebraic>),
    t: (Py<Algebraic>, Py<Algebraic>),
}

#[pymethods]
impl Overlap {
    fn __repr__(&self) -> String {
        format!(
            "Overlap(s=({}, {}), t=({}, {}))",
            self.s.0.get().__repr__(),
            self.s.1.get().__repr__(),
            self.t.0.get().__repr__(),
            self.t.1.get().__repr__()
        )
    }
}

/// Every intersection of two curves (or of a curve with itself): `points`, sorted by s then t,
/// and `overlaps`, sorted by their first s.
#[pyclass(module = "blossom", frozen, get_all)]
pub struct IntersectionRecords {
    points: Vec<Py<IntersectionPoint>>,
    overlaps: Vec<Py<Overlap>>,
}

#[pymethods]
impl IntersectionRecords {
    fn __repr__(&self) -> String {
        format!(
            "IntersectionRecords({} point(s), {} overlap(s))",
            self.points.len(),
            self.overlaps.len()
        )
    }
}

pub fn intersection_records(py: Python<'_>, x: &Intersections) -> PyResult<IntersectionRecords> {
    let points = x
        .points
        .iter()
        .map(|p| {
            Py::new(
                py,
                IntersectionPoint {
                    s: algebraic(py, &p.s)?,
                    t: algebraic(py, &p.t)?,
                    tangent: p.tangent,
                    point: (positive_zero(p.point[0]), positive_zero(p.point[1])),
                },
            )
        })
        .collect::<PyResult<_>>()?;
    let overlaps = x
        .overlaps
        .iter()
        .map(|o| {
            Py::new(
                py,
                Overlap {
                    s: (algebraic(py, &o.s[0])?, algebraic(py, &o.s[1])?),
                    t: (algebraic(py, &o.t[0])?, algebraic(py, &o.t[1])?),
                },
            )
        })
        .collect::<PyResult<_>>()?;
    Ok(IntersectionRecords { points, overlaps })
}

/// A zero of a polynomial given by Bernstein coefficients: `t` (Algebraic) and its
/// `multiplicity`.
#[pyclass(module = "blossom", frozen, get_all)]
pub struct Zero {
    t: Py<Algebraic>,
    multiplicity: usize,
}

#[pymethods]
impl Zero {
    fn __repr__(&self) -> String {
        format!(
            "Zero(t={}, multiplicity={})",
            self.t.get().__repr__(),
            self.multiplicity
        )
    }
}

/// The zeros in [0, 1] of a polynomial in Bernstein form: `zeros` (increasing) and
/// `identically_zero` (then `zeros` is empty).
#[pyclass(module = "blossom", frozen, get_all)]
pub struct Zeros {
    zeros: Vec<Py<Zero>>,
    identically_zero: bool,
}

#[pymethods]
impl Zeros {
    fn __repr__(&self) -> String {
        format!(
            "Zeros({} zero(s), identically_zero={})",
            self.zeros.len(),
            if self.identically_zero {
                "True"
            } else {
                "False"
            }
        )
    }
}

pub fn zeros_record(py: Python<'_>, z: &blossom::BezierZeros) -> PyResult<Zeros> {
    let zeros = z
        .zeros
        .iter()
        .map(|z| {
            Py::new(
                py,
                Zero {
                    t: algebraic(py, &z.t)?,
                    multiplicity: z.multiplicity,
                },
            )
        })
        .collect::<PyResult<_>>()?;
    Ok(Zeros {
        zeros,
        identically_zero: z.identically_zero,
    })
}

/// The least or greatest value of one coordinate over the curve: `value` (Algebraic), the
/// parameters `at` where it is reached, `everywhere` when the coordinate is constant.
#[pyclass(module = "blossom", frozen, get_all)]
pub struct Extreme {
    value: Py<Algebraic>,
    at: Vec<Py<Algebraic>>,
    everywhere: bool,
}

#[pymethods]
impl Extreme {
    fn __repr__(&self) -> String {
        format!(
            "Extreme(value={}, at {} parameter(s))",
            self.value.get().__repr__(),
            self.at.len()
        )
    }
}

fn algebraics(py: Python<'_>, v: &[AlgebraicReal]) -> PyResult<Vec<Py<Algebraic>>> {
    v.iter().map(|a| algebraic(py, a)).collect()
}

/// The tight bounding box of a curve: per coordinate the `min` and `max` Extreme.
#[pyclass(module = "blossom", frozen, get_all)]
pub struct Extremes {
    min: Vec<Py<Extreme>>,
    max: Vec<Py<Extreme>>,
}

pub fn extremes_record(py: Python<'_>, b: &blossom::TightBox) -> PyResult<Extremes> {
    let one = |e: &blossom::Extreme| {
        Py::new(
            py,
            Extreme {
                value: algebraic(py, &e.value)?,
                at: algebraics(py, &e.at)?,
                everywhere: e.everywhere,
            },
        )
    };
    Ok(Extremes {
        min: b.min.iter().map(one).collect::<PyResult<_>>()?,
        max: b.max.iter().map(one).collect::<PyResult<_>>()?,
    })
}

/// The points of a curve nearest to a point: `squared_distance` (Algebraic), the parameters
/// `at` (increasing) and the `points` there (each coordinate Algebraic); `everywhere` when
/// every point of the curve is at that distance (a curve that is a single point).
#[pyclass(module = "blossom", frozen, get_all)]
pub struct NearestPoint {
    squared_distance: Py<Algebraic>,
    at: Vec<Py<Algebraic>>,
    points: Vec<Vec<Py<Algebraic>>>,
    everywhere: bool,
}

pub fn nearest_record(py: Python<'_>, n: &blossom::NearestPoint) -> PyResult<NearestPoint> {
    Ok(NearestPoint {
        squared_distance: algebraic(py, &n.squared_distance)?,
        at: algebraics(py, &n.at)?,
        points: n
            .points
            .iter()
            .map(|p| algebraics(py, p))
            .collect::<PyResult<_>>()?,
        everywhere: n.everywhere,
    })
}
