//! `blossom figures` (being built: see issue 15, item 1).

use blossom::Error;
use std::path::{Path, PathBuf};

/// Writes the figures into `out`; returns the paths written.
pub fn write_figures(_out: &Path) -> Result<Vec<PathBuf>, Error> {
    Err(Error::new("figures", "not built yet"))
}
