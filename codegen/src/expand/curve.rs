//! Theorem 1, eq. (3), unrolled for one degree `n`:
//!
//! w_v = sum_{i=0}^n c_i / C(n, i) sum_{k=max(0, i+v-n)}^{min(i, v)} C(v, k) C(n-v, i-k) b^k a^(i-k).
//!
//! The inner sum is the weight `wV_cI` of c_i in w_v: computed once per (v, i) from the shared
//! monomials b^k a^(i-k), with the constant C(v, k) C(n-v, i-k) / C(n, i) folded and reduced.

use super::{
    array_type, coef, combination, fn_attrs, ident, reading, Monomials, Operand, Term, Weight,
};
use crate::constants::{binomial, Frac};
use crate::model::Spec;
use proc_macro2::TokenStream;
use quote::quote;

/// The weight of c_i in w_v (the inner sum of eq. (3)) over the parameters `hi` (b, at
/// `offset`) and `lo` (a, at `offset + 1`) of a monomial vector of length `width`; with its
/// unreduced reading for the comment. `None` on constant overflow.
pub fn weight(
    n: usize,
    v: usize,
    i: usize,
    offset: usize,
    width: usize,
    (hi, lo): (&str, &str),
) -> Option<(Weight, String)> {
    let (n64, v64, i64_) = (n as u64, v as u64, i as u64);
    let den = binomial(n64, i64_)?;
    let mut terms = Vec::new();
    let mut reading = Vec::new();
    for k in (i + v).saturating_sub(n)..=i.min(v) {
        let k64 = k as u64;
        let count = binomial(v64, k64)?.checked_mul(binomial(n64 - v64, i64_ - k64)?)?;
        if count == 0 {
            continue; // never happens within the bounds of (3); a zero term is never emitted
        }
        let mut exps = vec![0; width];
        exps[offset] = k as u32;
        exps[offset + 1] = (i - k) as u32;
        terms.push(Term {
            k: Frac::new(count, den)?,
            exps,
        });
        let mono = match (k, i - k) {
            (0, 0) => "1".to_string(),
            (k, 0) => power(hi, k),
            (0, j) => power(lo, j),
            (k, j) => format!("{} {}", power(hi, k), power(lo, j)),
        };
        reading.push(format!("C({v},{k}) C({},{}) {mono}", n - v, i - k));
    }
    let reading = format!("({}) / C({n},{i})", reading.join(" + "));
    Some((Weight { terms }, reading))
}

fn power(x: &str, e: usize) -> String {
    if e == 1 {
        x.to_string()
    } else {
        format!("{x}^{e}")
    }
}

/// The generated function for a power-basis curve of degree `n`. (Bézier curves have their
/// own evaluation order, [`casteljau`](super::casteljau).)
pub fn expand(spec: &Spec, n: usize) -> Option<TokenStream> {
    let table = (0..=n)
        .map(|v| {
            (0..=n)
                .map(|i| weight(n, v, i, 0, 2, ("b", "a")))
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    let (inputs, input_names): (Vec<TokenStream>, Vec<String>) =
        (0..=n).map(|i| (coef(&[i]), format!("c_{i}"))).unzip();
    let mut monomials = Monomials::new(&["b", "a"]);
    monomials.bind_all(
        &table
            .iter()
            .flatten()
            .flat_map(|(w, _)| w.terms.iter().map(|t| t.exps.clone()))
            .collect(),
    );
    let mut weight_stmts = Vec::new();
    // weights[v][i]: the operand of c_i's weight in w_v.
    let mut weights: Vec<Vec<Operand>> = Vec::new();
    for (v, row_table) in table.iter().enumerate() {
        let mut row = Vec::new();
        for (i, (w, reading)) in row_table.iter().enumerate() {
            let name = format!("w{v}_c{i}");
            row.push(w.bind(
                &name,
                &format!("{name} = {reading}"),
                &mut monomials,
                &mut weight_stmts,
            ));
        }
        weights.push(row);
    }
    let mut point_stmts = Vec::new();
    let mut points = Vec::new();
    for (v, row) in weights.iter().enumerate() {
        let items: Vec<(TokenStream, Operand)> = row
            .iter()
            .enumerate()
            .map(|(i, w)| (inputs[i].clone(), w.clone()))
            .collect();
        let sum = combination(&items);
        let id = ident(format!("w{v}"));
        let terms: Vec<(Operand, String)> = row
            .iter()
            .zip(&input_names)
            .map(|(w, name)| (w.clone(), name.clone()))
            .collect();
        let doc = format!(" w_{v} = blossom(b^{v}, a^{}) = {}", n - v, reading(&terms));
        point_stmts.push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
        points.push(id);
    }
    let unused = monomials.none_used().then(|| quote!(let _ = (a, b);));
    let mono_doc =
        " Powers and products b^k a^(i-k) of the end points, each computed once (eq. (3)).";
    let mono_stmts = monomials.statements();
    let mono_doc = (!mono_stmts.is_empty()).then(|| quote!(#[doc = #mono_doc]));
    // (The doc attribute attaches to the first monomial binding.)
    let ty = array_type(&[n + 1]);
    let doc = vec![
        format!("Restriction of the power-basis curve C(u) = sum_{{i=0}}^{n} c_i u^i to the interval [a, b]:"),
        format!("the Bézier control points w_v = blossom(b^v, a^({n}-v)), v = 0..={n} (eq. (1)), computed"),
        format!("by Theorem 1, eq. (3), unrolled for degree {n}:"),
        String::new(),
        format!("w_v = sum_i c_i / C({n}, i) sum_{{k=max(0, i+v-{n})}}^{{min(i, v)}} C(v, k) C({n}-v, i-k) b^k a^(i-k)."),
        String::new(),
        "`coef[i]` is c_i; points have `D` coordinates. Generated by `blossom::restriction!`.".into(),
    ];
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    Some(quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(coef: &#ty, a: &T, b: &T) -> #ty {
            #unused
            #mono_doc
            #(#mono_stmts)*
            #(#weight_stmts)*
            #(#point_stmts)*
            [#(#points),*]
        }
    })
}
