//! The fuzz targets of `fuzz/` (cargo-fuzz, libFuzzer) as plain functions of bytes, so that the
//! targets and the replay of their corpus (`cli/tests/cli/fuzz_corpus.rs`) run the very same
//! code. Each function decodes its input, runs the code under test and asserts its contract; a
//! violated contract (or a panic of the code under test) panics, which is what the fuzzer
//! reports.
//!
//! * [`job_entry`]: `blossom restrict` in process ([`crate::jobs::run`]) with arguments chosen
//!   by the first two bytes and the rest as standard input; the output contract of
//!   `docs/cli.md`, and under `f64` the promise of `"error_bound"` against the exact answer;
//! * [`number_entry`]: the exact number reader ([`crate::number`]) on arbitrary text;
//! * [`restrict_entry`]: the library's restrictions of arbitrary small shapes, every method
//!   against every other in exact arithmetic, and in `f64` the [`BoundedF64`] bound against
//!   the exact answer for the same input doubles.
//!
//! Sizes are capped in the decoders (degrees, dimensions, `--max-work`) so that one input runs
//! in about a millisecond or less: [`restrict_entry`] has lower degree caps in exact
//! arithmetic than in `f64`, and runs the exact methods with the most operations (definition,
//! polarisation, pyramid) at small total degrees only.

use crate::jobs::{self, EXIT_BAD_INPUT};
use crate::number::{
    f64_from_json, format_rational, parse_f64, parse_rational, rational_from_json, JsonNumber,
};
use blossom::engine::{
    bernstein_to_power, tensor_bernstein_to_power, triangle_bernstein_to_power, triangle_index,
    triangle_len,
};
use blossom::{
    rational_to_f64, restrict_power_curve, restrict_power_surface,
    restrict_power_surface_to_triangle, restrict_power_triangle, BezierCurve, BoundedF64, Method,
    PowerCurve, PowerSurface, PowerTriangle, Rational, Ring, TensorPatch, TriangularPatch,
};
use num_bigint::BigInt;
use num_traits::{FromPrimitive, Signed};
use serde_json::Value;
use std::ffi::OsString;

/// The methods `job_entry` picks from (`None`: no `--method`, the default).
const METHODS: [Option<&str>; 8] = [
    Some("closed-form"),
    Some("definition"),
    Some("pyramid"),
    Some("polarisation"),
    Some("specialised"),
    Some("bulk"),
    Some("taylor-shift"),
    None,
];

/// The `--max-work` values `job_entry` picks from: all small, so that every job the budget
/// admits runs in at most about two milliseconds (one unit is about a nanosecond), and `0`,
/// which refuses every job that does any work.
const MAX_WORK: [&str; 4] = ["1000000", "2e6", "0", "100000"];

/// The `--max-input` of the inputs that ask for a small one.
const SMALL_INPUT: &str = "256";

/// The command line `job_entry` runs for the option byte `options`.
fn job_arguments(options: u8, arithmetic: &str) -> Vec<OsString> {
    let method = METHODS[usize::from(options >> 1) & 7];
    let max_work = MAX_WORK[usize::from(options >> 4) & 3];
    let small_input = options & 0x40 != 0;
    let joined = options & 0x80 != 0;
    let mut args = vec![String::from("restrict")];
    let mut flag = |name: &str, value: &str| {
        if joined {
            args.push(format!("{name}={value}"));
        } else {
            args.push(name.to_string());
            args.push(value.to_string());
        }
    };
    flag("--arithmetic", arithmetic);
    if let Some(method) = method {
        flag("--method", method);
    }
    flag("--max-work", max_work);
    if small_input {
        flag("--max-input", SMALL_INPUT);
    }
    args.into_iter().map(OsString::from).collect()
}

