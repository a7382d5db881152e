//! Arithmetic modulo word-size primes, interpolation modulo a prime, and the reconstruction
//! of integers from their residues (Chinese remainder theorem, symmetric residues).
//!
//! **The primes** are the primes p with 2^61 < p < 2^62, taken downwards from 2^62 and proven
//! prime by the Miller–Rabin test with the twelve bases 2, 3, ..., 37, which is deterministic
//! below 3.3 * 10^24 (Sorenson and Webster, 2015). Residues are `u64`, products `u128`, and
//! products are reduced by **Montgomery's method** with R = 2^64: for t < p^2,
//! REDC(t) = (t + m p) / R with m = t (-p^-1) mod R is t R^-1 modulo p and lies in [0, 2p).
//! Residues are held in Montgomery form a R mod p, so a product costs two or three machine
//! multiplications and no division. Why 62 bits and not 31: one prime then carries twice the
//! bits, so a multi-modular computation needs half the primes and therefore half the
//! evaluations, for about the same cost per multiplication; below 2^62 a sum of two residues
//! never overflows and t + m p < 2^124 + 2^126 fits in a `u128`.
//!
//! **Reconstruction.** An integer x with |x| <= B is determined by its residues modulo primes
//! whose product M exceeds 2B: Garner's mixed-radix form x = v_0 + v_1 p_0 + v_2 p_0 p_1 + ...
//! (0 <= v_k < p_k, each v_k from one residue and the previous digits) gives the residue of
//! x in [0, M), and the symmetric residue (the representative in (-M/2, M/2]) is x itself.
//! Callers choose the number of primes from a proven bound ([`primes_for_bits`]), never by
//! waiting for the reconstruction to stabilise.

use num_bigint::{BigInt, BigUint, Sign};
use std::sync::Mutex;

/// The bits every prime carries at least: each prime exceeds 2^61.
pub const PRIME_BITS: u64 = 61;

/// Arithmetic modulo one odd prime 2^61 < p < 2^62 in Montgomery form: residues a R mod p
/// with R = 2^64, products reduced by REDC(t) = (t + m p) / R, m = t (-p^-1) mod R, with no
/// division; sums of two residues never overflow a `u64`.
#[derive(Clone, Copy, Debug)]
pub struct Field {
    p: u64,
    /// -p^-1 mod 2^64.
    neg_inv: u64,
    /// R^2 mod p (R = 2^64), which turns a residue into Montgomery form.
    r2: u64,
    /// R mod p: the Montgomery form of 1.
    one: u64,
}

