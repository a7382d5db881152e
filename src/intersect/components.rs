//! Curves that share a component (Res_t(A, B) = 0 identically), decided exactly.
//!
//! **Decomposition.** By Lüroth's theorem the field Q(x(s), y(s)) of a polynomial curve P
//! is Q(phi(s)) for a polynomial phi, and P = R(phi) with R a *proper* polynomial curve
//! (one-to-one but for finitely many points). With phi normalised monic and phi(0) = 0 it is
//! unique for its degree k, and every right component h of P (x, y in Q[h]) has
//! phi = g(h) (so deg h divides k). For a divisor k of the true degree n, the only candidate
//! of degree k is the "approximate k-th root" of a coordinate f of degree n (the monic h with
//! deg(f / lc(f) - h^(n/k)) < n - k, found coefficient by coefficient from the top); it is a
//! right component exactly when the h-adic expansions of x and y have constant digits. The
//! largest such k is deg phi. A curve on a line is R linear, phi its position (k = n).
//!
//! **Same curve.** Two proper polynomial parametrisations of one curve differ by an affine
//! change of parameter: Q = R2(psi) with R2(w) = R1(alpha w + beta), alpha, beta rational
//! (unique, so fixed by conjugation); alpha^d is the ratio of leading coefficients and beta
//! follows from the next one, verified by the exact identity of power coefficients. Then
//! P(s) = R(f(s)) and Q(t) = R(g(t)) with f = phi, g = alpha psi + beta.
//!
//! **Answer.** P(s) = Q(t) exactly when f(s) = g(t), or R(f(s)) = R(g(t)) with
//! f(s) != g(t) (R's finitely many double points). The first: f and g are cut at their
//! turning points (roots of f' of odd multiplicity in (0, 1), real algebraic numbers) into
//! monotone pieces; each pair of pieces whose images share a segment of positive length
//! gives one overlap (its ends are the preimages of the common segment's ends, found as the
//! one root in the piece of f(s) - c, or, c algebraic, of Res_v(m_c(v), f(s) - v), whose
//! value is c exactly); images that touch at one value give a tangential point (P' and Q'
//! are both multiples of R' there). The second: the solutions of the divided differences
//! (R(u) - R(v)) / (u - v) composed with u = f(s), v = g(t), which have no common factor (R
//! is proper); their Jacobian is f'(s) g'(t) times R's, which vanishes exactly when
//! cross(P'(s), Q'(t)) does. Solutions with f(s) = g(t) (cusps of R) lie on an overlap or are
//! a touching point, and are dropped or merged.

use super::algebraic::{value_at, AlgebraicReal};
use super::bivariate::{resultant_t, BiPoly};
use super::extension::{add_q, deg_q, divrem_q, mul_q, trim_q};
use super::intersections::Overlap;
use super::solve::{solve, Solution};
use super::upoly::{self, derivative, from_rationals, ZPoly};
use super::zeros::roots_with_multiplicity;
use crate::error::{Error, Result};
use crate::num::ring::Rational;
use crate::shape::basis::{scale_argument, taylor_shift};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// A polynomial curve P = R(phi): R's power coefficients and phi (monic, phi(0) = 0).
#[derive(Clone, Debug)]
pub(crate) struct Decomposed {
    pub rx: Vec<Rational>,
    pub ry: Vec<Rational>,
    pub phi: Vec<Rational>,
}

/// The curve's true degree (at least 1 for a curve that is not a point).
fn true_degree(x: &[Rational], y: &[Rational]) -> usize {
    deg_q(x).unwrap_or(0).max(deg_q(y).unwrap_or(0))
}

/// P = R(phi) with R proper and phi monic with phi(0) = 0 (Lüroth: phi is the right
/// component of largest degree k, the approximate k-th root of a coordinate whose h-adic
/// expansions of x and y have constant digits); P must not be a single point.
pub(crate) fn decompose(x: &[Rational], y: &[Rational]) -> Decomposed {
    let n = true_degree(x, y);
    let f = if deg_q(x) == Some(n) { x } else { y };
    for k in (2..=n).rev().filter(|k| n.is_multiple_of(*k)) {
        let h = approximate_root(f, n, k);
        if let (Some(rx), Some(ry)) = (digits(x, &h), digits(y, &h)) {
            return Decomposed { rx, ry, phi: h };
        }
    }
    Decomposed {
        rx: x.to_vec(),
        ry: y.to_vec(),
        phi: vec![Rational::zero(), Rational::one()],
    }
}

