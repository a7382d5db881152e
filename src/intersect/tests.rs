//! Tests of the certified zeros and intersections. Expected values are derived by hand or by
//! independent means (f64::sqrt, num's own rounding, exact products of linear factors).

use super::algebraic::AlgebraicReal;
use super::curves::{intersect_curves, intersect_curves_f64, self_intersections, Intersections};
use super::upoly;
use super::zeros::{bezier_zeros, bezier_zeros_f64};
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::basis::power_to_bernstein;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};
use std::cmp::Ordering;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

fn pts(v: &[(i64, i64)]) -> Vec<[Rational; 2]> {
    v.iter().map(|&(x, y)| [q(x, 1), q(y, 1)]).collect()
}

/// Bernstein coefficients of the product of (t - r_i) (power form multiplied out).
fn bernstein_of_roots(roots: &[Rational]) -> Vec<Rational> {
    let mut p = vec![Rational::one()];
    for r in roots {
        let mut next = vec![Rational::zero(); p.len() + 1];
        for (i, c) in p.iter().enumerate() {
            next[i + 1] += c;
            next[i] -= c * r;
        }
        p = next;
    }
    let pts: Vec<Vec<Rational>> = p.into_iter().map(|c| vec![c]).collect();
    power_to_bernstein(&pts)
        .into_iter()
        .map(|v| v[0].clone())
        .collect()
}

#[test]
fn high_multiplicity_and_ends() {
    let mut roots = vec![q(1, 3); 5];
    roots.push(q(1, 2));
    let z = bezier_zeros(&bernstein_of_roots(&roots)).unwrap();
    assert!(!z.identically_zero);
    let got: Vec<(Rational, usize)> = z
        .zeros
        .iter()
        .map(|r| (r.t.exact().unwrap().clone(), r.multiplicity))
        .collect();
    assert_eq!(got, vec![(q(1, 3), 5), (q(1, 2), 1)]);
    // Roots at both ends, a double root at 0, a root outside [0, 1] ignored.
    let z = bezier_zeros(&bernstein_of_roots(&[q(0, 1), q(0, 1), q(1, 1), q(3, 1)])).unwrap();
    let got: Vec<(Rational, usize)> = z
        .zeros
        .iter()
        .map(|r| (r.t.exact().unwrap().clone(), r.multiplicity))
        .collect();
    assert_eq!(got, vec![(q(0, 1), 2), (q(1, 1), 1)]);
}

#[test]
fn identically_zero_and_no_roots() {
    let z = bezier_zeros(&[q(0, 1), q(0, 1), q(0, 1)]).unwrap();
    assert!(z.identically_zero && z.zeros.is_empty());
    let z = bezier_zeros_f64(&[1.0, -0.5, 1.0]).unwrap();
    assert!(!z.identically_zero && z.zeros.is_empty());
    assert!(bezier_zeros(&[]).is_err());
    let e = bezier_zeros_f64(&[1.0, f64::NAN]).unwrap_err();
    assert_eq!(e.field, "coefficients[1]");
}

#[test]
fn irrational_roots_round_correctly() {
    // 2 t^2 - 1 = 0: t = sqrt(2)/2, f64::sqrt is correctly rounded (IEEE).
    let pts: Vec<Vec<Rational>> = [q(-1, 1), q(0, 1), q(2, 1)]
        .into_iter()
        .map(|c| vec![c])
        .collect();
    let b: Vec<Rational> = power_to_bernstein(&pts)
        .into_iter()
        .map(|v| v[0].clone())
        .collect();
    let z = bezier_zeros(&b).unwrap();
    assert_eq!(z.zeros.len(), 1);
    let t = &z.zeros[0].t;
    assert!(t.exact().is_none());
    assert_eq!(t.to_f64(), 0.5f64.sqrt());
    assert_eq!(z.zeros[0].multiplicity, 1);
    // k t^2 - 1 for several k: 1/sqrt(k), compared with an exact test of the nearest double:
    // x = to_f64 must satisfy (x - ulp/2)^2 k < 1 < (x + ulp/2)^2 k.
    for k in [3i64, 5, 7, 11, 13, 1000003] {
        let pts: Vec<Vec<Rational>> = [q(-1, 1), q(0, 1), q(k, 1)]
            .into_iter()
            .map(|c| vec![c])
            .collect();
        let b: Vec<Rational> = power_to_bernstein(&pts)
            .into_iter()
            .map(|v| v[0].clone())
            .collect();
        let z = bezier_zeros(&b).unwrap();
        let x = z.zeros[0].t.to_f64();
        let ex = Rational::from_float(x).unwrap();
        let half_ulp = Rational::from_float(f64::from_bits(x.to_bits() + 1) - x).unwrap() / q(2, 1);
        let lo = &ex - &half_ulp;
        let hi = &ex + &half_ulp;
        assert!(&lo * &lo * q(k, 1) < q(1, 1), "k = {k}");
        assert!(&hi * &hi * q(k, 1) > q(1, 1), "k = {k}");
    }
}

