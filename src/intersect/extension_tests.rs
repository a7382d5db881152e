//! Tests of the arithmetic in Q(alpha) by dynamic evaluation and of the fibre. The expected
//! values are built by hand: products of known factors, so the gcds and the roots are known
//! without the code under test.

use super::algebraic::AlgebraicReal;
use super::bivariate::BiPoly;
use super::extension::{Elem, Extension};
use super::zeros::roots_with_multiplicity;
use crate::num::ring::Rational;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

fn z(v: &[i64]) -> Vec<BigInt> {
    v.iter().map(|&c| BigInt::from(c)).collect()
}

fn qv(v: &[i64]) -> Vec<Rational> {
    v.iter()
        .map(|&c| Rational::from_integer(c.into()))
        .collect()
}

/// The real roots of an integer polynomial in [-10, 10], increasing.
fn roots(p: &[i64]) -> Vec<AlgebraicReal> {
    let (lo, hi) = (
        Rational::from_integer((-10).into()),
        Rational::from_integer(10.into()),
    );
    roots_with_multiplicity(&z(p), &lo, &hi)
        .into_iter()
        .map(|r| r.value)
        .collect()
}

/// A bivariate integer polynomial from (i, j, c) terms c s^i t^j.
fn bi(terms: &[(usize, usize, i64)]) -> BiPoly {
    let ns = terms.iter().map(|t| t.0).max().unwrap() + 1;
    let nt = terms.iter().map(|t| t.1).max().unwrap() + 1;
    let mut a = vec![vec![BigInt::zero(); nt]; ns];
    for &(i, j, c) in terms {
        a[i][j] += BigInt::from(c);
    }
    a
}

/// The product of two bivariate polynomials.
fn bi_mul(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let nt = a[0].len() + b[0].len() - 1;
    let mut out = vec![vec![BigInt::zero(); nt]; a.len() + b.len() - 1];
    for (i, ra) in a.iter().enumerate() {
        for (j, x) in ra.iter().enumerate() {
            for (k, rb) in b.iter().enumerate() {
                for (l, y) in rb.iter().enumerate() {
                    out[i + k][j + l] += x * y;
                }
            }
        }
    }
    out
}

/// (x^2 - 2)(x^2 - 3) = x^4 - 5 x^2 + 6: square-free and reducible.
const M23: [i64; 5] = [6, 0, -5, 0, 1];

#[test]
fn zero_divisors_split_the_modulus_toward_alpha() {
    // alpha = sqrt(2): x^2 - 2 is zero in Q(alpha), and the modulus becomes x^2 - 2.
    let sqrt2 = roots(&[-2, 0, 1]).pop().unwrap();
    let mut ext = Extension::new(&sqrt2, &z(&M23));
    assert_eq!(ext.degree(), 4);
    assert!(ext.is_zero(&qv(&[-2, 0, 1])));
    assert_eq!(ext.splits(), 1);
    assert_eq!(ext.modulus(), qv(&[-2, 0, 1]).as_slice());
    // Now the field is Q(sqrt 2): x^2 reduces to 2.
    assert_eq!(ext.mul(&qv(&[0, 1]), &qv(&[0, 1])), qv(&[2]));

    // alpha = sqrt(3): x^2 - 2 is a zero divisor modulo m but not zero at alpha; its inverse
    // is 1 (x^2 - 2 = 3 - 2 = 1 at sqrt 3) once the modulus is split to x^2 - 3.
    let sqrt3 = roots(&[-3, 0, 1]).pop().unwrap();
    let mut ext = Extension::new(&sqrt3, &z(&M23));
    assert!(!ext.is_zero(&qv(&[-2, 0, 1])));
    assert_eq!(ext.modulus(), qv(&[-3, 0, 1]).as_slice());
    let mut fresh = Extension::new(&sqrt3, &z(&M23));
    let inv = fresh.inverse(&qv(&[-2, 0, 1])).unwrap();
    assert_eq!(fresh.splits(), 1);
    assert_eq!(inv, qv(&[1]));
    // x + 1 at -sqrt(3) with the same modulus: an honest inverse, no split needed:
    // 1 / (1 - sqrt 3) = -(1 + sqrt 3) / 2, represented modulo m of degree 4.
    let minus_sqrt3 = roots(&[-3, 0, 1]).remove(0);
    let mut ext = Extension::new(&minus_sqrt3, &z(&M23));
    let inv = ext.inverse(&qv(&[1, 1])).unwrap();
    assert_eq!(ext.splits(), 0);
    let one = ext.mul(&inv, &qv(&[1, 1]));
    assert_eq!(one, qv(&[1]));
    // Both 1 - sqrt 3 and its inverse are negative; 2 inv + 1 = -sqrt 3 < 0 too, and
    // 2 inv - x + 1 = 0 (inv = (x - 1) / 2 at x = -sqrt 3).
    assert_eq!(ext.sign(&inv), Ordering::Less);
    assert_eq!(ext.sign(&qv(&[1, 1])), Ordering::Less);
    let twice = ext.mul(&inv, &qv(&[2]));
    assert!(ext.is_zero(&ext.sub(&twice, &qv(&[-1, 1]))));
    assert!(ext.inverse(&qv(&[-3, 0, 1])).is_none());
    assert_eq!(ext.modulus(), qv(&[-3, 0, 1]).as_slice());
}

