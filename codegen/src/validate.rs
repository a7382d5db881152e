//! Step 2: [`RawInput`] to [`Spec`]. Every problem becomes a `syn::Error` spanning the offending
//! tokens; all problems of one input are reported together.

use crate::model::{RawEntry, RawInput, Shape, Spec};
use proc_macro2::{Span, TokenStream};
use quote::ToTokens;
use syn::{Expr, Ident, Lit, UnOp, Visibility};

const KEYS: &str = "`vis`, `name`, `shape`, `degree`";
const SHAPES: &str =
    "`curve`, `tensor`, `triangle`, `triangle_total`, `bezier_curve`, `bezier_tensor` or `bezier_triangle`";

/// Collects errors so that one expansion reports every problem at once.
#[derive(Default)]
struct Errors(Option<syn::Error>);

impl Errors {
    fn push(&mut self, e: syn::Error) {
        match &mut self.0 {
            Some(all) => all.combine(e),
            None => self.0 = Some(e),
        }
    }
}

/// The value tokens of `entry`, or an error at its `=` when they are empty.
fn nonempty(entry: &RawEntry) -> syn::Result<&TokenStream> {
    if entry.value.is_empty() {
        Err(syn::Error::new(
            entry.eq.spans[0],
            format!("expected a value after `{} =`", entry.key),
        ))
    } else {
        Ok(&entry.value)
    }
}

fn visibility(entry: &RawEntry) -> syn::Result<Visibility> {
    let value = nonempty(entry)?;
    let vis: Visibility = syn::parse2(value.clone()).map_err(|_| {
        syn::Error::new_spanned(value, "expected a visibility such as `pub` or `pub(crate)`")
    })?;
    if matches!(vis, Visibility::Inherited) {
        return Err(syn::Error::new_spanned(
            value,
            "expected a visibility such as `pub` or `pub(crate)`; omit `vis` for a private function",
        ));
    }
    Ok(vis)
}

fn name(entry: &RawEntry) -> syn::Result<Ident> {
    let value = nonempty(entry)?;
    syn::parse2(value.clone()).map_err(|_| {
        syn::Error::new_spanned(
            value,
            "expected the name of the generated function, e.g. `name = restrict_cubic`",
        )
    })
}

/// The shape keyword, checked.
fn shape_keyword(entry: &RawEntry) -> syn::Result<(String, Span)> {
    let value = nonempty(entry)?;
    let ident: Ident = syn::parse2(value.clone())
        .map_err(|_| syn::Error::new_spanned(value, format!("expected a shape: {SHAPES}")))?;
    let kw = ident.to_string();
    if ![
        "curve",
        "tensor",
        "triangle",
        "triangle_total",
        "bezier_curve",
        "bezier_tensor",
        "bezier_triangle",
    ]
    .contains(&kw.as_str())
    {
        return Err(syn::Error::new(
            ident.span(),
            format!("unknown shape `{kw}`: expected {SHAPES}"),
        ));
    }
    Ok((kw, ident.span()))
}

/// One degree: a non-negative integer literal.
fn degree_component(expr: &Expr) -> syn::Result<usize> {
    match expr {
        Expr::Lit(lit) => match &lit.lit {
            Lit::Int(int) => int.base10_parse::<usize>().map_err(|_| {
                syn::Error::new(
                    int.span(),
                    format!("degree `{int}` is not a usable integer"),
                )
            }),
            Lit::Float(f) => Err(syn::Error::new(
                f.span(),
                format!("degree must be a non-negative integer, found `{f}`"),
            )),
            other => Err(syn::Error::new_spanned(
                other,
                "degree must be a non-negative integer literal such as `3`",
            )),
        },
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Err(syn::Error::new_spanned(
            expr,
            format!(
                "degree must be non-negative, found `{}`",
                expr.to_token_stream()
            ),
        )),
        Expr::Paren(p) => degree_component(&p.expr),
        Expr::Group(g) => degree_component(&g.expr),
        _ => Err(syn::Error::new_spanned(
            expr,
            "degree must be an integer literal such as `3`: the formula is unrolled when the \
             macro expands, so constants and expressions cannot be used",
        )),
    }
}

/// The degree value: `3` or `(3, 2)`.
fn degrees(entry: &RawEntry) -> syn::Result<(Vec<usize>, TokenStream)> {
    let value = nonempty(entry)?;
    let expr: Expr = syn::parse2(value.clone()).map_err(|_| {
        syn::Error::new_spanned(value, "expected a degree: `3`, or `(3, 2)` for a surface")
    })?;
    let parts: Vec<&Expr> = match &expr {
        Expr::Tuple(t) => t.elems.iter().collect(),
        other => vec![other],
    };
    let mut errors = Errors::default();
    let mut out = Vec::new();
    for part in parts {
        match degree_component(part) {
            Ok(d) => out.push(d),
            Err(e) => errors.push(e),
        }
    }
    match errors.0 {
        Some(e) => Err(e),
        None => Ok((out, value.clone())),
    }
}

