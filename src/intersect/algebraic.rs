//! Real algebraic numbers: a square-free primitive integer polynomial f with an isolating
//! interval, and exact operations on them (refinement, comparison, sign of a polynomial at
//! the number, correctly rounded conversion to `f64`). The invariant and the guarantees are
//! documented on [`AlgebraicReal`], where rustdoc shows them.

use super::bivariate::{resultant_t, BiPoly};
use super::isolate::{bernstein_on, isolate, sign_changes, Isolated};
use super::upoly::{self, degree, gcd, primitive, scaled_value_at, sign_at, ZPoly};
use crate::num::ring::{rational_to_f64, Rational};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// A real algebraic number, **exact**: a square-free primitive integer polynomial f with an
/// isolating interval [lo, hi] holding exactly one of its roots (or the rational number
/// itself). The parameters, values and coordinates of the certified answers (intersections,
/// zeros, boxes, nearest points) are of this type.
///
/// Guarantees: [`compare`](Self::compare), [`equals`](Self::equals),
/// [`cmp_rational`](Self::cmp_rational) and [`sign_of`](Self::sign_of) are decided exactly;
/// [`to_f64`](Self::to_f64) is correctly rounded (ties to even), [`to_f64_down`](Self::to_f64_down)
/// and [`to_f64_up`](Self::to_f64_up) round exactly towards -∞ and +∞; a rational number is
/// always known as one ([`exact`](Self::exact)). `Display` writes a rational exactly (`1/2`)
/// and an irrational number as its correctly rounded double followed by its definition,
/// `0.7071067811865476 (root of 2x^2 - 1 in [lo, hi])`; `{:#}` writes the double alone.
///
/// Limits: none but time and memory: comparing two numbers that are equal costs a gcd of
/// their polynomials; the cost of refinement grows with the degree and the size of the
/// coefficients.
///
/// ```
/// use blossom::{bezier_zeros, AlgebraicReal, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// // 1/sqrt(2), the zero of 2t^2 - 1 in [0, 1] (Bernstein coefficients -1, -1, 1).
/// let root = bezier_zeros(&[q(-1, 1), q(-1, 1), q(1, 1)])?.zeros[0].t.clone();
/// assert_eq!(root.exact(), None);
/// assert_eq!(root.polynomial(), [(-1).into(), 0.into(), 2.into()]);
/// assert_eq!(root.to_f64(), 0.5f64.sqrt());
/// assert!(root.to_f64_down() < root.to_f64_up());
/// assert!(root.compare(&AlgebraicReal::from_rational(q(7, 10))).is_gt());
/// assert!(root.cmp_rational(&q(71, 100)).is_lt());
/// assert!(format!("{root}").starts_with("0.7071067811865476 (root of 2x^2 - 1 in ["));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Method
///
/// Invariant: either the number is the rational r (then `exact` is r, the
/// polynomial is the primitive linear q x - p of r = p / q, and the interval is [r, r]), or it
/// is irrational, lo < hi, f(lo) and f(hi) are non-zero with opposite signs and f has exactly
/// one root in (lo, hi). Rationality is always decided exactly when a number is built:
/// * a factor of degree 1 gives a rational root;
/// * for degree >= 2, a root p/q in lowest terms has q | lc(f) (Gauss), and two distinct
///   rationals with denominators <= L = |lc(f)| differ by at least 1/L^2. So once the interval
///   is shorter than 1/L^2 the only possible rational root is the rational of least
///   denominator in it (found by continued fractions), and one exact evaluation decides.
///   Before that, a cheap sufficient test: a rational root reduces to a root of f modulo every
///   prime l not dividing lc(f), so f without a root modulo some such small prime has no
///   rational root at all.
///
/// Refinement is quadratic interval refinement falling back to bisection, every decision an
/// exact sign (homogeneous Horner at rational points).
/// `to_f64` is correctly rounded (ties to even): refine until both ends round to the same
/// double; when exactly one rounding boundary m (the midpoint of two adjacent doubles) lies
/// between the ends, the sign of f at m tells the side (m itself would be a rational root,
/// already detected).
#[derive(Clone, Debug)]
pub struct AlgebraicReal {
    poly: ZPoly,
    lo: Rational,
    hi: Rational,
    exact: Option<Rational>,
    /// log2 of the number of parts the next refinement step guesses among (see
    /// [`AlgebraicReal::refine`]).
    parts_log2: u32,
}

/// log2 of the number of parts the first secant guess of [`AlgebraicReal::refine`] chooses
/// among.
const FIRST_PARTS_LOG2: u32 = 2;

/// The most bits one refinement step gains: beyond this a step's guess costs more than the
/// callers' widths need.
const MAX_PARTS_LOG2: u32 = 1 << 14;

