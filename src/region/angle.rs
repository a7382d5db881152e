//! The angular order of the curve branches that leave one vertex, decided exactly.
//!
//! A branch leaves the vertex v = P(τ) along a piece of curve P, toward increasing parameters
//! (σ = +1) or decreasing ones (σ = -1). Its *leading direction* is u = σ^k P^(k)(τ) for the
//! first k with P^(k)(τ) ≠ 0 (P(τ + σh) - v = u h^k / k! + O(h^(k+1))), and the branch's
//! angle at v is the angle of u. The exact signs of u_x and u_y put u in one of eight
//! classes: the four open quadrants and the four axis directions, ordered counter-clockwise
//! from +x.
//!
//! Two branches of one class leave v on the same side of an axis-parallel line through v:
//! say x > v_x (u_x > 0). On each, x(t) is strictly monotone from τ up to the first root ρ of
//! x'(t) past τ on the piece (or the piece's other end). Pieces meet only at their ends, so
//! for every rational X strictly between v_x and the nearer of the two values x(ρ), the arcs
//! cross the line x = X once each, at different heights, and the arc that is higher there
//! is higher all the way down to v: the higher one is the more counter-clockwise. The
//! crossings are roots of x(t) - X between τ and ρ, their heights algebraic numbers compared
//! exactly. Branches going left (u_x < 0) are ordered the other way; branches along ±y use
//! lines y = Y.

use super::curve::{derivative, Curve};
use crate::intersect::algebraic::{shifted_poly, simplest_between, value_at, AlgebraicReal};
use crate::intersect::upoly;
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::ring::Rational;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// A branch leaving a vertex: curve `curve` from parameter `at` toward parameter `toward`
/// (the other end of its piece).
#[derive(Clone, Debug)]
pub(crate) struct Branch {
    pub curve: usize,
    pub at: AlgebraicReal,
    pub toward: AlgebraicReal,
}

impl Branch {
    fn forward(&self) -> bool {
        self.toward.compare(&self.at) == Ordering::Greater
    }
}

/// The exact sign of a rational polynomial at an algebraic number.
fn sign_at(p: &[Rational], t: &AlgebraicReal) -> Ordering {
    let z = upoly::positive_multiple(p);
    if upoly::is_zero(&z) {
        return Ordering::Equal;
    }
    t.clone().sign_of(&z)
}

/// The class (0..8, counter-clockwise from +x) of the branch's leading direction.
pub(crate) fn class(c: &Curve, b: &Branch) -> (u8, [Ordering; 2]) {
    let sigma_negative = !b.forward();
    let mut dx = c.power[0].clone();
    let mut dy = c.power[1].clone();
    for k in 1.. {
        dx = derivative(&dx);
        dy = derivative(&dy);
        let (sx, sy) = (sign_at(&dx, &b.at), sign_at(&dy, &b.at));
        if sx == Ordering::Equal && sy == Ordering::Equal {
            assert!(
                !dx.is_empty() || !dy.is_empty(),
                "a curve that traces more than a point"
            );
            continue;
        }
        let flip = sigma_negative && k % 2 == 1;
        let (sx, sy) = if flip {
            (sx.reverse(), sy.reverse())
        } else {
            (sx, sy)
        };
        use Ordering::{Equal as Z, Greater as P, Less as N};
        let class = match (sx, sy) {
            (P, Z) => 0,
            (P, P) => 1,
            (Z, P) => 2,
            (N, P) => 3,
            (N, Z) => 4,
            (N, N) => 5,
            (Z, N) => 6,
            (P, N) => 7,
            (Z, Z) => unreachable!("handled above"),
        };
        return (class, [sx, sy]);
    }
    unreachable!("the loop returns")
}

