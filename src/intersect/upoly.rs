//! Univariate polynomials with integer coefficients, `Vec<BigInt>` in ascending powers
//! (`[c0, c1, ..., cd]` is c0 + c1 x + ... + cd x^d; the zero polynomial is the empty vector).
//!
//! Everything here is exact integer arithmetic:
//! * gcd by the **primitive polynomial remainder sequence**: pseudo-remainders (Knuth's
//!   Algorithm R, so no fractions appear) divided by their content at every step, which keeps
//!   the coefficients no larger than the cofactors of the answer;
//! * the **square-free factorisation of Yun**: f = c f_1 f_2^2 ... f_k^k with every f_i
//!   square-free, primitive and the f_i pairwise coprime, so a zero of f_i is a zero of f of
//!   multiplicity exactly i;
//! * exact sign evaluation at a rational p/q by homogeneous Horner (q^d f(p/q), an integer).

use crate::num::meter::charge_integer_products;
use crate::num::ring::Rational;
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// A polynomial with integer coefficients, ascending powers, no trailing zero.
pub type ZPoly = Vec<BigInt>;

/// Drops trailing zero coefficients (the zero polynomial becomes empty).
pub fn trim(p: &mut ZPoly) {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
}

/// The degree, `None` for the zero polynomial.
pub fn degree(p: &[BigInt]) -> Option<usize> {
    p.iter().rposition(|c| !c.is_zero())
}

/// The gcd of the coefficients (non-negative; 0 for the zero polynomial).
///
/// Taken from the shortest coefficient up, each further coefficient first reduced modulo the
/// running gcd g (gcd(g, c) = gcd(g, c mod g)): one division of c by the short g instead of
/// a binary gcd of two long numbers, whose cost grows with the square of the longer one. The
/// resultants' coefficients run to thousands of bits while their content is usually short.
pub fn content(p: &[BigInt]) -> BigInt {
    let mut nonzero: Vec<&BigInt> = p.iter().filter(|c| !c.is_zero()).collect();
    nonzero.sort_unstable_by_key(|c| c.bits());
    let Some((first, rest)) = nonzero.split_first() else {
        return BigInt::zero();
    };
    let mut g = first.abs();
    for c in rest {
        if g.is_one() {
            break;
        }
        g = g.gcd(&(*c % &g));
    }
    g
}

/// The primitive part with a positive leading coefficient (the zero polynomial stays zero).
pub fn primitive(p: &[BigInt]) -> ZPoly {
    let mut out: ZPoly = p.to_vec();
    trim(&mut out);
    let mut g = content(&out);
    if g.is_zero() {
        return out;
    }
    if out.last().is_some_and(Signed::is_negative) {
        g = -g;
    }
    if !g.is_one() {
        for c in &mut out {
            *c /= &g;
        }
    }
    out
}

/// The integer polynomial with the same zeros as the rational polynomial `p` (ascending):
/// `p` times the lcm of its denominators, made primitive.
pub fn from_rationals(p: &[Rational]) -> ZPoly {
    let mut l = BigInt::one();
    for c in p {
        l = l.lcm(c.denom());
    }
    let scaled: ZPoly = p.iter().map(|c| c.numer() * (&l / c.denom())).collect();
    primitive(&scaled)
}

/// A positive integer multiple of the rational polynomial `p`, divided by its content: the
/// same zeros and the same signs everywhere.
pub fn positive_multiple(p: &[Rational]) -> ZPoly {
    let mut l = BigInt::one();
    for c in p {
        l = l.lcm(c.denom());
    }
    let mut out: ZPoly = p.iter().map(|c| c.numer() * (&l / c.denom())).collect();
    trim(&mut out);
    let g = content(&out);
    if !g.is_zero() && !g.is_one() {
        out.iter_mut().for_each(|x| *x /= &g);
    }
    out
}

/// The derivative.
pub fn derivative(p: &[BigInt]) -> ZPoly {
    let mut d: ZPoly = p
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * BigInt::from(i))
        .collect();
    trim(&mut d);
    d
}

/// The product.
pub fn mul(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![BigInt::zero(); a.len() + b.len() - 1];
    let b_bits = b.iter().map(BigInt::bits).max().unwrap_or(0);
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        charge_integer_products(b.len() as u64, x.bits(), b_bits);
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    trim(&mut out);
    out
}

/// `a - b`.
pub fn sub(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let mut out = vec![BigInt::zero(); a.len().max(b.len())];
    for (i, x) in a.iter().enumerate() {
        out[i] += x;
    }
    for (i, y) in b.iter().enumerate() {
        out[i] -= y;
    }
    trim(&mut out);
    out
}

