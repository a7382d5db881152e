//! The work budget of `blossom restrict` and `blossom check`: the work of a job is **metered**
//! as it is done, and a job is stopped when it passes `--max-work`; only a job whose estimate
//! from its sizes alone is far over the limit is refused before computing. Both refusals are one
//! `error: FIELD: the job's work ...` line naming the limit and the flag that raises it.
//!
//! # Why metering
//!
//! An estimate from sizes, degrees and number lengths with one calibrated factor per job family
//! and method cannot be both safe and exact: the work of an algorithm depends on its numbers'
//! growth, the cancellations, the shape of the input, and a factor high enough for the worst
//! input of a family refuses its other inputs that would finish in a fraction of a second (a
//! degree-16 `curve` under `polarisation`, 480 bytes, was estimated at 1.0e9 to 1.3e9 units and
//! refused; it runs in 0.2 to 0.3 s). Metering counts the work the job actually does, so it
//! never refuses a job that finishes within the limit and never lets one run much past it.
//!
//! # The two checks
//!
//! 1. **Up front** ([`up_front`]), from the sizes only, before the numbers are read: the
//!    estimate below, refused when it is over [`UP_FRONT_FACTOR`] times the limit. The factor
//!    is calibrated with the sweep (`cli_budget::budget_sweep`, which records the largest ratio
//!    of estimate to measured time) so that no job of 0.5 s or less is refused by it, while
//!    hopeless inputs (degree 2000 under `definition`, an `elevate` to degree 200 of
//!    332,000-bit numbers) are refused at once without reading or computing anything. A job
//!    between the two (a curve on an interval with ends of exponent 100000 under
//!    `taylor-shift`) goes to the meter, which stops it after the one or two operations that
//!    fit in the limit (1.2 s).
//! 2. **Metered** ([`metered`]): the computation runs under [`blossom::meter::metered`]. The
//!    library's generic algorithms compute through [`blossom::Ring`] in [`blossom::Rational`]
//!    (`--arithmetic exact`, and the jobs that decide exactly) or [`blossom::BoundedF64`]
//!    (`f64`, the carried evaluators included), whose operations charge the meter before they
//!    compute: a constant per operation, plus for rationals a term quadratic in the operands'
//!    bit lengths; one unit is about a nanosecond of a 2-core machine. When the charges pass the
//!    limit the computation unwinds to [`metered`], which answers the refusal.
//!
//! # What escapes the meter
//!
//! Work done outside `Ring` is not metered, and stays under the up-front estimate, which
//! counts it: reading the numbers (the decimal or fraction text into a big rational, quadratic
//! in its length), the binomial and multinomial constants the algorithms build (each used by a
//! charged `scale` right after), the comparisons of knots and breakpoints (`bspline`,
//! `bspline-eval`: O(k log k) beside O(k p^2) charged operations), writing the answer (of the
//! length the charged operations produced), and, in `blossom check`, the exact error of the
//! answer (one subtraction and division per coordinate). The library charges its own exact
//! linear algebra (`num/linalg.rs`: the inverse and products of the matrices of `reduce`)
//! explicitly, operation by operation.
//!
//! # The estimate
//!
//! One unit is about a nanosecond of this machine's time. The estimate is
//!
//! ```text
//! work = reading + operations(kind, method, sizes) * cost of one operation(arithmetic, bits)
//! ```
//!
//! * `operations` counts ring operations of the algorithm the job runs, from its asymptotic
//!   operation count with the constants rounded up (see the functions below, one per family);
//! * one operation costs [`F64_OPERATION`] under `f64` (a double and its running error bound,
//!   [`blossom::BoundedF64`]), and under `exact` [`EXACT_OPERATION`] plus a term quadratic in
//!   the length of the numbers the algorithm meets (the gcd that keeps a big rational in lowest
//!   terms is quadratic): a product of k inputs of b bits has about k b bits, so an algorithm of
//!   degree n on inputs of `b_c` (coefficients) and `b_d` (domain) bits meets numbers of about
//!   `b_c + n b_d + n log2 n` bits;
//! * `reading` is the cost of turning each number's text into a big rational (quadratic in its
//!   length too).
//!
//! The jobs that decide exactly (`bspline`, `rational-*`, the matrices of `reduce`) compute in
//! rationals under both arithmetics, and are estimated so.

