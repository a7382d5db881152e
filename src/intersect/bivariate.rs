//! Bivariate integer polynomials and their resultant and first subresultant with respect to
//! the second variable, computed exactly over the integers.
//!
//! A [`BiPoly`] `a` is the polynomial sum a[i][j] s^i t^j. For F, G of formal degrees p, q in t
//! and j < min(p, q), the j-th subresultant S_j(F, G) = sum_(i <= j) S_ji t^i has as S_ji the
//! determinant of the matrix of q - j shifted rows t^(q-j-1) F, ..., F and p - j rows
//! t^(p-j-1) G, ..., G (coefficients by descending powers of t, width p + q - j) restricted to
//! its first p + q - 2j - 1 columns and the column of t^i. S_0 is the Sylvester resultant
//! Res_t(F, G); S_1 = S_11(s) t + S_10(s) is the first subresultant (for p, q >= 2; when one of
//! A, B is linear in t, it is its own S_1). Here the formal degrees are the degrees in t of the
//! bivariate polynomials. Where the leading coefficients in t do not vanish, these determinants
//! specialise: at a root s0 of Res, gcd_t(A(s0, t), B(s0, t)) has degree 1 exactly when
//! S_11(s0) != 0, and then it is S_1(s0, t).
//!
//! **Method: multi-modular evaluation and interpolation.** Each S_ji is a polynomial in s; for
//! each word-size prime p (see `modular`) it is evaluated at s = 0, 1, ..., D modulo p and
//! interpolated, and the integer coefficients are recovered by the Chinese remainder theorem.
//! * *The value at one point* comes from the remainder sequence of F(s0, t), G(s0, t) over
//!   F_p, in O(p q) operations instead of a determinant's O((p + q)^3), through three identities
//!   of the determinants (row operations), valid for formal degrees whatever the leading
//!   coefficients are (so no prime and no point is ever bad, even where a leading coefficient
//!   vanishes):
//!   1. swap: S_j(F, G)_(p,q) = (-1)^((p-j)(q-j)) S_j(G, F)_(q,p);
//!   2. pseudo-division: for g = lc(G) != 0 at formal degree q and e = p - q + 1,
//!      g^e F = Q G + R, the q - j rows of F gain g^e and the multiples of G are row
//!      operations, so S_j(F, G)_(p,q) = S_j(R, G)_(p,q) / g^(e(q-j)) (R at formal degree p;
//!      the divisions of all the points of one prime cost one inversion together);
//!   3. degree drop: when F has formal degree p but actual degree r, the first p - r rows of
//!      G form a triangle with diagonal g = the formal leading coefficient of G over the first
//!      p - r columns, where every other row vanishes: for r > j,
//!      S_j(F, G)_(p,q) = (-1)^((p-r)(q-j)) g^(p-r) S_j(F, G)_(r,q); for r <= j (F = 0 too), all
//!      p - j rows of G form that triangle and what is left is triangular in F's rows:
//!      S_j(F, G)_(p,q) = (-1)^((p-j)(q-j)) g^(p-j) lc(F)^(q-j-1) F when r = j or q = j + 1,
//!      and 0 otherwise.
//! * *The degree bound D.* Give s the weight w_s >= 1 and t the weight w_t >= 0, and let W_F
//!   be the largest weight i w_s + k w_t of a monomial s^i t^k of F. The entry in column t^c
//!   of the row t^l F has s-degree <= (W_F - (c - l) w_t) / w_s; summed over one entry per
//!   row, deg_s S_ji <= ((q-j) W_F + (p-j) W_G - w_t (sum of the chosen columns' powers - sum
//!   of the rows' shifts)) / w_s. The least of the bounds for (w_s, w_t) = (1, 0), (1, 1) and
//!   (max deg_t, max deg_s) is used: for A = f(s) - g(t) (degrees n, m) the last gives the
//!   exact n m instead of the 2 n m of the first.
//! * *The coefficient bound.* On |s| = 1 an entry a_k(s) (the coefficient of t^k) has
//!   |a_k(s)| <= |a_k|_1 (the sum of its coefficients' absolute values), so by Hadamard's
//!   inequality |S_ji(s)| <= N_F^(q-j) N_G^(p-j) with N_F^2 = sum_k |a_k|_1^2, and every
//!   coefficient of S_ji is bounded by its maximum on the unit circle (Cauchy). The primes
//!   are chosen so that their product exceeds twice this bound: the symmetric residues are
//!   then the coefficients themselves.

