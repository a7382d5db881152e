//! Straight quadratics: a quadratic whose control points lie on one line, the middle one on
//! the segment between the ends, traces that segment once, at a varying speed. TrueType
//! outlines write them often (an off-curve point on an on-curve point: 31 of the 39 curves
//! of DejaVu Sans' airplane; or between two on-curve points of a straight stretch).
//!
//! With P1 = P0 + m (P2 - P0), 0 <= m <= 1, P(t) = P0 + φ(t)(P2 - P0) with
//! φ(t) = 2m t + (1 - 2m) t², increasing from φ(0) = 0 to φ(1) = 1 (φ'(t) = 2m (1 - t) +
//! 2 (1 - m) t > 0 inside): the curve is its chord under the change of parameter u = φ(t).
//! m is exact: 0 (P1 = P0, φ = t²), 1 (P1 = P2, φ = 2t - t²), or for control points that are
//! integers on one dyadic scale the rational dot(P1 - P0, P2 - P0) / |P2 - P0|² once their
//! cross product is exactly zero. The contacts of such a curve are those of its chord (found
//! in fixed width, `intersect::line`), each chord parameter u carried to t = φ⁻¹(u), the root
//! in [0, 1] of (1 - 2m) t² + 2m t - u, that is u / (m + √(m² + (1 - 2m) u)) (no
//! cancellation: m² + (1 - 2m) u = (m - u)² + u (1 - u) >= 0). Parameters on one straight
//! curve compare as their u do (φ is increasing), and a stretch shared with a segment or
//! another straight curve maps affinely between the chords' u.
//!
//! Doubles around t come cheaply ([`Straight::enclosure`]): φ⁻¹ is increasing, so t lies
//! between φ⁻¹ of the doubles around u; a guess of each is moved 8 ulps outward and
//! *checked*: φ(lo) < u < φ(hi), evaluated in [`BoundedF64`] (rigorous error bounds; m and u
//! enter as their nearest doubles with the distance to the exact value as the bound), proves
//! lo < t < hi. A bracket the check does not prove is widened (up to 2^20 ulps) and, failing
//! that, comes from the exact root. The double nearest to t is certified exactly, on demand
//! ([`Straight::nearest`]): t̂ is correctly rounded when φ of the midpoints between t̂ and its
//! neighbours bracket u (compared in rationals), and stepped by one ulp otherwise; the exact
//! t is the root of den(u) b φ(t) - num(u) b in [0, 1] (m = a / b), an algebraic number of
//! degree at most 2, made on demand.

use crate::intersect::algebraic::{exact_f64, AlgebraicReal};
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::bounded::BoundedF64;
use crate::num::ring::{Rational, Ring};
use crate::num::small::{Dyadic, SmallRational};
use num_bigint::BigInt;
use std::cmp::Ordering;

/// A straight quadratic's change of parameter u = φ(t) = 2m t + (1 - 2m) t² from the curve to
/// its chord, given by m, the place of the control point on the chord (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Straight {
    /// In [0, 1].
    m: SmallRational,
}

impl Straight {
    /// P1 = P0: φ(t) = t².
    #[cfg(test)]
    pub(crate) const SQUARE: Straight = Straight {
        m: SmallRational::ZERO,
    };
    /// P1 = P2: φ(t) = 2t - t².
    #[cfg(test)]
    pub(crate) const CAP: Straight = Straight {
        m: SmallRational::ONE,
    };

    /// The change of parameter of the curve with control points `points`, when it is a
    /// straight quadratic with distinct ends (module doc).
    pub(crate) fn of(points: &[[f64; 2]]) -> Option<Straight> {
        let [p0, p1, p2] = points else { return None };
        if p0 == p2 {
            return None;
        }
        if p1 == p0 {
            return Some(Straight {
                m: SmallRational::ZERO,
            });
        }
        if p1 == p2 {
            return Some(Straight {
                m: SmallRational::ONE,
            });
        }
        // The control point strictly inside the chord, decided in integers.
        let dyadic = Dyadic::of(points)?;
        let q = dyadic.points();
        let minus = |a: [i64; 2], b: [i64; 2]| {
            [
                i128::from(a[0]) - i128::from(b[0]),
                i128::from(a[1]) - i128::from(b[1]),
            ]
        };
        let (e, f) = (minus(q[2], q[0]), minus(q[1], q[0]));
        if e[0].checked_mul(f[1])? != e[1].checked_mul(f[0])? {
            return None;
        }
        let dot = e[0]
            .checked_mul(f[0])?
            .checked_add(e[1].checked_mul(f[1])?)?;
        let norm = e[0]
            .checked_mul(e[0])?
            .checked_add(e[1].checked_mul(e[1])?)?;
        (0 < dot && dot < norm)
            .then(|| SmallRational::new(dot, norm))
            .flatten()
            .map(|m| Straight { m })
    }

