//! The work budget's machinery, below every job (`budget.rs` puts it together for a document):
//! the limits, the metered runner and the cost model of the `restrict` jobs' estimates.
//!
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
//! 1. **Up front** ([`up_front`](super::budget::up_front)), from the sizes only, before the numbers are read: the
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

use super::args::MethodChoice;
pub use super::args::{Limits, DEFAULT_MAX_INPUT, DEFAULT_MAX_WORK};
use blossom::{Error, Method};
use serde_json::{Map, Value};

/// A job whose estimate is over this many times the limit is refused before computing (see
/// the module documentation): the sweep's largest ratio of estimate to measured time, in
/// units per nanosecond, times 0.5 s over the default limit of 1e9 units, must stay below it
/// (measured: see `cli_budget::budget_sweep`; its worst over-estimate was 132 units per ns,
/// a 40-digit `bspline` job, so a factor of 30 could refuse a job of 0.23 s). The meter, not
/// this check, bounds the work of what it lets through; the factor only has to keep inputs
/// whose sizes alone are hopeless (unmetered reading included) from being read at all.
pub const UP_FRONT_FACTOR: f64 = 100.0;

/// Work units of one ring operation under `f64` (with its error bound).
pub const F64_OPERATION: f64 = 40.0;

/// Work units of one ring operation on small exact rationals (allocation and gcd included).
pub const EXACT_OPERATION: f64 = 400.0;

/// Work units per (64-bit limb)^2 of the operands of an exact operation.
const LIMB_PAIR: f64 = 8.0;

/// log2(10): bits per decimal digit.
const BITS_PER_DIGIT: f64 = 3.33;

/// A job's estimated work and the field of the job that drives it.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Work units (see the module documentation).
    pub work: f64,
    /// The field named in a refusal: the one that holds the job's largest size or degree,
    /// or the one with the longest number when the length of the numbers dominates.
    pub field: String,
}

impl Estimate {
    /// No work, naming the input (for what is not a job: reading refuses it).
    pub fn zero() -> Self {
        Estimate {
            work: 0.0,
            field: String::from("input"),
        }
    }
}

/// The end of every refusal: the unit and the flag that raises the limit.
pub const RAISE_IT: &str = "(about a nanosecond each; raise it with --max-work if you mean it)";

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

/// Bit lengths of the numbers of one part of a job.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Numbers {
    /// The largest bit length of one number (numerator and denominator together).
    pub max_bits: f64,
    /// The cost of reading them all, in work units.
    pub reading: f64,
}

impl Numbers {
    /// Both parts together.
    pub fn and(self, other: Numbers) -> Numbers {
        Numbers {
            max_bits: self.max_bits.max(other.max_bits),
            reading: self.reading + other.reading,
        }
    }
}

