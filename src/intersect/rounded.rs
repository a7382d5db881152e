//! The `f64` answer of curve-curve intersection for every input: the float filter
//! ([`super::filter::certified_crossings_f64`]) when it proves the complete answer, otherwise
//! the exact path ([`super::curves::intersect_named`]) with every parameter rounded to the
//! nearest double ([`super::algebraic::AlgebraicReal::to_f64`]). Both give the same doubles.
//! The method form is [`crate::BezierCurve::intersect_rounded`] (and the same on
//! [`crate::Bezier`]); the free function [`intersect_curves_f64_rounded`] stays for slices of
//! doubles held anywhere, the fastest call for them (the filter runs on the slices as given).

use super::curves::{intersect_named, pairs, Intersections};
use super::filter::certified_crossings_f64;
use crate::error::Result;
use crate::num::exact::{exact_coordinates, ExactInput};

/// One isolated intersection P(s) = Q(t) of [`RoundedIntersections`]: the exact answer's
/// parameters correctly rounded. `Display` writes `s = 0.5, t = 0.5, point = (0.5, 0.5)`,
/// then `, tangent` for a tangency.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundedPoint {
    /// The double nearest to the exact parameter on the first curve.
    pub s: f64,
    /// The double nearest to the exact parameter on the second curve.
    pub t: f64,
    /// Whether P'(s) and Q'(t) are parallel (decided exactly).
    pub tangent: bool,
    /// The common point, each coordinate correctly rounded.
    pub point: [f64; 2],
}

/// One maximal common stretch, its exact ends correctly rounded (see [`crate::Overlap`]).
/// `Display` writes `s = [s0, s1], t = [t0, t1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundedOverlap {
    /// The ends on the first curve, increasing.
    pub s: [f64; 2],
    /// The matching ends on the second curve.
    pub t: [f64; 2],
}

/// Every intersection of two planar curves, as doubles: the answer of
/// [`BezierCurve::intersect_rounded`](crate::BezierCurve::intersect_rounded) and
/// [`intersect_curves_f64_rounded`].
///
/// Guarantee (**certified**, then correctly rounded): the points and overlaps are those of
/// the exact answer ([`crate::Intersections`], which states the method, the limits and the
/// f64 sub-curve trap), every parameter and every coordinate of a common point the double
/// nearest to the exact value (ties to even), the tangency flag exact. Whether the float
/// filter or the exact path answered, the doubles are the same; `by_filter` says which.
/// `Display` writes one line per point, then one per overlap, or `no intersection`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RoundedIntersections {
    /// Isolated points, sorted by s then t.
    pub points: Vec<RoundedPoint>,
    /// Overlaps, sorted by their first s.
    pub overlaps: Vec<RoundedOverlap>,
    /// Whether the float filter answered (else the exact path did).
    pub by_filter: bool,
}

impl From<&Intersections> for RoundedIntersections {
    /// The exact answer with every parameter rounded to the nearest double.
    fn from(x: &Intersections) -> Self {
        RoundedIntersections {
            points: x
                .points
                .iter()
                .map(|p| RoundedPoint {
                    s: p.s.to_f64(),
                    t: p.t.to_f64(),
                    tangent: p.tangent,
                    point: p.point,
                })
                .collect(),
            overlaps: x
                .overlaps
                .iter()
                .map(|o| RoundedOverlap {
                    s: [o.s[0].to_f64(), o.s[1].to_f64()],
                    t: [o.t[0].to_f64(), o.t[1].to_f64()],
                })
                .collect(),
            by_filter: false,
        }
    }
}

/// Every intersection of the planar curves with control points `p` and `q` (doubles read
/// exactly), as doubles, **certified** then correctly rounded ([`RoundedIntersections`]): the
/// float filter's answer when it proves the complete answer (transversal crossings inside
/// (0, 1)^2, in microseconds), else the exact path's, rounded. The method
/// [`Bezier::intersect_rounded`](crate::Bezier::intersect_rounded) is the same on a curve;
/// this form takes slices of doubles held anywhere. An overlap is found only between the
/// exact curves given: a piece computed in `f64` at a parameter that is not dyadic is
/// another curve ([`crate::Intersections`], "The f64 sub-curve trap").
///
/// ```
/// use blossom::intersect_curves_f64_rounded;
/// // A transversal crossing: the filter answers.
/// let x = intersect_curves_f64_rounded(&[[0.0, 0.0], [1.0, 1.0]], &[[0.0, 1.0], [1.0, 0.0]])?;
/// assert!(x.by_filter);
/// assert_eq!((x.points[0].s, x.points[0].t, x.points[0].point), (0.5, 0.5, [0.5, 0.5]));
/// // An end-point contact: the exact path answers.
/// let y = intersect_curves_f64_rounded(&[[0.0, 0.0], [1.0, 1.0]], &[[1.0, 1.0], [2.0, 0.0]])?;
/// assert!(!y.by_filter);
/// assert_eq!((y.points[0].s, y.points[0].t), (1.0, 0.0));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::Empty`](crate::ErrorKind::Empty) on `p` or `q` for fewer than two control
/// points, [`ErrorKind::NotFinite`](crate::ErrorKind::NotFinite) on `p[i][j]` or `q[i][j]`
/// for a NaN or an infinity.
pub fn intersect_curves_f64_rounded(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
) -> Result<RoundedIntersections> {
    rounded_named(p.as_flattened(), q.as_flattened(), ["p", "q"])
}

/// The rounded intersections of the planar curves with flat control points `p` and `q` (two
/// coordinates per point, of any [`ExactInput`] type), `names` naming them in errors: the
/// filter when both are doubles exactly and it decides, else the exact answer rounded. The
/// one implementation behind [`intersect_curves_f64_rounded`] and the `intersect_rounded`
/// methods.
pub(crate) fn rounded_named<T: ExactInput>(
    p: &[T],
    q: &[T],
    names: [&str; 2],
) -> Result<RoundedIntersections> {
    if let (Some(pd), Some(qd)) = (T::as_doubles(p), T::as_doubles(q)) {
        if let Some(crossings) = certified_crossings_f64(pd.as_chunks().0, qd.as_chunks().0) {
            return Ok(RoundedIntersections {
                // In place: the answer reuses the filter's vector.
                points: crossings
                    .into_iter()
                    .map(|c| RoundedPoint {
                        s: c.s,
                        t: c.t,
                        tangent: false,
                        point: c.point,
                    })
                    .collect(),
                overlaps: Vec::new(),
                by_filter: true,
            });
        }
    }
    let exact_p = pairs(&exact_coordinates(names[0], p, 2)?);
    let exact_q = pairs(&exact_coordinates(names[1], q, 2)?);
    Ok(RoundedIntersections::from(&intersect_named(
        &exact_p, &exact_q, names,
    )?))
}
