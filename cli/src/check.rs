//! `blossom check` (being built: see issue 15, item 5).

use crate::jobs::args::CheckOptions;
use blossom::Error;
use serde_json::Value;

/// The report of `blossom check` on `document` (`{"job": ..., "answer": ...}`).
pub fn check_command(_document: &Value, _options: &CheckOptions) -> Result<String, Error> {
    Err(Error::new("check", "not built yet"))
}
