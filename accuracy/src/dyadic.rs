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
    type Coords = Vec<Self>;
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
