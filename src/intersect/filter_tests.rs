//! Tests of the float filter against independent exact answers: the exact solver alone
//! ([`exact_solver_alone`]: resultants and subresultants, never the filter, which
//! [`intersect_curves_f64`] runs first) for cubic pairs, and for curves of degree 8 and 20
//! against a horizontal line, the exact zeros of the Bézier function P_y - c ([`bezier_zeros`],
//! Descartes' rule) with t = P_x(s) rounded exactly ([`round_polynomial_at`]): no resultant
//! involved. Degrees 9 to 40 are checked against the independent truth of
//! `tests/intersect_corpus/high_degree/` (`tests.rs`).

use super::algebraic::{round_polynomial_at, upoly_eval_q};
use super::curves::{intersect_curves, intersect_curves_f64, Intersections};
use super::filter::{
    certified_crossings_f64, certified_crossings_plain, clip_cell, crossing_parameters_f64,
    krawczyk_offsets, tangent_enclosure, CertifiedCrossing,
};
use super::interval::round_nearest;
use super::rounded::{intersect_curves_f64_rounded, RoundedIntersections, RoundedPoint};
use super::zeros::bezier_zeros_f64;
use crate::num::bounded::BoundedF64;
use crate::num::ring::Rational;
use crate::shape::basis::bernstein_to_power;
use num_traits::{FromPrimitive, Signed};

/// Samples drawn from the shared test generator ([`crate::test_rng::XorShift`]).
struct Random(crate::test_rng::XorShift);

