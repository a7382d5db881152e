//! Hand-written parsing of the command line into a [`Command`].
//!
//! Grammar (flags of a subcommand come after it, in any order, each at most once; a value may
//! be given as `--flag VALUE` or `--flag=VALUE`):
//!
//! ```text
//! blossom                                   same as `blossom verify`
//! blossom verify [--json] [--verbose]
//! blossom restrict [--input FILE] [--arithmetic exact|f64] [--method METHOD]
//!                  [--max-work UNITS] [--max-input BYTES]
//! blossom intersect [--input FILE] [--arithmetic exact|f64] [--max-work UNITS] [--max-input BYTES]
//! blossom region [--input FILE] [--arithmetic exact|f64] [--max-work UNITS] [--max-input BYTES]
//! blossom check [--input FILE] [--per-point] [--max-work UNITS] [--max-input BYTES]
//! blossom figures [--out DIR]
//! blossom expand curve N | tensor N M | triangle N M | triangle-total N | bezier-curve N
//!                | bezier-tensor N M | bezier-triangle N
//! blossom [SUBCOMMAND] --help | -h          help (also `blossom help`)
//! blossom --version | -V
//! ```
//!
//! `--input -` reads standard input, as does leaving `--input` out. A value that starts with
//! `--` is taken for a forgotten value (`--input --method pyramid`); write `--input=--odd-name`
//! for a file whose name starts with `--`.
//!
//! A mistyped subcommand, option or method gets the nearest accepted name in its message
//! (`did you mean "restrict"?`, [`super::names::suggest`]).
//!
//! # Why not clap
//!
//! The contract (`docs/cli.md`) wants every failure as one line `error: FIELD: message` naming
//! the argument, exit 2; a forgotten value (`--input --method pyramid`) reported as such; file
//! names that are not UTF-8 kept intact. With clap's derive every error kind would have to be
//! taken apart and re-rendered into that line, and `--input --method` would be read as a file
//! named `--method`; the grammar here is five subcommands with a few flags each. This parser is
//! 300 lines, tested per error (`tests` below and `bad_arguments` in `cli/tests/cli/cli_restrict.rs`), and costs no
//! compile time on a CI budget the test command already fills.

use crate::names::{did_you_mean, listed, quoted};
use blossom::Error;
use blossom::Method;
use std::ffi::{OsStr, OsString};
use std::path::PathBuf;

/// The arithmetic of `restrict`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// Rational numbers with unbounded integers (the default).
    Exact,
    /// IEEE double precision.
    F64,
}

/// The algorithm of `restrict`: one of the library's [`Method`]s or the compile-time
/// specialised evaluators (see [`super::specialised`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodChoice {
    /// A method of [`blossom`].
    Library(Method),
    /// The proc-macro generated evaluator for the job's degree.
    Specialised,
}

impl Default for MethodChoice {
    /// The default `--method`: the library's default, [`Method::Bulk`] (the restriction
    /// engine), for every kind of job.
    fn default() -> Self {
        MethodChoice::Library(Method::default())
    }
}

/// The names `--method` accepts, in the order the help and error messages list them: the
/// library's [`Method::ALL`] (the default first), then `specialised`.
pub const METHOD_NAMES: [(&str, MethodChoice); 7] = [
    ("bulk", MethodChoice::Library(Method::Bulk)),
    ("taylor-shift", MethodChoice::Library(Method::TaylorShift)),
    ("closed-form", MethodChoice::Library(Method::ClosedForm)),
    ("definition", MethodChoice::Library(Method::Definition)),
    ("pyramid", MethodChoice::Library(Method::Pyramid)),
    ("polarisation", MethodChoice::Library(Method::Polarisation)),
    ("specialised", MethodChoice::Specialised),
];

/// Options of `blossom restrict`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RestrictOptions {
    /// The job file; `None` for standard input.
    pub input: Option<PathBuf>,
    /// `--arithmetic`, default exact.
    pub arithmetic: Arithmetic,
    /// `--method`, default `bulk` ([`MethodChoice::default`]).
    pub method: MethodChoice,
    /// `--max-work` and `--max-input` ([`super::budget`]).
    pub limits: super::cost::Limits,
}

/// Options of `blossom intersect`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntersectOptions {
    /// The job file; `None` for standard input.
    pub input: Option<PathBuf>,
    /// `--arithmetic`, default exact: how the job's numbers are read.
    pub arithmetic: Arithmetic,
    /// `--max-work` and `--max-input` ([`super::budget`]).
    pub limits: super::cost::Limits,
}

/// Options of `blossom check`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CheckOptions {
    /// The file holding the job and the answer; `None` for standard input.
    pub input: Option<PathBuf>,
    /// `--per-point`: the error of every control point, besides the largest.
    pub per_point: bool,
    /// `--max-work` and `--max-input` ([`super::budget`]), applied to the job.
    pub limits: super::cost::Limits,
}

/// The subcommands, in the order the help lists them.
pub const SUBCOMMANDS: [&str; 8] = [
    "verify",
    "restrict",
    "intersect",
    "region",
    "check",
    "figures",
    "expand",
    "help",
];

