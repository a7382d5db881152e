//! A piecewise polynomial as a B-spline: Theorem 2.4 (Curry-Schoenberg) of seed 002, with the
//! de Boor points of Theorem 2.2 as blossom values of the pieces.
//!
//! Pieces F_1..F_K of degree <= p on consecutive intervals e_1 < e_2 < ... < e_{K+1} meet at
//! each interior breakpoint e_i with some exact order of continuity r_i (the highest r with
//! F_{i-1}^(j)(e_i) = F_i^(j)(e_i) for j = 0..r; -1 when the values differ already). The knot
//! vector repeats e_1 and e_{K+1} p + 1 times and e_i exactly u_i = p - r_i times (the
//! observation after Theorem 2.4; a breakpoint where the two pieces are one polynomial
//! disappears), and the de Boor points are d_k = f_j(t_{k+1}, ..., t_{k+p}) for every span j
//! with k = j - p..=j. A de Boor point is defined by up to p + 1 spans; all definitions are
//! computed and checked to agree, which is what the continuity guarantees.

use super::bspline::BSpline;
use super::knots::KnotVector;
use crate::error::{Error, ErrorKind, Result};
use crate::num::limits::{check_entries, checked_product};
use crate::num::linalg::{check_all_finite, Field};
use crate::restrict::definition::curve_blossom;
use crate::shape::basis::taylor_shift;
use crate::shape::point::Point;
use crate::shape::power::PowerCurve;

/// One piece of a piecewise polynomial: `curve` on the interval [e_0, e_1] of the global
/// parameter u (power basis of u).
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
pub struct Piece<T> {
    /// The interval [e_0, e_1], e_0 < e_1.
    pub interval: [T; 2],
    /// The polynomial on it, of degree <= p (leading zero coefficients beyond p are allowed).
    pub curve: PowerCurve<T>,
}

/// The pieces checked against degree `p` and written with exactly p + 1 coefficients each.
fn normalise<T: Field>(p: usize, pieces: &[Piece<T>]) -> Result<Vec<PowerCurve<T>>> {
    let Some(first) = pieces.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            "pieces",
            "expected at least one piece",
        ));
    };
    let dim = first.curve.dim();
    let len = check_entries(
        p.checked_add(1),
        "degree",
        "the number p + 1 of coefficients",
    )?;
    checked_product(
        &[pieces.len(), len, dim],
        "degree",
        "the coefficients of the pieces at degree p",
    )?;
    let mut out = Vec::with_capacity(pieces.len());
    for (i, piece) in pieces.iter().enumerate() {
        let [a, b] = &piece.interval;
        check_all_finite(&piece.interval, &format!("pieces[{i}].interval"))?;
        if a >= b {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("pieces[{i}].interval"),
                format!("expected e_0 < e_1, found [{a}, {b}]"),
            ));
        }
        if i > 0 {
            let prev = &pieces[i - 1].interval[1];
            if a != prev {
                let what = if a > prev {
                    "leaves a gap after"
                } else {
                    "overlaps"
                };
                return Err(Error::of(
                    ErrorKind::Domain,
                    format!("pieces[{i}].interval"),
                    format!("starts at {a}, which {what} the previous piece ending at {prev}"),
                ));
            }
        }
        let c = piece.curve.coefficients();
        if piece.curve.dim() != dim {
            return Err(Error::of(
                ErrorKind::Dimension,
                format!("pieces[{i}].coefficients[0]"),
                format!("expected {dim} coordinates, found {}", piece.curve.dim()),
            ));
        }
        if let Some(k) = (p + 1..c.len()).find(|&k| c[k].iter().any(|x| !x.is_zero())) {
            return Err(Error::of(
                ErrorKind::Degree,
                format!("pieces[{i}].coefficients[{k}]"),
                format!("the piece has degree above p = {p}"),
            ));
        }
        let mut padded: Vec<Point<T>> = c.iter().take(p + 1).map(<[T]>::to_vec).collect();
        padded.resize(p + 1, crate::shape::point::zero(dim));
        out.push(PowerCurve::new(padded)?);
    }
    Ok(out)
}

/// The highest order r in -1..=p of continuity of `left` and `right` (each with p + 1
/// coefficients) at `e`: the number of equal leading Taylor coefficients at e, minus one.
pub fn continuity_at<T: Field>(left: &PowerCurve<T>, right: &PowerCurve<T>, e: &T) -> isize {
    let mut l = left.coefficients().to_vec();
    let mut r = right.coefficients().to_vec();
    taylor_shift(&mut l, e);
    taylor_shift(&mut r, e);
    let n = l.len().max(r.len());
    let dim = left.dim();
    let coef = |c: &[Point<T>], k: usize| {
        c.get(k)
            .cloned()
            .unwrap_or_else(|| crate::shape::point::zero(dim))
    };
    (0..n).take_while(|&k| coef(&l, k) == coef(&r, k)).count() as isize - 1
}

