//! The command line as a type: [`Cli`] derives clap's `Parser`, its subcommands and flags are
//! fields, each value parsed by a function that says what is wrong with it; [`parse`] maps every
//! clap error to the contract's one line `error: FIELD: message` (the argument as FIELD; a
//! mistyped subcommand, option or value gets the nearest accepted name, [`crate::names`]) and
//! turns the parsed type into the [`Command`] the rest of the binary runs. The usage is the
//! help text's (`cli/help/blossom.txt`, [`HELP`]); `blossom completions SHELL` prints a
//! completion script (bash, zsh, fish, elvish, powershell).
//!
//! `--input -` reads standard input, as does leaving `--input` out. A value that starts with
//! `--` is taken for a forgotten value (`--input --method pyramid`: clap refuses it as a
//! missing value); write `--input=--odd-name` for a file whose name starts with `--`. File
//! names are `PathBuf`s, so names that are not UTF-8 are kept intact. The help texts are this
//! module's own (every limit they state is tested equal to the code's).

use crate::names::{did_you_mean, listed, lookup, quoted};
use blossom::{Error, Method};
use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{Args, CommandFactory, Parser, Subcommand};
use std::ffi::OsString;
use std::path::PathBuf;

/// The default limit on a job's work (`--max-work`): 10^9 units, about a second.
pub const DEFAULT_MAX_WORK: u64 = 1_000_000_000;

/// The default limit on the size of a job's input in bytes (`--max-input`): 1 MiB.
pub const DEFAULT_MAX_INPUT: u64 = 1 << 20;

/// The limits of one run of a job (`--max-work`, `--max-input`).
#[derive(Args, Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The work budget.
    #[arg(long = "max-work", value_parser = limit, allow_negative_numbers = true)]
    #[arg(default_value_t = DEFAULT_MAX_WORK)]
    pub max_work: u64,
    /// The longest input read.
    #[arg(long = "max-input", value_parser = limit, allow_negative_numbers = true)]
    #[arg(default_value_t = DEFAULT_MAX_INPUT)]
    pub max_input: u64,
}

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
#[derive(Args, Clone, Debug, PartialEq, Eq)]
pub struct RestrictOptions {
    /// The job file (`-`: standard input).
    #[arg(long)]
    pub input: Option<PathBuf>,
    /// `--max-work` and `--max-input` ([`super::budget`]).
    #[command(flatten)]
    pub limits: Limits,
    /// The arithmetic: exact (the default) or f64.
    #[arg(long, value_parser = arithmetic, default_value = "exact")]
    pub arithmetic: Arithmetic,
    /// The algorithm (bulk by default).
    #[arg(long, value_parser = method, default_value = Method::default().name())]
    pub method: MethodChoice,
}

/// Options of `blossom intersect` and `blossom region`.
#[derive(Args, Clone, Debug, PartialEq, Eq)]
pub struct IntersectOptions {
    /// The job file (`-`: standard input).
    #[arg(long)]
    pub input: Option<PathBuf>,
    /// `--max-work` and `--max-input` ([`super::budget`]).
    #[command(flatten)]
    pub limits: Limits,
    /// How the job's numbers are read: exact (the default) or f64.
    #[arg(long, value_parser = arithmetic, default_value = "exact")]
    pub arithmetic: Arithmetic,
}

/// Options of `blossom check`.
#[derive(Args, Clone, Debug, PartialEq, Eq)]
pub struct CheckOptions {
    /// The job file (`-`: standard input), holding the job and the answer.
    #[arg(long)]
    pub input: Option<PathBuf>,
    /// `--max-work` and `--max-input` ([`super::budget`]), applied to the job.
    #[command(flatten)]
    pub limits: Limits,
    /// The error of every control point, besides the largest.
    #[arg(long = "per-point")]
    pub per_point: bool,
}

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
    /// `blossom completions SHELL`: the shell's completion script.
    Completions(String),
    /// `--help`: print this text and succeed.
    Help(&'static str),
    /// `--version`.
    Version,
}

/// The help of the whole program, the binary's own (`cli/help/`); each subcommand's below.
pub const HELP: &str = include_str!("../../help/blossom.txt");
pub const RESTRICT_HELP: &str = include_str!("../../help/restrict.txt");
pub const EXPAND_HELP: &str = include_str!("../../help/expand.txt");
pub const VERIFY_HELP: &str = include_str!("../../help/verify.txt");
pub const FIGURES_HELP: &str = include_str!("../../help/figures.txt");
pub const INTERSECT_HELP: &str = include_str!("../../help/intersect.txt");
pub const REGION_HELP: &str = include_str!("../../help/region.txt");
pub const CHECK_HELP: &str = include_str!("../../help/check.txt");

