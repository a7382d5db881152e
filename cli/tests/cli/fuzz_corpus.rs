//! The seed corpus of the fuzz targets (`fuzz/corpus/<target>/`) replayed as ordinary tests:
//! every file through the very function its target calls (`blossom_cli::fuzzing`), so that
//! each input the fuzzers found interesting, and each that once broke a contract, stays
//! checked without cargo-fuzz.

use std::path::PathBuf;

/// The files of `fuzz/corpus/<target>/`, sorted; panics when the directory is missing or empty.
fn corpus(target: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz/corpus")
        .join(target);
    let entries = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("the corpus {} cannot be read: {e}", dir.display()));
    let mut files: Vec<PathBuf> = entries
        .map(|entry| entry.expect("a directory entry").path())
        .filter(|path| path.is_file())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "the corpus {} is empty", dir.display());
    files
        .into_iter()
        .map(|path| {
            let bytes = std::fs::read(&path)
                .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
            (path, bytes)
        })
        .collect()
}

/// Runs `check` on every file of the corpus of `target`, naming the file that fails.
fn replay(target: &str, check: fn(&[u8])) {
    for (path, bytes) in corpus(target) {
        let outcome = std::panic::catch_unwind(|| check(&bytes));
        assert!(outcome.is_ok(), "{target}: {} fails", path.display());
    }
}

#[test]
fn job_entry_corpus() {
    replay("job_entry", blossom_cli::fuzzing::job_entry);
}

#[test]
fn number_reader_corpus() {
    replay("number_reader", blossom_cli::fuzzing::number_entry);
}

#[test]
fn restrict_shapes_corpus() {
    replay("restrict_shapes", blossom_cli::fuzzing::restrict_entry);
}
