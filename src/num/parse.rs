//! Reading numbers written as text, exactly: the one reader of the crate (the `blossom`
//! binary's JSON jobs read their numbers through it too).
//!
//! The grammar (no white space, no underscores, ASCII only):
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
//! [`parse_rational`] reads every such number exactly; [`parse_f64`] reads it as the nearest
//! double. `str::parse::<Rational>` is num-rational's own parser (`Rational` is a type alias
//! of its `BigRational`, so its `FromStr` cannot be changed here): it reads integers and
//! fractions but no decimal, so `"0.25".parse::<Rational>()` fails where [`parse_rational`]
//! gives 1/4.

use super::ring::{rational_to_f64, Rational};
use crate::error::{Error, ErrorKind, Result};
use num_bigint::BigInt;
use num_traits::Zero;

/// The largest decimal exponent, in absolute value, that [`parse_rational`] accepts: `1e100000`
/// has 100001 digits, about 41 KB as a big integer; beyond it, a short text such as
/// `"1e999999999"` would ask for a number of a billion digits.
pub const MAX_DECIMAL_EXPONENT: u64 = 100_000;

/// How many characters of an offending text an error message quotes.
const QUOTE_LIMIT: usize = 40;

/// The shape of a number written as text, after checking the grammar, with its pieces.
#[derive(Debug, PartialEq, Eq)]
enum Syntax<'a> {
    /// `[sign] digits "/" digits`.
    Fraction {
        negative: bool,
        numerator: &'a str,
        denominator: &'a str,
    },
    /// `[sign] int [. frac] [e exp]`: the value is `int.frac * 10^exp` (either digit string
    /// may be empty, not both).
    Decimal {
        negative: bool,
        int: &'a str,
        frac: &'a str,
        exponent_negative: bool,
        exponent: &'a str,
    },
}

/// `text` as a quoted string for a message (JSON-style escapes), shortened when long.
fn quote(text: &str) -> String {
    let mut chars = text.chars();
    let head: String = chars.by_ref().take(QUOTE_LIMIT).collect();
    let ellipsis = if chars.next().is_some() { "..." } else { "" };
    let mut out = String::from("\"");
    for c in head.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push_str(ellipsis);
    out.push('"');
    out
}

/// Splits off a leading `+` or `-`.
fn split_sign(text: &str) -> (bool, &str) {
    match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    }
}

fn all_digits(s: &str) -> bool {
    s.bytes().all(|b| b.is_ascii_digit())
}

/// The error for a text that is not a number of the grammar.
fn unparsable(text: &str) -> Error {
    if text.is_empty() {
        return Error::of(
            ErrorKind::Empty,
            "",
            "expected a number, found an empty string",
        );
    }
    let (_, body) = split_sign(text);
    let lower = body.to_ascii_lowercase();
    if ["inf", "infinity", "nan"].contains(&lower.as_str()) {
        return Error::of(
            ErrorKind::NotFinite,
            "",
            format!("{} is not a finite number", quote(text)),
        );
    }
    Error::of(
        ErrorKind::Invalid,
        "",
        format!(
            "cannot read {} as a number (expected an integer such as \"-7\", a fraction such as \
             \"3/4\" or a decimal such as \"0.125\")",
            quote(text)
        ),
    )
}

/// Checks `text` against the grammar of the module documentation.
fn scan(text: &str) -> Result<Syntax<'_>> {
    let (negative, body) = split_sign(text);
    if let Some((numerator, denominator)) = body.split_once('/') {
        let ok = !numerator.is_empty()
            && !denominator.is_empty()
            && all_digits(numerator)
            && all_digits(denominator);
        return if ok {
            Ok(Syntax::Fraction {
                negative,
                numerator,
                denominator,
            })
        } else {
            Err(unparsable(text))
        };
    }
    let (mantissa, exponent_part) = match body.find(['e', 'E']) {
        Some(k) => (&body[..k], Some(&body[k + 1..])),
        None => (body, None),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let mantissa_ok = all_digits(int) && all_digits(frac) && !(int.is_empty() && frac.is_empty());
    let (exponent_negative, exponent) = match exponent_part {
        Some(e) => split_sign(e),
        None => (false, ""),
    };
    let exponent_ok = match exponent_part {
        Some(_) => !exponent.is_empty() && all_digits(exponent),
        None => true,
    };
    if mantissa_ok && exponent_ok {
        Ok(Syntax::Decimal {
            negative,
            int,
            frac,
            exponent_negative,
            exponent,
        })
    } else {
        Err(unparsable(text))
    }
}

