//! # blossom
//!
//! Exact and fast Bézier subdivision through blossoms (polar forms).
//!
//! A polynomial curve C(u) = sum c_i u^i or surface S(u, v) = sum c_ij u^i v^j, restricted to
//! an interval, a rectangle or a triangle, is a Bézier curve or patch whose control points are
//! values of the blossom of C or S (equations (1), (6), (12) of the subdivision paper). This
//! crate computes them exactly or in floating point, by four independent algorithms and by a
//! fast bulk path, all generic over one small number trait, [`Ring`].
//!
//! ```
//! use blossom::{restrict_curve, Method, PowerCurve, Rational};
//!
//! // C(u) = u^3 on [1, 2]: control points 1, 4/3, 2 ... as blossom values b(2^v, 1^(3-v)).
//! let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
//! let cubic = PowerCurve::new(vec![vec![q(0, 1)], vec![q(0, 1)], vec![q(0, 1)], vec![q(1, 1)]])?;
//! let bezier = restrict_curve(&cubic, &q(1, 1), &q(2, 1), Method::Bulk);
//! let w: Vec<Rational> = bezier.control_points().iter().map(|p| p[0].clone()).collect();
//! assert_eq!(w, vec![q(1, 1), q(2, 1), q(4, 1), q(8, 1)]);
//! // Every method gives the identical answer.
//! assert_eq!(bezier, restrict_curve(&cubic, &q(1, 1), &q(2, 1), Method::ClosedForm));
//! # Ok::<(), blossom::Error>(())
//! ```
#![forbid(unsafe_code)]

extern crate self as blossom;

pub mod accuracy;
pub mod basis;
pub mod batched;
pub mod bezier;
pub mod binomial;
pub mod blossoms;
pub mod cli;
pub mod degree;
pub mod error;
pub mod inverse;
pub mod linalg;
pub mod number;
pub mod nurbs;
pub mod point;
pub mod poly;
pub mod power;
pub mod proofs;
pub mod restrict;
pub mod ring;
pub mod specialised;
pub mod spline;
pub mod subdivide;
pub mod verify;

pub use bezier::{BezierCurve, TensorPatch, TriangularPatch};
pub use blossom_macros::restriction;
pub use error::Error;
pub use linalg::Field;
pub use poly::Poly;
pub use power::{PowerCurve, PowerSurface};
pub use restrict::{restrict_curve, restrict_tensor, restrict_triangle, Method};
pub use ring::{Rational, Ring};
pub use spline::BSpline;
pub use subdivide::{restrict_bezier_curve, restrict_bezier_tensor, restrict_bezier_triangle};

/// The README's examples, compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
