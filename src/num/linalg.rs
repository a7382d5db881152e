//! Exact linear algebra: the [`Field`] refinement of [`Ring`] (division and order, for knots,
//! de Boor weights and Cartesian points of rational curves) and Gaussian elimination with an
//! exact rational matrix, with the few matrix helpers of least-squares degree reduction
//! (products, Kronecker products, the constrained normal equations, Gram quadratic forms).

use crate::error::{Error, ErrorKind, Result};
use crate::num::meter::{charge_rational, charge_rational_sum};
use crate::shape::point::{self, Point};
use crate::{Rational, Ring};

/// A [`Ring`] with division by non-zero elements, a total order on the finite values the crate
/// meets and a printed form (for error messages): [`Rational`] (exact) and `f64`/`f32`
/// (rounded; NaN is never produced from finite input by the algorithms of this crate).
///
/// The order is total on finite values only: every public function whose control flow a
/// comparison decides (knot order, span search, interval and domain checks) first refuses
/// values that are not [`Field::is_finite`] with [`ErrorKind::NotFinite`]. `Ring`-only code
/// (the restriction algorithms) never compares values, so it takes NaN and infinities as they
/// are and propagates them by IEEE arithmetic.
pub trait Field: Ring + PartialOrd + std::fmt::Display {
    /// Whether the arithmetic is exact, so that equality of computed values is meaningful
    /// (`true` for [`Rational`], `false` for floats).
    const EXACT: bool;
    /// `self / rhs`; `rhs` must be non-zero (callers check, and return an error otherwise).
    fn divide(&self, rhs: &Self) -> Self;
    /// Whether the value is finite (neither NaN nor an infinity): always for [`Rational`],
    /// `f64::is_finite` for floats.
    fn is_finite(&self) -> bool;
}

impl Field for Rational {
    const EXACT: bool = true;
    /// Charges the work meter first, as the [`Ring`] operations do.
    fn divide(&self, rhs: &Self) -> Self {
        charge_rational(self, rhs);
        self / rhs
    }
    fn is_finite(&self) -> bool {
        true
    }
}

impl Field for f64 {
    const EXACT: bool = false;
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
}

impl Field for f32 {
    const EXACT: bool = false;
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
    fn is_finite(&self) -> bool {
        f32::is_finite(*self)
    }
}

/// `Ok(())` when `x` is finite, else an [`ErrorKind::NotFinite`] error about `field`: the one
/// finiteness check of the crate.
pub(crate) fn check_finite<T: Field>(x: &T, field: &str) -> Result<()> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Error::of(
            ErrorKind::NotFinite,
            field,
            format!("expected a finite number, found {x}"),
        ))
    }
}

/// [`check_finite`] on every entry of `xs`, naming the first bad one `field[i]`.
pub(crate) fn check_all_finite<T: Field>(xs: &[T], field: &str) -> Result<()> {
    for (i, x) in xs.iter().enumerate() {
        check_finite(x, &format!("{field}[{i}]"))?;
    }
    Ok(())
}

/// The inverse of a square matrix with exact rational entries, by Gauss-Jordan elimination
/// (pivoting on the first non-zero entry: exact arithmetic needs no numerical pivoting).
///
/// Fails with an error about `field` when the matrix is not square or is singular.
pub fn inverse(matrix: &[Vec<Rational>], field: &str) -> Result<Vec<Vec<Rational>>> {
    let n = matrix.len();
    if let Some(i) = matrix.iter().position(|row| row.len() != n) {
        return Err(Error::of(
            ErrorKind::Shape,
            format!("{field}[{i}]"),
            format!("expected {n} entries (a square matrix)"),
        ));
    }
    // [A | I] reduced to [I | A^-1].
    let mut a: Vec<Vec<Rational>> = matrix.to_vec();
    let mut inv: Vec<Vec<Rational>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| Rational::from_integer((i == j).into()))
                .collect()
        })
        .collect();
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| !Ring::is_zero(&a[r][col])) else {
            return Err(Error::of(
                ErrorKind::Singular,
                field,
                "the matrix is singular",
            ));
        };
        a.swap(col, pivot);
        inv.swap(col, pivot);
        let p = a[col][col].clone();
        for x in a[col].iter_mut().chain(inv[col].iter_mut()) {
            *x = Field::divide(&*x, &p);
        }
        for r in 0..n {
            if r == col || Ring::is_zero(&a[r][col]) {
                continue;
            }
            let k = a[r][col].clone();
            for c in 0..n {
                // Two products and two differences of about the same length, charged as such.
                charge_rational(&a[col][c], &k);
                charge_rational(&inv[col][c], &k);
                charge_rational_sum(&a[r][c], &a[col][c]);
                charge_rational_sum(&inv[r][c], &inv[col][c]);
                let (ac, ic) = (&a[col][c] * &k, &inv[col][c] * &k);
                a[r][c] -= ac;
                inv[r][c] -= ic;
            }
        }
    }
    Ok(inv)
}

