//! Numbers at the edge of the crate: exact reading of the numbers of a JSON job and writing of
//! the numbers of an answer, as the command-line contract (`cli.md`, section "Numbers") asks.
//!
//! # Input
//!
//! A number is a JSON integer of any size, or a JSON string in this grammar (no white space,
//! no underscores, ASCII only):
//!
//! ```text
//! number   = [sign] ( fraction | decimal )
//! sign     = "+" | "-"
//! fraction = digits "/" digits                      "3/4", "-22/7" (denominator unsigned, non-zero)
//! decimal  = ( digits [ "." [digits] ] | "." digits ) [ ("e" | "E") [sign] digits ]
//!                                                   "-7", "0.125", "-1e-3", "2.5E+3", ".5", "5."
//! digits   = one or more of 0-9 (leading zeros allowed)
//! ```
//!
//! The grammar and both readers are the library's ([`blossom::parse_rational`],
//! [`blossom::parse_f64`]); this module adds the JSON layer.
//!
//! Under exact arithmetic every such number is read exactly as a [`Rational`]; the decimal
//! exponent is capped at [`MAX_EXPONENT`] in absolute value so that `"1e999999999"` is a clear
//! error instead of an attempt to build a number with a billion digits (digits that are all
//! zero are zero whatever the exponent: `"0e999999999"` is 0). `"inf"`, `"NaN"` and
//! friends are rejected as non-finite; anything else is rejected as unparsable.
//!
//! A JSON number with a fraction part or an exponent (`0.1`, `1.0`, `1e3`) has already been
//! rounded by whoever wrote it as a binary float, so exact arithmetic rejects it (write it as a
//! string instead). Under `f64` it is accepted.
//!
//! Under `f64`, every input converts to the nearest double: decimals (and JSON numbers) by the
//! correctly rounded standard parser, fractions by exact division rounded once. A value out of
//! the range of `f64` (`"1e400"`) is an error, never an infinity; one too small to represent
//! rounds to zero, as the nearest double does.
//!
//! # Output
//!
//! Exact numbers are JSON strings in lowest terms: `"p/q"` with `q > 1`, or `"p"` when the
//! denominator is 1, the sign on the numerator, zero as `"0"`. Doubles are JSON numbers; a
//! non-finite result is an error (JSON has no infinities, and `null` would be a lie), and
//! `-0.0` is written as `0.0`.
//!
//! Error messages here name no field: the caller prefixes the path of the offending value.

use blossom::{BoundedF64, Rational};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use serde_json::Value;

/// The largest decimal exponent (in absolute value) that exact reading accepts: the library's
/// [`blossom::MAX_DECIMAL_EXPONENT`].
pub const MAX_EXPONENT: u64 = blossom::MAX_DECIMAL_EXPONENT;

/// How many characters of an offending text an error message quotes.
const QUOTE_LIMIT: usize = 40;

/// A number type that jobs can be read into and answers written from: the arithmetic of the
/// command line. Implemented by [`Rational`] (`exact`) and `f64`.
pub trait JsonNumber: crate::specialised::Carried {
    /// The name of the arithmetic on the command line (`exact`, `f64`).
    const ARITHMETIC: &'static str;

    /// Reads a number from a JSON value (see the module documentation for the rules).
    fn from_json(value: &Value) -> Result<Self, String>;

    /// Writes a number of an answer as a JSON value.
    fn to_json(&self) -> Result<Value, String>;
}

impl JsonNumber for Rational {
    const ARITHMETIC: &'static str = "exact";

    fn from_json(value: &Value) -> Result<Self, String> {
        rational_from_json(value)
    }

    fn to_json(&self) -> Result<Value, String> {
        format_rational(self).map(Value::String)
    }
}

impl JsonNumber for f64 {
    const ARITHMETIC: &'static str = "f64";

    fn from_json(value: &Value) -> Result<Self, String> {
        f64_from_json(value)
    }

    fn to_json(&self) -> Result<Value, String> {
        f64_to_json(*self)
    }
}

