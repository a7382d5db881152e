//! Bivariate integer polynomials and their resultant and first subresultant with respect to
//! the second variable, computed exactly over the integers.
//!
//! A [`BiPoly`] `a` is the polynomial sum a[i][j] s^i t^j. For A, B of degrees a, b in t,
//! Res_t(A, B)(s) is the determinant of the (a + b)-square Sylvester matrix (b shifted rows of
//! A's coefficients, a of B's, highest power first), and the first subresultant
//! S_1 = S_11(s) t + S_10(s) has as coefficients the two (a + b - 2)-minors of the matrix of
//! b - 1 rows of A and a - 1 rows of B made of its first a + b - 3 columns and the column of
//! t^1, respectively t^0 (for a, b >= 2; when one of A, B is linear in t, it is its own S_1).
//! Where the leading coefficients in t do not vanish, these determinants specialise: at a
//! root s0 of Res, gcd_t(A(s0, t), B(s0, t)) has degree 1 exactly when S_11(s0) != 0, and
//! then it is S_1(s0, t).
//!
//! Both are computed by **evaluation and interpolation**: each determinant is a polynomial
//! in s of degree at most the sum over its rows of the row's largest degree in s, so it is
//! evaluated at s = 0, 1, ..., D by the fraction-free elimination of Bareiss (integer
//! entries, exact divisions) and interpolated by Newton's forward differences (integers:
//! the k-th difference of an integer polynomial's values is divisible by k!).

use super::upoly::{trim, ZPoly};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// A bivariate integer polynomial: `a[i][j]` is the coefficient of s^i t^j.
pub type BiPoly = Vec<Vec<BigInt>>;

/// The degree in t (the largest j with a non-zero a[i][j]), `None` for zero.
pub fn degree_t(a: &BiPoly) -> Option<usize> {
    a.iter()
        .filter_map(|row| row.iter().rposition(|c| !c.is_zero()))
        .max()
}

/// The largest degree in s among the coefficients of t^j, j <= dt.
fn degree_s(a: &BiPoly) -> usize {
    a.iter()
        .rposition(|row| row.iter().any(|c| !c.is_zero()))
        .unwrap_or(0)
}

/// The coefficient of t^j as a polynomial in s.
pub fn coefficient_t(a: &BiPoly, j: usize) -> ZPoly {
    let mut p: ZPoly = a
        .iter()
        .map(|row| row.get(j).cloned().unwrap_or_default())
        .collect();
    trim(&mut p);
    p
}

/// Swaps the two variables.
pub fn swap(a: &BiPoly) -> BiPoly {
    let nt = a.iter().map(Vec::len).max().unwrap_or(0);
    (0..nt)
        .map(|j| {
            a.iter()
                .map(|row| row.get(j).cloned().unwrap_or_default())
                .collect()
        })
        .collect()
}

/// A(s0, t) for an integer s0, as a polynomial in t with `dt + 1` coefficients.
fn at_s(a: &BiPoly, s0: &BigInt, dt: usize) -> Vec<BigInt> {
    (0..=dt)
        .map(|j| {
            a.iter().rev().fold(BigInt::zero(), |acc, row| {
                acc * s0 + row.get(j).cloned().unwrap_or_default()
            })
        })
        .collect()
}

/// The determinant of a square integer matrix by Bareiss's fraction-free elimination.
pub fn determinant(mut m: Vec<Vec<BigInt>>) -> BigInt {
    let n = m.len();
    if n == 0 {
        return BigInt::one();
    }
    let mut sign = false;
    let mut prev = BigInt::one();
    for k in 0..n - 1 {
        if m[k][k].is_zero() {
            match (k + 1..n).find(|&r| !m[r][k].is_zero()) {
                Some(r) => {
                    m.swap(k, r);
                    sign = !sign;
                }
                None => return BigInt::zero(),
            }
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = (&m[i][j] * &m[k][k] - &m[i][k] * &m[k][j]) / &prev;
                m[i][j] = v;
            }
        }
        prev = m[k][k].clone();
    }
    let d = m[n - 1][n - 1].clone();
    if sign {
        -d
    } else {
        d
    }
}