#[test]
fn gcd_over_the_extension_matches_the_planted_factor() {
    // alpha = sqrt 2 + sqrt 3, a root of x^4 - 10 x^2 + 1 (irreducible), with the reducible
    // modulus (x^4 - 10 x^2 + 1)(x^2 - 2) = x^6 - 12 x^4 + 21 x^2 - 2.
    let m = [-2, 0, 21, 0, -12, 0, 1];
    let alphas = roots(&[1, 0, -10, 0, 1]);
    let alpha = alphas.last().unwrap().clone();
    assert!((alpha.to_f64() - (2f64.sqrt() + 3f64.sqrt())).abs() < 1e-15);
    // The common factor C = t^2 - s t + 1 times cofactors t + s^2 and t - 2 s + 1.
    let c = bi(&[(0, 2, 1), (1, 1, -1), (0, 0, 1)]);
    let a = bi_mul(&c, &bi(&[(0, 1, 1), (2, 0, 1)]));
    let b = bi_mul(&c, &bi(&[(0, 1, 1), (1, 0, -2), (0, 0, 1)]));
    let mut ext = Extension::new(&alpha, &z(&m));
    let g = ext.fibre(&a, &b);
    // Monic t^2 - alpha t + 1: coefficients 1, -x, 1 (reduced modulo the final modulus).
    let want: Vec<Elem> = vec![qv(&[1]), qv(&[0, -1]), qv(&[1])];
    assert_eq!(g, want);
    // Its real roots (alpha -+ sqrt(alpha^2 - 4)) / 2 are among the real roots of the norm
    // N(t) = prod over the conjugates a of alpha of (t^2 - a t + 1), an integer polynomial
    // whose other real roots are partners of the conjugates of alpha, not of alpha.
    let norm = norm_of_quadratic();
    let candidates = roots(&norm);
    let exact_partners: Vec<f64> = {
        let a = 2f64.sqrt() + 3f64.sqrt();
        let d = (a * a - 4.0).sqrt();
        vec![(a - d) / 2.0, (a + d) / 2.0]
    };
    let mut found = Vec::new();
    for beta in &candidates {
        if ext.vanishes_at(&g, beta) {
            found.push(beta.to_f64());
        }
    }
    assert_eq!(
        found.len(),
        2,
        "{found:?} of {} candidates",
        candidates.len()
    );
    for (x, y) in found.iter().zip(&exact_partners) {
        assert!((x - y).abs() < 1e-12, "{x} vs {y}");
    }
}

/// The norm prod_(a conjugate of sqrt 2 + sqrt 3) (t^2 - a t + 1), an integer polynomial:
/// with u = t^2 + 1, prod (u - a t) = u^4 - 10 u^2 t^2 + t^4 (the minimal polynomial of a,
/// x^4 - 10 x^2 + 1, homogenised as prod (u - a t) = t^4 ((u/t)^4 - 10 (u/t)^2 + 1)).
fn norm_of_quadratic() -> Vec<i64> {
    // u^4 = t^8 + 4 t^6 + 6 t^4 + 4 t^2 + 1; u^2 t^2 = t^6 + 2 t^4 + t^2.
    let mut n = [0i64; 9];
    for (k, c) in [(8, 1), (6, 4), (4, 6), (2, 4), (0, 1)] {
        n[k] += c;
    }
    for (k, c) in [(6, 1), (4, 2), (2, 1)] {
        n[k] -= 10 * c;
    }
    n[4] += 1;
    n.to_vec()
}

#[test]
fn fibre_tells_conjugate_partners_apart() {
    // A = (t - s)(t - 1), B = (t - s)(t + 3): over s = sqrt 2 the fibre is t - sqrt 2 alone;
    // -sqrt 2 (the conjugate, a root of the same t^2 - 2) and 1 (a root of A only) are not
    // partners.
    let a = bi(&[(0, 2, 1), (1, 1, -1), (0, 1, -1), (1, 0, 1)]);
    let b = bi(&[(0, 2, 1), (1, 1, -1), (0, 1, 3), (1, 0, -3)]);
    let sqrt2 = roots(&[-2, 0, 1]);
    let mut ext = Extension::new(&sqrt2[1], &z(&M23));
    let g = ext.fibre(&a, &b);
    assert_eq!(g, vec![qv(&[0, -1]), qv(&[1])]);
    assert!(ext.vanishes_at(&g, &sqrt2[1]));
    assert!(!ext.vanishes_at(&g, &sqrt2[0]));
    assert!(!ext.vanishes_at(&g, &AlgebraicReal::from_rational(Rational::one())));
    // A square in the fibre is made square-free: A^2 and B share (t - s)^1 after it.
    let a2 = bi_mul(&a, &a);
    let b2 = bi_mul(&b, &a);
    let g2 = ext.fibre(&a2, &b2);
    // gcd(A^2, AB) = A (t - 1)... = (t - s)^2 (t - 1) whose square-free part is
    // (t - s)(t - 1) = t^2 - (s + 1) t + s.
    assert_eq!(g2, vec![qv(&[0, 1]), qv(&[-1, -1]), qv(&[1])]);
}
