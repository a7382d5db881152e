//! Straight quadratics: a quadratic whose control point lies on one of its ends traces the
//! segment between its ends, once, at a varying speed. TrueType outlines write them often
//! (an off-curve point on an on-curve point: 31 of the 39 curves of DejaVu Sans' airplane).
//!
//! With P1 = P0, P(t) = P0 + t² (P2 - P0); with P1 = P2, P(t) = P0 + (2t - t²)(P2 - P0). In
//! both, P(t) = P0 + φ(t)(P2 - P0) with φ increasing from φ(0) = 0 to φ(1) = 1: the curve is
//! its chord under the change of parameter u = φ(t). The contacts of such a curve are those
//! of its chord (found in fixed width, `intersect::line`), each chord parameter u carried to
//! t = φ⁻¹(u): √u, or 1 - √(1 - u) = u / (1 + √(1 - u)). Parameters on one straight curve
//! compare as their u do (φ is increasing), and a stretch shared with a segment or another
//! straight curve maps affinely between the chords' u.
//!
//! Doubles around t come cheaply ([`Straight::enclosure`]): φ⁻¹ is increasing, so t lies
//! between φ⁻¹ of the doubles around u; each is computed in at most four correctly rounded
//! operations (relative error below 5 u, so below 5 ulps) and moved 8 ulps outward. The
//! double nearest to t is certified exactly, on demand ([`Straight::nearest`]): t̂ is
//! correctly rounded when φ of the midpoints between t̂ and its neighbours bracket u
//! (compared in rationals), and stepped by one ulp otherwise; the exact t is the root of
//! den(u) φ(t) - num(u) in [0, 1], an algebraic number of degree at most 2, made on demand.

use crate::intersect::algebraic::{exact_f64, AlgebraicReal};
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::ring::Rational;
use crate::num::small::SmallRational;
use num_bigint::BigInt;
use std::cmp::Ordering;

/// Which end a straight quadratic's control point lies on: the change of parameter
/// u = φ(t) from the curve to its chord.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Straight {
    /// P1 = P0: φ(t) = t².
    Square,
    /// P1 = P2: φ(t) = 2t - t².
    Cap,
}

impl Straight {
    /// The kind of the curve with control points `points`, when it is a straight quadratic
    /// with distinct ends.
    pub(crate) fn of(points: &[[f64; 2]]) -> Option<Straight> {
        let [p0, p1, p2] = points else { return None };
        if p0 == p2 {
            None
        } else if p1 == p0 {
            Some(Straight::Square)
        } else if p1 == p2 {
            Some(Straight::Cap)
        } else {
            None
        }
    }

    /// φ's integer coefficients, ascending.
    fn coefficients(self) -> [i64; 3] {
        match self {
            Straight::Square => [0, 0, 1],
            Straight::Cap => [0, 2, -1],
        }
    }

    /// φ(t), exactly.
    fn phi(self, t: &Rational) -> Rational {
        let [_, c1, c2] = self
            .coefficients()
            .map(|c| Rational::from_integer(c.into()));
        (c1 + c2 * t) * t
    }

    /// A double near φ⁻¹(u) (within a few ulps): √u, or u / (1 + √(1 - u)) without
    /// cancellation.
    fn guess(self, u: f64) -> f64 {
        match self {
            Straight::Square => u.sqrt(),
            Straight::Cap => u / (1.0 + (1.0 - u).sqrt()),
        }
    }

    /// A double near t = φ⁻¹(u) and doubles `[lo, hi]` around t (module doc): exact for the
    /// ends u = 0 and 1, a few ulps wide otherwise.
    pub(crate) fn enclosure(self, u: SmallRational) -> (f64, [f64; 2]) {
        if u == SmallRational::ZERO || u == SmallRational::ONE {
            let t = u.numer() as f64;
            return (t, [t, t]);
        }
        let (near, [u_lo, u_hi]) = u.to_f64_enclosure();
        let step = |mut x: f64, up: bool| {
            for _ in 0..8 {
                x = if up { x.next_up() } else { x.next_down() };
            }
            x
        };
        let lo = step(self.guess(u_lo.max(0.0)), false).max(0.0);
        let hi = step(self.guess(u_hi.min(1.0)), true).min(1.0);
        (self.guess(near).clamp(lo, hi), [lo, hi])
    }

