//! Theorem 2, eq. (9), unrolled for one bidegree `(n, m)`:
//!
//! p_{nu mu} = sum_i sum_j c_ij / (C(n, i) C(m, j)) sum_k sum_r C(nu, k) C(n-nu, i-k) C(mu, r)
//! C(m-mu, j-r) b^k a^(i-k) d^r c^(j-r).
//!
//! By (10)-(11) the quadruple sum is the product of two curve weights of eq. (3), `uNU_cI` in
//! (a, b) and `vMU_cJ` in (c, d), so p_{nu mu} = sum_i uNU_cI (sum_j vMU_cJ c_ij). The inner
//! sums `cI_vMU` (row i of the coefficient net restricted in v) are bound once and shared by
//! every nu: (n+1)(m+1)(n+m+2) multiply-adds per coordinate instead of (n+1)^2 (m+1)^2.

use super::curve::weight;
use super::{array_type, coef, combination, fn_attrs, ident, reading, Monomials, Operand};
use crate::model::Spec;
use proc_macro2::TokenStream;
use quote::quote;

/// The generated function for a power-basis tensor-product surface of bidegree `(n, m)`.
// `rows[i][mu]` is indexed by both paper indices; an iterator would hide one of them.
#[allow(clippy::needless_range_loop)]
pub fn expand(spec: &Spec, n: usize, m: usize) -> Option<TokenStream> {
    let (inputs, input_names): (Vec<Vec<TokenStream>>, Vec<Vec<String>>) = (
        (0..=n)
            .map(|i| (0..=m).map(|j| coef(&[i, j])).collect())
            .collect(),
        (0..=n)
            .map(|i| (0..=m).map(|j| format!("c_{i}{j}")).collect())
            .collect(),
    );
    let names = ["b", "a", "d", "c"];
    let u_table = (0..=n)
        .map(|nu| {
            (0..=n)
                .map(|i| weight(n, nu, i, 0, 4, ("b", "a")))
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    let v_table = (0..=m)
        .map(|mu| {
            (0..=m)
                .map(|j| weight(m, mu, j, 2, 4, ("d", "c")))
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    let mut monomials = Monomials::new(&names);
    monomials.bind_all(
        &u_table
            .iter()
            .chain(&v_table)
            .flatten()
            .flat_map(|(w, _)| w.terms.iter().map(|t| t.exps.clone()))
            .collect(),
    );
    let mut weight_stmts = Vec::new();
    let mut bind_table =
        |table: &[Vec<(super::Weight, String)>], prefix: &str| -> Vec<Vec<Operand>> {
            table
                .iter()
                .enumerate()
                .map(|(nu, row)| {
                    row.iter()
                        .enumerate()
                        .map(|(i, (w, reading))| {
                            let name = format!("{prefix}{nu}_c{i}");
                            w.bind(
                                &name,
                                &format!("{name} = {reading}"),
                                &mut monomials,
                                &mut weight_stmts,
                            )
                        })
                        .collect()
                })
                .collect()
        };
    let u = bind_table(&u_table, "u");
    let v = bind_table(&v_table, "v");

    // Inner sums of (9): row i of the net restricted in v at mu.
    let mut row_stmts = Vec::new();
    let mut rows: Vec<Vec<TokenStream>> = Vec::new();
    for i in 0..=n {
        let mut row = Vec::new();
        for (mu, v_mu) in v.iter().enumerate() {
            if m == 0 {
                row.push(inputs[i][0].clone());
                continue;
            }
            let items: Vec<(TokenStream, Operand)> = v_mu
                .iter()
                .enumerate()
                .map(|(j, w)| (inputs[i][j].clone(), w.clone()))
                .collect();
            let sum = combination(&items);
            let id = ident(format!("c{i}_v{mu}"));
            let terms: Vec<(Operand, String)> = v_mu
                .iter()
                .enumerate()
                .map(|(j, w)| (w.clone(), input_names[i][j].clone()))
                .collect();
            let doc = format!(
                " c{i}_v{mu} = {}: row {i} restricted in v, shared by every nu",
                reading(&terms)
            );
            row_stmts.push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
            row.push(quote!(#id));
        }
        rows.push(row);
    }
    let mut point_stmts = Vec::new();
    let mut net = Vec::new();
    for (nu, u_nu) in u.iter().enumerate() {
        let mut net_row = Vec::new();
        for mu in 0..=m {
            let items: Vec<(TokenStream, Operand)> = u_nu
                .iter()
                .enumerate()
                .map(|(i, w)| (rows[i][mu].clone(), w.clone()))
                .collect();
            let sum = combination(&items);
            let id = ident(format!("p{nu}_{mu}"));
            let terms: Vec<(Operand, String)> = u_nu
                .iter()
                .enumerate()
                .map(|(i, w)| {
                    (
                        w.clone(),
                        if m == 0 {
                            input_names[i][0].clone()
                        } else {
                            format!("c{i}_v{mu}")
                        },
                    )
                })
                .collect();
            let doc = format!(
                " p_{nu}{mu} = blossom(b^{nu}, a^{}; d^{mu}, c^{}) = {}",
                n - nu,
                m - mu,
                reading(&terms)
            );
            point_stmts.push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
            net_row.push(id);
        }
        net.push(quote!([#(#net_row),*]));
    }
    let pattern = monomials.pattern_names();
    let (pb, pa, pd, pc) = (&pattern[0], &pattern[1], &pattern[2], &pattern[3]);
    let mono_stmts = monomials.statements();
    let mono_doc =
        " Powers and products b^k a^(i-k), d^r c^(j-r) of the rectangle, each computed once.";
    let mono_doc = (!mono_stmts.is_empty()).then(|| quote!(#[doc = #mono_doc]));
    let coef_ty = array_type(&[n + 1, m + 1]);
    let (param, doc) = (quote!(coef), vec![
        format!("Restriction of the power-basis surface S(u, v) = sum_{{i<={n}, j<={m}}} c_ij u^i v^j to the rectangle"),
        "[a, b] x [c, d] (`rect = [a, b, c, d]`): the tensor-product Bézier control points".into(),
        format!("p_(nu mu) = blossom(b^nu, a^({n}-nu); d^mu, c^({m}-mu)) (eq. (6)), computed by Theorem 2,"),
        format!("eq. (9), unrolled for bidegree ({n}, {m}). By (10)-(11) the sum factors into curve weights of (3):"),
        String::new(),
        "p_(nu mu) = sum_i u_(nu i) sum_j v_(mu j) c_ij,".into(),
        format!("u_(nu i) = sum_k C(nu, k) C({n}-nu, i-k) / C({n}, i) b^k a^(i-k),"),
        format!("v_(mu j) = sum_r C(mu, r) C({m}-mu, j-r) / C({m}, j) d^r c^(j-r);"),
        String::new(),
        "the inner sums are shared by every nu. `coef[i][j]` is c_ij; points have `D` coordinates.".into(),
        "Generated by `blossom::restriction!`.".into(),
    ]);
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    Some(quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(#param: &#coef_ty, rect: &[T; 4]) -> #coef_ty {
            let [#pa, #pb, #pc, #pd] = rect;
            #mono_doc
            #(#mono_stmts)*
            #(#weight_stmts)*
            #(#row_stmts)*
            #(#point_stmts)*
            [#(#net),*]
        }
    })
}