impl Field {
    /// The field of the odd prime `p < 2^62`.
    pub fn new(p: u64) -> Self {
        debug_assert!(p % 2 == 1 && p < 1 << 62);
        // Newton's iteration x <- x (2 - p x) doubles the correct low bits of p^-1 mod 2^64;
        // x = p is right to 3 bits (p^2 = 1 mod 8 for odd p), so five steps reach 96 bits.
        let mut inv = p;
        for _ in 0..5 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % p as u128) as u64;
        let r2 = ((r as u128 * r as u128) % p as u128) as u64;
        Field {
            p,
            neg_inv: inv.wrapping_neg(),
            r2,
            one: r,
        }
    }

    /// The prime.
    pub fn prime(self) -> u64 {
        self.p
    }

    /// The Montgomery form of 1.
    #[inline]
    pub fn one(self) -> u64 {
        self.one
    }

    /// REDC: t R^-1 mod p for t < p R.
    #[inline]
    fn redc(self, t: u128) -> u64 {
        let m = (t as u64).wrapping_mul(self.neg_inv);
        let u = ((t + m as u128 * self.p as u128) >> 64) as u64;
        if u >= self.p {
            u - self.p
        } else {
            u
        }
    }

    /// The product (Montgomery forms in, Montgomery form out).
    #[inline]
    pub fn mul(self, a: u64, b: u64) -> u64 {
        self.redc(a as u128 * b as u128)
    }

    /// The sum.
    #[inline]
    pub fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p {
            s - self.p
        } else {
            s
        }
    }

    /// The difference.
    #[inline]
    pub fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + self.p - b
        }
    }

    /// The negative.
    #[inline]
    pub fn neg(self, a: u64) -> u64 {
        if a == 0 {
            0
        } else {
            self.p - a
        }
    }

    /// The Montgomery form of the integer x (any u64).
    #[inline]
    pub fn of_u64(self, x: u64) -> u64 {
        self.mul(x % self.p, self.r2)
    }

    /// The residue in [0, p) of a Montgomery form.
    #[inline]
    pub fn to_u64(self, a: u64) -> u64 {
        self.redc(a as u128)
    }

    /// The Montgomery form of an integer of any size: Horner over its 64-bit digits, the
    /// product by 2^64 being the Montgomery product by R^2 (a R * R^2 / R = (a 2^64) R).
    pub fn of_bigint(self, x: &BigInt) -> u64 {
        let mut acc = 0;
        for d in x.magnitude().iter_u64_digits().rev() {
            acc = self.add(self.mul(acc, self.r2), self.of_u64(d));
        }
        if x.sign() == Sign::Minus {
            self.neg(acc)
        } else {
            acc
        }
    }

    /// a^e.
    pub fn pow(self, mut a: u64, mut e: u64) -> u64 {
        let mut acc = self.one;
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        acc
    }

    /// a^-1 for a non-zero a (Fermat: a^(p - 2)).
    pub fn inv(self, a: u64) -> u64 {
        debug_assert!(a != 0);
        self.pow(a, self.p - 2)
    }

    /// The inverses of non-zero elements with one inversion (Montgomery's trick: prefix
    /// products, one inverse of the total, then the prefixes peeled off backwards).
    pub fn inv_all(self, xs: &mut [u64]) {
        let mut prefix = Vec::with_capacity(xs.len());
        let mut acc = self.one;
        for &x in xs.iter() {
            prefix.push(acc);
            acc = self.mul(acc, x);
        }
        let mut inv = self.inv(acc);
        for (x, pre) in xs.iter_mut().zip(prefix).rev() {
            let xi = self.mul(inv, pre);
            inv = self.mul(inv, *x);
            *x = xi;
        }
    }

    /// The polynomial (ascending coefficients) of degree < values.len() taking values[k] at
    /// x = k, k = 0, 1, ... (values.len() <= p). Newton's forward differences
    /// c_k = Delta^k y_0 / k! give p(x) = sum c_k x (x - 1) ... (x - k + 1), expanded by the
    /// nested form p = c_0 + x (c_1 + (x - 1) (c_2 + ...)): O(n^2) operations.
    pub fn interpolate_consecutive(self, values: &[u64]) -> Vec<u64> {
        let n = values.len();
        if n == 0 {
            return Vec::new();
        }
        let mut d = values.to_vec();
        for k in 1..n {
            for i in (k..n).rev() {
                d[i] = self.sub(d[i], d[i - 1]);
            }
        }
        // 1 / k! for k < n: one inversion of (n - 1)!, then downwards.
        let mut fact = self.one;
        for k in 1..n {
            fact = self.mul(fact, self.of_u64(k as u64));
        }
        let mut inv_fact = self.inv(fact);
        for k in (1..n).rev() {
            d[k] = self.mul(d[k], inv_fact);
            inv_fact = self.mul(inv_fact, self.of_u64(k as u64));
        }
        // p <- p (x - k) + c_k from k = n - 2 down to 0.
        let mut p = Vec::with_capacity(n);
        p.push(d[n - 1]);
        for k in (0..n - 1).rev() {
            let mk = self.neg(self.of_u64(k as u64));
            p.push(0);
            for i in (1..p.len()).rev() {
                p[i] = self.add(p[i - 1], self.mul(p[i], mk));
            }
            p[0] = self.add(self.mul(p[0], mk), d[k]);
        }
        p
    }
}

/// The primes found so far (decreasing from 2^62), shared by all computations.
static PRIMES: Mutex<Vec<u64>> = Mutex::new(Vec::new());

/// The first `k` primes below 2^62 (all above 2^61).
pub fn primes(k: usize) -> Vec<u64> {
    let mut list = PRIMES.lock().unwrap_or_else(|e| e.into_inner());
    let mut candidate = list.last().map_or((1u64 << 62) - 1, |&p| p - 2);
    while list.len() < k {
        if is_prime(candidate) {
            list.push(candidate);
        }
        candidate -= 2;
        assert!(candidate > 1 << 61, "more than 10^16 primes requested");
    }
    list[..k].to_vec()
}

/// The number of primes (each above 2^61) whose product exceeds 2^(bits + 1), enough to
/// recover integers of absolute value below 2^bits as symmetric residues.
pub fn primes_for_bits(bits: u64) -> usize {
    (bits + 1).div_ceil(PRIME_BITS).max(1) as usize
}

/// Deterministic Miller–Rabin for odd n < 2^64: the twelve bases 2, 3, ..., 37 decide
/// primality below 3.3 * 10^24 (Sorenson and Webster, 2015).
fn is_prime(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for &b in &BASES {
        if n.is_multiple_of(b) {
            return n == b;
        }
    }
    let mulmod = |a: u64, b: u64| ((a as u128 * b as u128) % n as u128) as u64;
    let powmod = |mut a: u64, mut e: u64| {
        let mut acc = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                acc = mulmod(acc, a);
            }
            a = mulmod(a, a);
            e >>= 1;
        }
        acc
    };
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    BASES.iter().all(|&a| {
        let mut x = powmod(a, d);
        if x == 1 || x == n - 1 {
            return true;
        }
        for _ in 1..s {
            x = mulmod(x, x);
            if x == n - 1 {
                return true;
            }
        }
        false
    })
}