use super::modular::{self, Field};
use super::upoly::{trim, ZPoly};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

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

/// Res_t(A, B), the Sylvester resultant in t, as a polynomial in s, exactly: evaluated at
/// s = 0..D modulo word-size primes by remainder sequences and interpolated, the integers
/// recovered by Chinese remaindering (D and the number of primes from proven bounds). Zero
/// when one of A, B is zero.
pub fn resultant_t(a: &BiPoly, b: &BiPoly) -> ZPoly {
    let (Some(da), Some(db)) = (degree_t(a), degree_t(b)) else {
        return Vec::new();
    };
    subresultant(a, b, da, db, 0).swap_remove(0)
}

/// The first subresultant S_1 = S_11(s) t + S_10(s) of A and B in t, as (S_11, S_10), by the
/// same multi-modular method as [`resultant_t`], or `None` when one of them has degree 0 in
/// t. At a root s0 of the resultant, gcd_t(A(s0, t), B(s0, t)) has degree 1 exactly when
/// S_11(s0) != 0, and is then S_1(s0, t).
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
    let mut s = subresultant(a, b, da, db, 1);
    let s11 = s.pop().expect("two coefficients");
    let s10 = s.pop().expect("two coefficients");
    Some((s11, s10))
}

/// The coefficients S_j0, ..., S_jj of the j-th subresultant of A and B at formal degrees
/// (p, q) in t, j < min(p, q) (or j = 0: then the resultant for any p, q), each a polynomial
/// in s, by the multi-modular method of the module docs.
fn subresultant(a: &BiPoly, b: &BiPoly, p: usize, q: usize, j: usize) -> Vec<ZPoly> {
    let deg = degree_bound(a, b, p, q, j);
    let bits = coefficient_bits(a, b, p, q, j);
    let fields: Vec<Field> = modular::primes(modular::primes_for_bits(bits))
        .into_iter()
        .map(Field::new)
        .collect();
    // residues[i][k]: the coefficients of S_ji modulo the k-th prime.
    let mut residues: Vec<Vec<Vec<u64>>> = vec![Vec::with_capacity(fields.len()); j + 1];
    // Per prime: the columns reduced, deg + 1 evaluations (Horner on every column, then a
    // Euclid of about p q steps), and j + 1 interpolations of (deg + 1)^2 steps.
    let entries = |x: &BiPoly| x.iter().map(Vec::len).sum::<usize>() as u64;
    let (d1, j1) = (deg as u64 + 1, j as u64 + 1);
    let per_prime = (entries(a) + entries(b)) * (d1 + 4)
        + d1 * (p as u64 + 1) * (q as u64 + 1) * 2
        + j1 * d1 * d1;
    // Garner's reconstruction: about 2 k^2 steps for each of the (j + 1)(deg + 1) results.
    let k = fields.len() as u64;
    crate::num::meter::charge_word_operations(j1 * d1 * 2 * k * k);
    for &f in &fields {
        crate::num::meter::charge_word_operations(per_prime);
        let (ca, cb) = (columns_mod(f, a, p), columns_mod(f, b, q));
        let mut values: Vec<Vec<u64>> = vec![Vec::with_capacity(deg + 1); j + 1];
        let mut dens = Vec::with_capacity(deg + 1);
        let mut x = 0;
        for _ in 0..=deg {
            let fa: Vec<u64> = ca.iter().map(|c| horner(f, c, x)).collect();
            let fb: Vec<u64> = cb.iter().map(|c| horner(f, c, x)).collect();
            let (s, den) = subresultant_mod(f, fa, fb, j);
            for (v, si) in values.iter_mut().zip(s) {
                v.push(si);
            }
            dens.push(den);
            x = f.add(x, f.one());
        }
        f.inv_all(&mut dens);
        for (r, mut v) in residues.iter_mut().zip(values) {
            for (vi, d) in v.iter_mut().zip(&dens) {
                *vi = f.mul(*vi, *d);
            }
            r.push(f.interpolate_consecutive(&v));
        }
    }
    residues
        .iter()
        .map(|r| {
            let mut c = modular::reconstruct_symmetric(&fields, r);
            trim(&mut c);
            c
        })
        .collect()
}