/// Small primes for the modular test of rational roots.
const SMALL_PRIMES: [u64; 30] = [
    3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127,
];

impl AlgebraicReal {
    /// The rational number `r`.
    pub fn from_rational(r: Rational) -> Self {
        let poly = vec![-r.numer().clone(), r.denom().clone()];
        AlgebraicReal {
            poly,
            lo: r.clone(),
            hi: r.clone(),
            exact: Some(r),
            parts_log2: FIRST_PARTS_LOG2,
        }
    }

    /// The root of the square-free integer polynomial `f` isolated by `iso` (from
    /// [`isolate`](super::isolate::isolate) on `f` or on a multiple of `f`, provided the root
    /// is a root of `f`). Decides rationality exactly.
    pub(crate) fn from_isolated(f: &[BigInt], iso: &Isolated) -> Self {
        if iso.exact {
            return Self::from_rational(iso.lo.clone());
        }
        let mut a = Self::unsettled(primitive(f), iso.lo.clone(), iso.hi.clone());
        a.settle_rationality();
        a
    }

    /// The root of the primitive square-free `poly` in (lo, hi), whose rationality is not
    /// decided yet (the caller decides it, or knows it irrational).
    fn unsettled(poly: ZPoly, lo: Rational, hi: Rational) -> Self {
        AlgebraicReal {
            poly,
            lo,
            hi,
            exact: None,
            parts_log2: FIRST_PARTS_LOG2,
        }
    }

    /// The rational of least denominator in the isolating interval, when it is a root of the
    /// polynomial (the only rational root the interval can hold once it is shorter than
    /// 1 / lc^2; see the type's docs).
    fn simplest_root(&self) -> Option<Rational> {
        let c = simplest_between(&self.lo, &self.hi);
        (sign_at(&self.poly, &c) == Ordering::Equal).then_some(c)
    }

    /// The root of the square-free integer polynomial `f` isolated by `iso` when a short
    /// search finds it rational: an exact hit of the isolation, or the rational of least
    /// denominator in the interval, tried every 8 of at most [`QUICK_BISECTIONS`] bisections.
    /// `None` proves nothing. Callers divide the rational roots so found out of `f` before
    /// settling the other roots, whose irrationality the modular test then proves quickly
    /// (a polynomial with a rational root has a root modulo every prime).
    pub(crate) fn quick_rational_root(f: &[BigInt], iso: &Isolated) -> Option<Rational> {
        if iso.exact {
            return Some(iso.lo.clone());
        }
        let mut a = Self::unsettled(primitive(f), iso.lo.clone(), iso.hi.clone());
        for step in 0..=QUICK_BISECTIONS {
            if let Some(r) = &a.exact {
                return Some(r.clone());
            }
            if step % 8 == 0 {
                if let Some(c) = a.simplest_root() {
                    return Some(c);
                }
            }
            a.bisect();
        }
        None
    }

    /// The one root of the square-free integer polynomial `f` in the interval [lo, hi] of
    /// doubles, when cheap exact tests prove it, else `None` (the caller then isolates the
    /// roots of `f` from scratch). Proved: lo == hi is a root; or f(lo), f(hi) are non-zero
    /// and the Bernstein coefficients of f over [lo, hi] have exactly one sign change
    /// (Descartes' rule: exactly one root, counted with multiplicity, in (lo, hi)).
    /// Rationality is settled only by the cheap tests of the type's docs (degree 1, no root
    /// modulo a small prime, the simplest rational in the interval is a root): when they do
    /// not decide, the answer is `None` rather than a long refinement.
    pub(crate) fn from_double_enclosure(f: &[BigInt], lo: f64, hi: f64) -> Option<Self> {
        let (lo, hi) = (exact_f64(lo), exact_f64(hi));
        if lo == hi {
            return (sign_at(f, &lo) == Ordering::Equal).then(|| Self::from_rational(lo));
        }
        let (at_lo, at_hi) = (sign_at(f, &lo), sign_at(f, &hi));
        if at_lo == Ordering::Equal || at_hi == Ordering::Equal || at_lo == at_hi {
            return None;
        }
        if sign_changes(&bernstein_on(f, &lo, &hi)) != 1 {
            return None;
        }
        let poly = primitive(f);
        let d = degree(&poly)?;
        if d == 1 {
            return Some(Self::from_rational(Rational::new(
                -poly[0].clone(),
                poly[1].clone(),
            )));
        }
        let lead = poly[d].abs();
        let a = Self::unsettled(poly, lo, hi);
        if let Some(c) = a.simplest_root() {
            return Some(Self::from_rational(c));
        }
        no_root_modulo_small_prime(&a.poly, &lead).then_some(a)
    }

    /// The square-free primitive integer polynomial (ascending powers) vanishing at the number.
    pub fn polynomial(&self) -> &[BigInt] {
        &self.poly
    }

