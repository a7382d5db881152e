//! Forward differences of a Bézier net: the change to the power basis that lets the Bézier
//! shapes reuse the unrolled formulae (3), (9), (14).
//!
//! * curve over [0, 1]: C(u) = sum_i C(n, i) (Δ^i b_0) u^i, Δ^k b_i = Δ^(k-1) b_(i+1) - Δ^(k-1) b_i;
//! * tensor patch over [0, 1]^2: c_ij = C(n, i) C(m, j) Δ_u^i Δ_v^j b_00;
//! * triangle with barycentric coordinates (u, v, 1 - u - v) of the reference triangle:
//!   c_ij = N! / (i! j! (N-i-j)!) Δ_1^i Δ_2^j b_(0,0,N), with Δ_1 b_(ν,μ) = b_(ν+1,μ) - b_(ν,μ)
//!   and Δ_2 b_(ν,μ) = b_(ν,μ+1) - b_(ν,μ) (λ moves to the first or second corner).
//!
//! The binomial or trinomial factor of c_i is exactly the denominator of the weight of c_i in
//! (3), (9) or (14), so the two cancel: the generated code multiplies the differences by
//! integer weights and never divides. Each difference costs one subtraction per coordinate and
//! is bound once: n(n+1)/2 subtractions for a curve, O(nm(n+m)) for a tensor patch, O(N^3) for
//! a triangle.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::HashMap;

/// `ctrl[i]`, `ctrl[i][j]`: a control point of the input net.
pub fn ctrl(indices: &[usize]) -> TokenStream {
    let idx = indices.iter().map(|&i| Literal::usize_unsuffixed(i));
    quote!(ctrl #([#idx])*)
}

/// Binds `name = minuend - subtrahend`, coordinate by coordinate, and returns its tokens.
fn difference(
    name: String,
    minuend: &TokenStream,
    subtrahend: &TokenStream,
    stmts: &mut Vec<TokenStream>,
) -> TokenStream {
    let id = format_ident!("{}", name);
    stmts.push(quote!(
        let #id: [T; D] = ::core::array::from_fn(|x| #minuend[x].sub(&#subtrahend[x]));
    ));
    quote!(#id)
}

/// The forward differences of one sequence of points: `out[k]` = Δ^k p_0, bound as
/// `{prefix}{k}_{i}` for the intermediate Δ^k p_i.
fn sequence(
    points: Vec<TokenStream>,
    prefix: &str,
    stmts: &mut Vec<TokenStream>,
) -> Vec<TokenStream> {
    let mut level = points;
    let mut out = vec![level[0].clone()];
    for k in 1..level.len() {
        level = (0..level.len() - 1)
            .map(|i| difference(format!("{prefix}{k}_{i}"), &level[i + 1], &level[i], stmts))
            .collect();
        out.push(level[0].clone());
    }
    out
}

/// Δ^k b_0 for k = 0..=n of the curve `ctrl[0..=n]`.
pub fn curve(n: usize, stmts: &mut Vec<TokenStream>) -> Vec<TokenStream> {
    sequence((0..=n).map(|i| ctrl(&[i])).collect(), "d", stmts)
}

/// `[i][j]` = Δ_u^i Δ_v^j b_00 of the net `ctrl[0..=n][0..=m]`: differences along v in every
/// row, then along u for every order in v.
pub fn tensor(n: usize, m: usize, stmts: &mut Vec<TokenStream>) -> Vec<Vec<TokenStream>> {
    // rows[r][j] = Δ_v^j b_(r, 0)
    let rows: Vec<Vec<TokenStream>> = (0..=n)
        .map(|r| {
            sequence(
                (0..=m).map(|j| ctrl(&[r, j])).collect(),
                &format!("dv{r}_"),
                stmts,
            )
        })
        .collect();
    let columns: Vec<Vec<TokenStream>> = (0..=m)
        .map(|j| {
            sequence(
                (0..=n).map(|r| rows[r][j].clone()).collect(),
                &format!("du_v{j}_"),
                stmts,
            )
        })
        .collect();
    (0..=n)
        .map(|i| (0..=m).map(|j| columns[j][i].clone()).collect())
        .collect()
}

/// `(i, j)` -> Δ_1^i Δ_2^j b_(0,0,N) for i + j <= N, of the triangular net `ctrl` listed in
/// lexicographic order of (ν, μ) (ν the exponent of the first barycentric coordinate).
pub fn triangle(
    big_n: usize,
    stmts: &mut Vec<TokenStream>,
) -> HashMap<(usize, usize), TokenStream> {
    let index = |nu: usize, mu: usize| nu * (big_n + 1) - nu * nu.saturating_sub(1) / 2 + mu;
    // level[(ν, μ)] = Δ_2^j b_(ν, μ) for ν + μ <= N - j.
    let mut level: HashMap<(usize, usize), TokenStream> = HashMap::new();
    for nu in 0..=big_n {
        for mu in 0..=big_n - nu {
            level.insert((nu, mu), ctrl(&[index(nu, mu)]));
        }
    }
    let mut out = HashMap::new();
    for j in 0..=big_n {
        if j > 0 {
            let mut next = HashMap::new();
            for nu in 0..=big_n - j {
                for mu in 0..=big_n - j - nu {
                    let d = difference(
                        format!("d2_{j}_{nu}_{mu}"),
                        &level[&(nu, mu + 1)],
                        &level[&(nu, mu)],
                        stmts,
                    );
                    next.insert((nu, mu), d);
                }
            }
            level = next;
        }
        // Δ_1^i of the column Δ_2^j b_(ν, 0), ν = 0..=N - j.
        let column: Vec<TokenStream> = (0..=big_n - j).map(|nu| level[&(nu, 0)].clone()).collect();
        for (i, d) in sequence(column, &format!("d1_{j}_"), stmts)
            .into_iter()
            .enumerate()
        {
            out.insert((i, j), d);
        }
    }
    out
}