/// The rows `count` shifted copies of the coefficients `c` (ascending, degree deg) in a
/// matrix of `width` columns indexed by descending powers of t.
fn shifted_rows(c: &[BigInt], deg: usize, count: usize, width: usize) -> Vec<Vec<BigInt>> {
    (0..count)
        .map(|i| {
            let mut row = vec![BigInt::zero(); width];
            for k in 0..=deg {
                row[i + (deg - k)] = c[k].clone();
            }
            row
        })
        .collect()
}

/// Interpolates the integer polynomial of degree <= values.len() - 1 taking `values[k]` at
/// s = k (Newton forward differences, then the nested form expanded).
pub fn interpolate(values: &[BigInt]) -> ZPoly {
    let n = values.len();
    let mut d: Vec<BigInt> = values.to_vec();
    for k in 1..n {
        for i in (k..n).rev() {
            let v = &d[i] - &d[i - 1];
            d[i] = v;
        }
    }
    let mut fact = BigInt::one();
    for (k, dk) in d.iter_mut().enumerate().skip(1) {
        fact *= BigInt::from(k);
        *dk /= &fact;
    }
    // p = d0 + s (d1 + (s - 1) (d2 + ... + (s - (n - 2)) d_(n-1))).
    let mut p: ZPoly = vec![d[n - 1].clone()];
    for k in (0..n - 1).rev() {
        // p <- p * (s - k) + d_k.
        let mut next = vec![BigInt::zero(); p.len() + 1];
        for (i, c) in p.iter().enumerate() {
            next[i + 1] += c;
            next[i] -= c * BigInt::from(k);
        }
        next[0] += &d[k];
        p = next;
    }
    trim(&mut p);
    p
}

/// Res_t(A, B) as a polynomial in s (see the module docs). Zero when one of A, B is zero.
pub fn resultant_t(a: &BiPoly, b: &BiPoly) -> ZPoly {
    let (Some(da), Some(db)) = (degree_t(a), degree_t(b)) else {
        return Vec::new();
    };
    let bound = db * degree_s(a) + da * degree_s(b);
    let values: Vec<BigInt> = (0..=bound)
        .map(|k| {
            let s0 = BigInt::from(k);
            let ca = at_s(a, &s0, da);
            let cb = at_s(b, &s0, db);
            let mut m = shifted_rows(&ca, da, db, da + db);
            m.extend(shifted_rows(&cb, db, da, da + db));
            determinant(m)
        })
        .collect();
    interpolate(&values)
}

/// The first subresultant (S_11(s), S_10(s)) of A and B in t, or `None` when one of them
/// has degree 0 in t (see the module docs).
pub fn subresultant_1(a: &BiPoly, b: &BiPoly) -> Option<(ZPoly, ZPoly)> {
    let (da, db) = (degree_t(a)?, degree_t(b)?);
    if da == 0 || db == 0 {
        return None;
    }
    if db == 1 {
        return Some((coefficient_t(b, 1), coefficient_t(b, 0)));
    }
    if da == 1 {
        return Some((coefficient_t(a, 1), coefficient_t(a, 0)));
    }
    let rows = da + db - 2;
    let bound = (db - 1) * degree_s(a) + (da - 1) * degree_s(b);
    let mut v1 = Vec::with_capacity(bound + 1);
    let mut v0 = Vec::with_capacity(bound + 1);
    for k in 0..=bound {
        let s0 = BigInt::from(k);
        let ca = at_s(a, &s0, da);
        let cb = at_s(b, &s0, db);
        let mut m = shifted_rows(&ca, da, db - 1, rows + 1);
        m.extend(shifted_rows(&cb, db, da - 1, rows + 1));
        let minor = |col: usize| -> Vec<Vec<BigInt>> {
            m.iter()
                .map(|row| {
                    let mut r: Vec<BigInt> = row[..rows - 1].to_vec();
                    r.push(row[col].clone());
                    r
                })
                .collect()
        };
        v1.push(determinant(minor(rows - 1)));
        v0.push(determinant(minor(rows)));
    }
    Some((interpolate(&v1), interpolate(&v0)))
}