    /// The isolating interval [lo, hi] (lo == hi exactly when the number is rational).
    pub fn interval(&self) -> (&Rational, &Rational) {
        (&self.lo, &self.hi)
    }

    /// The number itself when it is rational.
    pub fn exact(&self) -> Option<&Rational> {
        self.exact.as_ref()
    }

    /// The width hi - lo of the isolating interval.
    pub fn width(&self) -> Rational {
        &self.hi - &self.lo
    }

    /// Shrinks the isolating interval to at most half its width (no-op for a rational
    /// number), by quadratic interval refinement (J. Abbott, "Quadratic interval refinement
    /// for real roots", 2006): the secant through (lo, f(lo)) and (hi, f(hi)) guesses which of
    /// N = 2^k equal parts of the interval holds the root, and two exact signs confirm the
    /// guess. Near a simple root the secant's error is quadratic in the width, so confirmed
    /// guesses square N (the number of correct bits doubles per step); a wrong guess halves k
    /// and falls back to a bisection. Every decision is an exact sign; the secant only chooses
    /// where to look.
    pub fn refine(&mut self) {
        if self.exact.is_some() {
            return;
        }
        let k = self.parts_log2;
        if k >= 2 {
            if self.secant_step(k) {
                self.parts_log2 = k.saturating_mul(2).min(MAX_PARTS_LOG2);
                return;
            }
            if self.exact.is_some() {
                return;
            }
            self.parts_log2 = k / 2;
        } else {
            self.parts_log2 = FIRST_PARTS_LOG2;
        }
        self.bisect();
    }

    /// Halves the isolating interval by one bisection (no-op for a rational number): for
    /// loops with a fixed budget of steps, where the growing steps of
    /// [`refine`](Self::refine) would cost more than a cheap test is worth.
    pub fn bisect(&mut self) {
        if self.exact.is_some() {
            return;
        }
        let m = (&self.lo + &self.hi) / Rational::from_integer(2.into());
        match sign_at(&self.poly, &m) {
            Ordering::Equal => *self = Self::from_rational(m),
            s if s == sign_at(&self.poly, &self.lo) => self.lo = m,
            _ => self.hi = m,
        }
    }

    /// One guess of [`refine`](Self::refine) among 2^k parts: true when the interval is now
    /// one part wide (or the number turned out rational); false when the guess was wrong (the
    /// interval may still have shrunk).
    fn secant_step(&mut self, k: u32) -> bool {
        let deg = degree(&self.poly).expect("an irrational number's polynomial") as u32;
        let (fl, fh) = (
            scaled_value_at(&self.poly, &self.lo),
            scaled_value_at(&self.poly, &self.hi),
        );
        // f(lo) = fl / dl^deg and f(hi) = fh / dh^deg have opposite signs, so the secant
        // meets zero at lo + (hi - lo) x with x = |fl dh^deg| / (|fl dh^deg| + |fh dl^deg|);
        // the part is j = round(N x), from k + 64 leading bits of both terms.
        let left_sign = fl.sign();
        let mut u = fl.abs() * self.hi.denom().pow(deg);
        let mut v = fh.abs() * self.lo.denom().pow(deg);
        let keep = u64::from(k) + 64;
        let shift = u.bits().max(v.bits()).saturating_sub(keep);
        u >>= shift;
        v >>= shift;
        let parts = BigInt::one() << k;
        let sum = &u + &v;
        if sum.is_zero() {
            return false;
        }
        let j: BigInt = (&parts * &u * 2 + &sum) / (&sum * 2);
        let j = j.clamp(BigInt::one(), &parts - 1);
        let width = (&self.hi - &self.lo) / Rational::from_integer(parts.clone());
        let m = &self.lo + &width * Rational::from_integer(j.clone());
        let at_m = scaled_value_at(&self.poly, &m).sign();
        if at_m == num_bigint::Sign::NoSign {
            *self = Self::from_rational(m);
            return true;
        }
        // The neighbour of m on the side of the root, and whether it is the interval's end.
        let right = at_m == left_sign;
        let (next, at_end) = if right {
            (&m + &width, &j + 1 == parts)
        } else {
            (&m - &width, j.is_one())
        };
        let at_next = if at_end {
            -at_m
        } else {
            scaled_value_at(&self.poly, &next).sign()
        };
        if at_next == num_bigint::Sign::NoSign {
            *self = Self::from_rational(next);
            return true;
        }
        let confirmed = at_next != at_m;
        match (right, confirmed) {
            (true, true) => (self.lo, self.hi) = (m, next),
            (false, true) => (self.lo, self.hi) = (next, m),
            (true, false) => self.lo = next,
            (false, false) => self.hi = next,
        }
        confirmed
    }

