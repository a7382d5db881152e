//! Writing the pictures: the directory is created when missing, one SVG file per figure;
//! a directory that cannot be made or a file that cannot be written is an error on `--out`.

use super::{figures, svg};
use blossom::Error;
use std::fs;
use std::path::{Path, PathBuf};

fn cannot(what: &Path, e: &std::io::Error) -> Error {
    Error::new("--out", format!("cannot write {}: {e}", what.display()))
}

/// Writes every figure into `out` (created if missing); returns the paths written, in order.
pub fn write_figures(out: &Path) -> Result<Vec<PathBuf>, Error> {
    let all = figures()?;
    if out.exists() && !out.is_dir() {
        return Err(Error::new(
            "--out",
            format!("cannot write into {}: not a directory", out.display()),
        ));
    }
    fs::create_dir_all(out).map_err(|e| cannot(out, &e))?;
    let mut written = Vec::with_capacity(all.len());
    for figure in &all {
        let path = out.join(figure.file);
        fs::write(&path, svg(figure)?).map_err(|e| cannot(&path, &e))?;
        written.push(path);
    }
    Ok(written)
}