    /// The double nearest to t = φ⁻¹(u) (ties to even) and doubles around it (the double
    /// itself when t is one), for u in [0, 1]; see the module doc.
    pub(crate) fn nearest(self, u: SmallRational) -> (f64, [f64; 2]) {
        let exact_u = u.to_rational();
        let (approx, _) = u.to_f64_enclosure();
        let mut t = self.guess(approx).clamp(0.0, 1.0);
        // φ(x) against u, exactly.
        let side = |x: f64| self.phi(&exact_f64(x)).cmp(&exact_u);
        let midpoint =
            |a: f64, b: f64| (exact_f64(a) + exact_f64(b)) / Rational::from_integer(2.into());
        for _ in 0..64 {
            match side(t) {
                Ordering::Equal => return (t, [t, t]),
                Ordering::Less if t < 1.0 => {
                    let up = t.next_up();
                    match self.phi(&midpoint(t, up)).cmp(&exact_u) {
                        Ordering::Greater => return (t, [t, up]),
                        Ordering::Equal => return (even(t, up), [t, up]),
                        Ordering::Less => t = up,
                    }
                }
                Ordering::Greater if t > 0.0 => {
                    let down = t.next_down();
                    match self.phi(&midpoint(down, t)).cmp(&exact_u) {
                        Ordering::Less => return (t, [down, t]),
                        Ordering::Equal => return (even(down, t), [down, t]),
                        Ordering::Greater => t = down,
                    }
                }
                _ => break,
            }
        }
        // Unreachable for u in [0, 1] (φ is increasing and the guess is close); the exact
        // root answers all the same.
        let x = self.root(u);
        let nearest = x.to_f64();
        (nearest, [nearest.next_down(), nearest.next_up()])
    }

    /// t = φ⁻¹(u) exactly: the root in [0, 1] of den φ(t) - num.
    pub(crate) fn root(self, u: SmallRational) -> AlgebraicReal {
        let [c0, c1, c2] = self.coefficients();
        let (num, den) = (BigInt::from(u.numer()), BigInt::from(u.denom()));
        let poly = vec![
            BigInt::from(c0) * &den - num,
            BigInt::from(c1) * &den,
            BigInt::from(c2) * &den,
        ];
        let (zero, one) = (
            Rational::from_integer(0.into()),
            Rational::from_integer(1.into()),
        );
        roots_with_multiplicity(&poly, &zero, &one)
            .into_iter()
            .next()
            .expect("φ takes every value of [0, 1] once on [0, 1]")
            .value
    }
}

/// Of two adjacent doubles, the one with an even significand.
fn even(a: f64, b: f64) -> f64 {
    if a.to_bits().is_multiple_of(2) {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::Straight;
    use crate::intersect::algebraic::exact_f64;
    use crate::num::small::SmallRational;

    /// The certified nearest double and enclosure against the exact root, on every kind and
    /// many fractions, perfect squares (exact roots) included.
    #[test]
    fn nearest_root_is_correctly_rounded() {
        let mut exact_roots = 0;
        for kind in [Straight::Square, Straight::Cap] {
            for den in 1..40i128 {
                for num in 0..=den {
                    let u = SmallRational::new(num, den).unwrap();
                    let (nearest, [lo, hi]) = kind.nearest(u);
                    let x = kind.root(u);
                    let (near, [a, b]) = kind.enclosure(u);
                    assert!(x.cmp_rational(&exact_f64(a)).is_ge() && a <= near);
                    assert!(x.cmp_rational(&exact_f64(b)).is_le() && near <= b);
                    assert_eq!(nearest, x.to_f64(), "{kind:?} {u:?}");
                    assert!(x.cmp_rational(&exact_f64(lo)).is_ge());
                    assert!(x.cmp_rational(&exact_f64(hi)).is_le());
                    if lo == hi {
                        exact_roots += 1;
                        assert_eq!(x.exact(), Some(&exact_f64(nearest)));
                    }
                }
            }
        }
        assert!(
            exact_roots > 20,
            "0, 1, 1/4, 9/16, ... are exact: {exact_roots}"
        );
    }

    #[test]
    fn kinds() {
        let (a, b) = ([0.0, 0.0], [3.0, 1.0]);
        assert_eq!(Straight::of(&[a, a, b]), Some(Straight::Square));
        assert_eq!(Straight::of(&[a, b, b]), Some(Straight::Cap));
        assert_eq!(Straight::of(&[a, [1.0, 1.0], b]), None);
        assert_eq!(Straight::of(&[a, a, a]), None);
        assert_eq!(Straight::of(&[a, b]), None);
    }
}
