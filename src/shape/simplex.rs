//! Indexing of the simplex {(nu, mu, lambda) : nu + mu + lambda = n}, the index set of the
//! control points of a triangular patch of degree n, listed in lexicographic order of (nu, mu).

/// The position of `(nu, mu)` in the lexicographic listing of `{(nu, mu) : nu + mu <= n}`.
pub fn triangle_index(n: usize, nu: usize, mu: usize) -> usize {
    debug_assert!(nu + mu <= n);
    nu * (n + 1) - nu * nu.saturating_sub(1) / 2 + mu
}

/// The number of control points of a triangular patch of degree `n`: (n + 1)(n + 2) / 2.
pub fn triangle_len(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
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
}
