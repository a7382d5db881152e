//! # blossom
//!
//! Exact and fast Bézier subdivision through blossoms (polar forms).
//!
//! A polynomial curve C(u) = sum c_i u^i or surface S(u, v) = sum c_ij u^i v^j, restricted to
//! an interval, a rectangle or a triangle, is a Bézier curve or patch whose control points are
//! values of the blossom of C or S (equations (1), (6), (12) of the subdivision paper). This
//! crate computes them exactly or in floating point, by independent algorithms that never
//! compute through one another, all generic over one small number trait, [`Ring`].
//!
//! ```
//! use blossom::{restrict_power_curve, Method, PowerCurve, Rational};
//!
//! // C(u) = u^3 on [1, 2]: control points 1, 4/3, 2 ... as blossom values b(2^v, 1^(3-v)).
//! let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
//! let cubic = PowerCurve::new(vec![vec![q(0, 1)], vec![q(0, 1)], vec![q(0, 1)], vec![q(1, 1)]])?;
//! let bezier = restrict_power_curve(&cubic, &q(1, 1), &q(2, 1), Method::Bulk);
//! let w: Vec<Rational> = bezier.control_points().iter().map(|p| p[0].clone()).collect();
//! assert_eq!(w, vec![q(1, 1), q(2, 1), q(4, 1), q(8, 1)]);
//! // Every method gives the identical answer.
//! assert_eq!(bezier, restrict_power_curve(&cubic, &q(1, 1), &q(2, 1), Method::ClosedForm));
//! # Ok::<(), blossom::Error>(())
//! ```
//!
//! # Layers
//!
//! The modules are private; everything public is re-exported below, one path per item. Each
//! layer imports only the layers above it in this list:
//!
//! 1. **numbers** (`num/`): [`Ring`], [`Field`], [`Rational`] (read from text exactly by
//!    [`parse_rational`]), [`Poly`], [`BoundedF64`], [`engine::binomial`];
//! 2. **shapes** (`shape/`): [`PowerCurve`], [`PowerSurface`], [`BezierCurve`], [`TensorPatch`],
//!    [`TriangularPatch`], their evaluation (Horner, de Casteljau) and the changes of basis;
//! 3. **restriction** (`restrict/`): one file per algorithm, the dispatch on [`Method`];
//! 4. **applications** (`applications/`): Bézier input, batches, B-splines, rational forms,
//!    degree change, derivatives;
//! 5. **certified zeros and intersections** (`intersect/`), methods of the curve types for
//!    `f64` and [`Rational`] alike ([`ExactInput`]): [`BezierCurve::intersect`],
//!    [`BezierCurve::self_intersections`], [`BezierCurve::bounding_box`],
//!    [`BezierCurve::nearest_point`], [`BezierCurve::zeros`] (and the same on [`Bezier`]);
//!    the free functions [`bezier_zeros`] (every zero of
//!    a Bézier function with its multiplicity), [`AlgebraicReal`] (exact comparison, correctly
//!    rounded `to_f64`), [`intersect_curves`] (isolated points with an exact tangency flag,
//!    overlaps) and [`self_intersections`], all exact: Descartes' rule on Bernstein
//!    coefficients, Yun's square-free factorisation, resultants over the integers; for `f64`
//!    input a float filter, [`certified_crossings_f64`] (subdivision, Krawczyk's test,
//!    double-double residuals: the transversal case proved without big numbers), and
//!    [`intersect_curves_f64_rounded`] (the filter, else the exact path, as doubles);
//! 6. **interoperation** (`interop/`, optional): conversions to and from mint and kurbo types
//!    and serde support ([Features](#features)); nothing else imports it.
//!
//! The `blossom` binary (the papers' report, the JSON jobs, the carried grid of generated
//! evaluators and their proofs) is the separate crate `blossom-cli`.
//!
//! # Features
//!
//! None is on by default; each but `meter` and `unrolled-high` adds an optional dependency
//! (without its default features where it has any), and none changes anything else.
//!
//! * `rayon`: `Batch::par_restrict_into`, the blocks of a batch spread over threads.
//! * `mint` (mint 0.5): mint's `Point2`, `Point3`, `Vector2`, `Vector3` convert to and from the
//!   library's points through `ForeignPoint` (`Point<T>` is `Vec<T>`, so the orphan rule
//!   leaves no room for `From` between the two), and to and from Bézier curves:
//!   `BezierCurve::try_from(Vec<mint::Point2<T>>)` (an error only for an empty list) and
//!   `Vec::<mint::Point2<T>>::try_from(&curve)` ([`ErrorKind::Dimension`] on
//!   `control_points[i]` when the curve is not 2-D). The fixed-dimension shapes ([`Bezier`],
//!   ...) store `[T; D]`, which mint converts itself.
//! * `kurbo` (kurbo 0.13, with its `std` feature): kurbo's `Point` and `Vec2` as
//!   `ForeignPoint`s; `Line`, `QuadBez`, `CubicBez` and `PathSeg` into
//!   [`BezierCurve<f64>`](BezierCurve) and [`Bezier<f64, 2>`](Bezier) by `From` (the same
//!   control points in the same order: the same curve over [0, 1]), and back by `TryFrom`,
//!   which fails with [`ErrorKind::Degree`] on `control_points` (`points`) when the degree is
//!   not the segment's and with [`ErrorKind::Dimension`] on `control_points[i]` when a point is
//!   not 2-D.
//! * `lyon` (lyon_geom 1, without default features): lyon's `Point<f64>` and `Vector<f64>` as
//!   `ForeignPoint`s; `LineSegment<f64>`, `QuadraticBezierSegment<f64>` and
//!   `CubicBezierSegment<f64>` into and out of [`BezierCurve<f64>`](BezierCurve) and
//!   [`Bezier<f64, 2>`](Bezier) with the same conventions and errors as kurbo's.
//! * `unrolled-high` (no dependency): the unrolled restriction evaluators of degrees 9..=24
//!   (`f64`, `f32`, dimensions 1..=4) besides the default 1..=8: most of the library's compile
//!   time and memory (a dependent crate's first release build 146 s and 4.6 GB with them, 21 s
//!   and 0.56 GB without, on 2 cores); without them those degrees restrict by two de Casteljau
//!   subdivisions, which take fewer steps.
//! * `serde` (serde 1, with `alloc` and `derive` only): `Serialize` and `Deserialize` for the
//!   geometry types, generic over the number type. A type with private fields is written as the
//!   arguments of its checked constructor under their names (`{"control_points": [...]}`,
//!   `{"degree": 2, "knots": [...], "control_points": [...]}`, ...) and read back through that
//!   constructor, so a document that breaks an invariant is a deserialisation error naming the
//!   field inside the document (`control_points[1]: expected 2 coordinates, found 1`), never an
//!   invalid value. [`Rational`] is written as num-rational writes it, `[numerator,
//!   denominator]` of num-bigint integers `[sign, [u32 digits]]` (1/3 is
//!   `[[1, [1]], [1, [3]]]`): the feature turns on the `serde` features of num-rational and
//!   num-bigint for that. [`RationalBezierCell`], a result with public fields, is written but
//!   not read.
//!
//! * `meter` (no dependency): `blossom::meter`, a thread-local budget of work units that the
//!   arithmetic of [`Rational`] and [`BoundedF64`] charges as it computes, and
//!   `meter::metered`, which runs a computation under a limit and stops it when the charges
//!   pass it (the `blossom` binary's work budget). Without the feature the charges compile to
//!   nothing; with it and no meter started, a charge is one read of a thread-local cell.
//!   The work estimates of the certified zeros and intersections (`blossom::budget`) are
//!   there in every build.
//!
//! `cargo test -p blossom --features mint,kurbo,lyon,serde` runs the tests of these features alone
//! (`tests/suite/applications/interop.rs`); `cargo test --workspace` runs them too, because the
//! application crate's dev-dependency on this crate turns the four features on and Cargo
//! builds one `blossom` for the whole workspace.
//!
//! # References
//!
//! * K. Vlachkova, *Efficient subdivision of Bézier curves/surfaces via blossoms*: the closed
//!   forms (3), (9), (14) and the subset-sum definitions (2), (8), (13).
//! * L. Fernández-Jambrina, *Inverse relations for blossoms and parametrisations of rational
//!   curves and surfaces*: the pyramid algorithm, the inverse (polarisation) formula (19)-(23),
//!   rational curves, degree elevation and reduction.
//! * J. Dueñas Béjar, *Los puntos de de Boor de una curva seccionalmente polinómica*: de Boor
//!   points as blossoms, de Boor's algorithm, piecewise polynomials as B-splines
//!   (Curry-Schoenberg).
// No unsafe code but the calls of the AVX build of the halving (`shape/halving.rs`), of
// the FMA builds of the filter's double-double points (`intersect/pyramid.rs`) and of the
// AVX2 builds of the filter's search and settlement (`intersect/filter.rs`), each after the
// processor was seen to support the feature.
#![deny(unsafe_code)]
// Every example of the docs and of the README (`ReadmeDoctests` below) compiles without a
// warning: an unused import or variable in an example a user copies fails the doc tests.
#![doc(test(attr(deny(warnings))))]

