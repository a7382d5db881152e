//! Intersections of two 2-D polynomial Bézier curves P (degree n) and Q (degree m) over
//! [0, 1], and of one curve with itself, exactly: the mathematics, the guarantee and the
//! limits are documented on [`Intersections`], where rustdoc shows them.
//!
//! The operations are methods of the curve types ([`BezierCurve::intersect`](crate::BezierCurve::intersect),
//! [`BezierCurve::self_intersections`](crate::BezierCurve::self_intersections), and the same on [`crate::Bezier`]`<T, 2>`), for `f64`
//! and [`Rational`] alike. The free functions stay where they add something:
//! [`intersect_curves`] and [`self_intersections`] take the control points as slices held
//! anywhere (no curve to build; the `blossom` binary's path), and name their arguments `p`,
//! `q`, `curve` in errors; [`intersect_curves_f64`] and [`self_intersections_f64`] are the
//! same for slices of doubles. One implementation ([`intersect_named`],
//! [`self_intersections_named`]) answers all of them.

use super::algebraic::{
    exact_f64, over_common_denominator, round_polynomial_at, upoly_eval_q, AlgebraicReal,
};
use super::bivariate::BiPoly;
use super::bivariate::{resultant_t, swap};
use super::components::{common_component, retracing};
use super::filter::certified_crossings_f64;
use super::line::{curve_and_segment, segment_and_curve};
use super::solve::{solve, Solution};
use super::upoly::{self, from_rationals, square_free_part};
use super::zeros::roots_with_multiplicity;
use crate::error::{Error, ErrorKind, Result};
use crate::num::exact::exact_coordinates;
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::basis::bernstein_to_power;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};
use std::cmp::Ordering;

pub use super::intersections::{IntersectionPoint, Intersections, Overlap};

/// The power form of a 2-D curve: x and y coefficients, ascending, trailing zeros kept so that
/// both have n + 1 entries.
struct Power {
    x: Vec<Rational>,
    y: Vec<Rational>,
}

impl Power {
    fn of(field: &str, points: &[[Rational; 2]]) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::of(
                ErrorKind::Empty,
                field,
                format!("expected at least 2 control points, found {}", points.len()),
            ));
        }
        let pts: Vec<Vec<Rational>> = points.iter().map(|p| p.to_vec()).collect();
        let c = bernstein_to_power(&pts);
        let x: Vec<Rational> = c.iter().map(|p| p[0].clone()).collect();
        let y: Vec<Rational> = c.iter().map(|p| p[1].clone()).collect();
        Ok(Power { x, y })
    }

    /// The point of a curve that is a single point (every control point the same).
    fn single_point(&self) -> Option<[Rational; 2]> {
        (self.x[1..].iter().all(Zero::is_zero) && self.y[1..].iter().all(Zero::is_zero))
            .then(|| [self.x[0].clone(), self.y[0].clone()])
    }

    fn at(&self, s: &Rational) -> [Rational; 2] {
        [upoly_eval_q(&self.x, s), upoly_eval_q(&self.y, s)]
    }
}

/// f(s) - g(t) scaled by the lcm of the denominators, as an integer bivariate polynomial.
fn separated(f: &[Rational], g: &[Rational]) -> BiPoly {
    let both: Vec<Rational> = f.iter().chain(g).cloned().collect();
    let (numerators, _) = over_common_denominator(&both);
    let (nf, ng) = numerators.split_at(f.len());
    let mut a: BiPoly = vec![vec![BigInt::zero(); g.len().max(1)]; f.len().max(1)];
    for (i, c) in nf.iter().enumerate() {
        a[i][0] += c;
    }
    for (j, c) in ng.iter().enumerate() {
        a[0][j] -= c;
    }
    a
}

