//! Procedural macros of the `blossom` workspace: compile-time expansion of the closed-form
//! blossom formulae (3), (9), (14) of the subdivision paper into unrolled, degree-specialised
//! functions. Use them through the runtime crate: `blossom::restriction!`.
//!
//! The parsing, validation and expansion live in the ordinary library crate `blossom-codegen`
//! (so that the `blossom expand` command prints exactly what the macro generates); this crate
//! is the thin `#[proc_macro]` wrapper.
//!
//! # Syntax
//!
//! ```text
//! restriction! {
//!     /// optional outer attributes (doc comments, #[inline(never)], ...), copied to the function
//!     vis = pub,                 // optional: `pub`, `pub(crate)`, ...; private when absent
//!     name = restrict_cubic,     // required: the name of the generated function
//!     shape = curve,             // required: `curve`, `tensor` or `triangle`
//!     degree = 3,                // required: `n` for a curve, `(n, m)` for a surface
//! }
//! ```
//!
//! The function is `#[inline]` unless an `inline` attribute of the user's is given: it is
//! straight-line arithmetic for hot loops, and at small degrees the call costs as much as the
//! work (the cubic Bézier of `benches/peers.rs`: 8.5 ns called, 6.6 ns inlined).
//!
//! Keys may come in any order; each is given once. The generated signatures (`D`, the number of
//! coordinates of a point, is a const generic; `T` is any `blossom::Ring`):
//!
//! | shape | degree | signature |
//! |---|---|---|
//! | `curve` | `n` | `fn(coef: &[[T; D]; n+1], a: &T, b: &T) -> [[T; D]; n+1]` |
//! | `tensor` | `(n, m)` | `fn(coef: &[[[T; D]; m+1]; n+1], rect: &[T; 4]) -> [[[T; D]; m+1]; n+1]` |
//! | `triangle` | `(n, m)` | `fn(coef: &[[[T; D]; m+1]; n+1], tri: &[[T; 2]; 3]) -> [[T; D]; (N+1)(N+2)/2]` |
//! | `bezier_curve` | `n` | `fn(ctrl: &[[T; D]; n+1], a: &T, b: &T) -> [[T; D]; n+1]` |
//! | `bezier_tensor` | `(n, m)` | `fn(ctrl: &[[[T; D]; m+1]; n+1], rect: &[T; 4]) -> [[[T; D]; m+1]; n+1]` |
//! | `bezier_triangle` | `N` | `fn(ctrl: &[[T; D]; (N+1)(N+2)/2], tri: &[[T; 2]; 3]) -> [[T; D]; (N+1)(N+2)/2]` |
//!
//! * curve: `coef[i]` = c_i of C(u) = sum c_i u^i; returns w_v = blossom(b^v, a^(n-v)) on
//!   [a, b], Theorem 1, eq. (3);
//! * tensor: `coef[i][j]` = c_ij of S(u, v) = sum c_ij u^i v^j, `rect = [a, b, c, d]` for
//!   [a, b] x [c, d]; returns `[nu][mu]` = blossom(b^nu a^(n-nu); d^mu c^(m-mu)), Theorem 2,
//!   eq. (9) (factored by (10)-(11): the inner sums over j are shared by every nu);
//! * triangle: the same c_ij, total degree N = n + m, `tri = [[a1, a2], [b1, b2], [c1, c2]]`;
//!   returns q_(nu mu lambda) = blossom(a^nu, b^mu, c^lambda) in lexicographic order of
//!   (nu, mu), Theorem 3, eq. (14) with the bounds stated at the end of its proof.
//! * the `bezier_` shapes take control points instead of power coefficients: a Bézier curve
//!   over [0, 1] (`ctrl[i]` = b_i), a tensor patch over [0, 1]^2 (`ctrl[i][j]`), a triangular
//!   patch of degree N (`ctrl` in lexicographic order of (nu, mu), nu the exponent of the first
//!   barycentric coordinate), and return the same blossom values on the sub-interval,
//!   sub-rectangle or sub-triangle. A sub-triangle corner is given by its first two barycentric
//!   coordinates in the patch's own domain (the third is 1 minus their sum). The code first takes
//!   forward differences (one subtraction per coordinate each). The power coefficients are those
//!   differences times C(n, i) (C(n, i) C(m, j), N!/(i! j! (N-i-j)!)), which cancel the
//!   denominators of (3), (9), (14), so every constant left is an integer. A Bézier curve's
//!   blossom is then f(u) = sum_i Δ^i b_0 e_i(u) (e_i the elementary symmetric functions), and
//!   its control points are evaluated by halving: w_0..w_h (h = floor(n/2)) restrict the
//!   blossom f(a^(n-h), ·), w_(h+1)..w_n restrict f(b^(h+1), ·), each halved again; the same
//!   n^2 multiply-adds per coordinate as (3) term by term, but only O(n) distinct scalars
//!   C(k, l) a^l, C(k, l) b^l instead of one weight per pair (v, i). Limits: those of
//!   `curve` and `tensor`, and N <= 6 for `bezier_triangle`.
//!
//! The body is fully unrolled: no loop over a degree index and no binomial at run time. Every
//! combinatorial constant is folded at expansion time (exact `u128` arithmetic) into a reduced
//! fraction passed to `blossom::Ring::scale_frac` (skipped when it is 1); each power or product
//! of the domain parameters is bound once by a `let` and shared; no zero term is emitted. The
//! one iteration left is `core::array::from_fn` over the `D` coordinates of each point, after
//! the scalar weights have been computed once for all coordinates.
//!
//! # Example
//!
//! (Marked `ignore` here; the same file, `macros/src/doc_example.rs`, is compiled and run as
//! the test `macros::doc_example` of the runtime crate.)
//!
#![doc = concat!("```ignore\n", include_str!("doc_example.rs"), "```")]
//!
//! # Errors
//!
//! Every misuse is a compile error spanning the offending token: a missing key (at the macro
//! call), a duplicate or unknown key (at the key), a non-integer, negative or non-literal
//! degree (at the value), a degree of the wrong arity for the shape, a degree above the limit
//! below (at the degree), an unknown shape keyword (at the keyword).
//!
//! # Degree limits
//!
//! | shape | limit | largest accepted: tokens / formatted lines | release build of it |
//! |---|---|---|---|
//! | `curve` | n <= 24 | n = 24: 46 282 tokens / 4 807 lines | 10.7 s |
//! | `tensor` | n, m <= 10 | (10, 10): 49 416 tokens / 4 483 lines | 24.4 s |
//! | `triangle` | N = n + m <= 8 | (4, 4): 53 919 tokens / 5 624 lines | 32.3 s (before regrouping, 131 452 tokens) |
//! | `bezier_curve` | n <= 24 | n = 24: 21 567 tokens / 1 500 lines | not measured |
//! | `bezier_tensor` | n, m <= 10 | (10, 10): 84 206 tokens / 5 869 lines | not measured |
//! | `bezier_triangle` | N <= 6 | N = 6: 30 205 tokens / 2 972 lines (N = 8 would be 84 942) | not measured |
//!
//! The generated code grows like n^3 / 6 scalar terms for a curve (the weights of (3)),
//! like n m (n + m) for a tensor patch (the factored (9)) and, for a triangle, like the
//! regrouped (14): the inner sum over j of c_ij / T(N; i, j) times a corner power is shared by
//! every control point with the same split (nu', mu', lambda'), so the code grows about like
//! N^4 (measured: x2.8 from N = 6 to 8, x2.4 from 8 to 10) rather than the N^6 of the
//! sextuple sum written out per control point. The limits keep one
//! function around 50 000 tokens (about half a minute of optimised compile time); triangles
//! stop at N = 8, the degree the binary carries, because N = 10, (5, 5), is 127 957 tokens /
//! 13 270 lines. All folded constants fit `i128` far beyond these limits (checked at
//! expansion).
//!
//! Token counts are those of `blossom_codegen::expand`, lines those of the prettyplease output
//! (`blossom expand`); both are printed by
//! `cargo run --release -p blossom-codegen --example macro_sizes`. Build times were measured on
//! the project machine (2 shared cores, rustc 1.95) by expanding the macro in a scratch crate
//! with a stub ring and building it with `cargo build --release` (f64, D = 3, one
//! instantiation), timing the whole crate build; smaller degrees for comparison: curve 8:
//! 3 538 tokens, 1.1 s; curve 16: 17 038 tokens, 4.3 s; tensor (5, 5): 8 841 tokens, 2.8 s;
//! triangle (3, 3): 35 380 tokens, 6.8 s before regrouping (19 508 after). The triangle build
//! times were not re-measured after the regrouping.
#![forbid(unsafe_code)]

use proc_macro::TokenStream;

/// Generates a function restricting a power-basis curve or surface of one fixed degree to an
/// interval, a rectangle or a triangle by the unrolled closed forms (3), (9) or (14). See the
/// [crate documentation](crate) for the syntax, the signatures and an example.
#[proc_macro]
pub fn restriction(input: TokenStream) -> TokenStream {
    blossom_codegen::restriction(input.into()).into()
}