use super::args::{Arithmetic, MethodChoice};
use blossom::{Error, Method};
use serde_json::{Map, Value};

/// The default limit on a job's work (`--max-work`): 10^9 units, about a second.
pub const DEFAULT_MAX_WORK: u64 = 1_000_000_000;

/// A job whose estimate is over this many times the limit is refused before computing (see
/// the module documentation): the sweep's largest ratio of estimate to measured time, in
/// units per nanosecond, times 0.5 s over the default limit of 1e9 units, must stay below it
/// (measured: see `cli_budget::budget_sweep`; its worst over-estimate was 132 units per ns,
/// a 40-digit `bspline` job, so a factor of 30 could refuse a job of 0.23 s). The meter, not
/// this check, bounds the work of what it lets through; the factor only has to keep inputs
/// whose sizes alone are hopeless (unmetered reading included) from being read at all.
pub const UP_FRONT_FACTOR: f64 = 100.0;

/// The default limit on the size of a job's input in bytes (`--max-input`): 1 MiB.
pub const DEFAULT_MAX_INPUT: u64 = 1 << 20;

/// Work units of one ring operation under `f64` (with its error bound).
pub const F64_OPERATION: f64 = 40.0;

/// Work units of one ring operation on small exact rationals (allocation and gcd included).
pub const EXACT_OPERATION: f64 = 400.0;

/// Work units per (64-bit limb)^2 of the operands of an exact operation.
const LIMB_PAIR: f64 = 8.0;

/// log2(10): bits per decimal digit.
const BITS_PER_DIGIT: f64 = 3.33;

/// The limits of one run of `blossom restrict`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The largest estimated work of a job that is computed.
    pub max_work: u64,
    /// The largest input, in bytes, that is read.
    pub max_input: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_work: DEFAULT_MAX_WORK,
            max_input: DEFAULT_MAX_INPUT,
        }
    }
}

/// A job's estimated work and the field of the job that drives it.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Work units (see the module documentation).
    pub work: f64,
    /// The field named in a refusal: the one that holds the job's largest size or degree,
    /// or the one with the longest number when the length of the numbers dominates.
    pub field: String,
}

/// The end of every refusal: the unit and the flag that raises the limit.
const RAISE_IT: &str = "(about a nanosecond each; raise it with --max-work if you mean it)";

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

/// Runs `compute` under a work meter of `limits.max_work` units: its result, or the refusal
/// naming `field` when the work passed the limit (the computation is then abandoned). The one
/// metered runner of every subcommand that computes a job.
pub fn metered<R>(
    limits: &Limits,
    field: &str,
    compute: impl FnOnce() -> Result<R, Error>,
) -> Result<R, Error> {
    blossom::meter::metered(limits.max_work, compute).unwrap_or_else(|over| {
        Err(Error::new(
            field,
            format!(
                "the job's work passed the limit of {:.1e} units {RAISE_IT}",
                over.limit as f64
            ),
        ))
    })
}

/// Both checks on the job in `document`: [`up_front`], then `compute` under [`metered`], whose
/// refusal names the field of the estimate.
pub fn budgeted<R>(
    document: &Value,
    method: MethodChoice,
    arithmetic: Arithmetic,
    limits: &Limits,
    compute: impl FnOnce() -> Result<R, Error>,
) -> Result<R, Error> {
    let estimate = up_front(document, method, arithmetic, limits)?;
    metered(limits, &estimate.field, compute)
}

/// Bit lengths of the numbers of one part of a job.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Numbers {
    /// The largest bit length of one number (numerator and denominator together).
    max_bits: f64,
    /// The cost of reading them all, in work units.
    reading: f64,
}

impl Numbers {
    fn and(self, other: Numbers) -> Numbers {
        Numbers {
            max_bits: self.max_bits.max(other.max_bits),
            reading: self.reading + other.reading,
        }
    }
}