/// Every intersection of the planar curves with control points `p` and `q` (exact rationals)
/// over [0, 1], **certified**: isolated points with exact parameters and tangency flag, and
/// overlaps ([`Intersections`] states the guarantee, the method, the limits and the f64
/// sub-curve trap). The method [`BezierCurve::intersect`](crate::BezierCurve::intersect) is
/// the same on a curve; this form takes the control points as slices held anywhere.
///
/// ```
/// use blossom::{intersect_curves, Rational};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // The diagonals of the square [0, 2]^2 cross at (1, 1), halfway along both.
/// let x = intersect_curves(&[[q(0), q(0)], [q(2), q(2)]], &[[q(0), q(2)], [q(2), q(0)]])?;
/// assert_eq!(x.to_string(), "s = 1/2, t = 1/2, point = (1, 1)");
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::Empty`] on `p` or `q` for fewer than two control points; on `curves` only
/// for an internal inconsistency of the common-component case (never expected).
pub fn intersect_curves(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> Result<Intersections> {
    intersect_named(p, q, ["p", "q"])
}

/// [`intersect_curves`] with the names of the two arguments for its errors: the one
/// implementation behind the free functions and the methods of the curve types.
pub(crate) fn intersect_named(
    p: &[[Rational; 2]],
    q: &[[Rational; 2]],
    names: [&str; 2],
) -> Result<Intersections> {
    let pp = Power::of(names[0], p)?;
    let qq = Power::of(names[1], q)?;
    if let Some(answer) = single_point_pair(&pp, &qq) {
        return Ok(answer);
    }
    // A segment: the exact answer without resultants (module `line`).
    if p.len() == 2 {
        if let Some((points, overlaps)) = segment_and_curve(p, q, &qq.x, &qq.y) {
            return Ok(finish(points, overlaps));
        }
    } else if q.len() == 2 {
        if let Some(found) = segment_and_curve(q, p, &pp.x, &pp.y) {
            let (points, overlaps) = curve_and_segment(found);
            return Ok(finish(points, overlaps));
        }
    }
    general(p, q, &pp, &qq)
}

/// The general exact solver of [`intersect_named`] (resultants, overlaps by common
/// components), for any two curves that are not single points.
fn general(
    p: &[[Rational; 2]],
    q: &[[Rational; 2]],
    pp: &Power,
    qq: &Power,
) -> Result<Intersections> {
    let a = separated(&pp.x, &qq.x);
    let b = separated(&pp.y, &qq.y);
    if let Some(points) = filtered(p, q, &a, &b) {
        return Ok(finish(points, Vec::new()));
    }
    let (zero, one) = (Rational::zero(), Rational::one());
    match solve(&a, &b, (&zero, &one), (&zero, &one)) {
        Some(solutions) => {
            let points = solutions
                .into_iter()
                .map(|s| point_of(pp, Some(qq), s))
                .collect();
            Ok(finish(points, Vec::new()))
        }
        None => overlap_case(pp, qq),
    }
}

/// The answer through the float filter, when every coordinate is a double and the filter
/// proves the complete answer ([`certified_crossings_f64`]: only transversal crossings, all
/// inside (0, 1)^2). Each parameter is then made an exact [`AlgebraicReal`]: the square-free
/// part of the resultant Res_t(A, B) (for s) or Res_s(A, B) (for t) with the filter's
/// enclosure as isolating interval, proved by [`AlgebraicReal::from_double_enclosure`].
/// No crossing needs no resultant at all. `None` sends the pair to the exact solver.
fn filtered(
    p: &[[Rational; 2]],
    q: &[[Rational; 2]],
    a: &BiPoly,
    b: &BiPoly,
) -> Option<Vec<IntersectionPoint>> {
    let crossings = certified_crossings_f64(&as_doubles(p)?, &as_doubles(q)?)?;
    if crossings.is_empty() {
        return Some(Vec::new());
    }
    let parameter_polynomial = |a: &BiPoly, b: &BiPoly| {
        let r = resultant_t(a, b);
        (!upoly::is_zero(&r)).then(|| square_free_part(&r))
    };
    let fs = parameter_polynomial(a, b)?;
    let ft = parameter_polynomial(&swap(a), &swap(b))?;
    crossings
        .iter()
        .map(|c| {
            Some(IntersectionPoint {
                s: AlgebraicReal::from_double_enclosure(&fs, c.s_enclosure[0], c.s_enclosure[1])?,
                t: AlgebraicReal::from_double_enclosure(&ft, c.t_enclosure[0], c.t_enclosure[1])?,
                tangent: false,
                point: c.point,
            })
        })
        .collect()
}

/// The points as doubles when every coordinate is exactly a double.
pub(crate) fn as_doubles(points: &[[Rational; 2]]) -> Option<Vec<[f64; 2]>> {
    points
        .iter()
        .map(|xy| {
            let d = xy.clone().map(|c| rational_to_f64(&c));
            (d.iter()
                .zip(xy)
                .all(|(x, c)| x.is_finite() && &exact_f64(*x) == c))
            .then_some(d)
        })
        .collect()
}

/// [`intersect_curves`] of control points given as doubles, each read exactly (the exact
/// answer for those doubles, **certified**). The same as
/// [`Bezier::intersect`](crate::Bezier::intersect) on `Bezier<f64, 2>`; for doubles out,
/// [`intersect_curves_f64_rounded`](crate::intersect_curves_f64_rounded) is faster.
///
/// ```
/// use blossom::intersect_curves_f64;
/// let x = intersect_curves_f64(&[[0.0, 0.0], [1.0, 1.0]], &[[0.0, 1.0], [1.0, 0.0]])?;
/// assert_eq!(x.points[0].s.to_f64(), 0.5);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `p[i][j]` / `q[i][j]` for a NaN or infinity, else as
/// [`intersect_curves`].
pub fn intersect_curves_f64(p: &[[f64; 2]], q: &[[f64; 2]]) -> Result<Intersections> {
    intersect_curves(&exact_points("p", p)?, &exact_points("q", q)?)
}

