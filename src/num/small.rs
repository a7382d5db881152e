//! Fixed-width exact rationals: the stage before big integers.
//!
//! The contacts of font outlines (integer or dyadic coordinates of a few thousand units) are
//! rationals whose numerators and denominators fit in 64 bits: the parameter where two
//! segments meet is a quotient of two cross products of coordinate differences. A
//! [`SmallRational`] holds such a number as `num / den` in lowest terms with `den > 0`, both
//! in `i64`; every operation widens to `i128` (a product of two `i64` fits), reduces, and
//! answers `None` when the result no longer fits, so that the caller falls back to big
//! rationals. Comparisons never fail: a / b < c / d exactly when a d < c b (b, d > 0), a
//! product of two `i64` in `i128`.

use crate::num::ring::{rational_to_f64, Rational};
use num_bigint::BigInt;
use std::cmp::Ordering;

/// An exact rational `num / den`, `den > 0`, in lowest terms, both fitting in `i64`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SmallRational {
    num: i64,
    den: i64,
}

/// The greatest common divisor of a and b (binary; both non-zero).
fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

/// The greatest common divisor of a and b (Euclid, on `u128`, down to `u64` as soon as both
/// fit; both non-zero).
fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while a > u128::from(u64::MAX) || b > u128::from(u64::MAX) {
        (a, b) = (b, a % b);
        if b == 0 {
            return a;
        }
    }
    u128::from(gcd_u64(a as u64, b as u64))
}

/// 2^53: integers up to this magnitude are doubles exactly.
const EXACT_DOUBLE_INTEGERS: i64 = 1 << 53;

impl SmallRational {
    /// 0.
    pub const ZERO: SmallRational = SmallRational { num: 0, den: 1 };
    /// 1.
    pub const ONE: SmallRational = SmallRational { num: 1, den: 1 };

    /// `num / den` in lowest terms; `None` when `den` is zero or the reduced terms do not fit
    /// in `i64`.
    pub fn new(num: i128, den: i128) -> Option<SmallRational> {
        if den == 0 {
            return None;
        }
        if num == 0 {
            return Some(SmallRational::ZERO);
        }
        let negative = (num < 0) != (den < 0);
        let (n, d) = (num.unsigned_abs(), den.unsigned_abs());
        // Terms within 64 bits (the common case) divide in 64-bit instructions.
        let (n, d) = match (u64::try_from(n), u64::try_from(d)) {
            (Ok(n), Ok(d)) => {
                let g = gcd_u64(n, d);
                (u128::from(n / g), u128::from(d / g))
            }
            _ => {
                let g = gcd_u128(n, d);
                (n / g, d / g)
            }
        };
        let (n, d) = (i64::try_from(n).ok()?, i64::try_from(d).ok()?);
        Some(SmallRational {
            num: if negative { -n } else { n },
            den: d,
        })
    }

    /// The integer `n`.
    pub fn integer(n: i64) -> SmallRational {
        SmallRational { num: n, den: 1 }
    }

    /// The numerator (the sign of the number).
    pub fn numer(self) -> i64 {
        self.num
    }

    /// The denominator (positive).
    pub fn denom(self) -> i64 {
        self.den
    }

    /// `self + other`, `None` if it does not fit.
    pub fn add(self, other: SmallRational) -> Option<SmallRational> {
        let (a, b, c, d) = self.wide(other);
        SmallRational::new(a.checked_mul(d)?.checked_add(c.checked_mul(b)?)?, b * d)
    }

    /// `self - other`, `None` if it does not fit.
    pub fn sub(self, other: SmallRational) -> Option<SmallRational> {
        self.add(SmallRational {
            num: other.num.checked_neg()?,
            den: other.den,
        })
    }

    /// `self * other`, `None` if it does not fit.
    pub fn mul(self, other: SmallRational) -> Option<SmallRational> {
        let (a, b, c, d) = self.wide(other);
        SmallRational::new(a * c, b * d)
    }

    /// `self / other`, `None` if `other` is zero or the quotient does not fit.
    pub fn div(self, other: SmallRational) -> Option<SmallRational> {
        let (a, b, c, d) = self.wide(other);
        SmallRational::new(a * d, b * c)
    }

    fn wide(self, other: SmallRational) -> (i128, i128, i128, i128) {
        (
            i128::from(self.num),
            i128::from(self.den),
            i128::from(other.num),
            i128::from(other.den),
        )
    }

    /// The big rational of the same value.
    pub fn to_rational(self) -> Rational {
        Rational::new_raw(BigInt::from(self.num), BigInt::from(self.den))
    }