#[test]
fn rational_root_of_an_irreducible_looking_factor_is_exact() {
    // (3t - 1)(t^2 - 2)... in [0,1] only 1/3; and (5t-2)(7t-3) gives 2/5 and 3/7 exactly.
    let z = bezier_zeros(&bernstein_of_roots(&[q(2, 5), q(3, 7)])).unwrap();
    let got: Vec<Rational> = z
        .zeros
        .iter()
        .map(|r| r.t.exact().unwrap().clone())
        .collect();
    assert_eq!(got, vec![q(2, 5), q(3, 7)]);
    assert_eq!(
        z.zeros[0].t.polynomial(),
        &[BigInt::from(-2), BigInt::from(5)]
    );
    // to_f64 of a rational equals num's rounding of the exact value.
    assert_eq!(z.zeros[1].t.to_f64(), rational_to_f64(&q(3, 7)));
}

#[test]
fn yun_factors() {
    // (x - 1)^3 (x + 2)^2 x
    let lin = |a: i64| vec![BigInt::from(-a), BigInt::one()];
    let mut p = vec![BigInt::one()];
    for f in [lin(1), lin(1), lin(1), lin(-2), lin(-2), lin(0)] {
        p = upoly::mul(&p, &f);
    }
    let f = upoly::square_free_factors(&p);
    let mults: Vec<usize> = f.iter().map(|(_, m)| *m).collect();
    assert_eq!(mults, vec![1, 2, 3]);
    assert_eq!(f[0].0, lin(0));
    assert_eq!(f[1].0, lin(-2));
    assert_eq!(f[2].0, lin(1));
}

#[test]
fn algebraic_comparison() {
    let sqrt_half = {
        let b: Vec<Rational> = vec![q(-1, 1), q(-1, 1), q(1, 1)]; // 2t^2 - 1 in Bernstein
        bezier_zeros(&b).unwrap().zeros[0].t.clone()
    };
    // The same number from 4 t^2 - 2.
    let b2: Vec<Rational> = vec![q(-2, 1), q(-2, 1), q(2, 1)];
    let other = bezier_zeros(&b2).unwrap().zeros[0].t.clone();
    assert!(sqrt_half.equals(&other));
    assert_eq!(sqrt_half.compare(&other), Ordering::Equal);
    let r = AlgebraicReal::from_rational(q(7, 10));
    assert_eq!(sqrt_half.compare(&r), Ordering::Greater);
    let r = AlgebraicReal::from_rational(q(71, 100));
    assert_eq!(sqrt_half.compare(&r), Ordering::Less);
}

/// (s, t, tangent) of every point, as exact rationals where rational.
fn summary(x: &Intersections) -> Vec<(Option<Rational>, Option<Rational>, bool)> {
    x.points
        .iter()
        .map(|p| (p.s.exact().cloned(), p.t.exact().cloned(), p.tangent))
        .collect()
}

#[test]
fn transversal_lines_and_symmetry() {
    let p = pts(&[(0, 0), (4, 4)]);
    let qq = pts(&[(0, 4), (4, 0)]);
    let x = intersect_curves(&p, &qq).unwrap();
    assert_eq!(summary(&x), vec![(Some(q(1, 2)), Some(q(1, 2)), false)]);
    assert_eq!(x.points[0].point, [2.0, 2.0]);
}