/// `matrix * rhs` for a rational matrix and a column of points (any [`Ring`]), every point of
/// `dim` coordinates (callers check; a shorter point would be zero-padded).
pub(crate) fn apply<T: Ring>(
    matrix: &[Vec<Rational>],
    rhs: &[Point<T>],
    dim: usize,
) -> Vec<Point<T>> {
    matrix
        .iter()
        .map(|row| {
            let mut acc = point::zero::<T>(dim);
            for (k, p) in row.iter().zip(rhs) {
                point::add_scaled_rational(&mut acc, k, p);
            }
            acc
        })
        .collect()
}

/// Solves `matrix * x = rhs` for a column `x` of points of dimension `dim`, exactly: the
/// matrix is rational, the points may be of any [`Ring`] (rationals, floats, symbolic).
///
/// # Errors
/// [`ErrorKind::Shape`] about `field` when `rhs` does not have one point per row or the matrix
/// is not square, [`ErrorKind::Dimension`] on `rhs[i]` when a point does not have `dim`
/// coordinates, [`ErrorKind::Singular`] when the matrix is singular.
pub fn solve_rational_system<T: Ring>(
    matrix: &[Vec<Rational>],
    rhs: &[Point<T>],
    dim: usize,
    field: &str,
) -> Result<Vec<Point<T>>> {
    if rhs.len() != matrix.len() {
        return Err(Error::of(
            ErrorKind::Shape,
            field,
            format!(
                "expected {} right-hand sides, found {}",
                matrix.len(),
                rhs.len()
            ),
        ));
    }
    point::check_dims(rhs, dim, "rhs")?;
    Ok(apply(&inverse(matrix, field)?, rhs, dim))
}

/// The product of two exact matrices (`a` has as many columns as `b` has rows).
pub(crate) fn product(a: &[Vec<Rational>], b: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|c| {
                    row.iter()
                        .zip(b)
                        .map(|(x, r)| {
                            charge_rational(x, &r[c]);
                            x * &r[c]
                        })
                        .sum()
                })
                .collect()
        })
        .collect()
}

/// The Kronecker product `[i * p + j][k * q + l]` = `a[i][k] b[j][l]` of an exact matrix `a`
/// with an exact matrix `b` of `p` rows and `q` columns (the matrix of a tensor-product
/// operator on row-major index pairs).
pub(crate) fn kronecker(a: &[Vec<Rational>], b: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let mut out = Vec::with_capacity(a.len() * b.len());
    for ra in a {
        for rb in b {
            out.push(
                ra.iter()
                    .flat_map(|x| {
                        rb.iter().map(move |y| {
                            charge_rational(x, y);
                            x * y
                        })
                    })
                    .collect(),
            );
        }
    }
    out
}