/// What the command line asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// `blossom` or `blossom verify [--json] [--verbose]`.
    Verify {
        /// `--json`: the report as JSON.
        json: bool,
        /// `--verbose`: every section with its entries and findings, instead of the verdict
        /// and the table of sections.
        verbose: bool,
    },
    /// `blossom restrict ...`.
    Restrict(RestrictOptions),
    /// `blossom intersect ...`: certified zeros and intersections.
    Intersect(IntersectOptions),
    /// `blossom region ...`: certified booleans, triangle intersections and winding numbers
    /// (the same options as `intersect`).
    Region(IntersectOptions),
    /// `blossom check ...`: the exact error of another program's f64 answer.
    Check(CheckOptions),
    /// `blossom figures [--out DIR]`: the pictures, written as SVG files into the directory.
    Figures {
        /// `--out`, default `figures`.
        out: PathBuf,
    },
    /// `blossom expand SHAPE DEGREES...`: the words after `expand` (checked when run).
    Expand(Vec<String>),
    /// `--help`: print this text and succeed.
    Help(&'static str),
    /// `--version`.
    Version,
}

/// Help for the whole program.
pub const HELP: &str = "\
blossom: exact Bezier subdivision through blossoms

Usage:
  blossom                      same as `blossom verify`
  blossom verify [--json] [--verbose]
                               re-derive the tables and worked examples of the seed papers;
                               exit 0 when everything is reproduced or explained, 1 otherwise
                               (see `verify --help`)
  blossom restrict [OPTIONS]   restrict a curve or surface given as JSON (see `restrict --help`)
  blossom intersect [OPTIONS]  certified zeros of a Bezier function, intersections of two
                               curves and self-intersections (see `intersect --help`)
  blossom region [OPTIONS]     certified booleans of regions bounded by Bezier curves, the
                               intersection of two Bezier triangles and exact winding
                               numbers (see `region --help`)
  blossom check [OPTIONS]      the exact error of another program's f64 answer to a restrict
                               job (see `check --help`)
  blossom figures [--out DIR]  draw the papers' figures and examples as SVG files
                               (see `figures --help`)
  blossom expand SHAPE DEGREE  print the function the proc-macro generates for a fixed degree
                               (see `expand --help`)
  blossom --help | --version

Errors: one line `error: ...` on standard error, exit code 2.
";

/// Help for `blossom restrict`.
pub const RESTRICT_HELP: &str = "\
blossom restrict: the Bezier form of a polynomial curve or surface on a new domain

Usage: blossom restrict [--input FILE] [--arithmetic exact|f64] [--method METHOD]
                        [--max-work UNITS] [--max-input BYTES]

Options:
  --input FILE         read the job from FILE (default, or `-`: standard input)
  --arithmetic exact   rational numbers, no rounding anywhere (default); numbers in the
                       answer are strings \"p/q\" or \"p\" in lowest terms
  --arithmetic f64     IEEE double precision; numbers in the answer are JSON numbers
  --method METHOD      the algorithm; every method gives the identical exact answer:
      bulk             the restriction engine, in the input's own basis (default): all
                       control points at once by halving, with de Casteljau's affine steps
                       on the control points of Bezier input and the scaled power step
                       d_i + t d_(i+1) on power coefficients; O(n^2) for a curve, as
                       accurate under f64 as de Casteljau at every degree
      taylor-shift     Taylor shift of the power form, then the change to the Bernstein
                       basis (loses digits under f64 as the degree grows)
      closed-form      the closed forms (3), (9), (14), one control point at a time
      definition       the subset-sum definitions (2), (8), (13)
      pyramid          de Casteljau's pyramid on the blossom, one per control point
      polarisation     the inverse (polarisation) formula, sampling points only
      specialised      the evaluator the proc-macro generated at compile time for the
                       job's degree (exit 2 for a degree this binary does not carry)
                     Bezier input goes through its exact power form under taylor-shift,
                     closed-form and definition; power input through its Bernstein form
                     under pyramid.
  --max-work UNITS     stop a job whose work passes UNITS (default 1e9, about a second;
                       see Limits below)
  --max-input BYTES    refuse an input longer than BYTES (default 1048576, 1 MiB)
  -h, --help           print this help

