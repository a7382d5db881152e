//! The work budget of `blossom restrict` and `blossom check` put together for one job: the
//! up-front estimate of a job from its shape ([`estimate`]: each kind's own formula on the job
//! read without its numbers), its refusal when far over the limit ([`up_front`]), and the
//! metered run ([`metered`]). The machinery and the cost model are in [`super::cost`], whose
//! module documentation says why the work is metered and how the estimate is made.

use super::args::{Arithmetic, MethodChoice};
use super::cost::{longest_number_field, Env, Spelling, RAISE_IT};
pub use super::cost::{
    metered, Estimate, Limits, DEFAULT_MAX_INPUT, DEFAULT_MAX_WORK, EXACT_OPERATION, F64_OPERATION,
    UP_FRONT_FACTOR,
};
use super::kinds::{job_and_kind, Job, Subcommand};
use super::read::Text;
use blossom::Error;
use serde_json::{Map, Value};

/// The up-front check: `estimate`, or the refusal of a job whose estimate is over
/// [`UP_FRONT_FACTOR`] times `limits.max_work`.
pub fn up_front(estimate: Estimate, limits: &Limits) -> Result<Estimate, Error> {
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
    job_and_kind(document, Subcommand::Restrict)
        .and_then(|(job, kind)| Ok((job, Job::<Text>::read(kind.name, job)?)))
        .map_or_else(
            |_| Estimate::zero(),
            |(job, shape)| estimate_of(&shape, job, method, arithmetic),
        )
}

/// The estimate of the job `shape` (read without its numbers) whose object is `job`.
pub fn estimate_of(
    shape: &Job<Text>,
    job: &Map<String, Value>,
    method: MethodChoice,
    arithmetic: Arithmetic,
) -> Estimate {
    let work_of = |short: bool| {
        let f64 = arithmetic == Arithmetic::F64;
        let reading = Spelling {
            short,
            f64,
            doubles: f64,
        };
        let exact = !f64;
        shape.estimate(&Env {
            job,
            method,
            exact,
            reading,
        })
    };
    let Some((work, size_field)) = work_of(false) else {
        return Estimate::zero();
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