    /// Refines until the interval is no wider than `width`.
    pub fn refine_to(&mut self, width: &Rational) {
        while self.exact.is_none() && &self.width() > width {
            self.refine();
        }
    }

    /// Decides whether the (irrational-so-far) number is rational; see the type's docs.
    fn settle_rationality(&mut self) {
        let d = degree(&self.poly).unwrap_or(0);
        if d == 1 {
            let r = Rational::new(-self.poly[0].clone(), self.poly[1].clone());
            *self = Self::from_rational(r);
            return;
        }
        let lead = self.poly[d].abs();
        if no_root_modulo_small_prime(&self.poly, &lead) {
            return;
        }
        let bound = Rational::new(BigInt::one(), &lead * &lead);
        let mut step = 0u32;
        loop {
            if self.exact.is_some() {
                return;
            }
            let done = self.width() < bound;
            if done || step.is_multiple_of(8) {
                if let Some(c) = self.simplest_root() {
                    *self = Self::from_rational(c);
                    return;
                }
            }
            if done {
                return;
            }
            self.refine();
            step += 1;
        }
    }

    /// Exact comparison with a rational, without refinement.
    pub fn cmp_rational(&self, c: &Rational) -> Ordering {
        if let Some(r) = &self.exact {
            return r.cmp(c);
        }
        if c <= &self.lo {
            return Ordering::Greater;
        }
        if c >= &self.hi {
            return Ordering::Less;
        }
        let sc = sign_at(&self.poly, c);
        if sc == Ordering::Equal {
            return Ordering::Equal;
        }
        if sc == sign_at(&self.poly, &self.lo) {
            // The sign change is in (c, hi).
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }

    /// Whether the number is a root of the integer polynomial `h` (exactly: it is a root of
    /// gcd(f, h), which changes sign over the isolating interval).
    pub fn is_root_of(&self, h: &[BigInt]) -> bool {
        if let Some(r) = &self.exact {
            return sign_at(h, r) == Ordering::Equal;
        }
        if upoly::is_zero(h) {
            return true;
        }
        let g = gcd(&self.poly, h);
        if degree(&g).unwrap_or(0) == 0 {
            return false;
        }
        sign_at(&g, &self.lo) != sign_at(&g, &self.hi)
    }

    /// The sign of h at the number, exactly (refines `self` as needed).
    pub fn sign_of(&mut self, h: &[BigInt]) -> Ordering {
        if let Some(r) = &self.exact {
            return sign_at(h, r);
        }
        if self.is_root_of(h) {
            return Ordering::Equal;
        }
        loop {
            if let Some(r) = &self.exact {
                return sign_at(h, r);
            }
            let b = bernstein_on(h, &self.lo, &self.hi);
            if sign_changes(&b) == 0 {
                let s = b.iter().find(|x| !x.is_zero()).map(|x| x.sign());
                return match s {
                    Some(num_bigint::Sign::Minus) => Ordering::Less,
                    _ => Ordering::Greater,
                };
            }
            self.refine();
        }
    }

    /// Exact equality (both isolate the same root of the gcd of their polynomials).
    pub fn equals(&self, other: &Self) -> bool {
        match (&self.exact, &other.exact) {
            (Some(a), Some(b)) => a == b,
            (Some(a), None) => other.cmp_rational(a) == Ordering::Equal,
            (None, Some(b)) => self.cmp_rational(b) == Ordering::Equal,
            (None, None) => {
                if self.hi <= other.lo || other.hi <= self.lo {
                    return false;
                }
                let g = gcd(&self.poly, &other.poly);
                if degree(&g).unwrap_or(0) == 0 || !self.is_root_of(&g) || !other.is_root_of(&g) {
                    return false;
                }
                // Both are roots of g, which has one root only in self's interval.
                other.cmp_rational(&self.lo) == Ordering::Greater
                    && other.cmp_rational(&self.hi) == Ordering::Less
            }
        }
    }

    /// Exact comparison (refines copies until the intervals are disjoint; two equal numbers
    /// are recognised by the gcd of their polynomials, not by refinement).
    ///
    /// ```
    /// use blossom::{bezier_zeros, Rational};
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// // The zeros of 2t^2 - 1 and of 4t^2 - 2 (Bernstein coefficients), both 1/sqrt(2).
    /// let a = bezier_zeros(&[q(-1), q(-1), q(1)])?.zeros[0].t.clone();
    /// let b = bezier_zeros(&[q(-2), q(-2), q(2)])?.zeros[0].t.clone();
    /// assert!(a.compare(&b).is_eq() && a.equals(&b));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn compare(&self, other: &Self) -> Ordering {
        if let Some(b) = &other.exact {
            return self.cmp_rational(b);
        }
        if let Some(a) = &self.exact {
            return other.cmp_rational(a).reverse();
        }
        if self.equals(other) {
            return Ordering::Equal;
        }
        let (mut a, mut b) = (self.clone(), other.clone());
        loop {
            if let Some(r) = b.exact.clone() {
                return a.cmp_rational(&r);
            }
            if let Some(r) = a.exact.clone() {
                return b.cmp_rational(&r).reverse();
            }
            if a.hi <= b.lo {
                return Ordering::Less;
            }
            if b.hi <= a.lo {
                return Ordering::Greater;
            }
            a.refine();
            b.refine();
        }
    }

