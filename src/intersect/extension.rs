//! Exact arithmetic in a real algebraic extension Q(alpha), by dynamic evaluation, and the
//! fibre of a bivariate system over an algebraic abscissa.
//!
//! **The field.** alpha is a real algebraic number ([`AlgebraicReal`], an isolating interval)
//! and m a square-free rational polynomial with m(alpha) = 0, *not necessarily irreducible*.
//! An element of Q(alpha) is represented by a rational polynomial a(x) of degree < deg m and
//! stands for a(alpha). Sums and products are those of Q[x] reduced modulo m; they are
//! correct for every root of m at once. Division is where a reducible m shows: a(x) may be
//! a zero divisor modulo m (a non-zero polynomial vanishing at some roots of m). The
//! **dynamic evaluation** (D5) principle settles it: the extended Euclidean algorithm over Q
//! gives g = gcd(m, a) with a cofactor; when g = 1 the cofactor is the inverse; otherwise
//! m = g (m / g) with coprime factors (m is square-free) and alpha is a root of exactly one
//! of them, which one decided exactly by the sign change of that factor over alpha's
//! isolating interval (a divisor of m has at most the one root of m there, and it is simple).
//! The modulus is replaced by that factor, so the arithmetic always takes place in a field
//! that holds alpha: a(alpha) = 0 exactly when alpha is a root of g, and otherwise a is
//! invertible modulo m / g. Elements computed before a split stay valid (the new modulus
//! divides the old one) and are reduced again when next used. Every zero test is therefore
//! exact, and so is every degree of a polynomial over Q(alpha).
//!
//! **Signs.** The sign of a(alpha) for a non-zero a is the sign of a rational polynomial at
//! the algebraic number, decided exactly by [`AlgebraicReal::sign_of`] (Bernstein
//! coefficients over a refined isolating interval).
//!
//! **The fibre.** For integer polynomials A(s, t), B(s, t) and a root alpha of their
//! resultant Res_t(A, B), the common roots t of A(alpha, t) and B(alpha, t) are the roots
//! of G = gcd(A(alpha, t), B(alpha, t)) in Q(alpha)[t], computed by the monic Euclidean
//! algorithm with exact zero tests of the leading coefficients, and made square-free as
//! G / gcd(G, G'). A real algebraic beta with square-free integer polynomial f_beta and
//! isolating interval [l, h] is a root of G exactly when H = gcd(G, f_beta) (over Q(alpha))
//! changes sign over [l, h]: H divides f_beta, so its real roots in [l, h] are among
//! {beta}, and beta is a simple root of f_beta; H(alpha, l) and H(alpha, h) are non-zero
//! (else l or h would be a root of f_beta) and their signs are signs of elements of Q(alpha).
//! The same test decides whether the Jacobian of the system vanishes at (alpha, beta).
//!
//! **Cost.** Work grows with d = deg m: a product in Q(alpha) is about 2 d^2 rational
//! operations, a gcd of two polynomials of degree k in t about k^2 products and k
//! inversions (each an extended Euclid over Q of degree d). [`fibre_work`] estimates a fibre
//! and [`Extension::fibre`] charges that estimate to the work meter
//! ([`crate::meter::charge_work`]) *before* computing, so a metered caller is stopped before
//! a costly fibre starts.

use super::algebraic::AlgebraicReal;
use super::bivariate::{coefficient_t, degree_t, BiPoly};
use super::upoly::positive_multiple;
use crate::num::ring::Rational;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// An element of Q(alpha): a rational polynomial in x (ascending, no trailing zero) standing
/// for its value at alpha.
pub(crate) type Elem = Vec<Rational>;

/// A polynomial in t over Q(alpha): its coefficients, ascending.
pub(crate) type EPoly = Vec<Elem>;

/// Q(alpha) = Q[x]/(m) for a square-free m with m(alpha) = 0, not necessarily irreducible:
/// a division by a zero divisor splits m = g (m / g) and keeps the factor that alpha is a
/// root of (dynamic evaluation), so every zero test is exact.
#[derive(Clone, Debug)]
pub(crate) struct Extension {
    alpha: AlgebraicReal,
    /// Monic, square-free, m(alpha) = 0.
    m: Vec<Rational>,
    /// How many times the modulus was split.
    splits: usize,
}

/// Drops trailing zero coefficients of a rational polynomial.
pub(crate) fn trim_q(p: &mut Vec<Rational>) {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
}

/// The degree of a non-zero rational polynomial (`None` for zero).
pub(crate) fn deg_q(p: &[Rational]) -> Option<usize> {
    p.iter().rposition(|c| !c.is_zero())
}

