//! The answer of curve-curve intersection ([`Intersections`]: isolated points and overlaps,
//! exact), below the algorithms that compute it (`curves`, `line`, `components`).

use super::algebraic::AlgebraicReal;
#[cfg(doc)]
use crate::num::ring::Rational;

/// One isolated intersection P(s) = Q(t), certified (see [`Intersections`]): the exact
/// parameters, the exact tangency flag, the correctly rounded point. `Display` writes
/// `s = 1/2, t = ..., point = (x, y)`, then `, tangent` for a tangency.
#[derive(Clone, Debug)]
pub struct IntersectionPoint {
    /// The parameter on the first curve.
    pub s: AlgebraicReal,
    /// The parameter on the second curve.
    pub t: AlgebraicReal,
    /// Whether P'(s) and Q'(t) are parallel (cross product exactly zero).
    pub tangent: bool,
    /// The common point, each coordinate correctly rounded.
    pub point: [f64; 2],
}

/// One maximal common stretch, decided exactly (see [`Intersections`]): P over
/// `[s[0], s[1]]` (`s[0] < s[1]`) traces what Q traces between `t[0]` and `t[1]`, with
/// `P(s[0]) = Q(t[0])` and `P(s[1]) = Q(t[1])`; the ends are exact. `Display` writes
/// `s = [s0, s1], t = [t0, t1]`.
#[derive(Clone, Debug)]
pub struct Overlap {
    /// The ends on the first curve, increasing.
    pub s: [AlgebraicReal; 2],
    /// The matching ends on the second curve (decreasing when the curves run opposite ways).
    pub t: [AlgebraicReal; 2],
}

