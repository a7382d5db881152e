//! Exact linear algebra: the [`Field`] refinement of [`Ring`] (division and order, for knots,
//! de Boor weights and Cartesian points of rational curves) and Gaussian elimination with an
//! exact rational matrix (for the normal equations of least-squares degree reduction).

use crate::error::{Error, ErrorKind, Result};
use crate::shape::point::{self, Point};
use crate::{Rational, Ring};

/// A [`Ring`] with division by non-zero elements, a total order on the values the crate meets
/// and a printed form (for error messages): [`Rational`] (exact) and `f64`/`f32` (rounded; NaN
/// is never produced from finite input by the algorithms of this crate).
pub trait Field: Ring + PartialOrd + std::fmt::Display {
    /// Whether the arithmetic is exact, so that equality of computed values is meaningful
    /// (`true` for [`Rational`], `false` for floats).
    const EXACT: bool;
    /// `self / rhs`; `rhs` must be non-zero (callers check, and return an error otherwise).
    fn divide(&self, rhs: &Self) -> Self;
}

impl Field for Rational {
    const EXACT: bool = true;
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
}

impl Field for f64 {
    const EXACT: bool = false;
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
}

impl Field for f32 {
    const EXACT: bool = false;
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
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
            *x = &*x / &p;
        }
        for r in 0..n {
            if r == col || Ring::is_zero(&a[r][col]) {
                continue;
            }
            let k = a[r][col].clone();
            for c in 0..n {
                let (ac, ic) = (&a[col][c] * &k, &inv[col][c] * &k);
                a[r][c] -= ac;
                inv[r][c] -= ic;
            }
        }
    }
    Ok(inv)
}

/// `matrix * rhs` for a rational matrix and a column of points (any [`Ring`]).
pub fn apply<T: Ring>(matrix: &[Vec<Rational>], rhs: &[Point<T>], dim: usize) -> Vec<Point<T>> {
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
    Ok(apply(&inverse(matrix, field)?, rhs, dim))
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
