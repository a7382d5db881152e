//! The buffer that holds a Bézier curve's coordinates ([`crate::BezierCurve`]), chosen by the
//! number type through [`crate::Ring::Coords`]:
//!
//! * [`Vec<T>`] for the exact and symbolic numbers ([`crate::Rational`], [`crate::Poly`]) and
//!   the interval types, whose values live on the heap anyway;
//! * [`SmallCoords<T, 8>`] for `f64` and `f32`: up to 8 coordinates (a planar cubic, a 3-D
//!   quadratic, a 4-D line) are kept inline in the curve, more on the heap. A curve returned by
//!   [`crate::BezierCurve::subsegment`] or `split` then costs no allocation in the cases a
//!   vector-graphics user meets most, which is what makes the returning form as fast as
//!   kurbo's and lyon's stack values (`benches/peers.rs`, group `cubic2d`).
//!
//! Both are one contiguous run of coordinates, point after point: every algorithm reads them
//! as a slice ([`CoordinateBuffer::as_slice`]), so the choice changes where the bytes live and
//! nothing else.

use std::fmt::Debug;

/// A contiguous, growable run of numbers: what a [`crate::BezierCurve`] keeps its coordinates
/// in. Implemented by [`Vec<T>`] and by [`SmallCoords`].
pub trait CoordinateBuffer<T>: Clone + Debug + PartialEq {
    /// The buffer holding `values` (which it may keep or copy).
    fn from_vec(values: Vec<T>) -> Self;
    /// A buffer of `len` copies of `value`.
    fn filled(len: usize, value: T) -> Self;
    /// The numbers, in order.
    fn as_slice(&self) -> &[T];
    /// The numbers, to change in place.
    fn as_mut_slice(&mut self) -> &mut [T];
    /// Shortens to `len` or appends copies of `value` up to `len`.
    fn resize(&mut self, len: usize, value: T);
    /// The numbers as a vector (no copy when they are on the heap already).
    fn into_vec(self) -> Vec<T>;
}

impl<T: Clone + Debug + PartialEq> CoordinateBuffer<T> for Vec<T> {
    fn from_vec(values: Vec<T>) -> Self {
        values
    }
    fn filled(len: usize, value: T) -> Self {
        vec![value; len]
    }
    fn as_slice(&self) -> &[T] {
        self
    }
    fn as_mut_slice(&mut self) -> &mut [T] {
        self
    }
    fn resize(&mut self, len: usize, value: T) {
        Vec::resize(self, len, value);
    }
    fn into_vec(self) -> Vec<T> {
        self
    }
}

/// Up to `N` numbers inline, more on the heap: the coordinate buffer of the float curves.
///
/// Equality and `Debug` are those of the slice, so a curve compares and prints the same
/// whichever way its numbers are held.
#[derive(Clone)]
pub struct SmallCoords<T: Copy, const N: usize>(Repr<T, N>);

#[derive(Clone)]
enum Repr<T: Copy, const N: usize> {
    /// `data[..len]` are the numbers; the rest is filler.
    Inline {
        len: u8,
        data: [T; N],
    },
    Heap(Vec<T>),
}

impl<T: Copy + Debug + PartialEq, const N: usize> CoordinateBuffer<T> for SmallCoords<T, N> {
    #[inline]
    fn from_vec(values: Vec<T>) -> Self {
        match values.first() {
            Some(&first) if values.len() <= N.min(u8::MAX as usize) => {
                let mut data = [first; N];
                data[..values.len()].copy_from_slice(&values);
                SmallCoords(Repr::Inline {
                    len: values.len() as u8,
                    data,
                })
            }
            _ => SmallCoords(Repr::Heap(values)),
        }
    }

    #[inline]
    fn filled(len: usize, value: T) -> Self {
        if len <= N.min(u8::MAX as usize) {
            SmallCoords(Repr::Inline {
                len: len as u8,
                data: [value; N],
            })
        } else {
            SmallCoords(Repr::Heap(vec![value; len]))
        }
    }

    #[inline]
    fn as_slice(&self) -> &[T] {
        match &self.0 {
            Repr::Inline { len, data } => &data[..*len as usize],
            Repr::Heap(values) => values,
        }
    }

    #[inline]
    fn as_mut_slice(&mut self) -> &mut [T] {
        match &mut self.0 {
            Repr::Inline { len, data } => &mut data[..*len as usize],
            Repr::Heap(values) => values,
        }
    }

    #[inline]
    fn resize(&mut self, new_len: usize, value: T) {
        match &mut self.0 {
            Repr::Inline { len, data } if new_len <= N.min(u8::MAX as usize) => {
                let old = *len as usize;
                if new_len > old {
                    data[old..new_len].fill(value);
                }
                *len = new_len as u8;
            }
            Repr::Inline { len, data } => {
                let mut values = Vec::with_capacity(new_len);
                values.extend_from_slice(&data[..*len as usize]);
                values.resize(new_len, value);
                self.0 = Repr::Heap(values);
            }
            Repr::Heap(values) => values.resize(new_len, value),
        }
    }

    fn into_vec(self) -> Vec<T> {
        match self.0 {
            Repr::Inline { len, data } => data[..len as usize].to_vec(),
            Repr::Heap(values) => values,
        }
    }
}

impl<T: Copy + PartialEq, const N: usize> PartialEq for SmallCoords<T, N>
where
    SmallCoords<T, N>: CoordinateBuffer<T>,
{
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Copy + Debug, const N: usize> Debug for SmallCoords<T, N>
where
    SmallCoords<T, N>: CoordinateBuffer<T>,
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.as_slice().fmt(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation on the small buffer against the same operations on a `Vec`, across the
    /// inline limit in both directions.
    #[test]
    fn small_coords_behave_as_a_vec() {
        let mut small = SmallCoords::<f64, 4>::from_vec(vec![1.0, 2.0, 3.0]);
        let mut vec = vec![1.0, 2.0, 3.0];
        assert!(matches!(small.0, Repr::Inline { len: 3, .. }));
        for (len, value) in [(4, 7.0), (2, 0.0), (6, 5.0), (9, -1.0), (1, 0.0), (3, 8.0)] {
            small.resize(len, value);
            vec.resize(len, value);
            assert_eq!(small.as_slice(), &vec[..], "after resize to {len}");
        }
        small.as_mut_slice()[0] = 42.0;
        vec[0] = 42.0;
        assert_eq!(small.clone().into_vec(), vec);
        assert_eq!(format!("{small:?}"), format!("{vec:?}"));
        // Equal contents are equal, inline or not.
        let inline = SmallCoords::<f64, 4>::from_vec(vec.clone());
        assert!(matches!(inline.0, Repr::Inline { .. }));
        assert!(matches!(small.0, Repr::Heap(_)));
        assert_eq!(inline, small);
        assert_ne!(inline, SmallCoords::from_vec(vec![42.0, 5.0]));
        // Past the limit the numbers go to the heap, whole.
        let big = SmallCoords::<f64, 4>::filled(5, 1.5);
        assert!(matches!(big.0, Repr::Heap(_)));
        assert_eq!(big.as_slice(), &[1.5; 5]);
        assert_eq!(
            SmallCoords::<f64, 4>::from_vec(Vec::new()).as_slice(),
            &[] as &[f64]
        );
    }
}
