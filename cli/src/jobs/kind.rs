//! What a kind of job is ([`Kind`]: read with serde, answered; [`Estimate`]: its work before
//! reading), the subcommand that answers it,
//! the command line's choices it is computed with ([`Context`]) and what the kinds' files share
//! ([`prelude`]). Each kind's file implements [`Kind`]; the list of kinds ([`super::kinds`])
//! puts them together.

use super::args::{Arithmetic, Limits, MethodChoice};
use super::cost::Env;
use blossom::Error;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// What every kind's file works with (`use crate::jobs::kind::prelude::*`): the kind's trait,
/// the readers of a job's leaves, the writing of its answer and the cost model of its estimate.
pub mod prelude {
    pub use super::{Context, Estimate, Kind};
    pub use crate::jobs::args::MethodChoice;
    pub use crate::jobs::cost::{grown_bits, metered, operation, Calibration, Env};
    pub use crate::jobs::read::{any, exactly, items, leaf, not_empty, number, object, under};
    pub use crate::jobs::read::{coordinates, rectangular, triangular, MAX_DEGREE};
    pub use crate::jobs::read::{Corners, Degree, NumberList, NumberRows, Numbers, Points, Rows};
    pub use crate::jobs::read::{List, Reading, Written};
    pub use crate::jobs::write::{write, Double, Out, Param, Write};
    pub use blossom::{Error, Method, Point, Rational};
    pub use serde::{Deserialize, Deserializer, Serialize};
    pub use serde_json::Value;
}

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

impl Context {
    /// The choices of a run.
    pub fn new(method: MethodChoice, arithmetic: Arithmetic, limits: Limits) -> Self {
        Context {
            method,
            arithmetic,
            limits,
        }
    }
}

/// A kind of job: read with serde (its fields, unknown ones refused) and answered.
pub trait Kind: DeserializeOwned {
    /// The answer as JSON (`error_bound` and the one-line text are added by the caller).
    fn solve(self, context: &Context) -> Result<Value, Error>;
}

/// The up-front work estimate of a kind, on the job read without its numbers
/// ([`super::read::Text`]): the work units (its measured factor applied, the reading of its
/// numbers included) and the field that holds the sizes. Only the kinds of `blossom restrict`
/// have one; the others keep the default `None` (they are estimated after reading).
pub trait Estimate {
    /// The estimate.
    fn estimate(&self, _env: &Env) -> Option<(f64, &'static str)> {
        None
    }
}
