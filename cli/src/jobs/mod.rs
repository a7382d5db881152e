//! The command-line front end of the `blossom` binary, per the contract in `cli.md`.
//!
//! * `blossom` and `blossom verify [--json] [--verbose]` print [`crate::verify::run_report`]
//!   and exit 0 when it is all reproduced or explained, 1 otherwise;
//! * `blossom restrict`, `blossom intersect` and `blossom region` read one job and print its
//!   answer as **one line** of compact JSON followed by a newline, exit 0: the job's kind is
//!   looked up in the list of kinds ([`kinds`]), the job read into its type ([`read`]; a field
//!   its kind does not read is refused), computed ([`kind::Kind::solve`], within the budget:
//!   [`budget`], [`cost`]) and its answer written ([`write`](mod@write));
//! * `blossom check`, `figures`, `expand` and `completions` as [`args`] describes.
//!
//! The files import in one direction: this module (the subcommands) and [`budget`] over the
//! list of kinds ([`kinds`]), over the kinds' files ([`restrict`], [`intersect`], [`region`]),
//! over what they share: reading ([`read`]), writing ([`write`](mod@write)), the kind's trait ([`kind`]),
//! the cost model ([`cost`]) and the command line's types ([`args`]).
//!
//! Every failure is one line `error: FIELD: message` on standard error, where FIELD is the
//! offending argument (`--method`) or the path of the offending JSON field (`coefficients[2]`,
//! `interval`, `input` for the document as a whole), with exit code 2 and nothing on standard
//! output: the whole answer is built in memory before anything is printed. Control characters
//! in messages are escaped so that the error stays on one line.
//!
//! Nothing in the command line is meant to panic on any input. As a last-resort guard only,
//! [`main`] runs everything under [`std::panic::catch_unwind`] with a silent panic hook and
//! turns a panic into `error: internal: ...` with exit code 2.

pub mod args;
pub mod budget;
pub mod cost;
pub mod intersect;
pub mod kind;
pub mod kinds;
pub mod read;
pub mod region;
pub mod restrict;
pub mod write;

/// The jobs of `blossom intersect` under their former name.
pub use intersect as intersect_jobs;

use crate::number::take_error_bound;
use args::{Arithmetic, Command, IntersectOptions, Limits, MethodChoice};
use blossom::{BoundedF64, Error, Rational};
use kinds::{job_and_kind, Context, Job, KindInfo, Subcommand};
use read::Text;
use restrict::specialised;
use serde_json::{Map, Value};
use std::ffi::OsString;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The exit code of bad input or bad arguments.
pub const EXIT_BAD_INPUT: i32 = 2;

/// What a run prints and returns.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The exit code.
    pub code: i32,
    /// Everything for standard output.
    pub stdout: String,
    /// Everything for standard error.
    pub stderr: String,
}

impl Outcome {
    fn of(result: Result<String, Error>) -> Self {
        match result {
            Ok(stdout) => Outcome {
                code: 0,
                stdout,
                stderr: String::new(),
            },
            Err(error) => Outcome {
                code: EXIT_BAD_INPUT,
                stdout: String::new(),
                stderr: format!("error: {}\n", escaped(&error.to_string())),
            },
        }
    }
}

