//! The transcribed data the pictures start from (fractions and points written as text in
//! `verify::paper_data` and `verify::seeds_002_004`), read into exact rationals without
//! panicking: a malformed entry is an error naming it.

use blossom::{Error, Rational};
use std::str::FromStr;

/// A fraction `p/q` or an integer.
pub fn rational(text: &str) -> Result<Rational, Error> {
    Rational::from_str(text.trim()).map_err(|_| {
        Error::new(
            "figures",
            format!("transcribed number {text:?} is not a fraction"),
        )
    })
}

/// A point `(x, y, ...)` of fractions separated by commas.
pub fn point(text: &str) -> Result<Vec<Rational>, Error> {
    let inner = text.trim().trim_start_matches('(').trim_end_matches(')');
    inner.split(',').map(rational).collect()
}

/// A list of fractions separated by commas.
pub fn list(text: &str) -> Result<Vec<Rational>, Error> {
    text.split(',').map(rational).collect()
}

/// Four transcribed fractions.
pub fn four(texts: &[&str; 4]) -> Result<[Rational; 4], Error> {
    Ok([
        rational(texts[0])?,
        rational(texts[1])?,
        rational(texts[2])?,
        rational(texts[3])?,
    ])
}

/// Three transcribed corners of a triangle.
pub fn corners(texts: &[[&str; 2]; 3]) -> Result<[[Rational; 2]; 3], Error> {
    let corner =
        |c: &[&str; 2]| -> Result<[Rational; 2], Error> { Ok([rational(c[0])?, rational(c[1])?]) };
    Ok([corner(&texts[0])?, corner(&texts[1])?, corner(&texts[2])?])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_points_and_refuses_nonsense() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        assert_eq!(point("(6, -3/4)"), Ok(vec![q(6, 1), q(-3, 4)]));
        assert!(rational("ln2").is_err());
    }
}
