//! Tests of the certified zeros and intersections.

use super::*;
use crate::num::ring::Rational;
use num_bigint::BigInt;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

#[test]
fn placeholder_compiles() {
    let z = zeros::bezier_zeros(&[q(-1, 1), q(1, 1)]).unwrap();
    assert_eq!(z.zeros.len(), 1);
    assert_eq!(z.zeros[0].t.exact(), Some(&q(1, 2)));
}