#[test]
fn parabola_and_line_irrational() {
    // P(s) = (s, s^2) as a quadratic Bézier: (0,0), (1/2, 0), (1, 1); Q: y = 1/2, x in [0,1].
    let p = vec![[q(0, 1), q(0, 1)], [q(1, 2), q(0, 1)], [q(1, 1), q(1, 1)]];
    let qq = vec![[q(0, 1), q(1, 2)], [q(1, 1), q(1, 2)]];
    let x = intersect_curves(&p, &qq).unwrap();
    assert_eq!(x.points.len(), 1);
    let pt = &x.points[0];
    assert_eq!(pt.s.to_f64(), 0.5f64.sqrt());
    assert_eq!(pt.t.to_f64(), 0.5f64.sqrt());
    assert!(!pt.tangent);
    assert_eq!(pt.point, [0.5f64.sqrt(), 0.5]);
    // Swapped.
    let y = intersect_curves(&qq, &p).unwrap();
    assert_eq!(y.points.len(), 1);
    assert!(y.points[0].s.equals(&pt.t) && y.points[0].t.equals(&pt.s));
}

#[test]
fn tangent_parabola_and_line() {
    // y = s^2 touches y = 0 at s = 0 (an end point) and y = (2s-1)^2 touches at s = 1/2.
    let p = vec![[q(0, 1), q(1, 1)], [q(1, 2), q(-1, 1)], [q(1, 1), q(1, 1)]];
    let qq = pts(&[(-1, 0), (3, 0)]);
    let x = intersect_curves(&p, &qq).unwrap();
    assert_eq!(summary(&x), vec![(Some(q(1, 2)), Some(q(3, 8)), true)]);
    let y = intersect_curves(&qq, &p).unwrap();
    assert_eq!(summary(&y), vec![(Some(q(3, 8)), Some(q(1, 2)), true)]);
}

#[test]
fn end_point_touching_and_near_miss() {
    let p = pts(&[(0, 0), (1, 2), (2, 0)]);
    let qq = pts(&[(2, 0), (3, 1), (4, 0)]);
    let x = intersect_curves(&p, &qq).unwrap();
    assert_eq!(summary(&x), vec![(Some(q(1, 1)), Some(q(0, 1)), false)]);
    // Near miss: the line y = 1 + 1/10^12 above the arch whose top is y = 1.
    let line = vec![
        [q(0, 1), q(1_000_000_000_001, 1_000_000_000_000)],
        [q(2, 1), q(1_000_000_000_001, 1_000_000_000_000)],
    ];
    let x = intersect_curves(&p, &line).unwrap();
    assert!(x.points.is_empty() && x.overlaps.is_empty());
    // Exactly touching at the top: tangent.
    let line = pts(&[(0, 1), (2, 1)]);
    let x = intersect_curves(&p, &line).unwrap();
    assert_eq!(summary(&x), vec![(Some(q(1, 2)), Some(q(1, 2)), true)]);
}

#[test]
fn cubic_pair_many_crossings_symmetric() {
    let p = pts(&[(0, 0), (1, 6), (2, -6), (3, 0)]);
    let qq = pts(&[(0, 1), (3, -1), (0, -2), (3, 2)]);
    let x = intersect_curves(&p, &qq).unwrap();
    let y = intersect_curves(&qq, &p).unwrap();
    assert!(!x.points.is_empty());
    assert_eq!(x.points.len(), y.points.len());
    for a in &x.points {
        assert!(y
            .points
            .iter()
            .any(|b| b.s.equals(&a.t) && b.t.equals(&a.s)));
        // The point is on both curves within rounding.
        let s = a.s.to_f64();
        let px =
            (1.0 - s).powi(2) * 3.0 * s * 1.0 + 3.0 * (1.0 - s) * s * s * 2.0 + s.powi(3) * 3.0;
        assert!((px - a.point[0]).abs() < 1e-12);
    }
}