extern crate self as blossom;

mod applications;
mod error;
mod intersect;
mod num;
pub mod region;
mod restrict;
mod shape;
#[cfg(test)]
mod test_rng;
// Conversions and serialisation behind the features `mint`, `kurbo` and `serde`.
mod interop;

// Numbers.
pub use num::bounded::BoundedF64;
pub use num::exact::ExactInput;
pub use num::limits::MAX_ENTRIES;
pub use num::linalg::Field;
pub use num::parse::{parse_f64, parse_rational, MAX_DECIMAL_EXPONENT};
pub use num::poly::Poly;
pub use num::ring::{rational_to_f64, Rational, Ring};

// Work metering (feature `meter`): one module, its items under one path each; the work
// estimates of the certified intersections beside it (every build: they estimate, they charge
// nothing).
pub use intersect::budget;
#[cfg(feature = "meter")]
pub use num::meter;

// Errors.
pub use error::{Error, ErrorKind};

// Bézier shapes: the runtime-dimension types (one buffer, any dimension) and the
// fixed-dimension ones (`[T; D]` points), which convert into each other.
pub use shape::array::{Bezier, BezierTensor, BezierTriangle};
pub use shape::bezier::{
    bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom, BezierCurve, TensorPatch,
    TriangularPatch,
};
pub use shape::point::{Point, Points};
pub use shape::traits::{Evaluate, Restrict};