    /// The double nearest to the number (ties to even) and doubles `[lo, hi]` around it: the
    /// double itself when the number is one, else its two neighbours (the number lies strictly
    /// between them, within half an ulp of the nearest).
    ///
    /// When both terms are at most 2^53 in magnitude they are doubles exactly and one IEEE
    /// division rounds the quotient correctly; the number is a double exactly when its
    /// denominator is a power of two (then `num` fits the 53-bit significand). Larger terms
    /// round through the big rational.
    pub fn to_f64_enclosure(self) -> (f64, [f64; 2]) {
        let small = self.num.unsigned_abs() <= EXACT_DOUBLE_INTEGERS as u64
            && self.den <= EXACT_DOUBLE_INTEGERS;
        let nearest = if small {
            self.num as f64 / self.den as f64
        } else {
            rational_to_f64(&self.to_rational())
        };
        let exact = small && self.den.count_ones() == 1;
        if exact {
            (nearest, [nearest, nearest])
        } else {
            (nearest, [nearest.next_down(), nearest.next_up()])
        }
    }
}

impl Ord for SmallRational {
    fn cmp(&self, other: &SmallRational) -> Ordering {
        let (a, b, c, d) = self.wide(*other);
        (a * d).cmp(&(c * b))
    }
}

impl PartialOrd for SmallRational {
    fn partial_cmp(&self, other: &SmallRational) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The control points of a curve of degree at most 3 as integers on their own dyadic scale:
/// each coordinate is `m 2^exponent` exactly, with `exponent` the least exponent of the
/// lowest set bits of the non-zero coordinates (each double is an odd integer times a power
/// of two), or 0 when that is larger (integers stay as they are, so that the curves of an
/// outline in integer units share one scale). Two curves go to one common scale, the lesser
/// exponent ([`common_scale`]); ratios of differences (the parameters of contacts) do not
/// change under a common scale. Made once per curve, so that a pair costs only a comparison
/// (and shifts when the scales differ).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Dyadic {
    m: [[i64; 2]; 4],
    len: usize,
    /// At most 0.
    exponent: i32,
    /// The largest |m|.
    largest: u64,
}

/// Up to four points with integer coordinates (unused entries zero).
pub(crate) type IntegerPoints = [[i64; 2]; 4];

/// The integers of a [`Dyadic`] stay below 2^62 in magnitude.
const DYADIC_LIMIT: f64 = (1u64 << 62) as f64;

impl Dyadic {
    /// The points (at most four, finite) on their own scale; `None` for more points, a
    /// coordinate not finite, or an integer of 2^62 or more (coordinates of far-apart
    /// binades).
    pub(crate) fn of(points: &[[f64; 2]]) -> Option<Dyadic> {
        if points.len() > 4 {
            return None;
        }
        // Integers (the common case of font units) are their own integers.
        let integer = |x: f64| x.abs() < DYADIC_LIMIT && x == (x as i64) as f64;
        if points.iter().all(|p| integer(p[0]) && integer(p[1])) {
            let (mut m, mut largest) = ([[0i64; 2]; 4], 0u64);
            for (o, p) in m.iter_mut().zip(points) {
                *o = p.map(|x| x as i64);
                largest = largest.max(o[0].unsigned_abs()).max(o[1].unsigned_abs());
            }
            return Some(Dyadic {
                m,
                len: points.len(),
                exponent: 0,
                largest,
            });
        }
        let mut least = 0i32;
        for p in points {
            for &x in p {
                if !x.is_finite() {
                    return None;
                }
                if x != 0.0 {
                    least = least.min(lowest_bit_exponent(x));
                }
            }
        }
        let (mut m, mut largest) = ([[0i64; 2]; 4], 0u64);
        for (o, p) in m.iter_mut().zip(points) {
            for k in 0..2 {
                let y = scale_by_power_of_two(p[k], -least);
                if y.abs() >= DYADIC_LIMIT {
                    return None;
                }
                o[k] = y as i64;
                largest = largest.max(o[k].unsigned_abs());
            }
        }
        Some(Dyadic {
            m,
            len: points.len(),
            exponent: least,
            largest,
        })
    }

    /// The number of points.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The points as integers on their own scale.
    pub(crate) fn points(&self) -> &[[i64; 2]] {
        &self.m[..self.len]
    }

    /// The points on the scale 2^`exponent` (at most this one's): each integer times
    /// 2^(own exponent - `exponent`), exactly; `None` when one reaches `limit` (a power of
    /// two) in magnitude. Unused entries are zero.
    #[inline]
    fn at(&self, exponent: i32, limit: i64) -> Option<IntegerPoints> {
        let shift = i64::from(self.exponent) - i64::from(exponent);
        // |m| 2^shift < limit, that is |m| < limit / 2^shift (exact: limit is a power of two).
        let bound = if shift >= 63 { 0 } else { limit >> shift };
        if self.largest >= bound.unsigned_abs() && self.largest != 0 {
            return None;
        }
        if shift == 0 {
            return Some(self.m);
        }
        Some(self.m.map(|p| p.map(|x| x << shift)))
    }
}