/// The B-spline of degree `degree` equal to the piecewise polynomial `pieces`, with knot
/// multiplicities from the continuity that holds exactly at each breakpoint (Theorem 2.4).
///
/// In float arithmetic the continuity is judged on rounded Taylor coefficients, which rounding
/// can make unequal; the command line (crate `blossom-cli`) therefore decides it on the exact
/// input.
///
/// ```
/// use blossom::{bspline_from_pieces, Piece};
/// use blossom::{PowerCurve, Rational};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // u^2 on [0, 1] and 2u - 1 on [1, 2] meet with C^1: the knot 1 has multiplicity 2 - 1 = 1.
/// let pieces = vec![
///     Piece { interval: [q(0), q(1)], curve: PowerCurve::new(vec![vec![q(0)], vec![q(0)], vec![q(1)]])? },
///     Piece { interval: [q(1), q(2)], curve: PowerCurve::new(vec![vec![q(-1)], vec![q(2)]])? },
/// ];
/// let f = bspline_from_pieces(2, &pieces)?;
/// assert_eq!(f.knots(), &[0, 0, 0, 1, 2, 2, 2].map(q));
/// assert_eq!(f.control_points(), &[vec![q(0)], vec![q(0)], vec![q(2)], vec![q(3)]]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn bspline_from_pieces<T: Field>(degree: usize, pieces: &[Piece<T>]) -> Result<BSpline<T>> {
    let curves = normalise(degree, pieces)?;
    let p = degree;
    let mut knots = vec![pieces[0].interval[0].clone(); p + 1];
    for i in 1..pieces.len() {
        let e = &pieces[i].interval[0];
        let r = continuity_at(&curves[i - 1], &curves[i], e);
        let mult = (p as isize - r) as usize;
        knots.extend(std::iter::repeat_n(e.clone(), mult));
    }
    knots.extend(std::iter::repeat_n(
        pieces[pieces.len() - 1].interval[1].clone(),
        p + 1,
    ));
    // With these multiplicities Theorem 2.4 guarantees agreement; the check is a self-check,
    // meaningful in exact arithmetic only (rounded blossoms of two pieces may differ in the
    // last bits).
    de_boor_points(p, pieces, &curves, knots, T::EXACT)
}

/// The B-spline of degree `degree` on the given knot vector that equals `pieces`: every
/// breakpoint must be a knot, the domain must be [e_1, e_{K+1}], and the de Boor points that
/// several pieces define must agree (they do exactly when each breakpoint's multiplicity u
/// leaves the pieces C^(p-u) there); otherwise an error says which point disagrees. In float
/// arithmetic agreement means bitwise equality of rounded values, so exact numbers are the
/// ones to use here.
pub fn bspline_from_pieces_with_knots<T: Field>(
    degree: usize,
    pieces: &[Piece<T>],
    knots: Vec<T>,
) -> Result<BSpline<T>> {
    let curves = normalise(degree, pieces)?;
    de_boor_points(degree, pieces, &curves, knots, true)
}