/// Integer coefficients as rationals.
fn to_q(p: &[BigInt]) -> Vec<Rational> {
    let mut v: Vec<Rational> = p
        .iter()
        .map(|c| Rational::from_integer(c.clone()))
        .collect();
    trim_q(&mut v);
    v
}

/// a + b.
pub(crate) fn add_q(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out: Vec<Rational> = vec![Rational::zero(); a.len().max(b.len())];
    for (i, x) in a.iter().enumerate() {
        out[i] += x;
    }
    for (i, y) in b.iter().enumerate() {
        out[i] += y;
    }
    trim_q(&mut out);
    out
}

/// a - b.
fn sub_q(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out: Vec<Rational> = vec![Rational::zero(); a.len().max(b.len())];
    for (i, x) in a.iter().enumerate() {
        out[i] += x;
    }
    for (i, y) in b.iter().enumerate() {
        out[i] -= y;
    }
    trim_q(&mut out);
    out
}

/// a b.
pub(crate) fn mul_q(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![Rational::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            if !y.is_zero() {
                out[i + j] += x * y;
            }
        }
    }
    trim_q(&mut out);
    out
}

/// c a for a rational c.
fn scale_q(a: &[Rational], c: &Rational) -> Vec<Rational> {
    if c.is_zero() {
        return Vec::new();
    }
    a.iter().map(|x| x * c).collect()
}

/// Quotient and remainder of a by a non-zero b over Q.
pub(crate) fn divrem_q(a: &[Rational], b: &[Rational]) -> (Vec<Rational>, Vec<Rational>) {
    let db = deg_q(b).expect("a non-zero divisor");
    let mut r: Vec<Rational> = a.to_vec();
    trim_q(&mut r);
    let Some(da) = deg_q(&r) else {
        return (Vec::new(), Vec::new());
    };
    if da < db {
        return (Vec::new(), r);
    }
    let inv = Rational::one() / &b[db];
    let mut q = vec![Rational::zero(); da - db + 1];
    for k in (0..=da - db).rev() {
        let c = &r[k + db] * &inv;
        if c.is_zero() {
            continue;
        }
        for (j, bj) in b.iter().enumerate().take(db + 1) {
            if !bj.is_zero() {
                r[j + k] -= &c * bj;
            }
        }
        q[k] = c;
    }
    trim_q(&mut r);
    trim_q(&mut q);
    (q, r)
}

/// The monic gcd g of m and a (a reduced modulo m, m non-zero) over Q and a cofactor u with
/// u a = g modulo m (the extended Euclidean algorithm).
fn ext_gcd_q(m: &[Rational], a: &[Rational]) -> (Vec<Rational>, Vec<Rational>) {
    let (mut r0, mut r1) = (m.to_vec(), a.to_vec());
    let (mut u0, mut u1): (Vec<Rational>, Vec<Rational>) = (Vec::new(), vec![Rational::one()]);
    while deg_q(&r1).is_some() {
        let (q, r) = divrem_q(&r0, &r1);
        let u = sub_q(&u0, &mul_q(&q, &u1));
        (r0, r1) = (r1, r);
        (u0, u1) = (u1, u);
    }
    let lc = Rational::one() / r0.last().expect("a non-zero gcd");
    (scale_q(&r0, &lc), scale_q(&u0, &lc))
}

impl Extension {
    /// Q(alpha) = Q[x]/(m) for a square-free integer polynomial `m` of positive degree that
    /// vanishes at `alpha` (not necessarily irreducible).
    pub(crate) fn new(alpha: &AlgebraicReal, m: &[BigInt]) -> Self {
        debug_assert!(alpha.is_root_of(m), "the modulus vanishes at alpha");
        let mut q = to_q(m);
        let lc = Rational::one() / q.last().expect("a modulus of positive degree");
        q = scale_q(&q, &lc);
        Extension {
            alpha: alpha.clone(),
            m: q,
            splits: 0,
        }
    }

    /// The degree of the current modulus.
    pub(crate) fn degree(&self) -> usize {
        self.m.len() - 1
    }

    /// The current modulus (monic).
    #[cfg(test)]
    pub(crate) fn modulus(&self) -> &[Rational] {
        &self.m
    }

    /// How many times dynamic evaluation split the modulus.
    #[cfg(test)]
    pub(crate) fn splits(&self) -> usize {
        self.splits
    }

    /// a modulo the current modulus.
    pub(crate) fn reduce(&self, a: &[Rational]) -> Elem {
        if a.len() < self.m.len() {
            let mut v = a.to_vec();
            trim_q(&mut v);
            return v;
        }
        divrem_q(a, &self.m).1
    }

