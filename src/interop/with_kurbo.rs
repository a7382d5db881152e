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

/// The `K` control points `points` (about `field`) of a kurbo segment called `name`.
fn kurbo_points<const K: usize, P: AsRef<[f64]>>(
    points: &[P],
    field: &str,
    name: &str,
) -> Result<[kurbo::Point; K]> {
    if points.len() != K {
        return Err(Error::of(
            ErrorKind::Degree,
            field,
            format!(
                "a {name} has degree {} ({K} control points), found degree {}",
                K - 1,
                points.len().saturating_sub(1)
            ),
        ));
    }
    let mut out = [kurbo::Point::ZERO; K];
    for (i, (o, p)) in out.iter_mut().zip(points).enumerate() {
        *o = kurbo::Point::try_from_point(p.as_ref(), &format!("{field}[{i}]"))?;
    }
    Ok(out)
}

macro_rules! kurbo_segment {
    ($name:ident, $k:literal, $($p:ident),+) => {
        impl From<kurbo::$name> for BezierCurve<f64> {
            fn from(segment: kurbo::$name) -> Self {
                BezierCurve::new(vec![$(segment.$p.into_point()),+])
                    .expect("a non-empty polygon of 2-D points")
            }
        }

        impl TryFrom<&BezierCurve<f64>> for kurbo::$name {
            type Error = Error;

            fn try_from(curve: &BezierCurve<f64>) -> Result<Self> {
                let name = concat!("kurbo::", stringify!($name));
                let points: Vec<&[f64]> = curve.control_points().iter().collect();
                let [$($p),+] = kurbo_points::<$k, _>(&points, "control_points", name)?;
                Ok(kurbo::$name { $($p),+ })
            }
        }

        impl TryFrom<BezierCurve<f64>> for kurbo::$name {
            type Error = Error;

            fn try_from(curve: BezierCurve<f64>) -> Result<Self> {
                kurbo::$name::try_from(&curve)
            }
        }

        impl From<kurbo::$name> for Bezier<f64, 2> {
            fn from(segment: kurbo::$name) -> Self {
                Bezier::new(vec![$([segment.$p.x, segment.$p.y]),+])
                    .expect("a non-empty polygon")
            }
        }

        impl TryFrom<&Bezier<f64, 2>> for kurbo::$name {
            type Error = Error;

            fn try_from(curve: &Bezier<f64, 2>) -> Result<Self> {
                let name = concat!("kurbo::", stringify!($name));
                let [$($p),+] = kurbo_points::<$k, _>(curve.points(), "points", name)?;
                Ok(kurbo::$name { $($p),+ })
            }
        }

        impl TryFrom<Bezier<f64, 2>> for kurbo::$name {
            type Error = Error;

            fn try_from(curve: Bezier<f64, 2>) -> Result<Self> {
                kurbo::$name::try_from(&curve)
            }
        }
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
