//! Step 3: [`Spec`] to tokens. One module per formula ([`curve`]: eq. (3), [`tensor`]: eq. (9),
//! [`triangle`]: eq. (14); [`casteljau`]: Bézier shapes by de Casteljau's steps with shared
//! work) on top of two shared builders (used by the power-basis formulae):
//!
//! * [`Monomials`]: products of powers of the domain parameters, each bound once by a `let`
//!   (one `mul` per binding: `ap3 = ap2 * a`, `bp2_a = bp2 * a`, ...) and shared by every weight
//!   that needs it;
//! * [`Weight`]: a weight is a sum of monomials times folded rational constants (never a zero
//!   term; constant 1 skips `scale_frac`), bound once and shared by the coordinates of a point.
//!
//! Points are built per coordinate with `core::array::from_fn` over the `D` coordinates: the
//! only iteration in the generated code runs over coordinates, never over degree indices.

pub mod casteljau;
pub mod curve;
pub mod tensor;
pub mod triangle;

use crate::constants::Frac;
use crate::model::{Shape, Spec};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};
use std::collections::{BTreeSet, HashSet};

/// Expands a validated [`Spec`] into the item it stands for.
///
/// Fails only when a folded constant would not fit in `i128`, which the degree limits exclude.
pub fn expand(spec: &Spec) -> syn::Result<TokenStream> {
    let body = match spec.shape {
        Shape::Curve(n) => curve::expand(spec, n),
        Shape::Tensor(n, m) => tensor::expand(spec, n, m),
        Shape::Triangle(n, m) => triangle::expand(spec, n, m),
        Shape::TriangleTotal(n) => triangle::expand_total(spec, n),
        Shape::BezierCurve(n) => Some(casteljau::curve(spec, n)),
        Shape::BezierTensor(n, m) => Some(casteljau::tensor(spec, n, m)),
        Shape::BezierTriangle(n) => Some(casteljau::triangle(spec, n)),
    };
    body.ok_or_else(|| {
        syn::Error::new(
            spec.name.span(),
            format!("a constant of {} does not fit in i128", spec.shape),
        )
    })
}

/// How generated code refers to a scalar factor.
#[derive(Clone, Debug)]
pub enum Operand {
    /// The constant 1 (the empty monomial).
    One,
    /// A domain parameter, already a `&T` in the generated code (`a`, `b1`, ...).
    Param(Ident),
    /// A `let`-bound value of type `T`.
    Bound(Ident),
}

