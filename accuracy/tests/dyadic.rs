//! The gcd-free exact dyadic numbers of the harness: exact arithmetic, and the engine in
//! dyadics equal to the engine in rationals (the lib itself is not compiled in test mode:
//! `test = false` in Cargo.toml, since its unit-test build cost as much as the whole library).

use blossom::{Rational, Ring};
use blossom_accuracy::dyadic::Dyadic;

#[test]
fn dyadic_arithmetic_is_exact() {
    let d = |x: f64| Dyadic::from_f64(x).expect("finite");
    let (x, y) = (d(0.1), d(-3.75e-300));
    let q = |x: f64| Rational::from_float(x).expect("finite");
    assert_eq!(x.add(&y).to_rational(), q(0.1) + q(-3.75e-300));
    assert_eq!(x.sub(&y).to_rational(), q(0.1) - q(-3.75e-300));
    assert_eq!(x.mul(&y).to_rational(), q(0.1) * q(-3.75e-300));
    assert_eq!(d(5e-324).to_rational(), q(5e-324));
    assert_eq!(d(0.5).scale_frac(3, 8).to_rational(), q(0.1875));
    assert_eq!(d(0.5), d(1.0).mul(&d(0.5)));
    assert!(d(0.0).is_zero() && d(-2.0).is_negative());
    assert!(Dyadic::from_f64(f64::NAN).is_none());
}

#[test]
fn the_engine_in_dyadics_equals_the_engine_in_rationals() {
    let ctrl: Vec<[f64; 2]> = (0..20)
        .map(|i| [0.1 * i as f64, 1.0 / (i + 1) as f64])
        .collect();
    let (a, b) = (-2.7, 0.3);
    let dy = blossom::Bezier::new(
        ctrl.iter()
            .map(|p| p.map(|x| Dyadic::from_f64(x).unwrap()))
            .collect(),
    )
    .unwrap()
    .subsegment(Dyadic::from_f64(a).unwrap()..Dyadic::from_f64(b).unwrap());
    let q = |x: f64| Rational::from_float(x).unwrap();
    let ra = blossom::Bezier::new(ctrl.iter().map(|p| p.map(q)).collect())
        .unwrap()
        .subsegment(q(a)..q(b));
    for (d, r) in dy.points().iter().zip(ra.points()) {
        assert_eq!(d.each_ref().map(Dyadic::to_rational), *r);
    }
}