#[test]
fn overlaps_same_reversed_subsegment_elevated() {
    let p = pts(&[(0, 0), (1, 2), (3, 3)]);
    // The same curve.
    let x = intersect_curves(&p, &p).unwrap();
    assert!(x.points.is_empty());
    assert_eq!(x.overlaps.len(), 1);
    let o = &x.overlaps[0];
    let ends = |o: &super::curves::Overlap| {
        [
            o.s[0].exact().cloned().unwrap(),
            o.s[1].exact().cloned().unwrap(),
            o.t[0].exact().cloned().unwrap(),
            o.t[1].exact().cloned().unwrap(),
        ]
    };
    assert_eq!(ends(o), [q(0, 1), q(1, 1), q(0, 1), q(1, 1)]);
    // Reversed.
    let r: Vec<[Rational; 2]> = p.iter().rev().cloned().collect();
    let x = intersect_curves(&p, &r).unwrap();
    assert_eq!(ends(&x.overlaps[0]), [q(0, 1), q(1, 1), q(1, 1), q(0, 1)]);
    // Degree-elevated copy: Q = P elevated to 3.
    let e = vec![
        [q(0, 1), q(0, 1)],
        [q(2, 3), q(4, 3)],
        [q(5, 3), q(7, 3)],
        [q(3, 1), q(3, 1)],
    ];
    let x = intersect_curves(&p, &e).unwrap();
    assert_eq!(ends(&x.overlaps[0]), [q(0, 1), q(1, 1), q(0, 1), q(1, 1)]);
    // A sub-segment: P over [1/4, 3/4] (control points by de Casteljau, exact).
    let sub = {
        let mut out = p.clone();
        crate::shape::array::subsegment_into(&p, &q(1, 4), &q(3, 4), &mut out, &mut Vec::new())
            .unwrap();
        out
    };
    let x = intersect_curves(&p, &sub).unwrap();
    assert!(x.points.is_empty());
    assert_eq!(ends(&x.overlaps[0]), [q(1, 4), q(3, 4), q(0, 1), q(1, 1)]);
    // Adjacent pieces of the same parabola touch at one point.
    let right = {
        let mut out = p.clone();
        crate::shape::array::subsegment_into(&p, &q(1, 1), &q(2, 1), &mut out, &mut Vec::new())
            .unwrap();
        out
    };
    let x = intersect_curves(&p, &right).unwrap();
    assert!(x.overlaps.is_empty());
    assert_eq!(summary(&x), vec![(Some(q(1, 1)), Some(q(0, 1)), true)]);
}

#[test]
fn collinear_back_and_forth() {
    // P goes 0 -> 4 on the x axis; Q goes from 1 to 3 and back toward 2 (turning at a
    // rational parameter): x(t) = 1 + 6t - 5t^2... built from its power form.
    let p = pts(&[(0, 0), (4, 0)]);
    // Q(t) = (1 + 4t - 3t^2... choose x(t) = 1 + 4t - 4t^2 + ... use Bernstein (1, 3, 1): turns at 1/2 at x = 2.
    let qq = pts(&[(1, 0), (3, 0), (1, 0)]);
    let x = intersect_curves(&p, &qq).unwrap();
    assert!(x.points.is_empty());
    let ends: Vec<[Rational; 4]> = x
        .overlaps
        .iter()
        .map(|o| {
            [
                o.s[0].exact().cloned().unwrap(),
                o.s[1].exact().cloned().unwrap(),
                o.t[0].exact().cloned().unwrap(),
                o.t[1].exact().cloned().unwrap(),
            ]
        })
        .collect();
    assert_eq!(
        ends,
        vec![
            [q(1, 4), q(1, 2), q(0, 1), q(1, 2)],
            [q(1, 4), q(1, 2), q(1, 1), q(1, 2)],
        ]
    );
    // Self: Q retraces itself: one overlap with t0 > t1, s1 <= t1.
    let x = self_intersections(&qq).unwrap();
    assert_eq!(x.overlaps.len(), 1);
    let o = &x.overlaps[0];
    assert_eq!(o.s[0].exact(), Some(&q(0, 1)));
    assert_eq!(o.s[1].exact(), Some(&q(1, 2)));
    assert_eq!(o.t[0].exact(), Some(&q(1, 1)));
    assert_eq!(o.t[1].exact(), Some(&q(1, 2)));
}

#[test]
fn cubic_loop_self_intersection() {
    // P: (0,0), (2,1), (-1,1), (1,0). By hand: x(s) = 6s - 15s^2 + 10s^3 and y(s) = 3s(1 - s),
    // both symmetric under s -> 1 - s (x(s) + x(1 - s) = 1), so the loop closes at x = 1/2:
    // x(s) - 1/2 = (2s - 1)(5s^2 - 5s + 1/2), s = (5 - sqrt 15)/10, t = 1 - s, and
    // y = 3 s (1 - s) = 3/10.
    let p = pts(&[(0, 0), (2, 1), (-1, 1), (1, 0)]);
    let x = self_intersections(&p).unwrap();
    assert_eq!(x.points.len(), 1);
    let pt = &x.points[0];
    assert!(!pt.tangent);
    let f = [BigInt::from(1), BigInt::from(-10), BigInt::from(10)];
    assert!(pt.s.is_root_of(&f) && pt.t.is_root_of(&f));
    assert_eq!(
        pt.s.compare(&AlgebraicReal::from_rational(q(1, 2))),
        Ordering::Less
    );
    assert_eq!(
        pt.t.compare(&AlgebraicReal::from_rational(q(1, 2))),
        Ordering::Greater
    );
    let s = pt.s.to_f64();
    assert!((s - (5.0 - 15f64.sqrt()) / 10.0).abs() <= 2.0 * f64::EPSILON * s);
    assert_eq!(pt.point, [0.5, 0.3]);
}

