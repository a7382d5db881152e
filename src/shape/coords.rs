//! The buffer that holds a Bézier curve's coordinates ([`crate::BezierCurve`]), chosen by the
//! number type through [`crate::Ring::Coords`]:
//!
//! * [`Vec<T>`] for the exact and symbolic numbers ([`crate::Rational`], [`crate::Poly`]) and
//!   the interval types, whose values live on the heap anyway;
//! * [`SmallCoords<T, INLINE_COORDINATES>`] for `f64` and `f32`: up to 12 coordinates (a 3-D
//!   cubic, a planar quintic, a 4-D quadratic) are kept inline in the curve, more on the heap. A curve returned by
//!   [`crate::BezierCurve::subsegment`] or `split` then costs no allocation in the cases a
//!   vector-graphics user meets most, which is what makes the returning form as fast as
//!   kurbo's and lyon's stack values (`benches/peers.rs`, group `cubic2d`).
//!
//! Both are one contiguous run of coordinates, point after point: every algorithm reads them
//! as a slice ([`CoordinateBuffer::as_slice`]), so the choice changes where the bytes live and
//! nothing else.

use std::fmt::Debug;

/// How many coordinates a float curve keeps inline ([`SmallCoords`]): a 3-D cubic (a planar
/// quintic, a 4-D quadratic).
pub const INLINE_COORDINATES: usize = 12;

