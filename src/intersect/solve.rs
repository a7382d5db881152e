//! The real solutions (s, t) in a box [s0, s1] x [t0, t1] of a system A(s, t) = B(s, t) = 0 of
//! two integer polynomials whose leading coefficients in s and in t are non-zero constants
//! (so no solution escapes to infinity), each solution with the exact decision whether its
//! intersection multiplicity exceeds one (the Jacobian det d(A, B)/d(s, t) vanishes there).
//!
//! Method:
//! 1. R(s) = Res_t(A, B) and R2(t) = Res_s(A, B); R = 0 identically exactly when A and B
//!    share a factor (the caller's overlap case, answered `None`).
//! 2. The roots of R in a box side widened by 1 on both ends, with multiplicities (Yun) and
//!    open neighbourhoods holding no other root; the same for R2. Every solution's s is a
//!    root of R and its t a root of R2.
//! 3. Partners of a root s_i of R: when the first subresultant's leading coefficient
//!    S_11(s_i) is non-zero, gcd_t(A(s_i, t), B(s_i, t)) = S_1(s_i, t) is linear, so there is
//!    exactly one common t, t = -S_10(s_i) / S_11(s_i), a root of R2: refining s_i until the
//!    interval value of that quotient lies in one root's neighbourhood (or misses the box)
//!    names it exactly. When s_i is rational, the gcd over the rationals is computed and each
//!    root t_j of R2 is tested for being its root. The same from the side of t, when some
//!    in-box s_i is left unplaced (else every solution is already listed). A root s_i
//!    left over (S_11 vanishes at an irrational s_i) gets its **fibre**: the square-free gcd
//!    G of A(s_i, t) and B(s_i, t) over the real algebraic extension Q(s_i) (see
//!    `extension`: dynamic evaluation over Q[x]/(m) with m = gcd(f, S_11), f the polynomial
//!    of s_i), and the roots t_j not already placed from their own side are tested for being
//!    roots of G exactly (a sign change of gcd(G, f_(t_j)) over t_j's interval); a cheap
//!    interval exclusion (A or B provably non-zero on the box of the two intervals) is tried
//!    first. So every pair is decided.
//! 4. Multiplicity: the order of R at s_i is the sum of the intersection multiplicities of
//!    the solutions with that s (constant leading coefficients: no solution at infinity).
//!    With exactly one common t (a linear gcd, or a fibre of degree one) that sum is the
//!    pair's multiplicity, which is 1 exactly when the Jacobian is non-zero. Otherwise the
//!    side of t is used, else the Jacobian J is tested exactly: at a rational coordinate by a
//!    gcd over the rationals, else by the same fibre test of J(s_i, t) over Q(s_i) at t_j.

use super::algebraic::{enclose_scaled, AlgebraicReal};
use super::bivariate::{coefficient_t, degree_t, resultant_t, subresultant_1, swap, BiPoly};
use super::extension::Extension;
use super::upoly::{self, degree, gcd, ZPoly};
use super::zeros::{roots_with_multiplicity, RootInfo};
use crate::num::ring::Rational;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// One solution: indices into the s roots and t roots, and whether it is tangential.
#[derive(Clone, Debug)]
pub(crate) struct Solution {
    pub s: AlgebraicReal,
    pub t: AlgebraicReal,
    pub singular: bool,
}

/// How the partners of one root were found.
#[derive(Clone, Debug)]
enum Partners {
    /// All partners in the box are known; `single` when exactly one common root exists at all.
    Known { list: Vec<usize>, single: bool },
    /// Not decided from this side.
    Unresolved,
}

/// The roots of one side and their partner lists.
struct Side {
    roots: Vec<RootInfo>,
    in_box: Vec<bool>,
    partners: Vec<Partners>,
}