    /// The element p(alpha) of an integer polynomial p.
    pub(crate) fn of_integers(&self, p: &[BigInt]) -> Elem {
        self.reduce(&to_q(p))
    }

    /// a - b.
    pub(crate) fn sub(&self, a: &[Rational], b: &[Rational]) -> Elem {
        self.reduce(&sub_q(a, b))
    }

    /// a b.
    pub(crate) fn mul(&self, a: &[Rational], b: &[Rational]) -> Elem {
        self.reduce(&mul_q(&self.reduce(a), &self.reduce(b)))
    }

    /// Replaces the modulus by the factor of m = g (m / g) that vanishes at alpha (g a monic
    /// proper divisor of m); true when that factor is g.
    fn split(&mut self, g: &[Rational]) -> bool {
        self.splits += 1;
        let gi = positive_multiple(g);
        if self.alpha.is_root_of(&gi) {
            self.m = g.to_vec();
            true
        } else {
            let (q, _) = divrem_q(&self.m, g);
            let lc = Rational::one() / q.last().expect("a proper divisor");
            self.m = scale_q(&q, &lc);
            false
        }
    }

    /// The inverse of a, or `None` when a(alpha) = 0 (exactly; the modulus may be split).
    pub(crate) fn inverse(&mut self, a: &[Rational]) -> Option<Elem> {
        loop {
            let a = self.reduce(a);
            if a.is_empty() {
                return None;
            }
            let (g, u) = ext_gcd_q(&self.m, &a);
            if g.len() == 1 {
                return Some(self.reduce(&u));
            }
            if self.split(&g) {
                // alpha is a root of g, which divides a.
                return None;
            }
            // Now gcd(m, a) = 1: the next round inverts.
        }
    }

    /// Whether a(alpha) = 0, exactly (the modulus may be split).
    pub(crate) fn is_zero(&mut self, a: &[Rational]) -> bool {
        let r = self.reduce(a);
        if r.is_empty() {
            return true;
        }
        if r.len() == 1 {
            return false;
        }
        let (g, _) = ext_gcd_q(&self.m, &r);
        g.len() > 1 && self.split(&g)
    }

    /// The sign of a(alpha), exactly.
    pub(crate) fn sign(&mut self, a: &[Rational]) -> Ordering {
        if self.is_zero(a) {
            return Ordering::Equal;
        }
        let r = self.reduce(a);
        self.alpha.sign_of(&positive_multiple(&r))
    }

    /// Drops the leading coefficients of p that vanish at alpha.
    pub(crate) fn trim(&mut self, p: &mut EPoly) {
        while let Some(c) = p.last() {
            let c = c.clone();
            if !self.is_zero(&c) {
                break;
            }
            p.pop();
        }
        for c in p.iter_mut() {
            *c = self.reduce(c);
        }
    }

    /// p made monic (p trimmed, non-zero).
    fn monic(&mut self, p: &EPoly) -> EPoly {
        let inv = self
            .inverse(p.last().expect("a non-zero polynomial"))
            .expect("a trimmed polynomial has a non-zero leading coefficient");
        p.iter().map(|c| self.mul(c, &inv)).collect()
    }

    /// Quotient and remainder of a by a monic b (both trimmed), over Q(alpha).
    fn divrem_monic(&mut self, a: &EPoly, b: &EPoly) -> (EPoly, EPoly) {
        let db = b.len() - 1;
        let mut r = a.clone();
        if r.len() < b.len() {
            return (Vec::new(), r);
        }
        let mut q = vec![Elem::new(); r.len() - db];
        for k in (0..r.len() - db).rev() {
            let c = self.reduce(&r[k + db]);
            if c.is_empty() {
                continue;
            }
            for (j, bj) in b.iter().enumerate() {
                let prod = self.mul(&c, bj);
                r[j + k] = self.sub(&r[j + k], &prod);
            }
            q[k] = c;
        }
        r.truncate(db);
        self.trim(&mut r);
        self.trim(&mut q);
        (q, r)
    }

    /// The monic gcd of a and b in Q(alpha)[t] (empty when both vanish at alpha identically).
    pub(crate) fn gcd(&mut self, a: &EPoly, b: &EPoly) -> EPoly {
        let (mut x, mut y) = (a.clone(), b.clone());
        self.trim(&mut x);
        self.trim(&mut y);
        if x.len() < y.len() {
            std::mem::swap(&mut x, &mut y);
        }
        while !y.is_empty() {
            let ym = self.monic(&y);
            let (_, r) = self.divrem_monic(&x, &ym);
            x = ym;
            y = r;
        }
        if x.is_empty() {
            return x;
        }
        self.monic(&x)
    }