/// A string of ASCII digits (checked by [`scan`]) as a big integer; empty is zero.
fn digits_to_bigint(digits: &str) -> BigInt {
    if digits.is_empty() {
        return BigInt::zero();
    }
    BigInt::parse_bytes(digits.as_bytes(), 10).unwrap_or_default()
}

/// The value of an exponent's digits, or `None` when it exceeds [`MAX_DECIMAL_EXPONENT`].
fn small_exponent(digits: &str) -> Option<u64> {
    let mut value: u64 = 0;
    for b in digits.bytes() {
        value = value.checked_mul(10)?.checked_add(u64::from(b - b'0'))?;
        if value > MAX_DECIMAL_EXPONENT {
            return None;
        }
    }
    Some(value)
}

/// `10^k` as a big integer.
fn power_of_ten(k: u64) -> BigInt {
    num_traits::pow::pow(BigInt::from(10u32), k as usize)
}

/// Reads a number written as text **exactly**: an integer (`"-7"`), a fraction (`"3/4"`,
/// reduced to lowest terms) or a finite decimal with an optional exponent (`"0.125"`,
/// `"-1e-3"`, `"2.5E+3"`, `".5"`, `"5."`), in the grammar of the module docs. A decimal is
/// the rational it spells (`"0.1"` is 1/10, not the double nearest to it). This is what
/// `"0.25".parse::<Rational>()` is not: that is num-rational's parser, which reads no
/// decimal (`Rational` is a type alias of num-rational's `BigRational`).
///
/// Limits: the decimal exponent is at most [`MAX_DECIMAL_EXPONENT`] in absolute value
/// (digits that are all zero are zero whatever the exponent); the digits themselves are
/// unbounded.
///
/// ```
/// use blossom::{parse_rational, ErrorKind, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// assert_eq!(parse_rational("-7")?, q(-7, 1));
/// assert_eq!(parse_rational("6/8")?, q(3, 4));
/// assert_eq!(parse_rational("0.125")?, q(1, 8));
/// assert_eq!(parse_rational("-1e-3")?, q(-1, 1000));
/// assert_eq!(parse_rational("2.5E+3")?, q(2500, 1));
/// assert!("0.25".parse::<Rational>().is_err());
/// assert_eq!(parse_rational("1/0").unwrap_err().kind(), ErrorKind::ZeroWeight);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// With an empty path (the message quotes the text): [`ErrorKind::Empty`] for an empty
/// string; [`ErrorKind::NotFinite`] for `inf`, `infinity`, `nan` (any case, signed);
/// [`ErrorKind::ZeroWeight`] for a zero denominator; [`ErrorKind::TooLarge`] for an
/// exponent beyond [`MAX_DECIMAL_EXPONENT`]; [`ErrorKind::Invalid`] for any other text
/// outside the grammar (white space, `0x10`, `1_000`, `1/-2`, `1.5/2`, ...).
pub fn parse_rational(text: &str) -> Result<Rational> {
    match scan(text)? {
        Syntax::Fraction {
            negative,
            numerator,
            denominator,
        } => {
            let den = digits_to_bigint(denominator);
            if den.is_zero() {
                return Err(Error::of(
                    ErrorKind::ZeroWeight,
                    "",
                    format!("zero denominator in {}", quote(text)),
                ));
            }
            let q = Rational::new(digits_to_bigint(numerator), den);
            Ok(if negative { -q } else { q })
        }
        Syntax::Decimal {
            negative,
            int,
            frac,
            exponent_negative,
            exponent,
        } => {
            if int.bytes().chain(frac.bytes()).all(|d| d == b'0') {
                // Zero times any power of ten, however large the exponent.
                return Ok(Rational::zero());
            }
            let Some(e) = small_exponent(exponent) else {
                return Err(Error::of(
                    ErrorKind::TooLarge,
                    "",
                    format!(
                        "the exponent of {} is too large (at most {MAX_DECIMAL_EXPONENT} in \
                         absolute value)",
                        quote(text)
                    ),
                ));
            };
            // value = (int frac) * 10^(±e - frac.len())
            let mut digits = String::with_capacity(int.len() + frac.len());
            digits.push_str(int);
            digits.push_str(frac);
            let mantissa = digits_to_bigint(&digits);
            let frac_len = frac.len() as u64;
            let (scale_up, power) = if exponent_negative {
                (false, e + frac_len)
            } else if e >= frac_len {
                (true, e - frac_len)
            } else {
                (false, frac_len - e)
            };
            let ten_power = power_of_ten(power);
            let q = if scale_up {
                Rational::from_integer(mantissa * ten_power)
            } else {
                Rational::new(mantissa, ten_power)
            };
            Ok(if negative { -q } else { q })
        }
    }
}