/// A rational strictly between the distinct algebraic numbers `a` and `b`.
pub(crate) fn rational_between(a: &AlgebraicReal, b: &AlgebraicReal) -> Rational {
    let (mut lo, mut hi) = if a.compare(b) == Ordering::Less {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    loop {
        let (l, h) = (lo.interval().1.clone(), hi.interval().0.clone());
        if l < h {
            let four = Rational::from_integer(4.into());
            let three = Rational::from_integer(3.into());
            let x = (&three * &l + &h) / &four;
            let y = (&l + &three * &h) / &four;
            return simplest_between(&x, &y);
        }
        lo.refine();
        hi.refine();
    }
}

/// The parameter strictly between `from` and `to` closest to `from` where the polynomial
/// `g` (rational, ascending) vanishes, or `to` when there is none.
fn first_root(g: &[Rational], from: &AlgebraicReal, to: &AlgebraicReal) -> AlgebraicReal {
    let z = upoly::from_rationals(g);
    if upoly::is_zero(&z) || upoly::degree(&z).unwrap_or(0) == 0 {
        return to.clone();
    }
    let forward = to.compare(from) == Ordering::Greater;
    let roots = roots_with_multiplicity(&z, &Rational::zero(), &Rational::one());
    let between = roots.into_iter().map(|r| r.value).filter(|t| {
        if forward {
            t.compare(from) == Ordering::Greater && t.compare(to) == Ordering::Less
        } else {
            t.compare(from) == Ordering::Less && t.compare(to) == Ordering::Greater
        }
    });
    let best = if forward {
        between.min_by(|a, b| a.compare(b))
    } else {
        between.max_by(|a, b| a.compare(b))
    };
    best.unwrap_or_else(|| to.clone())
}

/// The height (coordinate `1 - axis`) where the branch crosses the line coordinate `axis`
/// = `level`, on its monotone stretch from its vertex to `limit`.
fn height_at(
    c: &Curve,
    b: &Branch,
    axis: usize,
    level: &Rational,
    limit: &AlgebraicReal,
) -> AlgebraicReal {
    let f = shifted_poly(&c.power[axis], level);
    let forward = b.forward();
    let t = roots_with_multiplicity(&f, &Rational::zero(), &Rational::one())
        .into_iter()
        .map(|r| r.value)
        .find(|t| {
            if forward {
                t.compare(&b.at) == Ordering::Greater && t.compare(limit) == Ordering::Less
            } else {
                t.compare(&b.at) == Ordering::Less && t.compare(limit) == Ordering::Greater
            }
        })
        .expect("a monotone arc reaching past the line crosses it");
    value_at(&c.power[1 - axis], &t)
}

/// The counter-clockwise order of the leading directions of two branches that leave the
/// same vertex (angles measured from +x in [0, 2π), branches tangent to +x ordered from the
/// lowest up): `Less` when `a` comes first. Distinct pieces never compare equal.
/// `curve_a` and `curve_b` are the curves of the branches.
pub(crate) fn compare(curve_a: &Curve, a: &Branch, curve_b: &Curve, b: &Branch) -> Ordering {
    let (ca, sa) = class(curve_a, a);
    let (cb, _) = class(curve_b, b);
    if ca != cb {
        return ca.cmp(&cb);
    }
    // The axis the branches move along, and the direction.
    let (axis, direction) = if sa[0] != Ordering::Equal {
        (0, sa[0])
    } else {
        (1, sa[1])
    };
    let ca_ = curve_a;
    let g = derivative(&ca_.power[axis]);
    let rho_a = first_root(&g, &a.at, &a.toward);
    let gb = derivative(&curve_b.power[axis]);
    let rho_b = first_root(&gb, &b.at, &b.toward);
    let v = value_at(&ca_.power[axis], &a.at);
    let ea = value_at(&ca_.power[axis], &rho_a);
    let eb = value_at(&curve_b.power[axis], &rho_b);
    let nearer = match (ea.compare(&eb), direction) {
        (Ordering::Less, Ordering::Greater) | (Ordering::Greater, Ordering::Less) => ea,
        _ => eb,
    };
    let level = rational_between(&v, &nearer);
    let ha = height_at(curve_a, a, axis, &level, &rho_a);
    let hb = height_at(curve_b, b, axis, &level, &rho_b);
    let order = ha.compare(&hb);
    // Moving +x: higher is more counter-clockwise. Moving -x: lower is. Moving +y: the one
    // further left (smaller x) is. Moving -y: the one further right is.
    match (axis, direction) {
        (0, Ordering::Greater) | (1, Ordering::Less) => order,
        _ => order.reverse(),
    }
}

#[cfg(test)]
mod tests {
    use super::{compare, Branch};
    use crate::num::ring::Rational;
    use crate::region::curve::{one, zero, Curve};
    use crate::shape::array::Bezier;
    use std::cmp::Ordering;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    fn curve(points: &[(i64, i64, i64)]) -> Curve {
        let pts = points.iter().map(|&(x, y, d)| [q(x, d), q(y, d)]).collect();
        Curve::new(&Bezier::new(pts).unwrap())
    }

    fn from_start(c: usize) -> Branch {
        Branch {
            curve: c,
            at: zero(),
            toward: one(),
        }
    }

    fn from_end(c: usize) -> Branch {
        Branch {
            curve: c,
            at: one(),
            toward: zero(),
        }
    }

    #[test]
    fn tangent_branches_and_a_cusp_are_ordered_exactly() {
        let curves = [
            // 0: y = x^2 from the origin (quadratic (0,0), (1/2,0), (1,1)).
            curve(&[(0, 0, 1), (1, 0, 2), (1, 1, 1)]),
            // 1: y = x^3 from the origin, as a cubic: (0,0), (1/3,0), (2/3,0), (1,1).
            curve(&[(0, 0, 1), (1, 0, 3), (2, 0, 3), (1, 1, 1)]),
            // 2: the x axis from the origin.
            curve(&[(0, 0, 1), (1, 0, 1)]),
            // 3: a cusp (t^2, t^3) at the origin: control points (0,0), (0,0), (1/3,0), (1,1).
            curve(&[(0, 0, 1), (0, 0, 1), (1, 0, 3), (1, 1, 1)]),
            // 4: y = -x^2, leaving the origin along +x below the axis.
            curve(&[(0, 0, 1), (1, 0, 2), (1, -1, 1)]),
            // 5: the y axis, arriving at the origin from (0, 1) (its end is the vertex).
            curve(&[(0, 1, 1), (0, 0, 1)]),
        ];
        let b = [
            from_start(0),
            from_start(1),
            from_start(2),
            from_start(3),
            from_start(4),
            from_end(5),
        ];
        // Counter-clockwise from just below +x: y = -x^2, the axis, y = x^3, y = x^2, the
        // cusp y = x^(3/2) (above x^2 near 0), then +y.
        let ccw =
            |i: usize, j: usize| compare(&curves[b[i].curve], &b[i], &curves[b[j].curve], &b[j]);
        assert_eq!(ccw(4, 2), Ordering::Less);
        assert_eq!(ccw(2, 1), Ordering::Less);
        assert_eq!(ccw(1, 0), Ordering::Less);
        assert_eq!(ccw(1, 3), Ordering::Less, "x^3 below the cusp's x^(3/2)");
        assert_eq!(ccw(0, 3), Ordering::Less, "x^(3/2) above x^2 near 0");
        assert_eq!(ccw(0, 5), Ordering::Less);
        assert_eq!(ccw(5, 4), Ordering::Greater);
        let mut order: Vec<usize> = (0..6).collect();
        order.sort_by(|&i, &j| ccw(i, j));
        assert_eq!(order, vec![4, 2, 1, 0, 3, 5]);
    }
}