/// What a checked run of `blossom restrict` answered: the parsed answer, or `None` for a
/// refusal (exit 2).
fn checked_restrict(args: &[OsString], input: &[u8], f64_answer: bool) -> Option<Value> {
    let outcome = jobs::run(args, &mut &input[..]);
    let context = || format!("args {args:?}, outcome {outcome:?}");
    match outcome.code {
        0 => {
            assert!(
                outcome.stderr.is_empty(),
                "stderr on success: {}",
                context()
            );
            let line = outcome
                .stdout
                .strip_suffix('\n')
                .unwrap_or_else(|| panic!("no final newline: {}", context()));
            assert!(
                !line.contains('\n') && !line.is_empty(),
                "not exactly one line: {}",
                context()
            );
            let answer: Value = serde_json::from_str(line)
                .unwrap_or_else(|e| panic!("answer is not JSON ({e}): {}", context()));
            let object = answer
                .as_object()
                .unwrap_or_else(|| panic!("answer is not an object: {}", context()));
            assert!(
                object.get("kind").is_some_and(Value::is_string),
                "answer without a string \"kind\": {}",
                context()
            );
            match object.get("error_bound") {
                Some(bound) if f64_answer => assert!(
                    bound.is_null() || bound.as_f64().is_some_and(|e| e >= 0.0),
                    "\"error_bound\" neither a non-negative number nor null: {}",
                    context()
                ),
                None if f64_answer => panic!("f64 answer without \"error_bound\": {}", context()),
                Some(_) => panic!("exact answer with \"error_bound\": {}", context()),
                None => check_exact_numbers(&answer),
            }
            Some(answer)
        }
        EXIT_BAD_INPUT => {
            assert!(outcome.stdout.is_empty(), "stdout on error: {}", context());
            let line = outcome
                .stderr
                .strip_suffix('\n')
                .unwrap_or_else(|| panic!("no final newline: {}", context()));
            assert!(
                line.starts_with("error: ") && !line.contains('\n'),
                "not one line `error: ...`: {}",
                context()
            );
            assert!(
                !line.starts_with("error: internal:"),
                "internal error: {}",
                context()
            );
            None
        }
        _ => panic!("exit code other than 0 or 2: {}", context()),
    }
}

/// Every string of an exact answer that reads as a number is written in lowest terms, as
/// `format_rational` writes it.
fn check_exact_numbers(value: &Value) {
    match value {
        Value::String(text) => {
            if let Ok(q) = parse_rational(text) {
                assert_eq!(
                    format_rational(&q).as_deref(),
                    Ok(text.as_str()),
                    "exact number {text:?} not in lowest terms"
                );
            }
        }
        Value::Array(items) => items.iter().for_each(check_exact_numbers),
        Value::Object(map) => map.values().for_each(check_exact_numbers),
        _ => {}
    }
}

/// The exact value of a number of an answer: an exact string or JSON integer, or the double a
/// JSON number of an `f64` answer stands for.
fn answer_number(value: &Value) -> Option<Rational> {
    match value {
        Value::String(text) => parse_rational(text).ok(),
        Value::Number(n) => {
            let text = n.to_string();
            if text.contains(['.', 'e', 'E']) {
                Rational::from_f64(text.parse::<f64>().ok()?)
            } else {
                parse_rational(&text).ok()
            }
        }
        _ => None,
    }
}

/// Checks that the `f64` answer `approx` has the shape of the exact answer `exact` and that
/// every number of it is within `bound` of the exact one.
fn check_within_bound(exact: &Value, approx: &Value, bound: &Rational, path: &str) {
    match (exact, approx) {
        (Value::Object(e), Value::Object(a)) => {
            let keys_a: Vec<&String> = a.keys().filter(|k| *k != "error_bound").collect();
            let keys_e: Vec<&String> = e.keys().collect();
            assert_eq!(keys_e, keys_a, "{path}: the answers have other fields");
            for (key, value) in e {
                check_within_bound(value, &a[key], bound, &format!("{path}.{key}"));
            }
        }
        (Value::Array(e), Value::Array(a)) => {
            assert_eq!(e.len(), a.len(), "{path}: arrays of other lengths");
            for (k, (x, y)) in e.iter().zip(a).enumerate() {
                check_within_bound(x, y, bound, &format!("{path}[{k}]"));
            }
        }
        _ => match (answer_number(exact), answer_number(approx)) {
            (Some(x), Some(y)) => assert!(
                (&x - &y).abs() <= *bound,
                "{path}: exact {exact} and f64 {approx} differ by more than the error bound \
                 {}",
                rational_to_f64(bound)
            ),
            _ => assert_eq!(exact, approx, "{path}: other values"),
        },
    }
}