    /// The double nearest to the number (ties to even), **correctly rounded**: the interval
    /// is refined until both ends round alike, or the one rounding boundary between them is
    /// decided by an exact sign.
    ///
    /// ```
    /// use blossom::{AlgebraicReal, Rational};
    /// let third = AlgebraicReal::from_rational(Rational::new(1.into(), 3.into()));
    /// assert_eq!(third.to_f64(), 1.0 / 3.0);
    /// ```
    pub fn to_f64(&self) -> f64 {
        let mut a = self.clone();
        loop {
            if let Some(r) = &a.exact {
                return rational_to_f64(r);
            }
            match rounding_decision(&a.lo, &a.hi) {
                Rounding::Same(x) => return x,
                Rounding::Boundary(below, m, above) => {
                    // m is not a root (the number is irrational), so the sign decides.
                    return match a.cmp_rational(&m) {
                        Ordering::Less => below,
                        Ordering::Greater => above,
                        Ordering::Equal => rational_to_f64(&m),
                    };
                }
                Rounding::Wide => a.refine(),
            }
        }
    }

    /// The largest double not above the number (rounding toward -∞), exactly; -∞ below the
    /// range of doubles.
    pub fn to_f64_down(&self) -> f64 {
        self.directed(Direction::Down)
    }

    /// The smallest double not below the number (rounding toward +∞), exactly; +∞ above the
    /// range of doubles.
    pub fn to_f64_up(&self) -> f64 {
        self.directed(Direction::Up)
    }

    /// Directed rounding: the ends of the isolating interval are rounded the same way; when
    /// they differ by one double, that double d is the only rounding boundary in between, and
    /// the exact comparison with d decides (the number is irrational when not exact, so it is
    /// not d).
    fn directed(&self, direction: Direction) -> f64 {
        let mut a = self.clone();
        loop {
            if let Some(r) = &a.exact {
                return round_rational(r, direction);
            }
            let (x, y) = (
                round_rational(&a.lo, direction),
                round_rational(&a.hi, direction),
            );
            if x == y {
                return x;
            }
            if x.is_finite() && y.is_finite() && next_up(x) == y {
                return match direction {
                    Direction::Down if a.cmp_rational(&exact_f64(y)) == Ordering::Less => x,
                    Direction::Down => y,
                    Direction::Up if a.cmp_rational(&exact_f64(x)) == Ordering::Greater => y,
                    Direction::Up => x,
                };
            }
            a.refine();
        }
    }
}

/// A direction of rounding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Direction {
    /// Toward -∞.
    Down,
    /// Toward +∞.
    Up,
}

/// The rational `r` rounded to a double in `direction`, exactly.
fn round_rational(r: &Rational, direction: Direction) -> f64 {
    let x = rational_to_f64(r);
    if !x.is_finite() {
        // Beyond the largest double: the largest finite double on the side toward zero.
        return match (direction, x > 0.0) {
            (Direction::Down, true) => f64::MAX,
            (Direction::Up, false) => f64::MIN,
            _ => x,
        };
    }
    match (direction, exact_f64(x).cmp(r)) {
        (Direction::Down, Ordering::Greater) => -next_up(-x),
        (Direction::Up, Ordering::Less) => next_up(x),
        _ => x,
    }
}

/// What the rounding of the numbers in [lo, hi] looks like.
pub(crate) enum Rounding {
    /// Every number in [lo, hi] rounds to this double.
    Same(f64),
    /// Exactly one rounding boundary m lies in [lo, hi]: numbers below round to the first
    /// double, numbers above to the last, m itself to even.
    Boundary(f64, Rational, f64),
    /// More than one boundary: refine.
    Wide,
}

/// The rounding situation of the interval [lo, hi] (lo <= hi).
pub(crate) fn rounding_decision(lo: &Rational, hi: &Rational) -> Rounding {
    let a = rational_to_f64(lo);
    let b = rational_to_f64(hi);
    if a == b {
        return Rounding::Same(a);
    }
    if !a.is_finite() || !b.is_finite() {
        return Rounding::Wide;
    }
    let next = next_up(a);
    if next != b {
        return Rounding::Wide;
    }
    let m = (exact_f64(a) + exact_f64(b)) / Rational::from_integer(2.into());
    Rounding::Boundary(a, m, b)
}