/// The pseudo-remainder of `a` by `b` (b non-zero): lc(b)^(deg a - deg b + 1) a mod b.
fn pseudo_remainder(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let mut r: ZPoly = a.to_vec();
    trim(&mut r);
    let db = degree(b).expect("non-zero divisor");
    let lb = &b[db];
    while let Some(dr) = degree(&r) {
        if dr < db {
            break;
        }
        let lr = r[dr].clone();
        let shift = dr - db;
        let longest = r.iter().map(BigInt::bits).max().unwrap_or(0);
        charge_integer_products(2 * (dr as u64 + 1), longest, lb.bits().max(lr.bits()));
        for c in r.iter_mut() {
            *c *= lb;
        }
        for (j, c) in b.iter().enumerate().take(db + 1) {
            r[j + shift] -= &lr * c;
        }
        trim(&mut r);
    }
    r
}

/// The exact quotient a / b when b divides a over the rationals and the quotient has integer
/// coefficients (as for a divisor of a primitive polynomial times an integer); `None` when the
/// division leaves a remainder or a fraction.
pub fn exact_div(a: &[BigInt], b: &[BigInt]) -> Option<ZPoly> {
    let db = degree(b)?;
    let mut r: ZPoly = a.to_vec();
    trim(&mut r);
    let Some(da) = degree(&r) else {
        return Some(Vec::new());
    };
    if da < db {
        return None;
    }
    let mut q = vec![BigInt::zero(); da - db + 1];
    let lb = &b[db];
    for k in (0..=da - db).rev() {
        let c = &r[k + db];
        if c.is_zero() {
            continue;
        }
        let (qk, rem) = c.div_rem(lb);
        if !rem.is_zero() {
            return None;
        }
        charge_integer_products(db as u64 + 2, c.bits(), qk.bits().max(lb.bits()));
        for (j, bj) in b.iter().enumerate().take(db + 1) {
            r[j + k] -= &qk * bj;
        }
        q[k] = qk;
    }
    if r.iter().any(|c| !c.is_zero()) {
        return None;
    }
    trim(&mut q);
    Some(q)
}

/// The greatest common divisor, primitive with a positive leading coefficient (`[1]` when the
/// polynomials are coprime, empty when both are zero), by the primitive remainder sequence.
///
/// Fast path: when the images modulo a prime p dividing neither leading coefficient are
/// coprime over F_p, the polynomials are coprime over Z (a common factor g has lc(g) | lc(a),
/// so g mod p keeps its degree and divides both images).
pub fn gcd(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let mut x = primitive(a);
    let mut y = primitive(b);
    if !x.is_empty() && !y.is_empty() && coprime_modulo_prime(&x, &y) {
        return vec![BigInt::one()];
    }
    if degree(&x) < degree(&y) {
        std::mem::swap(&mut x, &mut y);
    }
    while degree(&y).is_some() {
        let r = pseudo_remainder(&x, &y);
        x = y;
        y = primitive(&r);
    }
    primitive(&x)
}

/// Primes below 2^31 for the modular coprimality test.
const GCD_PRIMES: [u64; 3] = [2_147_483_647, 2_147_483_629, 2_147_483_587];

/// Whether a and b (non-zero) are proven coprime by their images modulo a prime dividing
/// neither leading coefficient (see [`gcd`]); `false` means "not proven".
fn coprime_modulo_prime(a: &[BigInt], b: &[BigInt]) -> bool {
    let (da, db) = (degree(a).unwrap_or(0), degree(b).unwrap_or(0));
    if da == 0 || db == 0 {
        return true;
    }
    for &p in &GCD_PRIMES {
        let pb = BigInt::from(p);
        let reduce = |v: &[BigInt]| -> Vec<u64> {
            v.iter()
                .map(|c| {
                    let r = c.mod_floor(&pb);
                    r.iter_u64_digits().next().unwrap_or(0)
                })
                .collect()
        };
        let (mut x, mut y) = (reduce(a), reduce(b));
        if x[da] == 0 || y[db] == 0 {
            continue;
        }
        let trim_p = |v: &mut Vec<u64>| {
            while v.last() == Some(&0) {
                v.pop();
            }
        };
        trim_p(&mut x);
        trim_p(&mut y);
        let inv = |v: u64| -> u64 {
            // v^(p-2) mod p.
            let (mut base, mut e, mut acc) = (v % p, p - 2, 1u64);
            while e > 0 {
                if e & 1 == 1 {
                    acc = acc * base % p;
                }
                base = base * base % p;
                e >>= 1;
            }
            acc
        };
        while !y.is_empty() {
            // x <- x mod y.
            let dy = y.len() - 1;
            let iy = inv(y[dy]);
            while x.len() > dy {
                let k = x[x.len() - 1] * iy % p;
                let shift = x.len() - 1 - dy;
                for (j, c) in y.iter().enumerate() {
                    x[j + shift] = (x[j + shift] + p - k * c % p) % p;
                }
                trim_p(&mut x);
            }
            std::mem::swap(&mut x, &mut y);
        }
        return x.len() == 1;
    }
    false
}

