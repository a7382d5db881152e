//! The code size of the generated evaluators at the degree limits, at the degrees the
//! `blossom` binary carries and, for triangles, one step beyond the limit: tokens of `blossom_codegen::expand` and lines of its
//! prettyplease output (what `blossom expand` prints). The figures of the "Degree limits"
//! table in the `blossom-macros` docs.
//!
//! `cargo run --release -p blossom-codegen --example macro_sizes`

use blossom_codegen::{expand, format_items, Shape, Spec};

fn main() {
    let shapes = [
        Shape::Curve(8),
        Shape::Curve(16),
        Shape::Curve(24),
        Shape::Tensor(3, 3),
        Shape::Tensor(5, 5),
        Shape::Tensor(10, 10),
        Shape::Triangle(3, 3),
        Shape::Triangle(4, 4),
        Shape::Triangle(5, 5),
        Shape::BezierCurve(3),
        Shape::BezierCurve(24),
        Shape::BezierTensor(10, 10),
        Shape::BezierTriangle(4),
        Shape::BezierTriangle(6),
        Shape::BezierTriangle(8),
    ];
    println!(
        "{:<16} {:>8} {:>9} {:>7}",
        "shape", "degree", "tokens", "lines"
    );
    for shape in shapes {
        let tokens = expand(&Spec::public(shape)).expect("within the degree limits");
        let count = count_tokens(tokens.clone());
        let lines = format_items(tokens).lines().count();
        println!(
            "{:<16} {:>8} {:>9} {:>7}",
            shape.keyword(),
            shape.degree_text(),
            count,
            lines
        );
    }
}

/// Leaf tokens of `tokens`, descending into groups (a group's delimiters count as one token).
fn count_tokens(tokens: proc_macro2::TokenStream) -> usize {
    tokens
        .into_iter()
        .map(|t| match t {
            proc_macro2::TokenTree::Group(g) => 1 + count_tokens(g.stream()),
            _ => 1,
        })
        .sum()
}
