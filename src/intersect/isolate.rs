//! Real root isolation of a square-free integer polynomial on a closed rational interval
//! [a, b], by **Descartes' rule of signs on Bernstein coefficients** with exact bisection.
//!
//! On [lo, hi] write f(x) = sum_i b_i C(n, i) u^i (1 - u)^(n - i), u = (x - lo) / (hi - lo).
//! The number V of sign changes of (b_0, ..., b_n) (zeros skipped) exceeds the number of roots
//! of f in the open interval (lo, hi) by an even number (the substitution u = y / (1 + y)
//! turns the Bernstein coefficients into the power coefficients of (1 + y)^n f, whose positive
//! roots Descartes counts). So V = 0 proves no root and V = 1 exactly one; otherwise the
//! interval is halved. For a square-free f the bisection terminates (the one- and two-circle
//! theorems of Ostrowski and Obreshkoff; Eigenwillig, Sharma and Yap, ISSAC 2006).
//!
//! The start coefficients are computed in integers ([`bernstein_on`]: an integer Taylor shift,
//! a scaling, and the power-to-Bernstein change as a shift by 1 of the reversed polynomial),
//! never through reduced fractions.
//! The halving is de Casteljau's algorithm at u = 1/2 with **sums instead of averages**: level
//! k holds 2^k times the true values, so after multiplying the left half by 2^(n - j) and the
//! right half by 2^j (j the level read) both halves are integer vectors proportional by a
//! positive factor to the true Bernstein coefficients. Only additions and shifts: no fractions
//! and no gcd on the hot path (a common power of two is removed after each halving).
//!
//! An accepted interval (V = 1) also has non-zero end coefficients: its ends are not roots,
//! so f changes sign over it, which the algebraic numbers rely on. A root found at a halving
//! point (the left half's last coefficient is f there) or at a or b is reported exactly.

use super::upoly::{degree, sign_at};
use crate::num::meter::{charge_integer_products, charge_integer_sums};
use crate::num::ring::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// One isolated real root: `exact` when the root was found as a rational number, else the
/// open interval (lo, hi) holds exactly one root, and f(lo), f(hi) are non-zero.
#[derive(Clone, Debug, PartialEq)]
pub struct Isolated {
    /// The lower end (the root itself when exact).
    pub lo: Rational,
    /// The upper end (the root itself when exact).
    pub hi: Rational,
    /// Whether the root is the rational `lo == hi`.
    pub exact: bool,
}