#[test]
fn closed_curve_gives_zero_one() {
    let p = pts(&[(0, 0), (2, 2), (-2, 2), (0, 0)]);
    let x = self_intersections(&p).unwrap();
    assert!(x
        .points
        .iter()
        .any(|pt| pt.s.exact() == Some(&q(0, 1)) && pt.t.exact() == Some(&q(1, 1))));
}

#[test]
fn f64_input_reads_doubles_exactly() {
    let x = intersect_curves_f64(&[[0.0, 0.0], [1.0, 1.0]], &[[0.0, 0.1], [1.0, 0.1]]).unwrap();
    assert_eq!(x.points.len(), 1);
    // s = t = the double 0.1 exactly (a rational with denominator 2^55).
    assert_eq!(
        x.points[0].s.exact(),
        Some(&Rational::from_float(0.1).unwrap())
    );
    assert_eq!(x.points[0].s.to_f64(), 0.1);
    assert!(intersect_curves_f64(
        &[[0.0, f64::INFINITY], [1.0, 1.0]],
        &[[0.0, 0.0], [1.0, 0.0]]
    )
    .is_err());
}

#[test]
fn bad_input_is_refused() {
    let e = intersect_curves(&pts(&[(0, 0)]), &pts(&[(0, 0), (1, 1)])).unwrap_err();
    assert_eq!(e.field, "p");
    let p = pts(&[(0, 0), (1, 1)]);
    let line_quadratic = pts(&[(0, 0), (0, 0), (1, 1)]);
    // Collinear: decided (one overlap), not refused.
    let x = intersect_curves(&p, &line_quadratic).unwrap();
    assert_eq!(x.overlaps.len(), 1);
}

/// Times exact curve pairs of degree 3, 8, 16 and 20 (deterministic pseudo-random): one pair
/// with small integer control points in [-10, 10] and one with random doubles in [0, 1) (53-bit
/// mantissas, read exactly). A measurement, not a check: run it in release with
/// `cargo test -p blossom --release --lib intersect::tests::timing -- --ignored --nocapture`
/// (degrees from the environment variable `BLOSSOM_DEGREES`, default "3 8 16 20"; the kinds
/// from `BLOSSOM_KINDS`, default "int f64").
#[test]
#[ignore]
fn timing_exact_pairs() {
    let degrees: Vec<usize> = std::env::var("BLOSSOM_DEGREES")
        .unwrap_or_else(|_| "3 8 16 20".into())
        .split_whitespace()
        .map(|d| d.parse().unwrap())
        .collect();
    let kinds = std::env::var("BLOSSOM_KINDS").unwrap_or_else(|_| "int f64".into());
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || next(&mut state);
    for kind in kinds.split_whitespace() {
        for &n in &degrees {
            let mut curve = || -> Vec<[Rational; 2]> {
                (0..=n)
                    .map(|_| {
                        let mut c = || match kind {
                            "int" => q((next() % 21) as i64 - 10, 1),
                            _ => Rational::from_float((next() >> 11) as f64 / (1u64 << 53) as f64)
                                .unwrap(),
                        };
                        [c(), c()]
                    })
                    .collect()
            };
            let (p, qq) = (curve(), curve());
            let start = std::time::Instant::now();
            let x = intersect_curves(&p, &qq).unwrap();
            println!(
                "{kind} degree {n}: {} points, {} overlaps, {:.3} s",
                x.points.len(),
                x.overlaps.len(),
                start.elapsed().as_secs_f64()
            );
        }
    }
}

