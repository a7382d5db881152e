//! B-spline curves F(u) = sum_k d_k N_k^p(u) and de Boor's algorithm as blossom evaluation
//! (Theorems 2.2 and 2.3 of seed 002).
//!
//! On a non-empty span [t_s, t_{s+1}) the curve is a polynomial F_s of degree p with blossom
//! f_s, and the de Boor points are its blossom values d_k = f_s(t_{k+1}, ..., t_{k+p}),
//! k = s - p..=s (Theorem 2.2). De Boor's recurrence
//!
//! d_i^r = (1 - w_i^r) d_{i-1}^r-1 + w_i^r d_i^{r-1},  w_i^r = (x_r - t_i) / (t_{i+p+1-r} - t_i),
//!
//! run with one argument x_r per level, computes
//! d_i^r = f_s(t_{i+1}, ..., t_s, x_1, ..., x_r, t_{s+1}, ..., t_{i+p-r}) (claim (1) in the proof
//! of Theorem 2.3), so d_s^p = f_s(x_1, ..., x_p): the blossom at any arguments, and with all
//! x_r = t the point F(t). On a non-empty span every denominator is positive
//! (t_i <= t_s < t_{s+1} <= t_{i+p+1-r}), so the paper's 0/0 convention is never needed.
//!
//! Knot insertion and the split into Bézier pieces are further blossom values of the spans.

use super::knots::KnotVector;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::Field;
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;

/// A B-spline curve of degree p: a validated knot vector and m de Boor points.
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline<T> {
    knots: KnotVector<T>,
    control_points: Vec<Point<T>>,
}

/// One polynomial piece of a spline, in Bézier form over [0, 1] for the parameter
/// (u - a) / (b - a) of its interval [a, b].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(
        deny_unknown_fields,
        bound(
            serialize = "T: crate::Ring + serde::Serialize",
            deserialize = "T: crate::Ring + serde::Deserialize<'de>"
        )
    )
)]
pub struct BezierPiece<T> {
    /// The interval [a, b] of the global parameter.
    pub interval: [T; 2],
    /// The piece's Bézier curve, b_i = f(a^(p-i), b^i).
    pub curve: BezierCurve<T>,
}

impl<T: Field> BSpline<T> {
    /// The B-spline of degree `degree` with knots `knots` (m + p + 1 of them) and de Boor points
    /// `control_points` (m of them, all of one dimension D >= 1).
    ///
    /// # Errors
    /// [`ErrorKind::Empty`] or [`ErrorKind::Dimension`] on `control_points` as
    /// [`BezierCurve::new`]; [`ErrorKind::Shape`] on `control_points` when m < p + 1 and on
    /// `knots` when there are not m + p + 1; otherwise as [`KnotVector::new`] (knots that are
    /// not finite, out of order or of too high a multiplicity).
    ///
    /// ```
    /// use blossom::BSpline;
    /// // The de Boor algorithm example of seed 002: F(0.8) = (2.6, 2.92).
    /// let f = BSpline::new(
    ///     2,
    ///     vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
    ///     vec![vec![1.0, 1.0], vec![2.0, 3.0], vec![4.0, 3.0], vec![3.0, 1.0]],
    /// )?;
    /// let x: Vec<f64> = f.eval(&0.8)?;
    /// assert!((x[0] - 2.6).abs() < 1e-12 && (x[1] - 2.92).abs() < 1e-12);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn new(degree: usize, knots: Vec<T>, control_points: Vec<Point<T>>) -> Result<Self> {
        // The same points as a Bézier polygon: at least one, all of one dimension D >= 1.
        let control_points = BezierCurve::new(control_points)?.into_control_points();
        let m = control_points.len();
        if m <= degree {
            return Err(Error::of(ErrorKind::Shape,
                "control_points",
                format!(
                    "a B-spline of degree {degree} needs at least p + 1 = {} de Boor points (Theorem 2.3, ii), found {m}",
                    degree as u128 + 1
                ),
            ));
        }
        if knots.len() != m + degree + 1 {
            return Err(Error::of(
                ErrorKind::Shape,
                "knots",
                format!(
                    "{m} de Boor points of degree {degree} need m + p + 1 = {} knots, found {}",
                    m + degree + 1,
                    knots.len()
                ),
            ));
        }
        Ok(BSpline {
            knots: KnotVector::new(degree, knots)?,
            control_points,
        })
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The knots.
    pub fn knots(&self) -> &[T] {
        self.knots.knots()
    }

    /// The validated knot vector.
    pub fn knot_vector(&self) -> &KnotVector<T> {
        &self.knots
    }

    /// The de Boor points d_1..d_m (0-based).
    pub fn control_points(&self) -> &[Point<T>] {
        &self.control_points
    }