/// The monic h of degree k with h(0) = 0 and deg(f / lc(f) - h^(n / k)) < n - k.
fn approximate_root(f: &[Rational], n: usize, k: usize) -> Vec<Rational> {
    let r = n / k;
    let g: Vec<Rational> = f[..=n].iter().map(|c| c / &f[n]).collect();
    let mut h = vec![Rational::zero(); k + 1];
    h[k] = Rational::one();
    for i in 1..k {
        let p = power(&h, r);
        let c = p.get(n - i).cloned().unwrap_or_default();
        // Raising h_(k-i) by d raises the coefficient of s^(n-i) of h^r by r d.
        h[k - i] = (&g[n - i] - c) / Rational::from_integer(BigInt::from(r));
    }
    h
}

/// p^e over Q.
fn power(p: &[Rational], e: usize) -> Vec<Rational> {
    (0..e).fold(vec![Rational::one()], |acc, _| mul_q(&acc, p))
}

/// The h-adic digits c_j of f = sum c_j h^j when all are constants, else `None`.
fn digits(f: &[Rational], h: &[Rational]) -> Option<Vec<Rational>> {
    let mut g = f.to_vec();
    trim_q(&mut g);
    let mut out = Vec::new();
    while deg_q(&g).is_some() {
        let (q, r) = divrem_q(&g, h);
        if deg_q(&r).unwrap_or(0) > 0 {
            return None;
        }
        out.push(r.first().cloned().unwrap_or_default());
        g = q;
    }
    if out.is_empty() {
        out.push(Rational::zero());
    }
    Some(out)
}

/// The rationals (alpha, beta) with R2(w) = R1(alpha w + beta) for two proper curves given by
/// power coefficients, when they exist.
pub(crate) fn affine_relation(
    r1: (&[Rational], &[Rational]),
    r2: (&[Rational], &[Rational]),
) -> Option<(Rational, Rational)> {
    let d = true_degree(r1.0, r1.1);
    if d != true_degree(r2.0, r2.1) || d == 0 {
        return None;
    }
    let at = |p: &[Rational], i: usize| p.get(i).cloned().unwrap_or_default();
    let (px, py, qx, qy) = (at(r1.0, d), at(r1.1, d), at(r2.0, d), at(r2.1, d));
    // q_d = lambda p_d.
    let lambda = if !px.is_zero() { &qx / &px } else { &qy / &py };
    if px.clone() * &lambda != qx || py.clone() * &lambda != qy {
        return None;
    }
    let dd = Rational::from_integer(BigInt::from(d));
    for alpha in rational_roots_of(&lambda, d) {
        // Coefficient of w^(d-1) of R1(alpha w + beta): alpha^(d-1) (p_(d-1) + d p_d beta).
        let a1 = num_traits::pow(alpha.clone(), d - 1);
        let beta = if !px.is_zero() {
            (at(r2.0, d - 1) / &a1 - at(r1.0, d - 1)) / (&dd * &px)
        } else {
            (at(r2.1, d - 1) / &a1 - at(r1.1, d - 1)) / (&dd * &py)
        };
        let map = |c: &[Rational]| -> Vec<Rational> {
            let mut v: Vec<Vec<Rational>> = c.iter().map(|x| vec![x.clone()]).collect();
            taylor_shift(&mut v, &beta);
            scale_argument(&mut v, &alpha);
            let mut out: Vec<Rational> = v.into_iter().map(|p| p[0].clone()).collect();
            trim_q(&mut out);
            out
        };
        let trimmed = |c: &[Rational]| {
            let mut c = c.to_vec();
            trim_q(&mut c);
            c
        };
        if map(r1.0) == trimmed(r2.0) && map(r1.1) == trimmed(r2.1) {
            return Some((alpha, beta));
        }
    }
    None
}

/// The exact rational d-th roots of a rational (both signs for even d), if any.
fn rational_roots_of(x: &Rational, d: usize) -> Vec<Rational> {
    let root = |n: &BigInt| -> Option<BigInt> {
        let r = n.abs().nth_root(d as u32);
        (num_traits::pow(r.clone(), d) == n.abs()).then_some(r)
    };
    let (Some(rn), Some(rd)) = (root(x.numer()), root(x.denom())) else {
        return Vec::new();
    };
    let r = Rational::new(rn, rd);
    if d.is_multiple_of(2) {
        if x.is_negative() {
            Vec::new()
        } else {
            vec![r.clone(), -r]
        }
    } else if x.is_negative() {
        vec![-r]
    } else {
        vec![r]
    }
}

