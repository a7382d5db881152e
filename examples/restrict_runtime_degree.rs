//! Restrict a curve whose degree is known only at run time, in f64 and exactly.
//!
//! `cargo run -p blossom --example restrict_runtime_degree [DEGREE]` (default 7).
//!
//! The curve is C(u) = sum_i c_i u^i with c_i = (1, (-1)^i / (i + 1)), of the degree read from
//! the command line. Restricted to [a, b] it is the Bézier curve of control points
//! w_v = blossom(a^(n-v), b^v) (Theorem 1 of the subdivision paper): the same polynomial,
//! reparametrised so that t in [0, 1] runs over u = a + t (b - a).

use blossom::{rational_to_f64, restrict_power_curve, Method, PowerCurve, Rational, Ring};

/// The curve of degree `n` in any number type.
fn curve<T: Ring>(n: usize) -> PowerCurve<T> {
    let sign = |i: usize| if i.is_multiple_of(2) { 1 } else { -1 };
    let c = (0..=n)
        .map(|i| {
            let y = Rational::new(sign(i).into(), (i as i64 + 1).into());
            vec![T::one(), T::from_rational(&y)]
        })
        .collect();
    PowerCurve::new(c).expect("n + 1 points of dimension 2")
}

/// Restricts the curve of degree `degree` to [1/4, 3/4] and checks the answer.
pub fn run(degree: usize) {
    // Exactly: every method gives the identical answer.
    let (a, b) = (
        Rational::new(1.into(), 4.into()),
        Rational::new(3.into(), 4.into()),
    );
    let exact = restrict_power_curve(&curve::<Rational>(degree), &a, &b, Method::Bulk);
    for method in Method::ALL {
        assert_eq!(restrict_power_curve(&curve(degree), &a, &b, method), exact);
    }
    // The restriction is the same polynomial: at t it equals C(a + t (b - a)).
    let c = curve::<Rational>(degree);
    for k in 0..=4 {
        let t = Rational::new(k.into(), 4.into());
        let u = &a + &t * (&b - &a);
        assert_eq!(exact.eval(&t), c.eval(&u));
    }

    // In f64 (the default method, the halving engine): close to the exact answer.
    let float = restrict_power_curve(&curve::<f64>(degree), &0.25, &0.75, Method::Bulk);
    for (p, q) in float.control_points().iter().zip(exact.control_points()) {
        for (x, y) in p.iter().zip(q) {
            let y = rational_to_f64(y);
            assert!((x - y).abs() <= 1e-13 * (1.0 + y.abs()), "{x} vs {y}");
        }
    }
    println!(
        "degree {degree} on [1/4, 3/4]: w_0 = ({}, {}), w_{degree} = ({}, {})",
        exact.control_points()[0][0],
        exact.control_points()[0][1],
        exact.control_points()[degree][0],
        exact.control_points()[degree][1]
    );
}

pub fn main() {
    let degree = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("DEGREE: a non-negative integer"))
        .unwrap_or(7);
    run(degree);
}
