//! Sparse multivariate polynomials with exact rational coefficients, in named variables.
//!
//! [`Poly`] is the symbolic member of the [`Ring`] family. Running an algorithm of the crate
//! over `Poly`, with every input a fresh variable (`c_0_1`, `u`, ...), computes its output as an
//! exact polynomial in those inputs. Because every `Poly` is kept in a *canonical form* (sorted
//! terms, no zero coefficients, no zero exponents, coefficients in lowest terms), two
//! polynomials are equal as polynomials exactly when they are `==`. So `alg_a(x) == alg_b(x)`
//! over `Poly` is a *proof* that the two algorithms agree for every input, not a test at a few
//! sample points.
//!
//! Variable names are interned once in a global table and represented by small integer ids, so
//! arithmetic never touches strings or locks; only [`Poly::var`], the name-based queries and
//! [`Display`](std::fmt::Display) consult the table. The printed form is deterministic and
//! independent of the order in which variables were first created.
//!
//! ```
//! use blossom::{Poly, Ring};
//!
//! let a = Poly::var("a");
//! let b = Poly::var("b");
//! let lhs = (&a + &b).pow(2);
//! let rhs = &a * &a + Poly::from_int(2) * &a * &b + &b * &b;
//! assert_eq!(lhs, rhs);
//! assert_eq!(lhs.to_string(), "a^2 + 2*a*b + b^2");
//! assert!((&a - &a).is_zero());
//! ```

use crate::num::ring::{Rational, Ring};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Signed;
use std::borrow::Borrow;
use std::cmp::Ordering;
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::iter::Peekable;
use std::sync::{OnceLock, PoisonError, RwLock};

/// Rational helpers (the names `zero`/`is_zero` are ambiguous between `num_traits` and
/// [`Ring`], which both implement them for [`Rational`]).
fn q_zero() -> Rational {
    num_traits::Zero::zero()
}
fn q_one() -> Rational {
    num_traits::One::one()
}
fn q_is_zero(c: &Rational) -> bool {
    num_traits::Zero::is_zero(c)
}
fn q_is_one(c: &Rational) -> bool {
    num_traits::One::is_one(c)
}
fn bigint_is_one(n: &BigInt) -> bool {
    num_traits::One::is_one(n)
}

/// `x += c` (or `x -= c`), skipping the gcd when the denominators agree and are `1`.
#[inline]
fn q_add_into(x: &mut Rational, c: &Rational, negate: bool) {
    if x.denom() == c.denom() {
        let (mut n, d) = std::mem::take(x).into_raw();
        if negate {
            n -= c.numer();
        } else {
            n += c.numer();
        }
        *x = if bigint_is_one(&d) {
            Rational::new_raw(n, d)
        } else {
            Rational::new(n, d)
        };
    } else if negate {
        *x -= c;
    } else {
        *x += c;
    }
}

/// Interned variable id.
type VarId = u32;

/// A monomial: `(variable id, exponent)` pairs, sorted by id, every exponent positive.
/// The empty monomial is the constant `1`.
type Mono = Vec<(VarId, u32)>;

/// One term of a polynomial: a monomial and its non-zero coefficient.
type Term = (Mono, Rational);

// ---------------------------------------------------------------------------------------------
// Variable interner
// ---------------------------------------------------------------------------------------------

#[derive(Default)]
struct Interner {
    ids: HashMap<String, VarId>,
    names: Vec<String>,
}

fn interner() -> &'static RwLock<Interner> {
    static INTERNER: OnceLock<RwLock<Interner>> = OnceLock::new();
    INTERNER.get_or_init(|| RwLock::new(Interner::default()))
}

/// The id of `name`, creating it on first use.
fn intern(name: &str) -> VarId {
    if let Some(id) = lookup(name) {
        return id;
    }
    let mut table = interner().write().unwrap_or_else(PoisonError::into_inner);
    if let Some(&id) = table.ids.get(name) {
        return id;
    }
    let id = VarId::try_from(table.names.len()).expect("too many polynomial variables");
    table.names.push(name.to_owned());
    table.ids.insert(name.to_owned(), id);
    id
}

/// The id of `name` if it was ever interned.
fn lookup(name: &str) -> Option<VarId> {
    let table = interner().read().unwrap_or_else(PoisonError::into_inner);
    table.ids.get(name).copied()
}

/// The names of `ids`, in the same order. The lock is released before returning, so callers
/// may run user code (which may create variables) with the result.
fn names_of(ids: &[VarId]) -> Vec<String> {
    let table = interner().read().unwrap_or_else(PoisonError::into_inner);
    ids.iter()
        .map(|&id| table.names[id as usize].clone())
        .collect()
}

// ---------------------------------------------------------------------------------------------
// A fast non-cryptographic hasher for monomials (FxHash).
// ---------------------------------------------------------------------------------------------

#[derive(Default, Clone, Copy)]
struct FxHasher(u64);

const FX_SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl FxHasher {
    #[inline]
    fn mix(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(FX_SEED);
    }
}

impl Hasher for FxHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.mix(u64::from_le_bytes(word));
        }
    }
    #[inline]
    fn write_u32(&mut self, i: u32) {
        self.mix(u64::from(i));
    }
    #[inline]
    fn write_u64(&mut self, i: u64) {
        self.mix(i);
    }
    #[inline]
    fn write_usize(&mut self, i: usize) {
        self.mix(i as u64);
    }
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
}

type FxMap<K, V> = HashMap<K, V, BuildHasherDefault<FxHasher>>;

// ---------------------------------------------------------------------------------------------
// Monomial and term helpers
// ---------------------------------------------------------------------------------------------

