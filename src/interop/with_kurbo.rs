//! Feature `kurbo`: kurbo's `Point` and `Vec2` as [`ForeignPoint`]s, and its Bézier segments as
//! the library's Bézier curves of the same degree over the same parameter range [0, 1]:
//!
//! | kurbo | degree | to the library | from the library |
//! |---|---|---|---|
//! | `Line` | 1 | `From` | `TryFrom` |
//! | `QuadBez` | 2 | `From` | `TryFrom` |
//! | `CubicBez` | 3 | `From` | `TryFrom` |
//! | `PathSeg` | 1, 2 or 3 | `From` | `TryFrom` |
//!
//! both for the runtime-dimension [`BezierCurve<f64>`] and for the fixed-dimension
//! [`Bezier<f64, 2>`]. kurbo's control points p0, p1, ... are the library's w_0, w_1, ... in
//! order, so both describe the same curve sum_i w_i B_i^n(t). The conversions from the library
//! fail with [`ErrorKind::Degree`] on `control_points` (`points` for [`Bezier`]) when the degree
//! is not the segment's, and with [`ErrorKind::Dimension`] on `control_points[i]` when a point
//! does not have 2 coordinates.

use super::points::{ForeignPoint, Sealed};
use crate::error::{Error, ErrorKind, Result};
use crate::shape::array::Bezier;
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;

macro_rules! kurbo_point {
    ($name:ident) => {
        impl Sealed for kurbo::$name {
            const NAME: &'static str = concat!("kurbo::", stringify!($name));
        }

        impl ForeignPoint<f64> for kurbo::$name {
            const DIM: usize = 2;

            fn into_point(self) -> Point<f64> {
                vec![self.x, self.y]
            }

            fn from_coordinates(coordinates: &[f64]) -> Option<Self> {
                let &[x, y] = coordinates else { return None };
                Some(kurbo::$name::new(x, y))
            }
        }
    };
}

kurbo_point!(Point);
kurbo_point!(Vec2);

macro_rules! kurbo_segment {
    ($name:ident, $k:literal, $($p:ident),+) => {
        super::points::foreign_segment!(
            kurbo::$name, kurbo::Point,
            concat!("kurbo::", stringify!($name)), $k, $($p),+
        );
    };
}

kurbo_segment!(Line, 2, p0, p1);
kurbo_segment!(QuadBez, 3, p0, p1, p2);
kurbo_segment!(CubicBez, 4, p0, p1, p2, p3);

/// The degree error of a `kurbo::PathSeg` (degree 1, 2 or 3) about `field`.
fn path_seg_degree(field: &str, degree: usize) -> Error {
    Error::of(
        ErrorKind::Degree,
        field,
        format!("a kurbo::PathSeg has degree 1, 2 or 3, found degree {degree}"),
    )
}

impl From<kurbo::PathSeg> for BezierCurve<f64> {
    fn from(segment: kurbo::PathSeg) -> Self {
        match segment {
            kurbo::PathSeg::Line(s) => s.into(),
            kurbo::PathSeg::Quad(s) => s.into(),
            kurbo::PathSeg::Cubic(s) => s.into(),
        }
    }
}

impl TryFrom<&BezierCurve<f64>> for kurbo::PathSeg {
    type Error = Error;

    fn try_from(curve: &BezierCurve<f64>) -> Result<Self> {
        Ok(match curve.degree() {
            1 => kurbo::PathSeg::Line(curve.try_into()?),
            2 => kurbo::PathSeg::Quad(curve.try_into()?),
            3 => kurbo::PathSeg::Cubic(curve.try_into()?),
            n => return Err(path_seg_degree("control_points", n)),
        })
    }
}

impl TryFrom<BezierCurve<f64>> for kurbo::PathSeg {
    type Error = Error;

    fn try_from(curve: BezierCurve<f64>) -> Result<Self> {
        kurbo::PathSeg::try_from(&curve)
    }
}

impl From<kurbo::PathSeg> for Bezier<f64, 2> {
    fn from(segment: kurbo::PathSeg) -> Self {
        match segment {
            kurbo::PathSeg::Line(s) => s.into(),
            kurbo::PathSeg::Quad(s) => s.into(),
            kurbo::PathSeg::Cubic(s) => s.into(),
        }
    }
}

impl TryFrom<&Bezier<f64, 2>> for kurbo::PathSeg {
    type Error = Error;

    fn try_from(curve: &Bezier<f64, 2>) -> Result<Self> {
        Ok(match curve.degree() {
            1 => kurbo::PathSeg::Line(curve.try_into()?),
            2 => kurbo::PathSeg::Quad(curve.try_into()?),
            3 => kurbo::PathSeg::Cubic(curve.try_into()?),
            n => return Err(path_seg_degree("points", n)),
        })
    }
}