/// The fuzz target `job_entry`: the first byte chooses the options of `blossom restrict`
/// (bit 0 the arithmetic, bits 1-3 the method, bits 4-5 `--max-work`, bit 6 a small
/// `--max-input`, bit 7 `--flag=value` spelling), the rest is standard input. Asserts the
/// output contract of `docs/cli.md`: exit 0 with one line of JSON on stdout (an object with a
/// string `"kind"`, and under `f64` a numeric or null `"error_bound"`, under `exact` none)
/// and nothing on stderr, or exit 2 with nothing on stdout and one line `error: ...` on stderr
/// (never `error: internal`). When an `f64` answer has a finite bound and the same job is
/// answered exactly, every number of the `f64` answer is within that bound of the exact one.
pub fn job_entry(data: &[u8]) {
    let Some((&options, input)) = data.split_first() else {
        return;
    };
    let f64_mode = options & 1 == 1;
    let arithmetic = if f64_mode { "f64" } else { "exact" };
    let args = job_arguments(options, arithmetic);
    let Some(answer) = checked_restrict(&args, input, f64_mode) else {
        return;
    };
    if !f64_mode {
        return;
    }
    let Some(bound) = answer["error_bound"].as_f64() else {
        return;
    };
    let Some(bound) = Rational::from_f64(bound) else {
        return;
    };
    let exact_args = job_arguments(options & !1, "exact");
    if let Some(exact) = checked_restrict(&exact_args, input, false) {
        check_within_bound(&exact, &answer, &bound, "answer");
    }
}

/// The fuzz target `number_reader`: the bytes as text (invalid UTF-8 replaced) through the
/// exact number reader. Asserts that an accepted exact number is written in lowest terms and
/// reads back to itself; that `parse_f64` is the nearest double of the exact value when both
/// accept the text, that the exact reader accepts whatever `parse_f64` accepts but for an
/// exponent over its cap, and that `parse_f64` refuses an exact number only when it is out of
/// the range of doubles; that the JSON readers agree with the text readers on strings and on
/// JSON numbers; and that the bounded reading of `--arithmetic f64` has the plain double as
/// its value and a bound that covers its distance to the number as written.
pub fn number_entry(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let text = text.as_ref();
    if large_exponent(text) {
        return;
    }
    let exact = parse_rational(text);
    let double = parse_f64(text);
    if let Ok(q) = &exact {
        let written = format_rational(q).expect("a read number has a non-zero denominator");
        assert_eq!(
            parse_rational(&written).as_ref(),
            Ok(q),
            "{text:?} written as {written:?} reads back otherwise"
        );
        assert_eq!(
            format_rational(&parse_rational(&written).expect("read back")).as_deref(),
            Ok(written.as_str()),
            "{written:?} is not in lowest terms"
        );
        let nearest = rational_to_f64(q);
        match &double {
            Ok(x) => assert_eq!(
                *x, nearest,
                "{text:?}: parse_f64 gives {x:e}, the nearest double is {nearest:e}"
            ),
            Err(e) => assert!(
                !nearest.is_finite(),
                "{text:?}: parse_f64 refuses ({e}) a number whose nearest double is {nearest:e}"
            ),
        }
    }
    if let (Err(e), Ok(x)) = (&exact, &double) {
        assert!(
            e.contains("exponent"),
            "{text:?}: parse_f64 reads {x:e}, the exact reader refuses: {e}"
        );
    }
    let string = Value::String(text.to_string());
    assert_eq!(
        rational_from_json(&string),
        exact,
        "{text:?} as a JSON string"
    );
    assert_eq!(f64_from_json(&string), double, "{text:?} as a JSON string");
    check_bounded_reading(&string, exact.as_ref().ok());
    // The text as a JSON document: a JSON number (integers of any size, decimals, exponents).
    if let Ok(value @ Value::Number(_)) = serde_json::from_str::<Value>(text) {
        let json_exact = rational_from_json(&value);
        let json_double = f64_from_json(&value);
        let spelled = parse_rational(&value.to_string());
        if let Ok(q) = &json_exact {
            assert_eq!(Ok(q), spelled.as_ref(), "JSON integer {text:?}");
        }
        if let (Ok(q), Ok(x)) = (&spelled, &json_double) {
            assert_eq!(*x, rational_to_f64(q), "JSON number {text:?}");
        }
        check_bounded_reading(&value, spelled.as_ref().ok());
    }
}