/// The points of `a` and `b` on their common scale (the lesser exponent), each coordinate
/// below `limit` (a power of two) in magnitude, else `None`.
pub(crate) fn common_scale(a: &Dyadic, b: &Dyadic, limit: i64) -> Option<[IntegerPoints; 2]> {
    let exponent = a.exponent.min(b.exponent);
    Some([a.at(exponent, limit)?, b.at(exponent, limit)?])
}

/// [`common_scale`] of two curves given by their control points (at most four each).
#[cfg(test)]
pub(crate) fn on_common_scale(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
    limit: i64,
) -> Option<[IntegerPoints; 2]> {
    common_scale(&Dyadic::of(p)?, &Dyadic::of(q)?, limit)
}

/// The exponent e of the lowest set bit of the finite non-zero double x = m 2^e (m odd).
fn lowest_bit_exponent(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    let (significand, exponent) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    exponent + significand.trailing_zeros() as i32
}

/// x 2^k, exact when the result is an integer below 2^63 (the caller's case): a product by a
/// power of two only moves the exponent, done in at most three exact steps.
fn scale_by_power_of_two(x: f64, k: i32) -> f64 {
    let mut y = x;
    let mut k = k;
    while k != 0 {
        let step = k.clamp(-1000, 1000);
        y *= 2f64.powi(step);
        k -= step;
    }
    y
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::ring::Rational;
    use crate::test_rng::XorShift;

    /// Every operation against big rationals on random small terms, overflow included.
    #[test]
    fn operations_agree_with_big_rationals() {
        let mut rng = XorShift(0x5e11);
        let mut term = |bits: u32| {
            let x = (rng.next() >> (64 - bits)) as i64;
            if rng.next().is_multiple_of(2) {
                -x
            } else {
                x
            }
        };
        let mut fitted = 0;
        for i in 0..4000 {
            let bits = [8, 20, 31, 40, 62][i % 5];
            let (a, b) = (
                SmallRational::new(term(bits).into(), term(bits).into()),
                SmallRational::new(term(bits).into(), term(bits).into()),
            );
            let (Some(a), Some(b)) = (a, b) else { continue };
            let (ra, rb) = (a.to_rational(), b.to_rational());
            assert_eq!(a.cmp(&b), ra.cmp(&rb));
            let results = [
                (a.add(b), &ra + &rb),
                (a.sub(b), &ra - &rb),
                (a.mul(b), &ra * &rb),
            ];
            for (small, big) in results {
                if let Some(s) = small {
                    assert_eq!(s.to_rational(), big);
                    fitted += 1;
                }
            }
            if rb != Rational::from_integer(0.into()) {
                if let Some(s) = a.div(b) {
                    assert_eq!(s.to_rational(), ra / rb);
                }
            }
            let (nearest, [lo, hi]) = a.to_f64_enclosure();
            assert_eq!(nearest, rational_to_f64(&a.to_rational()));
            let exact = |x: f64| Rational::from_float(x).unwrap();
            assert!(exact(lo) <= a.to_rational() && a.to_rational() <= exact(hi));
            assert_eq!(lo == hi, exact(nearest) == a.to_rational());
        }
        assert!(fitted > 3000, "most small operations fit: {fitted}");
    }

    #[test]
    fn coordinates_on_a_common_scale() {
        let (a, b) = ([[0.5, 3.0]], [[-1.25, 1024.0]]);
        assert_eq!(
            on_common_scale(&a, &b, 1 << 20),
            Some([
                [[2, 12], [0; 2], [0; 2], [0; 2]],
                [[-5, 4096], [0; 2], [0; 2], [0; 2]]
            ])
        );
        assert_eq!(on_common_scale(&a, &b, 4096), None);
        assert_eq!(on_common_scale(&b, &a, 4096), None);
        // 0.1 is an odd multiple of 2^-55 (about 2^51.7 of them).
        let tenth = [[0.1, 0.0]];
        assert_eq!(on_common_scale(&tenth, &[[0.0, 0.0]], 1 << 40), None);
        assert!(on_common_scale(&tenth, &[[0.0, 0.0]], 1 << 62).is_some());
        // 0.1 with 1: 1 goes to 2^55 on the common scale.
        let one = [[1.0, 0.0]];
        assert_eq!(
            on_common_scale(&tenth, &one, 1 << 62).unwrap()[1][0],
            [1 << 55, 0]
        );
        assert_eq!(on_common_scale(&tenth, &one, 1 << 55), None);
        let tiny = f64::MIN_POSITIVE;
        assert_eq!(
            on_common_scale(&[[tiny, 3.0 * tiny]], &[[0.0, -tiny]], 1 << 62),
            Some([
                [[1, 3], [0; 2], [0; 2], [0; 2]],
                [[0, -1], [0; 2], [0; 2], [0; 2]]
            ])
        );
        assert_eq!(Dyadic::of(&[[f64::NAN, 0.0]]), None);
        assert_eq!(Dyadic::of(&[[0.0, 0.0]; 5]), None);
        // Far-apart binades on one curve do not fit.
        assert_eq!(Dyadic::of(&[[1e-30, 1e30]]), None);
    }
}