/// A small deterministic generator (xorshift) for the cross-check below.
fn next(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

#[test]
fn filter_path_agrees_with_the_solver() {
    // Integer coordinates are doubles, so `intersect_curves` may answer through the float
    // filter and the resultants' enclosures; the same curves scaled by 1/3 (coordinates that
    // are not doubles, same parameters) go through the exact solver. Both must give the same
    // exact parameters and flags.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut filtered = 0;
    for case in 0..40 {
        let degree = 2 + case % 3;
        let curve = |state: &mut u64| -> Vec<[Rational; 2]> {
            (0..=degree)
                .map(|_| [0, 1].map(|_| q((next(state) % 17) as i64 - 8, 1)))
                .collect()
        };
        let (p, qq) = (curve(&mut state), curve(&mut state));
        let third = |c: &[[Rational; 2]]| -> Vec<[Rational; 2]> {
            c.iter().map(|xy| xy.clone().map(|v| v / q(3, 1))).collect()
        };
        let (Ok(x), Ok(y)) = (
            intersect_curves(&p, &qq),
            intersect_curves(&third(&p), &third(&qq)),
        ) else {
            continue;
        };
        if x.points.iter().all(|pt| !pt.tangent) && x.overlaps.is_empty() && !x.points.is_empty() {
            filtered += 1;
        }
        assert_eq!(x.points.len(), y.points.len(), "case {case}");
        for (a, b) in x.points.iter().zip(&y.points) {
            assert!(a.s.equals(&b.s) && a.t.equals(&b.t), "case {case}");
            assert_eq!(a.tangent, b.tangent, "case {case}");
            assert_eq!(
                (a.s.to_f64(), a.t.to_f64()),
                (b.s.to_f64(), b.t.to_f64()),
                "case {case}"
            );
            assert!(upoly::degree(a.s.polynomial()).is_some());
        }
    }
    assert!(
        filtered >= 10,
        "only {filtered} cases had transversal crossings"
    );
}

#[test]
fn integer_interval_horner_is_the_rational_one_scaled() {
    use super::algebraic::{enclose, enclose_scaled};
    let p: Vec<BigInt> = [7i64, -30, 0, 41, -5, 2]
        .iter()
        .map(|&c| c.into())
        .collect();
    let pr: Vec<Rational> = p
        .iter()
        .map(|c| Rational::from_integer(c.clone()))
        .collect();
    for (lo, hi) in [
        (q(-3, 2), q(1, 3)),
        (q(1, 4), q(5, 6)),
        (q(-7, 3), q(-1, 9)),
        (q(2, 5), q(2, 5)),
    ] {
        let (l, h) = enclose(&pr, &lo, &hi);
        let d = Rational::from_integer(lo.denom().lcm(hi.denom()));
        let scale = (0..6).fold(Rational::one(), |acc, _| acc * &d);
        let (sl, sh) = enclose_scaled(&p, 6, &lo, &hi);
        assert_eq!(Rational::from_integer(sl), l * &scale);
        assert_eq!(Rational::from_integer(sh), h * &scale);
    }
}

#[test]
fn integer_bernstein_coefficients_are_the_rational_ones_scaled() {
    use super::isolate::bernstein_on;
    use crate::shape::basis::{power_to_bernstein, scale_argument, taylor_shift};
    let mut state = 0x5eed_1234_abcd_ef01u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % 41) as i64 - 20
    };
    for n in [1usize, 2, 5, 9] {
        let f: Vec<BigInt> = (0..=n).map(|_| BigInt::from(next())).collect();
        for (a, b) in [
            (q(-1, 1), q(2, 1)),
            (q(1, 3), q(3, 4)),
            (q(-5, 8), q(-1, 16)),
        ] {
            let mut c: Vec<Vec<Rational>> = f
                .iter()
                .map(|x| vec![Rational::from_integer(x.clone())])
                .collect();
            taylor_shift(&mut c, &a);
            scale_argument(&mut c, &(&b - &a));
            let want: Vec<Rational> = power_to_bernstein(&c)
                .into_iter()
                .map(|p| p[0].clone())
                .collect();
            let got = bernstein_on(&f, &a, &b);
            assert_eq!(got.len(), want.len());
            // got = k * want for one k > 0.
            let (j, w) = want.iter().enumerate().find(|(_, w)| !w.is_zero()).unwrap();
            let k = Rational::from_integer(got[j].clone()) / w;
            assert!(k > Rational::zero());
            for (g, w) in got.iter().zip(&want) {
                assert_eq!(Rational::from_integer(g.clone()), w * &k);
            }
        }
    }
}

// High degrees against an independent truth: `tests/intersect_corpus/high_degree/cases.json`,
// computed by `truth.py` beside it with interval Krawczyk tests on Taylor enclosures of the
// power form in mpmath (no Bernstein form, no Descartes, no resultant), with a certified count:
// every crossing of every case, each parameter in an enclosure of width about 2^-100.