/// The exact rational value of a finite double.
pub(crate) fn exact_f64(x: f64) -> Rational {
    Rational::from_float(x).expect("finite double")
}

/// The next double above a finite `x`.
fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// The bisections of [`AlgebraicReal::quick_rational_root`].
const QUICK_BISECTIONS: u32 = 48;

/// The rational of least denominator in the closed interval [x, y] (x <= y) (the least
/// numerator in absolute value among those, so 0 when the interval holds it).
///
/// The continued fractions of x and y are expanded together while their partial quotients
/// agree, on integer numerators and denominators: with 0 < x = a / b <= y = c / d, either
/// ceil(x) <= y and ceil(x) is the last quotient, or both share q = floor(x) and the answer is
/// q + 1 / (the simplest rational in [1 / (y - q), 1 / (x - q)]). The answer is the
/// convergent of the quotients so found, already in lowest terms. Each step is one integer
/// division on shrinking numbers, so the whole costs O(L^2) word operations for L-bit
/// ends (ends of thousands of bits occur when an algebraic number's rationality is settled).
pub fn simplest_between(x: &Rational, y: &Rational) -> Rational {
    if !x.is_positive() && !y.is_negative() {
        return Rational::zero();
    }
    if y.is_negative() {
        return -simplest_between(&-y, &-x);
    }
    // 0 < x <= y: x = a / b, y = c / d in lowest terms with positive denominators.
    let (mut a, mut b) = (x.numer().clone(), x.denom().clone());
    let (mut c, mut d) = (y.numer().clone(), y.denom().clone());
    let mut quotients = Vec::new();
    loop {
        let (q, r) = a.div_rem(&b);
        if r.is_zero() {
            // x is the integer q: it is the simplest in the interval.
            quotients.push(q);
            break;
        }
        let up = &q + 1u32;
        if &up * &d <= c {
            quotients.push(up);
            break;
        }
        // floor(y) = q as well: recurse on [1 / (y - q), 1 / (x - q)] = [d / (c - q d), b / r].
        let rest = &c - &q * &d;
        quotients.push(q);
        (a, b, c, d) = (d, rest, b, r);
    }
    // The convergent h / k of [q0; q1, ..., qk].
    let (mut h, mut h_prev) = (BigInt::one(), BigInt::zero());
    let (mut k, mut k_prev) = (BigInt::zero(), BigInt::one());
    for q in &quotients {
        (h, h_prev) = (q * &h + &h_prev, h);
        (k, k_prev) = (q * &k + &k_prev, k);
    }
    Rational::new_raw(h, k)
}

/// True when f (non-zero) provably has no rational root: some prime l < 130 not dividing its
/// leading coefficient leaves it without a root modulo l (see [`AlgebraicReal`]'s docs).
pub(crate) fn has_no_rational_root(f: &[BigInt]) -> bool {
    match f.iter().rposition(|c| !c.is_zero()) {
        Some(d) => no_root_modulo_small_prime(&f[..=d], &f[d]),
        None => false,
    }
}

/// True when some prime l < 130 not dividing `lead` leaves f without a root modulo l, which
/// proves that f has no rational root.
fn no_root_modulo_small_prime(f: &[BigInt], lead: &BigInt) -> bool {
    SMALL_PRIMES.iter().any(|&l| {
        let lb = BigInt::from(l);
        if (lead % &lb).is_zero() {
            return false;
        }
        let c: Vec<u64> = f
            .iter()
            .map(|x| x.mod_floor(&lb).to_u64().expect("a residue fits"))
            .collect();
        (0..l).all(|x| c.iter().rev().fold(0u64, |acc, ci| (acc * x + ci) % l) != 0)
    })
}

/// A positive integer multiple of p - c for a rational polynomial p and a rational c
/// (ascending): same zeros and same signs.
pub(crate) fn shifted_poly(p: &[Rational], c: &Rational) -> ZPoly {
    let mut q: Vec<Rational> = p.to_vec();
    if q.is_empty() {
        q.push(Rational::zero());
    }
    q[0] -= c;
    upoly::positive_multiple(&q)
}

/// Encloses p([lo, hi]) for a rational polynomial p (ascending) by interval Horner, run on
/// integers ([`enclose_scaled`] on the numerators over the common denominator c): the same
/// interval as Horner on fractions (every intermediate is a positive multiple of the
/// fraction one), with two reductions in all instead of four per coefficient.
pub(crate) fn enclose(p: &[Rational], lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    let (numerators, c) = over_common_denominator(p);
    let n = p.len().saturating_sub(1);
    let (l, h) = enclose_scaled(&numerators, n, lo, hi);
    let d = lo.denom().lcm(hi.denom());
    let den = num_traits::pow(d, n) * c;
    (Rational::new(l, den.clone()), Rational::new(h, den))
}