// Power-basis shapes and their restriction (the subdivision paper's problem), by any method.
pub use restrict::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle,
    restrict_power_triangle, Method,
};
pub use shape::power::{PowerCurve, PowerSurface};
pub use shape::power_triangle::PowerTriangle;

// The blossoms of power-basis shapes: the subset-sum definitions, the inverse
// (polarisation) formula and the multilinear form of the homogenisation.
pub use restrict::definition::{
    curve_blossom, power_triangle_blossom, tensor_blossom, triangle_blossom,
};
pub use restrict::homogeneous::{
    homogeneous_curve, homogeneous_curve_blossom, homogeneous_surface,
    homogeneous_triangle_blossom, multilinear_polar_form,
};
pub use restrict::polarisation::{
    curve_blossom_from_samples, curve_control_points_from_samples, polar_form,
    tensor_blossom_from_samples, tensor_control_points_from_samples, triangle_blossom_from_samples,
    triangle_control_points_from_samples,
};

// Certified zeros and intersections.
pub use intersect::algebraic::AlgebraicReal;
pub use intersect::curves::{
    intersect_curves, intersect_curves_f64, self_intersections, self_intersections_f64,
    IntersectionPoint, Intersections, Overlap,
};
pub use intersect::extrema::{
    nearest_point, nearest_point_f64, tight_bounding_box, tight_bounding_box_f64, Extreme,
    NearestPoint, TightBox,
};
pub use intersect::filter::{certified_crossings_f64, CertifiedCrossing};
pub use intersect::rounded::{
    intersect_curves_f64_rounded, RoundedIntersections, RoundedOverlap, RoundedPoint,
};
pub use intersect::zeros::{bezier_zeros, bezier_zeros_f64, BezierZeros, PolynomialZero};

