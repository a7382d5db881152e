//! The expansion engine behind `blossom::restriction!`: the closed-form blossom formulae (3),
//! (9) and (14) of the subdivision paper unrolled, for one fixed degree, into a Rust function.
//!
//! A proc-macro crate cannot export ordinary functions, so the pipeline lives here and is used
//! twice: by `blossom-macros` (a thin `#[proc_macro]` wrapper) at compile time, and by the
//! `blossom` binary (`blossom expand curve 3`, crate `blossom-cli`) at run time, so the code
//! printed by the binary is exactly the code the macro generates. The formatting to text
//! (`format_items`, `source`) needs prettyplease and is behind the feature `pretty`, which
//! the macro does not use.
//!
//! The pipeline, one module per step:
//!
//! 1. [`parse()`] (module [`mod@parse`]): tokens to a plain [`RawInput`] of `key = value`
//!    entries;
//! 2. [`validate()`] (module [`mod@validate`]): to a [`Spec`], every error a `syn::Error`
//!    spanning the offending tokens;
//! 3. [`expand()`] (module [`mod@expand`]): to a `proc_macro2::TokenStream`, by one module per
//!    formula.
//!
//! ```
//! # #[cfg(feature = "pretty")] {
//! use blossom_codegen::{source, Shape, Spec};
//!
//! let code = source(&Spec::public(Shape::Curve(2)));
//! assert!(code.contains("pub fn restrict_curve_2<T: ::blossom::Ring, const D: usize>("));
//! // w_1 = blossom(b, a): the weight of c_2 is a b, no constant; that of c_1 is (a + b) / 2.
//! assert!(code.contains("let w1_c1 = a.scale_frac(1, 2).add(&b.scale_frac(1, 2));"));
//! # }
//! ```
#![forbid(unsafe_code)]

pub mod constants;
pub mod expand;
pub mod model;
pub mod parse;
pub mod validate;

pub use expand::expand;
pub use model::{
    RawEntry, RawInput, Shape, Spec, MAX_CURVE_DEGREE, MAX_TENSOR_DEGREE, MAX_TRIANGLE_DEGREE,
};
pub use parse::parse;
pub use validate::validate;

use proc_macro2::TokenStream;

/// The whole pipeline, as the proc macro runs it: the generated function, or
/// `compile_error!` invocations spanning every offending token.
pub fn restriction(input: TokenStream) -> TokenStream {
    match parse(input)
        .and_then(validate)
        .and_then(|spec| expand(&spec))
    {
        Ok(tokens) => tokens,
        Err(e) => e.to_compile_error(),
    }
}

/// Formats generated tokens as Rust source with prettyplease (feature `pretty`).
///
/// # Panics
/// If `tokens` is not a sequence of items (never for the output of [`expand()`]).
#[cfg(feature = "pretty")]
pub fn format_items(tokens: TokenStream) -> String {
    let file: syn::File = syn::parse2(tokens).expect("the expansion is a list of items");
    prettyplease::unparse(&file)
}

/// The generated function for `spec`, formatted as Rust source.
///
/// # Panics
/// If a constant of the expansion overflows `i128`: excluded by the degree limits, so check
/// [`Shape::check_limit`] first for degrees that come from users.
#[cfg(feature = "pretty")]
pub fn source(spec: &Spec) -> String {
    format_items(expand(spec).expect("constants fit within the degree limits"))
}