/// `--arithmetic f64` with error bounds: the doubles of plain `f64` arithmetic (read by the
/// same rules, bit for bit the same values), each carrying a rigorous bound on its distance
/// to the exact result of the same operations on the same input doubles. An answer written
/// from these numbers holds each as `bounded_json` marks it; [`take_error_bound`] turns the
/// marks back into plain JSON numbers and returns the largest bound, the answer's
/// `"error_bound"`.
impl JsonNumber for BoundedF64 {
    const ARITHMETIC: &'static str = "f64";

    /// The nearest double, with the exact distance to the number as written as its bound (so
    /// that an answer's bound covers its distance to the exact answer of the job as written,
    /// and a fortiori to that of the input doubles: every bound is monotone in the inputs').
    fn from_json(value: &Value) -> Result<Self, String> {
        let double = f64_from_json(value)?;
        let text = match value {
            Value::Number(n) => number_text(n),
            Value::String(s) => s.clone(),
            other => return Err(not_a_number(other)),
        };
        // A long decimal, or one far out of the range of doubles, is not read exactly (its
        // gcd would be quadratic in its length): the standard parser rounds it correctly.
        let written = if !text.contains('/') && (text.len() > 64 || decimal_exponent(&text) > 400) {
            Err(String::new())
        } else {
            parse_rational(&text)
        };
        Ok(match written {
            Ok(q) => BoundedF64::rounded_from(&q, double),
            // A spelling exact reading refuses (an exponent over its limit) whose double is
            // correctly rounded: within half an ulp, u |x|, or below the least subnormal.
            Err(_) => BoundedF64::with_bound(double, f64::EPSILON / 2.0 * double.abs() + 5e-324),
        })
    }

    fn to_json(&self) -> Result<Value, String> {
        bounded_json(self)
    }
}

/// The magnitude of the decimal exponent of a decimal's text (saturating; 0 without one).
fn decimal_exponent(text: &str) -> u64 {
    text.find(['e', 'E']).map_or(0, |k| {
        text[k + 1..]
            .trim_start_matches(['+', '-'])
            .bytes()
            .take(8)
            .filter(u8::is_ascii_digit)
            .fold(0, |acc, d| acc * 10 + u64::from(d - b'0'))
    })
}

/// The key of the one-entry object that stands for a bounded double in an answer under
/// construction (a control character, so no field of an answer can have it).
const BOUND_MARK: &str = "\u{1}bounded";

/// A bounded double as `{MARK: [value, bound]}`, until [`take_error_bound`] unmarks it.
fn bounded_json(x: &BoundedF64) -> Result<Value, String> {
    let value = f64_to_json(x.value())?;
    let bound = serde_json::Number::from_f64(x.error_bound())
        .map(Value::Number)
        .unwrap_or(Value::Null);
    let mut mark = serde_json::Map::new();
    mark.insert(BOUND_MARK.into(), Value::Array(vec![value, bound]));
    Ok(Value::Object(mark))
}

/// Replaces every bounded double in `answer` (written by [`BoundedF64`]'s
/// [`JsonNumber::to_json`]) by its plain JSON number and returns the largest bound over them:
/// `Some(0.0)` when there is none, `None` when one of them has no finite bound.
pub fn take_error_bound(answer: &mut Value) -> Option<f64> {
    fn walk(value: &mut Value, largest: &mut Option<f64>) {
        match value {
            Value::Array(items) => items.iter_mut().for_each(|v| walk(v, largest)),
            Value::Object(map) => {
                if map.len() == 1 {
                    if let Some(Value::Array(pair)) = map.get_mut(BOUND_MARK) {
                        let bound = pair.get(1).and_then(Value::as_f64);
                        *largest = match (*largest, bound) {
                            (Some(a), Some(b)) => Some(a.max(b)),
                            _ => None,
                        };
                        *value = pair.first().cloned().unwrap_or(Value::Null);
                        return;
                    }
                }
                map.values_mut().for_each(|v| walk(v, largest));
            }
            _ => {}
        }
    }
    let mut largest = Some(0.0);
    walk(answer, &mut largest);
    largest
}