/// How a job reads its numbers, for the estimate.
#[derive(Clone, Copy, Debug)]
struct Reading {
    /// As if every number had at most 64 bits (the estimate of the same job with short
    /// numbers, which decides which field a refusal names).
    short: bool,
    /// Under `--arithmetic f64`: a decimal whose exponent puts it beyond the range of doubles
    /// (zero, or an error) costs nothing to read.
    f64: bool,
    /// Under `f64` in a job that computes in doubles: a decimal is read by the standard parser
    /// (its exact error is computed only for short spellings, see `BoundedF64`'s reading), so
    /// only fractions cost a big-number reading.
    doubles: bool,
}

/// The pieces of a number written as `text`: the bit length of its exact value (an upper
/// estimate; 1 for zero digits, whatever the exponent) and, for a decimal, the magnitude of its
/// decimal exponent minus its number of digits (how far it is from the range of doubles).
fn text_parts(text: &str) -> (f64, Option<f64>) {
    let body = text.trim_start_matches(['+', '-']);
    let digits = |s: &str| s.bytes().filter(u8::is_ascii_digit).count() as f64;
    if let Some((p, q)) = body.split_once('/') {
        return ((digits(p) + digits(q)) * BITS_PER_DIGIT + 1.0, None);
    }
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(k) => (&body[..k], &body[k + 1..]),
        None => (body, ""),
    };
    let frac = mantissa.split_once('.').map_or(0.0, |(_, f)| digits(f));
    // The exponent's magnitude, saturating (reading refuses what is over its own limit).
    let e = exponent
        .trim_start_matches(['+', '-'])
        .bytes()
        .take(12)
        .filter(u8::is_ascii_digit)
        .fold(0.0, |acc, d| acc * 10.0 + f64::from(d - b'0'));
    if mantissa.bytes().all(|b| !(b'1'..=b'9').contains(&b)) {
        return (1.0, Some(0.0));
    }
    if e > crate::number::MAX_EXPONENT as f64 {
        // Refused by exact reading (with its own message); zero or out of range in f64.
        return (1.0, Some(f64::MAX));
    }
    let bits = (digits(mantissa) + frac + e) * BITS_PER_DIGIT + 1.0;
    (bits, Some(e - digits(mantissa)))
}

/// The cost of reading one number of `bits` bits into a big rational (the gcd that reduces it
/// is quadratic).
fn reading_cost(bits: f64) -> f64 {
    100.0 + 64.0 * LIMB_PAIR * (bits / 64.0).powi(2)
}

/// One number's bit length and reading cost.
fn leaf(text: &str, reading: Reading) -> Numbers {
    let (bits, beyond) = text_parts(text);
    let cheap = Numbers {
        max_bits: 1.0,
        reading: reading_cost(64.0),
    };
    match beyond {
        // Zero or out of the range of doubles under f64; any decimal in a job of doubles.
        Some(b) if reading.f64 && (b > 400.0 || reading.doubles) => cheap,
        _ if reading.short => Numbers {
            max_bits: bits.min(64.0),
            reading: reading_cost(64.0),
        },
        _ => Numbers {
            max_bits: bits,
            reading: reading_cost(bits),
        },
    }
}

/// The numbers anywhere in `value`.
fn numbers(value: &Value, reading: Reading) -> Numbers {
    match value {
        Value::Number(n) => leaf(&n.to_string(), reading),
        Value::String(s) => leaf(s, reading),
        Value::Array(items) => items
            .iter()
            .map(|v| numbers(v, reading))
            .fold(Numbers::default(), Numbers::and),
        Value::Object(map) => map
            .values()
            .map(|v| numbers(v, reading))
            .fold(Numbers::default(), Numbers::and),
        _ => Numbers::default(),
    }
}

/// The numbers of a field (none when it is missing).
fn numbers_in(value: Option<&Value>, reading: Reading) -> Numbers {
    value.map(|v| numbers(v, reading)).unwrap_or_default()
}

/// The length of an array (0 for anything else).
fn len(value: Option<&Value>) -> f64 {
    match value {
        Some(Value::Array(items)) => items.len() as f64,
        _ => 0.0,
    }
}