/// One parameter of the truth: an enclosure [lo, hi] and, when both ends round to the same
/// double, that double.
struct TruthParameter {
    lo: Rational,
    hi: Rational,
    value: Option<f64>,
}

/// One case of the truth: one curve (`self`) or two, and every intersection (s, t).
struct TruthCase {
    name: String,
    curves: Vec<Vec<[Rational; 2]>>,
    points: Vec<[TruthParameter; 2]>,
}

fn truth_number(v: &serde_json::Value) -> Rational {
    let text = match v {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    match text.split_once('/') {
        Some((n, d)) => Rational::new(n.parse().unwrap(), d.parse().unwrap()),
        None => Rational::from_integer(text.parse().unwrap()),
    }
}

fn high_degree_truth() -> Vec<TruthCase> {
    let text = include_str!("../../tests/intersect_corpus/high_degree/cases.json");
    let cases: serde_json::Value = serde_json::from_str(text).unwrap();
    let curve = |c: &serde_json::Value| -> Vec<[Rational; 2]> {
        c.as_array()
            .unwrap()
            .iter()
            .map(|xy| [truth_number(&xy[0]), truth_number(&xy[1])])
            .collect()
    };
    let parameter = |p: &serde_json::Value| TruthParameter {
        lo: truth_number(&p["lo"]),
        hi: truth_number(&p["hi"]),
        value: p["value"].as_str().map(|v| v.parse().unwrap()),
    };
    cases
        .as_array()
        .unwrap()
        .iter()
        .map(|c| TruthCase {
            name: c["name"].as_str().unwrap().to_string(),
            curves: match c["kind"].as_str().unwrap() {
                "self" => vec![curve(&c["curve"])],
                _ => c["curves"].as_array().unwrap().iter().map(curve).collect(),
            },
            points: c["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|pt| [parameter(&pt["s"]), parameter(&pt["t"])])
                .collect(),
        })
        .collect()
}

/// Whether the exact parameter lies in the truth's enclosure (decided exactly).
fn encloses(truth: &TruthParameter, x: &AlgebraicReal) -> bool {
    x.cmp_rational(&truth.lo) != Ordering::Less && x.cmp_rational(&truth.hi) != Ordering::Greater
}

/// Every truth point is matched by exactly one point of the answer and every answer point by
/// exactly one truth point (so none is missed and none is extra), with no overlap, no
/// tangency, and each parameter's double the truth's to the bit when the truth knows it.
fn check_against_truth(case: &TruthCase, answer: &Intersections) {
    let name = &case.name;
    assert!(answer.overlaps.is_empty(), "{name}: overlaps");
    let matches = |truth: &[TruthParameter; 2], found: &super::curves::IntersectionPoint| {
        encloses(&truth[0], &found.s) && encloses(&truth[1], &found.t)
    };
    for (k, truth) in case.points.iter().enumerate() {
        let hits: Vec<_> = answer.points.iter().filter(|f| matches(truth, f)).collect();
        assert_eq!(
            hits.len(),
            1,
            "{name}: truth point {k} matched {} times",
            hits.len()
        );
        assert!(!hits[0].tangent, "{name}: point {k} tangent");
        for (param, x) in truth.iter().zip([&hits[0].s, &hits[0].t]) {
            if let Some(v) = param.value {
                assert_eq!(x.to_f64().to_bits(), v.to_bits(), "{name}: point {k}");
            }
        }
    }
    for (k, found) in answer.points.iter().enumerate() {
        let hits = case.points.iter().filter(|t| matches(t, found)).count();
        assert_eq!(
            hits,
            1,
            "{name}: answer point {k} ({}, {}) is in {hits} truth boxes",
            found.s.to_f64(),
            found.t.to_f64()
        );
    }
}

/// The rounded answer (float filter first) against the truth: the same number of points, each
/// truth point's doubles present.
fn check_rounded_against_truth(case: &TruthCase, answer: &super::rounded::RoundedIntersections) {
    let name = &case.name;
    assert!(answer.overlaps.is_empty(), "{name}: overlaps");
    assert_eq!(
        answer.points.len(),
        case.points.len(),
        "{name}: number of points"
    );
    let rounded = |p: &TruthParameter| -> [f64; 2] {
        p.value
            .map_or([rational_to_f64(&p.lo), rational_to_f64(&p.hi)], |v| [v, v])
    };
    for (k, truth) in case.points.iter().enumerate() {
        let (s, t) = (rounded(&truth[0]), rounded(&truth[1]));
        let hits = answer
            .points
            .iter()
            .filter(|f| s.contains(&f.s) && t.contains(&f.t) && !f.tangent)
            .count();
        assert_eq!(
            hits, 1,
            "{name}: truth point {k} ({s:?}, {t:?}) matched {hits} times"
        );
    }
}

/// The curves of a truth case as doubles, when every coordinate is one.
fn truth_doubles(curve: &[[Rational; 2]]) -> Option<Vec<[f64; 2]>> {
    curve
        .iter()
        .map(|xy| {
            let d = [rational_to_f64(&xy[0]), rational_to_f64(&xy[1])];
            (Rational::from_float(d[0]).as_ref() == Some(&xy[0])
                && Rational::from_float(d[1]).as_ref() == Some(&xy[1]))
            .then_some(d)
        })
        .collect()
}

/// The product of the degrees of a pair (the degree of its resultant), or the squared degree
/// of the divided difference of one curve.
fn resultant_degree(case: &TruthCase) -> usize {
    match &case.curves[..] {
        [p] => (p.len() - 2) * (p.len() - 2),
        [p, q] => (p.len() - 1) * (q.len() - 1),
        _ => unreachable!(),
    }
}

#[test]
fn high_degree_pairs_match_the_independent_truth() {
    // Every pair of degrees 9 to 40 through the rounded answer (the float filter, the exact
    // path where it does not decide), and the exact answer (filter and resultants, or the
    // exact solver for coordinates that are not doubles) up to resultant degree 400; the
    // rest of the exact answers in `high_degree_exact_answers_match_the_truth` (ignored).
    let cases = high_degree_truth();
    let mut checked = 0;
    for case in cases.iter().filter(|c| c.curves.len() == 2) {
        let (p, q) = (&case.curves[0], &case.curves[1]);
        if let (Some(pf), Some(qf)) = (truth_doubles(p), truth_doubles(q)) {
            let rounded = super::rounded::intersect_curves_f64_rounded(&pf, &qf).unwrap();
            check_rounded_against_truth(case, &rounded);
            checked += 1;
        }
        if resultant_degree(case) <= 400 {
            check_against_truth(case, &intersect_curves(p, q).unwrap());
            checked += 1;
        }
    }
    assert!(checked >= 25, "checked {checked}");
}

#[test]
fn high_degree_self_intersections_match_the_independent_truth() {
    // Self-intersections always go through the exact solver: degrees 8 to 20 here, the rest
    // in `high_degree_exact_answers_match_the_truth` (ignored).
    let cases = high_degree_truth();
    let mut checked = 0;
    for case in cases.iter().filter(|c| c.curves.len() == 1) {
        if case.curves[0].len() <= 21 {
            check_against_truth(case, &self_intersections(&case.curves[0]).unwrap());
            checked += 1;
        }
    }
    assert!(checked >= 7, "checked {checked}");
}

/// The exact answers of the cases the two tests above leave (resultant degree over 400, self
/// over degree 20), with the time of each: over half an hour in all (pair-36-36 alone 5.5
/// min on a loaded 2-core machine). Run on request, all or the cases named in
/// `BLOSSOM_TRUTH_CASES` (say "self-24 self-28"):
/// `cargo test -p blossom --release --lib intersect::tests::high_degree_exact -- --ignored --nocapture`.
#[test]
#[ignore = "minutes: the exact solver at degrees 24 to 40"]
fn high_degree_exact_answers_match_the_truth() {
    let only = std::env::var("BLOSSOM_TRUTH_CASES").ok();
    for case in high_degree_truth() {
        if only
            .as_deref()
            .is_some_and(|names| !names.split_whitespace().any(|n| n == case.name))
        {
            continue;
        }
        let start = std::time::Instant::now();
        let answer = match &case.curves[..] {
            [p] if p.len() > 21 => self_intersections(p).unwrap(),
            [p, q] if resultant_degree(&case) > 400 => intersect_curves(p, q).unwrap(),
            _ => continue,
        };
        check_against_truth(&case, &answer);
        println!(
            "{}: {} points, {:.1} s",
            case.name,
            answer.points.len(),
            start.elapsed().as_secs_f64()
        );
    }
}