/// `text` with control characters escaped (`\n`, `\u{1b}`), so that it prints as one line.
fn escaped(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// `text`, ending with exactly one newline when it is not empty.
fn with_newline(mut text: String) -> String {
    if !text.is_empty() && !text.ends_with('\n') {
        text.push('\n');
    }
    text
}

/// Runs the command line `args` (without the program name), reading a job from `stdin` when
/// needed. Prints nothing itself.
pub fn run(args: &[OsString], stdin: &mut dyn Read) -> Outcome {
    let command = match args::parse(args) {
        Ok(command) => command,
        Err(error) => return Outcome::of(Err(error)),
    };
    let mut document = |input: &Option<PathBuf>, limits: &Limits| {
        read_input(input.as_deref(), limits, stdin).and_then(|bytes| parse_json(&bytes))
    };
    let one_line = |answer: Value| format!("{answer}\n");
    Outcome::of(match command {
        Command::Help(text) => Ok([
            ("  %RESTRICT%\n", Subcommand::Restrict),
            ("  %INTERSECT%\n", Subcommand::Intersect),
            ("  %REGION%\n", Subcommand::Region),
        ]
        .iter()
        .fold(text.to_string(), |text, (mark, sub)| {
            text.replace(mark, &kinds::help_list(*sub))
        })),
        Command::Version => Ok(format!("blossom {}\n", env!("CARGO_PKG_VERSION"))),
        Command::Verify { json, verbose } => {
            let (report, ok) = crate::verify::run_report(json, verbose);
            return Outcome {
                code: if ok { 0 } else { 1 },
                stdout: with_newline(report),
                stderr: String::new(),
            };
        }
        Command::Restrict(o) if o.method == MethodChoice::Specialised && !specialised::BUILT_IN => {
            Err(Error::new("--method", specialised::NOT_BUILT_IN))
        }
        Command::Restrict(o) => document(&o.input, &o.limits).and_then(|job| {
            solve(&job, &Context::new(o.method, o.arithmetic, o.limits)).map(one_line)
        }),
        Command::Intersect(o) => document(&o.input, &o.limits)
            .and_then(|job| certified(&job, Subcommand::Intersect, &o).map(one_line)),
        Command::Region(o) => document(&o.input, &o.limits)
            .and_then(|job| certified(&job, Subcommand::Region, &o).map(one_line)),
        Command::Check(o) => {
            let context = Context::new(MethodChoice::default(), Arithmetic::Exact, o.limits);
            let shape = |job: &Value| shape(job).map(drop);
            let exact = |job: &Value| solve(job, &context);
            document(&o.input, &o.limits).and_then(|document| {
                crate::check::check_command(&document, o.per_point, &shape, &exact)
                    .map(with_newline)
            })
        }
        Command::Figures { out } => crate::figures::write_figures(&out).map(|written| {
            written
                .iter()
                .map(|path| format!("{}\n", path.display()))
                .collect()
        }),
        Command::Completions(shell) => args::completions(&shell),
        Command::Expand(words) => crate::specialised::expand_command(&words).map(with_newline),
    })
}

/// The answer of the job `document` of `blossom intersect` or `blossom region`.
fn certified(
    document: &Value,
    subcommand: Subcommand,
    o: &IntersectOptions,
) -> Result<Value, Error> {
    let (job, kind) = job_and_kind(document, subcommand)?;
    answer(
        kind,
        job,
        &Context::new(MethodChoice::default(), o.arithmetic, o.limits),
    )
}

/// The answer of the job object `job` of kind `kind`, its numbers read in the arithmetic of
/// `context`: `"kind"` first, then the fields of the kind's answer.
fn answer(kind: &KindInfo, job: &Map<String, Value>, context: &Context) -> Result<Value, Error> {
    let answer = match context.arithmetic {
        Arithmetic::Exact => Job::<Rational>::read(kind.name, job)?.solve(context)?,
        Arithmetic::F64 => Job::<BoundedF64>::read(kind.name, job)?.solve(context)?,
    };
    let mut named = Map::from_iter([(String::from("kind"), Value::from(kind.name))]);
    if let Value::Object(fields) = answer {
        named.extend(fields);
    }
    Ok(Value::Object(named))
}

/// The answer of the `restrict` job `document` within the budget: its shape and fields are
/// checked first (its numbers not yet read), then its estimate ([`budget::up_front`]), then it
/// is read and computed under the meter. Under `f64` the answer has `"error_bound"`: the
/// largest bound over its numbers on their distance to the exact answer for the same input
/// doubles (`null` when some number has no finite bound).
pub fn solve(document: &Value, context: &Context) -> Result<Value, Error> {
    let (job, kind) = job_and_kind(document, Subcommand::Restrict)?;
    let shape = Job::<Text>::read(kind.name, job)?;
    let estimate = budget::estimate_of(&shape, job, context.method, context.arithmetic);
    let estimate = budget::up_front(estimate, &context.limits)?;
    budget::metered(&context.limits, &estimate.field, || {
        let mut answer = answer(kind, job, context)?;
        if context.arithmetic == Arithmetic::F64 {
            let bound = take_error_bound(&mut answer).and_then(serde_json::Number::from_f64);
            if let Value::Object(fields) = &mut answer {
                let bound = bound.map_or(Value::Null, Value::Number);
                fields.insert("error_bound".into(), bound);
            }
        }
        Ok(answer)
    })
}

/// Checks the kind and the fields of the `restrict` job `document` (the names of all of them
/// first), its numbers not yet read: the job so read.
pub fn shape(document: &Value) -> Result<Job<Text>, Error> {
    let (job, kind) = job_and_kind(document, Subcommand::Restrict)?;
    Job::<Text>::read(kind.name, job)
}

/// The bytes of the job: the `--input` file, or standard input when `input` is `None`, at most
/// `limits.max_input` of them (a longer input is refused, never truncated).
pub(crate) fn read_input(
    input: Option<&Path>,
    limits: &Limits,
    stdin: &mut dyn Read,
) -> Result<Vec<u8>, Error> {
    let (field, cannot) = match input {
        Some(path) => (
            "--input",
            format!("cannot read {:?}", path.display().to_string()),
        ),
        None => ("input", String::from("cannot read standard input")),
    };
    let refusal = |e: std::io::Error| Error::new(field, format!("{cannot}: {e}"));
    let mut source: Box<dyn Read + '_> = match input {
        Some(path) => Box::new(std::fs::File::open(path).map_err(refusal)?),
        None => Box::new(stdin),
    };
    let (limit, mut bytes) = (limits.max_input, Vec::new());
    let read = source
        .by_ref()
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes);
    read.map_err(refusal)?;
    if bytes.len() as u64 > limit {
        return Err(Error::new(
            field,
            format!(
                "the input is longer than the limit of {limit} bytes (raise it with --max-input)"
            ),
        ));
    }
    Ok(bytes)
}