    /// m = a / b as (a, b), b > 0.
    fn ratio(self) -> (i64, i64) {
        (self.m.numer(), self.m.denom())
    }

    /// φ(t), exactly.
    fn phi(self, t: &Rational) -> Rational {
        let m = self.m.to_rational();
        let two = Rational::from_integer(2.into());
        let one = Rational::from_integer(1.into());
        (&two * &m + (one - two * &m) * t) * t
    }

    /// A double near φ⁻¹(u) for u in [0, 1] (not certified): √u for m = 0, u / (1 + √(1 - u))
    /// for m = 1, else u / (m + √((m - u)² + u (1 - u))), with m - u taken as
    /// (1 - u) - (1 - m) above 1/2 (less cancellation near 1).
    fn guess(self, u: f64) -> f64 {
        if u <= 0.0 {
            return 0.0;
        }
        if self.m == SmallRational::ZERO {
            return u.sqrt();
        }
        if self.m == SmallRational::ONE {
            return u / (1.0 + (1.0 - u).sqrt());
        }
        let (a, b) = self.ratio();
        let m = self.m.to_f64_enclosure().0;
        let gap = if u <= 0.5 {
            m - u
        } else {
            (1.0 - u) - (b - a) as f64 / b as f64
        };
        (u / (m + (gap * gap + u * (1.0 - u)).sqrt())).clamp(0.0, 1.0)
    }

