//! Exact dyadic numbers m 2^e: the exact arithmetic of the accuracy sweep for Bézier input.
//!
//! Every finite double is dyadic, and de Casteljau's steps only add, subtract and multiply, so
//! the exact answer is dyadic too. Unlike [`Rational`], nothing is ever reduced by a gcd: at
//! degree 64 that makes the exact answer some hundred times cheaper. (Equality compares
//! values, so differently shifted mantissas of one value are equal.)

use blossom::{Rational, Ring};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The number `mantissa * 2^exponent`.
#[derive(Clone, Debug)]
pub struct Dyadic {
    mantissa: BigInt,
    exponent: i64,
}

impl Dyadic {
    /// The exact value of a finite double.
    pub fn from_f64(x: f64) -> Option<Self> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Dyadic::zero());
        }
        let bits = x.to_bits();
        let sign = if bits >> 63 == 1 { -1 } else { 1 };
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        Some(Dyadic {
            mantissa: BigInt::from(sign) * BigInt::from(m),
            exponent: e,
        })
    }

    /// The value as an exact rational.
    pub fn to_rational(&self) -> Rational {
        if self.exponent >= 0 {
            Rational::from_integer(&self.mantissa << self.exponent as usize)
        } else {
            Rational::new(
                self.mantissa.clone(),
                BigInt::one() << (-self.exponent) as usize,
            )
        }
    }

    /// Both mantissas at the smaller exponent.
    fn aligned(&self, rhs: &Self) -> (BigInt, BigInt, i64) {
        let e = self.exponent.min(rhs.exponent);
        (
            &self.mantissa << (self.exponent - e) as usize,
            &rhs.mantissa << (rhs.exponent - e) as usize,
            e,
        )
    }
}

impl PartialEq for Dyadic {
    fn eq(&self, rhs: &Self) -> bool {
        let (a, b, _) = self.aligned(rhs);
        a == b
    }
}

impl Ring for Dyadic {
    fn zero() -> Self {
        Dyadic {
            mantissa: BigInt::zero(),
            exponent: 0,
        }
    }
    fn one() -> Self {
        Dyadic {
            mantissa: BigInt::one(),
            exponent: 0,
        }
    }
    fn add(&self, rhs: &Self) -> Self {
        let (a, b, exponent) = self.aligned(rhs);
        Dyadic {
            mantissa: a + b,
            exponent,
        }
    }
    fn sub(&self, rhs: &Self) -> Self {
        let (a, b, exponent) = self.aligned(rhs);
        Dyadic {
            mantissa: a - b,
            exponent,
        }
    }
    fn mul(&self, rhs: &Self) -> Self {
        Dyadic {
            mantissa: &self.mantissa * &rhs.mantissa,
            exponent: self.exponent + rhs.exponent,
        }
    }
    fn neg(&self) -> Self {
        Dyadic {
            mantissa: -&self.mantissa,
            exponent: self.exponent,
        }
    }
    /// Exact when the denominator of `k` is a power of two, which is all this type is used
    /// for (the Bernstein steps use no constant); otherwise the quotient is truncated after
    /// 4096 more bits.
    fn scale(&self, k: &Rational) -> Self {
        let (num, den) = (k.numer(), k.denom());
        let twos = den.trailing_zeros().unwrap_or(0);
        let odd = den >> twos as usize;
        let (mantissa, extra) = if odd.is_one() {
            (&self.mantissa * num, 0)
        } else {
            (((&self.mantissa * num) << 4096usize).div_floor(&odd), 4096)
        };
        Dyadic {
            mantissa,
            exponent: self.exponent - twos as i64 - extra,
        }
    }
    fn is_zero(&self) -> bool {
        self.mantissa.is_zero()
    }
}

impl Dyadic {
    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        self.mantissa.is_negative()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
