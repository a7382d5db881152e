//! The proof grid: every generated evaluator of curves 1..=10, tensor patches (1..=4)^2 and
//! triangles (1..=3)^2, run on symbolic polynomials, is identical as a polynomial to the
//! subset-sum definition and to the polarisation formula. The table is snapshotted.
#![cfg(feature = "carried-grid")]

#[test]
fn every_generated_evaluator_of_the_grid_is_proved() {
    let rows = blossom_cli::specialised::proof_table();
    assert_eq!(rows.len(), 10 + 16 + 9 + 10);
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