// Applications.
pub use applications::batch::{Batch, RestrictionMap, BATCH_LANES};
pub use applications::check::{check_bezier_restriction, exact_error, AnswerError, PointError};
pub use applications::degree::{elevate, reduce, squared_l2_distance, Reduction};
pub use applications::derivative::{
    bezier_derivative, bezier_tensor_derivative, bezier_triangle_derivative,
    power_curve_derivative, power_tensor_derivative, power_triangle_derivative,
};
pub use applications::patch_degree::tensor::{
    elevate_tensor, reduce_tensor, tensor_squared_l2_distance,
};
pub use applications::patch_degree::triangle::{
    elevate_triangle, reduce_triangle, triangle_squared_l2_distance,
};
pub use applications::rational::{
    RationalBSpline, RationalBezierCurve, RationalCurve, RationalPowerTriangle, RationalSurface,
    RationalTensorPatch, RationalTriangularPatch,
};
pub use applications::spline::{
    bspline_from_pieces, bspline_from_pieces_with_knots, bspline_surface_from_pieces,
    continuity_at, BSpline, BSplineSurface, BezierCell, BezierPiece, KnotVector, Piece, PowerPiece,
    RationalBSplineSurface, RationalBezierCell, SurfacePiece,
};
pub use applications::true_degree::{tensor_true_degree, triangle_true_degree, true_degree};

/// The building blocks under the geometry, for code that composes its own algorithms: the
/// restriction engine (the halving nets on flat coordinates and their step types), the changes
/// of basis, the index of triangular nets, exact binomials and linear algebra, the matrices of
/// degree elevation and reduction, and the closed form (14) with its formula visible.
///
/// A user of the curves and patches needs none of it: every shape's methods call into here.
pub mod engine {
    pub use crate::applications::degree::{bernstein_gram, elevation_matrix, least_squares_matrix};
    pub use crate::applications::patch_degree::tensor::{
        tensor_bernstein_gram, tensor_least_squares_matrix,
    };
    pub use crate::applications::patch_degree::triangle::{
        triangle_bernstein_gram, triangle_elevation_matrix, triangle_least_squares_matrix,
    };
    pub use crate::applications::spline::bspline_basis_on_span;
    pub use crate::num::binomial::{binomial, multinomial};
    pub use crate::num::linalg::solve_rational_system;
    pub use crate::restrict::closed_form::{
        restrict_triangle_with_formula, TriangleFormula, TriangleSplit, THEOREM_3,
    };
    pub use crate::restrict::homogeneous::{multilinear_term_count, MAX_MULTILINEAR_DEGREE};
    pub use crate::shape::array::subsegment_into;
    pub use crate::shape::basis::{
        bernstein_by_horner, bernstein_to_power, bernstein_to_power_flat, power_to_bernstein,
        power_to_bernstein_flat, scale_argument, scale_argument_flat, taylor_shift,
        taylor_shift_flat, tensor_bernstein_to_power, triangle_bernstein_by_horner,
        triangle_bernstein_to_power, triangle_power_to_bernstein,
    };
    pub use crate::shape::coords::{CoordinateBuffer, SmallCoords, INLINE_COORDINATES};
    pub use crate::shape::halving::{
        curve_net, curve_scratch_len, tensor_net, tensor_scratch_len, triangle_net,
        triangle_scratch_len, BernsteinPairStep, BernsteinPairVectorStep, BernsteinStep,
        BernsteinVectorStep, CurveStep, Fixed, PowerPairStep, PowerPairVectorStep, PowerStep,
        PowerVectorStep, TriangleStep, Width,
    };
    pub use crate::shape::simplex::{checked_triangle_len, triangle_index, triangle_len};
}

// The compile-time expansion of formulae (3), (9), (14).
pub use blossom_macros::restriction;

// Interoperation (features `mint`, `kurbo`).
#[cfg(any(feature = "mint", feature = "kurbo", feature = "lyon"))]
pub use interop::points::ForeignPoint;

/// The README's examples, compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// The guide's examples (`docs/guide.md`), compiled and run as doc tests.
#[doc = include_str!("../docs/guide.md")]
#[cfg(doctest)]
pub struct GuideDoctests;
