//! The hook for `--method specialised`: the evaluators that the proc-macro generates at
//! compile time for fixed degrees (formulae (3), (9), (14) unrolled).
//!
//! This is the one place where they plug into the command line. They are not built yet, so
//! [`BUILT_IN`] is `false` and the command line refuses `--method specialised` (exit 2, before
//! reading any input) with [`NOT_BUILT_IN`]. The change that adds them sets [`BUILT_IN`] to
//! `true` and makes [`specialised`] return `Some(Ok(answer))` for the degrees it carries and
//! `Some(Err(..))`, naming the degrees it does carry, for the others.

use super::answer::Answer;
use super::job::Job;
use crate::{Error, Ring};

/// Whether this binary carries specialised evaluators at all.
pub const BUILT_IN: bool = false;

/// The message (for the argument `--method`) when they are not built in.
pub const NOT_BUILT_IN: &str = "specialised evaluators are not built into this binary yet";

/// The answer of `job` by the specialised evaluator of its degree: `None` when this binary
/// has no specialised evaluators, `Some(Err(..))` for a degree it does not carry.
pub fn specialised<T: Ring>(job: &Job<T>) -> Option<Result<Answer<T>, Error>> {
    let _ = job;
    None
}
