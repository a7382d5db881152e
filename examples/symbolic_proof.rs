//! A symbolic proof of one's own formula with `Poly`: polynomials with rational coefficients
//! in named variables, a `Ring` like the numbers, so that every algorithm of the library runs
//! on them and its answer is the formula itself.
//!
//! `cargo run -p blossom --example symbolic_proof`.
//!
//! Claim: for the cubic C(u) = c0 + c1 u + c2 u^2 + c3 u^3 on [a, b], the control point
//! w_1 = blossom(a, a, b) is
//!
//!   w_1 = c0 + c1 (2a + b) / 3 + c2 (a^2 + 2ab) / 3 + c3 a^2 b,
//!
//! (the blossom of u^k is the k-th elementary symmetric function of its arguments divided by
//! C(3, k)). The library computes w_1 with every method on symbolic coefficients and end
//! points; equality of the polynomials proves the formula for all numbers at once.

use blossom::{restrict_power_curve, BezierCurve, Method, Poly, PowerCurve, Rational};

pub fn main() {
    let v = Poly::var;
    let k = |n: i64, d: i64| Poly::constant(Rational::new(n.into(), d.into()));
    let (a, b) = (v("a"), v("b"));

    let cubic = PowerCurve::new((0..4).map(|i| vec![v(&format!("c{i}"))]).collect()).unwrap();
    let claim = v("c0")
        + v("c1") * (k(2, 1) * a.clone() + b.clone()) * k(1, 3)
        + v("c2") * (a.clone() * a.clone() + k(2, 1) * a.clone() * b.clone()) * k(1, 3)
        + v("c3") * a.clone() * a.clone() * b.clone();
    for method in Method::ALL {
        let w = restrict_power_curve(&cubic, &a, &b, method);
        assert_eq!(w.control_points()[1][0], claim, "{}", method.name());
    }
    println!("proved: w_1 = {claim}");

    // A wrong formula (the 2 in the c1 term dropped) is refused, with the difference shown.
    let wrong = claim.clone() - v("c1") * a.clone() * k(1, 3);
    let w = restrict_power_curve(&cubic, &a, &b, Method::Bulk).control_points()[1][0].clone();
    assert_ne!(w, wrong);
    println!(
        "refuted: the library's w_1 minus the wrong formula is {}",
        w - wrong
    );

    // Bézier input: the middle control point of a quadratic p0, p1, p2 on [a, b] is
    // (1-a)(1-b) p0 + (a(1-b) + b(1-a)) p1 + a b p2 (the blossom b[a, b]).
    let quad = BezierCurve::new((0..3).map(|i| vec![v(&format!("p{i}"))]).collect()).unwrap();
    let one = k(1, 1);
    let middle = (one.clone() - a.clone()) * (one.clone() - b.clone()) * v("p0")
        + (a.clone() * (one.clone() - b.clone()) + b.clone() * (one - a.clone())) * v("p1")
        + a.clone() * b.clone() * v("p2");
    assert_eq!(
        quad.subsegment(a.clone()..b.clone()).control_points()[1][0],
        middle
    );
    println!("proved: the middle point on [a, b] is {middle}");
}