/// The JSON type of a value, for messages.
pub fn json_type(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// `text` as a JSON string literal for a message, shortened when long.
fn quote(text: &str) -> String {
    let mut chars = text.chars();
    let head: String = chars.by_ref().take(QUOTE_LIMIT).collect();
    let shown = if chars.next().is_some() {
        format!("{head}...")
    } else {
        head
    };
    serde_json::to_string(&shown).unwrap_or_else(|_| String::from("\"?\""))
}

/// Reads a number written as text (see the module documentation) exactly: the library's
/// reader, [`blossom::parse_rational`], with its message as the error.
///
/// ```
/// use blossom_cli::number::{format_rational, parse_rational};
/// let q = parse_rational("-2.5e-1").unwrap();
/// assert_eq!(format_rational(&q).unwrap(), "-1/4");
/// assert!(parse_rational("1/0").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<Rational, String> {
    blossom::parse_rational(text).map_err(|e| e.message)
}

/// Reads a number written as text (see the module documentation) as the nearest `f64`: the
/// library's reader, [`blossom::parse_f64`], with its message as the error.
///
/// ```
/// use blossom_cli::number::parse_f64;
/// assert_eq!(parse_f64("1/3").unwrap(), 1.0 / 3.0);
/// assert_eq!(parse_f64("0.1").unwrap(), 0.1);
/// assert!(parse_f64("1e400").is_err());
/// ```
pub fn parse_f64(text: &str) -> Result<f64, String> {
    blossom::parse_f64(text).map_err(|e| e.message)
}

/// The text of a JSON number (its exact spelling, kept by `arbitrary_precision`).
fn number_text(n: &serde_json::Number) -> String {
    n.to_string()
}

/// Whether the text of a JSON number has a fraction part or an exponent.
fn is_json_integer(text: &str) -> bool {
    !text.contains(['.', 'e', 'E'])
}

/// Reads a number of a JSON job exactly: a JSON integer, or a string of the grammar.
pub fn rational_from_json(value: &Value) -> Result<Rational, String> {
    match value {
        Value::Number(n) => {
            let text = number_text(n);
            if !is_json_integer(&text) {
                return Err(format!(
                    "the JSON number {} has a fraction part or exponent, so it is already \
                     rounded; write it as a string (\"{}\") to read it exactly, or use \
                     --arithmetic f64",
                    shorten(&text),
                    shorten(&text)
                ));
            }
            parse_rational(&text)
        }
        Value::String(s) => parse_rational(s),
        other => Err(not_a_number(other)),
    }
}

/// Reads a number of a JSON job as the nearest `f64`: any JSON number, or a string of the
/// grammar.
pub fn f64_from_json(value: &Value) -> Result<f64, String> {
    match value {
        Value::Number(n) => parse_f64(&number_text(n)),
        Value::String(s) => parse_f64(s),
        other => Err(not_a_number(other)),
    }
}

/// A JSON number's text, shortened for a message.
fn shorten(text: &str) -> String {
    let q = quote(text);
    q[1..q.len() - 1].to_string()
}

fn not_a_number(value: &Value) -> String {
    format!(
        "expected a number (a JSON integer or a string such as \"3/4\"), found {}",
        json_type(value)
    )
}

/// Writes an exact number in lowest terms: `"p/q"` with `q > 1`, `"p"` when `q = 1`, the sign
/// on the numerator, zero as `"0"`. Fails only on a zero denominator, which arithmetic never
/// produces.
pub fn format_rational(q: &Rational) -> Result<String, String> {
    let (numer, denom) = (q.numer(), q.denom());
    if denom.is_zero() {
        return Err(String::from("not a number (zero denominator)"));
    }
    if numer.is_zero() {
        return Ok(String::from("0"));
    }
    let g = numer.gcd(denom);
    let (mut p, mut d) = (numer / &g, denom / &g);
    if d.is_negative() {
        p = -p;
        d = -d;
    }
    Ok(if d.is_one() {
        p.to_string()
    } else {
        format!("{p}/{d}")
    })
}