/// The number of sign changes of a sequence, zeros skipped.
pub fn sign_changes(b: &[BigInt]) -> usize {
    let mut last = 0i8;
    let mut v = 0;
    for c in b {
        let s = if c.is_positive() {
            1
        } else if c.is_negative() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

/// The integer Bernstein coefficients over [a, b] (a < b) of the polynomial f (ascending
/// powers), up to a positive factor, with integer arithmetic only (no fraction is reduced):
/// 1. with D the lcm of the ends' denominators, a = A / D and b - a = W / D, the polynomial
///    g(u) = D^n f(a + (b - a) u) is h(A + W u) for h(y) = sum f_i D^(n - i) y^i;
/// 2. h(A + z) by an integer Taylor shift, then z = W u multiplies the k-th coefficient by
///    W^k, giving g;
/// 3. the scaled Bernstein coefficients c_j = C(n, j) b_j of g are the coefficients of
///    (1 + y)^n g(y / (1 + y)) = sum_k g_k y^k (1 + y)^(n - k), whose reverse is the
///    reverse of g shifted by 1 (additions only);
/// 4. b_j = c_j / C(n, j), made integral by the lcm L of the binomials C(n, j):
///    L b_j = c_j (L / C(n, j)).
pub fn bernstein_on(f: &[BigInt], a: &Rational, b: &Rational) -> Vec<BigInt> {
    let n = f.len().saturating_sub(1);
    let d = a.denom().lcm(b.denom());
    let big_a = a.numer() * (&d / a.denom());
    let big_w = b.numer() * (&d / b.denom()) - &big_a;
    let mut g: Vec<BigInt> = f.to_vec();
    if !d.is_one() {
        let mut dpow = BigInt::one();
        for c in g.iter_mut().rev() {
            *c *= &dpow;
            dpow *= &d;
        }
    }
    taylor_shift_integer(&mut g, &big_a);
    if !big_w.is_one() {
        let mut wpow = BigInt::one();
        for c in g.iter_mut().skip(1) {
            wpow *= &big_w;
            *c *= &wpow;
        }
    }
    g.reverse();
    taylor_shift_integer(&mut g, &BigInt::one());
    g.reverse();
    // The binomials C(n, j) and their lcm.
    let mut binomials = Vec::with_capacity(n + 1);
    let mut c = BigInt::one();
    for j in 0..=n {
        binomials.push(c.clone());
        c = c * BigInt::from(n - j) / BigInt::from(j + 1);
    }
    let l = binomials.iter().fold(BigInt::one(), |l, c| l.lcm(c));
    g.iter_mut().zip(&binomials).for_each(|(x, c)| *x *= &l / c);
    g
}

/// The coefficients (ascending) of p(x + a) in place, for an integer a, by repeated synthetic
/// division (n(n + 1)/2 multiply-adds; additions only when a = 1 or a = -1).
fn taylor_shift_integer(p: &mut [BigInt], a: &BigInt) {
    if a.is_zero() {
        return;
    }
    let n = p.len().saturating_sub(1);
    let one = a.is_one();
    let minus_one = (-a).is_one();
    // Each pass adds at most the bits of a (and one) to the longest coefficient.
    let longest = p.iter().map(BigInt::bits).max().unwrap_or(0) + n as u64 * (a.bits() + 1);
    let steps = (n * (n + 1) / 2) as u64;
    if one || minus_one {
        charge_integer_sums(steps, longest);
    } else {
        charge_integer_products(steps, longest, a.bits());
    }
    for k in 0..n {
        for i in (k..n).rev() {
            let (lo, hi) = p.split_at_mut(i + 1);
            if one {
                lo[i] += &hi[0];
            } else if minus_one {
                lo[i] -= &hi[0];
            } else {
                lo[i] += a * &hi[0];
            }
        }
    }
}

/// The two halves of the integer Bernstein vector `b` (de Casteljau at u = 1/2 with sums
/// instead of averages, then the powers of two evened out), each scaled by
/// a positive factor; the left half's last entry is (a positive multiple of) f at the middle.
pub fn halve(b: &[BigInt]) -> (Vec<BigInt>, Vec<BigInt>) {
    let n = b.len() - 1;
    // n (n + 1) / 2 sums and 2 (n + 1) shifts of numbers of at most n more bits.
    let longest = b.iter().map(BigInt::bits).max().unwrap_or(0) + n as u64;
    charge_integer_sums((n * (n + 1) / 2 + 2 * (n + 1)) as u64, longest);
    let mut level: Vec<BigInt> = b.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = vec![BigInt::zero(); n + 1];
    left.push(level[0].clone() << n);
    right[n] = level[n].clone() << n;
    for j in 1..=n {
        for i in 0..=n - j {
            let next = &level[i] + &level[i + 1];
            level[i] = next;
        }
        left.push(level[0].clone() << (n - j));
        right[n - j] = level[n - j].clone() << (n - j);
    }
    (strip_twos(left), strip_twos(right))
}

/// Divides a vector by the largest power of two dividing all its entries.
fn strip_twos(mut v: Vec<BigInt>) -> Vec<BigInt> {
    let shift = v
        .iter()
        .filter_map(|x| x.trailing_zeros())
        .min()
        .unwrap_or(0);
    if shift > 0 {
        for x in &mut v {
            *x >>= shift;
        }
    }
    v
}

/// The real roots of the square-free, non-zero integer polynomial `f` in the closed interval
/// [a, b] (a < b), in increasing order.
pub fn isolate(f: &[BigInt], a: &Rational, b: &Rational) -> Vec<Isolated> {
    let mut out = Vec::new();
    let Some(n) = degree(f) else {
        return out;
    };
    if n == 0 {
        return out;
    }
    let width = b - a;
    let at = |k: &BigInt, d: usize| a + &width * Rational::new(k.clone(), BigInt::one() << d);
    let exact = |r: Rational| Isolated {
        lo: r.clone(),
        hi: r,
        exact: true,
    };
    if sign_at(f, a) == Ordering::Equal {
        out.push(exact(a.clone()));
    }
    // Depth-first, left before right (a stack: right half, middle, left half pushed in this
    // order), so the roots come out in increasing order.
    enum Task {
        Interval(Vec<BigInt>, BigInt, usize),
        Root(Rational),
    }
    let mut stack = vec![Task::Interval(bernstein_on(f, a, b), BigInt::zero(), 0)];
    while let Some(task) = stack.pop() {
        let (coef, k, d) = match task {
            Task::Root(r) => {
                out.push(exact(r));
                continue;
            }
            Task::Interval(coef, k, d) => (coef, k, d),
        };
        let v = sign_changes(&coef);
        if v == 0 {
            continue;
        }
        if v == 1 && !coef[0].is_zero() && !coef[n].is_zero() {
            out.push(Isolated {
                lo: at(&k, d),
                hi: at(&(&k + 1), d),
                exact: false,
            });
            continue;
        }
        let (left, right) = halve(&coef);
        let k2: BigInt = &k << 1;
        stack.push(Task::Interval(right, &k2 + 1, d + 1));
        if left[n].is_zero() {
            stack.push(Task::Root(at(&(&k2 + 1), d + 1)));
        }
        stack.push(Task::Interval(left, k2, d + 1));
    }
    if sign_at(f, b) == Ordering::Equal {
        out.push(exact(b.clone()));
    }
    out
}