impl Random {
    fn next(&mut self) -> u64 {
        self.0.next()
    }
    /// An integer in [-k, k].
    fn int(&mut self, k: i64) -> f64 {
        (self.next() % (2 * k as u64 + 1)) as f64 - k as f64
    }
    /// A dyadic number j / 2^bits in [0, 1].
    fn dyadic(&mut self, bits: u32) -> f64 {
        (self.next() % ((1u64 << bits) + 1)) as f64 / (1u64 << bits) as f64
    }
    /// A uniform double in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The filter's answer as rounded points (tangent false).
fn as_points(x: &[CertifiedCrossing]) -> Vec<RoundedPoint> {
    x.iter()
        .map(|c| RoundedPoint {
            s: c.s,
            t: c.t,
            tangent: false,
            point: c.point,
        })
        .collect()
}

/// The exact solver's answer alone, without the float filter that [`intersect_curves`] runs
/// first when every coordinate is a double: both curves are translated by (1/3, 0), which
/// keeps every parameter and tangency and leaves no coordinate a double (x + 1/3 has a
/// denominator divisible by 3 for every double x), so the pair goes straight to the solver.
/// The common points are those of the curves as given: each coordinate of P(s) rounded
/// correctly at the exact s.
fn exact_solver_alone(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
) -> crate::error::Result<RoundedIntersections> {
    let third = Rational::new(1.into(), 3.into());
    let shifted = |c: &[[f64; 2]]| -> Vec<[Rational; 2]> {
        c.iter()
            .map(|xy| {
                let [x, y] = xy.map(|v| Rational::from_f64(v).unwrap());
                [x + &third, y]
            })
            .collect()
    };
    let x: Intersections = intersect_curves(&shifted(p), &shifted(q))?;
    let power: Vec<Vec<Rational>> = bernstein_to_power(
        &p.iter()
            .map(|xy| xy.map(|v| Rational::from_f64(v).unwrap()).to_vec())
            .collect::<Vec<_>>(),
    );
    let coordinate = |k: usize| -> Vec<Rational> { power.iter().map(|c| c[k].clone()).collect() };
    let (px, py) = (coordinate(0), coordinate(1));
    let mut rounded = RoundedIntersections::from(&x);
    for (r, exact) in rounded.points.iter_mut().zip(&x.points) {
        r.point = [
            round_polynomial_at(&px, &exact.s),
            round_polynomial_at(&py, &exact.s),
        ];
    }
    Ok(rounded)
}

/// Checks one pair against the exact solver alone; returns whether the filter decided.
fn check_against_exact(p: &[[f64; 2]], q: &[[f64; 2]]) -> bool {
    let exact = exact_solver_alone(p, q).unwrap();
    let Some(filter) = certified_crossings_f64(p, q) else {
        return false;
    };
    assert!(exact.overlaps.is_empty(), "{p:?} {q:?}");
    assert_eq!(as_points(&filter), exact.points, "{p:?} {q:?}");
    for c in &filter {
        assert!(c.s_enclosure[0] <= c.s && c.s <= c.s_enclosure[1]);
        assert!(c.t_enclosure[0] <= c.t && c.t <= c.t_enclosure[1]);
    }
    true
}

#[test]
fn cubic_pairs_agree_with_the_exact_path_to_the_bit() {
    let mut r = Random(crate::test_rng::XorShift(0x2545_f491_4f6c_dd1d));
    let (mut decided, mut crossings) = (0, 0);
    let pairs = 200;
    for k in 0..pairs {
        // Half small integers, half dyadic numbers in [0, 1].
        let point = |r: &mut Random| {
            if k % 2 == 0 {
                [r.int(8), r.int(8)]
            } else {
                [r.dyadic(6), r.dyadic(6)]
            }
        };
        let p: Vec<[f64; 2]> = (0..4).map(|_| point(&mut r)).collect();
        let q: Vec<[f64; 2]> = (0..4).map(|_| point(&mut r)).collect();
        if check_against_exact(&p, &q) {
            decided += 1;
            crossings += certified_crossings_f64(&p, &q).unwrap().len();
        }
    }
    println!("decided {decided} of {pairs} cubic pairs, {crossings} crossings");
    assert!(
        decided * 10 >= pairs * 9,
        "decided only {decided} of {pairs}"
    );
    assert!(
        crossings >= pairs / 2,
        "too few crossings to mean anything: {crossings}"
    );
}

#[test]
fn lines_and_quadratics_agree_with_the_exact_path() {
    let mut r = Random(crate::test_rng::XorShift(0x0123_4567_89ab_cdef));
    let mut decided = 0;
    for k in 0..100 {
        let (n, m) = (1 + k % 2, 1 + (k / 2) % 3);
        let p: Vec<[f64; 2]> = (0..=n).map(|_| [r.int(6), r.int(6)]).collect();
        let q: Vec<[f64; 2]> = (0..=m).map(|_| [r.int(6), r.int(6)]).collect();
        if p.iter().all(|x| x == &p[0]) || q.iter().all(|x| x == &q[0]) {
            continue;
        }
        // Collinear pairs may be overlaps, refused or decided by the exact path: skip errors.
        if exact_solver_alone(&p, &q).is_err() {
            assert!(certified_crossings_f64(&p, &q).is_none());
            continue;
        }
        decided += usize::from(check_against_exact(&p, &q));
    }
    assert!(decided >= 60, "decided {decided}");
}

/// A curve of degree n against the line y = c from (0, c) to (1, c): the exact answer from the
/// zeros of P_y - c and t = P_x(s).
fn line_case(r: &mut Random, n: usize) -> (Vec<[f64; 2]>, Vec<[f64; 2]>, Vec<RoundedPoint>) {
    let p: Vec<[f64; 2]> = (0..=n)
        .map(|_| {
            let x = (1.0 + (r.next() % 1023) as f64) / 1024.0;
            [x, 2.0 * r.dyadic(10) - 1.0]
        })
        .collect();
    let c = 0.5 * r.dyadic(8) - 0.25;
    let q = vec![[0.0, c], [1.0, c]];
    let fy: Vec<f64> = p.iter().map(|xy| xy[1] - c).collect();
    let zeros = bezier_zeros_f64(&fy).unwrap();
    assert!(!zeros.identically_zero);
    let px: Vec<Vec<Rational>> = p
        .iter()
        .map(|xy| vec![Rational::from_f64(xy[0]).unwrap()])
        .collect();
    let power: Vec<Rational> = bernstein_to_power(&px)
        .into_iter()
        .map(|v| v[0].clone())
        .collect();
    let expected = zeros
        .zeros
        .iter()
        .map(|z| {
            let t = round_polynomial_at(&power, &z.t);
            RoundedPoint {
                s: z.t.to_f64(),
                t,
                tangent: z.multiplicity > 1,
                point: [t, c],
            }
        })
        .collect();
    (p, q, expected)
}

#[test]
fn degree_8_and_20_against_a_line_agree_with_exact_zeros() {
    let mut r = Random(crate::test_rng::XorShift(0x9e37_79b9_7f4a_7c15));
    for n in [8usize, 20] {
        let (mut decided, mut crossings, cases) = (0, 0, 40);
        for _ in 0..cases {
            let (p, q, expected) = line_case(&mut r, n);
            if let Some(x) = certified_crossings_f64(&p, &q) {
                assert_eq!(as_points(&x), expected, "{p:?} {q:?}");
                // And the same with the curves swapped.
                let y = certified_crossings_f64(&q, &p).expect("decided one way");
                let swapped: Vec<(f64, f64)> = y.iter().map(|c| (c.t, c.s)).collect();
                let mut direct: Vec<(f64, f64)> = x.iter().map(|c| (c.s, c.t)).collect();
                direct.sort_by(|a, b| a.0.total_cmp(&b.0));
                let mut swapped = swapped;
                swapped.sort_by(|a, b| a.0.total_cmp(&b.0));
                assert_eq!(direct, swapped);
                decided += 1;
                crossings += x.len();
            }
        }
        println!("degree {n}: decided {decided} of {cases}, {crossings} crossings");
        assert!(
            decided * 10 >= cases * 9,
            "degree {n}: decided {decided} of {cases}"
        );
        assert!(crossings >= cases, "degree {n}: only {crossings} crossings");
    }
}

#[test]
fn random_degree_20_pairs_are_decided_consistently() {
    // The filter must decide most pairs and agree with itself with the curves swapped, and
    // every crossing (s, t) must be a common point: |P(s) - Q(t)|, computed exactly at the
    // doubles s and t, is at most what moving each half an ulp to the exact parameter can
    // change it by (the curves' Lipschitz bounds n max |b_(i+1) - b_i|, exactly). The
    // answers themselves at degrees 9 to 40 are checked against an independent truth in
    // `tests.rs`.
    let mut r = Random(crate::test_rng::XorShift(0x5851_f42d_4c95_7f2d));
    let (mut decided, cases) = (0, 20);
    for _ in 0..cases {
        let p: Vec<[f64; 2]> = (0..=20).map(|_| [r.unit(), r.unit()]).collect();
        let q: Vec<[f64; 2]> = (0..=20).map(|_| [r.unit(), r.unit()]).collect();
        let Some(x) = certified_crossings_f64(&p, &q) else {
            continue;
        };
        decided += 1;
        let y = certified_crossings_f64(&q, &p).expect("decided one way");
        let mut swapped: Vec<(f64, f64, [f64; 2])> =
            y.iter().map(|c| (c.t, c.s, c.point)).collect();
        swapped.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let direct: Vec<(f64, f64, [f64; 2])> = x.iter().map(|c| (c.s, c.t, c.point)).collect();
        assert_eq!(direct, swapped);
        for c in &x {
            assert_common_point(&p, &q, c.s, c.t);
        }
    }
    assert!(decided * 10 >= cases * 9, "decided {decided} of {cases}");
}

/// |P(s) - Q(t)| <= (L_P ulp(s) + L_Q ulp(t)) / 2 in each coordinate, exactly: s and t are
/// the doubles nearest to a common point's parameters, L the largest |n (b_(i+1) - b_i)|
/// (a bound on |P'| over [0, 1]) and ulp the larger gap next to the double.
fn assert_common_point(p: &[[f64; 2]], q: &[[f64; 2]], s: f64, t: f64) {
    let exact = |v: f64| Rational::from_f64(v).unwrap();
    let ulp = |v: f64| {
        let up = f64::from_bits(v.to_bits() + 1) - v;
        let down = if v > 0.0 {
            v - f64::from_bits(v.to_bits() - 1)
        } else {
            up
        };
        exact(up.max(down))
    };
    for k in 0..2 {
        let at = |c: &[[f64; 2]], x: f64| -> (Rational, Rational) {
            let b: Vec<Vec<Rational>> = c.iter().map(|xy| vec![exact(xy[k])]).collect();
            let power: Vec<Rational> = bernstein_to_power(&b)
                .into_iter()
                .map(|v| v[0].clone())
                .collect();
            let n = Rational::from_integer((c.len() - 1).into());
            let lipschitz = c
                .windows(2)
                .map(|w| (exact(w[1][k]) - exact(w[0][k])).abs() * &n)
                .max()
                .unwrap();
            (upoly_eval_q(&power, &exact(x)), lipschitz)
        };
        let ((ps, lp), (qt, lq)) = (at(p, s), at(q, t));
        let half = Rational::new(1.into(), 2.into());
        let bound = (lp * ulp(s) + lq * ulp(t)) * half;
        assert!(
            (ps - qt).abs() <= bound,
            "({s}, {t}) is not a common point of {p:?} {q:?}"
        );
    }
}

#[test]
fn undecided_cases_go_to_the_exact_path() {
    let parabola = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
    // Tangent at the apex (1, 1).
    let tangent_line = [[0.0, 1.0], [2.0, 1.0]];
    assert!(certified_crossings_f64(&parabola, &tangent_line).is_none());
    let x = intersect_curves_f64_rounded(&parabola, &tangent_line).unwrap();
    assert!(!x.by_filter && x.points.len() == 1 && x.points[0].tangent);
    // An end-point contact.
    let a = [[0.0, 0.0], [1.0, 1.0]];
    let b = [[1.0, 1.0], [2.0, 0.0]];
    assert!(certified_crossings_f64(&a, &b).is_none());
    // Identical, reversed, and a stretch of one curve.
    let cubic = [[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [3.0, 1.0]];
    let reversed: Vec<[f64; 2]> = cubic.iter().rev().copied().collect();
    let half = [[0.0, 0.0], [0.5, 1.5], [1.0, 1.25], [1.5, 0.875]];
    for other in [&cubic[..], &reversed, &half] {
        assert!(certified_crossings_f64(&cubic, other).is_none());
        let x = intersect_curves_f64_rounded(&cubic, other).unwrap();
        assert!(!x.by_filter && x.overlaps.len() == 1);
    }
    // A common point with a zero coordinate cannot be rounded from an enclosure.
    let c = [[-1.0, -1.0], [1.0, 1.0]];
    let d = [[-1.0, 1.0], [1.0, -1.0]];
    assert!(certified_crossings_f64(&c, &d).is_none());
    // Bad input: no answer from the filter, the exact path's error naming the field.
    assert!(certified_crossings_f64(&[[0.0, f64::NAN], [1.0, 1.0]], &d).is_none());
    let e = intersect_curves_f64_rounded(&[[0.0, f64::NAN], [1.0, 1.0]], &d).unwrap_err();
    assert_eq!(e.field, "p[0][1]");
    assert!(certified_crossings_f64(&[[1.0, 1.0]], &d).is_none());
    assert!(certified_crossings_f64(&[[1.0, 1.0], [1.0, 1.0]], &d).is_none());
}

/// Crossings on an axis (a common point with a zero coordinate, which the filter cannot round
/// from an enclosure) are decided by the parameters-only entry the regions use, with the
/// exact solver's parameters to the bit; elsewhere it agrees with the full filter.
#[test]
fn parameters_alone_are_decided_where_the_point_cannot_be_rounded() {
    let mut r = Random(crate::test_rng::XorShift(0x5eed_0a15));
    let mut decided = 0;
    for k in 0..60 {
        // A segment on the x axis (k even) or on the y axis, and a quadratic across it.
        let a = [[-40.0 - k as f64, 0.0], [45.0 + r.unit() * 10.0, 0.0]];
        let mut q = [
            [r.unit() * 20.0 - 10.0, -30.0 - r.unit() * 10.0],
            [r.unit() * 20.0 - 10.0, r.unit() * 20.0 - 10.0],
            [r.unit() * 20.0 - 10.0, 25.0 + r.unit() * 10.0],
        ];
        let mut p = a;
        if k % 2 == 1 {
            p = a.map(|[x, y]| [y, x]);
            q = q.map(|[x, y]| [y, x]);
        }
        let exact = exact_solver_alone(&p, &q).unwrap();
        assert!(certified_crossings_f64(&p, &q).is_none(), "{p:?} {q:?}");
        let Some(found) = crossing_parameters_f64(&p, &q) else {
            continue;
        };
        decided += 1;
        assert!(exact.overlaps.is_empty());
        let params: Vec<[f64; 2]> = found.iter().map(|c| [c.s, c.t]).collect();
        let wanted: Vec<[f64; 2]> = exact.points.iter().map(|x| [x.s, x.t]).collect();
        assert_eq!(params, wanted, "{p:?} {q:?}");
        for c in &found {
            assert!(c.point[0].is_nan() && c.point[1].is_nan());
            assert!(c.s_enclosure[0] <= c.s && c.s <= c.s_enclosure[1]);
            assert!(c.t_enclosure[0] <= c.t && c.t <= c.t_enclosure[1]);
        }
    }
    assert!(decided >= 50, "only {decided} of 60 decided");
    // Off the axes the two entries give the same crossings.
    let (p, q) = (
        [[-1.0, -1.5], [1.0, 1.25]],
        [[-1.0, 1.0], [0.5, 0.0], [1.0, -1.0]],
    );
    let full = certified_crossings_f64(&p, &q).unwrap();
    let alone = crossing_parameters_f64(&p, &q).unwrap();
    assert_eq!(full.len(), 1);
    assert_eq!((full[0].s, full[0].t), (alone[0].s, alone[0].t));
}

#[test]
fn near_tangency_is_decided_right_or_left_to_the_exact_path() {
    // The parabola against lines just below its apex: two crossings 2 sqrt(eps) apart.
    let parabola = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
    let mut decided = 0;
    for k in 1..40 {
        let y = 1.0 - 2f64.powi(-k);
        let line = [[0.0, y], [2.0, y]];
        let exact = exact_solver_alone(&parabola, &line).unwrap();
        assert_eq!(exact.points.len(), 2);
        if let Some(x) = certified_crossings_f64(&parabola, &line) {
            assert_eq!(as_points(&x), exact.points, "k = {k}");
            decided += 1;
        }
    }
    // Roots 2^(1 - k/2) apart are separated by subdivision down to 2^-40 for small k.
    assert!(decided >= 20, "decided {decided}");
}

#[test]
fn rounded_answer_is_the_exact_answer_rounded() {
    let mut r = Random(crate::test_rng::XorShift(0xdead_beef_cafe_f00d));
    let mut by_filter = 0;
    for _ in 0..40 {
        let p: Vec<[f64; 2]> = (0..4).map(|_| [r.int(5), r.int(5)]).collect();
        let q: Vec<[f64; 2]> = (0..3).map(|_| [r.int(5), r.int(5)]).collect();
        let Ok(mut want) = exact_solver_alone(&p, &q) else {
            continue;
        };
        let got = intersect_curves_f64_rounded(&p, &q).unwrap();
        by_filter += usize::from(got.by_filter);
        want.by_filter = got.by_filter;
        assert_eq!(got, want);
    }
    assert!(by_filter >= 20, "by filter {by_filter}");
}

#[test]
fn reused_search_state_does_not_change_answers() {
    // The per-thread search state is reused: the same pairs in another order, mixed with
    // curves of other degrees, and on another thread, give the same answers.
    let mut r = Random(crate::test_rng::XorShift(0x7f4a_7c15_9e37_79b9));
    let curves: Vec<Vec<[f64; 2]>> = (0..60)
        .map(|k| (0..=1 + k % 6).map(|_| [r.unit(), r.unit()]).collect())
        .collect();
    let pairs: Vec<&[Vec<[f64; 2]>]> = curves.chunks_exact(2).collect();
    let forward: Vec<_> = pairs
        .iter()
        .map(|c| certified_crossings_f64(&c[0], &c[1]))
        .collect();
    let mut backward: Vec<_> = pairs
        .iter()
        .rev()
        .map(|c| certified_crossings_f64(&c[0], &c[1]))
        .collect();
    backward.reverse();
    assert_eq!(forward, backward);
    let threaded = std::thread::scope(|scope| {
        scope
            .spawn(|| {
                pairs
                    .iter()
                    .map(|c| certified_crossings_f64(&c[0], &c[1]))
                    .collect::<Vec<_>>()
            })
            .join()
            .unwrap()
    });
    assert_eq!(forward, threaded);
    assert!(forward.iter().filter(|x| x.is_some()).count() >= 25);
}

/// Times the filter on 10^4 random cubic pairs (coordinates uniform doubles in [0, 1]) and on
/// random pairs of degree 8 and 20, with lyon_geom's uncertified `cubic_intersections_t` on
/// the same cubic pairs for reference, and the exact path on the pairs the filter leaves. A
/// measurement, not a check:
/// `cargo test -p blossom --release --lib intersect::filter_tests::timing -- --ignored --nocapture`
/// (pairs from `BLOSSOM_PAIRS`, default 10000; degrees from `BLOSSOM_DEGREES`, default "8 20").
#[test]
#[ignore]
fn timing_filter() {
    use lyon_geom::{point, CubicBezierSegment};
    use std::time::Instant;
    let pairs: usize = std::env::var("BLOSSOM_PAIRS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10_000);
    let mut r = Random(crate::test_rng::XorShift(0x2545_f491_4f6c_dd1d));
    let cubics: Vec<[[f64; 2]; 4]> = (0..2 * pairs)
        .map(|_| std::array::from_fn(|_| [r.unit(), r.unit()]))
        .collect();
    let (mut crossings, mut undecided) = (0usize, Vec::new());
    for pq in cubics.chunks_exact(2) {
        match certified_crossings_f64(&pq[0], &pq[1]) {
            Some(x) => crossings += x.len(),
            None => undecided.push(pq),
        }
    }
    let segment = |c: &[[f64; 2]; 4]| CubicBezierSegment {
        from: point(c[0][0], c[0][1]),
        ctrl1: point(c[1][0], c[1][1]),
        ctrl2: point(c[2][0], c[2][1]),
        to: point(c[3][0], c[3][1]),
    };
    let segments: Vec<CubicBezierSegment<f64>> = cubics.iter().map(segment).collect();
    let lyon_crossings: usize = segments
        .chunks_exact(2)
        .map(|pq| pq[0].cubic_intersections_t(&pq[1]).len())
        .sum();
    // Five interleaved rounds on the shared machine; the fastest pass of each.
    let (mut filter, mut lyon) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..5 {
        let start = Instant::now();
        for pq in cubics.chunks_exact(2) {
            std::hint::black_box(certified_crossings_f64(&pq[0], &pq[1]));
        }
        filter = filter.min(start.elapsed().as_secs_f64() / pairs as f64);
        let start = Instant::now();
        for pq in segments.chunks_exact(2) {
            std::hint::black_box(pq[0].cubic_intersections_t(&pq[1]));
        }
        lyon = lyon.min(start.elapsed().as_secs_f64() / pairs as f64);
    }
    println!(
        "cubic: {pairs} pairs, filter {:.2} us/pair ({crossings} crossings, {} undecided), lyon {:.2} us/pair ({lyon_crossings} crossings), filter/lyon {:.2} (fastest of 5 interleaved passes)",
        filter * 1e6,
        undecided.len(),
        lyon * 1e6,
        filter / lyon
    );
    let start = Instant::now();
    for pq in &undecided {
        intersect_curves_f64(&pq[0], &pq[1]).unwrap();
    }
    if !undecided.is_empty() {
        println!(
            "exact path on the undecided pairs: {:.1} ms/pair",
            start.elapsed().as_secs_f64() / undecided.len() as f64 * 1e3
        );
    }
    let degrees = std::env::var("BLOSSOM_DEGREES").unwrap_or_else(|_| "8 20".into());
    for n in degrees
        .split_whitespace()
        .map(|d| d.parse::<usize>().unwrap())
    {
        let count = 200;
        let curves: Vec<Vec<[f64; 2]>> = (0..2 * count)
            .map(|_| (0..=n).map(|_| [r.unit(), r.unit()]).collect())
            .collect();
        let start = Instant::now();
        let (mut undecided, mut crossings, mut worst) = (0usize, 0usize, 0f64);
        for pq in curves.chunks_exact(2) {
            let one = Instant::now();
            match certified_crossings_f64(&pq[0], &pq[1]) {
                Some(x) => crossings += x.len(),
                None => undecided += 1,
            }
            worst = worst.max(one.elapsed().as_secs_f64());
        }
        println!(
            "degree {n}: {count} pairs, filter {:.1} us/pair (worst {:.1} us), {crossings} crossings, {undecided} undecided",
            start.elapsed().as_secs_f64() / count as f64 * 1e6,
            worst * 1e6
        );
    }
}

/// Crossings of a cubic with x = 3s against a vertical segment x = x0, x0 within a few ulps of
/// 3/2, 3/4, 9/4 and 1: the exact parameter s* = x0 / 3 (whose correctly rounded double is the
/// IEEE quotient x0 / 3) lies within a few ulps of the cell ends 1/2, 1/4, 3/4 that halving
/// makes, or of 1/3. The fat line of the vertical segment has no width of its own: the band
/// is its margins alone, and the clipped ranges end within a few ulps of s*, so that margins
/// smaller than the rounding they cover (in the restriction, the distance coefficients, the
/// crossings, the mapping to the global parameter) would lose the crossing or round it wrong.
#[test]
fn crossings_within_ulps_of_cell_ends_keep_their_margins() {
    let mut r = Random(crate::test_rng::XorShift(0x1405_7b7e_f767_814f));
    let (mut decided, mut cases) = (0, 0);
    for base in [1.5f64, 0.75, 2.25, 1.0] {
        let mut x0 = base;
        for _ in 0..6 {
            x0 = x0.next_down();
        }
        for _ in 0..13 {
            // y random in [-8, 8): one transversal crossing with the segment from y = -9 to 9.
            let p: Vec<[f64; 2]> = (0..4).map(|k| [k as f64, 16.0 * r.unit() - 8.0]).collect();
            let q: Vec<[f64; 2]> = [-9.0, -3.0, 3.0, 9.0].map(|y| [x0, y]).to_vec();
            for (first, second, swapped) in [(&p, &q, false), (&q, &p, true)] {
                cases += 1;
                if !check_against_exact(first, second) {
                    continue;
                }
                decided += 1;
                let x = certified_crossings_f64(first, second).unwrap();
                assert_eq!(x.len(), 1, "{p:?} {q:?}");
                let s = if swapped { x[0].t } else { x[0].s };
                assert_eq!(s, x0 / 3.0, "{p:?} {q:?}");
            }
            x0 = x0.next_up();
        }
    }
    assert!(decided * 10 >= cases * 9, "decided {decided} of {cases}");
}

/// A root exactly at a cell end, where the distance coefficient D_0 of the piece is exactly on
/// a fat line of no width of its own (the horizontal segment y = 0) and the piece leaves it:
/// P_y(s) = (s - a) g(s) with a = m 2^-30 and g's Bernstein coefficients multiples of 3, so that
/// P's control points are exact doubles (checked in rationals) while de Casteljau's steps at a
/// round. Only the margins keep the computed D_0 in the band: without them the rounding puts
/// it beyond in about half the cases, every coefficient on one side, and the cell (with its
/// root) would be dropped. The cell [a, a + w] must keep local 0, [a - w, a] local 1.
#[test]
fn a_root_at_a_cell_end_survives_clipping() {
    let mut r = Random(crate::test_rng::XorShift(0x6a09_e667_f3bc_c909));
    let third = |x: f64| x / 3.0;
    for _ in 0..200 {
        let a = (1 + r.next() % ((1 << 30) - 1)) as f64 * 2f64.powi(-30);
        let g = [3.0 * r.int(5), 3.0 * r.int(5), 3.0 * r.int(5)];
        if g[0] == 0.0 || g[2] == 0.0 {
            continue;
        }
        // (s - a) g(s) in Bernstein form of degree 3 (exact: a has 30 bits, g small).
        let y = [
            -a * g[0],
            third((1.0 - a) * g[0] - 2.0 * a * g[1]),
            third(2.0 * (1.0 - a) * g[1] - a * g[2]),
            (1.0 - a) * g[2],
        ];
        let ry = y.map(|v| Rational::from_f64(v).unwrap());
        let ra = Rational::from_f64(a).unwrap();
        let one = Rational::from_integer(1.into());
        let b = |k: usize, s: &Rational| {
            let c = [1, 3, 3, 1][k];
            let mut v = Rational::from_integer(c.into());
            for _ in 0..k {
                v = &v * s;
            }
            for _ in k..3 {
                v = &v * &(&one - s);
            }
            v
        };
        let at_a = (0..4).fold(Rational::from_integer(0.into()), |acc, k| {
            &acc + &(&b(k, &ra) * &ry[k])
        });
        assert_eq!(
            at_a,
            Rational::from_integer(0.into()),
            "the construction is exact"
        );
        let p: Vec<[f64; 2]> = (0..4).map(|k| [k as f64 + r.unit(), y[k]]).collect();
        let q: Vec<[f64; 2]> = [-20.0, -7.0, 7.0, 20.0].map(|x| [x, 0.0]).to_vec();
        for w in [2f64.powi(-12), 2f64.powi(-24), 2f64.powi(-36)] {
            if a + w <= 1.0 {
                let u = clip_cell(&p, &q, [a, a + w], [0.0, 1.0]);
                assert_eq!(u.map(|u| u[0]), Some(0.0), "{p:?} [a, a + {w}]");
            }
            if a - w >= 0.0 {
                let u = clip_cell(&p, &q, [a - w, a], [0.0, 1.0]);
                assert_eq!(u.map(|u| u[1]), Some(1.0), "{p:?} [a - {w}, a]");
            }
        }
    }
}

/// Krawczyk's operator in plain `f64` ([`krawczyk_offsets`]) against the exact set it must
/// enclose: with Y the filter's computed inverse of the midpoint Jacobian a (recomputed here
/// the same way), K(X) - m lies in M ± R* exactly, M = -Y f and
/// R*_i = Σ_k |Y_ik| e_k + Σ_j (|δ_ij - Σ_k Y_ik a_kj| + Σ_k |Y_ik| ρ_kj) r_j (the extremes of
/// an affine function over the boxes), in rationals. Cases with no input bounds and zero radii
/// make R* = 0, so that the computed radius must cover the rounding of μ alone, and small
/// radii with exact Jacobians make the rounding of I - Y a matter: without the margins of the
/// module documentation (3u T, 3u |a|) the enclosure misses M ± R*.
#[test]
fn krawczyk_in_plain_f64_encloses_the_exact_operator() {
    let mut r = Random(crate::test_rng::XorShift(0x1f83_d9ab_fb41_bd6b));
    let q = |x: f64| Rational::from_f64(x).unwrap();
    let abs = |x: Rational| if x < q(0.0) { -x } else { x };
    let (mut proved, mut checked) = (0, 0);
    for round in 0..3000 {
        let scale = 2f64.powi((r.next() % 40) as i32 - 20);
        let mut value = || scale * (2.0 * r.unit() - 1.0);
        let (fv, av): ([f64; 2], [[f64; 2]; 2]) = (
            [value() * 1e-3, value() * 1e-3],
            [[value(), value()], [value(), value()]],
        );
        let kind = round % 3;
        let bound = |x: f64, r: &mut Random| match kind {
            0 => 0.0,
            _ => x.abs() * 1e-16 * r.unit(),
        };
        let f = fv.map(|x| BoundedF64::with_bound(x, bound(x, &mut r)));
        let dp = [0, 1].map(|c| BoundedF64::with_bound(av[c][0], bound(av[c][0], &mut r)));
        let dq = [0, 1].map(|c| BoundedF64::with_bound(-av[c][1], bound(av[c][1], &mut r)));
        let radius = match kind {
            0 => [0.0, 0.0],
            1 => [2f64.powi(-40) * r.unit(), 2f64.powi(-40) * r.unit()],
            _ => [0.5 * r.unit(), 0.5 * r.unit()],
        };
        let mid = [r.unit(), r.unit()];
        let Some((offset, ok)) = krawczyk_offsets(mid, radius, f, dp, dq) else {
            continue;
        };
        checked += 1;
        // Y as the filter computes it.
        let a = [
            [dp[0].value(), -dq[0].value()],
            [dp[1].value(), -dq[1].value()],
        ];
        let rho = [
            [dp[0].error_bound(), dq[0].error_bound()],
            [dp[1].error_bound(), dq[1].error_bound()],
        ];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let inverse = 1.0 / det;
        let y = [
            [a[1][1] * inverse, -a[0][1] * inverse],
            [-a[1][0] * inverse, a[0][0] * inverse],
        ];
        for i in 0..2 {
            let m = -(q(y[i][0]) * q(fv[0]) + q(y[i][1]) * q(fv[1]));
            let mut rad =
                abs(q(y[i][0])) * q(f[0].error_bound()) + abs(q(y[i][1])) * q(f[1].error_bound());
            for j in 0..2 {
                let identity = q(if i == j { 1.0 } else { 0.0 });
                let c = identity - (q(y[i][0]) * q(a[0][j]) + q(y[i][1]) * q(a[1][j]));
                let spread = abs(q(y[i][0])) * q(rho[0][j]) + abs(q(y[i][1])) * q(rho[1][j]);
                rad += (abs(c) + spread) * q(radius[j]);
            }
            let (mu, big) = (q(offset[i].value()), q(offset[i].error_bound()));
            assert!(&mu - &big <= &m - &rad, "{f:?} {dp:?} {dq:?} {radius:?}");
            assert!(&m + &rad <= &mu + &big, "{f:?} {dp:?} {dq:?} {radius:?}");
            if ok {
                assert!(abs(mu) + big < q(radius[i]));
            }
        }
        proved += ok as usize;
    }
    assert!(
        checked > 2900 && proved > 100,
        "{checked} checked, {proved} proved"
    );
}

/// The exact derivative of the curve with control points `points` at the rational `s`: de
/// Casteljau in rationals on the exact hodograph n (p_(i+1) - p_i).
fn exact_derivative(points: &[[f64; 2]], s: &Rational) -> [Rational; 2] {
    let q = |x: f64| Rational::from_f64(x).unwrap();
    let n = q((points.len() - 1) as f64);
    let mut level: Vec<[Rational; 2]> = points
        .windows(2)
        .map(|w| [0, 1].map(|c| &n * (q(w[1][c]) - q(w[0][c]))))
        .collect();
    let one_minus = q(1.0) - s;
    for k in (1..level.len()).rev() {
        for i in 0..k {
            level[i] = [0, 1].map(|c| &one_minus * &level[i][c] + s * &level[i + 1][c]);
        }
    }
    level.swap_remove(0)
}

/// The enclosure of P'(S) over S = mid ± radius holds the exact derivative at the ends of S,
/// its middle and points inside, for degrees 1 to 7, sizes 2^±250 and radii from 0 to 1/2,
/// both inside [0, 1] (the mean value bound) and reaching outside it (the hodograph
/// pyramid). Without the term r G the enclosure misses the ends of wide boxes; without the
/// rounding terms it misses at radius 0 for many curves.
#[test]
fn tangent_enclosure_holds_the_exact_derivative() {
    let mut r = Random(crate::test_rng::XorShift(0x6a09_e667_f3bc_c908));
    let q = |x: f64| Rational::from_f64(x).unwrap();
    let (mut inside, mut outside) = (0, 0);
    for round in 0..1500 {
        let n = 1 + round % 7;
        let scale = 2f64.powi((r.next() % 501) as i32 - 250);
        let points: Vec<[f64; 2]> = (0..=n)
            .map(|_| {
                [
                    scale * (2.0 * r.unit() - 1.0),
                    scale * (2.0 * r.unit() - 1.0),
                ]
            })
            .collect();
        let mid = r.unit();
        let radius = match round % 4 {
            0 => 0.0,
            1 => 2f64.powi(-48) * r.unit(),
            2 => 2f64.powi(-20) * r.unit(),
            _ => 0.5 * r.unit(),
        };
        let Some(enclosure) = tangent_enclosure(&points, mid, radius) else {
            continue;
        };
        if radius <= mid && mid + radius < 1.0 {
            inside += 1;
        } else {
            outside += 1;
        }
        let (m, w) = (q(mid), q(radius));
        let samples = [
            &m - &w,
            m.clone(),
            &m + &w,
            &m + &w * q(2.0 * r.unit() - 1.0),
        ];
        for s in samples {
            let exact = exact_derivative(&points, &s);
            for c in 0..2 {
                let (v, e) = (q(enclosure[c].value()), q(enclosure[c].error_bound()));
                assert!(
                    &v - &e <= exact[c] && exact[c] <= &v + &e,
                    "{points:?} at {mid} ± {radius}"
                );
            }
        }
    }
    assert!(
        inside > 900 && outside > 150,
        "{inside} inside, {outside} outside"
    );
}

/// A decided rounding is the double strictly nearest to every point of the enclosure
/// (compared with both neighbours in exact rationals, so no tie is ever decided), on bases
/// of both signs and all sizes, offsets near half a gap and near powers of two; enclosures
/// well inside a rounding interval are decided.
#[test]
fn rounding_decisions_are_the_nearest_double_of_the_whole_enclosure() {
    let mut r = Random(crate::test_rng::XorShift(0xbb67_ae85_84ca_a73b));
    let q = |x: f64| Rational::from_f64(x).unwrap();
    let abs = |x: Rational| if x < q(0.0) { -x } else { x };
    let (mut decided, mut clear) = (0, 0);
    for round in 0..20000 {
        let sign = if r.next().is_multiple_of(2) {
            1.0
        } else {
            -1.0
        };
        let exponent = (r.next() % 2001) as i32 - 1000;
        // Powers of two (a gap changes there) and random mantissas.
        let mantissa = if round % 5 == 0 { 1.0 } else { 1.0 + r.unit() };
        let base = sign * mantissa * 2f64.powi(exponent);
        let gap = (base.abs().next_up() - base.abs()).max(f64::MIN_POSITIVE);
        // Offsets of a few gaps, often near a half gap.
        let whole = (r.next() % 5) as f64 - 2.0;
        let part = match round % 3 {
            0 => 0.5 + (r.unit() - 0.5) * 1e-6,
            _ => r.unit(),
        };
        let v = (whole + part) * gap;
        let e = gap
            * match round % 4 {
                0 => 0.0,
                1 => 1e-12 * r.unit(),
                2 => 1e-3 * r.unit(),
                _ => r.unit(),
            };
        let offset = BoundedF64::with_bound(v, e);
        let Some(c) = round_nearest(base, &offset) else {
            continue;
        };
        decided += 1;
        let (below, above) = (q(c.next_down()), q(c.next_up()));
        for x in [q(base) + q(v) - q(e), q(base) + q(v) + q(e)] {
            let d = abs(&x - q(c));
            assert!(
                d < abs(&x - &below) && d < abs(&x - &above),
                "{base} + {v} ± {e}"
            );
        }
        clear += (e < 1e-3 * gap && part > 0.1 && part < 0.4) as usize;
    }
    assert!(
        decided > 8000 && clear > 1000,
        "{decided} decided ({clear} clear)"
    );
}

/// The builds compiled for AVX2 (where the processor has it) and the plain ones give the
/// same answers, bit for bit, on random pairs of degrees 1 to 5 (cubics, the fixed-size path,
/// and vectors for the rest), and decide them.
#[test]
fn avx2_and_plain_builds_give_the_same_bits() {
    let mut r = Random(crate::test_rng::XorShift(0x3c6e_f372_fe94_f82b));
    let bits = |x: &Option<Vec<CertifiedCrossing>>| {
        x.as_ref().map(|v| {
            v.iter()
                .map(|c| {
                    [c.s, c.t, c.point[0], c.point[1]]
                        .map(f64::to_bits)
                        .into_iter()
                        .chain(c.s_enclosure.map(f64::to_bits))
                        .chain(c.t_enclosure.map(f64::to_bits))
                        .collect::<Vec<_>>()
                })
                .collect::<Vec<_>>()
        })
    };
    let (mut decided, mut crossings) = (0, 0);
    for round in 0..3000 {
        let (n, m) = if round % 2 == 0 {
            (3, 3)
        } else {
            (1 + round % 5, 1 + round / 2 % 5)
        };
        let mut curve =
            |k: usize| -> Vec<[f64; 2]> { (0..=k).map(|_| [r.unit(), r.unit()]).collect() };
        let (p, q) = (curve(n), curve(m));
        let (wide, plain) = (
            certified_crossings_f64(&p, &q),
            certified_crossings_plain(&p, &q),
        );
        assert_eq!(bits(&wide), bits(&plain), "{p:?} {q:?}");
        if let Some(x) = &wide {
            decided += 1;
            crossings += x.len();
        }
    }
    assert!(
        decided > 2900 && crossings > 1500,
        "{decided} decided, {crossings} crossings"
    );
}
