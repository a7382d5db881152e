//! Carrying a parameter across an overlap: where a curve Q passes through the point P(s) of
//! a stretch that P and Q trace together.
//!
//! On an overlap both curves are one-to-one, so Q passes through P(s) at exactly one t of
//! the overlap's range. With X = P(s) (exact: rational, or the algebraic numbers
//! [`value_at`] gives) and a coordinate a that Q does not keep constant, every such t is a
//! root of h(t) = Res_v(f(v), c v - N(t)), where f is the polynomial of X_a and
//! N / c = Q_a (h is not zero: the second argument is linear in v with a constant leading
//! coefficient). The candidate roots of h inside the range are tested exactly, Q(t) = X in
//! both coordinates ([`AlgebraicReal::equals`]); the one that passes is t.

use super::curve::Curve;
use crate::intersect::algebraic::{over_common_denominator, value_at, AlgebraicReal};
use crate::intersect::bivariate::{resultant_t, swap, BiPoly};
use crate::intersect::upoly;
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::ring::Rational;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// The parameter t strictly between `range.0` and `range.1` (either order) with
/// Q(t) = P(s), where P and Q overlap on a stretch holding P(s) and that range.
pub(crate) fn transfer(
    p: &Curve,
    s: &AlgebraicReal,
    q: &Curve,
    range: (&AlgebraicReal, &AlgebraicReal),
) -> AlgebraicReal {
    let (lo, hi) = if range.0.compare(range.1) == Ordering::Greater {
        (range.1, range.0)
    } else {
        range
    };
    let inside =
        |t: &AlgebraicReal| t.compare(lo) == Ordering::Greater && t.compare(hi) == Ordering::Less;
    if let Some(s0) = s.exact() {
        let x = p.at(s0);
        return q
            .parameters_at(&x)
            .into_iter()
            .find(inside)
            .expect("the overlapping curve passes through the point once on the overlap");
    }
    let x = [value_at(&p.power[0], s), value_at(&p.power[1], s)];
    let a = if q.power[0][1..].iter().any(|c| !c.is_zero()) {
        0
    } else {
        1
    };
    let (numerators, scale) = over_common_denominator(&q.power[a]);
    // A(v, t) = f(v); B(v, t) = c v - N(t); Res_v leaves a polynomial in t.
    let f: BiPoly = x[a].polynomial().iter().map(|c| vec![c.clone()]).collect();
    let mut b: BiPoly = vec![numerators.iter().map(|c| -c).collect(), vec![scale]];
    let width = b[0].len();
    b[1].resize(width, BigInt::zero());
    let h = resultant_t(&swap(&f), &swap(&b));
    let h = upoly::square_free_part(&h);
    roots_with_multiplicity(&h, &Rational::zero(), &Rational::one())
        .into_iter()
        .map(|r| r.value)
        .filter(inside)
        .find(|t| value_at(&q.power[0], t).equals(&x[0]) && value_at(&q.power[1], t).equals(&x[1]))
        .expect("the overlapping curve passes through the point once on the overlap")
}

#[cfg(test)]
mod tests {
    use super::transfer;
    use crate::intersect::algebraic::AlgebraicReal;
    use crate::num::ring::Rational;
    use crate::region::curve::Curve;
    use crate::shape::array::Bezier;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    /// P(s) = (s, s^2) and Q(t) = P(1 - t) run the same parabola both ways; at the
    /// irrational s = 1/sqrt(2) (root of 2 s^2 - 1 in [1/2, 1]), Q passes at t = 1 - s.
    #[test]
    fn an_irrational_parameter_crosses_a_reversed_parabola() {
        let p = Curve::new(
            &Bezier::new(vec![
                [q(0, 1), q(0, 1)],
                [q(1, 2), q(0, 1)],
                [q(1, 1), q(1, 1)],
            ])
            .unwrap(),
        );
        let r = Curve::new(
            &Bezier::new(vec![
                [q(1, 1), q(1, 1)],
                [q(1, 2), q(0, 1)],
                [q(0, 1), q(0, 1)],
            ])
            .unwrap(),
        );
        let roots = crate::intersect::zeros::roots_with_multiplicity(
            &[(-1).into(), 0.into(), 2.into()],
            &q(1, 2),
            &q(1, 1),
        );
        let s = roots[0].value.clone();
        let t = transfer(
            &p,
            &s,
            &r,
            (
                &AlgebraicReal::from_rational(q(0, 1)),
                &AlgebraicReal::from_rational(q(1, 1)),
            ),
        );
        // t = 1 - 1/sqrt(2) = 0.29289...: 1 - t is a root of 2 x^2 - 1.
        assert!((t.to_f64() - (1.0 - std::f64::consts::FRAC_1_SQRT_2)).abs() < 1e-15);
        let back = transfer(
            &r,
            &t,
            &p,
            (
                &AlgebraicReal::from_rational(q(0, 1)),
                &AlgebraicReal::from_rational(q(1, 1)),
            ),
        );
        assert!(back.equals(&s));
        // A rational parameter: s = 1/4, t = 3/4.
        let quarter = AlgebraicReal::from_rational(q(1, 4));
        let t = transfer(
            &p,
            &quarter,
            &r,
            (
                &AlgebraicReal::from_rational(q(0, 1)),
                &AlgebraicReal::from_rational(q(1, 1)),
            ),
        );
        assert_eq!(t.exact(), Some(&q(3, 4)));
    }
}