/// The largest decimal exponent [`number_entry`] reads: the exact reading of `1e-100000`
/// takes seconds (the gcd of `Rational::new` on 10^100000, `fuzz/findings/`), so the
/// target skips texts with a larger exponent to keep each run short.
const FUZZ_EXPONENT: u64 = 2000;

/// Whether `text` has an `e` or `E` followed by an optional sign and digits worth more than
/// [`FUZZ_EXPONENT`].
fn large_exponent(text: &str) -> bool {
    text.split(['e', 'E']).skip(1).any(|tail| {
        let digits = tail.trim_start_matches(['+', '-']);
        let digits: String = digits.chars().take_while(char::is_ascii_digit).collect();
        let significant = digits.trim_start_matches('0');
        significant.len() > 6 || significant.parse::<u64>().is_ok_and(|e| e > FUZZ_EXPONENT)
    })
}

/// The bounded double of `value` (as `--arithmetic f64` reads it) is the plain double of
/// [`f64_from_json`] and lies within its bound of `written`, the number as written.
fn check_bounded_reading(value: &Value, written: Option<&Rational>) {
    let bounded = <BoundedF64 as JsonNumber>::from_json(value);
    let plain = f64_from_json(value);
    match (&bounded, &plain) {
        (Ok(b), Ok(x)) => assert_eq!(b.value().to_bits(), x.to_bits(), "{value}: bounded value"),
        (Err(e), Err(f)) => assert_eq!(e, f, "{value}: other errors"),
        _ => panic!("{value}: bounded {bounded:?}, plain {plain:?}"),
    }
    if let (Ok(b), Some(q)) = (&bounded, written) {
        let bound = b.error_bound();
        if bound.is_finite() {
            let value_q = Rational::from_f64(b.value()).expect("a finite double");
            let bound_q = Rational::from_f64(bound).expect("a finite bound");
            assert!(
                (q - value_q).abs() <= bound_q,
                "{value}: the double {:e} is farther than its bound {bound:e} from the number",
                b.value()
            );
        }
    }
}

/// A little reader of fuzz bytes: past the end, every byte is zero.
struct Bytes<'a> {
    data: &'a [u8],
}

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.data.split_first() {
            Some((&b, rest)) => {
                self.data = rest;
                b
            }
            None => 0,
        }
    }

    /// A number in `0..=max`.
    fn upto(&mut self, max: u8) -> usize {
        usize::from(self.byte() % (max + 1))
    }

    /// A small fraction p/q, p in -128..=127, q in 1..=8.
    fn fraction(&mut self) -> (i64, i64) {
        let p = i64::from(self.byte() as i8);
        let q = 1 + i64::from(self.byte() % 8);
        (p, q)
    }

    fn rational(&mut self) -> Rational {
        let (p, q) = self.fraction();
        Rational::new(BigInt::from(p), BigInt::from(q))
    }

    /// A double: a raw bit pattern (NaN, infinities, subnormals, huge), or a small fraction,
    /// or one scaled by a power of two.
    fn double(&mut self) -> f64 {
        match self.byte() % 4 {
            0 => {
                let mut bits = [0u8; 8];
                bits.iter_mut().for_each(|b| *b = self.byte());
                f64::from_le_bytes(bits)
            }
            3 => {
                let (p, q) = self.fraction();
                let e = i32::from(self.byte() % 64) - 32;
                p as f64 / q as f64 * 2f64.powi(e)
            }
            _ => {
                let (p, q) = self.fraction();
                p as f64 / q as f64
            }
        }
    }
}