/// The error of a common component that the decomposition does not explain (impossible by
/// the module docs; reported rather than answered wrongly).
fn unexplained() -> Error {
    Error::new(
        "curves",
        "the curves share a component but their proper parametrisations are not related by \
         an affine change of parameter (an internal inconsistency)",
    )
}

/// The answer for P = R1(phi) and Q = R2(psi) sharing a component, with R2(w) =
/// R1(alpha w + beta) so that P = R(f), Q = R(g): overlaps from the monotone pieces of f and
/// g whose images share a segment, touching points, and R's double points; isolated solutions (tangential flags decided) and overlaps, all pairs in [0, 1]^2.
pub(crate) fn common_component(
    p: (&[Rational], &[Rational]),
    q: (&[Rational], &[Rational]),
) -> Result<(Vec<Solution>, Vec<Overlap>)> {
    let dp = decompose(p.0, p.1);
    let dq = decompose(q.0, q.1);
    let (alpha, beta) =
        affine_relation((&dp.rx, &dp.ry), (&dq.rx, &dq.ry)).ok_or_else(unexplained)?;
    let g = add_q(
        &dq.phi.iter().map(|c| c * &alpha).collect::<Vec<_>>(),
        &[beta],
    );
    shared_answer(&dp, &dp.phi, &g, false)
}

/// The pairs s < t with P(s) = P(t) and the overlaps of a curve whose divided differences
/// share a factor (it retraces itself): P = R(phi) with deg phi > 1.
pub(crate) fn retracing(x: &[Rational], y: &[Rational]) -> Result<(Vec<Solution>, Vec<Overlap>)> {
    let d = decompose(x, y);
    let (mut sols, overlaps) = shared_answer(&d, &d.phi, &d.phi, true)?;
    sols.retain(|s| s.s.compare(&s.t) == Ordering::Less);
    Ok((sols, overlaps))
}

/// The answer for R(f(s)) = R(g(t)); with `same` only piece pairs k < l.
fn shared_answer(
    r: &Decomposed,
    f: &[Rational],
    g: &[Rational],
    same: bool,
) -> Result<(Vec<Solution>, Vec<Overlap>)> {
    let (mut points, overlaps) = monotone_overlaps(f, g, same);
    if true_degree(&r.rx, &r.ry) >= 2 {
        let a = composed_difference(&r.rx, f, g);
        let b = composed_difference(&r.ry, f, g);
        let (zero, one) = (Rational::zero(), Rational::one());
        let sols = solve(&a, &b, (&zero, &one), (&zero, &one)).ok_or_else(unexplained)?;
        for sol in sols {
            if !points
                .iter()
                .any(|p| p.s.equals(&sol.s) && p.t.equals(&sol.t))
            {
                points.push(sol);
            }
        }
    }
    Ok((points, overlaps))
}

/// (c(f(s)) - c(g(t))) / (f(s) - g(t)) for a 1-D polynomial c, scaled to integers: the
/// divided differences sum_k c_k sum_(i + j = k - 1) u^i v^j at u = f(s), v = g(t).
fn composed_difference(c: &[Rational], f: &[Rational], g: &[Rational]) -> BiPoly {
    let n = c.len();
    let fp: Vec<Vec<Rational>> = (0..n).map(|i| power(f, i)).collect();
    let gp: Vec<Vec<Rational>> = (0..n).map(|i| power(g, i)).collect();
    let ds = fp.last().map_or(1, Vec::len);
    let dt = gp.last().map_or(1, Vec::len);
    let mut q: Vec<Vec<Rational>> = vec![vec![Rational::zero(); dt]; ds];
    for (k, ck) in c.iter().enumerate().skip(1) {
        if ck.is_zero() {
            continue;
        }
        for i in 0..k {
            for (a, x) in fp[i].iter().enumerate() {
                for (b, y) in gp[k - 1 - i].iter().enumerate() {
                    q[a][b] += ck * x * y;
                }
            }
        }
    }
    let l = q
        .iter()
        .flatten()
        .fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    q.iter()
        .map(|row| row.iter().map(|c| c.numer() * (&l / c.denom())).collect())
        .collect()
}

/// One monotone piece of a 1-D polynomial: parameter ends and the values there.
struct Piece {
    a: AlgebraicReal,
    b: AlgebraicReal,
    fa: AlgebraicReal,
    fb: AlgebraicReal,
}