    /// The dimension D of the points.
    pub fn dim(&self) -> usize {
        self.control_points[0].len()
    }

    /// The domain [t_{p+1}, t_{m+1}].
    pub fn domain(&self) -> (&T, &T) {
        self.knots.domain()
    }

    /// De Boor's table on span `s` with one argument per level: `table[r][j]` is d_i^r for
    /// i = s - p + r + j (Theorem 2.3), the de Boor points at level 0 and f_s(args) at level p.
    /// `s` must be a non-empty domain span and `args.len()` the degree.
    pub(crate) fn de_boor_table(&self, s: usize, args: &[T]) -> Vec<Vec<Point<T>>> {
        de_boor_table(&self.knots, s, self.window(s), args)
    }

    /// The de Boor points d_{s-p}..d_s that act on span `s`.
    fn window(&self, s: usize) -> &[Point<T>] {
        &self.control_points[s - self.degree()..=s]
    }

    /// The blossom f_s(args) of the polynomial piece on the non-empty domain span `s`
    /// (0-based: `[knots[s], knots[s+1])`), by de Boor's algorithm with one argument per level.
    pub fn blossom(&self, s: usize, args: &[T]) -> Result<Point<T>> {
        if !self.knots.is_span(s) {
            return Err(Error::of(
                ErrorKind::Domain,
                "span",
                format!(
                    "{s} is not a non-empty span of the domain (spans: {:?})",
                    self.knots.spans()
                ),
            ));
        }
        if args.len() != self.degree() {
            return Err(Error::of(
                ErrorKind::Arity,
                "args",
                format!(
                    "a blossom of degree {} takes {} arguments, found {}",
                    self.degree(),
                    self.degree(),
                    args.len()
                ),
            ));
        }
        Ok(self.blossom_unchecked(s, args))
    }

    pub(crate) fn blossom_unchecked(&self, s: usize, args: &[T]) -> Point<T> {
        de_boor_blossom(&self.knots, s, self.window(s), args)
    }

    /// De Boor's full table at parameter t: the span k (0-based) with t_k <= t < t_{k+1} and
    /// `table[r][j]` = d_i^r(t) for i = k - p + r + j; F(t) = `table[p][0]`.
    pub fn de_boor(&self, t: &T) -> Result<(usize, Vec<Vec<Point<T>>>)> {
        let k = self.knots.span(t)?;
        Ok((k, self.de_boor_table(k, &vec![t.clone(); self.degree()])))
    }

    /// F(t) by de Boor's algorithm (Theorem 2.3). At the right end of the domain the last span
    /// is used.
    ///
    /// # Errors
    /// As [`KnotVector::span`]: [`ErrorKind::NotFinite`] on `t` for a NaN or an infinity,
    /// [`ErrorKind::Domain`] on `t` outside the domain.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        let k = self.knots.span(t)?;
        Ok(self.blossom_unchecked(k, &vec![t.clone(); self.degree()]))
    }

    /// The Bézier pieces: on every non-empty domain span [a, b], b_i = f_s(a^(p-i), b^i).
    pub fn bezier_pieces(&self) -> Vec<BezierPiece<T>> {
        let t = self.knots();
        self.knots
            .spans()
            .into_iter()
            .map(|s| BezierPiece {
                interval: [t[s].clone(), t[s + 1].clone()],
                curve: BezierCurve::new(bezier_points(&self.knots, s, self.window(s)))
                    .expect("p + 1 points of one dimension"),
            })
            .collect()
    }

    /// The same curve with the knot `x` inserted once (Boehm's algorithm read as blossoms).
    ///
    /// With x in the span s, the new knot vector T' has x after t_s, and by Theorem 2.2 the new
    /// de Boor points are d'_k = f_s(t'_{k+1}, ..., t'_{k+p}) for k = s - p + 1..=s; the others
    /// are old points (their knot windows do not contain x). An error names `x` outside the
    /// domain, or `knots` when x would exceed multiplicity p + 1.
    pub fn insert_knot(&self, x: &T) -> Result<BSpline<T>> {
        let (knots, control_points) = insert_knot(&self.knots, &self.control_points, x)?;
        Ok(BSpline {
            knots,
            control_points,
        })
    }
}

// The algorithms on a knot vector and a list of de Boor points of any length. Every step is an
// affine combination taken coordinate by coordinate, so a point may be a whole row of a
// surface's control grid flattened into one long point (the tensor-product surfaces of
// `surface.rs` run the curve algorithms this way, one variable at a time).