/// The solutions in the box, or `None` when A and B share a factor (R = 0 identically).
pub(crate) fn solve(
    a: &BiPoly,
    b: &BiPoly,
    s_box: (&Rational, &Rational),
    t_box: (&Rational, &Rational),
) -> Option<Vec<Solution>> {
    let r = resultant_t(a, b);
    if upoly::is_zero(&r) {
        return None;
    }
    let (sa, sb) = (swap(a), swap(b));
    let r2 = resultant_t(&sa, &sb);
    let mut s_side = side(&r, s_box);
    let mut t_side = side(&r2, t_box);
    let sub = subresultant_1(a, b);
    find_partners(&mut s_side, &t_side, a, b, sub.as_ref(), t_box);
    // When every in-box s root has its complete list, every solution in the box is listed
    // and the side of t could add nothing: its `single` flags only shorten the tangency
    // decision, which the exact Jacobian test below makes without them.
    let s_side_complete = (0..s_side.roots.len())
        .all(|i| !s_side.in_box[i] || matches!(s_side.partners[i], Partners::Known { .. }));
    if !s_side_complete {
        let sub2 = subresultant_1(&sa, &sb);
        find_partners(&mut t_side, &s_side, &sa, &sb, sub2.as_ref(), s_box);
    }
    fibre_partners(&mut s_side, &t_side, a, b, sub.as_ref());
    // Pairs: the union of both sides' findings.
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for (i, p) in s_side.partners.iter().enumerate() {
        if let Partners::Known { list, .. } = p {
            pairs.extend(list.iter().map(|&j| (i, j)));
        }
    }
    for (j, p) in t_side.partners.iter().enumerate() {
        if let Partners::Known { list, .. } = p {
            pairs.extend(list.iter().map(|&i| (i, j)));
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    let jac = jacobian(a, b);
    let mut out = Vec::with_capacity(pairs.len());
    for (i, j) in pairs {
        let (si, tj) = (&s_side.roots[i], &t_side.roots[j]);
        let singular = match (&s_side.partners[i], &t_side.partners[j]) {
            (Partners::Known { single: true, .. }, _) => si.multiplicity >= 2,
            (_, Partners::Known { single: true, .. }) => tj.multiplicity >= 2,
            _ => {
                if let Some(s0) = si.value.exact() {
                    tj.value.is_root_of(&at_rational(&jac, s0))
                } else if let Some(t0) = tj.value.exact() {
                    si.value.is_root_of(&at_rational(&swap(&jac), t0))
                } else {
                    let mut ext = Extension::new(&si.value, si.value.polynomial());
                    let j_alpha = ext.specialise(&jac);
                    ext.vanishes_at(&j_alpha, &tj.value)
                }
            }
        };
        out.push(Solution {
            s: si.value.clone(),
            t: tj.value.clone(),
            singular,
        });
    }
    Some(out)
}

/// Step 3 of the module docs for the in-box roots of the s side that neither side placed:
/// the fibre over Q(s_i), and the exact test of every in-box t root not placed from its side.
fn fibre_partners(
    s_side: &mut Side,
    t_side: &Side,
    a: &BiPoly,
    b: &BiPoly,
    sub: Option<&(ZPoly, ZPoly)>,
) {
    for i in 0..s_side.roots.len() {
        if !s_side.in_box[i] || !matches!(s_side.partners[i], Partners::Unresolved) {
            continue;
        }
        let alpha = &s_side.roots[i].value;
        let candidates: Vec<usize> = (0..t_side.roots.len())
            .filter(|&j| {
                t_side.in_box[j]
                    && matches!(t_side.partners[j], Partners::Unresolved)
                    && !excluded(a, b, alpha, &t_side.roots[j].value)
            })
            .collect();
        // The smallest known factor of f vanishing at alpha: S_11 vanishes there.
        let m = match sub {
            Some((s11, _)) if !upoly::is_zero(s11) => gcd(alpha.polynomial(), s11),
            _ => alpha.polynomial().to_vec(),
        };
        let mut ext = Extension::new(alpha, &m);
        let g = ext.fibre(a, b);
        let list = candidates
            .into_iter()
            .filter(|&j| ext.vanishes_at(&g, &t_side.roots[j].value))
            .collect();
        s_side.partners[i] = Partners::Known {
            list,
            single: g.len() == 2,
        };
    }
}

/// The roots of `r` in the widened box side, with in-box flags.
fn side(r: &[BigInt], range: (&Rational, &Rational)) -> Side {
    let one = Rational::one();
    let roots = roots_with_multiplicity(r, &(range.0 - &one), &(range.1 + &one));
    let in_box = roots
        .iter()
        .map(|x| {
            x.value.cmp_rational(range.0) != Ordering::Less
                && x.value.cmp_rational(range.1) != Ordering::Greater
        })
        .collect();
    let partners = vec![Partners::Unresolved; roots.len()];
    Side {
        roots,
        in_box,
        partners,
    }
}

/// Fills `this.partners` for every in-box root (see step 3 of the module docs).
fn find_partners(
    this: &mut Side,
    other: &Side,
    a: &BiPoly,
    b: &BiPoly,
    sub: Option<&(ZPoly, ZPoly)>,
    other_box: (&Rational, &Rational),
) {
    for i in 0..this.roots.len() {
        if !this.in_box[i] {
            continue;
        }
        let value = &this.roots[i].value;
        if let Some((s11, s10)) = sub {
            if !value.is_root_of(s11) {
                let j = locate_quotient(value, s10, s11, other, other_box);
                this.partners[i] = Partners::Known {
                    list: j.into_iter().collect(),
                    single: true,
                };
                continue;
            }
        }
        if let Some(s0) = value.exact() {
            let h = gcd(&at_rational(a, s0), &at_rational(b, s0));
            let list = (0..other.roots.len())
                .filter(|&j| other.in_box[j] && other.roots[j].value.is_root_of(&h))
                .collect();
            this.partners[i] = Partners::Known {
                list,
                single: degree(&h) == Some(1),
            };
        }
    }
}

/// The in-box root of `other` equal to -n(x)/d(x) at the algebraic x (d(x) != 0 and the
/// quotient is a root of `other`'s polynomial), or `None` when the quotient is outside the box.
/// The quotient is enclosed by integer interval Horner ([`enclose_scaled`]: n and d share the
/// positive scale, which cancels) and compared with rationals by cross-multiplication, so no
/// fraction is ever reduced.
fn locate_quotient(
    x: &AlgebraicReal,
    n: &[BigInt],
    d: &[BigInt],
    other: &Side,
    other_box: (&Rational, &Rational),
) -> Option<usize> {
    let mut x = x.clone();
    let deg = n.len().max(d.len()).saturating_sub(1);
    // a / b < c / e for b, e > 0.
    let less = |a: &BigInt, b: &BigInt, c: &BigInt, e: &BigInt| a * e < c * b;
    loop {
        let (lo, hi) = x.interval();
        let (nl, nh) = enclose_scaled(n, deg, lo, hi);
        let (dl, dh) = enclose_scaled(d, deg, lo, hi);
        if dl.is_positive() || dh.is_negative() {
            // q = m / e with e in [el, eh], el > 0, and m in [ml, mh].
            let (ml, mh, el, eh) = if dl.is_positive() {
                (-nh, -nl, dl, dh)
            } else {
                (nl, nh, -dh, -dl)
            };
            let (ql, ql_den) = if ml.is_negative() {
                (ml, &el)
            } else {
                (ml, &eh)
            };
            let (qh, qh_den) = if mh.is_negative() {
                (mh, &eh)
            } else {
                (mh, &el)
            };
            let (b0, b1) = other_box;
            if less(&qh, qh_den, b0.numer(), b0.denom())
                || less(b1.numer(), b1.denom(), &ql, ql_den)
            {
                return None;
            }
            for (j, root) in other.roots.iter().enumerate() {
                let (r0, r1) = &root.nbhd;
                if less(r0.numer(), r0.denom(), &ql, ql_den)
                    && less(&qh, qh_den, r1.numer(), r1.denom())
                {
                    return other.in_box[j].then_some(j);
                }
            }
        }
        x.refine();
    }
}

/// Integer coefficients as rationals.
fn to_rationals(p: &[BigInt]) -> Vec<Rational> {
    p.iter()
        .map(|c| Rational::from_integer(c.clone()))
        .collect()
}

/// A(s0, t) for a rational s0, as an integer polynomial in t (a positive multiple).
pub(crate) fn at_rational(a: &BiPoly, s0: &Rational) -> ZPoly {
    let dt = degree_t(a).unwrap_or(0);
    let coeffs: Vec<Rational> = (0..=dt)
        .map(|j| super::algebraic::upoly_eval_q(&to_rationals(&coefficient_t(a, j)), s0))
        .collect();
    upoly::positive_multiple(&coeffs)
}

/// The Jacobian A_s B_t - A_t B_s.
fn jacobian(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let ds = |p: &BiPoly| -> BiPoly {
        p.iter()
            .enumerate()
            .skip(1)
            .map(|(i, row)| row.iter().map(|c| c * BigInt::from(i)).collect())
            .collect()
    };
    let dt = |p: &BiPoly| swap(&ds(&swap(p)));
    sub_bi(&mul_bi(&ds(a), &dt(b)), &mul_bi(&dt(a), &ds(b)))
}

/// The product of two bivariate polynomials.
fn mul_bi(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let ns = a.len() + b.len();
    let nt = a.iter().map(Vec::len).max().unwrap_or(0) + b.iter().map(Vec::len).max().unwrap_or(0);
    let mut out = vec![vec![BigInt::zero(); nt]; ns];
    for (i, ra) in a.iter().enumerate() {
        for (j, x) in ra.iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            for (k, rb) in b.iter().enumerate() {
                for (l, y) in rb.iter().enumerate() {
                    out[i + k][j + l] += x * y;
                }
            }
        }
    }
    out
}

/// The difference of two bivariate polynomials.
fn sub_bi(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let ns = a.len().max(b.len());
    let nt = a.iter().chain(b.iter()).map(Vec::len).max().unwrap_or(0);
    let mut out = vec![vec![BigInt::zero(); nt]; ns];
    for (i, row) in a.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            out[i][j] += x;
        }
    }
    for (i, row) in b.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            out[i][j] -= x;
        }
    }
    out
}

