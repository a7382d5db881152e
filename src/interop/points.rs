//! The library's points ([`Point<T>`], a `Vec<T>` of any length) and the fixed-size point and
//! vector types of other crates, converted both ways through one trait, [`ForeignPoint`].
//!
//! `Point<T>` is the standard library's `Vec<T>`, so Rust's orphan rule forbids
//! `impl From<mint::Point2<T>> for Point<T>` in this crate (neither the trait nor the types would
//! be local). [`ForeignPoint`] is that conversion instead; on the library's own types the usual
//! traits are implemented, generically over it:
//!
//! * `BezierCurve<T>: TryFrom<Vec<P>>` for every `P: ForeignPoint<T>` (the control points; an
//!   error only for an empty list);
//! * `Vec<P>: TryFrom<&BezierCurve<T>>` (an error of kind [`ErrorKind::Dimension`] on
//!   `control_points[0]` when the curve's points do not have `P::DIM` coordinates).

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;
use crate::Ring;

mod sealed {
    /// Only this crate implements [`super::ForeignPoint`].
    pub trait Sealed {
        /// The type's name in error messages (`mint::Point2`, `kurbo::Point`, ...).
        const NAME: &'static str;
    }
}
pub(crate) use sealed::Sealed;

/// A point or vector type of another crate with a fixed number of coordinates
/// ([`ForeignPoint::DIM`]), converted to and from the library's runtime-dimension points
/// [`Point<T>`](crate::Point).
///
/// Implemented (sealed) by mint's `Point2`, `Point3`, `Vector2`, `Vector3` for any `T: Clone`
/// (feature `mint`) and by kurbo's `Point` and `Vec2` for `T = f64` (feature `kurbo`).
///
/// ```
/// # #[cfg(feature = "mint")] {
/// use blossom::{ErrorKind, ForeignPoint};
/// let p = mint::Point3 { x: 1.0, y: 2.0, z: 3.0 };
/// assert_eq!(p.into_point(), vec![1.0, 2.0, 3.0]);
/// let v = mint::Vector2::try_from_point(&[4.0, 5.0], "point").unwrap();
/// assert_eq!((v.x, v.y), (4.0, 5.0));
/// let e = mint::Vector2::<f64>::try_from_point(&[1.0, 2.0, 3.0], "point").unwrap_err();
/// assert_eq!((e.path(), e.kind()), ("point", ErrorKind::Dimension));
/// # }
/// ```
pub trait ForeignPoint<T>: Sized + Sealed {
    /// The number of coordinates.
    const DIM: usize;

    /// The coordinates, in order (x, y[, z]): a library point of `DIM` coordinates.
    fn into_point(self) -> Point<T>;

    /// The value with the coordinates `coordinates`, or `None` unless there are `DIM` of them.
    fn from_coordinates(coordinates: &[T]) -> Option<Self>;

    /// The value with the coordinates `point`.
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `field` when `point` does not have `DIM` coordinates.
    fn try_from_point(point: &[T], field: &str) -> Result<Self> {
        Self::from_coordinates(point).ok_or_else(|| dimension_error::<T, Self>(point.len(), field))
    }
}

/// The error of a point with `found` coordinates where `P` needs `P::DIM`.
fn dimension_error<T, P: ForeignPoint<T>>(found: usize, field: &str) -> Error {
    Error::of(
        ErrorKind::Dimension,
        field,
        format!(
            "expected {} coordinates (a {}), found {found}",
            P::DIM,
            P::NAME
        ),
    )
}

/// The curve with the control points `points`, as [`BezierCurve::new`] checks them (the
/// dimension is `P::DIM` by construction, so the one error is an empty list:
/// [`ErrorKind::Empty`] on `control_points`).
impl<T: Ring, P: ForeignPoint<T>> TryFrom<Vec<P>> for BezierCurve<T> {
    type Error = Error;

    fn try_from(points: Vec<P>) -> Result<Self> {
        BezierCurve::new(points.into_iter().map(ForeignPoint::into_point).collect())
    }
}

/// The control points of `curve` as `P`s; [`ErrorKind::Dimension`] on `control_points[0]` when
/// the curve's dimension is not `P::DIM`.
impl<T: Ring, P: ForeignPoint<T>> TryFrom<&BezierCurve<T>> for Vec<P> {
    type Error = Error;

    fn try_from(curve: &BezierCurve<T>) -> Result<Self> {
        curve
            .control_points()
            .iter()
            .enumerate()
            .map(|(i, p)| P::try_from_point(p, &format!("control_points[{i}]")))
            .collect()
    }
}

/// The `K` control points `points` (about `field`) of a foreign segment called `name`, as the
/// foreign point type `P`: [`ErrorKind::Degree`] on `field` when there are not `K`,
/// [`ErrorKind::Dimension`] on `field[i]` when point i is not 2-D.
pub(crate) fn foreign_points<const K: usize, P: ForeignPoint<f64> + Copy, Q: AsRef<[f64]>>(
    points: &[Q],
    field: &str,
    name: &str,
) -> Result<[P; K]> {
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
    let mut out = Vec::with_capacity(K);
    for (i, p) in points.iter().enumerate() {
        out.push(P::try_from_point(p.as_ref(), &format!("{field}[{i}]"))?);
    }
    Ok(out
        .try_into()
        .unwrap_or_else(|_| unreachable!("K points were checked")))
}

/// The conversions between a foreign planar Bézier segment of degree `K - 1` (a struct whose
/// fields `$p` are its control points in order, of the [`ForeignPoint`] type `$point`) and
/// [`BezierCurve<f64>`](crate::BezierCurve) and [`Bezier<f64, 2>`](crate::Bezier): `From`
/// into the library, `TryFrom` back (a degree or dimension error naming the field).
macro_rules! foreign_segment {
    ($segment:ty, $point:ty, $name:expr, $k:literal, $($p:ident),+) => {
        impl From<$segment> for BezierCurve<f64> {
            fn from(segment: $segment) -> Self {
                BezierCurve::new(vec![$(segment.$p.into_point()),+])
                    .expect("a non-empty polygon of 2-D points")
            }
        }

        impl TryFrom<&BezierCurve<f64>> for $segment {
            type Error = Error;

            fn try_from(curve: &BezierCurve<f64>) -> Result<Self> {
                let points: Vec<&[f64]> = curve.control_points().iter().collect();
                let [$($p),+] = super::points::foreign_points::<$k, $point, _>(
                    &points, "control_points", $name,
                )?;
                Ok(Self { $($p),+ })
            }
        }

        impl TryFrom<BezierCurve<f64>> for $segment {
            type Error = Error;

            fn try_from(curve: BezierCurve<f64>) -> Result<Self> {
                <$segment>::try_from(&curve)
            }
        }

        impl From<$segment> for Bezier<f64, 2> {
            fn from(segment: $segment) -> Self {
                Bezier::new(vec![$([segment.$p.x, segment.$p.y]),+])
                    .expect("a non-empty polygon")
            }
        }

        impl TryFrom<&Bezier<f64, 2>> for $segment {
            type Error = Error;

            fn try_from(curve: &Bezier<f64, 2>) -> Result<Self> {
                let [$($p),+] =
                    super::points::foreign_points::<$k, $point, _>(curve.points(), "points", $name)?;
                Ok(Self { $($p),+ })
            }
        }

        impl TryFrom<Bezier<f64, 2>> for $segment {
            type Error = Error;

            fn try_from(curve: Bezier<f64, 2>) -> Result<Self> {
                <$segment>::try_from(&curve)
            }
        }
    };
}
pub(crate) use foreign_segment;
