//! Feature `serde`: `Serialize` and `Deserialize` for the geometry types, generic over the
//! number type `T`.
//!
//! # The documents
//!
//! A type whose fields are private is written as the arguments of its checked constructor,
//! under the constructor's parameter names, and read back *through that constructor*: a
//! document that breaks an invariant (a ragged grid, points of two dimensions, knots out of
//! order, a zero weight, a wrong number of points) is an error of the deserializer carrying the
//! constructor's message and field path, which is then the path inside the document (for
//! example `control_points[1]: expected 2 coordinates, found 1`), never an invalid value.
//!
//! | type | document | read by |
//! |---|---|---|
//! | [`PowerCurve`], [`PowerSurface`] | `{coefficients}` | `new` |
//! | [`PowerTriangle`] | `{coefficients}`, the full triangular array (absent c_ij written as zero) | `new` |
//! | [`BezierCurve`], [`TensorPatch`] | `{control_points}` | `new` |
//! | [`TriangularPatch`] | `{degree, control_points}` | `new` |
//! | [`Bezier`], [`BezierTensor`], [`BezierTriangle`] | `{points}`, `{degree, points}`, `{degree, points}` (points as lists of `D` numbers) | `new` |
//! | [`KnotVector`], [`BSpline`] | `{degree, knots}`, `{degree, knots, control_points}` | `new` |
//! | [`BSplineSurface`] | `{degree, u_knots, v_knots, control_points}` | `new` |
//! | [`RationalCurve`], [`RationalSurface`], [`RationalPowerTriangle`] | `{numerator, denominator}` | `new` |
//! | [`RationalBezierCurve`] | `{points, weights}` | `new` |
//! | [`RationalTensorPatch`], [`RationalTriangularPatch`] | `{points, weights}` (rows `[ν][μ]`), `{degree, points, weights}` | `new` |
//! | [`RationalBSpline`], [`RationalBSplineSurface`] | `{degree, knots, points, weights}`, `{degree, u_knots, v_knots, points, weights}` | `new` |
//!
//! The structs with public fields ([`Piece`](crate::Piece), [`PowerPiece`](crate::PowerPiece),
//! [`BezierPiece`](crate::BezierPiece), [`SurfacePiece`](crate::SurfacePiece),
//! [`BezierCell`](crate::BezierCell); [`RationalBezierCell`](crate::RationalBezierCell) written
//! only) derive both traits where they are defined; their members are checked as above.
//!
//! Unknown fields are refused. Reading what was written gives an equal value, except that a
//! [`PowerTriangle`] kept as a grid ([`PowerTriangle::from_surface`]) comes back as the same
//! polynomial at the same degree in triangular form, and the NURBS types store homogeneous
//! points (w d, w), whose d are written as (w d) / w: exactly d for exact numbers, to within a
//! rounding in floating point.
//!
//! # Numbers
//!
//! `T` is written by its own `Serialize`: `f64` and `f32` as numbers; [`Rational`](crate::Rational)
//! (`BigRational`) the way num-rational writes it, a pair `[numerator, denominator]` of
//! num-bigint integers, each `[sign, [u32 digits, least significant first]]` (1/3 is
//! `[[1, [1]], [1, [3]]]`, -2 is `[[-1, [2]], [1, [1]]]`, 0 is `[[0, []], [1, [1]]]`).
//! num-rational refuses a zero denominator and keeps a fraction as written (`[2, 4]` is read
//! as the unreduced 2/4, equal to 1/2 and reduced by the first arithmetic on it).

use crate::applications::rational::homogeneous::divide_point;
use crate::error::{Error, ErrorKind, Result};
use crate::num::limits::{check_entries, checked_product};
use crate::num::linalg::Field;
use crate::shape::point::{self, Point, Points as FlatPoints};
use crate::shape::simplex::checked_triangle_len;
use crate::{
    BSpline, BSplineSurface, Bezier, BezierCurve, BezierTensor, BezierTriangle, KnotVector,
    PowerCurve, PowerSurface, PowerTriangle, RationalBSpline, RationalBSplineSurface,
    RationalBezierCurve, RationalCurve, RationalPowerTriangle, RationalSurface,
    RationalTensorPatch, RationalTriangularPatch, Ring, TensorPatch, TriangularPatch,
};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

