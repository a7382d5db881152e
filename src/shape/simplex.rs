//! Indexing of the simplex {(nu, mu, lambda) : nu + mu + lambda = n}, the index set of the
//! control points of a triangular patch of degree n, listed in lexicographic order of (nu, mu).

/// The position of `(nu, mu)` in the lexicographic listing of `{(nu, mu) : nu + mu <= n}`.
pub fn triangle_index(n: usize, nu: usize, mu: usize) -> usize {
    debug_assert!(nu + mu <= n);
    nu * (n + 1) - nu * nu.saturating_sub(1) / 2 + mu
}

/// The number of control points of a triangular patch of degree `n`: (n + 1)(n + 2) / 2.
///
/// # Panics
/// When the count overflows `usize` (n about 2^32 on 64-bit targets); degrees of existing
/// patches never do, since their constructors refuse them. [`checked_triangle_len`] returns
/// `None` instead.
pub fn triangle_len(n: usize) -> usize {
    checked_triangle_len(n).expect("the number of points of a triangle of this degree overflows")
}

/// (n + 1)(n + 2) / 2, or `None` when it overflows `usize`.
pub fn checked_triangle_len(n: usize) -> Option<usize> {
    let (a, b) = (n.checked_add(1)?, n.checked_add(2)?);
    // One of two consecutive integers is even: halve it first.
    if a % 2 == 0 {
        (a / 2).checked_mul(b)
    } else {
        a.checked_mul(b / 2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_indices_are_lexicographic() {
        for n in 0..8 {
            let mut k = 0;
            for nu in 0..=n {
                for mu in 0..=n - nu {
                    assert_eq!(triangle_index(n, nu, mu), k);
                    k += 1;
                }
            }
            assert_eq!(k, triangle_len(n));
        }
    }

    #[test]
    fn checked_triangle_len_overflows_to_none() {
        for n in 0..100 {
            assert_eq!(checked_triangle_len(n), Some((n + 1) * (n + 2) / 2));
        }
        assert_eq!(checked_triangle_len(usize::MAX), None);
        assert_eq!(checked_triangle_len(usize::MAX / 2), None);
        assert!(checked_triangle_len(1 << 31).is_some());
    }
}