/// Reads a number of the same grammar as [`parse_rational`] as the **nearest double**
/// (correctly rounded, ties to even): a decimal by the standard library's correctly rounded
/// parser (any exponent), a fraction by exact division rounded once. A value beyond the
/// range of `f64` is an error, never an infinity; one too small to represent rounds to zero,
/// as the nearest double does.
///
/// ```
/// use blossom::parse_f64;
/// assert_eq!(parse_f64("1/3")?, 1.0 / 3.0);
/// assert_eq!(parse_f64("0.1")?, 0.1);
/// assert_eq!(parse_f64("1e-999999999")?, 0.0);
/// assert!(parse_f64("1e400").is_err());
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// As [`parse_rational`] (but for the exponent limit, which this reader has not), and
/// [`ErrorKind::NotFinite`] for a value beyond the range of `f64`.
pub fn parse_f64(text: &str) -> Result<f64> {
    let value = match scan(text)? {
        Syntax::Fraction { .. } => rational_to_f64(&parse_rational(text)?),
        // The grammar is a subset of the standard parser's, which rounds correctly and copes
        // with any exponent (huge ones overflow to infinity, caught below).
        Syntax::Decimal { .. } => text.parse::<f64>().map_err(|_| unparsable(text))?,
    };
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::of(
            ErrorKind::NotFinite,
            "",
            format!("{} is out of the range of f64", quote(text)),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::One;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    fn kind(text: &str) -> ErrorKind {
        parse_rational(text).unwrap_err().kind()
    }

    #[test]
    fn integers_of_any_size() {
        assert_eq!(parse_rational("-7").unwrap(), q(-7, 1));
        assert_eq!(parse_rational("+7").unwrap(), q(7, 1));
        assert_eq!(parse_rational("007").unwrap(), q(7, 1));
        assert_eq!(parse_rational("-0").unwrap(), q(0, 1));
        let big = "123456789012345678901234567890123456789012345678901234567890";
        assert_eq!(parse_rational(big).unwrap().to_string(), big);
        assert_eq!(
            parse_rational(&format!("-{big}")).unwrap().to_string(),
            format!("-{big}")
        );
    }

    #[test]
    fn fractions_in_lowest_terms() {
        assert_eq!(parse_rational("3/4").unwrap(), q(3, 4));
        assert_eq!(parse_rational("-22/7").unwrap(), q(-22, 7));
        assert_eq!(parse_rational("6/8").unwrap().to_string(), "3/4");
        assert_eq!(parse_rational("-6/3").unwrap().to_string(), "-2");
        assert_eq!(parse_rational("0/5").unwrap(), q(0, 1));
        assert_eq!(parse_rational("+10/4").unwrap(), q(5, 2));
    }

    #[test]
    fn decimals_read_exactly() {
        assert_eq!(parse_rational("0.125").unwrap(), q(1, 8));
        assert_eq!(parse_rational("-1e-3").unwrap(), q(-1, 1000));
        assert_eq!(parse_rational("2.5E+3").unwrap(), q(2500, 1));
        assert_eq!(parse_rational(".5").unwrap(), q(1, 2));
        assert_eq!(parse_rational("5.").unwrap(), q(5, 1));
        assert_eq!(parse_rational("0.1").unwrap(), q(1, 10));
        assert_eq!(parse_rational("1.50e1").unwrap(), q(15, 1));
        assert_eq!(parse_rational("12.345e-2").unwrap(), q(2469, 20000));
        assert_eq!(parse_rational("0e100000").unwrap(), q(0, 1));
        let tiny = parse_rational("1e-100000").unwrap();
        assert!(tiny.numer().is_one() && tiny.denom().to_string().len() == 100_001);
        assert!(power_of_ten(0).is_one());
        assert_eq!(power_of_ten(3), BigInt::from(1000));
    }

    #[test]
    fn every_error_has_its_kind() {
        assert_eq!(kind(""), ErrorKind::Empty);
        for text in ["inf", "-inf", "Infinity", "NaN", "nan", "+INF"] {
            assert_eq!(kind(text), ErrorKind::NotFinite, "{text}");
        }
        for text in ["1/0", "0/0", "-3/000"] {
            assert_eq!(kind(text), ErrorKind::ZeroWeight, "{text}");
            assert_eq!(parse_f64(text).unwrap_err().kind(), ErrorKind::ZeroWeight);
        }
        for text in ["1e100001", "1e999999999", "1e-999999999999999999999999"] {
            assert_eq!(kind(text), ErrorKind::TooLarge, "{text}");
        }
        for bad in [
            "1/", "/2", "abc", "1/2/3", "1.2.3", "e5", "1e", "1e+", ".", "-", "+", " 1", "1 ",
            "0x10", "1_000", "1/-2", "--1", "1.5/2", "١", "1e1.5", "1.e", "+-1",
        ] {
            assert_eq!(kind(bad), ErrorKind::Invalid, "{bad:?}");
            assert_eq!(
                parse_f64(bad).unwrap_err().kind(),
                ErrorKind::Invalid,
                "{bad:?}"
            );
        }
        let e = parse_rational("abc").unwrap_err();
        assert_eq!(e.path(), "");
        assert!(
            e.to_string().starts_with("cannot read \"abc\" as a number"),
            "{e}"
        );
        let long = "x".repeat(100);
        assert!(parse_rational(&long)
            .unwrap_err()
            .message
            .contains("xxx...\""));
        assert!(parse_rational("\"\n")
            .unwrap_err()
            .message
            .contains("\"\\\"\\n\""));
    }

    #[test]
    fn exponent_limit_at_its_edge() {
        assert!(parse_rational("1e100000").is_ok());
        assert!(parse_rational("1e-100000").is_ok());
        let e = parse_rational("1e100001").unwrap_err();
        assert!(
            e.message.contains("exponent") && e.message.contains("100000"),
            "{e}"
        );
        assert!(parse_rational("0.000e999999999").unwrap().is_zero());
        assert!(parse_rational("-0e-999999999").unwrap().is_zero());
    }

    #[test]
    fn f64_reading_is_nearest() {
        assert_eq!(parse_f64("1/3").unwrap(), 1.0 / 3.0);
        assert_eq!(parse_f64("-22/7").unwrap(), -22.0 / 7.0);
        assert_eq!(parse_f64("0.1").unwrap(), 0.1);
        assert_eq!(parse_f64(".5").unwrap(), 0.5);
        // 2^53 + 1 rounds to even.
        assert_eq!(parse_f64("9007199254740993").unwrap(), 9007199254740992.0);
        // A fraction of huge integers is rounded once.
        let big = format!("1{}/1{}", "0".repeat(400), "0".repeat(399));
        assert_eq!(parse_f64(&big).unwrap(), 10.0);
        let e = parse_f64(&format!("1{}/3", "0".repeat(400))).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::NotFinite);
        assert!(e.message.contains("out of the range of f64"));
        assert_eq!(
            parse_f64("1e999999999").unwrap_err().kind(),
            ErrorKind::NotFinite
        );
        assert_eq!(parse_f64("1e-999999999").unwrap(), 0.0);
    }
}
