//! `blossom::restriction!`: the Bézier-input evaluators proved symbolically, the printed
//! expansion compiled against the library, and the compile errors of its misuses.

mod doc_example;
mod macros_bezier;
mod macros_expanded_compiles;
mod macros_ui;
