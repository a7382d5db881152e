//! Feature `lyon`: lyon_geom's (version 1) `Point<f64>` and `Vector<f64>` as
//! [`ForeignPoint`]s, and its Bézier segments in `f64` as the library's Bézier curves of the
//! same degree over the same parameter range [0, 1]:
//!
//! | lyon_geom | degree | to the library | from the library |
//! |---|---|---|---|
//! | `LineSegment<f64>` | 1 | `From` | `TryFrom` |
//! | `QuadraticBezierSegment<f64>` | 2 | `From` | `TryFrom` |
//! | `CubicBezierSegment<f64>` | 3 | `From` | `TryFrom` |
//!
//! both for the runtime-dimension [`BezierCurve<f64>`] and for the fixed-dimension
//! [`Bezier<f64, 2>`]. lyon's control points (`from`, `ctrl`/`ctrl1`, `ctrl2`, `to`) are the
//! library's w_0, w_1, ... in order, so both describe the same curve sum_i w_i B_i^n(t). The
//! conversions from the library fail with [`ErrorKind::Degree`](crate::ErrorKind::Degree) on
//! `control_points` (`points` for [`Bezier`]) when the degree is not the segment's, and with
//! [`ErrorKind::Dimension`](crate::ErrorKind::Dimension) on `control_points[i]` when a point
//! does not have 2 coordinates.

use super::points::{foreign_segment, ForeignPoint, Sealed};
use crate::error::{Error, Result};
use crate::shape::array::Bezier;
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;

macro_rules! lyon_point {
    ($name:ident, $make:path) => {
        impl Sealed for lyon_geom::$name<f64> {
            const NAME: &'static str = concat!("lyon_geom::", stringify!($name));
        }

        impl ForeignPoint<f64> for lyon_geom::$name<f64> {
            const DIM: usize = 2;

            fn into_point(self) -> Point<f64> {
                vec![self.x, self.y]
            }

            fn from_coordinates(coordinates: &[f64]) -> Option<Self> {
                let &[x, y] = coordinates else { return None };
                Some($make(x, y))
            }
        }
    };
}

lyon_point!(Point, lyon_geom::point);
lyon_point!(Vector, lyon_geom::vector);

foreign_segment!(
    lyon_geom::LineSegment<f64>,
    lyon_geom::Point<f64>,
    "lyon_geom::LineSegment",
    2,
    from,
    to
);
foreign_segment!(
    lyon_geom::QuadraticBezierSegment<f64>,
    lyon_geom::Point<f64>,
    "lyon_geom::QuadraticBezierSegment",
    3,
    from,
    ctrl,
    to
);
foreign_segment!(
    lyon_geom::CubicBezierSegment<f64>,
    lyon_geom::Point<f64>,
    "lyon_geom::CubicBezierSegment",
    4,
    from,
    ctrl1,
    ctrl2,
    to
);