/// The kinds of shape of [`restrict_entry`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Curve,
    Tensor,
    TriangleGrid,
    PowerTriangle,
    BezierCurve,
    BezierTensor,
    BezierTriangle,
}

/// The sizes of a decoded shape: kind, dimension of the points, degrees (n, m) (for triangles
/// of a given total degree, and for Bézier triangles, n is that degree).
#[derive(Clone, Copy, Debug)]
struct Layout {
    kind: Kind,
    dim: usize,
    n: usize,
    m: usize,
}

impl Layout {
    /// The kind, dimension and degrees, each degree capped by the caps of the arithmetic
    /// (`exact`: [`EXACT_CAPS`], else [`F64_CAPS`]).
    fn decode(bytes: &mut Bytes, exact: bool) -> Self {
        let kind = match bytes.byte() % 7 {
            0 => Kind::Curve,
            1 => Kind::Tensor,
            2 => Kind::TriangleGrid,
            3 => Kind::PowerTriangle,
            4 => Kind::BezierCurve,
            5 => Kind::BezierTensor,
            _ => Kind::BezierTriangle,
        };
        let caps = if exact { EXACT_CAPS } else { F64_CAPS };
        let dim = 1 + bytes.upto(2);
        let (n, m) = match kind {
            Kind::Curve | Kind::BezierCurve => (bytes.upto(caps.curve), 0),
            Kind::Tensor | Kind::BezierTensor => {
                (bytes.upto(caps.tensor.0), bytes.upto(caps.tensor.1))
            }
            Kind::TriangleGrid => (bytes.upto(caps.grid.0), bytes.upto(caps.grid.1)),
            Kind::PowerTriangle | Kind::BezierTriangle => (bytes.upto(caps.triangle), 0),
        };
        Layout { kind, dim, n, m }
    }

    /// The total degree: n for curves and triangles, n + m for the tensor grids.
    fn total_degree(&self) -> usize {
        match self.kind {
            Kind::Curve | Kind::BezierCurve | Kind::PowerTriangle | Kind::BezierTriangle => self.n,
            Kind::Tensor | Kind::BezierTensor | Kind::TriangleGrid => self.n + self.m,
        }
    }

    /// Whether `method` runs on this shape in exact arithmetic: the methods whose exact work
    /// grows fastest with the degree ([`SLOW_METHODS`]) only up to [`SLOW_EXACT_DEGREE`].
    fn admits_exact(&self, method: Method) -> bool {
        !SLOW_METHODS.contains(&method) || self.total_degree() <= SLOW_EXACT_DEGREE
    }

    /// How many points the shape has, and how many domain numbers.
    fn counts(&self) -> (usize, usize) {
        let (n, m) = (self.n, self.m);
        match self.kind {
            Kind::Curve | Kind::BezierCurve => (n + 1, 2),
            Kind::Tensor | Kind::BezierTensor => ((n + 1) * (m + 1), 4),
            Kind::TriangleGrid => ((n + 1) * (m + 1), 6),
            Kind::PowerTriangle | Kind::BezierTriangle => (triangle_len(n), 6),
        }
    }

    /// How many numbers the shape and its domain take.
    fn numbers(&self) -> usize {
        let (points, domain) = self.counts();
        points * self.dim + domain
    }
}

/// The largest degrees [`Layout::decode`] gives: a curve's n, a tensor grid's (n, m), a grid
/// on a triangle's (n, m), a triangle's total degree n.
#[derive(Clone, Copy, Debug)]
struct Caps {
    curve: u8,
    tensor: (u8, u8),
    grid: (u8, u8),
    triangle: u8,
}

/// The caps in `f64` (with [`BoundedF64`] and, for short dyadic inputs, the exact reference):
/// every method runs at these degrees in well under a millisecond.
const F64_CAPS: Caps = Caps {
    curve: 7,
    tensor: (3, 3),
    grid: (3, 2),
    triangle: 5,
};

