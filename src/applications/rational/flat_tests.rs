//! The flat storage of the rational shapes against nested points and textbook algorithms.

use super::*;
use crate::Rational;
use num_bigint::BigInt;

fn q(n: i64) -> Rational {
    Rational::from_integer(BigInt::from(n))
}

#[test]
fn zero_weights_and_low_degrees_are_errors() {
    // 1 / t on [0, 1]: w_0 = w(0) = 0.
    let c = RationalCurve::new(&[vec![q(1)]], &[q(0), q(1)]).unwrap();
    let e = c.bezier(&q(0), &q(1), None).unwrap_err();
    assert_eq!(e.field, "denominator");
    assert!(e.message.starts_with("weight w_0 is zero"), "{e}");
    assert_eq!(c.bezier(&q(1), &q(2), Some(0)).unwrap_err().field, "degree");
    assert_eq!(
        RationalCurve::new(&[vec![q(1)]], &[q(0)])
            .unwrap_err()
            .field,
        "denominator"
    );
    assert_eq!(
        RationalCurve::<Rational>::new(&[], &[q(1)])
            .unwrap_err()
            .field,
        "numerator"
    );
    let e = RationalBSpline::new(
        1,
        vec![q(0), q(0), q(1), q(1)],
        vec![vec![q(0)], vec![q(1)]],
        vec![q(1), q(0)],
    );
    assert_eq!(e.unwrap_err().field, "weights[1]");
}