/// Every intersection of two planar polynomial Bézier curves P (degree n) and Q (degree m)
/// over [0, 1], or of one curve with itself: the answer of [`BezierCurve::intersect`](crate::BezierCurve::intersect),
/// [`BezierCurve::self_intersections`](crate::BezierCurve::self_intersections) (and the same methods of [`crate::Bezier`]`<T, 2>`),
/// [`intersect_curves`](super::curves::intersect_curves) and [`self_intersections`](super::curves::self_intersections).
///
/// # Guarantee
///
/// **Certified**: every intersection is listed, once, and nothing else. Each parameter is an
/// exact [`AlgebraicReal`] (rational, or a root of an integer polynomial with an isolating
/// interval), the tangency flag is decided exactly, each common point is correctly rounded.
/// Overlaps are decided exactly (a common component of the two curves), never by a distance
/// tolerance. Doubles are read exactly (every finite double is a rational): the answer is
/// the exact answer for the curves with those control points.
///
/// # The f64 sub-curve trap
///
/// A sub-curve computed in `f64` at a parameter that is not dyadic is **another curve**: its
/// control points are rounded, so it is not a piece of the original, and the certified answer
/// correctly lists no overlap with the original (at most isolated crossings). To find the
/// overlap, compute the sub-curve exactly, in [`Rational`], and intersect exactly:
///
/// ```
/// use blossom::{BezierCurve, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let points = [[0, 0], [1, 2], [3, 3], [4, 0]];
/// let c = BezierCurve::new(points.iter().map(|p| vec![p[0] as f64, p[1] as f64]).collect())?;
/// // In f64 the piece over [1/3, 2/3] has rounded control points: no overlap with `c`.
/// let rounded_piece = c.subsegment(1.0 / 3.0..2.0 / 3.0);
/// assert!(c.intersect(&rounded_piece)?.overlaps.is_empty());
/// // In exact arithmetic it is the curve itself over [1/3, 2/3]: one overlap.
/// let exact = BezierCurve::new(points.iter().map(|p| vec![q(p[0], 1), q(p[1], 1)]).collect())?;
/// let piece = exact.subsegment(q(1, 3)..q(2, 3));
/// let x = exact.intersect(&piece)?;
/// assert_eq!(x.overlaps.len(), 1);
/// assert_eq!(x.overlaps[0].s[0].exact(), Some(&q(1, 3)));
/// assert_eq!(x.overlaps[0].t[1].exact(), Some(&q(1, 1)));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Limits
///
/// Any degree n, m >= 1 (a curve of one control point is refused; one whose control points
/// are all equal is a single point, answered as below). No budget is enforced here: for a
/// transversal `f64` pair a float filter ([`crate::certified_crossings_f64`]) proves the
/// answer in microseconds and the exact parameters cost two resultants; otherwise the cost
/// grows about as (n m)^2 operations on integers of (n + m)(bits + n + m) bits (measured on
/// a 2-core machine in release: random pairs of degree 20 with small rational coordinates
/// 0.6-1.6 s, degree 28 4-7 s). Bound the degree, or run under the `meter` feature's budget,
/// when the input is not yours.
///
/// `Display` writes one line per point, then one per overlap (`overlap: s = [..], t = [..]`),
/// or `no intersection`.
///
/// # Method
///
/// **Isolated points.** With the power forms of the control points (the library's
/// [`bernstein_to_power`](crate::engine::bernstein_to_power)), the common denominators of
/// each coordinate cleared,
/// A(s, t) = P_x(s) - Q_x(t) and B(s, t) = P_y(s) - Q_y(t) are integer polynomials with
/// constant leading coefficients in s and in t, and their common zeros in [0, 1]^2 are the
/// intersections. An exact bivariate solver finds them through the resultants Res_t and
/// Res_s and first subresultants; a pair is tangential exactly when its intersection multiplicity exceeds one,
/// i.e. when the Jacobian det d(A, B)/d(s, t) = -cross(P'(s), Q'(t)) vanishes (a zero
/// derivative included). The common point is P(s) exactly (rounded) when s or t is rational,
/// else each coordinate P_x(s), P_y(s) is rounded correctly by refining s until the interval
/// value of the coordinate has one rounding (a rounding boundary in it is decided by the exact
/// sign of P_x - m at s).
///
/// **Overlaps.** Res_t(A, B) vanishes identically exactly when A and B share a factor, i.e.
/// the curves share a component. Then both are decomposed as P = R(phi), Q = R(g) with R
/// proper and the answer is decided exactly (overlaps between the monotone
/// pieces of phi and g, cut at turning points that may be irrational algebraic numbers,
/// touching points, and R's own double points): curves on one line, reparametrised curves
/// such as Q(t) = P(t^2), and curves that retrace themselves are all answered.
///
/// **Single points.** A curve whose control points are all one point c is accepted. Every s
/// then pairs with each t where the other curve passes through c (the roots in [0, 1] of
/// gcd(Q_x - c_x, Q_y - c_y)); these pairs are not isolated, so each is reported as an
/// overlap whose range on the single-point curve is all of [0, 1] and whose range on the
/// other is the one value (t0 = t1): P maps [0, 1] onto the same set, {c}, as Q maps
/// [t0, t0]. Two single points give one overlap [0, 1] x [0, 1] when equal, else nothing. A
/// single point with itself gives one overlap in the form of a curve that retraces itself
/// (t0 > t1, s1 <= t1): s = [0, 1/2], t = [1, 1/2], the two halves of the
/// curve tracing the same set; every pair s < t is a double point and none is listed apart.
///
/// **Self-intersection.** D(s, t) = (P(s) - P(t)) / (s - t) (exact division: the divided
/// differences of the power coefficients, sum_k p_k sum_(i + j = k - 1) s^i t^j) vanishes off
/// the diagonal exactly where P(s) = P(t); pairs s < t are kept (s = t only at cusps).
/// A closed curve gives (0, 1). The Jacobian of D at a solution is -cross(P'(s), P'(t)) /
/// (s - t)^2, so the tangency rule is the same. A curve that retraces itself (D has a
/// factor of its own, P = R(phi) with deg phi > 1) gives overlaps with t0 > t1, s1 <= t1,
/// one per pair of monotone pieces of phi whose images overlap (decided as above).
#[derive(Clone, Debug, Default)]
pub struct Intersections {
    /// Isolated points, sorted by s then t.
    pub points: Vec<IntersectionPoint>,
    /// Overlaps, sorted by their first s.
    pub overlaps: Vec<Overlap>,
}
