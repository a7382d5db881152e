//! Bézier curves by halving the blossom: Theorem 1, eq. (3), in the form it takes for a
//! Bézier polygon, evaluated so that the outputs share their work.
//!
//! With c_i = C(n, i) Δ^i b_0 (forward differences, [`differences`](super::differences)), the
//! inner sum of (3) times C(n, i) is the elementary symmetric function e_i of the arguments,
//! so the blossom of the curve is
//!
//! f(u_1, ..., u_n) = sum_i Δ^i b_0 e_i(u_1, ..., u_n).
//!
//! Fixing k arguments at one value c leaves a blossom of the same form in the others, since
//! e_i(c^k, u') = sum_l C(k, l) c^l e_(i-l)(u'):
//!
//! f(c^k, u') = sum_j G_j e_j(u'),  G_j = sum_(l=0..k) C(k, l) c^l Δ^(j+l) b_0.
//!
//! The control points w_v = f(b^v, a^(n-v)) split in two halves: with h = floor(n / 2),
//! w_0..w_h have at least n - h arguments a, so they are the restriction to [a, b] of the
//! degree-h blossom f(a^(n-h), ·), and w_(h+1)..w_n that of the degree-(n-h-1) blossom
//! f(b^(h+1), ·). Each half is split again, down to degree 0, where the blossom is its own
//! single coefficient. That is about n^2 multiply-adds per coordinate, like (3) term by term,
//! but the only scalars are the C(k, l) a^l and C(k, l) b^l of O(log n) sizes k, instead of
//! one weight per pair (v, i).

use super::{
    array_type, combination, differences, fn_attrs, ident, reading, Monomials, Operand, Term,
    Weight,
};
use crate::constants::{binomial, Frac};
use crate::model::Spec;
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::HashMap;

/// The end point a half is pinned to.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum End {
    A,
    B,
}

impl End {
    fn name(self) -> &'static str {
        match self {
            End::A => "a",
            End::B => "b",
        }
    }

    /// Exponents over the monomial parameters `[b, a]`.
    fn exps(self, l: usize) -> Vec<u32> {
        match self {
            End::A => vec![0, l as u32],
            End::B => vec![l as u32, 0],
        }
    }
}

/// A blossom in the form sum_j G_j e_j: its coefficient points and their names for docs.
struct Coefficients {
    points: Vec<TokenStream>,
    names: Vec<String>,
}

/// The emission state: the scalars C(k, l) c^l, bound once each, and the point statements.
struct Halving {
    monomials: Monomials,
    scalar_stmts: Vec<TokenStream>,
    scalars: HashMap<(End, usize, usize), Operand>,
    point_stmts: Vec<TokenStream>,
    /// The control points w_v in order, as bound identifiers.
    outputs: Vec<TokenStream>,
}

impl Halving {
    /// C(k, l) c^l as an operand; `None` on constant overflow.
    fn scalar(&mut self, end: End, k: usize, l: usize) -> Option<Operand> {
        if let Some(op) = self.scalars.get(&(end, k, l)) {
            return Some(op.clone());
        }
        let count = binomial(k as u64, l as u64)?;
        let weight = Weight {
            terms: vec![Term {
                k: Frac::new(count, 1)?,
                exps: end.exps(l),
            }],
        };
        let mono = self.monomials.ident_name(&end.exps(l));
        let comment = format!(
            "{mono}_x{count} = C({k},{l}) {}",
            self.monomials.display(&end.exps(l))
        );
        let op = weight.bind(
            &format!("{mono}_x{count}"),
            &comment,
            &mut self.monomials,
            &mut self.scalar_stmts,
        );
        self.scalars.insert((end, k, l), op.clone());
        Some(op)
    }

