//! The worked examples of seed 002 (de Boor points through blossoms) and seed 004 (inverse
//! relations for blossoms, rational curves, degree elevation and reduction).
//!
//! Printed values are transcribed as data (numbers and formulas in the papers' own form, read
//! by [`expr`]) and compared with values computed by the library; formulas with symbols
//! (alpha, beta, t_1, ln 2, ...) are compared as polynomials, which proves them for every value
//! of the symbols. Where a printed value or step does not hold, the section says what holds
//! instead.

pub mod circle;
pub mod expr;
pub mod inverse;
pub mod logarithm;
pub mod reduction;
pub mod splines;

use super::report::{Entry, Section};
use blossom::Rational;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::str::FromStr;

/// Every section of seeds 002 and 004, in the order of the papers.
pub fn sections() -> Vec<Section> {
    let mut out = splines::sections();
    out.extend(inverse::sections());
    out.extend(circle::sections());
    out.extend(reduction::sections());
    out.extend(logarithm::sections());
    out
}

/// A printed number: an integer, a fraction `p/q`, or a decimal with a point or the Spanish
/// decimal comma (`0,8`).
pub fn num(text: &str) -> Rational {
    let t = text.trim().replace(',', ".");
    if let Some((int, frac)) = t.split_once('.') {
        let negative = int.starts_with('-');
        let digits = format!("{}{frac}", int.trim_start_matches('-'));
        let mut v = Rational::new(
            BigInt::from_str(&digits).expect("transcribed decimal"),
            BigInt::from(10u32).pow(frac.len() as u32),
        );
        if negative {
            v = -v;
        }
        v
    } else {
        Rational::from_str(&t).expect("transcribed fraction")
    }
}

/// A printed point `(x, y, ...)` of numbers as [`num`] reads them (coordinates separated by
/// `;` when they use the decimal comma).
pub fn point(text: &str) -> Vec<Rational> {
    let inner = text.trim().trim_start_matches('(').trim_end_matches(')');
    let sep = if inner.contains(';') { ';' } else { ',' };
    inner.split(sep).map(num).collect()
}

/// `(x, y, ...)` in lowest terms.
pub fn show(p: &[Rational]) -> String {
    let parts: Vec<String> = p.iter().map(|x| x.to_string()).collect();
    format!("({})", parts.join(", "))
}

/// An entry.
pub fn entry(
    label: impl Into<String>,
    printed: impl Into<String>,
    computed: impl Into<String>,
    matches: bool,
) -> Entry {
    Entry {
        label: label.into(),
        printed: printed.into(),
        computed: computed.into(),
        matches,
    }
}

/// `x` in scientific notation with `digits` significant digits, e.g. `1.7364e-7`.
pub fn sci(x: &Rational, digits: usize) -> String {
    if x.is_zero() {
        return "0".into();
    }
    let sign = if x.is_negative() { "-" } else { "" };
    let a = x.abs();
    let ten = Rational::from_integer(BigInt::from(10));
    // Find e with 10^e <= a < 10^(e+1).
    let mut e: i64 = 0;
    let mut scaled = a.clone();
    while scaled >= ten {
        scaled /= &ten;
        e += 1;
    }
    while scaled < Rational::from_integer(BigInt::from(1)) {
        scaled *= &ten;
        e -= 1;
    }
    let factor = BigInt::from(10).pow(digits.saturating_sub(1) as u32);
    let mut m = (scaled * Rational::from_integer(factor.clone()))
        .round()
        .to_integer();
    if m >= &factor * 10 {
        m /= 10;
        e += 1;
    }
    let s = m.to_string();
    let mantissa = if s.len() > 1 {
        format!("{}.{}", &s[..1], &s[1..])
    } else {
        s
    };
    format!("{sign}{mantissa}e{e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_scientific_notation() {
        assert_eq!(num("0,8"), Rational::new(4.into(), 5.into()));
        assert_eq!(num("-29/10"), Rational::new((-29).into(), 10.into()));
        assert_eq!(point("(1.8; 2,6)"), vec![num("9/5"), num("13/5")]);
        assert_eq!(sci(&num("0.00000017364"), 3), "1.74e-7");
        assert_eq!(sci(&num("-999.6"), 3), "-1.00e3");
        assert_eq!(sci(&num("2"), 1), "2e0");
    }
}
