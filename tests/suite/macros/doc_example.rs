//! The example of `blossom-macros`' documentation, run here: the macro crate's page shows
//! `macros/src/doc_example.rs` (marked `ignore` there, because a doc test of a proc-macro
//! crate that uses the runtime crate builds the runtime crate a second time, for the host, a
//! third of a minute of every cold `cargo test --workspace`).

include!("../../../macros/src/doc_example.rs");

#[test]
fn the_macro_crate_example_runs() {
    main();
}
