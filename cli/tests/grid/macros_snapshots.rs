//! Snapshots of the code `blossom::restriction!` generates, formatted by prettyplease, for the
//! three shapes of the issue: curve 3 (eq. (3)), tensor (3, 2) (eq. (9)), triangle (3, 2)
//! (eq. (14)), and for the Bézier-input shapes: curve 3, tensor (2, 1), triangle 2. The expansion functions are called directly on tokens, as the macro calls them.

use blossom_codegen::{expand, format_items, parse, validate, Shape, Spec};
use quote::quote;

fn snapshot(name: &str, code: &str) {
    insta::with_settings!({
        snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"),
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!(name, code);
    });
}

#[test]
fn curve_3() {
    snapshot(
        "macros_curve_3",
        &blossom_codegen::source(&Spec::public(Shape::Curve(3))),
    );
}

#[test]
fn tensor_3_2() {
    snapshot(
        "macros_tensor_3_2",
        &blossom_codegen::source(&Spec::public(Shape::Tensor(3, 2))),
    );
}

#[test]
fn triangle_3_2() {
    snapshot(
        "macros_triangle_3_2",
        &blossom_codegen::source(&Spec::public(Shape::Triangle(3, 2))),
    );
}

#[test]
fn triangle_total_2() {
    snapshot(
        "macros_triangle_total_2",
        &blossom_codegen::source(&Spec::public(Shape::TriangleTotal(2))),
    );
}

#[test]
fn bezier_curve_3() {
    snapshot(
        "macros_bezier_curve_3",
        &blossom_codegen::source(&Spec::public(Shape::BezierCurve(3))),
    );
}

#[test]
fn bezier_tensor_2_1() {
    snapshot(
        "macros_bezier_tensor_2_1",
        &blossom_codegen::source(&Spec::public(Shape::BezierTensor(2, 1))),
    );
}

#[test]
fn bezier_triangle_2() {
    snapshot(
        "macros_bezier_triangle_2",
        &blossom_codegen::source(&Spec::public(Shape::BezierTriangle(2))),
    );
}

/// The pipeline from the macro's own input tokens gives the same code as the `Spec` shortcut
/// (used by `blossom expand`), attributes and visibility included.
#[test]
fn macro_input_and_spec_expand_alike() {
    let tokens = quote!(vis = pub, name = restrict_curve_3, shape = curve, degree = 3);
    let spec = validate(parse(tokens).unwrap()).unwrap();
    let from_input = format_items(expand(&spec).unwrap());
    assert_eq!(
        from_input,
        blossom_codegen::source(&Spec::public(Shape::Curve(3)))
    );

    let tokens = quote!(
        #[inline]
        name = f,
        shape = triangle,
        degree = (1, 0)
    );
    let code = format_items(blossom_codegen::restriction(tokens));
    assert!(code.contains("#[inline]\n"), "{code}");
    assert!(
        code.contains("\nfn f<T: ::blossom::Ring, const D: usize>("),
        "{code}"
    );
}

/// No loop over degree indices, no binomial at run time, no zero term, no `T::zero()`.
#[test]
fn generated_code_is_unrolled_and_folded() {
    for shape in [Shape::Curve(7), Shape::Tensor(3, 4), Shape::Triangle(2, 3)] {
        let source = blossom_codegen::source(&Spec::public(shape));
        // The code without its comments (they say "unrolled for degree 7").
        let code: String = source
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        for banned in [
            "for ",
            "while ",
            "loop ",
            "binomial",
            "T::zero()",
            "scale_frac(0,",
            "scale_frac(1, 1)",
        ] {
            assert!(
                !code.contains(banned),
                "{shape}: `{banned}` in the generated code"
            );
        }
        // Each monomial binding is computed once.
        let lets: Vec<&str> = code
            .lines()
            .filter_map(|l| l.trim().strip_prefix("let "))
            .collect();
        let names: std::collections::HashSet<&str> = lets
            .iter()
            .map(|l| l.split([' ', ':']).next().unwrap())
            .collect();
        assert_eq!(names.len(), lets.len(), "{shape}: a binding is repeated");
    }
}