/// Yun's square-free factorisation of a non-zero `p`: the list of (f_i, i) with f_i
/// primitive, square-free, of positive degree and pairwise coprime, such that
/// p = c * prod f_i^i for a constant c. Factors of degree 0 are left out.
///
/// Yun's recurrence a_i = gcd(b_i, d_i), b_(i+1) = b_i / a_i, c_(i+1) = d_i / a_i,
/// d_i = c_i - b_i' (b_1 = f / gcd(f, f'), c_1 = f' / gcd(f, f')) only needs b_i and c_i to
/// carry the *same* constant factor, so every quotient is taken by a primitive divisor (an
/// integer quotient by Gauss's lemma) and b_i, c_i are divided by their common content only.
pub fn square_free_factors(p: &[BigInt]) -> Vec<(ZPoly, usize)> {
    let f = primitive(p);
    let mut out = Vec::new();
    if degree(&f).unwrap_or(0) == 0 {
        return out;
    }
    let df = derivative(&f);
    let a0 = gcd(&f, &df);
    let mut b = exact_div(&f, &a0).expect("a primitive divisor divides exactly");
    let mut c = exact_div(&df, &a0).expect("a primitive divisor divides exactly");
    let mut i = 1;
    loop {
        let d = sub(&c, &derivative(&b));
        let a = gcd(&b, &d);
        if degree(&a).unwrap_or(0) > 0 {
            out.push((a.clone(), i));
        }
        b = exact_div(&b, &a).expect("a primitive divisor divides exactly");
        if degree(&b).unwrap_or(0) == 0 {
            break;
        }
        c = exact_div(&d, &a).expect("a primitive divisor divides exactly");
        let g = content(&b).gcd(&content(&c));
        if !g.is_zero() && !g.is_one() {
            b.iter_mut().for_each(|x| *x /= &g);
            c.iter_mut().for_each(|x| *x /= &g);
        }
        i += 1;
    }
    out
}

/// The square-free part f / gcd(f, f') of a non-zero `f`, primitive.
pub fn square_free_part(f: &[BigInt]) -> ZPoly {
    let f = primitive(f);
    let g = gcd(&f, &derivative(&f));
    if degree(&g).unwrap_or(0) == 0 {
        return f;
    }
    primitive(&exact_div(&f, &g).expect("a primitive divisor divides exactly"))
}

/// Whether `p` vanishes identically.
pub fn is_zero(p: &[BigInt]) -> bool {
    p.iter().all(Zero::is_zero)
}

/// The sign of p(x) for a rational x = n / d (d > 0), exactly, by homogeneous Horner:
/// d^deg p(n/d) = sum c_i n^i d^(deg - i).
pub fn sign_at(p: &[BigInt], x: &Rational) -> Ordering {
    match scaled_value_at(p, x).sign() {
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
        Sign::Plus => Ordering::Greater,
    }
}

/// d^deg p(x) for a rational x = n / d in lowest terms (d > 0), deg the degree of `p`, by
/// homogeneous Horner (sum c_i n^i d^(deg - i)): p(x) with its denominator cleared by a
/// positive factor; zero for the zero polynomial.
pub fn scaled_value_at(p: &[BigInt], x: &Rational) -> BigInt {
    let Some(deg) = degree(p) else {
        return BigInt::zero();
    };
    let (n, d) = (x.numer(), x.denom());
    let mut acc = p[deg].clone();
    let mut dpow = BigInt::one();
    for c in p[..deg].iter().rev() {
        charge_integer_products(1, acc.bits(), n.bits());
        charge_integer_products(2, c.bits(), dpow.bits().max(d.bits()));
        dpow *= d;
        acc = acc * n + c * &dpow;
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::content;
    use num_bigint::BigInt;
    use num_integer::Integer;
    use num_traits::Zero;

    #[test]
    fn content_is_the_gcd_of_all_coefficients() {
        // Coefficients k_i g with pseudo-random k_i of 1 to 300 bits, signs and zeros mixed:
        // the content against the gcd taken in order, one pair at a time (its definition).
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for case in 0..40 {
            let g = BigInt::from(next() % 1000 + 1) * BigInt::from(next() >> (case % 60));
            let p: Vec<BigInt> = (0..(case % 9 + 1))
                .map(|i| {
                    let words = next() % 5;
                    let mut k = BigInt::from(next() % 7);
                    for _ in 0..words {
                        k = (k << 64) + BigInt::from(next());
                    }
                    let k = if i % 3 == 1 { -k } else { k };
                    k * &g
                })
                .collect();
            let want = p.iter().fold(BigInt::zero(), |acc, c| acc.gcd(c));
            assert_eq!(content(&p), want, "case {case}");
        }
        assert_eq!(content(&[]), BigInt::zero());
        assert_eq!(
            content(&[BigInt::zero(), BigInt::from(-6)]),
            BigInt::from(6)
        );
    }
}