/// Writes a double as a JSON number; a non-finite value is an error, `-0.0` becomes `0.0`.
pub fn f64_to_json(x: f64) -> Result<Value, String> {
    let x = if x == 0.0 { 0.0 } else { x };
    serde_json::Number::from_f64(x)
        .map(Value::Number)
        .ok_or_else(|| {
            format!(
                "the result {x} is not finite in f64 arithmetic (overflow or an invalid \
                 operation); try --arithmetic exact"
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use serde_json::json;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    fn exact(text: &str) -> String {
        format_rational(&parse_rational(text).unwrap()).unwrap()
    }

    #[test]
    fn integers_of_any_size() {
        assert_eq!(exact("-7"), "-7");
        assert_eq!(exact("+7"), "7");
        assert_eq!(exact("007"), "7");
        assert_eq!(exact("-0"), "0");
        let big = "123456789012345678901234567890123456789012345678901234567890";
        assert_eq!(exact(big), big);
        let v: Value = serde_json::from_str(&format!("[{big}, -{big}]")).unwrap();
        assert_eq!(
            format_rational(&rational_from_json(&v[0]).unwrap()).unwrap(),
            big
        );
        assert_eq!(
            format_rational(&rational_from_json(&v[1]).unwrap()).unwrap(),
            format!("-{big}")
        );
    }

    #[test]
    fn fractions_in_lowest_terms() {
        assert_eq!(exact("3/4"), "3/4");
        assert_eq!(exact("-22/7"), "-22/7");
        assert_eq!(exact("6/8"), "3/4");
        assert_eq!(exact("-6/3"), "-2");
        assert_eq!(exact("0/5"), "0");
        assert_eq!(parse_rational("-10/4").unwrap(), q(-5, 2));
    }

    #[test]
    fn decimals_read_exactly() {
        assert_eq!(exact("0.125"), "1/8");
        assert_eq!(exact("-1e-3"), "-1/1000");
        assert_eq!(exact("2.5E+3"), "2500");
        assert_eq!(exact(".5"), "1/2");
        assert_eq!(exact("5."), "5");
        assert_eq!(exact("0.1"), "1/10");
        assert_eq!(exact("1.50e1"), "15");
        assert_eq!(exact("12.345e-2"), "2469/20000");
        assert_eq!(exact("0e100000"), "0");
        assert_eq!(exact("1e-100000").len(), 2 + 100_001);
    }

    #[test]
    fn bad_text_is_an_error() {
        for bad in [
            "", "inf", "-inf", "Infinity", "NaN", "nan", "1/", "/2", "abc", "1/2/3", "1.2.3", "e5",
            "1e", "1e+", ".", "-", "+", " 1", "1 ", "0x10", "1_000", "1/-2", "--1", "1.5/2", "١",
        ] {
            assert!(parse_rational(bad).is_err(), "{bad:?} should be rejected");
            assert!(
                parse_f64(bad).is_err(),
                "{bad:?} should be rejected under f64"
            );
        }
        assert!(parse_rational("inf")
            .unwrap_err()
            .contains("not a finite number"));
        assert!(parse_rational("abc")
            .unwrap_err()
            .contains("cannot read \"abc\""));
        assert!(parse_rational("").unwrap_err().contains("empty string"));
    }

    #[test]
    fn zero_denominator_is_an_error() {
        for bad in ["1/0", "0/0", "-3/000"] {
            assert!(
                parse_rational(bad)
                    .unwrap_err()
                    .contains("zero denominator"),
                "{bad}"
            );
            assert!(
                parse_f64(bad).unwrap_err().contains("zero denominator"),
                "{bad}"
            );
        }
    }

    #[test]
    fn huge_exponents_are_capped_under_exact() {
        let e = parse_rational("1e999999999").unwrap_err();
        assert!(e.contains("exponent") && e.contains("100000"), "{e}");
        assert!(parse_rational("1e-999999999999999999999999").is_err());
        assert!(parse_rational("1e100000").is_ok());
        assert!(parse_rational("1e100001").is_err());
        assert!(parse_rational("0.000e999999999").unwrap().is_zero());
        assert!(parse_rational("-0e-999999999").unwrap().is_zero());
        // Under f64 the standard parser copes: overflow is an error, underflow rounds to 0.
        assert!(parse_f64("1e999999999")
            .unwrap_err()
            .contains("out of the range"));
        assert_eq!(parse_f64("1e-999999999").unwrap(), 0.0);
    }

    #[test]
    fn json_values() {
        let v = json!([3, "3/4", 0.5, true, null, [1], {"a": 1}]);
        assert_eq!(rational_from_json(&v[0]).unwrap(), q(3, 1));
        assert_eq!(rational_from_json(&v[1]).unwrap(), q(3, 4));
        let e = rational_from_json(&v[2]).unwrap_err();
        assert!(
            e.contains("already rounded") && e.contains("\"0.5\""),
            "{e}"
        );
        assert_eq!(f64_from_json(&v[2]).unwrap(), 0.5);
        for k in 3..7 {
            assert!(rational_from_json(&v[k])
                .unwrap_err()
                .starts_with("expected a number"));
            assert!(f64_from_json(&v[k]).is_err());
        }
        let parsed: Value = serde_json::from_str("[1.0, 1e3, 1E-2, 1e400]").unwrap();
        for k in 0..3 {
            assert!(rational_from_json(&parsed[k]).is_err());
        }
        assert_eq!(f64_from_json(&parsed[1]).unwrap(), 1000.0);
        assert_eq!(f64_from_json(&parsed[2]).unwrap(), 0.01);
        assert!(f64_from_json(&parsed[3]).is_err());
    }

    #[test]
    fn f64_reading_is_nearest() {
        assert_eq!(parse_f64("1/3").unwrap(), 1.0 / 3.0);
        assert_eq!(parse_f64("-22/7").unwrap(), -22.0 / 7.0);
        assert_eq!(parse_f64("0.1").unwrap(), 0.1);
        assert_eq!(parse_f64("-7").unwrap(), -7.0);
        assert_eq!(parse_f64(".5").unwrap(), 0.5);
        // 2^53 + 1 rounds to even.
        assert_eq!(parse_f64("9007199254740993").unwrap(), 9007199254740992.0);
        // A fraction of huge integers is rounded once.
        let big = format!("1{}/1{}", "0".repeat(400), "0".repeat(399));
        assert_eq!(parse_f64(&big).unwrap(), 10.0);
        assert!(parse_f64(&format!("1{}/3", "0".repeat(400))).is_err());
    }

    #[test]
    fn formatting() {
        assert_eq!(format_rational(&q(0, 7)).unwrap(), "0");
        assert_eq!(format_rational(&q(4, -6)).unwrap(), "-2/3");
        assert_eq!(format_rational(&q(9, 3)).unwrap(), "3");
        // A non-normalised value (as from `new_raw`) is still written in lowest terms.
        let raw = Rational::new_raw(BigInt::from(6), BigInt::from(-4));
        assert_eq!(format_rational(&raw).unwrap(), "-3/2");
        let zero_den = Rational::new_raw(BigInt::from(1), BigInt::from(0));
        assert!(format_rational(&zero_den).is_err());
        assert_eq!(f64_to_json(0.5).unwrap().to_string(), "0.5");
        assert_eq!(f64_to_json(-0.0).unwrap().to_string(), "0.0");
        assert!(f64_to_json(f64::INFINITY).is_err());
        assert!(f64_to_json(f64::NAN).is_err());
        assert_eq!(
            Rational::from_json(&json!("-22/7"))
                .unwrap()
                .to_json()
                .unwrap(),
            json!("-22/7")
        );
        assert_eq!(
            f64::from_json(&json!("1/4")).unwrap().to_json().unwrap(),
            json!(0.25)
        );
    }
}
