//! Feature `mint`: mint's `Point2`, `Point3`, `Vector2` and `Vector3` as [`ForeignPoint`]s, so
//! that they convert to and from the library's points and Bézier curves
//! (`BezierCurve::try_from(Vec<mint::Point2<T>>)`, `Vec::<mint::Point3<T>>::try_from(&curve)`).
//!
//! The fixed-dimension shapes ([`crate::Bezier`] and its siblings) store `[T; D]`, which mint
//! converts itself (`From<[T; 2]> for mint::Point2<T>` and back).

use super::points::{ForeignPoint, Sealed};
use crate::shape::point::Point;

macro_rules! mint_point {
    ($name:ident, $dim:literal, $($x:ident),+) => {
        impl<T> Sealed for mint::$name<T> {
            const NAME: &'static str = concat!("mint::", stringify!($name));
        }

        impl<T: Clone> ForeignPoint<T> for mint::$name<T> {
            const DIM: usize = $dim;

            fn into_point(self) -> Point<T> {
                vec![$(self.$x),+]
            }

            fn from_coordinates(coordinates: &[T]) -> Option<Self> {
                let [$($x),+] = coordinates else { return None };
                Some(mint::$name { $($x: $x.clone()),+ })
            }
        }
    };
}

mint_point!(Point2, 2, x, y);
mint_point!(Point3, 3, x, y, z);
mint_point!(Vector2, 2, x, y);
mint_point!(Vector3, 3, x, y, z);