/// Points of doubles read exactly, a coordinate that is not finite refused as `field[i][j]`.
fn exact_points(field: &str, p: &[[f64; 2]]) -> Result<Vec<[Rational; 2]>> {
    Ok(pairs(&exact_coordinates(field, p.as_flattened(), 2)?))
}

/// Flat coordinates (two per point) as points.
pub(crate) fn pairs(coordinates: &[Rational]) -> Vec<[Rational; 2]> {
    coordinates
        .chunks_exact(2)
        .map(|xy| [xy[0].clone(), xy[1].clone()])
        .collect()
}

/// The reported point of a solution (P(s), rounded correctly).
fn point_of(pp: &Power, qq: Option<&Power>, sol: Solution) -> IntersectionPoint {
    let point = if let Some(s0) = sol.s.exact() {
        pp.at(s0).map(|c| rational_to_f64(&c))
    } else if let (Some(t0), Some(qq)) = (sol.t.exact(), qq) {
        qq.at(t0).map(|c| rational_to_f64(&c))
    } else if let (Some(t0), None) = (sol.t.exact(), qq) {
        pp.at(t0).map(|c| rational_to_f64(&c))
    } else {
        [
            round_polynomial_at(&pp.x, &sol.s),
            round_polynomial_at(&pp.y, &sol.s),
        ]
    };
    IntersectionPoint {
        s: sol.s,
        t: sol.t,
        tangent: sol.singular,
        point,
    }
}

/// Sorts, and drops points that lie on an overlap's ranges.
fn finish(mut points: Vec<IntersectionPoint>, mut overlaps: Vec<Overlap>) -> Intersections {
    let within = |x: &AlgebraicReal, a: &AlgebraicReal, b: &AlgebraicReal| {
        let (lo, hi) = if a.compare(b) == Ordering::Greater {
            (b, a)
        } else {
            (a, b)
        };
        x.compare(lo) != Ordering::Less && x.compare(hi) != Ordering::Greater
    };
    points.retain(|pt| {
        !overlaps
            .iter()
            .any(|o| within(&pt.s, &o.s[0], &o.s[1]) || within(&pt.t, &o.t[0], &o.t[1]))
    });
    points.sort_by(|a, b| a.s.compare(&b.s).then_with(|| a.t.compare(&b.t)));
    overlaps.sort_by(|a, b| {
        a.s[0]
            .compare(&b.s[0])
            .then_with(|| a.t[0].compare(&b.t[0]))
    });
    Intersections { points, overlaps }
}

/// The answer when P or Q is a single point (every control point the same), as
/// [`Intersections`] states it (overlaps pairing all of [0, 1] with each parameter where the
/// other curve passes through the point), else `None`.
fn single_point_pair(pp: &Power, qq: &Power) -> Option<Intersections> {
    let whole = || {
        [
            AlgebraicReal::from_rational(Rational::zero()),
            AlgebraicReal::from_rational(Rational::one()),
        ]
    };
    let twice = |x: AlgebraicReal| [x.clone(), x];
    let overlaps = match (pp.single_point(), qq.single_point()) {
        (None, None) => return None,
        (Some(c), Some(d)) if c == d => vec![Overlap {
            s: whole(),
            t: whole(),
        }],
        (Some(_), Some(_)) => Vec::new(),
        (Some(c), None) => through_point(qq, &c)
            .into_iter()
            .map(|t| Overlap {
                s: whole(),
                t: twice(t),
            })
            .collect(),
        (None, Some(d)) => through_point(pp, &d)
            .into_iter()
            .map(|s| Overlap {
                s: twice(s),
                t: whole(),
            })
            .collect(),
    };
    Some(finish(Vec::new(), overlaps))
}

/// The parameters in [0, 1] where the curve (not a single point) passes through c: the
/// roots of gcd(x(t) - c_x, y(t) - c_y).
fn through_point(curve: &Power, c: &[Rational; 2]) -> Vec<AlgebraicReal> {
    let minus = |p: &[Rational], c: &Rational| {
        let mut p = p.to_vec();
        p[0] -= c;
        from_rationals(&p)
    };
    let g = upoly::gcd(&minus(&curve.x, &c[0]), &minus(&curve.y, &c[1]));
    roots_with_multiplicity(&g, &Rational::zero(), &Rational::one())
        .into_iter()
        .map(|r| r.value)
        .collect()
}