/// The refinements (halvings of both intervals) of the interval exclusion test.
const EXCLUSION_ROUNDS: usize = 24;

/// Encloses a bivariate polynomial over the box of the two numbers' intervals.
fn enclose_bi(a: &BiPoly, s: &AlgebraicReal, t: &AlgebraicReal) -> (Rational, Rational) {
    let (sl, sh) = s.interval();
    let (tl, th) = t.interval();
    let dt = degree_t(a).unwrap_or(0);
    // Horner in t over intervals of the coefficients' enclosures.
    let mut lo = Rational::zero();
    let mut hi = Rational::zero();
    for j in (0..=dt).rev() {
        let (cl, ch) = super::algebraic::enclose(&to_rationals(&coefficient_t(a, j)), sl, sh);
        let products = [&lo * tl, &lo * th, &hi * tl, &hi * th];
        lo = products.iter().min().expect("four").clone() + cl;
        hi = products.iter().max().expect("four").clone() + ch;
    }
    (lo, hi)
}

/// Whether interval values prove that (s, t) solves A = B = 0 nowhere, trying a few
/// refinements (a cheap test before the exact one).
fn excluded(a: &BiPoly, b: &BiPoly, s: &AlgebraicReal, t: &AlgebraicReal) -> bool {
    let (mut s, mut t) = (s.clone(), t.clone());
    let zero = Rational::zero();
    for _ in 0..EXCLUSION_ROUNDS {
        for p in [a, b] {
            let (lo, hi) = enclose_bi(p, &s, &t);
            if lo > zero || hi < zero {
                return true;
            }
        }
        if s.exact().is_some() && t.exact().is_some() {
            return false;
        }
        s.bisect();
        t.bisect();
    }
    false
}