/// The columns of `a` (the coefficients of t^0, ..., t^dt as polynomials in s, ascending)
/// modulo the field's prime.
fn columns_mod(f: Field, a: &BiPoly, dt: usize) -> Vec<Vec<u64>> {
    (0..=dt)
        .map(|k| {
            let mut c: Vec<u64> = a
                .iter()
                .map(|row| row.get(k).map_or(0, |x| f.of_bigint(x)))
                .collect();
            while c.last() == Some(&0) {
                c.pop();
            }
            c
        })
        .collect()
}

/// c(x) modulo the field's prime (Montgomery forms).
fn horner(f: Field, c: &[u64], x: u64) -> u64 {
    c.iter().rev().fold(0, |acc, &ci| f.add(f.mul(acc, x), ci))
}

/// (-1)^(m n) as a flag.
fn odd(m: usize, n: usize) -> bool {
    m % 2 == 1 && n % 2 == 1
}

/// S_j(F, G) over F_p at the formal degrees (len - 1) of `x` and `y`, j < both (or j = 0),
/// as (N, d) with S_j = N / d, d != 0, by the identities 1 to 3 of the module docs.
fn subresultant_mod(f: Field, mut x: Vec<u64>, mut y: Vec<u64>, j: usize) -> (Vec<u64>, u64) {
    let (mut p, mut q) = (x.len() - 1, y.len() - 1);
    let mut out = vec![0; j + 1];
    // The 0-th subresultant of a constant: the determinant of the other's rows alone.
    if j == 0 && (p == 0 || q == 0) {
        out[0] = match (p, q) {
            (0, 0) => f.one(),
            (_, 0) => f.pow(y[0], p as u64),
            _ => f.pow(x[0], q as u64),
        };
        return (out, f.one());
    }
    // Invariant: S_j(input) = (-1)^neg num / den S_j(x, y)_(p,q), j < min(p, q).
    let (mut neg, mut num, mut den) = (false, f.one(), f.one());
    let actual = |v: &[u64]| v.iter().rposition(|&c| c != 0);
    // The final triangle of identity 3 (r <= j), as (-1)^neg num * g^(p-j) * ... of `fx`.
    let last = |fx: &[u64], r: Option<usize>, p: usize, q: usize, g: u64| -> Vec<u64> {
        let mut res = vec![0; j + 1];
        let Some(r) = r else { return res };
        if r != j && q != j + 1 {
            return res;
        }
        let scale = f.mul(f.pow(g, (p - j) as u64), f.pow(fx[r], (q - j - 1) as u64));
        for (o, &c) in res.iter_mut().zip(fx) {
            *o = f.mul(c, scale);
        }
        res
    };
    let fin = |res: Vec<u64>, neg: bool, num: u64, den: u64| -> (Vec<u64>, u64) {
        let res = res
            .into_iter()
            .map(|c| {
                let v = f.mul(c, num);
                if neg {
                    f.neg(v)
                } else {
                    v
                }
            })
            .collect();
        (res, den)
    };
    loop {
        if p < q {
            std::mem::swap(&mut x, &mut y);
            std::mem::swap(&mut p, &mut q);
            neg ^= odd(p - j, q - j);
        }
        match actual(&y) {
            None => return (out, den),
            Some(r) if r < q => {
                // Swap, then identity 3 for y (formal q, actual r) against x (formal p).
                neg ^= odd(p - j, q - j);
                let g = x[p];
                if r <= j {
                    neg ^= odd(q - j, p - j);
                    return fin(last(&y, Some(r), q, p, g), neg, num, den);
                }
                neg ^= odd(q - r, p - j);
                num = f.mul(num, f.pow(g, (q - r) as u64));
                y.truncate(r + 1);
                std::mem::swap(&mut x, &mut y);
                (p, q) = (r, p);
            }
            Some(_) => {
                // Identity 2, then identity 3 for the remainder (formal p, actual r < q).
                let g = y[q];
                pseudo_remainder(f, &mut x, &y);
                den = f.mul(den, f.pow(g, ((p - q + 1) * (q - j)) as u64));
                match actual(&x) {
                    Some(r) if r > j => {
                        neg ^= odd(p - r, q - j);
                        num = f.mul(num, f.pow(g, (p - r) as u64));
                        x.truncate(r + 1);
                        p = r;
                    }
                    r => {
                        neg ^= odd(p - j, q - j);
                        return fin(last(&x, r, p, q, g), neg, num, den);
                    }
                }
            }
        }
    }
}

