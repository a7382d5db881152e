//! The files in `tests/macros_expanded/` of the workspace root are exactly what `blossom expand`
//! prints (`expand_source`; regenerate with `BLOSSOM_UPDATE_EXPANDED=1`). The root test crate
//! `macros` compiles them against the library alone and runs them against the closed form.

use blossom_cli::specialised::{expand_source, Shape};

#[test]
fn the_files_are_what_expand_prints() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/macros_expanded");
    for (shape, file) in [
        (Shape::Curve(3), "curve_3.rs"),
        (Shape::Tensor(3, 2), "tensor_3_2.rs"),
        (Shape::Triangle(3, 2), "triangle_3_2.rs"),
    ] {
        let printed = expand_source(shape).unwrap();
        let path = format!("{dir}/{file}");
        if std::env::var_os("BLOSSOM_UPDATE_EXPANDED").is_some() {
            std::fs::write(&path, &printed).unwrap();
        }
        let stored = std::fs::read_to_string(&path).unwrap();
        assert!(
            stored == printed,
            "{file} differs from `blossom expand {shape}`"
        );
    }
}