fn de_boor_points<T: Field>(
    p: usize,
    pieces: &[Piece<T>],
    curves: &[PowerCurve<T>],
    knots: Vec<T>,
    check_agreement: bool,
) -> Result<BSpline<T>> {
    let kv = KnotVector::new(p, knots)?;
    let t = kv.knots();
    let (lo, hi) = kv.domain();
    let (e0, e1) = (
        &pieces[0].interval[0],
        &pieces[pieces.len() - 1].interval[1],
    );
    if lo != e0 || hi != e1 {
        return Err(Error::of(
            ErrorKind::Domain,
            "knots",
            format!("the domain [{lo}, {hi}] differs from the pieces' interval [{e0}, {e1}]"),
        ));
    }
    let m = kv.control_count();
    // For every de Boor point: (piece index, value) of its first definition.
    let mut points: Vec<Option<(usize, Point<T>)>> = vec![None; m];
    for s in kv.spans() {
        // The pieces overlapping the span; a breakpoint inside a span is allowed only between
        // pieces that are one polynomial (continuity p, multiplicity 0).
        let mut overlapping = (0..pieces.len())
            .filter(|&i| pieces[i].interval[0] < t[s + 1] && t[s] < pieces[i].interval[1]);
        let piece = overlapping
            .next()
            .expect("the domain is covered by the pieces");
        if let Some(other) = overlapping.find(|&i| curves[i] != curves[piece]) {
            return Err(Error::of(ErrorKind::Domain,
                "knots",
                format!(
                    "the span [{}, {}] contains the breakpoint {} (between different polynomials) but it is not a knot",
                    t[s],
                    t[s + 1],
                    pieces[other].interval[0]
                ),
            ));
        }
        for k in s - p..=s {
            let value = curve_blossom(&curves[piece], &t[k + 1..=k + p])?;
            match &points[k] {
                None => points[k] = Some((piece, value)),
                Some((other, v)) if check_agreement && *v != value => {
                    return Err(Error::of(ErrorKind::Invalid,
                        "knots",
                        format!(
                            "the de Boor point d_{} is {} from pieces[{other}] but {} from pieces[{piece}]: \
                             the pieces are less continuous than the knot multiplicities require",
                            k + 1,
                            show(v),
                            show(&value)
                        ),
                    ))
                }
                Some(_) => {}
            }
        }
    }
    let dim = curves[0].dim();
    let mut coords = Vec::with_capacity(m * dim);
    for d in points {
        coords.extend(
            d.expect("every de Boor point is defined by a span of the domain")
                .1,
        );
    }
    BSpline::checked(p, kv.knots().to_vec(), dim, coords, "control_points")
}

fn show<T: Field>(p: &[T]) -> String {
    format!(
        "({})",
        p.iter()
            .map(|x| x.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    fn piece(a: i64, b: i64, c: &[i64]) -> Piece<Rational> {
        Piece {
            interval: [q(a), q(b)],
            curve: PowerCurve::new(c.iter().map(|&x| vec![q(x)]).collect()).unwrap(),
        }
    }

    #[test]
    fn continuity_orders() {
        let p = |c: &[i64]| PowerCurve::new(c.iter().map(|&x| vec![q(x)]).collect()).unwrap();
        // u^2 vs 2u - 1 at 1: C^1; u^2 vs u at 1: C^0; u^2 vs 0: C^-1; equal: p.
        assert_eq!(continuity_at(&p(&[0, 0, 1]), &p(&[-1, 2, 0]), &q(1)), 1);
        assert_eq!(continuity_at(&p(&[0, 0, 1]), &p(&[0, 1, 0]), &q(1)), 0);
        assert_eq!(continuity_at(&p(&[0, 0, 1]), &p(&[0, 0, 0]), &q(1)), -1);
        assert_eq!(continuity_at(&p(&[0, 0, 1]), &p(&[0, 0, 1]), &q(1)), 2);
    }

    #[test]
    fn bad_pieces_name_the_field() {
        let gap = [piece(0, 1, &[0]), piece(2, 3, &[0])];
        let e = bspline_from_pieces(1, &gap).unwrap_err();
        assert_eq!(e.field, "pieces[1].interval");
        assert!(e.message.contains("gap"), "{e}");
        let overlap = [piece(0, 2, &[0]), piece(1, 3, &[0])];
        assert!(bspline_from_pieces(1, &overlap)
            .unwrap_err()
            .message
            .contains("overlaps"));
        let high = [piece(0, 1, &[0, 0, 1])];
        assert_eq!(
            bspline_from_pieces(1, &high).unwrap_err().field,
            "pieces[0].coefficients[2]"
        );
        let empty = [piece(1, 1, &[0])];
        assert_eq!(
            bspline_from_pieces(1, &empty).unwrap_err().field,
            "pieces[0].interval"
        );
        assert_eq!(
            bspline_from_pieces::<Rational>(1, &[]).unwrap_err().field,
            "pieces"
        );
    }

    #[test]
    fn too_few_knots_for_the_continuity_is_detected() {
        // u on [0, 1], 1 on [1, 2]: C^0 at 1, so the knot 1 must have multiplicity 2 at p = 2;
        // with multiplicity 1 the de Boor points disagree.
        let pieces = [piece(0, 1, &[0, 1]), piece(1, 2, &[1])];
        assert!(bspline_from_pieces(2, &pieces).is_ok());
        let knots = [0, 0, 0, 1, 2, 2, 2].map(q).to_vec();
        let e = bspline_from_pieces_with_knots(2, &pieces, knots).unwrap_err();
        assert!(e.message.contains("de Boor point"), "{e}");
        // Equal pieces: the breakpoint disappears.
        let same = [piece(0, 1, &[0, 1]), piece(1, 2, &[0, 1])];
        assert_eq!(bspline_from_pieces(2, &same).unwrap().knots().len(), 6);
    }
}