    /// The derivative in t.
    fn derivative(&self, p: &EPoly) -> EPoly {
        p.iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| scale_q(c, &Rational::from_integer(BigInt::from(i))))
            .collect()
    }

    /// The square-free part p / gcd(p, p') of a non-zero p, monic.
    pub(crate) fn square_free_part(&mut self, p: &EPoly) -> EPoly {
        let mut p = p.clone();
        self.trim(&mut p);
        let p = self.monic(&p);
        let d = self.derivative(&p);
        let g = self.gcd(&p, &d);
        if g.len() <= 1 {
            return p;
        }
        let (q, _) = self.divrem_monic(&p, &g);
        self.monic(&q)
    }

    /// A(alpha, t) for a bivariate integer polynomial (a[i][j] the coefficient of s^i t^j).
    pub(crate) fn specialise(&mut self, a: &BiPoly) -> EPoly {
        let dt = degree_t(a).unwrap_or(0);
        let mut p: EPoly = (0..=dt)
            .map(|j| self.of_integers(&coefficient_t(a, j)))
            .collect();
        self.trim(&mut p);
        p
    }

    /// p(alpha, t0) at a rational t0.
    fn eval_at(&self, p: &EPoly, t0: &Rational) -> Elem {
        p.iter()
            .rev()
            .fold(Elem::new(), |acc, c| add_q(&scale_q(&acc, t0), c))
    }

    /// Whether the real algebraic beta is a root of p(alpha, t): H = gcd(p, f_beta) over
    /// Q(alpha) changes sign over beta's isolating interval (f_beta its polynomial).
    pub(crate) fn vanishes_at(&mut self, p: &EPoly, beta: &AlgebraicReal) -> bool {
        let mut p = p.clone();
        self.trim(&mut p);
        if p.is_empty() {
            return true;
        }
        if let Some(b) = beta.exact() {
            let v = self.eval_at(&p, b);
            return self.is_zero(&v);
        }
        let f: EPoly = beta
            .polynomial()
            .iter()
            .map(|c| to_q(std::slice::from_ref(c)))
            .collect();
        let h = self.gcd(&p, &f);
        if h.len() <= 1 {
            return false;
        }
        let (lo, hi) = beta.interval();
        let (at_lo, at_hi) = (self.eval_at(&h, lo), self.eval_at(&h, hi));
        let (sl, sh) = (self.sign(&at_lo), self.sign(&at_hi));
        debug_assert!(sl != Ordering::Equal && sh != Ordering::Equal);
        sl != sh
    }

    /// The fibre of the system A = B = 0 over alpha: the square-free monic gcd of A(alpha, t)
    /// and B(alpha, t) in Q(alpha)[t] (empty when both vanish identically at alpha). Charges
    /// [`fibre_work`] to the work meter first.
    pub(crate) fn fibre(&mut self, a: &BiPoly, b: &BiPoly) -> EPoly {
        let k = degree_t(a).unwrap_or(0).max(degree_t(b).unwrap_or(0));
        crate::num::meter::charge_work(fibre_work(self.degree(), k, bits_of(a).max(bits_of(b))));
        let (pa, pb) = (self.specialise(a), self.specialise(b));
        let g = self.gcd(&pa, &pb);
        if g.is_empty() {
            return g;
        }
        self.square_free_part(&g)
    }
}

/// The longest coefficient of a bivariate polynomial, in bits.
pub(crate) fn bits_of(a: &BiPoly) -> usize {
    a.iter()
        .flatten()
        .map(|c| c.bits() as usize)
        .max()
        .unwrap_or(1)
}

/// A work estimate, in nanoseconds as [`intersection_work`](super::budget::intersection_work),
/// of one fibre ([`Extension::fibre`]) and the tests of its partners, over an extension of
/// degree `d`, for polynomials of degree `k` in t with coefficients of `bits` bits: about
/// (k + 1)^2 products in Q(alpha), each 2 d^2 rational operations on numbers of about
/// d (bits + d) bits, plus k + 1 inversions of the same order (the partner tests and the
/// Jacobian repeat this a few times: a factor 8 is included).
pub(crate) fn fibre_work(d: usize, k: usize, bits: usize) -> u64 {
    let (d, k, bits) = (d as u64, k as u64, bits as u64);
    let words = d.saturating_mul(bits + d) / 64 + 1;
    let per_op = 200 + 40 * words + 4 * words * words;
    8u64.saturating_mul((k + 2) * (k + 2))
        .saturating_mul(2 * d * d + d)
        .saturating_mul(per_op)
}