/// The length of the first element of an array that is an array itself (0 otherwise).
fn first_len(value: Option<&Value>) -> f64 {
    match value {
        Some(Value::Array(items)) => len(items.first()),
        _ => 0.0,
    }
}

/// The dimension of the points of a list (`[p, ...]`), a grid (`[[p, ...], ...]`) or a list
/// of triangle entries (`[{"point": p}, ...]`): the length of the first point, at least 1.
fn dimension(value: Option<&Value>) -> f64 {
    let mut v = value;
    for _ in 0..3 {
        match v {
            Some(Value::Array(items)) => match items.first() {
                Some(Value::Array(inner)) if !matches!(inner.first(), Some(Value::Array(_))) => {
                    return (inner.len() as f64).max(1.0)
                }
                Some(Value::Object(entry)) => {
                    return dimension(Some(&Value::Array(vec![entry
                        .get("point")
                        .cloned()
                        .unwrap_or(Value::Null)])))
                }
                next => v = next,
            },
            _ => return 1.0,
        }
    }
    1.0
}

/// A degree field's value as the job will read it (0 when it is not a number; reading checks).
fn degree_of(value: Option<&Value>) -> f64 {
    match value {
        Some(Value::Number(n)) => n.as_f64().unwrap_or(0.0).max(0.0),
        Some(Value::String(s)) => s.trim().parse::<f64>().unwrap_or(0.0).max(0.0),
        Some(Value::Array(items)) => items.iter().map(|v| degree_of(Some(v))).fold(0.0, f64::max),
        _ => 0.0,
    }
}

/// What one ring operation costs in the arithmetic, on numbers of about `bits` bits.
#[derive(Clone, Copy, Debug)]
struct Arith {
    exact: bool,
}

impl Arith {
    fn operation(self, bits: f64) -> f64 {
        if self.exact {
            EXACT_OPERATION + LIMB_PAIR * (bits / 64.0).powi(2)
        } else {
            F64_OPERATION
        }
    }
}

/// The bit length of the numbers an algorithm of degree `n` meets, from inputs of
/// `coefficients` and `domain` bits.
fn grown_bits(coefficients: f64, domain: f64, n: f64) -> f64 {
    coefficients + n * domain + n * (n + 2.0).log2() + 64.0
}

/// The index of a method in the rows of [`CALIBRATION`].
fn method_index(method: MethodChoice) -> usize {
    match method {
        MethodChoice::Library(Method::ClosedForm) => 0,
        MethodChoice::Library(Method::Definition) => 1,
        MethodChoice::Library(Method::Pyramid) => 2,
        MethodChoice::Library(Method::Polarisation) => 3,
        MethodChoice::Library(Method::Bulk) => 4,
        MethodChoice::Library(Method::TaylorShift) => 5,
        // The carried evaluators unroll the closed forms.
        MethodChoice::Specialised => 0,
    }
}

