//! The exact error of somebody else's floating-point answer to a restriction.
//!
//! Another program (kurbo, lyon, a GPU kernel) restricts a curve in `f64` and returns control
//! points ŵ_i. The reference is the exact answer w_i for the exact values of the same input
//! doubles: every double is a dyadic rational, so the inputs are converted without rounding
//! ([`Rational::from_float`]), restricted in exact arithmetic, and compared with the answer's
//! doubles, also taken exactly. The errors are exact rationals, with their nearest doubles
//! ([`rational_to_f64`]) for display.
//!
//! The definitions of the errors are those of [`AnswerError`].

use crate::error::{Error, ErrorKind, Result};
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::bezier::BezierCurve;
use crate::shape::point::Point;
use num_traits::{Signed, Zero};

/// The error of one control point of an answer: absolute e_i and relative r_i (definitions
/// at [`AnswerError`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PointError {
    /// e_i = max_k |ŵ_ik - w_ik|, exactly.
    pub abs: Rational,
    /// r_i = e_i / max_k |w_ik| (with the conventions for an exact zero point), exactly.
    pub rel: Rational,
}

impl PointError {
    /// The nearest double of [`PointError::abs`].
    pub fn abs_f64(&self) -> f64 {
        rational_to_f64(&self.abs)
    }

    /// The nearest double of [`PointError::rel`].
    pub fn rel_f64(&self) -> f64 {
        rational_to_f64(&self.rel)
    }
}

/// The exact error of an `f64` answer against the exact control points: per point, and the
/// largest absolute and relative errors with the (first) index of the point where each occurs.
///
/// # Definitions
///
/// For control point i with exact coordinates w_ik and answer coordinates ŵ_ik:
///
/// * the **absolute error** is e_i = max_k |ŵ_ik - w_ik|;
/// * the **scale** of the point is s_i = max_k |w_ik|, and S = max_i s_i that of the answer;
/// * the **relative error** is r_i = e_i / s_i when s_i > 0. When the exact point is 0
///   (s_i = 0), r_i = 0 if e_i = 0, and otherwise e_i / S, measured against the largest exact
///   coordinate of all control points (and against 1 when every exact coordinate is 0, so that
///   r_i = e_i then).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AnswerError {
    /// max_i e_i.
    pub max_abs: Rational,
    /// The first i with e_i = max_abs.
    pub max_abs_at: usize,
    /// max_i r_i.
    pub max_rel: Rational,
    /// The first i with r_i = max_rel.
    pub max_rel_at: usize,
    /// (e_i, r_i) for every control point, in the order of the input.
    pub per_point: Vec<PointError>,
}

impl AnswerError {
    /// The nearest double of [`AnswerError::max_abs`].
    pub fn max_abs_f64(&self) -> f64 {
        rational_to_f64(&self.max_abs)
    }

    /// The nearest double of [`AnswerError::max_rel`].
    pub fn max_rel_f64(&self) -> f64 {
        rational_to_f64(&self.max_rel)
    }
}

/// The exact value of the double `x` (every finite double is a dyadic rational), or an
/// [`ErrorKind::NotFinite`] error about `field`.
fn exact_double(x: f64, field: impl FnOnce() -> String) -> Result<Rational> {
    Rational::from_float(x).ok_or_else(|| {
        Error::of(
            ErrorKind::NotFinite,
            field(),
            format!("expected a finite number, found {x}"),
        )
    })
}

/// The index of the first largest of `xs` (0 for an empty list) with a copy of it.
fn first_max<'a>(xs: impl Iterator<Item = &'a Rational>) -> (Rational, usize) {
    let mut best = (Rational::zero(), 0);
    for (i, x) in xs.enumerate() {
        if i == 0 || *x > best.0 {
            best = (x.clone(), i);
        }
    }
    best
}

/// The exact error of `answer` against the exact control points `exact` (definitions at
/// [`AnswerError`]).
///
/// ```
/// use blossom::{exact_error, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let exact = vec![vec![q(1, 3), q(0, 1)], vec![q(2, 1), q(-4, 1)]];
/// let err = exact_error(&exact, &[vec![1.0 / 3.0, 0.0], vec![2.0, -4.5]])?;
/// assert_eq!((err.max_abs.clone(), err.max_abs_at), (q(1, 2), 1));
/// assert_eq!(err.max_rel, q(1, 8)); // 1/2 against max(|2|, |-4|) = 4
/// assert!(err.per_point[0].rel_f64() < 1e-16);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::Empty`] when `exact` is empty; [`ErrorKind::Shape`] at `control_points` when
/// the numbers of points differ; [`ErrorKind::Dimension`] at `control_points[i]` when point i
/// has a different number of coordinates; [`ErrorKind::NotFinite`] at `control_points[i][k]`
/// for a NaN or infinite answer coordinate.
pub fn exact_error(exact: &[Point<Rational>], answer: &[Point<f64>]) -> Result<AnswerError> {
    if exact.is_empty() {
        return Err(Error::of(
            ErrorKind::Empty,
            "control_points",
            "no control points to compare",
        ));
    }
    if exact.len() != answer.len() {
        return Err(Error::of(
            ErrorKind::Shape,
            "control_points",
            format!("expected {} points, found {}", exact.len(), answer.len()),
        ));
    }
    // (e_i, s_i) per point.
    let mut measured = Vec::with_capacity(exact.len());
    for (i, (w, a)) in exact.iter().zip(answer).enumerate() {
        if w.len() != a.len() {
            return Err(Error::of(
                ErrorKind::Dimension,
                format!("control_points[{i}]"),
                format!("expected {} coordinates, found {}", w.len(), a.len()),
            ));
        }
        let mut abs = Rational::zero();
        let mut scale = Rational::zero();
        for (k, (wk, ak)) in w.iter().zip(a).enumerate() {
            let ak = exact_double(*ak, || format!("control_points[{i}][{k}]"))?;
            abs = abs.max((ak - wk).abs());
            scale = scale.max(wk.abs());
        }
        measured.push((abs, scale));
    }
    let (largest, _) = first_max(measured.iter().map(|(_, s)| s));
    let per_point: Vec<PointError> = measured
        .into_iter()
        .map(|(abs, scale)| {
            let rel = if !scale.is_zero() {
                &abs / scale
            } else if abs.is_zero() {
                Rational::zero()
            } else if !largest.is_zero() {
                &abs / &largest
            } else {
                abs.clone()
            };
            PointError { abs, rel }
        })
        .collect();
    let (max_abs, max_abs_at) = first_max(per_point.iter().map(|p| &p.abs));
    let (max_rel, max_rel_at) = first_max(per_point.iter().map(|p| &p.rel));
    Ok(AnswerError {
        max_abs,
        max_abs_at,
        max_rel,
        max_rel_at,
        per_point,
    })
}