/// `out = a * b` (exponents of common variables add).
fn mono_mul_into(a: &[(VarId, u32)], b: &[(VarId, u32)], out: &mut Mono) {
    out.clear();
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            Ordering::Less => {
                out.push(a[i]);
                i += 1;
            }
            Ordering::Greater => {
                out.push(b[j]);
                j += 1;
            }
            Ordering::Equal => {
                let e = a[i].1.checked_add(b[j].1).expect("exponent overflow");
                out.push((a[i].0, e));
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
}

fn mono_degree(m: &[(VarId, u32)]) -> u32 {
    m.iter().map(|&(_, e)| e).sum()
}

/// Merges two sorted term sequences into `a + b` (or `a - b` when `negate_b`), dropping terms
/// that cancel.
fn merge<I, J>(a: I, b: J, negate_b: bool) -> Vec<Term>
where
    I: Iterator<Item = Term>,
    J: Iterator<Item = Term>,
{
    let mut a: Peekable<I> = a.peekable();
    let mut b: Peekable<J> = b.peekable();
    let mut out = Vec::with_capacity(a.size_hint().0 + b.size_hint().0);
    loop {
        let ord = match (a.peek(), b.peek()) {
            (Some(x), Some(y)) => x.0.cmp(&y.0),
            (Some(_), None) => Ordering::Less,
            (None, Some(_)) => Ordering::Greater,
            (None, None) => break,
        };
        match ord {
            Ordering::Less => out.extend(a.next()),
            Ordering::Greater => {
                let (m, c) = b.next().expect("peeked");
                out.push((m, if negate_b { -c } else { c }));
            }
            Ordering::Equal => {
                let (m, mut c) = a.next().expect("peeked");
                let (_, d) = b.next().expect("peeked");
                q_add_into(&mut c, &d, negate_b);
                if !q_is_zero(&c) {
                    out.push((m, c));
                }
            }
        }
    }
    out
}

/// `terms += sign * rhs`, in place: binary search and insert, cheap when `rhs` is much smaller
/// than `terms`.
fn add_in_place(terms: &mut Vec<Term>, rhs: &[Term], negate: bool) {
    for (m, c) in rhs {
        match terms.binary_search_by(|t| t.0.cmp(m)) {
            Ok(k) => {
                q_add_into(&mut terms[k].1, c, negate);
                if q_is_zero(&terms[k].1) {
                    terms.remove(k);
                }
            }
            Err(k) => terms.insert(k, (m.clone(), if negate { -c } else { c.clone() })),
        }
    }
}

/// Builds a canonical polynomial from an accumulation map.
fn from_map(acc: FxMap<Mono, Rational>) -> Poly {
    let mut terms: Vec<Term> = acc.into_iter().filter(|(_, c)| !q_is_zero(c)).collect();
    terms.sort_unstable_by(|x, y| x.0.cmp(&y.0));
    Poly { terms }
}

/// Adds `c * m` into an accumulation map.
#[inline]
fn accumulate(acc: &mut FxMap<Mono, Rational>, m: &[(VarId, u32)], c: Rational) {
    match acc.get_mut(m) {
        Some(x) => q_add_into(x, &c, false),
        None => {
            acc.insert(m.to_vec(), c);
        }
    }
}

/// Display order of named monomials: decreasing total degree, then graded-lexicographic with
/// variables ordered by name (`a^2` before `a*b` before `b^2`).
fn display_cmp(a: &[(String, u32)], b: &[(String, u32)]) -> Ordering {
    let da: u64 = a.iter().map(|&(_, e)| u64::from(e)).sum();
    let db: u64 = b.iter().map(|&(_, e)| u64::from(e)).sum();
    db.cmp(&da).then_with(|| {
        for (x, y) in a.iter().zip(b) {
            let o = x.0.cmp(&y.0).then_with(|| y.1.cmp(&x.1));
            if o != Ordering::Equal {
                return o;
            }
        }
        a.len().cmp(&b.len())
    })
}

// ---------------------------------------------------------------------------------------------
// Poly
// ---------------------------------------------------------------------------------------------

/// A sparse multivariate polynomial with exact [`Rational`] coefficients in named variables.
///
/// The representation is canonical: terms are sorted by monomial, no coefficient is zero, no
/// monomial stores a zero exponent, and coefficients are reduced rationals. Hence the derived
/// `==` (and `Hash`) is *identity of polynomials*, which is what makes `Poly` usable to prove
/// two algorithms equal by running both symbolically.
///
/// Arithmetic is available both through [`Ring`] (by reference: `a.mul(&b)`) and through the
/// std operators on owned values and references (`&a * &b + c`).
///
/// ```
/// use blossom::{Poly, Ring};
///
/// let a = Poly::var("a");
/// let b = Poly::var("b");
/// // (a + b)^2 == a^2 + 2ab + b^2, as polynomials.
/// assert_eq!((&a + &b).pow(2), a.pow(2) + (&a * &b).scale_frac(2, 1) + b.pow(2));
/// // (a + b)(a - b) == a^2 - b^2
/// assert_eq!((&a + &b) * (&a - &b), a.pow(2) - b.pow(2));
/// assert_eq!((&a - &b).scale_frac(3, 2).to_string(), "3/2*a - 3/2*b");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    /// Sorted by monomial (strictly increasing), every coefficient non-zero.
    terms: Vec<Term>,
}

impl Poly {
    /// The polynomial consisting of the single variable `name`.
    ///
    /// Variables are identified by name: `Poly::var("x") == Poly::var("x")`.
    ///
    /// # Panics
    /// If `name` is empty.
    pub fn var(name: &str) -> Poly {
        assert!(
            !name.is_empty(),
            "polynomial variable names must not be empty"
        );
        Poly {
            terms: vec![(vec![(intern(name), 1)], q_one())],
        }
    }

    /// The constant polynomial `k`.
    pub fn constant(k: Rational) -> Poly {
        if q_is_zero(&k) {
            Poly::default()
        } else {
            Poly {
                terms: vec![(Vec::new(), k)],
            }
        }
    }

    /// The single term `coef * Π name^exp`. Repeated names multiply (`x^1 * x^2 = x^3`), zero
    /// exponents are ignored.
    ///
    /// # Panics
    /// If a name with a positive exponent is empty.
    pub fn monomial(coef: Rational, powers: &[(&str, u32)]) -> Poly {
        if q_is_zero(&coef) {
            return Poly::default();
        }
        let mut mono: Mono = Vec::with_capacity(powers.len());
        for &(name, e) in powers {
            if e > 0 {
                assert!(
                    !name.is_empty(),
                    "polynomial variable names must not be empty"
                );
                mono.push((intern(name), e));
            }
        }
        Poly {
            terms: vec![(normalize_mono(mono), coef)],
        }
    }