/// The caps in exact arithmetic, lower: every exact operation reduces its fraction (a gcd),
/// and at the `f64` caps one input took up to 0.3 s (a degree-5 triangle: the pyramid's
/// O(n^5) and polarisation's sums over sub-multisets; perf).
const EXACT_CAPS: Caps = Caps {
    curve: 5,
    tensor: (2, 2),
    grid: (2, 1),
    triangle: 3,
};

/// The methods that [`restrict_entry`] runs in exact arithmetic on small shapes only: the
/// subset sums of the definition (2^n terms per control point of a curve, 3^n of a
/// triangle), the polar forms of polarisation (a sum over sub-multisets of the sample
/// points) and the pyramid (a de Casteljau pyramid per control point, O(n^5) for a triangle)
/// do the most exact operations; at the old caps they took 40-85% of an input's time.
const SLOW_METHODS: [Method; 3] = [Method::Definition, Method::Polarisation, Method::Pyramid];

/// The largest total degree at which the exact arithmetic runs [`SLOW_METHODS`] too.
const SLOW_EXACT_DEGREE: usize = 2;

/// A shape and its new domain, in the arithmetic `T`.
enum Shape<T: Ring> {
    Curve(PowerCurve<T>, [T; 2]),
    Tensor(PowerSurface<T>, [T; 4]),
    TriangleGrid(PowerSurface<T>, [[T; 2]; 3]),
    PowerTriangle(PowerTriangle<T>, [[T; 2]; 3]),
    BezierCurve(BezierCurve<T>, [T; 2]),
    BezierTensor(TensorPatch<T>, [T; 4]),
    BezierTriangle(TriangularPatch<T>, [[T; 2]; 3]),
}

/// The shape of `layout` whose coordinates and domain numbers are `numbers`, in order.
fn build<T: Ring>(layout: &Layout, numbers: &[T]) -> Shape<T> {
    let (points, _) = layout.counts();
    let dim = layout.dim;
    let (coordinates, domain) = numbers.split_at(points * dim);
    let pts: Vec<Vec<T>> = coordinates.chunks(dim).map(<[T]>::to_vec).collect();
    let grid = |cols: usize| -> Vec<Vec<Vec<T>>> { pts.chunks(cols).map(<[_]>::to_vec).collect() };
    let d = |k: usize| domain[k].clone();
    let interval = || [d(0), d(1)];
    let rect = || [d(0), d(1), d(2), d(3)];
    let tri = || [[d(0), d(1)], [d(2), d(3)], [d(4), d(5)]];
    let (n, m) = (layout.n, layout.m);
    let triangle_rows = || -> Vec<Vec<Vec<T>>> {
        (0..=n)
            .map(|i| {
                (0..=n - i)
                    .map(|j| pts[triangle_index(n, i, j)].clone())
                    .collect()
            })
            .collect()
    };
    let ok = "a well-formed shape";
    match layout.kind {
        Kind::Curve => Shape::Curve(PowerCurve::new(pts.clone()).expect(ok), interval()),
        Kind::Tensor => Shape::Tensor(PowerSurface::new(grid(m + 1)).expect(ok), rect()),
        Kind::TriangleGrid => Shape::TriangleGrid(PowerSurface::new(grid(m + 1)).expect(ok), tri()),
        Kind::PowerTriangle => {
            Shape::PowerTriangle(PowerTriangle::new(triangle_rows()).expect(ok), tri())
        }
        Kind::BezierCurve => {
            Shape::BezierCurve(BezierCurve::new(pts.clone()).expect(ok), interval())
        }
        Kind::BezierTensor => Shape::BezierTensor(TensorPatch::new(grid(m + 1)).expect(ok), rect()),
        Kind::BezierTriangle => {
            Shape::BezierTriangle(TriangularPatch::new(n, pts.clone()).expect(ok), tri())
        }
    }
}

/// The ways of computing a restriction: a library method (for a Bézier shape: through its
/// power form, `bernstein_to_power` and its siblings, then the method), or for a Bézier shape
/// the library's direct Bézier restriction (`None`).
fn variants(shape_is_bezier: bool) -> Vec<Option<Method>> {
    let mut all: Vec<Option<Method>> = Method::ALL.iter().copied().map(Some).collect();
    if shape_is_bezier {
        all.insert(0, None);
    }
    all
}

