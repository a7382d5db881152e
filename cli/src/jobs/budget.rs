//! The work budget of `blossom restrict` and `blossom check` put together for one document:
//! the up-front estimate of a job from its sizes ([`estimate`], each kind's own formula,
//! [`super::kinds::Kind::estimate`]), its refusal when far over the limit ([`up_front`]), and
//! the metered run ([`metered`]). The machinery and the cost model are in [`super::cost`],
//! whose module documentation says why the work is metered and how the estimate is made.

use super::args::{Arithmetic, MethodChoice};
use super::cost::{degree_of, longest_number_field, Env, Spelling, RAISE_IT};
pub use super::cost::{
    metered, Estimate, Limits, DEFAULT_MAX_INPUT, DEFAULT_MAX_WORK, EXACT_OPERATION, F64_OPERATION,
    UP_FRONT_FACTOR,
};
use super::kinds::{job_and_kind, Job, Subcommand};
use super::read::MAX_DEGREE;
use blossom::{Error, Rational};
use serde_json::Value;

/// The up-front check: the estimate of the job in `document`, or the refusal of a job whose
/// estimate is over [`UP_FRONT_FACTOR`] times `limits.max_work`.
pub fn up_front(
    document: &Value,
    method: MethodChoice,
    arithmetic: Arithmetic,
    limits: &Limits,
) -> Result<Estimate, Error> {
    let estimate = estimate(document, method, arithmetic);
    if estimate.work <= UP_FRONT_FACTOR * limits.max_work as f64 {
        return Ok(estimate);
    }
    Err(Error::new(
        estimate.field,
        format!(
            "the job's work is estimated at {:.1e} units before computing, far over the \
             limit of {:.1e} units {RAISE_IT}",
            estimate.work, limits.max_work as f64
        ),
    ))
}

/// The estimate of the `restrict` job in `document` (zero for what is not one: reading
/// refuses it).
pub fn estimate(document: &Value, method: MethodChoice, arithmetic: Arithmetic) -> Estimate {
    let zero = || Estimate {
        work: 0.0,
        field: String::from("input"),
    };
    let Ok((job, kind)) = job_and_kind(document, Subcommand::Restrict) else {
        return zero();
    };
    // A degree over the limit of the reading is refused by the reading, with its own message.
    let named_degrees = ["degree", "to_degree", "total_degree", "order"];
    if named_degrees
        .iter()
        .any(|name| degree_of(job.get(*name)) > MAX_DEGREE as f64)
    {
        return zero();
    }
    let work_of = |short: bool| {
        let env = Env {
            job,
            method,
            exact: arithmetic == Arithmetic::Exact,
            reading: Spelling {
                short,
                f64: arithmetic == Arithmetic::F64,
                doubles: arithmetic == Arithmetic::F64,
            },
        };
        Job::<Rational>::estimate(kind.name, &env)
    };
    let Some((work, size_field)) = work_of(false) else {
        return zero();
    };
    // The field to name: the one with the longest number when the numbers' length is what
    // makes the job expensive (the same job with numbers of 64 bits would cost less than a
    // tenth), else the one that holds the sizes.
    let short = work_of(true).map_or(0.0, |(w, _)| w);
    let field = if short * 10.0 < work {
        longest_number_field(job)
    } else {
        size_field.to_string()
    };
    Estimate { work, field }
}
