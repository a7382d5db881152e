//! The small trait family of the shapes, in kurbo's manner: one trait per capability, each
//! implemented by every shape that has it, so generic code can evaluate or restrict a shape
//! without knowing which one it is.

use crate::shape::array::{Bezier, BezierTensor, BezierTriangle};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point::Point;
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::Ring;

/// A polynomial shape evaluated at a parameter of its domain: its blossom with all arguments
/// equal.
pub trait Evaluate {
    /// The parameter: t for a curve, (s, t) for a patch (for triangles the affine coordinates
    /// of the reference triangle, i.e. barycentric (s, t, 1 - s - t)).
    type Param;
    /// The point type.
    type Point;
    /// The point at `at`.
    fn eval(&self, at: &Self::Param) -> Self::Point;
}

/// A shape restricted to a subdomain, written as a Bézier shape over the reference domain:
/// its control points are blossom values at the subdomain's corners (equations (1), (6), (12)
/// of the subdivision paper).
pub trait Restrict {
    /// The subdomain: `[a, b]`, `[a, b, c, d]` for [a, b] x [c, d], or three triangle corners
    /// in affine coordinates.
    type Domain;
    /// The Bézier shape over the reference domain.
    type Output;
    /// The restriction to `domain`.
    fn restrict(&self, domain: &Self::Domain) -> Self::Output;
}

macro_rules! evaluate {
    ($ty:ty, $param:ty, $point:ty, |$s:ident, $at:ident| $body:expr) => {
        impl<T: Ring> Evaluate for $ty {
            type Param = $param;
            type Point = $point;
            fn eval(&self, $at: &$param) -> $point {
                let $s = self;
                $body
            }
        }
    };
}

macro_rules! evaluate_array {
    ($ty:ident, $param:ty, |$s:ident, $at:ident| $body:expr) => {
        impl<T: Ring, const D: usize> Evaluate for $ty<T, D> {
            type Param = $param;
            type Point = [T; D];
            fn eval(&self, $at: &$param) -> [T; D] {
                let $s = self;
                $body
            }
        }
    };
}

evaluate!(PowerCurve<T>, T, Point<T>, |s, t| s.eval(t));
evaluate!(PowerSurface<T>, [T; 2], Point<T>, |s, p| s
    .eval(&p[0], &p[1]));
evaluate!(BezierCurve<T>, T, Point<T>, |s, t| s.eval(t));
evaluate!(TensorPatch<T>, [T; 2], Point<T>, |s, p| s
    .eval(&p[0], &p[1]));
evaluate!(TriangularPatch<T>, [T; 2], Point<T>, |s, p| s.eval(p));
evaluate_array!(Bezier, T, |s, t| s.eval(t));
evaluate_array!(BezierTensor, [T; 2], |s, p| s.eval(&p[0], &p[1]));
evaluate_array!(BezierTriangle, [T; 2], |s, p| s.eval(p));

impl<T: Ring> Restrict for PowerCurve<T> {
    type Domain = [T; 2];
    type Output = BezierCurve<T>;
    /// By [`crate::Method::Bulk`].
    fn restrict(&self, [a, b]: &[T; 2]) -> BezierCurve<T> {
        crate::restrict::restrict_power_curve(self, a, b, crate::Method::Bulk)
    }
}

impl<T: Ring> Restrict for BezierCurve<T> {
    type Domain = [T; 2];
    type Output = BezierCurve<T>;
    fn restrict(&self, [a, b]: &[T; 2]) -> BezierCurve<T> {
        self.subsegment(a.clone()..b.clone())
    }
}

impl<T: Ring> Restrict for TensorPatch<T> {
    type Domain = [T; 4];
    type Output = TensorPatch<T>;
    fn restrict(&self, rect: &[T; 4]) -> TensorPatch<T> {
        TensorPatch::restrict(self, rect)
    }
}

impl<T: Ring> Restrict for TriangularPatch<T> {
    type Domain = [[T; 2]; 3];
    type Output = TriangularPatch<T>;
    fn restrict(&self, corners: &[[T; 2]; 3]) -> TriangularPatch<T> {
        TriangularPatch::restrict(self, corners)
    }
}

impl<T: Ring, const D: usize> Restrict for Bezier<T, D> {
    type Domain = [T; 2];
    type Output = Self;
    fn restrict(&self, [a, b]: &[T; 2]) -> Self {
        self.subsegment(a.clone()..b.clone())
    }
}

impl<T: Ring, const D: usize> Restrict for BezierTensor<T, D> {
    type Domain = [T; 4];
    type Output = Self;
    fn restrict(&self, rect: &[T; 4]) -> Self {
        BezierTensor::restrict(self, rect)
    }
}

impl<T: Ring, const D: usize> Restrict for BezierTriangle<T, D> {
    type Domain = [[T; 2]; 3];
    type Output = Self;
    fn restrict(&self, corners: &[[T; 2]; 3]) -> Self {
        BezierTriangle::restrict(self, corners)
    }
}