/// The coordinates of a patch's control points, row after row.
fn flat<T: Ring>(patch: TensorPatch<T>) -> Vec<T> {
    patch.into_coordinates()
}

impl<T: Ring> Shape<T> {
    fn is_bezier(&self) -> bool {
        matches!(
            self,
            Shape::BezierCurve(..) | Shape::BezierTensor(..) | Shape::BezierTriangle(..)
        )
    }

    /// The control points of the restriction computed by `variant`, as flat coordinates.
    fn restrict(&self, variant: Option<Method>) -> Vec<T> {
        let direct = "the direct restriction applies to Bézier shapes only";
        match self {
            Shape::Curve(c, [a, b]) => restrict_power_curve(c, a, b, variant.expect(direct))
                .control_points()
                .concat(),
            Shape::Tensor(s, rect) => flat(restrict_power_surface(s, rect, variant.expect(direct))),
            Shape::TriangleGrid(s, tri) => {
                restrict_power_surface_to_triangle(s, tri, variant.expect(direct))
                    .control_points()
                    .concat()
            }
            Shape::PowerTriangle(s, tri) => restrict_power_triangle(s, tri, variant.expect(direct))
                .control_points()
                .concat(),
            Shape::BezierCurve(c, [a, b]) => match variant {
                None => c.subsegment(a.clone()..b.clone()).control_points().concat(),
                Some(method) => {
                    let power = PowerCurve::new(bernstein_to_power(&c.control_points().to_vec()))
                        .expect("the power form of a curve");
                    restrict_power_curve(&power, a, b, method)
                        .control_points()
                        .concat()
                }
            },
            Shape::BezierTensor(p, rect) => match variant {
                None => flat(p.restrict(rect)),
                Some(method) => flat(restrict_power_surface(
                    &tensor_bernstein_to_power(p),
                    rect,
                    method,
                )),
            },
            Shape::BezierTriangle(p, tri) => match variant {
                None => p.restrict(tri).control_points().concat(),
                Some(method) => {
                    restrict_power_triangle(&triangle_bernstein_to_power(p), tri, method)
                        .control_points()
                        .concat()
                }
            },
        }
    }
}

/// Whether a double is a short dyadic number: zero, or m 2^e with an odd m of at most 24 bits
/// and a magnitude in [2^-16, 2^16]. These are the inputs whose exact answer the target
/// computes as the reference of the bounds: on doubles of 53 significant bits the exact answer
/// takes tens of milliseconds (the gcd of every rational operation), too slow for a fuzz run.
fn moderate(x: f64) -> bool {
    if x == 0.0 {
        return true;
    }
    if !x.is_finite() || !(2f64.powi(-16)..=2f64.powi(16)).contains(&x.abs()) {
        return false;
    }
    // Exact: a power-of-two scaling of a double in this range is an integer below 2^56.
    let scaled = (x.abs() * 2f64.powi(40)) as u64;
    scaled as f64 == x.abs() * 2f64.powi(40) && (scaled >> scaled.trailing_zeros()) < 1 << 24
}