/// The curves share a component: the answer of [`common_component`], with the points.
fn overlap_case(pp: &Power, qq: &Power) -> Result<Intersections> {
    let (sols, overlaps) = common_component((&pp.x, &pp.y), (&qq.x, &qq.y))?;
    let points = sols
        .into_iter()
        .map(|s| point_of(pp, Some(qq), s))
        .collect();
    Ok(finish(points, overlaps))
}

/// The bivariate polynomial (f(s) - f(t)) / (s - t) scaled to integers.
fn divided_difference(f: &[Rational]) -> BiPoly {
    let l = f.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    let n = f.len().saturating_sub(1).max(1);
    let mut a: BiPoly = vec![vec![BigInt::zero(); n]; n];
    for (k, c) in f.iter().enumerate().skip(1) {
        let ck = c.numer() * (&l / c.denom());
        for i in 0..k {
            a[i][k - 1 - i] += &ck;
        }
    }
    a
}

/// The solutions of D(s, t) = 0 (divided differences of P) in the box.
fn divided_difference_solutions(
    pp: &Power,
    s_box: (&Rational, &Rational),
    t_box: (&Rational, &Rational),
) -> Option<Vec<Solution>> {
    let a = divided_difference(&pp.x);
    let b = divided_difference(&pp.y);
    solve(&a, &b, s_box, t_box)
}

/// Every pair s < t in [0, 1] with P(s) = P(t) of the planar curve with control points `p`,
/// and the overlaps of a curve that retraces itself, **certified** ([`Intersections`] states
/// the guarantee, the method and the limits). The method
/// [`BezierCurve::self_intersections`](crate::BezierCurve::self_intersections) is the same on
/// a curve; this form takes the control points as a slice held anywhere.
///
/// ```
/// use blossom::{self_intersections, Rational};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // A closed curve meets itself at its ends: (s, t) = (0, 1).
/// let closed = [[q(0), q(0)], [q(4), q(4)], [q(-4), q(4)], [q(0), q(0)]];
/// let x = self_intersections(&closed)?;
/// assert_eq!(x.points[0].s.to_string(), "0");
/// assert_eq!(x.points[0].t.to_string(), "1");
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::Empty`] on `curve` for fewer than two control points; on `curves` only for
/// an internal inconsistency of the retracing case (never expected).
pub fn self_intersections(p: &[[Rational; 2]]) -> Result<Intersections> {
    self_intersections_named(p, "curve")
}

/// [`self_intersections`] with the name of the argument for its errors.
pub(crate) fn self_intersections_named(p: &[[Rational; 2]], name: &str) -> Result<Intersections> {
    let pp = Power::of(name, p)?;
    let (zero, one) = (Rational::zero(), Rational::one());
    if pp.single_point().is_some() {
        // The whole curve as one retracing overlap in the spec's form (t0 > t1, s1 <= t1):
        // [0, 1/2] and [1, 1/2] trace the same set, the point.
        let half = Rational::new(1.into(), 2.into());
        return Ok(finish(
            Vec::new(),
            vec![Overlap {
                s: [
                    AlgebraicReal::from_rational(zero),
                    AlgebraicReal::from_rational(half.clone()),
                ],
                t: [
                    AlgebraicReal::from_rational(one),
                    AlgebraicReal::from_rational(half),
                ],
            }],
        ));
    }
    let sols = divided_difference_solutions(&pp, (&zero, &one), (&zero, &one));
    let Some(sols) = sols else {
        let (sols, overlaps) = retracing(&pp.x, &pp.y)?;
        let points = sols
            .into_iter()
            .map(|sol| point_of(&pp, None, sol))
            .collect();
        return Ok(finish(points, overlaps));
    };
    let points = sols
        .into_iter()
        .filter(|sol| sol.s.compare(&sol.t) == Ordering::Less)
        .map(|sol| point_of(&pp, None, sol))
        .collect();
    Ok(finish(points, Vec::new()))
}

/// [`self_intersections`] of control points given as doubles, each read exactly (the exact
/// answer for those doubles, **certified**). The same as
/// [`Bezier::self_intersections`](crate::Bezier::self_intersections) on `Bezier<f64, 2>`.
///
/// ```
/// use blossom::self_intersections_f64;
/// let line = self_intersections_f64(&[[0.0, 0.0], [1.0, 1.0]])?;
/// assert!(line.points.is_empty() && line.overlaps.is_empty());
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `curve[i][j]`, else as [`self_intersections`].
pub fn self_intersections_f64(p: &[[f64; 2]]) -> Result<Intersections> {
    self_intersections(&exact_points("curve", p)?)
}

/// The general solver alone on two curves (no segment shortcut), for the tests of the
/// shortcut against it.
#[cfg(test)]
pub(crate) fn intersect_general(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> Result<Intersections> {
    let (pp, qq) = (Power::of("p", p)?, Power::of("q", q)?);
    general(p, q, &pp, &qq)
}
