//! The area of a result, enclosed rigorously.
//!
//! By Green's theorem the area enclosed by a loop traversed counter-clockwise is the sum over
//! its edges of the integral of x dy; on an edge that is curve P = (x, y) from parameter a to
//! b, that integral is F(b) - F(a) with F the antiderivative of x(t) y'(t), a polynomial with
//! rational coefficients. At a rational parameter F is exact; at an algebraic one it is
//! enclosed by interval Horner over the isolating interval ([`enclose`]), which shrinks as
//! the interval is refined. The sum of the enclosures is refined, widest term first, until
//! its width meets the caller's bound. A loop's sign (counter-clockwise or clockwise) is
//! decided the same way: a simple loop bounds a positive area, so refinement until the
//! enclosure excludes zero terminates.

use super::arrangement::Arrangement;
use super::chain::Run;
use crate::intersect::algebraic::{enclose, AlgebraicReal};
use crate::num::ring::Rational;
use num_traits::Zero;

/// One term ± F(τ) of a sum.
pub(crate) struct Term<'a> {
    sign: bool,
    f: &'a [Rational],
    at: AlgebraicReal,
    enclosure: (Rational, Rational),
}

impl Term<'_> {
    fn enclose(&mut self) {
        let (l, h) = self.at.interval();
        let (lo, hi) = enclose(self.f, l, h);
        self.enclosure = if self.sign { (lo, hi) } else { (-hi, -lo) };
    }

    fn width(&self) -> Rational {
        &self.enclosure.1 - &self.enclosure.0
    }
}

/// The terms ± F(τ) of the integrals of x dy over the runs of one loop.
pub(crate) fn loop_terms<'a>(arr: &'a Arrangement, runs: &[Run]) -> Vec<Term<'a>> {
    let mut terms = Vec::new();
    for r in runs {
        for (sign, k) in [(true, r.to), (false, r.from)] {
            if arr.params[r.curve][k].exact().is_some_and(Zero::is_zero) {
                continue; // F(0) = 0.
            }
            let mut t = Term {
                sign,
                f: arr.curves[r.curve].x_dy(),
                at: arr.params[r.curve][k].clone(),
                enclosure: (Rational::zero(), Rational::zero()),
            };
            t.enclose();
            terms.push(t);
        }
    }
    terms
}

/// Refines the terms, widest first, until `done(lo, hi)` holds for their sum; returns it.
pub(crate) fn refine_sum(
    terms: &mut [Term],
    done: impl Fn(&Rational, &Rational) -> bool,
) -> (Rational, Rational) {
    loop {
        let lo: Rational = terms.iter().map(|t| &t.enclosure.0).sum();
        let hi: Rational = terms.iter().map(|t| &t.enclosure.1).sum();
        if done(&lo, &hi) {
            return (lo, hi);
        }
        let width = &hi - &lo;
        let share = width / Rational::from_integer(((2 * terms.len()) as i64).into());
        for t in terms.iter_mut() {
            if t.at.exact().is_none() && t.width() >= share {
                t.at.refine();
                t.enclose();
            }
        }
    }
}