/// The exact matrix R (P rows, Q columns) of the least-squares fit x = R b of a function
/// sum_k b_k g_k by sum_i x_i f_i, with the unknowns listed in `fixed` pinned:
/// `(i, k)` imposes x_i = b_k.
///
/// `gram[i][j]` = <f_i, f_j> (P x P) and `cross[i][k]` = <f_i, g_k> (P x Q). The free unknowns
/// F solve the normal equations restricted to F:
///
/// sum_{j in F} gram[i][j] x_j = sum_k cross[i][k] b_k - sum_{(j, k) fixed} gram[i][j] b_k,
/// i in F,
///
/// whose right-hand side, written as rows over the Q inputs b, gives the rows of R (pinned
/// unknowns get the unit row e_k). Fails with [`ErrorKind::Singular`] about `field` when the
/// restricted Gram matrix is singular (never for the Gram matrix of a basis).
pub(crate) fn least_squares_operator(
    gram: &[Vec<Rational>],
    cross: &[Vec<Rational>],
    fixed: &[(usize, usize)],
    field: &str,
) -> Result<Vec<Vec<Rational>>> {
    let p = gram.len();
    let q = cross.first().map_or(0, Vec::len);
    let mut pinned: Vec<Option<usize>> = vec![None; p];
    for &(i, k) in fixed {
        pinned[i] = Some(k);
    }
    let free: Vec<usize> = (0..p).filter(|&i| pinned[i].is_none()).collect();
    let rhs: Vec<Vec<Rational>> = free
        .iter()
        .map(|&i| {
            let mut row = cross[i].clone();
            for (j, pin) in pinned.iter().enumerate() {
                if let Some(k) = pin {
                    row[*k] -= &gram[i][j];
                }
            }
            row
        })
        .collect();
    let inner: Vec<Vec<Rational>> = free
        .iter()
        .map(|&i| free.iter().map(|&j| gram[i][j].clone()).collect())
        .collect();
    let mut solved = product(&inverse(&inner, field)?, &rhs).into_iter();
    Ok(pinned
        .iter()
        .map(|pin| match pin {
            Some(k) => (0..q)
                .map(|c| Rational::from_integer((c == *k).into()))
                .collect(),
            None => solved.next().expect("one solved row per free unknown"),
        })
        .collect())
}

/// The quadratic form sum_{i, j} gram[i][j] <d_i, d_j> of points `d` (the squared norm of
/// sum_i d_i f_i when `gram` is the Gram matrix of the f_i).
pub(crate) fn gram_quadratic_form<T: Ring>(gram: &[Vec<Rational>], d: &[Point<T>]) -> T {
    let mut acc = T::zero();
    for (di, row) in d.iter().zip(gram) {
        for (dj, g) in d.iter().zip(row) {
            let dot = di
                .iter()
                .zip(dj)
                .fold(T::zero(), |s, (x, y)| s.add(&x.mul(y)));
            acc.add_assign(&dot.scale(g));
        }
    }
    acc
}

/// The coordinate-wise differences `a_i - b_i` of two lists of points.
pub(crate) fn differences<T: Ring>(a: &[Point<T>], b: &[Point<T>]) -> Vec<Point<T>> {
    a.iter()
        .zip(b)
        .map(|(p, q)| p.iter().zip(q).map(|(x, y)| x.sub(y)).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn hilbert_matrix_inverse_is_exact() {
        // The 4x4 Hilbert matrix has an integer inverse.
        let h: Vec<Vec<Rational>> = (0..4)
            .map(|i| (0..4).map(|j| q(1, i + j + 1)).collect())
            .collect();
        let inv = inverse(&h, "h").unwrap();
        assert_eq!(inv[0], vec![q(16, 1), q(-120, 1), q(240, 1), q(-140, 1)]);
        for (i, row) in h.iter().enumerate() {
            for j in 0..4 {
                let s: Rational = row.iter().zip(&inv).map(|(a, r)| a * &r[j]).sum();
                assert_eq!(s, q((i == j) as i64, 1));
            }
        }
    }

    #[test]
    fn singular_and_ragged_matrices_are_errors() {
        let s = vec![vec![q(1, 1), q(2, 1)], vec![q(2, 1), q(4, 1)]];
        assert_eq!(
            inverse(&s, "m").unwrap_err().to_string(),
            "m: the matrix is singular"
        );
        let r = vec![vec![q(1, 1)], vec![q(2, 1), q(4, 1)]];
        assert_eq!(inverse(&r, "m").unwrap_err().field, "m[0]");
    }

    #[test]
    fn solve_with_pivoting() {
        // [[0, 1], [1, 1]] x = [(2), (3)] -> x = [(1), (2)]
        let m = vec![vec![q(0, 1), q(1, 1)], vec![q(1, 1), q(1, 1)]];
        let x = solve_rational_system(&m, &[vec![q(2, 1)], vec![q(3, 1)]], 1, "m").unwrap();
        assert_eq!(x, vec![vec![q(1, 1)], vec![q(2, 1)]]);
        let xf = solve_rational_system(&m, &[vec![2.0f64], vec![3.0]], 1, "m").unwrap();
        assert_eq!(xf, vec![vec![1.0], vec![2.0]]);
    }
}