    /// Whether φ(x) - u is proved to have the sign `side` (-1 or 1), in [`BoundedF64`] with
    /// m and u as their nearest doubles bounded by their distance to the exact values.
    fn proved(self, x: f64, u: SmallRational, side: i64) -> bool {
        let bounded = |q: SmallRational| {
            let (near, [lo, hi]) = q.to_f64_enclosure();
            BoundedF64::with_bound(near, (hi - lo).next_up())
        };
        let (m, u) = (bounded(self.m), bounded(u));
        let x = BoundedF64::exact(x);
        let one = BoundedF64::exact(1.0);
        let two_m = m.add(&m);
        let v = x.mul(&two_m.add(&one.sub(&two_m).mul(&x))).sub(&u);
        let (value, bound) = (v.value(), v.error_bound());
        if side < 0 {
            value + bound < 0.0
        } else {
            value - bound > 0.0
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
        let step = |mut x: f64, up: bool, n: u32| {
            for _ in 0..n {
                x = if up { x.next_up() } else { x.next_down() };
            }
            x
        };
        let mut found = None;
        for n in [8, 32, 128, 1 << 10, 1 << 20] {
            let widen = |x: f64, up: bool| {
                if n <= 128 {
                    step(x, up, n)
                } else {
                    // n ulps of x at once (a power of two times the ulp).
                    let ulp = (x.next_up() - x).max(f64::MIN_POSITIVE);
                    if up {
                        x + ulp * n as f64
                    } else {
                        x - ulp * n as f64
                    }
                }
            };
            let lo = widen(self.guess(u_lo.max(0.0)), false).max(0.0);
            let hi = widen(self.guess(u_hi.min(1.0)), true).min(1.0);
            let lo_ok = lo == 0.0 || self.proved(lo, u, -1);
            let hi_ok = hi == 1.0 || self.proved(hi, u, 1);
            if lo_ok && hi_ok {
                found = Some([lo, hi]);
                break;
            }
        }
        let [lo, hi] = found.unwrap_or_else(|| {
            // The exact root's neighbours.
            let t = self.root(u).to_f64();
            [t.next_down().max(0.0), t.next_up().min(1.0)]
        });
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
        // Reached only when the guess is far (φ is increasing on [0, 1]); the exact root
        // answers all the same.
        let x = self.root(u);
        let nearest = x.to_f64();
        (nearest, [nearest.next_down(), nearest.next_up()])
    }

    /// t = φ⁻¹(u) exactly: the root in [0, 1] of den b φ(t) - num b (u = num / den,
    /// m = a / b), that is of den (b - 2a) t² + 2 den a t - num b.
    pub(crate) fn root(self, u: SmallRational) -> AlgebraicReal {
        let (a, b) = self.ratio();
        let (a, b) = (BigInt::from(a), BigInt::from(b));
        let (num, den) = (BigInt::from(u.numer()), BigInt::from(u.denom()));
        let poly = vec![
            -(&num * &b),
            BigInt::from(2) * &a * &den,
            (&b - BigInt::from(2) * &a) * &den,
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

    /// The certified nearest double and enclosure against the exact root, on both end kinds
    /// and on control points inside the chord (m = 1/2, where φ(t) = t, and others), for many
    /// fractions, perfect squares (exact roots) included.
    #[test]
    fn nearest_root_is_correctly_rounded() {
        let (mut exact_roots, mut narrow, mut total) = (0, 0, 0);
        let inner =
            |a: f64, b: f64| Straight::of(&[[0.0, 0.0], [a, 2.0 * a], [b, 2.0 * b]]).unwrap();
        let kinds = [
            Straight::SQUARE,
            Straight::CAP,
            inner(1.0, 2.0),
            inner(1.0, 3.0),
            inner(79.0, 202.0),
            inner(135.0, 271.0),
            inner(52.0, 61.0),
            inner(1.0, 1000.0),
            inner(999.0, 1000.0),
        ];
        for kind in kinds {
            for den in 1..40i128 {
                for num in 0..=den {
                    let u = SmallRational::new(num, den).unwrap();
                    let (nearest, [lo, hi]) = kind.nearest(u);
                    let x = kind.root(u);
                    let (near, [a, b]) = kind.enclosure(u);
                    assert!(
                        x.cmp_rational(&exact_f64(a)).is_ge() && a <= near,
                        "{kind:?} {u:?}"
                    );
                    assert!(
                        x.cmp_rational(&exact_f64(b)).is_le() && near <= b,
                        "{kind:?} {u:?}"
                    );
                    // A few ulps, at most 2^-40 (the check widens a bracket it cannot prove).
                    assert!(
                        b - a <= 1.0 / (1u64 << 40) as f64,
                        "{kind:?} {u:?}: [{a}, {b}]"
                    );
                    narrow += usize::from(b - a <= 32.0 * f64::EPSILON);
                    total += 1;
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
        assert!(
            narrow * 10 > total * 9,
            "{narrow} of {total} within 32 ulps of 1"
        );
    }

    #[test]
    fn kinds() {
        let (a, b) = ([0.0, 0.0], [3.0, 1.0]);
        assert_eq!(Straight::of(&[a, a, b]), Some(Straight::SQUARE));
        assert_eq!(Straight::of(&[a, b, b]), Some(Straight::CAP));
        assert_eq!(Straight::of(&[a, [1.0, 1.0], b]), None);
        assert_eq!(Straight::of(&[a, a, a]), None);
        assert_eq!(Straight::of(&[a, b]), None);
        // On the chord: m = 1/3 and m = 1/2; beyond the ends or off the line: not straight.
        let third = Straight::of(&[a, [1.0, 1.0 / 3.0], b]);
        assert!(third.is_none(), "the double nearest to 1/3 is off the line");
        let (c, d) = ([0.0, 0.0], [6.0, 3.0]);
        assert_eq!(
            Straight::of(&[c, [2.0, 1.0], d]).map(|s| s.m),
            SmallRational::new(1, 3)
        );
        assert_eq!(
            Straight::of(&[c, [3.0, 1.5], d]).map(|s| s.m),
            SmallRational::new(1, 2)
        );
        assert_eq!(Straight::of(&[c, [8.0, 4.0], d]), None);
        assert_eq!(Straight::of(&[c, [-2.0, -1.0], d]), None);
        assert_eq!(Straight::of(&[c, [2.0, 1.5], d]), None);
    }
}