Jobs (JSON objects; a field not listed is refused, with the nearest listed name):
  {\"kind\": \"curve\", \"coefficients\": [c0, ..., cn], \"interval\": [a, b]}
  {\"kind\": \"tensor\", \"coefficients\": [[c00, ..., c0m], ...], \"rectangle\": [a, b, c, d]}
  {\"kind\": \"triangle\", \"coefficients\": [[c00, ..., c0m], ...],
   \"triangle\": [[a1, a2], [b1, b2], [c1, c2]]}
  {\"kind\": \"triangle\", \"total_degree\": N, \"coefficients\": [[c00, ..., c0N], ..., [cN0]],
   \"triangle\": [...]}   (a triangular array: row i holds N + 1 - i points)
  {\"kind\": \"bezier-curve\", \"control_points\": [b0, ..., bn], \"interval\": [a, b]}
  {\"kind\": \"bezier-tensor\", \"control_points\": [[b00, ..., b0m], ...], \"rectangle\": [a, b, c, d]}
  {\"kind\": \"bezier-triangle\", \"control_points\": [{\"a\": i, \"b\": j, \"c\": k, \"point\": p}, ...],
   \"triangle\": [P, Q, R]}   (corners by 3 barycentric coordinates adding up to 1)
  {\"kind\": \"derivative\", \"control_points\": [b0, ..., bn], \"order\": k}
  {\"kind\": \"bspline\", \"degree\": p,
   \"pieces\": [{\"interval\": [e0, e1], \"coefficients\": [c0, ..., cp]}, ...]}
  {\"kind\": \"bspline-eval\", \"degree\": p, \"knots\": [...], \"control_points\": [...],
   \"at\": [t, ...]}
  {\"kind\": \"rational-curve\", \"numerator\": [c0, ...], \"denominator\": [w0, ...],
   \"interval\": [alpha, beta], \"degree\": n (optional)}
  {\"kind\": \"elevate\", \"control_points\": [...], \"to_degree\": m}
  {\"kind\": \"reduce\", \"control_points\": [...], \"to_degree\": m,
   \"method\": \"interpolating\" | \"least-squares\" | \"least-squares-endpoints\"}
  {\"kind\": \"rational-tensor\", \"numerator\": [[p00, ...], ...], \"denominator\": [[w00, ...], ...],
   \"rectangle\": [a, b, c, d], \"degree\": [n, m] (optional)}
  {\"kind\": \"rational-triangle\", \"numerator\": ..., \"denominator\": ..., \"triangle\": [...],
   \"degree\": N (optional), \"total_degree\": N (optional: triangular arrays)}
Points are arrays of numbers, all of one length D >= 1. A number is a JSON integer or a
string: \"-7\", \"3/4\", \"0.125\", \"-1e-3\" (JSON numbers such as 0.1 only under f64).
Under exact arithmetic a decimal exponent is at most 100000 in absolute value (unless the
digits are all zero). The degree of a list of coefficients is its length minus one, zero
coefficients included (so a rational curve's default degree is that of its longer list).
Degrees a job names (degree, to_degree, total_degree, order, the indices of a bezier-triangle
entry, the grids of the rational jobs) are at most 200. The methods apply to curve, tensor, triangle, bezier-curve, bezier-tensor
and bezier-triangle; the other jobs have one algorithm each and answer the same under every
method.

Limits: a job's work is metered as it is computed, every arithmetic operation weighted by the
length of its numbers, in units of about a nanosecond; a job whose work passes --max-work is
stopped with `error: FIELD: the job's work passed the limit ...`, and one whose work, estimated
from its sizes before computing, is far over the limit is refused at once (`error: FIELD: the
job's work is estimated at ...`). FIELD names the sizes (coefficients, control_points, pieces,
at, ...) or the field with the longest number when the numbers' length is what makes the job
expensive. The input is read up to --max-input bytes.

Output: the answer as one line of JSON on standard output, exit code 0; on bad input one line
`error: FIELD: ...` on standard error, nothing on standard output, exit code 2. Under f64 the
answer also has \"error_bound\": a rigorous bound on the distance of every number of the
answer to the exact answer for the same input doubles (null when no finite bound is known).
";

/// Help for `blossom expand`.
pub const EXPAND_HELP: &str = "\
blossom expand: the Rust function `blossom::restriction!` generates for one fixed degree

Usage: blossom expand curve N | tensor N M | triangle N M | triangle-total N
                      | bezier-curve N | bezier-tensor N M | bezier-triangle N

Prints the formatted source of the unrolled closed form (3), (9) or (14) for that degree, as
`blossom::restriction!(vis = pub, name = restrict_<shape>_<degrees>, shape = .., degree = ..)`
expands it; it compiles on its own in a crate that depends on `blossom`. The bezier- shapes
take control points (a Bézier curve over [0, 1], a patch over [0, 1]^2, a triangular patch)
instead of power coefficients; triangle-total takes a triangular array of total degree N.
Limits (those of the macro): curves N <= 24, tensor patches N, M <= 10, triangles N + M <= 8
(triangle-total N <= 8), Bézier triangles N <= 6.
";

/// Help for `blossom verify`.
pub const VERIFY_HELP: &str = "\
blossom verify: re-derive every table and worked example of the seed papers exactly

Usage: blossom verify [--json] [--verbose]

By default the report opens with its verdict and then lists the sections, one line each:
section, source, entries matched, status. Mismatches and findings are in the full report.

Options:
  --verbose   the full report: every section with its findings and every entry
  --json      the full report as JSON
  -h, --help  print this help

Exit code 0 when every printed value was reproduced or explained, 1 otherwise.
";

/// Help for `blossom figures`.
pub const FIGURES_HELP: &str = "\
blossom figures: the papers' figures and examples drawn from the library's results

Usage: blossom figures [--out DIR]

Writes one SVG file per picture into DIR (default `figures`, created if missing), every
coordinate computed by the library from the papers' inputs, and prints the path of every file
written, one per line; exit code 0. A DIR that cannot be created or written: one line
`error: --out: ...` on standard error, exit code 2.

Options:
  --out DIR   the directory of the pictures
  -h, --help  print this help
";

/// Help for `blossom intersect`.
pub const INTERSECT_HELP: &str = "\
blossom intersect: certified zeros and intersections of Bezier curves

Usage: blossom intersect [--input FILE] [--arithmetic exact|f64] [--max-work UNITS]
                         [--max-input BYTES]

Reads one job (JSON) and prints its exact answer as one line of JSON; exit code 0.
  {\"kind\": \"roots\", \"control_points\": [b0, ..., bn]}
      every distinct zero in [0, 1] of the Bezier function with these coefficients, with
      its multiplicity (\"identically_zero\": true for the zero function)
  {\"kind\": \"curve-curve\", \"curves\": [P, Q]}
      every isolated intersection P(s) = Q(t) with an exact tangency flag, and every
      overlap (common stretch), of two 2-D Bezier curves over [0, 1]
  {\"kind\": \"self\", \"curve\": P}
      every pair s < t with P(s) = P(t), and the stretches a curve retraces
A curve is its control points [[x0, y0], ..., [xn, yn]], 1 <= n <= 40; a Bezier function
has degree 0 <= n <= 200. Within those limits the work budget decides: a job is refused
when its estimated work is over twice --max-work, or stopped when its metered work passes
it. Every parameter is written as {\"value\": the correctly rounded double, \"exact\":
\"p/q\" or null, \"interval\": an isolating interval [lo, hi], \"polynomial\": a
square-free integer polynomial it is a root of} (see docs/cli.md).

Options:
  --input FILE         read the job from FILE (default, or `-`: standard input)
  --arithmetic exact   read the numbers as written (default; \"1/3\" is one third)
  --arithmetic f64     round each input number to the nearest double first; the answer
                       is still the exact one for those doubles
  --max-work UNITS     the work budget (as for restrict)
  --max-input BYTES    the longest input read (as for restrict)
  -h, --help           print this help

On bad input one line `error: FIELD: ...` on standard error, exit code 2.
";

/// Help for `blossom region`.
pub const REGION_HELP: &str = "\
blossom region: certified booleans of regions bounded by Bezier curves

Usage: blossom region [--input FILE] [--arithmetic exact|f64] [--max-work UNITS]
                      [--max-input BYTES]

Reads one job (JSON) and prints its exact answer as one line of JSON; exit code 0.
  {\"kind\": \"boolean\", \"op\": OP, \"regions\": [A, B]}
      OP one of \"intersection\", \"union\", \"difference\" (A minus B), \"xor\"
  {\"kind\": \"triangle-triangle\", \"triangles\": [T1, T2]}
      the intersection of two planar Bezier triangles
  {\"kind\": \"winding\", \"region\": A, \"points\": [[x, y], ...]}
      the exact winding number of each point and where it lies (inside, outside, boundary)
A region is {\"loops\": [LOOP, ...], \"fill\": \"nonzero\" (default) | \"evenodd\"}; a loop is a
list of curves [[x0, y0], ..., [xn, yn]], each starting exactly where the previous one ends
and the last ending where the first starts; loops may cross, touch, overlap and run either
way. A triangle is {\"degree\": n, \"nodes\": [...]}: (n + 1)(n + 2)/2 nodes by increasing k,
within it increasing j (p_n00, p_(n-1)10, ..., p_0n0, p_(n-1)01, ..., p_00n); its edges are
curves 0, 1, 2 (the second triangle's 3, 4, 5). Curve degrees 1 to 20.

The answer of boolean and triangle-triangle: {\"kind\": K, \"loops\": [{\"hole\": bool, \"edges\":
[EDGE, ...]}, ...], \"area\": [lo, hi]}: the regularized result as simple loops with the
result on their left (holes clockwise), each edge a piece of one input curve
{\"region\": r, \"loop\": l, \"curve\": c, \"from\": PARAM, \"to\": PARAM} (triangle-triangle:
{\"curve\": i, \"from\", \"to\"}); area: doubles enclosing the exact area, hi - lo <= 2^-40 B
(B the area of the box of every input control point). A PARAM is {\"value\": the correctly
rounded double, \"exact\": \"p/q\" or null, \"interval\": [lo, hi], \"polynomial\": [...]}.

Options:
  --input FILE         read the job from FILE (default, or `-`: standard input)
  --arithmetic exact   read the numbers as written (default; \"1/3\" is one third)
  --arithmetic f64     round each input number to the nearest double first; the answer
                       is still the exact one for those doubles
  --max-work UNITS     refuse a job whose work, estimated before computing, is over twice
                       UNITS (default 1e9, about a second)
  --max-input BYTES    the longest input read (default 1048576)
  -h, --help           print this help

On bad input one line `error: FIELD: ...` on standard error, exit code 2.
";

/// Help for `blossom check`.
pub const CHECK_HELP: &str = "\
blossom check: the exact error of somebody else's f64 answer to a restriction job

Usage: blossom check [--input FILE] [--per-point] [--max-work UNITS] [--max-input BYTES]

Reads {\"job\": JOB, \"answer\": ANSWER}: JOB is a job of `blossom restrict`, its numbers
doubles; ANSWER has the job's answer shape (\"control_points\" as `restrict` prints them) in
doubles. The exact answer for the exact values of the job's doubles is computed (by the
default method, bulk) and compared with ANSWER; the errors are exact rationals and their
nearest doubles (see docs/cli.md). A field of the document other than \"job\" and \"answer\",
or one that the job's kind does not read, is refused; ANSWER's fields other than
\"control_points\" are ignored.

Output: one line of JSON, {\"points\", \"max_abs_error\", \"max_abs_error_f64\", \"max_abs_at\",
\"max_rel_error\", \"max_rel_error_f64\", \"max_rel_at\"} and with --per-point \"per_point\";
exit code 0. On bad input one line `error: FIELD: ...` on standard error, exit code 2.

Options:
  --input FILE       read from FILE (default, or `-`: standard input)
  --per-point        also the error of every control point
  --max-work UNITS   the work budget of the exact job (as for restrict)
  --max-input BYTES  the longest input read (as for restrict)
  -h, --help         print this help
";

fn is_help(arg: &str) -> bool {
    arg == "--help" || arg == "-h"
}

/// Splits `--flag=value` into its flag and value.
fn split_flag(arg: &OsStr) -> (String, Option<OsString>) {
    let text = arg.to_string_lossy();
    match text.split_once('=') {
        Some((flag, _)) if flag.starts_with("--") => {
            // Recover the value as an OsString so that non-UTF-8 file names survive.
            let value = os_suffix(arg, flag.len() + 1);
            (flag.to_string(), Some(value))
        }
        _ => (text.into_owned(), None),
    }
}

/// `arg` without its first `skip` bytes (the `--flag=` prefix, which is ASCII-compatible).
fn os_suffix(arg: &OsStr, skip: usize) -> OsString {
    let bytes = arg.as_encoded_bytes();
    let tail = bytes.get(skip..).unwrap_or_default();
    match std::str::from_utf8(tail) {
        Ok(s) => OsString::from(s),
        // Only reachable for non-UTF-8 arguments: fall back to the lossy text.
        Err(_) => OsString::from(String::from_utf8_lossy(tail).into_owned()),
    }
}

/// Parses the arguments after the program name.
pub fn parse(args: &[OsString]) -> Result<Command, Error> {
    let Some(first) = args.first() else {
        return Ok(Command::Verify {
            json: false,
            verbose: false,
        });
    };
    let first = first.to_string_lossy();
    let rest = &args[1..];
    match first.as_ref() {
        "verify" => parse_verify(rest),
        "restrict" => parse_restrict(rest),
        "check" => parse_check(rest),
        "intersect" => parse_certified(rest, "intersect", INTERSECT_HELP, Command::Intersect),
        "region" => parse_certified(rest, "region", REGION_HELP, Command::Region),
        "figures" => parse_figures(rest),
        "expand" => parse_expand(rest),
        "help" => Ok(Command::Help(HELP)),
        "--version" | "-V" => Ok(Command::Version),
        arg if is_help(arg) => Ok(Command::Help(HELP)),
        arg if arg.starts_with('-') => Err(Error::new(
            arg,
            format!(
                "unknown option (expected a subcommand: {}; see blossom --help){}",
                listed(&SUBCOMMANDS),
                did_you_mean(arg, &["--help", "--version"])
            ),
        )),
        arg => Err(Error::new(
            arg,
            format!(
                "unknown subcommand{} (expected {}; see blossom --help)",
                did_you_mean(arg, &SUBCOMMANDS),
                listed(&SUBCOMMANDS)
            ),
        )),
    }
}

/// `error: FLAG: unknown option for SUBCOMMAND (expected ...)`, with a suggestion.
fn unknown_option(flag: &str, subcommand: &str, flags: &[&str]) -> Error {
    Error::new(
        flag,
        format!(
            "unknown option for {subcommand}{} (expected {})",
            did_you_mean(flag, flags),
            listed(flags)
        ),
    )
}

fn parse_verify(args: &[OsString]) -> Result<Command, Error> {
    let mut json = false;
    let mut verbose = false;
    for arg in args {
        let (flag, value) = split_flag(arg);
        match (flag.as_str(), value) {
            (f, None) if is_help(f) => return Ok(Command::Help(VERIFY_HELP)),
            ("--json", None) => switch(&mut json, "--json")?,
            ("--verbose", None) => switch(&mut verbose, "--verbose")?,
            (f @ ("--json" | "--verbose"), Some(_)) => return Err(Error::new(f, "takes no value")),
            (f, _) if f.starts_with('-') => {
                return Err(unknown_option(f, "verify", &["--json", "--verbose"]))
            }
            (f, _) => return Err(Error::new(f, "unexpected argument for verify")),
        }
    }
    Ok(Command::Verify { json, verbose })
}

/// Sets a flag that takes no value, refusing it a second time.
fn switch(slot: &mut bool, flag: &str) -> Result<(), Error> {
    once(*slot, flag)?;
    *slot = true;
    Ok(())
}

fn parse_figures(args: &[OsString]) -> Result<Command, Error> {
    let mut out: Option<PathBuf> = None;
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        let (flag, inline) = split_flag(arg);
        match flag.as_str() {
            f if is_help(f) && inline.is_none() => return Ok(Command::Help(FIGURES_HELP)),
            "--out" => {
                once(out.is_some(), "--out")?;
                let value = take_value("--out", inline, &mut rest)?;
                if value.is_empty() {
                    return Err(Error::new("--out", "empty directory name"));
                }
                out = Some(PathBuf::from(value));
            }
            f if f.starts_with('-') && f.len() > 1 => {
                return Err(unknown_option(f, "figures", &["--out"]))
            }
            f => {
                return Err(Error::new(
                    f,
                    "unexpected argument for figures (give the directory as --out DIR)",
                ))
            }
        }
    }
    Ok(Command::Figures {
        out: out.unwrap_or_else(|| PathBuf::from("figures")),
    })
}

fn parse_expand(args: &[OsString]) -> Result<Command, Error> {
    let words: Vec<String> = args
        .iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    if words.iter().any(|w| is_help(w)) {
        return Ok(Command::Help(EXPAND_HELP));
    }
    if let Some(flag) = words.iter().find(|w| w.starts_with("--")) {
        return Err(Error::new(
            flag.as_str(),
            "unknown option for expand (expected a shape and its degrees; see `blossom expand --help`)",
        ));
    }
    Ok(Command::Expand(words))
}

/// The value of `flag`: from `--flag=value` or the next argument.
fn take_value(
    flag: &str,
    inline: Option<OsString>,
    rest: &mut std::slice::Iter<'_, OsString>,
) -> Result<OsString, Error> {
    if let Some(value) = inline {
        return Ok(value);
    }
    match rest.next() {
        Some(value) if !value.to_string_lossy().starts_with("--") => Ok(value.clone()),
        _ => Err(Error::new(flag, "missing value")),
    }
}

/// The flags `restrict` and `check` share: `--input`, `--max-work`, `--max-input`.
#[derive(Default)]
struct Common {
    input: Option<Option<PathBuf>>,
    max_work: Option<u64>,
    max_input: Option<u64>,
}

impl Common {
    /// Takes `flag` if it is one of the shared flags; `Ok(false)` if it is not.
    fn take(
        &mut self,
        flag: &str,
        inline: Option<OsString>,
        rest: &mut std::slice::Iter<'_, OsString>,
    ) -> Result<bool, Error> {
        match flag {
            "--input" => {
                once(self.input.is_some(), "--input")?;
                let value = take_value("--input", inline, rest)?;
                self.input = Some(match value.to_str() {
                    Some("-") => None,
                    Some("") => return Err(Error::new("--input", "empty file name")),
                    _ => Some(PathBuf::from(value)),
                });
            }
            "--max-work" => {
                once(self.max_work.is_some(), "--max-work")?;
                let value = take_value("--max-work", inline, rest)?;
                self.max_work = Some(limit_value("--max-work", &value.to_string_lossy())?);
            }
            "--max-input" => {
                once(self.max_input.is_some(), "--max-input")?;
                let value = take_value("--max-input", inline, rest)?;
                self.max_input = Some(limit_value("--max-input", &value.to_string_lossy())?);
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn limits(&self) -> super::cost::Limits {
        super::cost::Limits {
            max_work: self.max_work.unwrap_or(super::cost::DEFAULT_MAX_WORK),
            max_input: self.max_input.unwrap_or(super::cost::DEFAULT_MAX_INPUT),
        }
    }
}

/// The flags of `restrict`, for messages and suggestions.
const RESTRICT_FLAGS: [&str; 5] = [
    "--input",
    "--arithmetic",
    "--method",
    "--max-work",
    "--max-input",
];

/// The flags of `check`, for messages and suggestions.
const CHECK_FLAGS: [&str; 4] = ["--input", "--per-point", "--max-work", "--max-input"];

fn parse_restrict(args: &[OsString]) -> Result<Command, Error> {
    let mut common = Common::default();
    let mut arithmetic: Option<Arithmetic> = None;
    let mut method: Option<MethodChoice> = None;
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        let (flag, inline) = split_flag(arg);
        match flag.as_str() {
            f if is_help(f) && inline.is_none() => return Ok(Command::Help(RESTRICT_HELP)),
            "--arithmetic" => {
                once(arithmetic.is_some(), "--arithmetic")?;
                let value = take_value("--arithmetic", inline, &mut rest)?;
                arithmetic = Some(arithmetic_value(&value)?);
            }
            "--method" => {
                once(method.is_some(), "--method")?;
                let value = take_value("--method", inline, &mut rest)?;
                let name = value.to_string_lossy();
                let Some((_, choice)) = METHOD_NAMES.iter().find(|(n, _)| *n == name) else {
                    let names: Vec<&str> = METHOD_NAMES.iter().map(|(n, _)| *n).collect();
                    return Err(Error::new(
                        "--method",
                        format!(
                            "unknown method {}{} (expected {})",
                            quoted(&name),
                            did_you_mean(&name, &names),
                            listed(&names)
                        ),
                    ));
                };
                method = Some(*choice);
            }
            f => {
                if common.take(f, inline, &mut rest)? {
                    continue;
                }
                if f.starts_with('-') && f.len() > 1 {
                    return Err(unknown_option(f, "restrict", &RESTRICT_FLAGS));
                }
                return Err(Error::new(
                    f,
                    "unexpected argument for restrict (give the job file as --input FILE)",
                ));
            }
        }
    }
    Ok(Command::Restrict(RestrictOptions {
        input: common.input.clone().unwrap_or(None),
        arithmetic: arithmetic.unwrap_or(Arithmetic::Exact),
        method: method.unwrap_or_default(),
        limits: common.limits(),
    }))
}

/// The value of `--arithmetic`: `exact` or `f64`.
fn arithmetic_value(value: &OsStr) -> Result<Arithmetic, Error> {
    match value.to_string_lossy().as_ref() {
        "exact" => Ok(Arithmetic::Exact),
        "f64" => Ok(Arithmetic::F64),
        other => Err(Error::new(
            "--arithmetic",
            format!(
                "unknown arithmetic {}{} (expected exact or f64)",
                quoted(other),
                did_you_mean(other, &["exact", "f64"])
            ),
        )),
    }
}

/// The flags of `intersect` and `region`, for messages and suggestions.
const INTERSECT_FLAGS: [&str; 4] = ["--input", "--arithmetic", "--max-work", "--max-input"];

/// `intersect` and `region`: the same flags, a different help text and command.
fn parse_certified(
    args: &[OsString],
    name: &str,
    help: &'static str,
    command: fn(IntersectOptions) -> Command,
) -> Result<Command, Error> {
    let mut common = Common::default();
    let mut arithmetic: Option<Arithmetic> = None;
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        let (flag, inline) = split_flag(arg);
        match flag.as_str() {
            f if is_help(f) && inline.is_none() => return Ok(Command::Help(help)),
            "--arithmetic" => {
                once(arithmetic.is_some(), "--arithmetic")?;
                let value = take_value("--arithmetic", inline, &mut rest)?;
                arithmetic = Some(arithmetic_value(&value)?);
            }
            f => {
                if common.take(f, inline, &mut rest)? {
                    continue;
                }
                if f.starts_with('-') && f.len() > 1 {
                    return Err(unknown_option(f, name, &INTERSECT_FLAGS));
                }
                return Err(Error::new(
                    f,
                    format!("unexpected argument for {name} (give the job file as --input FILE)"),
                ));
            }
        }
    }
    Ok(command(IntersectOptions {
        input: common.input.clone().unwrap_or(None),
        arithmetic: arithmetic.unwrap_or(Arithmetic::Exact),
        limits: common.limits(),
    }))
}

fn parse_check(args: &[OsString]) -> Result<Command, Error> {
    let mut common = Common::default();
    let mut per_point = false;
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        let (flag, inline) = split_flag(arg);
        match (flag.as_str(), inline) {
            (f, None) if is_help(f) => return Ok(Command::Help(CHECK_HELP)),
            ("--per-point", None) => switch(&mut per_point, "--per-point")?,
            ("--per-point", Some(_)) => return Err(Error::new("--per-point", "takes no value")),
            (f, inline) => {
                if common.take(f, inline, &mut rest)? {
                    continue;
                }
                if f.starts_with('-') && f.len() > 1 {
                    return Err(unknown_option(f, "check", &CHECK_FLAGS));
                }
                return Err(Error::new(
                    f,
                    "unexpected argument for check (give the file as --input FILE)",
                ));
            }
        }
    }
    Ok(Command::Check(CheckOptions {
        input: common.input.clone().unwrap_or(None),
        per_point,
        limits: common.limits(),
    }))
}

/// The value of `--max-work` or `--max-input`: a non-negative integer, written in digits or in
/// scientific notation (`1e12`), at most 2^64 - 1.
fn limit_value(flag: &str, text: &str) -> Result<u64, Error> {
    let well_formed = !text.is_empty()
        && text
            .bytes()
            .all(|b| b.is_ascii_digit() || matches!(b, b'e' | b'E' | b'.' | b'+'));
    match text.parse::<f64>() {
        Ok(x)
            if well_formed
                && x.is_finite()
                && x >= 0.0
                && x <= u64::MAX as f64
                && x.fract() == 0.0 =>
        {
            Ok(x as u64)
        }
        _ => Err(Error::new(
            flag,
            format!(
                "expected a non-negative integer such as 1000000000 or 1e12, found {}",
                quoted(text)
            ),
        )),
    }
}

fn once(seen: bool, flag: &str) -> Result<(), Error> {
    if seen {
        Err(Error::new(flag, "given more than once"))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_strs(args: &[&str]) -> Result<Command, Error> {
        let args: Vec<OsString> = args.iter().map(OsString::from).collect();
        parse(&args)
    }

    #[test]
    fn defaults_and_values() {
        let verify = |json, verbose| Command::Verify { json, verbose };
        assert_eq!(parse_strs(&[]).unwrap(), verify(false, false));
        assert_eq!(
            parse_strs(&["verify", "--json"]).unwrap(),
            verify(true, false)
        );
        assert_eq!(
            parse_strs(&["verify", "--verbose", "--json"]).unwrap(),
            verify(true, true)
        );
        assert_eq!(
            parse_strs(&["figures"]).unwrap(),
            Command::Figures {
                out: PathBuf::from("figures")
            }
        );
        assert_eq!(
            parse_strs(&["figures", "--out=pics"]).unwrap(),
            Command::Figures {
                out: PathBuf::from("pics")
            }
        );
        let Command::Check(c) = parse_strs(&["check", "--per-point", "--max-work", "1e6"]).unwrap()
        else {
            panic!("check")
        };
        assert!(c.per_point);
        assert_eq!((c.input, c.limits.max_work), (None, 1_000_000));
        let Command::Restrict(o) = parse_strs(&["restrict"]).unwrap() else {
            panic!("restrict")
        };
        assert_eq!(o.input, None);
        assert_eq!(o.arithmetic, Arithmetic::Exact);
        assert_eq!(o.method, MethodChoice::Library(Method::Bulk));
        assert_eq!(o.method, MethodChoice::default());
        let Command::Restrict(o) = parse_strs(&[
            "restrict",
            "--method=bulk",
            "--arithmetic",
            "f64",
            "--input",
            "x.json",
        ])
        .unwrap() else {
            panic!("restrict")
        };
        assert_eq!(o.input, Some(PathBuf::from("x.json")));
        assert_eq!(o.arithmetic, Arithmetic::F64);
        assert_eq!(o.method, MethodChoice::Library(Method::Bulk));
    }

    #[test]
    fn errors_name_the_argument() {
        let field = |args: &[&str]| parse_strs(args).unwrap_err().field;
        assert_eq!(field(&["frob"]), "frob");
        assert_eq!(field(&["restrict", "--frob"]), "--frob");
        assert_eq!(field(&["restrict", "--input"]), "--input");
        assert_eq!(
            field(&["restrict", "--input", "--method", "bulk"]),
            "--input"
        );
        assert_eq!(field(&["restrict", "--method", "x"]), "--method");
        assert_eq!(field(&["restrict", "--arithmetic", "f32"]), "--arithmetic");
        assert_eq!(
            field(&["restrict", "--method", "bulk", "--method", "bulk"]),
            "--method"
        );
        assert_eq!(field(&["restrict", "extra"]), "extra");
        assert_eq!(field(&["verify", "--jsn"]), "--jsn");
        assert_eq!(field(&["expand", "curve", "--x"]), "--x");
        assert_eq!(
            field(&["check", "--per-point", "--per-point"]),
            "--per-point"
        );
        assert_eq!(field(&["check", "--method", "bulk"]), "--method");
        assert_eq!(field(&["figures", "--out"]), "--out");
        assert_eq!(field(&["figures", "--out="]), "--out");
        assert_eq!(field(&["figures", "x"]), "x");
        assert_eq!(field(&["verify", "--verbose=1"]), "--verbose");
    }

    #[test]
    fn mistypes_get_the_nearest_name() {
        let message = |args: &[&str]| parse_strs(args).unwrap_err().to_string();
        assert!(message(&["restirct"]).contains("did you mean \"restrict\"?"));
        assert!(message(&["verfy"]).contains("did you mean \"verify\"?"));
        assert!(message(&["figure"]).contains("did you mean \"figures\"?"));
        assert!(message(&["chek"]).contains("did you mean \"check\"?"));
        assert!(message(&["restrict", "--method", "pyramd"]).contains("did you mean \"pyramid\"?"));
        assert!(message(&["restrict", "--method", "closed_form"])
            .contains("did you mean \"closed-form\"?"));
        assert!(
            message(&["restrict", "--method", "taylor"]).contains("did you mean \"taylor-shift\"?")
        );
        assert!(message(&["restrict", "--arithmetic", "F64"]).contains("did you mean \"f64\"?"));
        assert!(message(&["restrict", "--metod", "bulk"]).contains("did you mean \"--method\"?"));
        assert!(message(&["verify", "--jsno"]).contains("did you mean \"--json\"?"));
        // Nothing near: no suggestion, the list of names only.
        let far = message(&["restrict", "--method", "newton"]);
        assert!(!far.contains("did you mean"), "{far}");
        assert!(far.contains("closed-form, definition"), "{far}");
        assert!(!message(&["xyz"]).contains("did you mean"));
    }

    #[test]
    fn help_names_every_method() {
        // `--method` accepts the library's methods in the order of `Method::ALL` (the default
        // first), each by its own name, then `specialised`.
        let expected: Vec<&str> = Method::ALL
            .iter()
            .map(|m| m.name())
            .chain(["specialised"])
            .collect();
        let names: Vec<&str> = METHOD_NAMES.iter().map(|(n, _)| *n).collect();
        assert_eq!(names, expected);
        for (name, choice) in METHOD_NAMES {
            if let MethodChoice::Library(method) = choice {
                assert_eq!(method.name(), name);
            }
        }
        // The help lists each on a line of its own, and marks the default.
        for name in &expected {
            assert!(
                RESTRICT_HELP.contains(&format!("\n      {name} ")),
                "restrict --help does not list {name}"
            );
        }
        let default = MethodChoice::default();
        let (default_name, _) = METHOD_NAMES.iter().find(|(_, c)| *c == default).unwrap();
        assert!(RESTRICT_HELP.contains(&format!("\n      {default_name} ")));
        let default_entry = RESTRICT_HELP
            .split(&format!("\n      {default_name} "))
            .nth(1)
            .and_then(|rest| rest.split("\n      ").next())
            .unwrap_or_default();
        assert!(default_entry.contains("(default)"), "{default_entry}");
        assert_eq!(
            RESTRICT_HELP.matches("(default)").count(),
            2,
            "arithmetic and method"
        );
        // The top-level help shows every flag of verify.
        assert!(HELP.contains("blossom verify [--json] [--verbose]"));
        assert!(VERIFY_HELP.contains("blossom verify [--json] [--verbose]"));
        assert!(CHECK_HELP.contains("bulk"));
    }

    #[test]
    fn expand_takes_its_words() {
        assert_eq!(
            parse_strs(&["expand", "tensor", "3", "2"]).unwrap(),
            Command::Expand(vec!["tensor".into(), "3".into(), "2".into()])
        );
        assert_eq!(
            parse_strs(&["expand", "--help"]).unwrap(),
            Command::Help(EXPAND_HELP)
        );
    }
}