// The documents: one struct per list of field names, generic over the fields' types, so that
// the same struct is written from borrowed data and read into owned data.

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Coefficients<C> {
    coefficients: C,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ControlPoints<P> {
    control_points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct DegreeControlPoints<N, P> {
    degree: N,
    control_points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Points<P> {
    points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct DegreePoints<N, P> {
    degree: N,
    points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Knots<K> {
    degree: usize,
    knots: K,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Spline<K, P> {
    degree: usize,
    knots: K,
    control_points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SplineSurface<K, P> {
    degree: (usize, usize),
    u_knots: K,
    v_knots: K,
    control_points: P,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Quotient<N, D> {
    numerator: N,
    denominator: D,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Weighted<P, W> {
    points: P,
    weights: W,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct DegreeWeighted<N, P, W> {
    degree: N,
    points: P,
    weights: W,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Nurbs<K, P, W> {
    degree: usize,
    knots: K,
    points: P,
    weights: W,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct NurbsSurface<K, P, W> {
    degree: (usize, usize),
    u_knots: K,
    v_knots: K,
    points: P,
    weights: W,
}

/// The value `read` builds (a checked constructor, possibly after checks of its own with `?`).
fn checked<V>(read: impl FnOnce() -> Result<V>) -> Result<V> {
    read()
}

/// `Serialize` for `$ty<T>` or, for the fixed-dimension shapes, `$ty<T, D>` (with
/// `T: $bound`) writing the document `$write` built from `$this`, and `Deserialize` reading
/// the document type `$doc` into `$this` and returning `$read`, a `Result` of the checked
/// constructor whose error becomes the deserializer's.
macro_rules! through_constructor {
    ($ty:ident<T: $bound:ident $(, const $d:ident: usize)?>,
     |$this:ident| $write:expr, |$doc:ident: $doc_ty:ty| $read:expr) => {
        impl<T: $bound + Serialize $(, const $d: usize)?> Serialize for $ty<T $(, $d)?> {
            fn serialize<S: Serializer>(
                &self,
                serializer: S,
            ) -> std::result::Result<S::Ok, S::Error> {
                let $this = self;
                $write.serialize(serializer)
            }
        }

        impl<'de, T: $bound + Deserialize<'de> $(, const $d: usize)?> Deserialize<'de>
            for $ty<T $(, $d)?>
        {
            fn deserialize<De: Deserializer<'de>>(
                deserializer: De,
            ) -> std::result::Result<Self, De::Error> {
                let $doc = <$doc_ty>::deserialize(deserializer)?;
                checked(|| $read).map_err(De::Error::custom)
            }
        }
    };
}

/// A run of flat points is written as the list of its points, each a list of coordinates:
/// the same document as nested vectors.
impl<T: Serialize> Serialize for FlatPoints<'_, T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_seq(self.iter())
    }
}

// Power form.

through_constructor!(
    PowerCurve<T: Ring>,
    |c| Coefficients { coefficients: c.coefficients() },
    |doc: Coefficients<Vec<Point<T>>>| PowerCurve::new(doc.coefficients)
);

through_constructor!(
    PowerSurface<T: Ring>,
    |s| Coefficients { coefficients: s.rows().collect::<Vec<_>>() },
    |doc: Coefficients<Vec<Vec<Point<T>>>>| PowerSurface::new(doc.coefficients)
);

/// The rows of `s` as the full triangular array of its total degree N: row i holds
/// c_i0, ..., c_i(N-i), absent coefficients zero (a grid's rows and the rows it lacks are
/// padded; none is longer, since a stored row i never exceeds N + 1 - i entries).
fn triangular_rows<T: Ring>(s: &PowerTriangle<T>) -> Vec<Vec<Point<T>>> {
    let big_n = s.degree();
    let zero = point::zero::<T>(s.dim());
    (0..=big_n)
        .map(|i| {
            let mut row = s.rows().nth(i).map(|r| r.to_vec()).unwrap_or_default();
            row.resize(big_n + 1 - i, zero.clone());
            row
        })
        .collect()
}

through_constructor!(
    PowerTriangle<T: Ring>,
    |s| Coefficients { coefficients: triangular_rows(s) },
    |doc: Coefficients<Vec<Vec<Point<T>>>>| PowerTriangle::new(doc.coefficients)
);

// Bézier form, runtime dimension.

through_constructor!(
    BezierCurve<T: Ring>,
    |c| ControlPoints { control_points: c.control_points() },
    |doc: ControlPoints<Vec<Point<T>>>| BezierCurve::new(doc.control_points)
);

through_constructor!(
    TensorPatch<T: Ring>,
    |p| ControlPoints { control_points: p.rows().collect::<Vec<_>>() },
    |doc: ControlPoints<Vec<Vec<Point<T>>>>| TensorPatch::new(doc.control_points)
);

through_constructor!(
    TriangularPatch<T: Ring>,
    |p| DegreeControlPoints { degree: p.degree(), control_points: p.control_points() },
    |doc: DegreeControlPoints<usize, Vec<Point<T>>>| TriangularPatch::new(doc.degree, doc.control_points)
);

// Bézier form, fixed dimension: points are written as lists of D numbers (serde has no impl
// for arrays of a generic length) and read back checked to have D coordinates.

/// Points of `D` coordinates as slices.
fn slices<T, const D: usize>(points: &[[T; D]]) -> Vec<&[T]> {
    points.iter().map(|p| &p[..]).collect()
}

/// `points` as arrays of `D` coordinates; [`ErrorKind::Dimension`] on `points[i]` otherwise.
fn arrays<T, const D: usize>(points: Vec<Vec<T>>) -> Result<Vec<[T; D]>> {
    points
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let found = p.len();
            <[T; D]>::try_from(p).map_err(|_| {
                Error::of(
                    ErrorKind::Dimension,
                    format!("points[{i}]"),
                    format!("expected {D} coordinates, found {found}"),
                )
            })
        })
        .collect()
}

/// The number of points (n + 1)(m + 1) of bidegree `degree`, refused on `degree` when it
/// overflows or exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES) (a document can name any degree).
fn tensor_len((n, m): (usize, usize)) -> Result<usize> {
    let what = "the number of control points (n + 1)(m + 1)";
    let rows = check_entries(n.checked_add(1), "degree", what)?;
    let cols = check_entries(m.checked_add(1), "degree", what)?;
    checked_product(&[rows, cols], "degree", what)
}

through_constructor!(
    Bezier<T: Ring, const D: usize>,
    |c| Points {
        points: slices(c.points())
    },
    |doc: Points<Vec<Vec<T>>>| Bezier::new(arrays(doc.points)?)
);

through_constructor!(
    BezierTensor<T: Ring, const D: usize>,
    |p| DegreePoints {
        degree: p.degree(),
        points: slices(p.points())
    },
    |doc: DegreePoints<(usize, usize), Vec<Vec<T>>>| {
        tensor_len(doc.degree)?;
        BezierTensor::new(doc.degree, arrays(doc.points)?)
    }
);

through_constructor!(
    BezierTriangle<T: Ring, const D: usize>,
    |p| DegreePoints {
        degree: p.degree(),
        points: slices(p.points())
    },
    |doc: DegreePoints<usize, Vec<Vec<T>>>| {
        check_entries(
            checked_triangle_len(doc.degree),
            "degree",
            "the number of control points (N + 1)(N + 2) / 2",
        )?;
        BezierTriangle::new(doc.degree, arrays(doc.points)?)
    }
);

// B-splines.

through_constructor!(
    KnotVector<T: Field>,
    |k| Knots { degree: k.degree(), knots: k.knots() },
    |doc: Knots<Vec<T>>| KnotVector::new(doc.degree, doc.knots)
);

through_constructor!(
    BSpline<T: Field>,
    |f| Spline { degree: f.degree(), knots: f.knots(), control_points: f.control_points() },
    |doc: Spline<Vec<T>, Vec<Point<T>>>| BSpline::new(doc.degree, doc.knots, doc.control_points)
);

through_constructor!(
    BSplineSurface<T: Field>,
    |f| SplineSurface {
        degree: f.degree(),
        u_knots: f.u_knots(),
        v_knots: f.v_knots(),
        control_points: f.control_points().collect::<Vec<_>>(),
    },
    |doc: SplineSurface<Vec<T>, Vec<Vec<Point<T>>>>| {
        BSplineSurface::new(doc.degree, doc.u_knots, doc.v_knots, doc.control_points)
    }
);

// Rational forms.

/// A homogeneous point (N, w) split into its numerator point N and its last coordinate w.
fn split<T: Clone>(h: &[T]) -> (Point<T>, T) {
    let (w, n) = h
        .split_last()
        .expect("homogeneous points have D + 1 >= 2 coordinates");
    (n.to_vec(), w.clone())
}

/// Rows of homogeneous points split into rows of numerator points and rows of denominators.
fn split_rows<T: Clone>(rows: &[Vec<Point<T>>]) -> (Vec<Vec<Point<T>>>, Vec<Vec<T>>) {
    rows.iter()
        .map(|row| row.iter().map(|h| split(h)).unzip())
        .unzip()
}

through_constructor!(
    RationalCurve<T: Ring>,
    |c| {
        let (numerator, denominator): (Vec<_>, Vec<_>) =
            c.homogeneous().coefficients().iter().map(|h| split(h)).unzip();
        Quotient { numerator, denominator }
    },
    |doc: Quotient<Vec<Point<T>>, Vec<T>>| RationalCurve::new(&doc.numerator, &doc.denominator)
);

through_constructor!(
    RationalSurface<T: Ring>,
    |s| {
        let (numerator, denominator) = split_rows(&s.homogeneous().to_nested());
        Quotient { numerator, denominator }
    },
    |doc: Quotient<Vec<Vec<Point<T>>>, Vec<Vec<T>>>| {
        RationalSurface::new(&doc.numerator, &doc.denominator)
    }
);

through_constructor!(
    RationalPowerTriangle<T: Ring>,
    |s| {
        let (numerator, denominator) = split_rows(&triangular_rows(s.homogeneous()));
        Quotient { numerator, denominator }
    },
    |doc: Quotient<Vec<Vec<Point<T>>>, Vec<Vec<T>>>| {
        RationalPowerTriangle::new(&doc.numerator, &doc.denominator)
    }
);

through_constructor!(
    RationalBezierCurve<T: Field>,
    |c| Weighted { points: c.points(), weights: c.weights() },
    |doc: Weighted<Vec<Point<T>>, Vec<T>>| RationalBezierCurve::new(doc.points, doc.weights)
);

/// The de Boor points d and weights w of homogeneous points (w d, w), all weights non-zero.
fn project_all<T: Field>(homogeneous: FlatPoints<'_, T>) -> (Vec<Point<T>>, Vec<T>) {
    homogeneous
        .iter()
        .map(|h| {
            let (n, w) = split(h);
            (divide_point(n, &w).expect("the weights are non-zero"), w)
        })
        .unzip()
}

through_constructor!(
    RationalBSpline<T: Field>,
    |f| {
        let h = f.homogeneous();
        let (points, weights) = project_all(h.control_points());
        Nurbs { degree: h.degree(), knots: h.knots(), points, weights }
    },
    |doc: Nurbs<Vec<T>, Vec<Point<T>>, Vec<T>>| {
        RationalBSpline::new(doc.degree, doc.knots, doc.points, doc.weights)
    }
);

through_constructor!(
    RationalBSplineSurface<T: Field>,
    |f| {
        let h = f.homogeneous();
        NurbsSurface {
            degree: h.degree(),
            u_knots: h.u_knots(),
            v_knots: h.v_knots(),
            points: f.points(),
            weights: f.weights(),
        }
    },
    |doc: NurbsSurface<Vec<T>, Vec<Vec<Point<T>>>, Vec<Vec<T>>>| {
        RationalBSplineSurface::new(doc.degree, doc.u_knots, doc.v_knots, doc.points, doc.weights)
    }
);

through_constructor!(
    RationalTensorPatch<T: Field>,
    |p| Weighted {
        points: p.rows().collect::<Vec<_>>(),
        weights: p.weight_rows().collect::<Vec<_>>()
    },
    |doc: Weighted<Vec<Vec<Point<T>>>, Vec<Vec<T>>>| RationalTensorPatch::new(doc.points, doc.weights)
);

through_constructor!(
    RationalTriangularPatch<T: Field>,
    |p| DegreeWeighted { degree: p.degree(), points: p.points(), weights: p.weights() },
    |doc: DegreeWeighted<usize, Vec<Point<T>>, Vec<T>>| {
        RationalTriangularPatch::new(doc.degree, doc.points, doc.weights)
    }
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::applications::rational::homogeneous::lift_all_into;

    #[test]
    fn homogeneous_points_split_into_numerator_and_weight() {
        assert_eq!(split(&[1.0, 2.0, 4.0]), (vec![1.0, 2.0], 4.0));
        let mut lifted = Vec::new();
        lift_all_into(&[1.0, 2.0], 2, &[4.0], &mut lifted);
        assert_eq!(
            project_all(FlatPoints::new(&lifted, 3)),
            (vec![vec![1.0, 2.0]], vec![4.0])
        );
    }
}
