//! Compile-fail tests of `blossom::restriction!`: every misuse is a compile error with a clear
//! message spanning the offending token (the expected diagnostics are in `tests/ui/*.stderr`;
//! regenerate with `TRYBUILD=overwrite` and review).

#[test]
fn misuses_of_the_macro_fail_to_compile() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