/// How a job reads its numbers, for the estimate (the default: exactly, at full length).
#[derive(Clone, Copy, Debug, Default)]
pub struct Spelling {
    /// As if every number had at most 64 bits (the estimate of the same job with short
    /// numbers, which decides which field a refusal names).
    pub short: bool,
    /// Under `--arithmetic f64`: a decimal whose exponent puts it beyond the range of doubles
    /// (zero, or an error) costs nothing to read.
    pub f64: bool,
    /// Under `f64` in a job that computes in doubles: a decimal is read by the standard parser
    /// (its exact error is computed only for short spellings, see `BoundedF64`'s reading), so
    /// only fractions cost a big-number reading.
    pub doubles: bool,
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
fn leaf(text: &str, reading: Spelling) -> Numbers {
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
pub fn numbers(value: &Value, reading: Spelling) -> Numbers {
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

/// Work units of one ring operation on numbers of about `bits` bits, exactly (rationals) or
/// in doubles with their error bounds.
pub fn operation(exact: bool, bits: f64) -> f64 {
    if exact {
        EXACT_OPERATION + LIMB_PAIR * (bits / 64.0).powi(2)
    } else {
        F64_OPERATION
    }
}

/// The bit length of the numbers an algorithm of degree `n` meets, from inputs of
/// `coefficients` and `domain` bits.
pub fn grown_bits(coefficients: f64, domain: f64, n: f64) -> f64 {
    coefficients + n * domain + n * (n + 2.0).log2() + 64.0
}

/// The index of a method in the rows of [`CALIBRATION`].
fn method_index(method: MethodChoice) -> usize {
    match method {
        // The carried evaluators unroll the closed forms.
        MethodChoice::Library(Method::ClosedForm) | MethodChoice::Specialised => 0,
        MethodChoice::Library(Method::Definition) => 1,
        MethodChoice::Library(Method::Pyramid) => 2,
        MethodChoice::Library(Method::Polarisation) => 3,
        MethodChoice::Library(Method::Bulk) => 4,
        MethodChoice::Library(Method::TaylorShift) => 5,
    }
}

/// Measured factors by which a kind's operation count is multiplied, per method
/// (closed-form, definition, pyramid, polarisation, bulk, taylor-shift), as `[exact, f64]`: the
/// largest ratio of measured time (ns) to the unscaled estimate seen by a calibration sweep on
/// this machine (jobs of 0.25 s and more), times about 1.5, from when the estimate was the only
/// check. Each kind keeps its row beside its estimate; the jobs of one algorithm use their first
/// entry. Now that the estimate only refuses what is far over the limit, what matters is the
/// other direction: the largest over-estimate, which `cli_budget::budget_sweep` records.
pub type Calibration = [[f64; 2]; 6];

/// What an estimate is made from: the job as written, the method and the arithmetic.
#[derive(Clone, Copy, Debug)]
pub struct Env<'a> {
    /// The job object.
    pub job: &'a Map<String, Value>,
    /// `--method`.
    pub method: MethodChoice,
    /// `--arithmetic exact`.
    pub exact: bool,
    /// How the numbers are read.
    pub reading: Spelling,
}

impl<'a> Env<'a> {
    /// The numbers anywhere in the field `name` (none when it is missing).
    pub fn numbers(&self, name: &str) -> Numbers {
        self.job
            .get(name)
            .map(|v| numbers(v, self.reading))
            .unwrap_or_default()
    }

    /// Work units of one operation in the job's arithmetic on numbers of about `bits` bits.
    pub fn operation(&self, bits: f64) -> f64 {
        operation(self.exact, bits)
    }

    /// The estimate of a job that computes in rationals under both arithmetics and reads its
    /// numbers as written (`bspline`, the rational jobs).
    pub fn deciding_exactly(self) -> Env<'a> {
        Env {
            reading: Spelling {
                doubles: false,
                ..self.reading
            },
            ..self
        }
    }

    /// The factor of `row` for the method and the arithmetic.
    pub fn calibrated(&self, row: &Calibration) -> f64 {
        row[method_index(self.method)][usize::from(!self.exact)]
    }

    /// The factor `[exact, f64]` of a job of one algorithm for the arithmetic.
    pub fn factor(&self, factor: [f64; 2]) -> f64 {
        factor[usize::from(!self.exact)]
    }

    /// The estimate of a restriction by `--method` (`curve`, `tensor`, `triangle` and their
    /// Bézier forms) of degree `degree` in `ops` ring operations, whose points are the field
    /// `points` and whose domain is the field `domain`, calibrated by `row`: the field named is
    /// `points`.
    pub fn restriction(
        &self,
        (points, domain): (&'static str, &str),
        degree: f64,
        ops: f64,
        row: &Calibration,
    ) -> Option<(f64, &'static str)> {
        let (c, i) = (self.numbers(points), self.numbers(domain));
        let polar = polar_bits(self.method);
        let bits = grown_bits(polar * c.max_bits, polar * i.max_bits, degree);
        let work = ops * self.operation(bits) * self.calibrated(row);
        Some((work + c.and(i).reading, points))
    }
}

/// How much longer the numbers of `method` grow than those of the other methods: the
/// polarisation formula averages up to n arguments and weighs its terms by size^n / n!, so its
/// numbers are about twice as long (measured with 40-digit inputs: without this, a degree-6
/// Bézier triangle under polarisation ran 2.5 s within the limit).
pub fn polar_bits(method: MethodChoice) -> f64 {
    if method == MethodChoice::Library(Method::Polarisation) {
        2.0
    } else {
        1.0
    }
}

/// Ring operations of a curve restriction of degree n in dimension d.
pub fn curve_operations(method: MethodChoice, n: f64, d: f64) -> f64 {
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
pub fn tensor_operations(method: MethodChoice, n: f64, m: f64, d: f64) -> f64 {
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
pub fn triangle_operations(method: MethodChoice, big_n: f64, terms: f64, d: f64) -> f64 {
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

/// The top-level field of `job` that holds the number with the most bits (read exactly, at
/// its full length).
pub fn longest_number_field(job: &Map<String, Value>) -> String {
    let fields = job.iter().filter(|(name, _)| name.as_str() != "kind");
    let fields = fields.map(|(name, value)| (name, numbers(value, Spelling::default()).max_bits));
    let longest = fields.fold(("input", 0.0), |best, (name, bits)| match bits > best.1 {
        true => (name.as_str(), bits),
        false => best,
    });
    longest.0.to_string()
}