impl Operand {
    /// The operand as a method receiver: `a` or `ap2`.
    fn recv(&self) -> TokenStream {
        match self {
            Operand::One => quote!(T::one()),
            Operand::Param(id) | Operand::Bound(id) => quote!(#id),
        }
    }
    /// The operand as a `&T` argument: `a` or `&ap2`.
    fn by_ref(&self) -> TokenStream {
        match self {
            Operand::One => quote!(&T::one()),
            Operand::Param(id) => quote!(#id),
            Operand::Bound(id) => quote!(&#id),
        }
    }
    /// The operand as an owned `T`.
    fn owned(&self) -> TokenStream {
        match self {
            Operand::One => quote!(T::one()),
            Operand::Param(id) | Operand::Bound(id) => quote!(#id.clone()),
        }
    }
    fn is_one(&self) -> bool {
        matches!(self, Operand::One)
    }
}

/// The sum `w_0 p_0 + w_1 p_1 + ...` for a doc comment, weights by name (`1` omitted).
pub fn reading(items: &[(Operand, String)]) -> String {
    items
        .iter()
        .map(|(w, p)| match w {
            Operand::One => p.clone(),
            Operand::Param(id) | Operand::Bound(id) => format!("{id} {p}"),
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The products of powers of the domain parameters, bound once each.
pub struct Monomials {
    /// Parameter names in the order of the paper's monomials (`b, a` for b^k a^(i-k)).
    names: Vec<&'static str>,
    /// Which parameters occur in some emitted monomial.
    used: Vec<bool>,
    seen: HashSet<Vec<u32>>,
    stmts: Vec<TokenStream>,
}

impl Monomials {
    /// A registry over the parameters `names`.
    pub fn new(names: &[&'static str]) -> Self {
        Monomials {
            names: names.to_vec(),
            used: vec![false; names.len()],
            seen: HashSet::new(),
            stmts: Vec::new(),
        }
    }

    /// The readable name of a monomial, e.g. `bp2_a` for b^2 a, `a1p2_b2` for a1^2 b2.
    pub fn ident_name(&self, exps: &[u32]) -> String {
        exps.iter()
            .zip(&self.names)
            .filter(|(e, _)| **e > 0)
            .map(|(&e, v)| {
                if e == 1 {
                    (*v).to_string()
                } else {
                    format!("{v}p{e}")
                }
            })
            .collect::<Vec<_>>()
            .join("_")
    }

    /// The human-readable monomial for comments, e.g. `b^2 a`.
    pub fn display(&self, exps: &[u32]) -> String {
        let s = exps
            .iter()
            .zip(&self.names)
            .filter(|(e, _)| **e > 0)
            .map(|(&e, v)| {
                if e == 1 {
                    (*v).to_string()
                } else {
                    format!("{v}^{e}")
                }
            })
            .collect::<Vec<_>>()
            .join(" ");
        if s.is_empty() {
            "1".into()
        } else {
            s
        }
    }

    /// The operand for the monomial with exponents `exps`, binding it (and the prefixes and
    /// powers it is built from) on first use. Each binding costs one multiplication.
    pub fn get(&mut self, exps: &[u32]) -> Operand {
        let nonzero: Vec<usize> = (0..exps.len()).filter(|&v| exps[v] > 0).collect();
        match nonzero.as_slice() {
            [] => return Operand::One,
            &[v] if exps[v] == 1 => {
                self.used[v] = true;
                return Operand::Param(Ident::new(self.names[v], Span::call_site()));
            }
            _ => {}
        }
        let id = Ident::new(&self.ident_name(exps), Span::call_site());
        if self.seen.contains(exps) {
            return Operand::Bound(id);
        }
        let last = *nonzero.last().expect("non-empty");
        let (left, right) = if nonzero.len() == 1 {
            // A power: v^e = v^(e-1) * v.
            let mut prev = exps.to_vec();
            prev[last] -= 1;
            let mut one = vec![0; exps.len()];
            one[last] = 1;
            (self.get(&prev), self.get(&one))
        } else {
            // A product: (all factors but the last) * (the last factor's power).
            let mut prefix = exps.to_vec();
            prefix[last] = 0;
            let mut tail = vec![0; exps.len()];
            tail[last] = exps[last];
            (self.get(&prefix), self.get(&tail))
        };
        let (recv, arg) = (left.recv(), right.by_ref());
        self.stmts.push(quote!(let #id = #recv.mul(#arg);));
        self.seen.insert(exps.to_vec());
        Operand::Bound(id)
    }

    /// Binds every monomial of `all` in a readable order (fewer factors first, then lower
    /// degree, then the paper's parameter order), so powers come before products.
    pub fn bind_all(&mut self, all: &BTreeSet<Vec<u32>>) {
        let mut order: Vec<&Vec<u32>> = all.iter().collect();
        order.sort_by_key(|e| {
            let factors = e.iter().filter(|&&x| x > 0).count();
            (
                factors,
                e.iter().sum::<u32>(),
                std::cmp::Reverse((*e).clone()),
            )
        });
        for exps in order {
            self.get(exps);
        }
    }

    /// The `let` statements, in dependency order.
    pub fn statements(&self) -> &[TokenStream] {
        &self.stmts
    }

    /// The parameter names with unused ones replaced by `_` (for destructuring patterns).
    pub fn pattern_names(&self) -> Vec<TokenStream> {
        self.names
            .iter()
            .zip(&self.used)
            .map(|(n, &u)| {
                if u {
                    let id = Ident::new(n, Span::call_site());
                    quote!(#id)
                } else {
                    quote!(_)
                }
            })
            .collect()
    }

    /// Whether no parameter is used at all (degree 0).
    pub fn none_used(&self) -> bool {
        !self.used.iter().any(|&u| u)
    }
}

/// One term of a weight: a folded constant times a monomial.
pub struct Term {
    /// The reduced constant, e.g. 2/3.
    pub k: Frac,
    /// Exponents of the monomial.
    pub exps: Vec<u32>,
}

/// A scalar weight: the coefficient of one input point c_i (or c_ij) in one control point.
pub struct Weight {
    /// The terms, each with a distinct monomial and a non-zero constant.
    pub terms: Vec<Term>,
}

impl Weight {
    /// The weight as an operand: a shared monomial when it is one monomial with constant 1,
    /// otherwise a new binding `name` (pushed to `stmts`, preceded by its `comment`).
    pub fn bind(
        &self,
        name: &str,
        comment: &str,
        monomials: &mut Monomials,
        stmts: &mut Vec<TokenStream>,
    ) -> Operand {
        if let [t] = self.terms.as_slice() {
            if t.k.is_one() {
                return monomials.get(&t.exps);
            }
        }
        // Terms with a constant other than 1 first, so the sum starts without a clone.
        let mut terms: Vec<(Frac, Operand)> = self
            .terms
            .iter()
            .map(|t| (t.k, monomials.get(&t.exps)))
            .collect();
        terms.sort_by_key(|(k, _)| k.is_one());
        let scaled = |k: Frac, op: &Operand| {
            let recv = op.recv();
            if (k.num, k.den) == (2, 1) {
                // Doubling by an addition: exact in every ring, and cheaper than a scaling
                // (no constant to convert for floats, no multiplication for big numbers).
                let arg = op.by_ref();
                return quote!(#recv.add(#arg));
            }
            let (p, q) = (
                Literal::i128_unsuffixed(k.num),
                Literal::i128_unsuffixed(k.den),
            );
            quote!(#recv.scale_frac(#p, #q))
        };
        let first = match &terms[0] {
            (k, op) if k.is_one() => op.owned(),
            (k, op) => scaled(*k, op),
        };
        // One `quote!` for the whole chain: re-quoting a growing expression term by term
        // would be quadratic (and slow through the proc-macro bridge).
        let rest = terms[1..].iter().map(|(k, op)| {
            if k.is_one() {
                op.by_ref()
            } else {
                let s = scaled(*k, op);
                quote!(&#s)
            }
        });
        let expr = quote!(#first #(.add(#rest))*);
        let id = Ident::new(name, Span::call_site());
        let comment = format!(" {comment}");
        stmts.push(quote!(#[doc = #comment] let #id = #expr;));
        Operand::Bound(id)
    }
}

/// `core::array::from_fn(|x| sum_k weight_k * point_k[x])`: one point of `D` coordinates as a
/// linear combination of points (`coef[i]`, `coef[i][j]` or a bound row), weights shared.
pub fn combination(items: &[(TokenStream, Operand)]) -> TokenStream {
    let mut items: Vec<&(TokenStream, Operand)> = items.iter().collect();
    items.sort_by_key(|(_, w)| w.is_one());
    let (first_point, first_weight) = items[0];
    let first = if first_weight.is_one() {
        quote!(#first_point[x].clone())
    } else {
        let w = first_weight.by_ref();
        quote!(#first_point[x].mul(#w))
    };
    let rest = items[1..].iter().map(|(point, weight)| {
        if weight.is_one() {
            quote!(&#point[x])
        } else {
            let w = weight.by_ref();
            quote!(&#point[x].mul(#w))
        }
    });
    quote!(::core::array::from_fn(|x| #first #(.add(#rest))*))
}

/// `coef[i]` or `coef[i][j]` as tokens.
pub fn coef(indices: &[usize]) -> TokenStream {
    let idx = indices.iter().map(|&i| Literal::usize_unsuffixed(i));
    quote!(coef #([#idx])*)
}

/// `[T; D]` nested in arrays of the given lengths, outermost first.
pub fn array_type(lengths: &[usize]) -> TokenStream {
    let mut ty = quote!([T; D]);
    for &len in lengths.iter().rev() {
        let len = Literal::usize_unsuffixed(len);
        ty = quote!([#ty; #len]);
    }
    ty
}

/// The attributes every generated function carries: the user's first, then the doc lines,
/// then the lint allowances (generated code names values after the paper, and the doc
/// comments on `let` statements are there for the reader of the expansion).
///
/// The function is `#[inline]` unless the user gave an `inline` attribute of their own: it is
/// straight-line arithmetic meant for hot loops, where the call and the return of the control
/// points through memory cost as much as the arithmetic of a small degree (measured: the cubic
/// Bézier of `benches/peers.rs` takes 8.5 ns called, 6.6 ns inlined). It is a hint; the
/// optimiser still weighs the size of a large degree.
pub fn fn_attrs(spec: &Spec, doc: &[String]) -> TokenStream {
    let user = &spec.attrs;
    let inline = (!user.iter().any(|a| a.path().is_ident("inline"))).then(|| quote!(#[inline]));
    let sep = (!user.is_empty()).then(|| quote!(#[doc = ""]));
    let doc: Vec<String> = doc
        .iter()
        .map(|line| {
            if line.is_empty() {
                String::new()
            } else {
                format!(" {line}")
            }
        })
        .collect();
    quote! {
        #(#user)*
        #sep
        #(#[doc = #doc])*
        #[allow(
            unused_doc_comments,
            clippy::similar_names,
            clippy::many_single_char_names,
            clippy::too_many_lines,
            clippy::too_many_arguments,
            clippy::unreadable_literal
        )]
        #inline
    }
}

/// An identifier from a formatted name.
pub fn ident(name: String) -> Ident {
    format_ident!("{}", name)
}

#[cfg(test)]
mod tests {
    use crate::{format_items, restriction};
    use quote::quote;

    fn generated(input: proc_macro2::TokenStream) -> String {
        format_items(restriction(input))
    }

    #[test]
    fn the_function_is_inline_unless_the_user_says_otherwise() {
        let plain = generated(quote!(name = f, shape = bezier_curve, degree = 3));
        assert_eq!(plain.matches("#[inline]").count(), 1, "{plain}");
        let never = generated(quote!(
            #[inline(never)]
            name = f,
            shape = curve,
            degree = 2
        ));
        assert!(never.contains("#[inline(never)]"), "{never}");
        assert!(!never.contains("#[inline]\n"), "{never}");
    }
}