    /// Number of (non-zero) terms; `0` for the zero polynomial.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The largest total degree of a term; `0` for constants, including the zero polynomial.
    pub fn total_degree(&self) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| mono_degree(m))
            .max()
            .unwrap_or(0)
    }

    /// The largest exponent of `name` in any term (`0` if it does not occur).
    pub fn degree_in(&self, name: &str) -> u32 {
        let Some(id) = lookup(name) else {
            return 0;
        };
        self.terms
            .iter()
            .filter_map(|(m, _)| m.iter().find(|&&(v, _)| v == id).map(|&(_, e)| e))
            .max()
            .unwrap_or(0)
    }

    /// The names of the variables that occur, sorted by name.
    pub fn variables(&self) -> Vec<String> {
        let mut names = names_of(&self.variable_ids());
        names.sort_unstable();
        names
    }

    /// The coefficient of the monomial `Π name^exp` (zero if absent). Repeated names multiply,
    /// zero exponents are ignored; `&[]` asks for the constant term.
    pub fn coefficient(&self, powers: &[(&str, u32)]) -> Rational {
        let mut mono: Mono = Vec::with_capacity(powers.len());
        for &(name, e) in powers {
            if e > 0 {
                match lookup(name) {
                    Some(id) => mono.push((id, e)),
                    None => return q_zero(),
                }
            }
        }
        let mono = normalize_mono(mono);
        match self.terms.binary_search_by(|t| t.0.cmp(&mono)) {
            Ok(k) => self.terms[k].1.clone(),
            Err(_) => q_zero(),
        }
    }

    /// The constant term (the value at the origin).
    pub fn constant_term(&self) -> Rational {
        match self.terms.first() {
            Some((m, c)) if m.is_empty() => c.clone(),
            _ => q_zero(),
        }
    }

    /// Whether no variable occurs (the zero polynomial is constant).
    pub fn is_constant(&self) -> bool {
        self.terms.iter().all(|(m, _)| m.is_empty())
    }

    /// The value of a constant polynomial, `None` if some variable occurs.
    pub fn as_constant(&self) -> Option<Rational> {
        self.is_constant().then(|| self.constant_term())
    }

    /// The terms as `(monomial, coefficient)` with monomials given by variable names (sorted by
    /// name), in the same order as [`Display`](fmt::Display) prints them.
    pub fn terms(&self) -> Vec<(Vec<(String, u32)>, Rational)> {
        let ids = self.variable_ids();
        let names = names_of(&ids);
        let name_of = |id: VarId| -> String {
            let k = ids.binary_search(&id).expect("collected id");
            names[k].clone()
        };
        let mut out: Vec<(Vec<(String, u32)>, Rational)> = self
            .terms
            .iter()
            .map(|(m, c)| {
                let mut named: Vec<(String, u32)> =
                    m.iter().map(|&(id, e)| (name_of(id), e)).collect();
                named.sort_unstable();
                (named, c.clone())
            })
            .collect();
        out.sort_by(|x, y| display_cmp(&x.0, &y.0));
        out
    }

    /// Evaluates in any ring `R`, with `value(name)` giving the value of each variable.
    /// Returns `None` if `value` returns `None` for a variable that occurs.
    ///
    /// `value` is called once per occurring variable, sorted by name. With `R = Poly` this is a
    /// simultaneous substitution of all variables.
    pub fn eval_in<R: Ring>(&self, mut value: impl FnMut(&str) -> Option<R>) -> Option<R> {
        let ids = self.variable_ids();
        let names = names_of(&ids);
        let mut order: Vec<usize> = (0..ids.len()).collect();
        order.sort_by(|&x, &y| names[x].cmp(&names[y]));
        let mut values: Vec<Option<R>> = vec![None; ids.len()];
        for k in order {
            values[k] = Some(value(&names[k])?);
        }
        let mut acc = R::zero();
        for (m, c) in &self.terms {
            let mut t = R::from_rational(c);
            for &(id, e) in m {
                let k = ids.binary_search(&id).expect("collected id");
                let v = values[k].as_ref().expect("all values set");
                t = t.mul(&v.pow(e));
            }
            acc.add_assign(&t);
        }
        Some(acc)
    }

    /// Evaluates at rational values given by `value(name)`; `None` if a variable that occurs
    /// has no value. Accepts closures as well as `&dyn Fn(&str) -> Option<Rational>`.
    pub fn eval(&self, value: impl FnMut(&str) -> Option<Rational>) -> Option<Rational> {
        self.eval_in(value)
    }

    /// Evaluates at the rational values of a map from names; `None` if a variable that occurs
    /// is missing from the map.
    pub fn eval_map<S>(&self, values: &HashMap<S, Rational>) -> Option<Rational>
    where
        S: Borrow<str> + Hash + Eq,
    {
        self.eval_in(|name| values.get(name).cloned())
    }

    /// Replaces the variable `name` by the polynomial `p` (which may itself contain `name`).
    pub fn substitute(&self, name: &str, p: &Poly) -> Poly {
        let Some(id) = lookup(name) else {
            return self.clone();
        };
        // Group the terms by the exponent of `name`, stripping it.
        let mut buckets: BTreeMap<u32, Vec<Term>> = BTreeMap::new();
        for (m, c) in &self.terms {
            match m.iter().position(|&(v, _)| v == id) {
                None => buckets.entry(0).or_default().push((m.clone(), c.clone())),
                Some(k) => {
                    let mut rest = m.clone();
                    let (_, e) = rest.remove(k);
                    buckets.entry(e).or_default().push((rest, c.clone()));
                }
            }
        }
        let mut result = Poly::zero();
        let mut power = Poly::one();
        let mut power_exp = 0u32;
        for (e, mut terms) in buckets {
            terms.sort_unstable_by(|x, y| x.0.cmp(&y.0));
            let part = Poly { terms };
            while power_exp < e {
                power = mul_ref(&power, p);
                power_exp += 1;
            }
            result += mul_ref(&part, &power);
        }
        result
    }

    /// The ids of the occurring variables, sorted and deduplicated.
    fn variable_ids(&self) -> Vec<VarId> {
        let mut ids: Vec<VarId> = self
            .terms
            .iter()
            .flat_map(|(m, _)| m.iter().map(|&(id, _)| id))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        ids
    }

    /// The coefficient if `self` is a non-zero constant.
    fn nonzero_constant(&self) -> Option<&Rational> {
        match self.terms.as_slice() {
            [(m, c)] if m.is_empty() => Some(c),
            _ => None,
        }
    }

    fn scale_ref(&self, k: &Rational) -> Poly {
        if q_is_zero(k) {
            return Poly::default();
        }
        if q_is_one(k) {
            return self.clone();
        }
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), c * k)).collect(),
        }
    }

    fn negate_in_place(&mut self) {
        for (_, c) in &mut self.terms {
            *c = -std::mem::take(c);
        }
    }

    /// `self += sign * rhs` with `rhs` borrowed.
    fn add_assign_ref(&mut self, rhs: &Poly, negate: bool) {
        if rhs.terms.len().saturating_mul(16) <= self.terms.len() {
            add_in_place(&mut self.terms, &rhs.terms, negate);
        } else {
            let lhs = std::mem::take(&mut self.terms);
            self.terms = merge(lhs.into_iter(), rhs.terms.iter().cloned(), negate);
        }
    }

    /// `self += sign * rhs` with `rhs` owned.
    fn add_assign_owned(&mut self, rhs: Poly, negate: bool) {
        if rhs.terms.len().saturating_mul(16) <= self.terms.len() {
            add_in_place(&mut self.terms, &rhs.terms, negate);
        } else {
            let lhs = std::mem::take(&mut self.terms);
            self.terms = merge(lhs.into_iter(), rhs.terms.into_iter(), negate);
        }
    }
}