/// The command line as clap reads it (help and version are this module's own flags, so that
/// their texts are the contract's).
#[derive(Parser, Debug)]
#[command(
    name = "blossom",
    disable_help_flag = true,
    disable_version_flag = true
)]
#[command(disable_help_subcommand = true, no_binary_name = true)]
pub struct Cli {
    #[arg(short = 'h', long = "help")]
    help: bool,
    #[arg(short = 'V', long = "version")]
    version: bool,
    #[command(subcommand)]
    command: Option<Sub>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
enum Sub {
    /// Re-derive the papers' tables and examples.
    Verify {
        #[arg(long)]
        json: bool,
        #[arg(long)]
        verbose: bool,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// Restrict a curve or surface given as JSON.
    Restrict {
        #[command(flatten)]
        options: RestrictOptions,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// Certified zeros and intersections.
    Intersect {
        #[command(flatten)]
        options: IntersectOptions,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// Certified booleans, triangle intersections and winding numbers.
    Region {
        #[command(flatten)]
        options: IntersectOptions,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// The exact error of another program's f64 answer.
    Check {
        #[command(flatten)]
        options: CheckOptions,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// Draw the papers' figures as SVG files.
    Figures {
        #[arg(long)]
        out: Option<PathBuf>,
        #[arg(short = 'h', long = "help")]
        help: bool,
    },
    /// The function the proc-macro generates for a fixed degree.
    Expand {
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        words: Vec<String>,
    },
    /// Shell completions.
    Completions {
        #[arg(allow_hyphen_values = true)]
        words: Vec<String>,
    },
    /// Help.
    Help,
}

/// The `--input` as given: `None` for standard input (`-` or none), an empty name refused.
fn input(input: Option<PathBuf>) -> Result<Option<PathBuf>, Error> {
    match input.as_deref().map(|p| p.as_os_str()) {
        Some(p) if p.is_empty() => Err(Error::new("--input", "empty file name")),
        Some(p) if p == "-" => Ok(None),
        _ => Ok(input),
    }
}

/// The value of `--arithmetic`: `exact` or `f64`.
fn arithmetic(value: &str) -> Result<Arithmetic, String> {
    let names = [("exact", Arithmetic::Exact), ("f64", Arithmetic::F64)];
    lookup("arithmetic", value, &names)
}

/// The value of `--method`: one of [`METHOD_NAMES`].
fn method(value: &str) -> Result<MethodChoice, String> {
    lookup("method", value, &METHOD_NAMES)
}

/// The value of `--max-work` or `--max-input`: a non-negative integer, written in digits or in
/// scientific notation (`1e12`), at most 2^64 - 1.
fn limit(text: &str) -> Result<u64, String> {
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
        _ => Err(format!(
            "expected a non-negative integer such as 1000000000 or 1e12, found {}",
            quoted(text)
        )),
    }
}

/// Parses the arguments after the program name.
pub fn parse(args: &[OsString]) -> Result<Command, Error> {
    let cli = Cli::try_parse_from(args).map_err(|e| refusal(&e, args))?;
    if cli.help {
        return Ok(Command::Help(HELP));
    }
    if cli.version {
        return Ok(Command::Version);
    }
    match cli.command {
        None => Ok(Command::Verify {
            json: false,
            verbose: false,
        }),
        Some(Sub::Help) => Ok(Command::Help(HELP)),
        Some(Sub::Verify { help: true, .. }) => Ok(Command::Help(VERIFY_HELP)),
        Some(Sub::Verify { json, verbose, .. }) => Ok(Command::Verify { json, verbose }),
        Some(Sub::Restrict { help: true, .. }) => Ok(Command::Help(RESTRICT_HELP)),
        Some(Sub::Intersect { help: true, .. }) => Ok(Command::Help(INTERSECT_HELP)),
        Some(Sub::Region { help: true, .. }) => Ok(Command::Help(REGION_HELP)),
        Some(Sub::Check { help: true, .. }) => Ok(Command::Help(CHECK_HELP)),
        Some(Sub::Restrict { options: o, .. }) => Ok(Command::Restrict(RestrictOptions {
            input: input(o.input)?,
            ..o
        })),
        Some(Sub::Intersect { options: o, .. }) => Ok(Command::Intersect(IntersectOptions {
            input: input(o.input)?,
            ..o
        })),
        Some(Sub::Region { options: o, .. }) => Ok(Command::Region(IntersectOptions {
            input: input(o.input)?,
            ..o
        })),
        Some(Sub::Check { options: o, .. }) => Ok(Command::Check(CheckOptions {
            input: input(o.input)?,
            ..o
        })),
        Some(Sub::Figures { help: true, .. }) => Ok(Command::Help(FIGURES_HELP)),
        Some(Sub::Figures { out, .. }) => match out {
            Some(dir) if dir.as_os_str().is_empty() => {
                Err(Error::new("--out", "empty directory name"))
            }
            out => Ok(Command::Figures {
                out: out.unwrap_or_else(|| PathBuf::from("figures")),
            }),
        },
        Some(Sub::Expand { words }) => {
            if words.iter().any(|w| w == "--help" || w == "-h") {
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
        Some(Sub::Completions { words }) => match words.as_slice() {
            [shell] => Ok(Command::Completions(shell.clone())),
            _ => Err(Error::new(
                "completions",
                "expected one shell: bash, zsh, fish, elvish or powershell",
            )),
        },
    }
}

/// The clap error `e` of the command line `args` as the contract's one-line error.
fn refusal(e: &clap::Error, args: &[OsString]) -> Error {
    let context = |kind: ContextKind| match e.get(kind) {
        Some(ContextValue::String(s)) => s.clone(),
        Some(ContextValue::Strings(v)) => v.join(" "),
        Some(other) => other.to_string(),
        None => String::new(),
    };
    // `--input <INPUT>` names the flag `--input`.
    let argument = context(ContextKind::InvalidArg);
    let flag = argument
        .split([' ', '='])
        .next()
        .unwrap_or_default()
        .to_string();
    let subcommand = args
        .first()
        .map(|a| a.to_string_lossy().into_owned())
        .filter(|a| !a.starts_with('-'))
        .unwrap_or_default();
    let cli = Cli::command();
    let subcommands: Vec<&str> = cli.get_subcommands().map(|c| c.get_name()).collect();
    match e.kind() {
        ErrorKind::InvalidValue if context(ContextKind::InvalidValue).is_empty() => {
            Error::new(flag, "missing value")
        }
        ErrorKind::ValueValidation | ErrorKind::InvalidValue => {
            let message =
                std::error::Error::source(e).map_or_else(|| e.to_string(), |s| s.to_string());
            Error::new(flag, message)
        }
        ErrorKind::ArgumentConflict => Error::new(flag, "given more than once"),
        ErrorKind::TooManyValues | ErrorKind::NoEquals => Error::new(flag, "takes no value"),
        ErrorKind::InvalidSubcommand => {
            let word = context(ContextKind::InvalidSubcommand);
            Error::new(
                word.as_str(),
                format!(
                    "unknown subcommand{} (expected {}; see blossom --help)",
                    did_you_mean(&word, &subcommands),
                    listed(&subcommands)
                ),
            )
        }
        ErrorKind::UnknownArgument => {
            let word = argument.split('=').next().unwrap_or_default().to_string();
            let Some(sub) = cli.find_subcommand(&subcommand) else {
                return Error::new(
                    word.as_str(),
                    format!(
                        "unknown option (expected a subcommand: {}; see blossom --help){}",
                        listed(&subcommands),
                        did_you_mean(&word, &["--help", "--version"])
                    ),
                );
            };
            if word.starts_with('-') && word.len() > 1 {
                // The long flags of the subcommand (help excepted).
                let flags: Vec<String> = sub
                    .get_arguments()
                    .filter_map(|a| a.get_long())
                    .filter(|l| *l != "help")
                    .map(|l| format!("--{l}"))
                    .collect();
                let names: Vec<&str> = flags.iter().map(String::as_str).collect();
                Error::new(
                    word.as_str(),
                    format!(
                        "unknown option for {subcommand}{} (expected {})",
                        did_you_mean(&word, &names),
                        listed(&names)
                    ),
                )
            } else {
                let hint = match subcommand.as_str() {
                    "figures" => " (give the directory as --out DIR)",
                    "verify" => "",
                    _ => " (give the job file as --input FILE)",
                };
                Error::new(
                    word.as_str(),
                    format!("unexpected argument for {subcommand}{hint}"),
                )
            }
        }
        _ => Error::new(
            if flag.is_empty() {
                String::from("arguments")
            } else {
                flag
            },
            e.to_string()
                .lines()
                .next()
                .unwrap_or_default()
                .trim_start_matches("error: ")
                .to_string(),
        ),
    }
}

/// The completion script of `shell` for `blossom`.
pub fn completions(shell: &str) -> Result<String, Error> {
    let shells = ["bash", "zsh", "fish", "elvish", "powershell"];
    let parsed: clap_complete::Shell = shell.parse().map_err(|_| {
        Error::new(
            shell,
            format!(
                "unknown shell{} (expected {})",
                did_you_mean(shell, &shells),
                listed(&shells)
            ),
        )
    })?;
    let mut command = Cli::command().no_binary_name(false);
    let mut out = Vec::new();
    clap_complete::generate(parsed, &mut command, "blossom", &mut out);
    String::from_utf8(out).map_err(|e| Error::new("internal", e.to_string()))
}