    /// Appends w_(first)..w_(first + degree) of the blossom `f` (of degree
    /// `f.points.len() - 1`, with the arguments `args` already fixed) to the outputs; `path`
    /// names its intermediate coefficients.
    fn restrict(
        &mut self,
        f: &Coefficients,
        args: &[String],
        first: usize,
        path: &str,
    ) -> Option<()> {
        let degree = f.points.len() - 1;
        if degree == 0 {
            let (id, point) = (ident(format!("w{first}")), &f.points[0]);
            let doc = format!(" w{first} = {}", f.names[0]);
            self.point_stmts
                .push(quote!(#[doc = #doc] let #id: [T; D] = #point.clone();));
            self.outputs.push(quote!(#id));
            return Some(());
        }
        let h = degree / 2;
        // (end, number of arguments fixed, degree left, index of its first output)
        let halves = [
            (End::A, degree - h, h, first),
            (End::B, h + 1, degree - h - 1, first + h + 1),
        ];
        for (end, k, left, start) in halves {
            let sub_path = format!("{path}{}", end.name());
            let mut sub_args = args.to_vec();
            sub_args.push(if k == 1 {
                end.name().to_string()
            } else {
                format!("{}^{k}", end.name())
            });
            let mut half = Coefficients {
                points: Vec::new(),
                names: Vec::new(),
            };
            for j in 0..=left {
                let terms = (0..=k)
                    .map(|l| Some((f.points[j + l].clone(), self.scalar(end, k, l)?, l)))
                    .collect::<Option<Vec<_>>>()?;
                let items: Vec<(TokenStream, Operand)> = terms
                    .iter()
                    .map(|(p, w, _)| (p.clone(), w.clone()))
                    .collect();
                let read: Vec<(Operand, String)> = terms
                    .iter()
                    .map(|(_, w, l)| (w.clone(), f.names[j + l].clone()))
                    .collect();
                let sum = combination(&items);
                // A half of degree 0 is a control point: bind it under its final name.
                let (name, doc) = if left == 0 {
                    let name = format!("w{start}");
                    let doc = format!(" {name} = f({}) = {}", sub_args.join(", "), reading(&read));
                    (name, doc)
                } else {
                    let name = format!("g{sub_path}_{j}");
                    let doc = format!(
                        " {name} = {}: the coefficient of e_{j} in f({}, ·)",
                        reading(&read),
                        sub_args.join(", ")
                    );
                    (name, doc)
                };
                let id = ident(name.clone());
                self.point_stmts
                    .push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
                half.points.push(quote!(#id));
                half.names.push(name);
            }
            if left == 0 {
                self.outputs.push(half.points[0].clone());
            } else {
                self.restrict(&half, &sub_args, start, &sub_path)?;
            }
        }
        Some(())
    }
}

/// The generated function for a Bézier curve of degree `n` over [0, 1].
pub fn expand(spec: &Spec, n: usize) -> Option<TokenStream> {
    let mut diff_stmts = Vec::new();
    let top = Coefficients {
        points: differences::curve(n, &mut diff_stmts),
        names: (0..=n).map(|i| format!("Δ^{i} b_0")).collect(),
    };
    let mut state = Halving {
        monomials: Monomials::new(&["b", "a"]),
        scalar_stmts: Vec::new(),
        scalars: HashMap::new(),
        point_stmts: Vec::new(),
        outputs: Vec::new(),
    };
    state.restrict(&top, &[], 0, "")?;
    let unused = state.monomials.none_used().then(|| quote!(let _ = (a, b);));
    let mono_stmts = state.monomials.statements();
    let scalar_stmts = &state.scalar_stmts;
    let point_stmts = &state.point_stmts;
    let outputs = &state.outputs;
    let ty = array_type(&[n + 1]);
    let h = n / 2;
    let doc = vec![
        format!("Restriction of the Bézier curve of degree {n} over [0, 1] with control points `ctrl` to the"),
        format!("interval [a, b]: the control points w_v = blossom(b^v, a^({n}-v)), v = 0..={n}. With"),
        "c_i = C(n, i) Δ^i b_0, Theorem 1, eq. (3), gives the blossom f(u) = sum_i Δ^i b_0 e_i(u)".into(),
        "(e_i the elementary symmetric functions), and fixing k arguments at c leaves".into(),
        String::new(),
        "f(c^k, u') = sum_j G_j e_j(u'),  G_j = sum_l C(k, l) c^l Δ^(j+l) b_0.".into(),
        String::new(),
        format!("So w_0..w_h (h = floor(n/2) = {h}) restrict the blossom f(a^(n-h), ·), and w_(h+1)..w_n"),
        format!("restrict f(b^(h+1), ·); each half is halved again down to degree 0. Unrolled for degree {n};"),
        "integer constants only.".into(),
        "`ctrl[i]` is b_i; points have `D` coordinates. Generated by `blossom::restriction!`.".into(),
    ];
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    Some(quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(ctrl: &#ty, a: &T, b: &T) -> #ty {
            #unused
            #(#diff_stmts)*
            #(#mono_stmts)*
            #(#scalar_stmts)*
            #(#point_stmts)*
            [#(#outputs),*]
        }
    })
}