/// The integers x_i with |x_i| < M / 2 (M the product of the fields' primes) from their
/// residues: `residues[k][i]` is x_i mod p_k, a Montgomery form of `fields[k]` (see the
/// module docs: Garner's mixed radix, then the symmetric residue).
pub fn reconstruct_symmetric(fields: &[Field], residues: &[Vec<u64>]) -> Vec<BigInt> {
    let k = fields.len();
    let n = residues.first().map_or(0, Vec::len);
    // p_l in the Montgomery form of field j (l < j), and (p_0 ... p_(j-1))^-1 mod p_j.
    let radix: Vec<Vec<u64>> = (0..k)
        .map(|j| {
            (0..j)
                .map(|l| fields[j].of_u64(fields[l].prime()))
                .collect()
        })
        .collect();
    let garner: Vec<u64> = (0..k)
        .map(|j| {
            let f = fields[j];
            f.inv(radix[j].iter().fold(f.one(), |acc, &pl| f.mul(acc, pl)))
        })
        .collect();
    let modulus: BigUint = fields.iter().map(|f| BigUint::from(f.prime())).product();
    let mut digits = vec![0u64; k];
    (0..n)
        .map(|i| {
            for j in 0..k {
                let f = fields[j];
                // x_(j-1) = v_0 + p_0 (v_1 + p_1 (... + p_(j-2) v_(j-1))) mod p_j, Horner.
                let mut acc = 0;
                for l in (0..j).rev() {
                    acc = f.add(f.mul(acc, radix[j][l]), f.of_u64(digits[l]));
                }
                let v = f.mul(f.sub(residues[j][i], acc), garner[j]);
                digits[j] = f.to_u64(v);
            }
            let mut x = BigUint::from(0u32);
            for j in (0..k).rev() {
                x = x * fields[j].prime() + digits[j];
            }
            if &x << 1 > modulus {
                BigInt::from_biguint(Sign::Minus, &modulus - x)
            } else {
                BigInt::from_biguint(Sign::Plus, x)
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Zero;

    #[test]
    fn field_arithmetic_matches_u128() {
        for &p in &primes(3) {
            let f = Field::new(p);
            let xs = [0u64, 1, 2, p - 1, p / 3, 0x1234_5678_9abc_def0 % p];
            for &a in &xs {
                for &b in &xs {
                    let want = (a as u128 * b as u128 % p as u128) as u64;
                    let got = f.to_u64(f.mul(f.of_u64(a), f.of_u64(b)));
                    assert_eq!(got, want);
                    assert_eq!(
                        f.to_u64(f.sub(f.of_u64(a), f.of_u64(b))),
                        ((a as u128 + p as u128 - b as u128) % p as u128) as u64
                    );
                }
                if a != 0 {
                    let ia = f.inv(f.of_u64(a));
                    assert_eq!(f.mul(ia, f.of_u64(a)), f.one());
                }
            }
            let mut v: Vec<u64> = (1..20u64).map(|x| f.of_u64(x * 7919)).collect();
            let w = v.clone();
            f.inv_all(&mut v);
            for (x, y) in v.iter().zip(&w) {
                assert_eq!(f.mul(*x, *y), f.one());
            }
            let big: BigInt = BigInt::from(-3i64) * (BigInt::from(1u64) << 200) + 12345;
            let want = ((&big % BigInt::from(p)) + BigInt::from(p)) % BigInt::from(p);
            assert_eq!(BigInt::from(f.to_u64(f.of_bigint(&big))), want);
        }
    }

    #[test]
    fn primes_are_prime_and_in_range() {
        let ps = primes(4);
        assert!(ps.windows(2).all(|w| w[0] > w[1]));
        for &p in &ps {
            assert!(p > 1 << 61 && p < 1 << 62);
            // Trial division by small odd numbers as a cross-check of Miller–Rabin.
            assert!((3..20_000u64).step_by(2).all(|d| p % d != 0));
        }
        assert!(!is_prime((1u64 << 61) + 1));
        assert!(is_prime((1u64 << 61) - 1));
        assert_eq!(primes_for_bits(60), 1);
        assert_eq!(primes_for_bits(61), 2);
    }

    #[test]
    fn interpolation_and_reconstruction_recover_a_big_polynomial() {
        // p(x) = sum c_i x^i with coefficients of up to 150 bits, both signs.
        let c: Vec<BigInt> = (0..9)
            .map(|i| {
                let v = (BigInt::from(3u32).pow(90 + i) - BigInt::from(7u32).pow(40)) * (i + 1);
                if i % 2 == 0 {
                    -v
                } else {
                    v
                }
            })
            .collect();
        let bound_bits = c.iter().map(|x| x.bits()).max().unwrap();
        let fields: Vec<Field> = primes(primes_for_bits(bound_bits))
            .into_iter()
            .map(Field::new)
            .collect();
        let residues: Vec<Vec<u64>> = fields
            .iter()
            .map(|&f| {
                let values: Vec<u64> = (0..c.len() as u64)
                    .map(|x| {
                        let xm = f.of_u64(x);
                        c.iter()
                            .rev()
                            .fold(0, |acc, ci| f.add(f.mul(acc, xm), f.of_bigint(ci)))
                    })
                    .collect();
                f.interpolate_consecutive(&values)
            })
            .collect();
        assert_eq!(reconstruct_symmetric(&fields, &residues), c);
        assert!(reconstruct_symmetric(&fields, &[vec![0], vec![0], vec![0]])[0].is_zero());
    }
}
