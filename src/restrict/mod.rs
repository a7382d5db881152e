//! Restriction of a power-basis curve or surface to an interval, a rectangle or a triangle:
//! the Bézier object that describes the same polynomial there, by one of several algorithms
//! that never compute through one another.
//!
//! | module | curves | tensor patches | triangles |
//! |---|---|---|---|
//! | [`definition`] (subset sums) | eq. (2) | eqs. (7)-(8) | eq. (13) |
//! | [`closed_form`] (per control point) | Theorem 1, eq. (3) | Theorem 2, eq. (9) | Theorem 3, eq. (14) |
//! | [`pyramid`] (de Casteljau) | eq. (2) of 004 | eq. (9) of 004 | barycentric steps |
//! | [`polarisation`] (inverse formula) | eqs. (20), (22) of 004 | two passes | eqs. (21), (23) of 004 |
//! | [`homogeneous`] (multilinear form (18) of the homogenisation) | Theorem 1 of 004 at (t, 1) | - | at (u, v, 1) |
//! | [`halving`] (scaled power basis, shared work) | eq. (3) by halving | along u, then v | box halving |
//! | [`taylor_shift`] (through the power basis) | shift + Bernstein | along u, then v | 2-D shift, Horner, Bernstein |
//!
//! The dispatch on [`Method`] is this module's one job; each algorithm is a file of its own and
//! none calls another.

pub(crate) mod closed_form;
pub(crate) mod definition;
pub(crate) mod halving;
pub(crate) mod homogeneous;
pub(crate) mod nets;
pub(crate) mod polarisation;
pub(crate) mod pyramid;
pub(crate) mod taylor_shift;

use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::Ring;

/// Which algorithm computes a restriction. All give the identical exact answer.
///
/// The default is [`Method::Bulk`], the restriction engine, which is also the default
/// `--method` of `blossom restrict`:
///
/// ```
/// use blossom::Method;
/// assert_eq!(Method::default(), Method::Bulk);
/// assert_eq!(Method::default(), Method::ALL[0]);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Method {
    /// All control points at once, sharing work, in the scaled power basis the input is
    /// written in ([`crate::engine::curve_net`] on d_i = c_i / C(n, i)): O(n^2) for a curve, as
    /// accurate in f64 as the closed form. The default ([`Method::default`]).
    #[default]
    Bulk,
    /// All control points at once through a Taylor shift and the change to the Bernstein
    /// basis. Division-free and O(n^2) too, but the power basis of the shifted polynomial is
    /// ill-conditioned: in f64 it loses digits with the degree (kept as an independent method
    /// and as the measured "before" of `BENCHMARKS.md`).
    TaylorShift,
    /// The closed forms (3), (9), (14), one control point at a time.
    ClosedForm,
    /// The subset-sum definitions (2), (8), (13) at every control point.
    Definition,
    /// The pyramid (de Casteljau) on the Bernstein form over the reference domain.
    Pyramid,
    /// The inverse formula (19)-(21) of seed 004, sampling points of the input only.
    Polarisation,
}

impl Method {
    /// Every method, the default first.
    pub const ALL: [Method; 6] = [
        Method::Bulk,
        Method::TaylorShift,
        Method::ClosedForm,
        Method::Definition,
        Method::Pyramid,
        Method::Polarisation,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Method::Bulk => "bulk",
            Method::TaylorShift => "taylor-shift",
            Method::ClosedForm => "closed-form",
            Method::Definition => "definition",
            Method::Pyramid => "pyramid",
            Method::Polarisation => "polarisation",
        }
    }
}

/// `curve` restricted to [a, b] by `method`.
pub fn restrict_power_curve<T: Ring>(
    curve: &PowerCurve<T>,
    a: &T,
    b: &T,
    method: Method,
) -> BezierCurve<T> {
    match method {
        Method::Bulk => halving::restrict_curve(curve, a, b),
        Method::TaylorShift => taylor_shift::restrict_curve(curve, a, b),
        Method::ClosedForm => closed_form::restrict_curve(curve, a, b),
        Method::Definition => definition::restrict_curve(curve, a, b),
        Method::Pyramid => pyramid::restrict_curve(curve, a, b),
        Method::Polarisation => polarisation::restrict_curve(curve, a, b),
    }
}

/// `surface` restricted to `rect = [a, b, c, d]`, i.e. [a, b] x [c, d], by `method`.
pub fn restrict_power_surface<T: Ring>(
    surface: &PowerSurface<T>,
    rect: &[T; 4],
    method: Method,
) -> TensorPatch<T> {
    match method {
        Method::Bulk => halving::restrict_tensor(surface, rect),
        Method::TaylorShift => taylor_shift::restrict_tensor(surface, rect),
        Method::ClosedForm => closed_form::restrict_tensor(surface, rect),
        Method::Definition => definition::restrict_tensor(surface, rect),
        Method::Pyramid => pyramid::restrict_tensor(surface, rect),
        Method::Polarisation => polarisation::restrict_tensor(surface, rect),
    }
}

/// `surface`, as a triangular patch of total degree N = n + m (the paper's convention),
/// restricted to the triangle with corners `tri = [a, b, c]`, by `method`.
pub fn restrict_power_surface_to_triangle<T: Ring>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
    method: Method,
) -> TriangularPatch<T> {
    restrict_power_triangle(&PowerTriangle::from_surface(surface), tri, method)
}

/// `surface`, a polynomial of total degree N given by its triangular array (or a grid taken at
/// total degree N), restricted to the triangle with corners `tri = [a, b, c]` at degree N, by
/// `method`: q_{nu mu lambda} = b(a^nu, b^mu, c^lambda), eq. (12).
///
/// ```
/// use blossom::{restrict_power_triangle, Method, PowerTriangle};
/// // u + v, total degree 1, on the triangle (0, 0), (1, 0), (0, 1): values at the corners.
/// let s = PowerTriangle::new(vec![vec![vec![0.0], vec![1.0]], vec![vec![1.0]]])?;
/// let tri = [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]];
/// let patch = restrict_power_triangle(&s, &tri, Method::Definition);
/// assert_eq!(patch.degree(), 1);
/// assert_eq!((patch.get(1, 0), patch.get(0, 0)), (&[1.0][..], &[0.0][..]));
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn restrict_power_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
    method: Method,
) -> TriangularPatch<T> {
    match method {
        Method::Bulk => halving::restrict_triangle(surface, tri),
        Method::TaylorShift => taylor_shift::restrict_triangle(surface, tri),
        Method::ClosedForm => closed_form::restrict_triangle(surface, tri),
        Method::Definition => definition::restrict_triangle(surface, tri),
        Method::Pyramid => pyramid::restrict_triangle(surface, tri),
        Method::Polarisation => polarisation::restrict_triangle(surface, tri),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_is_the_engine_listed_first() {
        assert_eq!(Method::default(), Method::Bulk);
        assert_eq!(Method::ALL[0], Method::default());
        assert_eq!(Method::default().name(), "bulk");
        // The default is the engine itself: the same answer, bit for bit, in f64.
        let curve = PowerCurve::new(vec![vec![1.0, 0.5], vec![-2.0, 3.0], vec![0.25, 1.0]])
            .expect("a curve");
        assert_eq!(
            restrict_power_curve(&curve, &0.1, &0.7, Method::default()),
            halving::restrict_curve(&curve, &0.1, &0.7)
        );
    }
}