/// The integer numerators N and the positive common denominator c of a rational polynomial:
/// p = N / c.
pub(crate) fn over_common_denominator(p: &[Rational]) -> (ZPoly, BigInt) {
    let c = p.iter().fold(BigInt::one(), |c, x| c.lcm(x.denom()));
    let n = p.iter().map(|x| x.numer() * (&c / x.denom())).collect();
    (n, c)
}

/// Encloses p([lo, hi]) for an integer polynomial p (ascending) of degree <= n without
/// fractions: with D the lcm of the ends' denominators, x = X / D for X in the integer interval
/// [D lo, D hi], and D^n p(X / D) = sum c_i X^i D^(n - i) is enclosed by interval Horner over
/// the integers. Returns (l, h) with l <= D^n p(x) <= h for every x in [lo, hi]; two calls with
/// the same ends and the same n share the positive factor D^n.
pub(crate) fn enclose_scaled(
    p: &[BigInt],
    n: usize,
    lo: &Rational,
    hi: &Rational,
) -> (BigInt, BigInt) {
    debug_assert!(p.len() <= n + 1 && lo <= hi);
    let d = lo.denom().lcm(hi.denom());
    let a = lo.numer() * (&d / lo.denom());
    let b = hi.numer() * (&d / hi.denom());
    let (mut l, mut h) = (BigInt::zero(), BigInt::zero());
    let mut dpow = BigInt::one();
    for i in (0..=n).rev() {
        let ends = a.bits().max(b.bits());
        crate::num::meter::charge_integer_products(2, l.bits().max(h.bits()), ends);
        crate::num::meter::charge_integer_products(1, dpow.bits(), ends);
        (l, h) = interval_product(&l, &h, &a, &b);
        if let Some(c) = p.get(i) {
            if !c.is_zero() {
                let term = c * &dpow;
                l += &term;
                h += &term;
            }
        }
        if i > 0 {
            dpow *= &d;
        }
    }
    (l, h)
}

/// [l, h] * [a, b] for integer intervals (l <= h, a <= b): two products unless both
/// intervals hold zero inside.
fn interval_product(l: &BigInt, h: &BigInt, a: &BigInt, b: &BigInt) -> (BigInt, BigInt) {
    if l.is_zero() && h.is_zero() {
        return (BigInt::zero(), BigInt::zero());
    }
    let (l_pos, h_neg) = (!l.is_negative(), !h.is_positive());
    if !a.is_negative() {
        if l_pos {
            (l * a, h * b)
        } else if h_neg {
            (l * b, h * a)
        } else {
            (l * b, h * b)
        }
    } else if !b.is_positive() {
        if l_pos {
            (h * a, l * b)
        } else if h_neg {
            (h * b, l * a)
        } else {
            (h * a, l * a)
        }
    } else if l_pos {
        (h * a, h * b)
    } else if h_neg {
        (l * b, l * a)
    } else {
        ((l * b).min(h * a), (l * a).max(h * b))
    }
}

/// The value p(alpha) of a rational polynomial at an algebraic number, correctly rounded to a
/// double (ties to even), exactly.
pub fn round_polynomial_at(p: &[Rational], alpha: &AlgebraicReal) -> f64 {
    let mut a = alpha.clone();
    loop {
        if let Some(r) = &a.exact {
            return rational_to_f64(&upoly_eval_q(p, r));
        }
        let (lo, hi) = enclose(p, &a.lo, &a.hi);
        match rounding_decision(&lo, &hi) {
            Rounding::Same(x) => return x,
            Rounding::Boundary(below, m, above) => {
                return match a.sign_of(&shifted_poly(p, &m)) {
                    Ordering::Less => below,
                    Ordering::Greater => above,
                    Ordering::Equal => rational_to_f64(&m),
                };
            }
            Rounding::Wide => a.refine(),
        }
    }
}

/// p(r) for a rational polynomial (ascending) at a rational.
pub(crate) fn upoly_eval_q(p: &[Rational], r: &Rational) -> Rational {
    p.iter().rev().fold(Rational::zero(), |acc, c| acc * r + c)
}