/// Sorts a monomial by id and merges repeated variables.
fn normalize_mono(mut mono: Mono) -> Mono {
    mono.sort_unstable_by_key(|&(id, _)| id);
    let mut out: Mono = Vec::with_capacity(mono.len());
    for (id, e) in mono {
        match out.last_mut() {
            Some(last) if last.0 == id => {
                last.1 = last.1.checked_add(e).expect("exponent overflow");
            }
            _ => out.push((id, e)),
        }
    }
    out
}

/// The lcm `l` of the denominators of `p` and the integer coefficients `l * c`.
fn integer_coefficients(p: &Poly) -> (BigInt, Vec<BigInt>) {
    let mut l = BigInt::from(1);
    for (_, c) in &p.terms {
        if !bigint_is_one(c.denom()) {
            l = l.lcm(c.denom());
        }
    }
    let ints = if bigint_is_one(&l) {
        p.terms.iter().map(|(_, c)| c.numer().clone()).collect()
    } else {
        p.terms
            .iter()
            .map(|(_, c)| c.numer() * (&l / c.denom()))
            .collect()
    };
    (l, ints)
}

/// The product of two polynomials.
///
/// Both operands are lifted to integer coefficients over a common denominator, so the inner
/// loop only multiplies and adds big integers (no gcd); the products are accumulated in a hash
/// map keyed by monomial and reduced once per output term.
fn mul_ref(a: &Poly, b: &Poly) -> Poly {
    if a.terms.is_empty() || b.terms.is_empty() {
        return Poly::default();
    }
    if let Some(k) = a.nonzero_constant() {
        return b.scale_ref(k);
    }
    if let Some(k) = b.nonzero_constant() {
        return a.scale_ref(k);
    }
    let (outer, inner) = if a.terms.len() <= b.terms.len() {
        (a, b)
    } else {
        (b, a)
    };
    let (l_outer, c_outer) = integer_coefficients(outer);
    let (l_inner, c_inner) = integer_coefficients(inner);
    let cap = outer.terms.len().saturating_mul(inner.terms.len()).min(
        inner
            .terms
            .len()
            .saturating_mul(4)
            .max(outer.terms.len() * 4),
    );
    let mut acc: FxMap<Mono, BigInt> = FxMap::with_capacity_and_hasher(cap, Default::default());
    let mut buf: Mono = Vec::new();
    for ((ma, _), ca) in outer.terms.iter().zip(&c_outer) {
        for ((mb, _), cb) in inner.terms.iter().zip(&c_inner) {
            mono_mul_into(ma, mb, &mut buf);
            let prod = ca * cb;
            match acc.get_mut(buf.as_slice()) {
                Some(x) => *x += prod,
                None => {
                    acc.insert(buf.clone(), prod);
                }
            }
        }
    }
    let den = l_outer * l_inner;
    let den_is_one = bigint_is_one(&den);
    let mut terms: Vec<Term> = acc
        .into_iter()
        .filter(|(_, n)| !num_traits::Zero::is_zero(n))
        .map(|(m, n)| {
            let c = if den_is_one {
                Rational::new_raw(n, den.clone())
            } else {
                Rational::new(n, den.clone())
            };
            (m, c)
        })
        .collect();
    terms.sort_unstable_by(|x, y| x.0.cmp(&y.0));
    Poly { terms }
}

impl Ring for Poly {
    type Coords = Vec<Self>;
    fn zero() -> Self {
        Poly::default()
    }
    fn one() -> Self {
        Poly::constant(q_one())
    }
    fn add(&self, rhs: &Self) -> Self {
        self + rhs
    }
    fn sub(&self, rhs: &Self) -> Self {
        self - rhs
    }
    fn mul(&self, rhs: &Self) -> Self {
        mul_ref(self, rhs)
    }
    fn neg(&self) -> Self {
        -self
    }
    fn scale(&self, k: &Rational) -> Self {
        self.scale_ref(k)
    }
    fn scale_frac(&self, num: i128, den: i128) -> Self {
        assert!(den != 0, "scale_frac with zero denominator");
        self.scale_ref(&Rational::new(BigInt::from(num), BigInt::from(den)))
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    fn add_assign(&mut self, rhs: &Self) {
        self.add_assign_ref(rhs, false);
    }
    fn from_rational(k: &Rational) -> Self {
        Poly::constant(k.clone())
    }
    fn from_int(k: i64) -> Self {
        Poly::constant(Rational::from_integer(BigInt::from(k)))
    }
}

impl From<Rational> for Poly {
    fn from(k: Rational) -> Poly {
        Poly::constant(k)
    }
}

impl From<i64> for Poly {
    fn from(k: i64) -> Poly {
        <Poly as Ring>::from_int(k)
    }
}

// ---------------------------------------------------------------------------------------------
// std operators
// ---------------------------------------------------------------------------------------------

impl std::ops::Add<&Poly> for &Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        Poly {
            terms: merge(self.terms.iter().cloned(), rhs.terms.iter().cloned(), false),
        }
    }
}

