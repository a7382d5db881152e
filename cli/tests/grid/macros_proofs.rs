//! The proof grid: every generated evaluator the binary carries (curves 1..=16, tensor patches
//! (0..=5)^2, triangles (0..=4)^2, (0, 0) excepted, Bézier curves 1..=16, triangular arrays of
//! total degree 1..=6, Bézier tensor patches (0..=4)^2 without (0, 0), Bézier triangles 1..=6),
//! run on symbolic polynomials, is identical as a polynomial to the subset-sum definition and
//! to the polarisation formula. The table is snapshotted.
#![cfg(feature = "carried-grid")]

#[test]
fn every_generated_evaluator_of_the_grid_is_proved() {
    let rows = blossom_cli::specialised::proof_table();
    assert_eq!(rows.len(), 16 + 35 + 24 + 16 + 6 + 24 + 6);
    let text = blossom_cli::specialised::proof_table_text(&rows);
    for row in &rows {
        assert!(row.identical(), "not proved:\n{text}");
    }
    insta::with_settings!({
        snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"),
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("macros_proof_table", text);
    });
}