/// x <- g^(p - q + 1) x mod y over F_p (g = y[q] != 0, p = formal degree of x >= q): the
/// pseudo-remainder, p - q + 1 elimination steps whatever x's leading entries are.
fn pseudo_remainder(f: Field, x: &mut [u64], y: &[u64]) {
    let q = y.len() - 1;
    let g = y[q];
    for k in (q..x.len()).rev() {
        let c = x[k];
        x[k] = 0;
        for v in x[..k].iter_mut() {
            *v = f.mul(*v, g);
        }
        if c != 0 {
            for (v, &yi) in x[k - q..k].iter_mut().zip(&y[..q]) {
                *v = f.sub(*v, f.mul(c, yi));
            }
        }
    }
}

/// The largest weight i ws + k wt of a monomial s^i t^k of `a` (0 for zero).
fn weighted_degree(a: &BiPoly, ws: usize, wt: usize) -> usize {
    let mut w = 0;
    for (i, row) in a.iter().enumerate() {
        for (k, c) in row.iter().enumerate() {
            if !c.is_zero() {
                w = w.max(i * ws + k * wt);
            }
        }
    }
    w
}

/// A bound on deg_s of every S_ji: with weights w_s for s and w_t for t, the weighted degree
/// of each row's entries summed over the rows, the least over the weights (1, 0), (1, 1) and
/// (max deg_t, max deg_s).
fn degree_bound(a: &BiPoly, b: &BiPoly, p: usize, q: usize, j: usize) -> usize {
    let (rows_a, rows_b) = (q - j, p - j);
    // The chosen columns: powers j + 1 .. p + q - j - 1 and the variable one (>= 0).
    let columns: usize = (j + 1..p + q - j).sum();
    let shifts = rows_a * rows_a.saturating_sub(1) / 2 + rows_b * rows_b.saturating_sub(1) / 2;
    let excess = columns - shifts;
    let ws = p.max(q).max(1);
    let wt = degree_s(a).max(degree_s(b));
    [(1, 0), (1, 1), (ws, wt)]
        .iter()
        .map(|&(ws, wt)| {
            let total = rows_a * weighted_degree(a, ws, wt) + rows_b * weighted_degree(b, ws, wt);
            total.saturating_sub(wt * excess) / ws
        })
        .min()
        .expect("three weights")
}

/// Bits b with every coefficient of every S_ji below 2^b in absolute value (see the module
/// docs: N_A^(q-j) N_B^(p-j) < 2^(((q-j) L_A + (p-j) L_B) / 2) with L the bit length of N^2).
fn coefficient_bits(a: &BiPoly, b: &BiPoly, p: usize, q: usize, j: usize) -> u64 {
    let norm2_bits = |a: &BiPoly, dt: usize| -> u64 {
        let n2: BigInt = (0..=dt)
            .map(|k| {
                let l1: BigInt = a.iter().filter_map(|row| row.get(k)).map(|c| c.abs()).sum();
                &l1 * &l1
            })
            .sum();
        n2.bits()
    };
    let total = (q - j) as u64 * norm2_bits(a, p) + (p - j) as u64 * norm2_bits(b, q);
    total.div_ceil(2)
}

#[cfg(test)]
mod tests {
    //! The multi-modular subresultants against an independent oracle: the determinants of the
    //! Sylvester matrix and its minors at s = 0, 1, ..., by Bareiss's fraction-free
    //! elimination over the integers, interpolated by Newton's forward differences.