/// The monotone pieces of f on [0, 1], cut at the roots of f' of odd multiplicity in (0, 1).
fn pieces(f: &[Rational]) -> Vec<Piece> {
    let (zero, one) = (Rational::zero(), Rational::one());
    let mut cuts = vec![AlgebraicReal::from_rational(zero.clone())];
    let df = derivative(&from_rationals(f));
    if !upoly::is_zero(&df) {
        for r in roots_with_multiplicity(&df, &zero, &one) {
            let end = r.value.exact().is_some_and(|x| x.is_zero() || x.is_one());
            if r.multiplicity % 2 == 1 && !end {
                cuts.push(r.value);
            }
        }
    }
    cuts.push(AlgebraicReal::from_rational(one));
    cuts.windows(2)
        .map(|w| Piece {
            fa: value_at(f, &w[0]),
            fb: value_at(f, &w[1]),
            a: w[0].clone(),
            b: w[1].clone(),
        })
        .collect()
}

/// The parameter in the piece where the monotone f takes the value c (between the piece's
/// values), exactly.
fn preimage(f: &[Rational], piece: &Piece, c: &AlgebraicReal) -> AlgebraicReal {
    if piece.fa.equals(c) {
        return piece.a.clone();
    }
    if piece.fb.equals(c) {
        return piece.b.clone();
    }
    let h = match c.exact() {
        Some(c) => {
            let mut g = f.to_vec();
            g[0] -= c;
            from_rationals(&g)
        }
        None => preimage_polynomial(f, c.polynomial()),
    };
    let (lo, hi) = (piece.a.interval().0, piece.b.interval().1);
    roots_with_multiplicity(&h, lo, hi)
        .into_iter()
        .map(|r| r.value)
        .find(|r| {
            r.compare(&piece.a) == Ordering::Greater
                && r.compare(&piece.b) == Ordering::Less
                && value_at(f, r).equals(c)
        })
        .expect("a monotone piece takes every value between its ends once")
}

/// Res_v(m(v), N(s) - l v) with N = l f integer: its roots are the s with f(s) a root of m.
fn preimage_polynomial(f: &[Rational], m: &[BigInt]) -> ZPoly {
    let l = f.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    let a: BiPoly = vec![m.to_vec()];
    let mut b: BiPoly = f
        .iter()
        .map(|c| vec![c.numer() * (&l / c.denom()), BigInt::zero()])
        .collect();
    b[0][1] = -l;
    resultant_t(&a, &b)
}

/// The lesser and greater of two algebraic numbers.
fn ordered<'a>(
    x: &'a AlgebraicReal,
    y: &'a AlgebraicReal,
) -> (&'a AlgebraicReal, &'a AlgebraicReal) {
    if x.compare(y) == Ordering::Greater {
        (y, x)
    } else {
        (x, y)
    }
}

/// Overlaps and touching points of the monotone pieces of f (for s) and g (for t).
fn monotone_overlaps(f: &[Rational], g: &[Rational], same: bool) -> (Vec<Solution>, Vec<Overlap>) {
    let (pf, pg) = (pieces(f), pieces(g));
    let mut points = Vec::new();
    let mut overlaps = Vec::new();
    for (k, a) in pf.iter().enumerate() {
        for (l, b) in pg.iter().enumerate() {
            if same && l <= k {
                continue;
            }
            let (a_lo, a_hi) = ordered(&a.fa, &a.fb);
            let (b_lo, b_hi) = ordered(&b.fa, &b.fb);
            let lo = if a_lo.compare(b_lo) == Ordering::Less {
                b_lo
            } else {
                a_lo
            };
            let hi = if a_hi.compare(b_hi) == Ordering::Less {
                a_hi
            } else {
                b_hi
            };
            match lo.compare(hi) {
                Ordering::Greater => {}
                Ordering::Equal => points.push(Solution {
                    s: preimage(f, a, lo),
                    t: preimage(g, b, lo),
                    singular: true,
                }),
                Ordering::Less => {
                    // s increases along the piece: its first end has the value nearer fa.
                    let (c0, c1) = if a.fa.compare(&a.fb) == Ordering::Less {
                        (lo, hi)
                    } else {
                        (hi, lo)
                    };
                    overlaps.push(Overlap {
                        s: [preimage(f, a, c0), preimage(f, a, c1)],
                        t: [preimage(g, b, c0), preimage(g, b, c1)],
                    });
                }
            }
        }
    }
    (points, overlaps)
}