/// Checks the raw entries and builds the [`Spec`].
pub fn validate(raw: RawInput) -> syn::Result<Spec> {
    let mut errors = Errors::default();
    let (mut vis, mut name_entry, mut shape_entry, mut degree_entry) = (None, None, None, None);
    for entry in raw.entries {
        let slot = match entry.key.to_string().as_str() {
            "vis" => &mut vis,
            "name" => &mut name_entry,
            "shape" => &mut shape_entry,
            "degree" => &mut degree_entry,
            other => {
                errors.push(syn::Error::new(
                    entry.key.span(),
                    format!("unknown key `{other}`: expected one of {KEYS}"),
                ));
                continue;
            }
        };
        if slot.is_some() {
            errors.push(syn::Error::new(
                entry.key.span(),
                format!("duplicate key `{}`: each key may be given once", entry.key),
            ));
            continue;
        }
        *slot = Some(entry);
    }
    let missing = |key: &str, example: &str| {
        syn::Error::new(
            Span::call_site(),
            format!("missing key `{key}`: add `{key} = {example}`"),
        )
    };
    let vis = match vis.as_ref().map(visibility).transpose() {
        Ok(v) => v.unwrap_or(Visibility::Inherited),
        Err(e) => {
            errors.push(e);
            Visibility::Inherited
        }
    };
    let name = match name_entry.as_ref().map(name) {
        Some(Ok(n)) => Some(n),
        Some(Err(e)) => {
            errors.push(e);
            None
        }
        None => {
            errors.push(missing("name", "restrict_cubic"));
            None
        }
    };
    let kw = match shape_entry.as_ref().map(shape_keyword) {
        Some(Ok(k)) => Some(k),
        Some(Err(e)) => {
            errors.push(e);
            None
        }
        None => {
            errors.push(missing("shape", "curve"));
            None
        }
    };
    let degree = match degree_entry.as_ref().map(degrees) {
        Some(Ok(d)) => Some(d),
        Some(Err(e)) => {
            errors.push(e);
            None
        }
        None => {
            errors.push(missing("degree", "3"));
            None
        }
    };
    let mut shape = None;
    if let (Some((kw, _)), Some((ds, tokens))) = (&kw, &degree) {
        let made = match (kw.as_str(), ds.as_slice()) {
            ("curve", &[n]) => Ok(Shape::Curve(n)),
            ("tensor", &[n, m]) => Ok(Shape::Tensor(n, m)),
            ("triangle", &[n, m]) => Ok(Shape::Triangle(n, m)),
            ("bezier_curve", &[n]) => Ok(Shape::BezierCurve(n)),
            ("bezier_tensor", &[n, m]) => Ok(Shape::BezierTensor(n, m)),
            ("bezier_triangle", &[n]) => Ok(Shape::BezierTriangle(n)),
            ("triangle_total", &[n]) => Ok(Shape::TriangleTotal(n)),
            ("curve" | "bezier_curve", _) => Err("a curve has one degree, as in `degree = 3`"),
            ("tensor" | "bezier_tensor", _) => {
                Err("a tensor patch has a degree in u and one in v, as in `degree = (3, 2)`")
            }
            ("bezier_triangle", _) => {
                Err("a triangular Bézier patch has one total degree N, as in `degree = 3`")
            }
            ("triangle_total", _) => {
                Err("a triangular array has one total degree N, as in `degree = 3`")
            }
            _ => Err(
                "a triangular patch takes the degrees (n, m) of u and v, as in `degree = (3, 2)`",
            ),
        };
        match made.map_err(|msg| syn::Error::new_spanned(tokens, msg)) {
            Ok(s) => match s.check_limit() {
                Ok(()) => shape = Some(s),
                Err(msg) => errors.push(syn::Error::new_spanned(tokens, msg)),
            },
            Err(e) => errors.push(e),
        }
    }
    if let Some(e) = errors.0 {
        return Err(e);
    }
    Ok(Spec {
        attrs: raw.attrs,
        vis,
        name: name.expect("no error, so the name was read"),
        shape: shape.expect("no error, so the shape was read"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse;
    use quote::quote;

    fn check(tokens: TokenStream) -> Result<Spec, String> {
        parse(tokens).and_then(validate).map_err(|e| {
            e.into_iter()
                .map(|e| e.to_string())
                .collect::<Vec<_>>()
                .join(" | ")
        })
    }

    #[test]
    fn a_full_input_validates() {
        let spec = check(quote!(vis = pub, name = cubic, shape = curve, degree = 3)).unwrap();
        assert_eq!(spec.shape, Shape::Curve(3));
        assert_eq!(spec.name, "cubic");
        let spec = check(quote!(name = t, shape = triangle, degree = (3, 2),)).unwrap();
        assert_eq!(spec.shape, Shape::Triangle(3, 2));
        assert!(matches!(spec.vis, Visibility::Inherited));
    }

    #[test]
    fn every_problem_is_reported() {
        assert_eq!(
            check(quote!(name = f, shape = curve)).unwrap_err(),
            "missing key `degree`: add `degree = 3`"
        );
        assert_eq!(
            check(quote!(name = f, name = g, shape = curve, degree = 3)).unwrap_err(),
            "duplicate key `name`: each key may be given once"
        );
        assert_eq!(
            check(quote!(nme = f, shape = circle, degree = -1)).unwrap_err(),
            "unknown key `nme`: expected one of `vis`, `name`, `shape`, `degree` \
             | missing key `name`: add `name = restrict_cubic` \
             | unknown shape `circle`: expected `curve`, `tensor`, `triangle`, `triangle_total`, `bezier_curve`, `bezier_tensor` or `bezier_triangle` \
             | degree must be non-negative, found `- 1`"
        );
        assert_eq!(
            check(quote!(name = f, shape = tensor, degree = 3)).unwrap_err(),
            "a tensor patch has a degree in u and one in v, as in `degree = (3, 2)`"
        );
        assert!(check(quote!(name = f, shape = curve, degree = 2.5))
            .unwrap_err()
            .contains("non-negative integer, found `2.5`"));
        assert!(check(quote!(name = f, shape = curve, degree = 99))
            .unwrap_err()
            .contains("above the limit"));
        assert!(check(quote!(name = f, shape = curve, degree = N))
            .unwrap_err()
            .contains("integer literal"));
        assert!(check(quote!(vis = , name = f, shape = curve, degree = 1))
            .unwrap_err()
            .contains("expected a value after `vis =`"));
    }
}
