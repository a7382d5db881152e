//! Tests of curves sharing a component, retracing curves and single-point curves. Expected
//! values are derived by hand (noted at each test).

use super::algebraic::AlgebraicReal;
use super::curves::{intersect_curves, self_intersections, Overlap};
use crate::num::ring::Rational;
use num_bigint::BigInt;
use std::cmp::Ordering;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

fn curve(v: &[(i64, i64, i64, i64)]) -> Vec<[Rational; 2]> {
    v.iter().map(|&(a, b, c, d)| [q(a, b), q(c, d)]).collect()
}

fn exact(x: &AlgebraicReal) -> Rational {
    x.exact().cloned().expect("a rational parameter")
}

fn ends(o: &Overlap) -> [Rational; 4] {
    [
        exact(&o.s[0]),
        exact(&o.s[1]),
        exact(&o.t[0]),
        exact(&o.t[1]),
    ]
}

/// x(s) = s^3 - s / 2 on the x axis (Bernstein 0, -1/6, -1/3, 1/2, by hand): it turns at
/// s = 1/sqrt(6) (x' = 3 s^2 - 1/2), where x = -1/(3 sqrt 6), and is back at 0 for
/// s = 1/sqrt(2). So it retraces [-1/(3 sqrt 6), 0]: s in [0, 1/sqrt 6] against t from
/// 1/sqrt 2 down to 1/sqrt 6.
fn irrational_turning() -> Vec<[Rational; 2]> {
    curve(&[(0, 1, 0, 1), (-1, 6, 0, 1), (-1, 3, 0, 1), (1, 2, 0, 1)])
}

#[test]
fn collinear_self_with_irrational_turning_point() {
    let x = self_intersections(&irrational_turning()).unwrap();
    assert!(x.points.is_empty());
    assert_eq!(x.overlaps.len(), 1);
    let o = &x.overlaps[0];
    let sixth = [BigInt::from(-1), BigInt::from(0), BigInt::from(6)];
    let half = [BigInt::from(-1), BigInt::from(0), BigInt::from(2)];
    assert_eq!(exact(&o.s[0]), q(0, 1));
    assert!(o.s[1].is_root_of(&sixth) && o.t[1].is_root_of(&sixth));
    assert!(o.t[0].is_root_of(&half));
    assert_eq!(o.s[1].to_f64(), (1.0f64 / 6.0).sqrt());
    assert_eq!(o.t[0].to_f64(), std::f64::consts::FRAC_1_SQRT_2);
    assert_eq!(o.s[1].compare(&o.t[1]), Ordering::Equal);
}

#[test]
fn collinear_pair_with_irrational_turning_point() {
    // Q: the segment from 0 to 1/2. P's second piece [1/sqrt 6, 1] covers [-1/(3 sqrt 6), 1/2]:
    // one overlap s from 1/sqrt 2 to 1 against t from 0 to 1; the first piece touches Q at
    // x = 0 (s = 0, t = 0), a pair on the overlap's t-range, so not listed.
    let seg = curve(&[(0, 1, 0, 1), (1, 2, 0, 1)]);
    let x = intersect_curves(&irrational_turning(), &seg).unwrap();
    assert!(x.points.is_empty(), "{:?}", x.points);
    assert_eq!(x.overlaps.len(), 1);
    let o = &x.overlaps[0];
    assert!(o.s[0].is_root_of(&[BigInt::from(-1), BigInt::from(0), BigInt::from(2)]));
    assert_eq!(exact(&o.s[1]), q(1, 1));
    assert_eq!((exact(&o.t[0]), exact(&o.t[1])), (q(0, 1), q(1, 1)));
}

#[test]
fn reparametrised_parabola_overlaps_once() {
    // P(s) = (2s, 4s - 4s^2) and Q(t) = P(t^2) = (2t^2, 4t^2 - 4t^4), whose Bernstein points
    // are (0,0), (0,0), (1/3,2/3), (1,2), (2,0) (b_i = sum_j C(i,j)/C(4,j) p_j, by hand).
    // The parabola is proper and t^2 maps [0, 1] onto itself: one overlap, no point.
    let p = curve(&[(0, 1, 0, 1), (1, 1, 2, 1), (2, 1, 0, 1)]);
    let qq = curve(&[
        (0, 1, 0, 1),
        (0, 1, 0, 1),
        (1, 3, 2, 3),
        (1, 1, 2, 1),
        (2, 1, 0, 1),
    ]);
    let x = intersect_curves(&p, &qq).unwrap();
    assert!(x.points.is_empty());
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 1), q(0, 1), q(1, 1)]]);
    // Swapped: the same overlap seen from Q.
    let x = intersect_curves(&qq, &p).unwrap();
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 1), q(0, 1), q(1, 1)]]);
}

#[test]
fn symmetric_quartic_retraces_itself() {
    // P(s) = P(1 - s) (control points symmetric): phi = s^2 - s, one overlap s [0, 1/2]
    // against t [1, 1/2].
    let p = curve(&[
        (0, 1, 0, 1),
        (2, 1, 4, 1),
        (16, 3, -16, 3),
        (2, 1, 4, 1),
        (0, 1, 0, 1),
    ]);
    let x = self_intersections(&p).unwrap();
    assert!(x.points.is_empty());
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 2), q(1, 1), q(1, 2)]]);
}

#[test]
fn single_point_curves_are_answered() {
    // The point (1/2, 1/2) lies on the diagonal at t = 1/2: every s pairs with it.
    let point = curve(&[(1, 2, 1, 2), (1, 2, 1, 2)]);
    let diagonal = curve(&[(0, 1, 0, 1), (1, 1, 1, 1)]);
    let x = intersect_curves(&point, &diagonal).unwrap();
    assert!(x.points.is_empty());
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 1), q(1, 2), q(1, 2)]]);
    let x = intersect_curves(&diagonal, &point).unwrap();
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(1, 2), q(1, 2), q(0, 1), q(1, 1)]]);
    // (5, 5) is on the diagonal's line but beyond t = 1: nothing.
    let far = curve(&[(5, 1, 5, 1), (5, 1, 5, 1)]);
    let x = intersect_curves(&far, &diagonal).unwrap();
    assert!(x.points.is_empty() && x.overlaps.is_empty());
    // Two points: equal (everything) or not (nothing).
    let x = intersect_curves(&point, &point).unwrap();
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 1), q(0, 1), q(1, 1)]]);
    assert!(intersect_curves(&point, &far).unwrap().overlaps.is_empty());
    // With itself: every pair, as one retracing overlap in the spec's form (t0 > t1, s1 <= t1).
    let x = self_intersections(&far).unwrap();
    assert!(x.points.is_empty());
    let got: Vec<[Rational; 4]> = x.overlaps.iter().map(ends).collect();
    assert_eq!(got, vec![[q(0, 1), q(1, 2), q(1, 1), q(1, 2)]]);
}