/// The value p(alpha) of a rational polynomial (ascending) at an algebraic number, as an
/// algebraic number, exactly. With N = c p an integer polynomial (c > 0) and f the polynomial
/// of alpha, v = p(alpha) is a root of R(v) = Res_t(f(t), c v - N(t)), which is not zero (the
/// second argument is of degree 1 in v with a constant leading coefficient); v is isolated
/// among the roots of the square-free part of R by interval Horner enclosures of p over
/// alpha's interval, refined until exactly one root of R lies in the enclosure.
pub fn value_at(p: &[Rational], alpha: &AlgebraicReal) -> AlgebraicReal {
    if let Some(r) = &alpha.exact {
        return AlgebraicReal::from_rational(upoly_eval_q(p, r));
    }
    let (n, scale) = over_common_denominator(p);
    if degree(&n).unwrap_or(0) == 0 {
        return AlgebraicReal::from_rational(upoly_eval_q(p, &Rational::zero()));
    }
    // A(v, t) = f(t) and B(v, t) = c v - N(t), as a[i][j] = coefficient of v^i t^j.
    let a: BiPoly = vec![alpha.poly.clone()];
    let mut linear = vec![BigInt::zero(); n.len()];
    linear[0] = scale;
    let b: BiPoly = vec![n.iter().map(|x| -x).collect(), linear];
    let r = upoly::square_free_part(&resultant_t(&a, &b));
    let mut t = alpha.clone();
    loop {
        if t.exact.is_some() {
            return value_at(p, &t);
        }
        let (lo, hi) = enclose(p, &t.lo, &t.hi);
        if lo == hi {
            return AlgebraicReal::from_rational(lo);
        }
        if let [one] = isolate(&r, &lo, &hi).as_slice() {
            return AlgebraicReal::from_isolated(&r, one);
        }
        t.refine();
    }
}

#[cfg(test)]
mod tests {
    use super::{simplest_between, AlgebraicReal};
    use crate::intersect::isolate::Isolated;
    use crate::intersect::upoly::sign_at;
    use crate::num::ring::Rational;
    use num_bigint::BigInt;
    use std::cmp::Ordering;

    fn ints(c: &[i64]) -> Vec<BigInt> {
        c.iter().map(|&x| BigInt::from(x)).collect()
    }

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    /// Every refinement keeps one sign change of f across the interval and at least halves
    /// it; near a simple root the steps converge quadratically, so 2^-2000 is reached in far
    /// fewer steps than the 2000 bisections would take.
    #[test]
    fn refinement_halves_keeps_the_root_and_converges_quadratically() {
        let cases: [(&[i64], Rational, Rational); 4] = [
            (&[-2, 0, 1], q(1, 1), q(2, 1)),
            // Roots 1/3 +- sqrt(2) / 3000: (3x - 1)^2 - 2 / 10^6, scaled to integers.
            (&[999_998, -6_000_000, 9_000_000], q(1, 3), q(1, 2)),
            (&[-1, -1, 0, 0, 0, 1], q(1, 1), q(2, 1)),
            (&[-7, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3], q(1, 1), q(2, 1)),
        ];
        for (poly, lo, hi) in cases {
            let f = ints(poly);
            let iso = Isolated {
                lo: lo.clone(),
                hi: hi.clone(),
                exact: false,
            };
            let mut x = AlgebraicReal::from_isolated(&f, &iso);
            assert!(x.exact().is_none(), "{poly:?}");
            let target = q(1, 1) / Rational::from_integer(BigInt::from(1) << 2000);
            let mut steps = 0;
            while x.width() > target {
                let before = x.width();
                x.refine();
                steps += 1;
                let (lo, hi) = x.interval();
                let (sl, sh) = (sign_at(&f, lo), sign_at(&f, hi));
                assert!(
                    sl != Ordering::Equal && sh != Ordering::Equal && sl != sh,
                    "{poly:?}"
                );
                assert!(x.width() * q(2, 1) <= before, "{poly:?}: step {steps}");
                assert!(steps < 60, "{poly:?}: {steps} steps, width {}", x.width());
            }
        }
    }

    /// By search: the least denominator k with an integer in [k x, k y], and the integer of
    /// least absolute value there.
    fn simplest_by_search(x: &Rational, y: &Rational) -> Rational {
        (1i64..)
            .find_map(|k| {
                let k = Rational::from_integer(k.into());
                let (lo, hi) = ((x * &k).ceil(), (y * &k).floor());
                (lo <= hi).then(|| {
                    let zero = Rational::from_integer(0.into());
                    let n = if lo > zero {
                        lo
                    } else if hi < zero {
                        hi
                    } else {
                        zero
                    };
                    n / k
                })
            })
            .unwrap()
    }

    #[test]
    fn simplest_between_is_the_least_denominator_in_the_interval() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % m) as i64
        };
        for _ in 0..3000 {
            let x = Rational::new((next(401) - 200).into(), (next(60) + 1).into());
            let y = &x + Rational::new(next(30).into(), (next(500) + 1).into());
            assert_eq!(
                simplest_between(&x, &y),
                simplest_by_search(&x, &y),
                "[{x}, {y}]"
            );
        }
        // Ends of thousands of bits, one apart in the last place: the convergent is exact.
        let big = num_bigint::BigInt::from(3).pow(2000);
        let x = Rational::new(big.clone() * 7 + 1, big.clone() * 5);
        let y = Rational::new(big.clone() * 7 + 2, big * 5);
        let c = simplest_between(&x, &y);
        assert!(x <= c && c <= y);
    }
}
