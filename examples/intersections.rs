//! Two Bézier curves intersected, certified: every common point listed once with its exact
//! parameters (correctly rounded doubles at once, the exact algebraic numbers whenever asked),
//! tangencies flagged exactly, common stretches (overlaps) found exactly.
//!
//! `cargo run -p blossom --example intersections`.
//!
//! Each answer is checked against numbers computed by hand in the comments.

use blossom::{
    intersect_curves, intersect_curves_f64, intersect_curves_f64_rounded, AlgebraicReal, Rational,
};
use num_bigint::BigInt;

/// `x` with `digits` decimals, truncated towards -∞ (exact: no double involved).
fn decimals(x: &Rational, digits: u32) -> String {
    let scale = BigInt::from(10).pow(digits);
    let scaled = (x * Rational::from_integer(scale.clone()))
        .floor()
        .to_integer();
    let (whole, frac) = (&scaled / &scale, &scaled % &scale);
    format!(
        "{whole}.{:0>width$}",
        frac.to_string(),
        width = digits as usize
    )
}

pub fn main() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());

    // 1. Two transversal crossings at irrational parameters.
    //
    // P, a cubic with control points (0, 0), (1, 3), (2, -3), (3, 0): its x coordinates are
    // equally spaced, so x(s) = 3s, and y(s) = 9 s (1 - s)^2 - 9 s^2 (1 - s) = 9s - 27s^2 + 18s^3.
    // Q, a quadratic with control points (0, 1), (1.5, -2), (3, 1): x(t) = 3t and
    // y(t) = (1 - t)^2 - 4t(1 - t) + t^2 = 1 - 6t + 6t^2.
    // Equal x gives s = t, and equal y then gives f(s) = 18s^3 - 33s^2 + 15s - 1 = 0, where
    // f(0) = -1, f(1/6) = 2/3, f(1/2) = 1/2, f(2/3) = -1/3, f(1) = -1: one root in (0, 1/6),
    // one in (1/2, 2/3) (the third is above 1). No rational p/q with p | 1, q | 18 is a root
    // (f(1/2), f(1/3) = 1, f(1/6), f(1/9), f(1/18) are not 0; negative s gives f < 0), so f
    // is irreducible and both parameters are irrational roots of f itself.
    let p = [[0.0, 0.0], [1.0, 3.0], [2.0, -3.0], [3.0, 0.0]];
    let qd = [[0.0, 1.0], [1.5, -2.0], [3.0, 1.0]];
    let x = intersect_curves_f64(&p, &qd).unwrap();
    println!("cubic and quadratic:\n{x}");
    assert_eq!(x.points.len(), 2);
    assert!(x.overlaps.is_empty());
    let f: Vec<BigInt> = [-1, 15, -33, 18].map(BigInt::from).to_vec();
    let (one_sixth, half, two_thirds) = (q(1, 6), q(1, 2), q(2, 3));
    for (point, (lo, hi)) in x.points.iter().zip([
        (&Rational::from_integer(0.into()), &one_sixth),
        (&half, &two_thirds),
    ]) {
        // The exact parameters: roots of f, with s = t exactly, in the intervals found above.
        assert_eq!(point.s.polynomial(), f.as_slice());
        assert!(point.s.equals(&point.t));
        assert!(point.s.cmp_rational(lo).is_gt() && point.s.cmp_rational(hi).is_lt());
        assert!(!point.tangent);
        // The point is P(s) = (3s, ...): its x is the correctly rounded 3s.
        assert!((point.point[0] - 3.0 * point.s.to_f64()).abs() <= 4.0 * f64::EPSILON);
    }

    // Exact numbers on demand: an AlgebraicReal is f and an isolating interval; refined, the
    // interval gives as many digits as asked, exactly (here to 10^-50, and the two ends agree
    // on 40 decimals, which are therefore the number's own).
    let mut s = x.points[1].s.clone();
    s.refine_to(&Rational::new(1.into(), BigInt::from(10).pow(50)));
    let (lo, hi) = s.interval();
    let digits = decimals(lo, 40);
    assert_eq!(digits, decimals(hi, 40));
    println!(
        "second crossing: s = t = {digits}... (40 decimals, exact); nearest double {}",
        s.to_f64()
    );

    // The same answer as doubles, proved by the float filter alone (no big numbers): each
    // parameter is the correctly rounded double of the exact one.
    let rounded = intersect_curves_f64_rounded(&p, &qd).unwrap();
    assert!(rounded.by_filter);
    for (r, e) in rounded.points.iter().zip(&x.points) {
        assert_eq!((r.s, r.t), (e.s.to_f64(), e.t.to_f64()));
    }
    println!(
        "as doubles (float filter): s = {:?}",
        rounded.points.iter().map(|r| r.s).collect::<Vec<_>>()
    );

    // 2. A tangency, decided exactly.
    //
    // P: (-1, 1), (0, -1), (1, 1) is the parabola y = x^2 with x = 2s - 1.
    // Q: (0, -1/2), (1, 3/2), (2, -1/2) is y = -(x - 1)^2 + 1/2 with x = 2t.
    // x^2 = -(x - 1)^2 + 1/2 is 2 (x - 1/2)^2 = 0: one double root, x = 1/2, where both
    // slopes are 1: the point (1/2, 1/4) at s = 3/4, t = 1/4, a tangency.
    let parabola = [[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]];
    let cap = [[0.0, -0.5], [1.0, 1.5], [2.0, -0.5]];
    let x = intersect_curves_f64(&parabola, &cap).unwrap();
    println!("tangent parabolas: {x}");
    assert_eq!(x.points.len(), 1);
    let touch = &x.points[0];
    assert_eq!(
        (touch.s.exact(), touch.t.exact()),
        (Some(&q(3, 4)), Some(&q(1, 4)))
    );
    assert!(touch.tangent);
    assert_eq!(touch.point, [0.5, 0.25]);
    // The float filter proves transversal crossings only: here it declines, and the rounded
    // call answers from the exact solver (still certified).
    let rounded = intersect_curves_f64_rounded(&parabola, &cap).unwrap();
    assert!(!rounded.by_filter && rounded.points[0].tangent);

    // 3. An overlap: y = x^2 again, and its piece over x in [0, 2] as its own curve,
    // (0, 0), (1, 0), (2, 4) (x = 2t, y = 4t^2). They share x in [0, 1]: s in [1/2, 1] on the
    // first, t in [0, 1/2] on the second. Found exactly, never by a distance tolerance.
    let wider = [[0.0, 0.0], [1.0, 0.0], [2.0, 4.0]];
    let x = intersect_curves_f64(&parabola, &wider).unwrap();
    println!("overlapping parabolas: {x}");
    assert!(x.points.is_empty());
    assert_eq!(x.overlaps.len(), 1);
    assert_eq!(x.overlaps[0].to_string(), "s = [1/2, 1], t = [0, 1/2]");

    // 4. Exact input: control points that are not doubles (thirds) go through
    // `intersect_curves`. The line from (0, 1/3) to (3, 1/3) meets y = x^2 (x = 2s - 1) where
    // x^2 = 1/3: x = ±1/√3, s = (1 ± 1/√3)/2, roots of 6s^2 - 6s + 1 (s(1 - s) = 1/6);
    // on the line x = 3t, so t = ±1/(3√3), and only the positive one lies in [0, 1].
    let exact_parabola = parabola.map(|p| p.map(|c| Rational::from_float(c).unwrap()));
    let line = [[q(0, 1), q(1, 3)], [q(3, 1), q(1, 3)]];
    let x = intersect_curves(&exact_parabola, &line).unwrap();
    println!("parabola and a line at height 1/3: {x}");
    assert_eq!(x.points.len(), 1);
    let s = &x.points[0].s;
    assert_eq!(s.polynomial(), [1, -6, 6].map(BigInt::from).as_slice());
    // s = (1 + 1/√3)/2 > 1/2: compared exactly, and to 1/√3 through x = 2s - 1.
    assert!(s.cmp_rational(&half).is_gt());
    let root_third = 1.0 / 3f64.sqrt();
    assert!((s.to_f64() - (1.0 + root_third) / 2.0).abs() < 1e-15);
    let t: &AlgebraicReal = &x.points[0].t;
    assert!((t.to_f64() - root_third / 3.0).abs() < 1e-15);
}