/// De Boor's table (Theorem 2.3) on the non-empty domain span `s` of `knots` from the
/// de Boor points `window` = d_{s-p}..d_s, one argument x_r per level: `table[r][j]` is d_i^r
/// for i = s - p + r + j, so level 0 is `window` and level p is f_s(args).
pub(crate) fn de_boor_table<T: Field>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[Point<T>],
    args: &[T],
) -> Vec<Vec<Point<T>>> {
    let p = knots.degree();
    let t = knots.knots();
    debug_assert!(knots.is_span(s) && args.len() == p && window.len() == p + 1);
    let mut table = vec![window.to_vec()];
    for (r, x) in (1..=p).zip(args) {
        let prev = &table[r - 1];
        let level = (s - p + r..=s)
            .map(|i| {
                let j = i - (s - p + r);
                let w = x.sub(&t[i]).divide(&t[i + p + 1 - r].sub(&t[i]));
                crate::shape::point::lerp(&prev[j], &prev[j + 1], &w)
            })
            .collect();
        table.push(level);
    }
    table
}

/// The blossom f_s(args) on the non-empty domain span `s` from the de Boor points
/// `window` = d_{s-p}..d_s: the last level of [`de_boor_table`].
pub(crate) fn de_boor_blossom<T: Field>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[Point<T>],
    args: &[T],
) -> Point<T> {
    de_boor_table(knots, s, window, args)
        .pop()
        .and_then(|mut l| l.pop())
        .expect("level p has one point")
}

/// The Bézier points b_i = f_s(a^(p-i), b^i), i = 0..=p, of the piece on the non-empty domain
/// span `s` = [a, b] from the de Boor points `window` = d_{s-p}..d_s.
pub(crate) fn bezier_points<T: Field>(
    knots: &KnotVector<T>,
    s: usize,
    window: &[Point<T>],
) -> Vec<Point<T>> {
    let p = knots.degree();
    let (a, b) = (&knots.knots()[s], &knots.knots()[s + 1]);
    (0..=p)
        .map(|i| {
            de_boor_blossom(
                knots,
                s,
                window,
                &crate::restrict::nets::repeated(a, p - i, b, i),
            )
        })
        .collect()
}

/// The knot vector and de Boor points `points` (all m of them) with `x` inserted once:
/// with x in the span s, d'_k = f_s(t'_{k+1}, ..., t'_{k+p}) for k = s - p + 1..=s (Theorem
/// 2.2 on the new knot vector T'), the other points unchanged. An error names `x` outside the
/// domain, or `knots[i]` when x would exceed multiplicity p + 1.
pub(crate) fn insert_knot<T: Field>(
    knots: &KnotVector<T>,
    points: &[Point<T>],
    x: &T,
) -> Result<(KnotVector<T>, Vec<Point<T>>)> {
    let p = knots.degree();
    let s = knots
        .span(x)
        .map_err(|e| Error::of(e.kind, "x", e.message))?;
    let mut new = knots.knots().to_vec();
    new.insert(s + 1, x.clone());
    let new = KnotVector::new(p, new)?;
    let t = new.knots();
    let window = &points[s - p..=s];
    let mut out = Vec::with_capacity(points.len() + 1);
    out.extend_from_slice(&points[..=s - p]);
    for k in s - p + 1..=s {
        out.push(de_boor_blossom(knots, s, window, &t[k + 1..=k + p]));
    }
    out.extend_from_slice(&points[s..]);
    Ok((new, out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    fn example() -> BSpline<Rational> {
        // The de Boor algorithm example of seed 002.
        let knots = [0, 0, 0, 1, 2, 2, 2].map(|k| q(k, 1)).to_vec();
        let pts = [(1, 1), (2, 3), (4, 3), (3, 1)]
            .map(|(x, y)| vec![q(x, 1), q(y, 1)])
            .to_vec();
        BSpline::new(2, knots, pts).unwrap()
    }

    #[test]
    fn f_of_four_fifths() {
        assert_eq!(example().eval(&q(4, 5)).unwrap(), vec![q(13, 5), q(73, 25)]);
    }

    #[test]
    fn insertion_keeps_the_curve() {
        let f = example();
        let g = f
            .insert_knot(&q(1, 2))
            .unwrap()
            .insert_knot(&q(1, 1))
            .unwrap();
        assert_eq!(g.control_points().len(), 6);
        for k in 0..=8 {
            let t = q(k, 4);
            assert_eq!(f.eval(&t).unwrap(), g.eval(&t).unwrap(), "t = {t}");
        }
        // The end knot 2 already has multiplicity p + 1.
        assert_eq!(f.insert_knot(&q(2, 1)).unwrap_err().field, "knots[7]");
        assert_eq!(f.insert_knot(&q(3, 1)).unwrap_err().field, "x");
    }

    #[test]
    fn count_mismatch_is_an_error() {
        let e = BSpline::new(
            1,
            vec![q(0, 1), q(0, 1), q(1, 1)],
            vec![vec![q(0, 1)], vec![q(1, 1)]],
        )
        .unwrap_err();
        assert_eq!(e.field, "knots");
    }
}