/// The fuzz target `restrict_shapes`: the first byte chooses exact (even) or `f64` (odd)
/// arithmetic, then `Layout::decode` a shape (power curve, tensor grid, grid on a triangle,
/// triangular array, Bézier curve, patch or triangle) of small degree (the private caps
/// `F64_CAPS` and `EXACT_CAPS`), then its coordinates and domain.
///
/// In exact arithmetic every method of [`Method::ALL`] (and for Bézier input the direct Bézier
/// restriction, and the barycentric form of the triangle's) gives the identical answer; the
/// methods that grow fastest with the degree (`SLOW_METHODS`) take part up to total degree
/// `SLOW_EXACT_DEGREE`. In `f64` (every method at every degree) nothing panics on any doubles
/// (NaN, infinities, huge); [`BoundedF64`] computes bit for bit the values of plain `f64`, and
/// when every input is a short dyadic number (`moderate`), every finite bound covers the
/// distance to the exact answer for the same input doubles.
pub fn restrict_entry(data: &[u8]) {
    let mut bytes = Bytes { data };
    let f64_mode = bytes.byte() & 1 == 1;
    let layout = Layout::decode(&mut bytes, !f64_mode);
    let count = layout.numbers();
    if !f64_mode {
        let numbers: Vec<Rational> = (0..count).map(|_| bytes.rational()).collect();
        let shape = build(&layout, &numbers);
        let mut variants = variants(shape.is_bezier());
        variants.retain(|variant| variant.is_none_or(|method| layout.admits_exact(method)));
        let reference = shape.restrict(variants[0]);
        for &variant in &variants[1..] {
            assert_eq!(
                shape.restrict(variant),
                reference,
                "{layout:?}: {variant:?} differs from {:?} on {numbers:?}",
                variants[0]
            );
        }
        if let Shape::BezierTriangle(patch, tri) = &shape {
            // Every control point is the blossom at the corners, q_(ν μ λ) = b[A^ν, B^μ, C^λ],
            // by the barycentric pyramid (one per point) instead of the halving net.
            let one = Rational::from_integer(1.into());
            let corners = tri
                .clone()
                .map(|[s, t]| [s.clone(), t.clone(), &one - &s - &t]);
            let n = patch.degree();
            let mut by_blossom = Vec::with_capacity(reference.len());
            for nu in 0..=n {
                for mu in 0..=n - nu {
                    let args: Vec<[Rational; 3]> = std::iter::repeat_n(corners[0].clone(), nu)
                        .chain(std::iter::repeat_n(corners[1].clone(), mu))
                        .chain(std::iter::repeat_n(corners[2].clone(), n - nu - mu))
                        .collect();
                    by_blossom.extend(patch.blossom(&args).expect("N arguments"));
                }
            }
            assert_eq!(by_blossom, reference, "the blossom at the corners");
        }
        return;
    }
    let numbers: Vec<f64> = (0..count).map(|_| bytes.double()).collect();
    let plain = build(&layout, &numbers);
    let bounded_numbers: Vec<BoundedF64> = numbers.iter().map(|&x| BoundedF64::exact(x)).collect();
    let bounded = build(&layout, &bounded_numbers);
    let exact = if numbers.iter().all(|&x| moderate(x)) {
        let exact_numbers: Vec<Rational> = numbers
            .iter()
            .map(|&x| Rational::from_f64(x).expect("a finite double"))
            .collect();
        let shape = build(&layout, &exact_numbers);
        let variant = variants(shape.is_bezier())[0];
        Some(shape.restrict(variant))
    } else {
        None
    };
    for variant in variants(plain.is_bezier()) {
        let values = plain.restrict(variant);
        let with_bounds = bounded.restrict(variant);
        assert_eq!(values.len(), with_bounds.len());
        for (k, (x, b)) in values.iter().zip(&with_bounds).enumerate() {
            let same = x.to_bits() == b.value().to_bits() || (x.is_nan() && b.value().is_nan());
            assert!(
                same,
                "{layout:?} {variant:?}: coordinate {k}: f64 {x:e}, BoundedF64 {:e}, on {numbers:?}",
                b.value()
            );
            let Some(exact) = &exact else { continue };
            let bound = b.error_bound();
            if !bound.is_finite() {
                continue;
            }
            let value = Rational::from_f64(b.value()).unwrap_or_else(|| {
                panic!(
                    "{layout:?} {variant:?}: coordinate {k}: the value {:e} is not finite \
                     with the finite bound {bound:e}, on {numbers:?}",
                    b.value()
                )
            });
            let bound_q = Rational::from_f64(bound).expect("a finite bound");
            let distance = (&exact[k] - &value).abs();
            assert!(
                distance <= bound_q,
                "{layout:?} {variant:?}: coordinate {k}: f64 {:e} is {:e} from the exact {:e}, \
                 over its bound {bound:e}, on {numbers:?}",
                b.value(),
                rational_to_f64(&distance),
                rational_to_f64(&exact[k])
            );
        }
    }
}