/// A contiguous, growable run of numbers: what a [`crate::BezierCurve`] keeps its coordinates
/// in. Implemented by [`Vec<T>`] and by [`SmallCoords`].
pub trait CoordinateBuffer<T>: Clone + Debug + PartialEq {
    /// The buffer holding `values` (which it may keep or copy).
    fn from_vec(values: Vec<T>) -> Self;
    /// The buffer holding a copy of `values`.
    fn from_slice(values: &[T]) -> Self;
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
    fn from_slice(values: &[T]) -> Self {
        values.to_vec()
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
/// The layout is chosen for the way a returned curve is used: it is written once, where it is
/// computed, and often moved (returned, stored in a vector, handed to `black_box`) right
/// after, and a move that reads back bytes still on their way to memory waits unless each of
/// its loads lies inside one of the stores that wrote them (store forwarding). So:
///
/// * the inline numbers come first, with no enum tag in front of them, so that the moves'
///   16-byte loads line up with the 16-byte writes of the answer's points (with a tag first,
///   each move of a just-restricted cubic stalled for longer than the restriction took);
/// * the whole curve stays within 128 bytes (the heap part is a boxed slice, two words, not a
///   vector's three), which the compiler moves with inline 16-byte loads and stores; at 136
///   bytes a [`crate::BezierCurve`] was moved by a call of the C library's `memcpy`, whose
///   wider loads (32 or 64 bytes, chosen at run time for the processor) spanned several of
///   the stores just made and waited on all of them (issue 47; how long such a wait lasts is
///   the processor's, which is why the figures moved from machine to machine);
/// * a curve held inline writes as few words beside its numbers as it can: the heap part is
///   an `Option`, whose `None` is one null word (an empty boxed slice is two, a vector's
///   three). Through `black_box`, a planar cubic took 1.4x lyon's time with the empty
///   boxed slice and 1.1x with `None` (`benches/dependent`, `consume`).
///
/// Equality and `Debug` are those of the slice, so a curve compares and prints the same
/// whichever way its numbers are held.
#[derive(Clone)]
#[repr(C)]
pub struct SmallCoords<T: Copy, const N: usize> {
    /// `inline[..len]` are the numbers when `len <= N`; the rest is filler.
    inline: [T; N],
    len: usize,
    /// The numbers when `len > N` (then of length `len`); `None` otherwise, which writes one
    /// word (a null pointer) and leaves the slice's length unwritten.
    heap: Option<Box<[T]>>,
}

impl<T: Copy, const N: usize> SmallCoords<T, N> {
    /// Whether the numbers are in `inline`.
    #[inline]
    pub(crate) fn is_inline(&self) -> bool {
        self.heap.is_none()
    }
}

/// The heap part is freed out of line, behind a test: a loop that restricts
/// small curves and drops the answers then holds no call on its common path, so the compiler
/// keeps its running values in registers instead of saving them around a call in every pass.
impl<T: Copy, const N: usize> Drop for SmallCoords<T, N> {
    #[inline]
    fn drop(&mut self) {
        #[cold]
        #[inline(never)]
        fn free<T>(heap: Box<[T]>) {
            drop(heap);
        }
        if let Some(heap) = self.heap.take() {
            free(heap);
        }
    }
}

impl<T: Copy + Default + Debug + PartialEq, const N: usize> CoordinateBuffer<T>
    for SmallCoords<T, N>
{
    #[inline]
    fn from_vec(values: Vec<T>) -> Self {
        if values.len() <= N {
            Self::from_slice(&values)
        } else {
            SmallCoords {
                inline: [T::default(); N],
                len: values.len(),
                heap: Some(values.into_boxed_slice()),
            }
        }
    }

    #[inline]
    fn from_slice(values: &[T]) -> Self {
        if values.len() > N {
            return Self::from_vec(values.to_vec());
        }
        let mut inline = [T::default(); N];
        inline[..values.len()].copy_from_slice(values);
        SmallCoords {
            inline,
            len: values.len(),
            heap: None,
        }
    }

    /// Past `N`, the numbers are allocated and then written, not allocated zeroed: a zeroed
    /// allocation is `calloc`, which glibc serves past its per-thread cache (and `free` then
    /// finds that cache full), about 300 instructions a curve instead of 50 (issue 47).
    #[inline]
    fn filled(len: usize, value: T) -> Self {
        SmallCoords {
            inline: [value; N],
            len,
            heap: (len > N).then(|| {
                let mut values = Vec::with_capacity(len);
                values.resize(len, value);
                values.into_boxed_slice()
            }),
        }
    }

    #[inline]
    fn as_slice(&self) -> &[T] {
        match &self.heap {
            None => &self.inline[..self.len],
            Some(heap) => heap,
        }
    }

    #[inline]
    fn as_mut_slice(&mut self) -> &mut [T] {
        match &mut self.heap {
            None => &mut self.inline[..self.len],
            Some(heap) => heap,
        }
    }

    #[inline]
    fn resize(&mut self, new_len: usize, value: T) {
        match (self.is_inline(), new_len <= N) {
            (true, true) => {
                if new_len > self.len {
                    self.inline[self.len..new_len].fill(value);
                }
            }
            (true, false) => {
                let mut values = Vec::with_capacity(new_len);
                values.extend_from_slice(&self.inline[..self.len]);
                values.resize(new_len, value);
                self.heap = Some(values.into_boxed_slice());
            }
            (false, true) => {
                // Shrinking below the limit: `new_len < self.len`.
                let heap = self.heap.take().expect("the numbers");
                self.inline[..new_len].copy_from_slice(&heap[..new_len]);
            }
            (false, false) => {
                let mut values = self.heap.take().expect("the numbers").into_vec();
                values.reserve_exact(new_len.saturating_sub(values.len()));
                values.resize(new_len, value);
                self.heap = Some(values.into_boxed_slice());
            }
        }
        self.len = new_len;
    }

    fn into_vec(mut self) -> Vec<T> {
        match self.heap.take() {
            None => self.inline[..self.len].to_vec(),
            Some(heap) => heap.into_vec(),
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
        assert!(small.is_inline() && small.len == 3);
        for (len, value) in [(4, 7.0), (2, 0.0), (6, 5.0), (9, -1.0), (1, 0.0), (3, 8.0)] {
            small.resize(len, value);
            vec.resize(len, value);
            assert_eq!(small.as_slice(), &vec[..], "after resize to {len}");
        }
        small.as_mut_slice()[0] = 42.0;
        vec[0] = 42.0;
        assert_eq!(small.clone().into_vec(), vec);
        assert_eq!(format!("{small:?}"), format!("{vec:?}"));
        // Shrunk below the limit, the numbers are back inline and the heap is freed.
        assert!(small.is_inline() && small.heap.is_none());
        // Equal contents are equal, inline or not; a grown-then-shrunk heap buffer keeps
        // only its first numbers.
        let mut heap = SmallCoords::<f64, 4>::from_vec(vec![42.0, 8.0, 8.0, 1.0, 2.0]);
        assert!(!heap.is_inline());
        heap.resize(3, 0.0);
        assert!(heap.is_inline());
        assert_eq!(heap, small);
        let mut grown = SmallCoords::<f64, 4>::from_vec(vec![42.0]);
        grown.resize(3, 5.0);
        assert_ne!(grown, small);
        grown.as_mut_slice()[1..].fill(8.0);
        assert_eq!(grown, small);
        // Past the limit the numbers go to the heap, whole.
        let big = SmallCoords::<f64, 4>::filled(5, 1.5);
        assert!(!big.is_inline() && big.heap.as_ref().map(|h| h.len()) == Some(5));
        assert_eq!(big.as_slice(), &[1.5; 5]);
        assert_eq!(
            SmallCoords::<f64, 4>::from_vec(Vec::new()).as_slice(),
            &[] as &[f64]
        );
        // A copy of a slice, on either side of the limit, holds the slice, where a vector
        // of the same numbers would be held.
        for len in 0..=6 {
            let values: Vec<f64> = (0..len).map(|i| i as f64 + 0.5).collect();
            let copied = SmallCoords::<f64, 4>::from_slice(&values);
            assert_eq!(copied.as_slice(), &values[..], "from_slice, {len} numbers");
            assert_eq!(copied.is_inline(), len <= 4);
            let heap_len = copied.heap.as_ref().map_or(0, |h| h.len());
            assert_eq!(heap_len, if len <= 4 { 0 } else { len });
        }
    }

    /// The float curves stay within the 128 bytes the compiler moves with inline 16-byte
    /// loads and stores (above, a call of `memcpy`: see [`SmallCoords`]).
    #[test]
    fn float_curves_move_inline() {
        use crate::{Bezier, BezierCurve};
        assert!(std::mem::size_of::<BezierCurve<f64>>() <= 128);
        assert!(std::mem::size_of::<Bezier<f64, 3>>() <= 128);
        assert!(std::mem::size_of::<BezierCurve<f32>>() <= 128);
    }
}