/// The exact error of `answer`, somebody's `f64` control points of the Bézier curve `curve`
/// (over [0, 1]) restricted to [a, b]: the reference is the exact restriction of the exact
/// values of the same doubles (`curve`'s coordinates, `a`, `b`), computed in [`Rational`] by
/// [`BezierCurve::subsegment`] (control points b[a^(n-j), b^j] of the blossom, by the halving net
/// of Bernstein steps), so without any rounding; then [`exact_error`].
///
/// ```
/// use blossom::{check_bezier_restriction, BezierCurve};
/// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 3.0], vec![4.0, 0.0]])?;
/// let ours = c.subsegment(0.25..0.5);
/// let err = check_bezier_restriction(&c, 0.25, 0.5, &ours.control_points().to_vec())?;
/// assert!(err.max_rel_f64() <= 1e-15);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] at `a`, `b` or `curve.control_points[i][k]` for an input that is
/// not finite; those of [`exact_error`] for the answer.
pub fn check_bezier_restriction(
    curve: &BezierCurve<f64>,
    a: f64,
    b: f64,
    answer: &[Point<f64>],
) -> Result<AnswerError> {
    let points = curve
        .control_points()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            p.iter()
                .enumerate()
                .map(|(k, x)| exact_double(*x, || format!("curve.control_points[{i}][{k}]")))
                .collect::<Result<Point<Rational>>>()
        })
        .collect::<Result<Vec<_>>>()?;
    let a = exact_double(a, || String::from("a"))?;
    let b = exact_double(b, || String::from("b"))?;
    let exact = BezierCurve::new(points)?.subsegment(a..b);
    exact_error(&exact.control_points().to_vec(), answer)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn zero_points_follow_the_stated_conventions() {
        let exact = vec![vec![q(0, 1)], vec![q(4, 1)], vec![q(0, 1)]];
        let err = exact_error(&exact, &[vec![0.0], vec![4.0], vec![1.0]]).unwrap();
        assert_eq!(err.per_point[0].rel, q(0, 1));
        assert_eq!(err.per_point[2].rel, q(1, 4));
        assert_eq!((err.max_abs.clone(), err.max_abs_at), (q(1, 1), 2));
        // Every exact coordinate 0: measured against 1.
        let err = exact_error(&[vec![q(0, 1)]], &[vec![0.5]]).unwrap();
        assert_eq!(err.max_rel, q(1, 2));
    }

    #[test]
    fn bad_answers_name_the_path() {
        let exact = vec![vec![q(1, 1), q(2, 1)]; 3];
        let e = exact_error(&exact, &vec![vec![1.0, 2.0]; 2]).unwrap_err();
        assert_eq!((e.kind(), e.path()), (ErrorKind::Shape, "control_points"));
        let e = exact_error(&exact, &[vec![1.0, 2.0], vec![1.0], vec![1.0, 2.0]]).unwrap_err();
        assert_eq!(
            (e.kind(), e.path()),
            (ErrorKind::Dimension, "control_points[1]")
        );
        let mut bad = vec![vec![1.0, 2.0]; 3];
        bad[2][1] = f64::NAN;
        let e = exact_error(&exact, &bad).unwrap_err();
        assert_eq!(
            (e.kind(), e.path()),
            (ErrorKind::NotFinite, "control_points[2][1]")
        );
        assert_eq!(exact_error(&[], &[]).unwrap_err().kind(), ErrorKind::Empty);
        let c = BezierCurve::new(vec![vec![0.0], vec![1.0]]).unwrap();
        let e = check_bezier_restriction(&c, 0.0, f64::INFINITY, &vec![vec![0.0]; 2]).unwrap_err();
        assert_eq!(e.path(), "b");
    }

    #[test]
    fn a_perturbation_is_measured_exactly() {
        let c = BezierCurve::new(vec![vec![1.0], vec![3.0], vec![2.0]]).unwrap();
        // Exact on [0, 1/2]: 1, 2, 9/4.
        let err = check_bezier_restriction(&c, 0.0, 0.5, &[vec![1.0], vec![2.0], vec![2.5]]);
        let err = err.unwrap();
        assert_eq!((err.max_abs.clone(), err.max_abs_at), (q(1, 4), 2));
        assert_eq!((err.max_rel.clone(), err.max_rel_at), (q(1, 9), 2));
        assert_eq!(err.max_abs_f64(), 0.25);
    }
}
