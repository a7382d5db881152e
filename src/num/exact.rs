//! The number types the certified layer reads exactly: `f64` and [`Rational`].
//!
//! Every finite double is a rational number (m 2^e), so a curve of doubles is read as the
//! curve of exactly those rationals, and the certified answers (intersections, zeros, boxes,
//! nearest points) are the exact answers for the doubles as given: nothing is rounded on the
//! way in. NaN and the infinities are no numbers and are refused, naming the coordinate.
//! One trait, sealed, so that every certified method is written once for both types.

use super::ring::{rational_to_f64, Rational, Ring};
use crate::error::{Error, ErrorKind, Result};
use std::borrow::Cow;

mod sealed {
    /// Only `f64` and `Rational` are read exactly.
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for super::Rational {}
}

/// A number type whose values are rational numbers that the certified operations
/// ([`BezierCurve::intersect`](crate::BezierCurve::intersect),
/// [`zeros`](crate::BezierCurve::zeros), [`bounding_box`](crate::BezierCurve::bounding_box),
/// [`nearest_point`](crate::BezierCurve::nearest_point), ...) read **exactly**: `f64` (a finite
/// double is m 2^e; NaN and infinities are refused with [`ErrorKind::NotFinite`]) and
/// [`Rational`]. Sealed: no other type implements it.
///
/// ```
/// use blossom::{ExactInput, Rational};
/// // 0.1 as a double is not 1/10: it is read as the double it is.
/// assert_eq!(0.1f64.to_exact(), Some(Rational::from_float(0.1).unwrap()));
/// assert_ne!(0.1f64.to_exact(), Some(Rational::new(1.into(), 10.into())));
/// assert_eq!(f64::NAN.to_exact(), None);
/// // A rational is a double only when it is one exactly.
/// assert_eq!(Rational::new(1.into(), 4.into()).exact_f64(), Some(0.25));
/// assert_eq!(Rational::new(1.into(), 3.into()).exact_f64(), None);
/// ```
pub trait ExactInput: Ring + sealed::Sealed {
    /// The number as an exact rational; `None` for NaN and the infinities.
    fn to_exact(&self) -> Option<Rational>;

    /// The number as a double when it is exactly a finite double, else `None`.
    fn exact_f64(&self) -> Option<f64>;

    /// Every value as an exact rational (borrowed when it already is one).
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `name(k)` for the first value k that is not finite.
    #[doc(hidden)]
    fn read_exactly<'a>(
        values: &'a [Self],
        name: impl Fn(usize) -> String,
    ) -> Result<Cow<'a, [Rational]>>;

    /// Every value as a double when each is exactly one (borrowed when it already is).
    #[doc(hidden)]
    fn as_doubles(values: &[Self]) -> Option<Cow<'_, [f64]>>;
}

/// The error of a value that is not finite, at `field`.
fn not_finite(field: String, x: f64) -> Error {
    Error::of(
        ErrorKind::NotFinite,
        field,
        format!("expected a finite number, found {x}"),
    )
}

impl ExactInput for f64 {
    fn to_exact(&self) -> Option<Rational> {
        Rational::from_float(*self)
    }

    fn exact_f64(&self) -> Option<f64> {
        self.is_finite().then_some(*self)
    }

    fn read_exactly<'a>(
        values: &'a [Self],
        name: impl Fn(usize) -> String,
    ) -> Result<Cow<'a, [Rational]>> {
        values
            .iter()
            .enumerate()
            .map(|(k, x)| x.to_exact().ok_or_else(|| not_finite(name(k), *x)))
            .collect::<Result<Vec<_>>>()
            .map(Cow::Owned)
    }

    fn as_doubles(values: &[Self]) -> Option<Cow<'_, [f64]>> {
        values
            .iter()
            .all(|x| x.is_finite())
            .then_some(Cow::Borrowed(values))
    }
}

impl ExactInput for Rational {
    fn to_exact(&self) -> Option<Rational> {
        Some(self.clone())
    }

    fn exact_f64(&self) -> Option<f64> {
        let x = rational_to_f64(self);
        (x.is_finite() && Rational::from_float(x).as_ref() == Some(self)).then_some(x)
    }

    fn read_exactly<'a>(
        values: &'a [Self],
        _name: impl Fn(usize) -> String,
    ) -> Result<Cow<'a, [Rational]>> {
        Ok(Cow::Borrowed(values))
    }

    fn as_doubles(values: &[Self]) -> Option<Cow<'_, [f64]>> {
        values
            .iter()
            .map(ExactInput::exact_f64)
            .collect::<Option<Vec<_>>>()
            .map(Cow::Owned)
    }
}

/// The values of a flat list `field` read exactly, a value that is not finite refused as
/// `field[k]`.
pub(crate) fn exact_values<'a, T: ExactInput>(
    field: &str,
    values: &'a [T],
) -> Result<Cow<'a, [Rational]>> {
    T::read_exactly(values, |k| format!("{field}[{k}]"))
}

/// The coordinates of points (`dim` per point, point after point) read exactly, a coordinate
/// that is not finite refused as `field[i][j]`.
pub(crate) fn exact_coordinates<'a, T: ExactInput>(
    field: &str,
    coordinates: &'a [T],
    dim: usize,
) -> Result<Cow<'a, [Rational]>> {
    T::read_exactly(coordinates, |k| {
        format!("{field}[{}][{}]", k / dim.max(1), k % dim.max(1))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doubles_are_read_as_the_rationals_they_are() {
        let third = 1.0f64 / 3.0;
        let q = third.to_exact().unwrap();
        // 1/3 rounded: its denominator is a power of two, so it is not 1/3.
        let d = q.denom();
        assert!(
            (d & (d - 1u32)) == num_bigint::BigInt::from(0)
                && q != Rational::new(1.into(), 3.into())
        );
        assert_eq!(q.exact_f64(), Some(third));
        assert_eq!(Rational::new(1.into(), 3.into()).exact_f64(), None);
        // Beyond the range of doubles: not a double, whatever it rounds to.
        let huge = Rational::from_integer(num_bigint::BigInt::from(1) << 1100u32);
        assert_eq!(huge.exact_f64(), None);
        assert_eq!(f64::INFINITY.exact_f64(), None);
    }

    #[test]
    fn the_first_value_that_is_not_finite_is_named() {
        let e =
            exact_coordinates("points", &[0.0, 1.0, 2.0, f64::NAN, f64::INFINITY], 2).unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::NotFinite, "points[1][1]"));
        let e = exact_values("c", &[1.0, f64::NEG_INFINITY]).unwrap_err();
        assert_eq!(e.path(), "c[1]");
        let q = [Rational::from_integer(3.into())];
        assert!(matches!(exact_values("c", &q).unwrap(), Cow::Borrowed(_)));
        assert!(f64::as_doubles(&[1.0, f64::NAN]).is_none());
    }
}