/// Measured factors by which the operation counts below are multiplied, per job family and
/// method (closed-form, definition, pyramid, polarisation, bulk, taylor-shift), as
/// `[exact, f64]`: the largest ratio of measured time (ns) to the unscaled estimate seen by a
/// calibration sweep on this machine (jobs of 0.25 s and more), times about 1.5, from when the
/// estimate was the only check. The jobs of one algorithm use their first entry. Now that the
/// estimate only refuses what is far over the limit, what matters is the other direction: the
/// largest over-estimate, which `cli_budget::budget_sweep` records.
#[rustfmt::skip]
const CALIBRATION: [(&str, [[f64; 2]; 6]); 14] = [
    ("curve", [[2.4, 36.0], [3.9, 1.5], [22.0, 0.66], [7.5, 1.7], [3.9, 0.89], [1.6, 0.09]]),
    ("tensor", [[6.3, 4.8], [8.9, 14.0], [9.7, 0.15], [10.0, 0.49], [5.4, 0.44], [3.0, 0.51]]),
    ("triangle", [[11.0, 12.0], [11.0, 1.6], [36.0, 0.35], [4.4, 0.35], [17.0, 0.56], [11.0, 0.79]]),
    ("bezier-curve", [[3.1, 26.0], [3.2, 1.4], [4.5, 0.66], [61.0, 10.0], [5.2, 0.075], [2.6, 0.06]]),
    ("bezier-tensor", [[9.8, 4.0], [8.9, 5.4], [2.6, 0.1], [11.0, 1.8], [8.0, 0.61], [5.2, 0.41]]),
    ("bezier-triangle", [[2.4, 6.3], [5.7, 2.9], [6.2, 0.43], [3.7, 3.0], [17.0, 0.86], [7.5, 1.2]]),
    ("derivative", [[0.27, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("elevate", [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("reduce", [[1.7, 0.35], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("bspline", [[0.58, 0.81], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("bspline-eval", [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("rational-curve", [[7.0, 7.4], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("rational-tensor", [[5.8, 5.6], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
    ("rational-triangle", [[1.7, 1.7], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]),
];

/// The factor of [`CALIBRATION`] for the family `kind`, the method and the arithmetic.
fn calibration(kind: &str, method: MethodChoice, exact: bool) -> f64 {
    CALIBRATION
        .iter()
        .find(|(family, _)| *family == kind)
        .map_or(1.0, |(_, rows)| {
            rows[method_index(method)][usize::from(!exact)]
        })
}

/// How much longer the numbers of `method` grow than those of the other methods: the
/// polarisation formula averages up to n arguments and weighs its terms by size^n / n!, so its
/// numbers are about twice as long (measured with 40-digit inputs: without this, a degree-6
/// Bézier triangle under polarisation ran 2.5 s within the limit).
fn polar_bits(method: MethodChoice) -> f64 {
    if method == MethodChoice::Library(Method::Polarisation) {
        2.0
    } else {
        1.0
    }
}

/// Ring operations of a curve restriction of degree n in dimension d.
fn curve_operations(method: MethodChoice, n: f64, d: f64) -> f64 {
    let k = n + 1.0;
    match method {
        MethodChoice::Library(Method::Bulk | Method::TaylorShift) => 4.0 * k * k * d,
        MethodChoice::Library(Method::ClosedForm | Method::Definition) => 2.0 * k * k * (k + d),
        MethodChoice::Library(Method::Pyramid) | MethodChoice::Specialised => 2.0 * k * k * k * d,
        // Every sub-multiset of every control point's arguments, a Horner evaluation each.
        MethodChoice::Library(Method::Polarisation) => k * k * k * (k + 2.0) * (d + 1.0) / 2.0,
    }
}

/// Ring operations of a tensor restriction of bidegree (n, m) in dimension d.
fn tensor_operations(method: MethodChoice, n: f64, m: f64, d: f64) -> f64 {
    let (k, l) = (n + 1.0, m + 1.0);
    let points = k * l;
    match method {
        MethodChoice::Library(Method::Bulk | Method::TaylorShift) => 4.0 * points * (k + l) * d,
        MethodChoice::Library(Method::ClosedForm | Method::Definition)
        | MethodChoice::Specialised => 2.0 * points * (points * d + k * k + l * l),
        MethodChoice::Library(Method::Pyramid) => 2.0 * points * points * (k + l) * d,
        MethodChoice::Library(Method::Polarisation) => {
            points * (k * k * k / 4.0 + 1.0) * (l * l * l / 4.0 + 1.0) * (d + 1.0)
        }
    }
}

/// Ring operations of a triangle restriction of total degree N with `terms` coefficients in
/// dimension d.
fn triangle_operations(method: MethodChoice, big_n: f64, terms: f64, d: f64) -> f64 {
    let k = big_n + 1.0;
    let points = k * (k + 1.0) / 2.0;
    match method {
        MethodChoice::Library(Method::Bulk | Method::TaylorShift) => 8.0 * points * k * d,
        MethodChoice::Library(Method::ClosedForm) | MethodChoice::Specialised => {
            points * terms * (k * k + d)
        }
        MethodChoice::Library(Method::Definition) => 2.0 * points * terms * (k + d),
        MethodChoice::Library(Method::Pyramid) => 2.0 * points * points * k * d,
        MethodChoice::Library(Method::Polarisation) => (k + 4.0).powi(5) / 60.0 * terms * (d + 1.0),
    }
}

/// The estimate of the job in `document` (zero for what is not a job: reading refuses it).
pub fn estimate(document: &Value, method: MethodChoice, arithmetic: Arithmetic) -> Estimate {
    let zero = || Estimate {
        work: 0.0,
        field: String::from("input"),
    };
    let Value::Object(job) = document else {
        return zero();
    };
    let Some(Value::String(kind)) = job.get("kind") else {
        return zero();
    };
    // A degree over the limit of the reading is refused by the reading, with its own message.
    let named_degrees = ["degree", "to_degree", "total_degree", "order"];
    if named_degrees
        .iter()
        .any(|name| degree_of(job.get(*name)) > super::job::MAX_DEGREE as f64)
    {
        return zero();
    }
    let Some((work, size_field)) = work_of(job, kind, method, arithmetic, false) else {
        return zero();
    };
    // The field to name: the one with the longest number when the numbers' length is what
    // makes the job expensive (the same job with numbers of 64 bits would cost less than a
    // tenth), else the one that holds the sizes.
    let short = work_of(job, kind, method, arithmetic, true).map_or(0.0, |(w, _)| w);
    let field = if short * 10.0 < work {
        longest_number_field(job)
    } else {
        size_field.to_string()
    };
    Estimate { work, field }
}

/// The work of the job `job` of kind `kind` and the field that holds its sizes; `short`: as
/// if every number had at most 64 bits. `None` for an unknown kind.
fn work_of(
    job: &Map<String, Value>,
    kind: &str,
    method: MethodChoice,
    arithmetic: Arithmetic,
    short: bool,
) -> Option<(f64, &'static str)> {
    let arith = Arith {
        exact: arithmetic == Arithmetic::Exact,
    };
    let exact_decisions = matches!(
        kind,
        "bspline" | "rational-curve" | "rational-tensor" | "rational-triangle"
    );
    let reading = Reading {
        short,
        f64: arithmetic == Arithmetic::F64,
        doubles: arithmetic == Arithmetic::F64 && !exact_decisions,
    };
    let exact = Arith { exact: true };
    let g = |name: &str| job.get(name);
    // (work of the algorithm, reading, the field of the sizes, the field of the numbers)
    let (work, reading, size_field, _numbers): (f64, f64, &'static str, Numbers) = match kind {
        "curve" => {
            let (c, i) = (
                numbers_in(g("coefficients"), reading),
                numbers_in(g("interval"), reading),
            );
            let n = (len(g("coefficients")) - 1.0).max(0.0);
            let bits = grown_bits(
                polar_bits(method) * c.max_bits,
                polar_bits(method) * i.max_bits,
                n,
            );
            let ops = curve_operations(method, n, dimension(g("coefficients")));
            (
                ops * arith.operation(bits),
                c.and(i).reading,
                "coefficients",
                c.and(i),
            )
        }
        "bezier-curve" => {
            let (c, i) = (
                numbers_in(g("control_points"), reading),
                numbers_in(g("interval"), reading),
            );
            let n = (len(g("control_points")) - 1.0).max(0.0);
            let d = dimension(g("control_points"));
            let bits = grown_bits(
                polar_bits(method) * c.max_bits,
                polar_bits(method) * i.max_bits,
                n,
            );
            let ops = curve_operations(method, n, d) + 2.0 * (n + 1.0) * (n + 1.0) * d;
            (
                ops * arith.operation(bits),
                c.and(i).reading,
                "control_points",
                c.and(i),
            )
        }
        "derivative" => {
            let c = numbers_in(g("control_points"), reading);
            let n = (len(g("control_points")) - 1.0).max(0.0);
            let d = dimension(g("control_points"));
            let bits = grown_bits(c.max_bits, 0.0, n);
            let ops = 4.0 * (n + 1.0) * (n + 1.0) * d;
            (ops * arith.operation(bits), c.reading, "control_points", c)
        }
        "tensor" | "bezier-tensor" => {
            let grid = if kind == "tensor" {
                "coefficients"
            } else {
                "control_points"
            };
            let (c, r) = (
                numbers_in(g(grid), reading),
                numbers_in(g("rectangle"), reading),
            );
            let n = (len(g(grid)) - 1.0).max(0.0);
            let m = (first_len(g(grid)) - 1.0).max(0.0);
            let d = dimension(g(grid));
            let bits = grown_bits(
                polar_bits(method) * c.max_bits,
                polar_bits(method) * r.max_bits,
                n + m,
            );
            let conversion = 2.0 * (n + 1.0) * (m + 1.0) * (n + m + 2.0) * d;
            let ops = tensor_operations(method, n, m, d) + conversion;
            (
                ops * arith.operation(bits),
                c.and(r).reading,
                grid,
                c.and(r),
            )
        }
        "triangle" | "bezier-triangle" => {
            let grid = if kind == "triangle" {
                "coefficients"
            } else {
                "control_points"
            };
            let (c, t) = (
                numbers_in(g(grid), reading),
                numbers_in(g("triangle"), reading),
            );
            let d = dimension(g(grid));
            let (big_n, terms) = if kind == "bezier-triangle" {
                let entries = len(g(grid));
                // N from the number of entries (N + 1)(N + 2) / 2.
                (
                    ((8.0 * entries + 1.0).sqrt() - 3.0).max(0.0) / 2.0 + 1.0,
                    entries,
                )
            } else if g("total_degree").is_some_and(|v| !v.is_null()) {
                let rows = len(g(grid));
                ((rows - 1.0).max(0.0), rows * (rows + 1.0) / 2.0)
            } else {
                let (rows, columns) = (len(g(grid)), first_len(g(grid)));
                ((rows + columns - 2.0).max(0.0), rows * columns)
            };
            let bits = grown_bits(
                polar_bits(method) * c.max_bits,
                polar_bits(method) * t.max_bits,
                big_n,
            );
            let ops = triangle_operations(method, big_n, terms, d) + 4.0 * terms * big_n * d;
            (
                ops * arith.operation(bits),
                c.and(t).reading,
                grid,
                c.and(t),
            )
        }
        "elevate" => {
            let c = numbers_in(g("control_points"), reading);
            let n = (len(g("control_points")) - 1.0).max(0.0);
            let m = degree_of(g("to_degree")).max(n);
            let d = dimension(g("control_points"));
            let bits = grown_bits(c.max_bits, 0.0, m);
            let ops = 4.0 * (n + 1.0) * (m + 1.0) * d;
            (ops * arith.operation(bits), c.reading, "to_degree", c)
        }
        "reduce" => {
            let c = numbers_in(g("control_points"), reading);
            let n = (len(g("control_points")) - 1.0).max(0.0);
            let m = degree_of(g("to_degree")).min(n);
            let d = dimension(g("control_points"));
            // The Gram matrices and the solve, exact; their entries grow like a Hilbert
            // matrix's, about 4 n log2 n bits.
            let matrix_bits = grown_bits(0.0, 0.0, 4.0 * n);
            let (k, l) = (n + 1.0, m + 1.0);
            let matrices = 4.0 * (k * k * k + l * l * l) * exact.operation(matrix_bits);
            let bits = grown_bits(c.max_bits, 0.0, 4.0 * n);
            let application = 8.0 * k * l * d * arith.operation(bits);
            (matrices + application, c.reading, "control_points", c)
        }
        "bspline" => {
            let pieces = g("pieces");
            let p = degree_of(g("degree"));
            let k = len(pieces);
            let c = numbers_in(pieces, reading);
            let d = match pieces {
                Some(Value::Array(items)) => match items.first() {
                    Some(Value::Object(piece)) => dimension(piece.get("coefficients")),
                    _ => 1.0,
                },
                _ => 1.0,
            };
            let bits = grown_bits(c.max_bits, c.max_bits, p);
            let q = p + 1.0;
            let ops = 4.0 * k * q * q * (q + d);
            (ops * exact.operation(bits), c.reading, "pieces", c)
        }
        "bspline-eval" => {
            let (k, c, t) = (
                numbers_in(g("knots"), reading),
                numbers_in(g("control_points"), reading),
                numbers_in(g("at"), reading),
            );
            let p = degree_of(g("degree"));
            let d = dimension(g("control_points"));
            let at = len(g("at"));
            let q = p + 1.0;
            let bits = grown_bits(c.max_bits, 2.0 * (k.max_bits + t.max_bits), p);
            let ops = at * (2.0 * q * q * (d + 1.0) + len(g("knots")).log2().max(1.0))
                + 4.0 * (len(g("knots")) + len(g("control_points")) * d);
            let all = k.and(c).and(t);
            let field = if at > q { "at" } else { "degree" };
            (ops * arith.operation(bits), all.reading, field, all)
        }
        "rational-curve" => {
            let (nu, de, i) = (
                numbers_in(g("numerator"), reading),
                numbers_in(g("denominator"), reading),
                numbers_in(g("interval"), reading),
            );
            let longest = len(g("numerator")).max(len(g("denominator")));
            let n = degree_of(g("degree")).max((longest - 1.0).max(0.0));
            let d = dimension(g("numerator")) + 1.0;
            let all = nu.and(de).and(i);
            let bits = grown_bits(nu.max_bits.max(de.max_bits), i.max_bits, n);
            let ops = curve_operations(MethodChoice::Library(Method::Polarisation), n, d);
            (ops * exact.operation(bits), all.reading, "numerator", all)
        }
        "rational-tensor" | "rational-triangle" => {
            let (nu, de) = (
                numbers_in(g("numerator"), reading),
                numbers_in(g("denominator"), reading),
            );
            let domain_name = if kind == "rational-tensor" {
                "rectangle"
            } else {
                "triangle"
            };
            let domain = numbers_in(g(domain_name), reading);
            let all = nu.and(de).and(domain);
            let d = dimension(g("numerator")) + 1.0;
            let rows = len(g("numerator")).max(len(g("denominator")));
            let columns = first_len(g("numerator")).max(first_len(g("denominator")));
            let (n, m) = ((rows - 1.0).max(0.0), (columns - 1.0).max(0.0));
            let polarisation = MethodChoice::Library(Method::Polarisation);
            let (degree, ops) = if kind == "rational-tensor" {
                let asked = match g("degree") {
                    Some(Value::Array(items)) => (
                        degree_of(items.first()).max(n),
                        degree_of(items.get(1)).max(m),
                    ),
                    _ => (n, m),
                };
                (
                    asked.0 + asked.1,
                    tensor_operations(polarisation, asked.0, asked.1, d),
                )
            } else {
                let total = if g("total_degree").is_some_and(|v| !v.is_null()) {
                    n
                } else {
                    n + m
                };
                let big_n = degree_of(g("degree")).max(total);
                (
                    big_n,
                    triangle_operations(polarisation, big_n, rows * columns.max(1.0), d),
                )
            };
            let bits = grown_bits(nu.max_bits.max(de.max_bits), domain.max_bits, degree);
            (ops * exact.operation(bits), all.reading, "numerator", all)
        }
        _ => return None,
    };
    let family = match kind {
        "triangle" if job.get("total_degree").is_some_and(|v| !v.is_null()) => "triangle",
        other => other,
    };
    let one_algorithm = !matches!(
        kind,
        "curve" | "tensor" | "triangle" | "bezier-curve" | "bezier-tensor" | "bezier-triangle"
    );
    let (method, exact) = if one_algorithm {
        (
            MethodChoice::Library(Method::ClosedForm),
            arithmetic == Arithmetic::Exact,
        )
    } else {
        (method, arithmetic == Arithmetic::Exact)
    };
    Some((
        work * calibration(family, method, exact) + reading,
        size_field,
    ))
}

/// Reading every number exactly, at its full length.
const EXACT_READING: Reading = Reading {
    short: false,
    f64: false,
    doubles: false,
};

/// The top-level field of `job` that holds the number with the most bits.
fn longest_number_field(job: &Map<String, Value>) -> String {
    job.iter()
        .filter(|(name, _)| name.as_str() != "kind")
        .map(|(name, value)| (name, numbers(value, EXACT_READING).max_bits))
        .fold((String::from("input"), 0.0), |best, (name, bits)| {
            if bits > best.1 {
                (name.clone(), bits)
            } else {
                best
            }
        })
        .0
}