/// Parses the input as one JSON document (a leading UTF-8 byte-order mark is skipped).
pub(crate) fn parse_json(bytes: &[u8]) -> Result<Value, Error> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    serde_json::from_slice(bytes).map_err(|e| {
        let full = e.to_string();
        let (line, column) = (e.line(), e.column());
        let message = full.strip_suffix(&format!(" at line {line} column {column}"));
        let message = message.unwrap_or(&full);
        let message = format!("invalid JSON at line {line} column {column}: {message}");
        Error::new("input", message)
    })
}

/// Where the panic hook leaves the message of a panic for [`main`].
static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

/// The binary's entry point: runs the process's command line, prints the outcome and returns
/// the exit code. A panic (a bug, never expected) becomes `error: internal: ...`, exit 2.
pub fn main() -> i32 {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    std::panic::set_hook(Box::new(|info| {
        if let Ok(mut slot) = LAST_PANIC.lock() {
            *slot = Some(info.to_string());
        }
    }));
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        run(&args, &mut std::io::stdin().lock())
    }))
    .unwrap_or_else(|payload| {
        let message = LAST_PANIC
            .lock()
            .ok()
            .and_then(|mut slot| slot.take())
            .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| String::from("unknown panic"));
        Outcome::of(Err(Error::new("internal", message)))
    });
    // Write errors (a closed pipe) are ignored: the exit code still tells the story.
    let _ = std::io::stdout()
        .lock()
        .write_all(outcome.stdout.as_bytes());
    let _ = std::io::stdout().flush();
    let _ = std::io::stderr()
        .lock()
        .write_all(outcome.stderr.as_bytes());
    outcome.code
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run_with(args: &[&str], input: &str) -> Outcome {
        let args: Vec<OsString> = args.iter().map(OsString::from).collect();
        run(&args, &mut input.as_bytes())
    }

    #[test]
    fn curve_answer_is_one_line() {
        let out = run_with(
            &["restrict"],
            r#"{"kind": "curve", "coefficients": [[0], [0], [1]], "interval": [0, 1]}"#,
        );
        assert_eq!(out.code, 0, "{}", out.stderr);
        assert_eq!(
            out.stdout,
            "{\"kind\":\"curve\",\"degree\":2,\"control_points\":[[\"0\"],[\"0\"],[\"1\"]]}\n"
        );
    }

    #[test]
    fn errors_are_one_line() {
        let out = run_with(&["restrict"], "{\"kind\": \"a\\nb\"}");
        assert_eq!(out.code, 2);
        assert!(out.stdout.is_empty());
        assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
        assert_eq!(escaped("a\nb\u{1b}"), "a\\nb\\u{1b}");
    }

    #[test]
    fn invalid_json_names_line_and_column() {
        let out = run_with(&["restrict"], "{\n  \"kind\": }");
        assert_eq!(out.code, 2);
        assert!(
            out.stderr
                .starts_with("error: input: invalid JSON at line 2 column 11: "),
            "{}",
            out.stderr
        );
    }
}