impl std::ops::Add<Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: Poly) -> Poly {
        self.add_assign_owned(rhs, false);
        self
    }
}

impl std::ops::Add<&Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: &Poly) -> Poly {
        self.add_assign_ref(rhs, false);
        self
    }
}

impl std::ops::Add<Poly> for &Poly {
    type Output = Poly;
    fn add(self, mut rhs: Poly) -> Poly {
        rhs.add_assign_ref(self, false);
        rhs
    }
}

impl std::ops::Sub<&Poly> for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        Poly {
            terms: merge(self.terms.iter().cloned(), rhs.terms.iter().cloned(), true),
        }
    }
}

impl std::ops::Sub<Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: Poly) -> Poly {
        self.add_assign_owned(rhs, true);
        self
    }
}

impl std::ops::Sub<&Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: &Poly) -> Poly {
        self.add_assign_ref(rhs, true);
        self
    }
}

impl std::ops::Sub<Poly> for &Poly {
    type Output = Poly;
    fn sub(self, mut rhs: Poly) -> Poly {
        // self - rhs = -(rhs - self)
        rhs.add_assign_ref(self, true);
        rhs.negate_in_place();
        rhs
    }
}

impl std::ops::Mul<&Poly> for &Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        mul_ref(self, rhs)
    }
}

impl std::ops::Mul<Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        mul_ref(&self, &rhs)
    }
}

impl std::ops::Mul<&Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        mul_ref(&self, rhs)
    }
}

impl std::ops::Mul<Poly> for &Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        mul_ref(self, &rhs)
    }
}

impl std::ops::Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        self.negate_in_place();
        self
    }
}

impl std::ops::Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }
}

impl std::ops::AddAssign<Poly> for Poly {
    fn add_assign(&mut self, rhs: Poly) {
        self.add_assign_owned(rhs, false);
    }
}

impl std::ops::AddAssign<&Poly> for Poly {
    fn add_assign(&mut self, rhs: &Poly) {
        self.add_assign_ref(rhs, false);
    }
}

impl std::ops::SubAssign<Poly> for Poly {
    fn sub_assign(&mut self, rhs: Poly) {
        self.add_assign_owned(rhs, true);
    }
}

impl std::ops::SubAssign<&Poly> for Poly {
    fn sub_assign(&mut self, rhs: &Poly) {
        self.add_assign_ref(rhs, true);
    }
}

impl std::ops::MulAssign<Poly> for Poly {
    fn mul_assign(&mut self, rhs: Poly) {
        *self = mul_ref(self, &rhs);
    }
}

impl std::ops::MulAssign<&Poly> for Poly {
    fn mul_assign(&mut self, rhs: &Poly) {
        *self = mul_ref(self, rhs);
    }
}

/// Sums many polynomials at once through a hash map (no repeated merging).
impl std::iter::Sum for Poly {
    fn sum<I: Iterator<Item = Poly>>(iter: I) -> Poly {
        let mut acc: FxMap<Mono, Rational> = FxMap::default();
        for p in iter {
            for (m, c) in p.terms {
                match acc.get_mut(&m) {
                    Some(x) => q_add_into(x, &c, false),
                    None => {
                        acc.insert(m, c);
                    }
                }
            }
        }
        from_map(acc)
    }
}

impl<'a> std::iter::Sum<&'a Poly> for Poly {
    fn sum<I: Iterator<Item = &'a Poly>>(iter: I) -> Poly {
        let mut acc: FxMap<Mono, Rational> = FxMap::default();
        for p in iter {
            for (m, c) in &p.terms {
                accumulate(&mut acc, m, c.clone());
            }
        }
        from_map(acc)
    }
}

impl std::iter::Product for Poly {
    fn product<I: Iterator<Item = Poly>>(iter: I) -> Poly {
        iter.fold(Poly::one(), |acc, p| mul_ref(&acc, &p))
    }
}

impl<'a> std::iter::Product<&'a Poly> for Poly {
    fn product<I: Iterator<Item = &'a Poly>>(iter: I) -> Poly {
        iter.fold(Poly::one(), |acc, p| mul_ref(&acc, p))
    }
}

// ---------------------------------------------------------------------------------------------
// Display
// ---------------------------------------------------------------------------------------------

/// Prints e.g. `3/2*a^2*b - c_0 + 1`: terms by decreasing total degree, then
/// graded-lexicographically by variable *name*; variables in a monomial sorted by name;
/// coefficients `±1` omitted except for constants; `0` for the zero polynomial. The output does
/// not depend on the order in which variables were created.
impl fmt::Display for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return f.write_str("0");
        }
        for (i, (mono, c)) in self.terms().into_iter().enumerate() {
            let negative = c.is_negative();
            match (i, negative) {
                (0, true) => f.write_str("-")?,
                (0, false) => {}
                (_, true) => f.write_str(" - ")?,
                (_, false) => f.write_str(" + ")?,
            }
            let abs = c.abs();
            if mono.is_empty() {
                write!(f, "{abs}")?;
                continue;
            }
            if !q_is_one(&abs) {
                write!(f, "{abs}*")?;
            }
            for (k, (name, e)) in mono.iter().enumerate() {
                if k > 0 {
                    f.write_str("*")?;
                }
                f.write_str(name)?;
                if *e != 1 {
                    write!(f, "^{e}")?;
                }
            }
        }
        Ok(())
    }
}

/// Same as [`Display`](fmt::Display).
impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

