//! What a kind of job is ([`Kind`]: read with serde, estimated, answered), the subcommand that
//! answers it and the command line's choices it is computed with ([`Context`]). Each kind's file
//! implements [`Kind`]; the list of kinds ([`super::kinds`]) puts them together.

use super::args::{Arithmetic, Limits, MethodChoice};
use super::cost::Env;
use blossom::Error;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// The subcommand that answers a kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Subcommand {
    /// `blossom restrict` (and `blossom check`).
    Restrict,
    /// `blossom intersect`.
    Intersect,
    /// `blossom region`.
    Region,
}

/// What a job is computed with: the command line's choices.
#[derive(Clone, Copy, Debug)]
pub struct Context {
    /// `--method` (restrict).
    pub method: MethodChoice,
    /// `--arithmetic`.
    pub arithmetic: Arithmetic,
    /// `--max-work` and `--max-input`.
    pub limits: Limits,
}

/// A kind of job: read with serde (its fields, unknown ones refused), estimated, answered.
pub trait Kind: DeserializeOwned {
    /// The up-front work estimate of a `restrict` job of this kind from the job as written
    /// (sizes and number lengths, nothing read): the work units (its measured factor applied,
    /// the reading of its numbers included) and the field that holds the sizes; `None` for the
    /// kinds estimated after reading.
    fn estimate(env: &Env) -> Option<(f64, &'static str)> {
        let _ = env;
        None
    }

    /// The answer as JSON (`error_bound` and the one-line text are added by the caller).
    fn solve(self, context: &Context) -> Result<Value, Error>;
}