    use super::*;
    use num_traits::One;

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
    fn determinant(mut m: Vec<Vec<BigInt>>) -> BigInt {
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
    fn interpolate(values: &[BigInt]) -> ZPoly {
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

    /// Res_t(A, B) as a polynomial in s, by exact determinants (the independent oracle of
    /// [`resultant_t`]). Zero when one of A, B is zero.
    fn resultant_oracle(a: &BiPoly, b: &BiPoly) -> ZPoly {
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

    /// The first subresultant (S_11(s), S_10(s)) of A and B in t by exact determinants (the
    /// independent oracle of [`subresultant_1`]), or `None` when one of them has degree 0 in t.
    fn subresultant_1_oracle(a: &BiPoly, b: &BiPoly) -> Option<(ZPoly, ZPoly)> {
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

    /// Samples drawn from the shared test generator ([`crate::test_rng::XorShift`]).
    struct Rng(crate::test_rng::XorShift);

    impl Rng {
        fn next(&mut self) -> u64 {
            self.0.next()
        }

        fn small(&mut self, r: i64) -> BigInt {
            BigInt::from((self.next() % (2 * r as u64 + 1)) as i64 - r)
        }

        /// A BiPoly of degrees <= (ds, dt), each coefficient non-zero with probability 1/2
        /// (the corner entries that fix the degrees sometimes zero too).
        fn bipoly(&mut self, ds: usize, dt: usize, r: i64) -> BiPoly {
            (0..=ds)
                .map(|_| {
                    (0..=dt)
                        .map(|_| {
                            if self.next().is_multiple_of(2) {
                                BigInt::zero()
                            } else {
                                self.small(r)
                            }
                        })
                        .collect()
                })
                .collect()
        }
    }

    fn mul_bi(a: &BiPoly, b: &BiPoly) -> BiPoly {
        let nt =
            a.iter().map(Vec::len).max().unwrap_or(0) + b.iter().map(Vec::len).max().unwrap_or(0);
        let mut out = vec![vec![BigInt::zero(); nt]; a.len() + b.len()];
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

    fn check(a: &BiPoly, b: &BiPoly) {
        assert_eq!(
            resultant_t(a, b),
            resultant_oracle(a, b),
            "Res of {a:?}, {b:?}"
        );
        assert_eq!(
            subresultant_1(a, b),
            subresultant_1_oracle(a, b),
            "S_1 of {a:?}, {b:?}"
        );
    }

    #[test]
    fn random_general_bipolys_match_the_determinants() {
        let mut rng = Rng(crate::test_rng::XorShift(0x9e37_79b9_7f4a_7c15));
        for case in 0..300 {
            let (ds1, dt1) = (rng.next() % 4, rng.next() % 5);
            let (ds2, dt2) = (rng.next() % 4, rng.next() % 5);
            let r = if case % 3 == 0 { 1_000_000_000 } else { 3 };
            let a = rng.bipoly(ds1 as usize, dt1 as usize, r);
            let b = rng.bipoly(ds2 as usize, dt2 as usize, r);
            check(&a, &b);
        }
    }

    #[test]
    fn common_factors_give_zero_and_match() {
        let mut rng = Rng(crate::test_rng::XorShift(0x1234_5678_9abc_def1));
        for _ in 0..60 {
            let (cs, ct) = (1 + (rng.next() % 2) as usize, 1 + (rng.next() % 2) as usize);
            let c = rng.bipoly(cs, ct, 4);
            if degree_t(&c).unwrap_or(0) == 0 {
                continue;
            }
            let a = mul_bi(&c, &rng.bipoly(2, 2, 4));
            let b = mul_bi(&c, &rng.bipoly(2, 3, 4));
            check(&a, &b);
            if degree_t(&a).is_some() && degree_t(&b).is_some() {
                assert!(resultant_t(&a, &b).is_empty());
            }
        }
    }

    #[test]
    fn separated_and_degenerate_shapes_match() {
        let mut rng = Rng(crate::test_rng::XorShift(0x0dd_ba11_cafe_f00d));
        // f(s) - g(t) with big coefficients, as for curves; divided differences; leading
        // coefficients that vanish modulo nothing but at some s; constants.
        for _ in 0..40 {
            let (n, m) = (1 + (rng.next() % 5) as usize, 1 + (rng.next() % 5) as usize);
            let mut sep = |r: i64| -> BiPoly {
                let mut a = vec![vec![BigInt::zero(); m + 1]; n + 1];
                for row in a.iter_mut() {
                    row[0] = rng.small(r);
                }
                for c in a[0].iter_mut().skip(1) {
                    *c = rng.small(r);
                }
                a
            };
            let (a, b) = (sep(1 << 40), sep(1 << 40));
            check(&a, &b);
            check(&b, &a);
            check(&swap(&a), &swap(&b));
        }
        let x = |v: &[&[i64]]| -> BiPoly {
            v.iter()
                .map(|r| r.iter().map(|&c| BigInt::from(c)).collect())
                .collect()
        };
        // lc_t vanishing at s = 0 and s = 1: (s^2 - s) t^2 + t - 3, and 2 t^3 - s.
        let a = x(&[&[-3, 1, 0], &[0, 0, -1], &[0, 0, 1]]);
        let b = x(&[&[0, 0, 0, 2], &[-1]]);
        check(&a, &b);
        check(&b, &a);
        check(&x(&[&[5]]), &a);
        check(&a, &x(&[&[0], &[2], &[1]]));
        check(&x(&[&[0, 1]]), &x(&[&[0, 0, 1]]));
    }
}