// ---------------------------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------------------------

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::hash_map::DefaultHasher;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    fn v(name: &str) -> Poly {
        Poly::var(name)
    }

    fn k(n: i64) -> Poly {
        Poly::from_int(n)
    }

    /// Deterministic pseudo-random generator (LCG), no external crates.
    struct Lcg(u64);

    impl Lcg {
        fn next(&mut self) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            self.0 >> 33
        }
        fn below(&mut self, n: u64) -> u64 {
            self.next() % n
        }
    }

    /// A random polynomial in `t_a..t_d` with up to 6 terms, exponents up to 3 and small
    /// fractional coefficients (possibly repeated monomials, which must merge).
    fn random_poly(rng: &mut Lcg) -> Poly {
        let names = ["t_a", "t_b", "t_c", "t_d"];
        let mut p = Poly::zero();
        for _ in 0..rng.below(7) {
            let num = rng.below(11) as i64 - 5;
            let den = rng.below(4) as i64 + 1;
            let mut powers: Vec<(&str, u32)> = Vec::new();
            for &n in &names {
                let e = rng.below(4) as u32;
                if rng.below(2) == 0 {
                    powers.push((n, e));
                }
            }
            p += Poly::monomial(q(num, den), &powers);
        }
        p
    }

    /// Checks the canonical-form invariant directly.
    fn assert_canonical(p: &Poly) {
        for w in p.terms.windows(2) {
            assert!(w[0].0 < w[1].0, "terms not strictly sorted: {p}");
        }
        for (m, c) in &p.terms {
            assert!(!c.is_zero(), "zero coefficient stored: {p}");
            assert!(m.iter().all(|&(_, e)| e > 0), "zero exponent stored");
            assert!(m.windows(2).all(|w| w[0].0 < w[1].0), "monomial not sorted");
        }
    }

    #[test]
    fn ring_axioms_on_random_polynomials() {
        let mut rng = Lcg(0x1234_5678);
        for _ in 0..60 {
            let a = random_poly(&mut rng);
            let b = random_poly(&mut rng);
            let c = random_poly(&mut rng);
            for p in [&a, &b, &c] {
                assert_canonical(p);
            }
            // commutativity
            assert_eq!(a.add(&b), b.add(&a));
            assert_eq!(a.mul(&b), b.mul(&a));
            // associativity
            assert_eq!(a.add(&b).add(&c), a.add(&b.add(&c)));
            assert_eq!(a.mul(&b).mul(&c), a.mul(&b.mul(&c)));
            // distributivity
            assert_eq!(a.mul(&b.add(&c)), a.mul(&b).add(&a.mul(&c)));
            assert_eq!(a.sub(&b).mul(&c), a.mul(&c).sub(&b.mul(&c)));
            // identities and inverses
            assert_eq!(a.add(&Poly::zero()), a);
            assert_eq!(a.mul(&Poly::one()), a);
            assert!(a.mul(&Poly::zero()).is_zero());
            assert!(a.add(&a.neg()).is_zero());
            assert_eq!(a.sub(&b), a.add(&b.neg()));
            assert_eq!(a.pow(3), a.mul(&a).mul(&a));
            assert_canonical(&a.mul(&b).sub(&c));
        }
    }

    #[test]
    fn operator_forms_agree_with_ring_methods() {
        let mut rng = Lcg(99);
        for _ in 0..30 {
            let a = random_poly(&mut rng);
            let b = random_poly(&mut rng);
            let sum = a.add(&b);
            let diff = a.sub(&b);
            let prod = a.mul(&b);
            assert_eq!(&a + &b, sum);
            assert_eq!(a.clone() + b.clone(), sum);
            assert_eq!(a.clone() + &b, sum);
            assert_eq!(&a + b.clone(), sum);
            assert_eq!(&a - &b, diff);
            assert_eq!(a.clone() - b.clone(), diff);
            assert_eq!(a.clone() - &b, diff);
            assert_eq!(&a - b.clone(), diff);
            assert_eq!(&a * &b, prod);
            assert_eq!(a.clone() * b.clone(), prod);
            assert_eq!(a.clone() * &b, prod);
            assert_eq!(&a * b.clone(), prod);
            assert_eq!(-&a, a.neg());
            assert_eq!(-a.clone(), a.neg());
            let mut x = a.clone();
            x += &b;
            assert_eq!(x, sum);
            let mut x = a.clone();
            x += b.clone();
            assert_eq!(x, sum);
            let mut x = a.clone();
            x -= &b;
            assert_eq!(x, diff);
            let mut x = a.clone();
            x -= b.clone();
            assert_eq!(x, diff);
            let mut x = a.clone();
            x *= &b;
            assert_eq!(x, prod);
            let mut x = a.clone();
            Ring::add_assign(&mut x, &b);
            assert_eq!(x, sum);
            assert_eq!([a.clone(), b.clone()].into_iter().sum::<Poly>(), sum);
            assert_eq!([&a, &b].into_iter().sum::<Poly>(), sum);
            assert_eq!([&a, &b].into_iter().product::<Poly>(), prod);
        }
    }

    #[test]
    fn small_addend_fast_path_matches_merge() {
        // A big polynomial plus many single terms exercises the in-place insertion path,
        // including cancellation and insertion at both ends.
        let x = v("fp_x");
        let y = v("fp_y");
        let big = (&x + &y + k(1)).pow(8);
        assert_eq!(big.num_terms(), 45);
        let mut acc = big.clone();
        let mut reference = big.clone();
        let mut rng = Lcg(7);
        for _ in 0..200 {
            let t = Poly::monomial(
                q(rng.below(5) as i64 - 2, 1),
                &[
                    ("fp_x", rng.below(10) as u32),
                    ("fp_y", rng.below(10) as u32),
                ],
            );
            acc += &t;
            reference = Poly {
                terms: merge(reference.terms.into_iter(), t.terms.iter().cloned(), false),
            };
            assert_canonical(&acc);
        }
        assert_eq!(acc, reference);
        acc -= &reference;
        assert!(acc.is_zero());
        // Cancel every term one at a time.
        let mut c = big.clone();
        for (m, coef) in big.terms.iter() {
            c -= &Poly {
                terms: vec![(m.clone(), coef.clone())],
            };
        }
        assert_eq!(c.num_terms(), 0);
    }

    #[test]
    fn canonical_equality() {
        let a = v("a");
        let b = v("b");
        assert_eq!((&a + &b) * (&a - &b), &a * &a - &b * &b);
        let x = v("x");
        let zero = &x - &x;
        assert_eq!(zero.num_terms(), 0);
        assert!(zero.is_zero());
        assert_eq!(zero, Poly::zero());
        assert_eq!(Poly::var("x"), x);
        assert_ne!(a, b);
        // Different construction orders, same polynomial, same hash.
        let p1 = &a * &b + k(2) * &a + k(1);
        let p2 = k(1) + &a + &b * &a + &a;
        assert_eq!(p1, p2);
        let hash = |p: &Poly| {
            let mut h = DefaultHasher::new();
            p.hash(&mut h);
            h.finish()
        };
        assert_eq!(hash(&p1), hash(&p2));
        // Coefficients are stored in lowest terms.
        assert_eq!(a.scale(&q(2, 4)), a.scale(&q(1, 2)));
        // Monomial normalisation: repeated names and zero exponents.
        assert_eq!(
            Poly::monomial(q(1, 1), &[("a", 1), ("b", 0), ("a", 2)]),
            a.pow(3)
        );
        assert_eq!(Poly::monomial(q(0, 1), &[("a", 1)]), Poly::zero());
        assert_eq!(Poly::constant(q(0, 5)).num_terms(), 0);
    }

    #[test]
    fn display_exact_strings() {
        let a = v("a");
        let b = v("b");
        let c0 = v("c_0");
        let p = (&a * &a * &b).scale(&q(3, 2)) - &c0 + k(1);
        assert_eq!(p.to_string(), "3/2*a^2*b - c_0 + 1");
        assert_eq!(format!("{p:?}"), "3/2*a^2*b - c_0 + 1");
        assert_eq!((-v("x")).to_string(), "-x");
        assert_eq!(Poly::zero().to_string(), "0");
        assert_eq!(Poly::one().to_string(), "1");
        assert_eq!(k(-1).to_string(), "-1");
        assert_eq!(Poly::constant(q(-2, 6)).to_string(), "-1/3");
        assert_eq!((k(1) - &a).scale(&q(-3, 4)).to_string(), "3/4*a - 3/4");
        assert_eq!((&a - &b).pow(2).to_string(), "a^2 - 2*a*b + b^2");
        assert_eq!(
            (&b + &a + k(1)).pow(2).to_string(),
            "a^2 + 2*a*b + b^2 + 2*a + 2*b + 1"
        );
        assert_eq!((&a * &b * &b - &a.pow(3)).to_string(), "-a^3 + a*b^2");
    }

    #[test]
    fn display_is_independent_of_interning_order() {
        // Interned in reverse alphabetical order on purpose (names unique to this test).
        let z = v("ord_z");
        let m = v("ord_m");
        let a = v("ord_a");
        let p = &z + &m * &z + &a + &a * &a.pow(2) - &m;
        assert_eq!(
            p.to_string(),
            "ord_a^3 + ord_m*ord_z + ord_a - ord_m + ord_z"
        );
        assert_eq!(p.variables(), vec!["ord_a", "ord_m", "ord_z"]);
        let named = p.terms();
        assert_eq!(
            named[1].0,
            vec![("ord_m".to_string(), 1), ("ord_z".to_string(), 1)]
        );
        assert_eq!(named[3].1, q(-1, 1));
    }

    #[test]
    fn queries() {
        let p = Poly::monomial(q(3, 2), &[("qa", 2), ("qb", 1)]) - v("qc") + k(7);
        assert_eq!(p.num_terms(), 3);
        assert_eq!(p.total_degree(), 3);
        assert_eq!(p.degree_in("qa"), 2);
        assert_eq!(p.degree_in("qc"), 1);
        assert_eq!(p.degree_in("never_interned_name"), 0);
        assert_eq!(p.variables(), vec!["qa", "qb", "qc"]);
        assert_eq!(p.coefficient(&[("qb", 1), ("qa", 2)]), q(3, 2));
        assert_eq!(p.coefficient(&[("qc", 1)]), q(-1, 1));
        assert_eq!(p.coefficient(&[("qa", 1)]), q(0, 1));
        assert_eq!(p.coefficient(&[("never_interned_name", 1)]), q(0, 1));
        assert_eq!(p.coefficient(&[]), q(7, 1));
        assert_eq!(p.constant_term(), q(7, 1));
        assert_eq!((&p - k(7)).constant_term(), q(0, 1));
        assert_eq!(Poly::zero().total_degree(), 0);
        assert!(!p.is_constant());
        assert_eq!(p.as_constant(), None);
        assert_eq!(Poly::constant(q(5, 3)).as_constant(), Some(q(5, 3)));
        assert_eq!(Poly::zero().as_constant(), Some(q(0, 1)));
    }

    #[test]
    fn eval_and_substitute() {
        let a = v("ea");
        let b = v("eb");
        let p = (&a + &b).pow(2).scale(&q(3, 1)) - &a + k(1);
        let values = |name: &str| match name {
            "ea" => Some(q(1, 2)),
            "eb" => Some(q(1, 3)),
            _ => None,
        };
        // 3*(5/6)^2 - 1/2 + 1 = 25/12 + 1/2 = 31/12
        assert_eq!(p.eval(values), Some(q(31, 12)));
        let dyn_values: &dyn Fn(&str) -> Option<Rational> = &values;
        assert_eq!(p.eval(dyn_values), Some(q(31, 12)));
        assert_eq!(p.eval(|n| (n == "ea").then(|| q(1, 1))), None);
        let mut map = HashMap::new();
        map.insert("ea", q(2, 1));
        map.insert("eb", q(-1, 1));
        assert_eq!(p.eval_map(&map), Some(q(3 - 2 + 1, 1)));
        map.remove("eb");
        assert_eq!(p.eval_map(&map), None);
        assert_eq!(k(4).eval(|_| None), Some(q(4, 1)));
        // Evaluation in f64.
        let x: f64 = p
            .eval_in(|n| Some(if n == "ea" { 0.5 } else { 0.25 }))
            .unwrap();
        assert!((x - (3.0 * 0.75f64.powi(2) - 0.5 + 1.0)).abs() < 1e-12);

        // substitute ea := eb + 1 in ea^2  ->  eb^2 + 2 eb + 1
        assert_eq!(
            a.pow(2).substitute("ea", &(&b + k(1))),
            &b * &b + k(2) * &b + k(1)
        );
        // Self-referential: ea := ea + 1 in ea^3 - ea
        let s = (a.pow(3) - &a).substitute("ea", &(&a + k(1)));
        assert_eq!(s, (&a + k(1)).pow(3) - (&a + k(1)));
        // Substituting an absent variable is the identity; substituting a constant evaluates.
        assert_eq!(p.substitute("never_interned_name", &k(3)), p);
        assert_eq!(p.substitute("ez_absent", &k(3)), p);
        let partial = p.substitute("ea", &Poly::constant(q(1, 2)));
        assert_eq!(partial.variables(), vec!["eb"]);
        assert_eq!(
            partial
                .substitute("eb", &Poly::constant(q(1, 3)))
                .as_constant(),
            Some(q(31, 12))
        );
        // Substitution agrees with evaluation at random points.
        let mut rng = Lcg(42);
        for _ in 0..20 {
            let r = random_poly(&mut rng);
            let sub = random_poly(&mut rng);
            let val = |n: &str| Some(q(n.len() as i64 + 1, 3 + n.as_bytes()[2] as i64 % 5));
            let lhs = r.substitute("t_b", &sub).eval(|n| val(n));
            let sub_val = sub.eval(|n| val(n)).unwrap();
            let rhs = r.eval(|n| {
                if n == "t_b" {
                    Some(sub_val.clone())
                } else {
                    val(n)
                }
            });
            assert_eq!(lhs, rhs);
            // eval_in Poly with identity is the identity.
            assert_eq!(r.eval_in(|n| Some(Poly::var(n))), Some(r.clone()));
        }
    }

    #[test]
    fn scaling_by_rationals() {
        let a = v("sa");
        let b = v("sb");
        let p = &a + &b.scale(&q(2, 3)) - k(1);
        assert_eq!(p.scale(&q(3, 2)).to_string(), "3/2*sa + sb - 3/2");
        assert_eq!(p.scale_frac(-3, 2), p.scale(&q(-3, 2)));
        assert_eq!(p.scale_frac(6, 4), p.scale(&q(3, 2)));
        assert!(p.scale(&q(0, 1)).is_zero());
        assert!(p.scale_frac(0, 7).is_zero());
        assert_eq!(p.scale(&q(1, 1)), p);
        assert_eq!(p.scale(&q(-1, 1)), -&p);
        assert_eq!(Poly::from_rational(&q(5, 7)), Poly::constant(q(5, 7)));
        assert_eq!(Poly::from_rational(&q(5, 7)).to_string(), "5/7");
        assert_eq!(&p * &Poly::constant(q(3, 2)), p.scale(&q(3, 2)));
        assert_eq!(Poly::from(q(1, 2)) * k(2), Poly::one());
        assert_eq!(Poly::from(-3i64), k(-3));
    }

    #[test]
    fn binomial_expansion_has_expected_terms() {
        // (x + y + z)^6 has C(8, 2) = 28 terms; the coefficient of x^2 y^2 z^2 is 6!/(2!2!2!).
        let p = (v("bx") + v("by") + v("bz")).pow(6);
        assert_eq!(p.num_terms(), 28);
        assert_eq!(p.total_degree(), 6);
        assert_eq!(p.coefficient(&[("bx", 2), ("by", 2), ("bz", 2)]), q(90, 1));
        assert_eq!(p.eval(|_| Some(q(1, 1))), Some(q(729, 1)));
    }

    /// The use case: de Casteljau's algorithm on a degree-6 triangular patch (28 symbolic
    /// control points, barycentric point given by linear forms in 6 corner variables) equals
    /// the Bernstein closed form, as polynomials.
    #[test]
    fn de_casteljau_on_triangle_equals_bernstein_closed_form() {
        let n = 6usize;
        // barycentric coords as linear forms in 6 corner variables
        let x: Vec<Poly> = (0..6).map(|i| Poly::var(&format!("x{i}"))).collect();
        let u = &x[0] + &x[1].scale_frac(1, 2) + &x[2];
        let v = &x[3] - &x[4].scale_frac(1, 3) + &x[5];
        let w = Poly::one() - &u - &v;
        let mut pts: Vec<Vec<Poly>> = (0..=n)
            .map(|i| {
                (0..=n - i)
                    .map(|j| Poly::var(&format!("c_{i}_{j}")))
                    .collect()
            })
            .collect();
        for level in (1..=n).rev() {
            let mut next = Vec::new();
            for i in 0..level {
                let mut row = Vec::new();
                for j in 0..level - i {
                    let p = &pts[i + 1][j] * &u + &pts[i][j + 1] * &v + &pts[i][j] * &w;
                    row.push(p);
                }
                next.push(row);
            }
            pts = next;
        }
        let dc = pts[0][0].clone();
        // closed form
        let fact = |k: usize| (1..=k as i128).product::<i128>();
        let mut terms = Vec::new();
        for i in 0..=n {
            for j in 0..=n - i {
                let k = n - i - j;
                let coef = fact(n) / (fact(i) * fact(j) * fact(k));
                terms.push(
                    (u.pow(i as u32)
                        * v.pow(j as u32)
                        * w.pow(k as u32)
                        * Poly::var(&format!("c_{i}_{j}")))
                    .scale_frac(coef, 1),
                );
            }
        }
        let cf: Poly = terms.into_iter().sum();
        assert_eq!(dc.num_terms(), 10131);
        assert_eq!(dc.total_degree(), 7);
        assert_eq!(dc, cf);
        // A wrong closed form (two control points swapped) is detected.
        let swapped = cf
            .substitute("c_1_0", &Poly::var("c_swap_tmp"))
            .substitute("c_0_1", &Poly::var("c_1_0"))
            .substitute("c_swap_tmp", &Poly::var("c_0_1"));
        assert_eq!(swapped.num_terms(), cf.num_terms());
        assert_ne!(dc, swapped);
    }
}
