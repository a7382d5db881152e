//! Every program of `examples/` run as a test, so that `cargo test --workspace` runs them
//! (each asserts its own results; a wrong answer panics).
//!
//! Each example file is compiled a second time here as a module (`#[path]`) and its `pub fn
//! main()` (or, for a program that reads its arguments, the `run` its `main` calls) is called:
//! no extra test binary and no `[[example]]` entries, and `cargo run -p blossom --example NAME`
//! keeps working on the same file. `cargo test` compiles the examples as programs as well, so a
//! file that only works as a module would still fail the build.

#[path = "../../../examples/batch_of_curves.rs"]
mod batch_of_curves;
#[path = "../../../examples/booleans.rs"]
mod booleans;
#[path = "../../../examples/bspline_from_pieces.rs"]
mod bspline_from_pieces;
#[path = "../../../examples/degree_reduction.rs"]
mod degree_reduction;
#[path = "../../../examples/intersections.rs"]
mod intersections;
// Its `main` reads the command line and is not called here (see the test).
#[allow(dead_code)]
#[path = "../../../examples/restrict_runtime_degree.rs"]
mod restrict_runtime_degree;
#[path = "../../../examples/restriction_macro.rs"]
mod restriction_macro;
#[path = "../../../examples/symbolic_proof.rs"]
mod symbolic_proof;
#[path = "../../../examples/triangle_subpatch.rs"]
mod triangle_subpatch;

#[test]
fn example_restrict_runtime_degree() {
    // `main` reads the degree from the command line, which here is the test harness's; the
    // degrees are given directly instead.
    for degree in [0, 1, 4, 7, 12] {
        restrict_runtime_degree::run(degree);
    }
}

#[test]
fn example_restriction_macro() {
    restriction_macro::main();
}

#[test]
fn example_triangle_subpatch() {
    triangle_subpatch::main();
}

#[test]
fn example_bspline_from_pieces() {
    bspline_from_pieces::main();
}

#[test]
fn example_degree_reduction() {
    degree_reduction::main();
}

#[test]
fn example_batch_of_curves() {
    batch_of_curves::main();
}

#[test]
fn example_symbolic_proof() {
    symbolic_proof::main();
}

#[test]
fn example_intersections() {
    intersections::main();
}

#[test]
fn example_booleans() {
    booleans::main();
}
