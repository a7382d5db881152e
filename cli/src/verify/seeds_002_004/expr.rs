//! A tiny reader of printed formulas, so that they are transcribed as the papers print them and
//! compared as polynomials ([`Poly`] equality is identity).
//!
//! Grammar: sums and differences of products and quotients of factors; a factor is a number
//! (`3`, `9/2` reads as 9 divided by 2), a variable (`alpha`, `t1`, `ln2`), a parenthesised
//! formula, a power `x^k`, a unary minus, or a sample `b(x)` of the parametrisation, which
//! becomes the variable [`sample_name`] of the argument. Division is by constants only.

use blossom::{Poly, Rational, Ring};
use num_bigint::BigInt;

/// The name of the variable standing for the point b(x) of the parametrisation: `b[x]` with
/// x in the canonical printed form of [`Poly`], so equal arguments give the same variable.
pub fn sample_name(args: &[Poly]) -> String {
    let inner: Vec<String> = args.iter().map(|a| a.to_string()).collect();
    format!("b[{}]", inner.join(", "))
}

/// Reads `text`; panics with the position on a malformed formula (the formulas are constants
/// of this module, so a panic is a bug in the transcription, found by the tests).
pub fn parse(text: &str) -> Poly {
    let mut p = Parser {
        s: text.as_bytes(),
        i: 0,
    };
    let v = p.sum();
    p.skip();
    assert!(
        p.i == p.s.len(),
        "unexpected {:?} at {} in {text:?}",
        &text[p.i..],
        p.i
    );
    v
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
}

impl Parser<'_> {
    fn skip(&mut self) {
        while self.i < self.s.len() && self.s[self.i] == b' ' {
            self.i += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip();
        self.s.get(self.i).copied()
    }

    fn eat(&mut self, c: u8) -> bool {
        if self.peek() == Some(c) {
            self.i += 1;
            true
        } else {
            false
        }
    }

    fn sum(&mut self) -> Poly {
        let mut acc = self.product();
        loop {
            if self.eat(b'+') {
                acc = acc.add(&self.product());
            } else if self.eat(b'-') {
                acc = acc.sub(&self.product());
            } else {
                return acc;
            }
        }
    }

    fn product(&mut self) -> Poly {
        let mut acc = self.power();
        loop {
            if self.eat(b'*') {
                acc = acc.mul(&self.power());
            } else if self.eat(b'/') {
                let d = self.power();
                let k = d.as_constant().expect("division by a constant");
                acc = acc.scale(&(Rational::from_integer(1.into()) / k));
            } else {
                return acc;
            }
        }
    }

    fn power(&mut self) -> Poly {
        if self.eat(b'-') {
            return self.power().neg();
        }
        let base = self.atom();
        if self.eat(b'^') {
            let e = self.integer();
            let e = u32::try_from(e).expect("a small exponent");
            base.pow(e)
        } else {
            base
        }
    }

    fn integer(&mut self) -> BigInt {
        self.skip();
        let start = self.i;
        while self.i < self.s.len() && self.s[self.i].is_ascii_digit() {
            self.i += 1;
        }
        std::str::from_utf8(&self.s[start..self.i])
            .ok()
            .and_then(|d| d.parse().ok())
            .unwrap_or_else(|| panic!("expected a number at {start}"))
    }

    fn atom(&mut self) -> Poly {
        match self.peek() {
            Some(b'(') => {
                self.i += 1;
                let v = self.sum();
                assert!(self.eat(b')'), "expected ) at {}", self.i);
                v
            }
            Some(c) if c.is_ascii_digit() => Poly::constant(Rational::from_integer(self.integer())),
            Some(c) if c.is_ascii_alphabetic() => {
                let start = self.i;
                while self.i < self.s.len()
                    && (self.s[self.i].is_ascii_alphanumeric() || self.s[self.i] == b'_')
                {
                    self.i += 1;
                }
                let name = std::str::from_utf8(&self.s[start..self.i])
                    .expect("ASCII")
                    .to_string();
                if name == "b" && self.eat(b'(') {
                    let mut args = vec![self.sum()];
                    while self.eat(b',') {
                        args.push(self.sum());
                    }
                    assert!(self.eat(b')'), "expected ) at {}", self.i);
                    Poly::var(&sample_name(&args))
                } else {
                    Poly::var(&name)
                }
            }
            other => panic!("unexpected {other:?} at {}", self.i),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_formulas() {
        assert_eq!(
            parse("(alpha + beta)^2"),
            parse("alpha^2 + 2*alpha*beta + beta^2")
        );
        assert_eq!(
            parse("-8/3*b((alpha+beta)/2)"),
            parse("-(8/3)*b(beta/2 + alpha/2)")
        );
        assert_eq!(parse("7/12 - 1").to_string(), "-5/12");
    }
}
