//! Intersections of two 2-D polynomial Bézier curves P (degree n) and Q (degree m) over
//! [0, 1], and of one curve with itself, exactly.
//!
//! **Isolated points.** With the power forms of the control points (the library's
//! [`bernstein_to_power`]), the common denominators of each coordinate cleared,
//! A(s, t) = P_x(s) - Q_x(t) and B(s, t) = P_y(s) - Q_y(t) are integer polynomials with
//! constant leading coefficients in s and in t, and their common zeros in [0, 1]^2 are the
//! intersections. `solve` finds them through the resultants Res_t and Res_s and first
//! subresultants; a pair is tangential exactly when its intersection multiplicity exceeds one,
//! i.e. when the Jacobian det d(A, B)/d(s, t) = -cross(P'(s), Q'(t)) vanishes (a zero
//! derivative included). The common point is P(s) exactly (rounded) when s or t is rational,
//! else each coordinate P_x(s), P_y(s) is rounded correctly by refining s until the interval
//! value of the coordinate has one rounding (a rounding boundary in it is decided by the exact
//! sign of P_x - m at s).
//!
//! **Overlaps.** Res_t(A, B) vanishes identically exactly when A and B share a factor, i.e.
//! the curves share a component. Two cases are decided exactly:
//! * both curves on one line (all control points collinear): with p(s), q(t) the positions
//!   along the line, each curve is cut at its turning points (roots of p' of odd multiplicity
//!   in (0, 1)) into monotone pieces; every pair of pieces whose images share a segment of
//!   positive length gives one overlap, whose ends are the parameters of the common image's
//!   ends (roots of p(s) - c in the piece); pieces whose images only touch give a point;
//! * otherwise, curves of the same degree d related by an affine change of parameter
//!   s = alpha t + beta with rational alpha, beta (alpha^d = the ratio of the leading
//!   coefficients, beta from the next coefficient), verified by the exact identity
//!   P(alpha t + beta) = Q(t) of power coefficients: the overlap is the part of [0, 1] whose
//!   image under the map lies in [0, 1]; the crossings of P with itself between the two
//!   stretches are found by the divided differences (see [`self_intersections`]).
//!
//! Anything else with a common component (different degrees such as Q(t) = P(t^2), turning
//! points of collinear curves at irrational parameters) is refused with an error saying so.
//! In the affine case each curve is assumed not to retrace itself (a proper
//! parametrisation).
//!
//! **Self-intersection.** D(s, t) = (P(s) - P(t)) / (s - t) (exact division: the divided
//! differences of the power coefficients, sum_k p_k sum_(i + j = k - 1) s^i t^j) vanishes off
//! the diagonal exactly where P(s) = P(t); pairs s < t are kept (s = t only at cusps).
//! A closed curve gives (0, 1). The Jacobian of D at a solution is -cross(P'(s), P'(t)) /
//! (s - t)^2, so the tangency rule is the same. A curve that retraces itself (collinear case
//! only) gives overlaps with t0 > t1, s1 <= t1.

use super::algebraic::{exact_f64, round_polynomial_at, upoly_eval_q, AlgebraicReal};
use super::bivariate::BiPoly;
use super::bivariate::{resultant_t, swap};
use super::filter::certified_crossings_f64;
use super::solve::{solve, Solution};
use super::upoly::{self, derivative, from_rationals, square_free_part};
use super::zeros::{rationals_of, roots_with_multiplicity};
use crate::error::{Error, ErrorKind, Result};
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::basis::{bernstein_to_power, scale_argument, taylor_shift};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// One isolated intersection P(s) = Q(t).
#[derive(Clone, Debug)]
pub struct IntersectionPoint {
    /// The parameter on the first curve.
    pub s: AlgebraicReal,
    /// The parameter on the second curve.
    pub t: AlgebraicReal,
    /// Whether P'(s) and Q'(t) are parallel (cross product exactly zero).
    pub tangent: bool,
    /// The common point, each coordinate correctly rounded.
    pub point: [f64; 2],
}

/// One maximal common stretch: P over `[s[0], s[1]]` (`s[0] < s[1]`) traces what Q traces
/// between `t[0]` and `t[1]`, with `P(s[0]) = Q(t[0])` and `P(s[1]) = Q(t[1])`.
#[derive(Clone, Debug)]
pub struct Overlap {
    /// The ends on the first curve, increasing.
    pub s: [AlgebraicReal; 2],
    /// The matching ends on the second curve (decreasing when the curves run opposite ways).
    pub t: [AlgebraicReal; 2],
}

/// Every intersection of two curves (or of a curve with itself).
#[derive(Clone, Debug, Default)]
pub struct Intersections {
    /// Isolated points, sorted by s then t.
    pub points: Vec<IntersectionPoint>,
    /// Overlaps, sorted by their first s.
    pub overlaps: Vec<Overlap>,
}

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
        if x[1..].iter().all(Zero::is_zero) && y[1..].iter().all(Zero::is_zero) {
            return Err(Error::new(
                field,
                "the curve is a single point (every control point the same)",
            ));
        }
        Ok(Power { x, y })
    }

    fn at(&self, s: &Rational) -> [Rational; 2] {
        [upoly_eval_q(&self.x, s), upoly_eval_q(&self.y, s)]
    }
}

/// The lcm of the denominators of the coefficients of two polynomials.
fn common_denominator(a: &[Rational], b: &[Rational]) -> BigInt {
    a.iter()
        .chain(b)
        .fold(BigInt::one(), |l, c| l.lcm(c.denom()))
}

/// f(s) - g(t) scaled by the lcm of the denominators, as an integer bivariate polynomial.
fn separated(f: &[Rational], g: &[Rational]) -> BiPoly {
    let l = common_denominator(f, g);
    let int = |c: &Rational| c.numer() * (&l / c.denom());
    let mut a: BiPoly = vec![vec![BigInt::zero(); g.len().max(1)]; f.len().max(1)];
    for (i, c) in f.iter().enumerate() {
        a[i][0] += int(c);
    }
    for (j, c) in g.iter().enumerate() {
        a[0][j] -= int(c);
    }
    a
}

/// Every intersection of the curves with control points `p` and `q` (exact rationals): see
/// the module docs for the method and its limits.
///
/// # Errors
/// [`ErrorKind::Empty`] on `p` or `q` for fewer than two control points; on `p` or `q` for a
/// curve that is a single point; on `curves` for a common component that is not one of the
/// decided cases, or a pair that cannot be decided exactly (see the module docs).
pub fn intersect_curves(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> Result<Intersections> {
    let pp = Power::of("p", p)?;
    let qq = Power::of("q", q)?;
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
                .map(|s| point_of(&pp, Some(&qq), s))
                .collect();
            Ok(finish(points, Vec::new()))
        }
        None => overlap_case(p, q, &pp, &qq),
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
fn as_doubles(points: &[[Rational; 2]]) -> Option<Vec<[f64; 2]>> {
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

/// [`intersect_curves`] of control points given as doubles, each read exactly.
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `p[i]` / `q[i]` for a NaN or infinity, else as
/// [`intersect_curves`].
pub fn intersect_curves_f64(p: &[[f64; 2]], q: &[[f64; 2]]) -> Result<Intersections> {
    intersect_curves(&exact_points("p", p)?, &exact_points("q", q)?)
}

/// Points of doubles read exactly.
fn exact_points(field: &str, p: &[[f64; 2]]) -> Result<Vec<[Rational; 2]>> {
    p.iter()
        .enumerate()
        .map(|(i, xy)| {
            let v = rationals_of(&format!("{field}[{i}]"), xy)?;
            Ok([v[0].clone(), v[1].clone()])
        })
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

/// Whether every point of both lists lies on one line.
fn collinear(points: &[[Rational; 2]]) -> Option<([Rational; 2], [Rational; 2])> {
    let o = points[0].clone();
    let d = points
        .iter()
        .map(|p| [&p[0] - &o[0], &p[1] - &o[1]])
        .find(|v| !v[0].is_zero() || !v[1].is_zero())?;
    points
        .iter()
        .all(|p| ((&p[0] - &o[0]) * &d[1] - (&p[1] - &o[1]) * &d[0]).is_zero())
        .then_some((o, d))
}

/// The curves share a component: the decided cases of the module docs.
fn overlap_case(
    p: &[[Rational; 2]],
    q: &[[Rational; 2]],
    pp: &Power,
    qq: &Power,
) -> Result<Intersections> {
    let all: Vec<[Rational; 2]> = p.iter().chain(q).cloned().collect();
    if let Some((o, d)) = collinear(&all) {
        let along = |c: &Power| -> Vec<Rational> {
            c.x.iter()
                .zip(&c.y)
                .enumerate()
                .map(|(i, (x, y))| {
                    let (ox, oy) = if i == 0 {
                        (o[0].clone(), o[1].clone())
                    } else {
                        (Rational::zero(), Rational::zero())
                    };
                    (x - ox) * &d[0] + (y - oy) * &d[1]
                })
                .collect()
        };
        let (pts, ovs) = collinear_overlaps(&along(pp), &along(qq), false)?;
        let points = pts
            .into_iter()
            .map(|(s, t)| {
                point_of(
                    pp,
                    Some(qq),
                    Solution {
                        s,
                        t,
                        singular: true,
                    },
                )
            })
            .collect();
        return Ok(finish(points, ovs));
    }
    affine_overlap(pp, qq)
}

/// The monotone pieces of the 1-D polynomial f on [0, 1]: the turning points (roots of f'
/// of odd multiplicity in (0, 1)) with 0 and 1, all rational, else an error.
fn pieces(f: &[Rational]) -> Result<Vec<Rational>> {
    let fi = from_rationals(f);
    let mut cuts = vec![Rational::zero()];
    let df = derivative(&fi);
    if !upoly::is_zero(&df) {
        for r in roots_with_multiplicity(&df, &Rational::zero(), &Rational::one()) {
            if r.multiplicity % 2 == 0 {
                continue;
            }
            match r.value.exact() {
                Some(x) if x.is_zero() || x.is_one() => {}
                Some(x) => cuts.push(x.clone()),
                None => {
                    return Err(Error::new(
                        "curves",
                        "the curves overlap on a line and one turns back at an irrational \
                         parameter: not decided exactly by this version",
                    ))
                }
            }
        }
    }
    cuts.push(Rational::one());
    Ok(cuts)
}

/// The parameter in [a, b] where the monotone f takes the value c (f(a) <= c <= f(b) or
/// reversed), exactly.
fn preimage(f: &[Rational], a: &Rational, b: &Rational, c: &Rational) -> AlgebraicReal {
    for x in [a, b] {
        if &upoly_eval_q(f, x) == c {
            return AlgebraicReal::from_rational(x.clone());
        }
    }
    let mut g = f.to_vec();
    g[0] -= c;
    let gi = from_rationals(&g);
    roots_with_multiplicity(&gi, a, b)
        .into_iter()
        .next()
        .expect("a monotone piece takes every value between its ends")
        .value
}

/// Overlaps and touching points of two collinear curves with positions f(s), g(t) along
/// their line. With `same` (one curve against itself) only piece pairs k < l are used.
#[allow(clippy::type_complexity)]
fn collinear_overlaps(
    f: &[Rational],
    g: &[Rational],
    same: bool,
) -> Result<(Vec<(AlgebraicReal, AlgebraicReal)>, Vec<Overlap>)> {
    let (cf, cg) = (pieces(f)?, pieces(g)?);
    let mut points = Vec::new();
    let mut overlaps = Vec::new();
    for k in 0..cf.len() - 1 {
        let (a0, a1) = (&cf[k], &cf[k + 1]);
        let (fa0, fa1) = (upoly_eval_q(f, a0), upoly_eval_q(f, a1));
        for l in 0..cg.len() - 1 {
            if same && l <= k {
                continue;
            }
            let (b0, b1) = (&cg[l], &cg[l + 1]);
            let (gb0, gb1) = (upoly_eval_q(g, b0), upoly_eval_q(g, b1));
            let lo = fa0
                .clone()
                .min(fa1.clone())
                .max(gb0.clone().min(gb1.clone()));
            let hi = fa0
                .clone()
                .max(fa1.clone())
                .min(gb0.clone().max(gb1.clone()));
            match lo.cmp(&hi) {
                Ordering::Greater => {}
                Ordering::Equal => {
                    points.push((preimage(f, a0, a1, &lo), preimage(g, b0, b1, &lo)))
                }
                Ordering::Less => {
                    // s increases along the piece: its first end has the value nearer fa0.
                    let (c0, c1) = if fa0 < fa1 { (&lo, &hi) } else { (&hi, &lo) };
                    overlaps.push(Overlap {
                        s: [preimage(f, a0, a1, c0), preimage(f, a0, a1, c1)],
                        t: [preimage(g, b0, b1, c0), preimage(g, b0, b1, c1)],
                    });
                }
            }
        }
    }
    Ok((points, overlaps))
}

/// The exact rational d-th roots of a rational (both signs for even d), if any.
fn rational_roots_of(x: &Rational, d: usize) -> Vec<Rational> {
    let root = |n: &BigInt| -> Option<BigInt> {
        let r = n.abs().nth_root(d as u32);
        (num_traits::pow(r.clone(), d) == n.abs()).then_some(r)
    };
    let (Some(rn), Some(rd)) = (root(x.numer()), root(x.denom())) else {
        return Vec::new();
    };
    let r = Rational::new(rn, rd);
    if d.is_multiple_of(2) {
        if x.is_negative() {
            Vec::new()
        } else {
            vec![r.clone(), -r]
        }
    } else if x.is_negative() {
        vec![-r]
    } else {
        vec![r]
    }
}

/// The affine case of the module docs.
fn affine_overlap(pp: &Power, qq: &Power) -> Result<Intersections> {
    let refuse = || {
        Error::new(
            "curves",
            "the curves share a component through a change of parameter that is not affine: \
             not decided exactly by this version",
        )
    };
    let deg = |c: &Power| {
        c.x.iter()
            .zip(&c.y)
            .rposition(|(x, y)| !x.is_zero() || !y.is_zero())
            .unwrap_or(0)
    };
    let d = deg(pp);
    if d != deg(qq) || d == 0 {
        return Err(refuse());
    }
    let (px, py, qx, qy) = (&pp.x[d], &pp.y[d], &qq.x[d], &qq.y[d]);
    // q_d = lambda p_d.
    let lambda = if !px.is_zero() { qx / px } else { qy / py };
    if &(px * &lambda) != qx || &(py * &lambda) != qy {
        return Err(refuse());
    }
    let dd = Rational::from_integer(BigInt::from(d));
    for alpha in rational_roots_of(&lambda, d) {
        // Coefficient of t^(d-1) of P(alpha t + beta): alpha^(d-1) (p_(d-1) + d p_d beta).
        let a1 = num_traits::pow(alpha.clone(), d - 1);
        let beta = if !px.is_zero() {
            (&qq.x[d - 1] / &a1 - &pp.x[d - 1]) / (&dd * px)
        } else {
            (&qq.y[d - 1] / &a1 - &pp.y[d - 1]) / (&dd * py)
        };
        let compose = |c: &[Rational]| -> Vec<Rational> {
            let mut v: Vec<Vec<Rational>> = c.iter().map(|x| vec![x.clone()]).collect();
            taylor_shift(&mut v, &beta);
            scale_argument(&mut v, &alpha);
            v.into_iter().map(|p| p[0].clone()).collect()
        };
        let same = |a: Vec<Rational>, b: &[Rational]| {
            let n = a.len().max(b.len());
            (0..n).all(|i| {
                a.get(i).cloned().unwrap_or_default() == b.get(i).cloned().unwrap_or_default()
            })
        };
        if !same(compose(&pp.x), &qq.x) || !same(compose(&pp.y), &qq.y) {
            continue;
        }
        return Ok(affine_answer(pp, qq, &alpha, &beta));
    }
    Err(refuse())
}

/// Overlap and crossings of P and Q(t) = P(alpha t + beta).
fn affine_answer(pp: &Power, qq: &Power, alpha: &Rational, beta: &Rational) -> Intersections {
    let (zero, one) = (Rational::zero(), Rational::one());
    let s_of = |t: &Rational| alpha * t + beta;
    let t_of = |s: &Rational| (s - beta) / alpha;
    // The t-range where s = alpha t + beta is in [0, 1].
    let (ta, tb) = {
        let (u, v) = (t_of(&zero), t_of(&one));
        let (u, v) = if u < v { (u, v) } else { (v, u) };
        (u.max(zero.clone()), v.min(one.clone()))
    };
    let mut overlaps = Vec::new();
    let mut points = Vec::new();
    match ta.cmp(&tb) {
        Ordering::Less => {
            let (t0, t1) = if alpha.is_positive() {
                (ta, tb)
            } else {
                (tb, ta)
            };
            overlaps.push(Overlap {
                s: [
                    AlgebraicReal::from_rational(s_of(&t0)),
                    AlgebraicReal::from_rational(s_of(&t1)),
                ],
                t: [
                    AlgebraicReal::from_rational(t0),
                    AlgebraicReal::from_rational(t1),
                ],
            });
        }
        Ordering::Equal => points.push(point_of(
            pp,
            Some(qq),
            Solution {
                s: AlgebraicReal::from_rational(s_of(&ta)),
                t: AlgebraicReal::from_rational(ta),
                singular: true,
            },
        )),
        Ordering::Greater => {}
    }
    // Crossings P(s) = P(u), s != u, u = alpha t + beta with t in [0, 1].
    let (u0, u1) = {
        let (u, v) = (s_of(&zero), s_of(&one));
        if u < v {
            (u, v)
        } else {
            (v, u)
        }
    };
    if let Some(sols) = divided_difference_solutions(pp, (&zero, &one), (&u0, &u1)) {
        for sol in sols {
            if sol.s.equals(&sol.t) {
                continue;
            }
            let t = sol.t.affine_preimage(alpha, beta);
            points.push(point_of(
                pp,
                Some(qq),
                Solution {
                    s: sol.s,
                    t,
                    singular: sol.singular,
                },
            ));
        }
    }
    finish(points, overlaps)
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

/// Every pair s < t in [0, 1] with P(s) = P(t) of the curve with control points `p`, and
/// the overlaps of a curve that retraces itself (see the module docs).
///
/// # Errors
/// [`ErrorKind::Empty`] on `curve` for fewer than two control points; on `curve` for a single
/// point, or for a retracing that is not decided (a curve that is not on a line, or turns at
/// irrational parameters).
pub fn self_intersections(p: &[[Rational; 2]]) -> Result<Intersections> {
    let pp = Power::of("curve", p)?;
    let (zero, one) = (Rational::zero(), Rational::one());
    let sols = divided_difference_solutions(&pp, (&zero, &one), (&zero, &one));
    let Some(sols) = sols else {
        if let Some((o, d)) = collinear(p) {
            let f: Vec<Rational> =
                pp.x.iter()
                    .zip(&pp.y)
                    .enumerate()
                    .map(|(i, (x, y))| {
                        if i == 0 {
                            (x - &o[0]) * &d[0] + (y - &o[1]) * &d[1]
                        } else {
                            x * &d[0] + y * &d[1]
                        }
                    })
                    .collect();
            let (pts, ovs) = collinear_overlaps(&f, &f, true)?;
            let points = pts
                .into_iter()
                .filter(|(s, t)| s.compare(t) == Ordering::Less)
                .map(|(s, t)| {
                    point_of(
                        &pp,
                        None,
                        Solution {
                            s,
                            t,
                            singular: true,
                        },
                    )
                })
                .collect();
            return Ok(finish(points, ovs));
        }
        return Err(Error::new(
            "curve",
            "the curve retraces itself along a path that is not a line: not decided exactly \
             by this version",
        ));
    };
    let points = sols
        .into_iter()
        .filter(|sol| sol.s.compare(&sol.t) == Ordering::Less)
        .map(|sol| point_of(&pp, None, sol))
        .collect();
    Ok(finish(points, Vec::new()))
}

/// [`self_intersections`] of control points given as doubles, each read exactly.
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `curve[i]`, else as [`self_intersections`].
pub fn self_intersections_f64(p: &[[f64; 2]]) -> Result<Intersections> {
    self_intersections(&exact_points("curve", p)?)
}

/// A work estimate, in nanoseconds of a 2-core x86-64 machine, for [`intersect_curves`] on
/// curves of degrees `n` and `m` whose power coefficients, after clearing denominators, have
/// at most `bits` bits, when the exact solver answers (the float filter did not decide): the
/// resultant has degree n m and coefficients of about (n + m) (bits + n + m) bits, and the
/// dominant steps (isolation, partner matching) cost about (n m)^3 operations on numbers of
/// that size. Measured in release (2026-12-03, multi-modular resultants): random
/// small-integer pairs n = m = 8 about 0.2 s, n = m = 16 about 7 s, n = m = 20 about 30 s.
pub fn intersection_work(n: usize, m: usize, bits: usize) -> u128 {
    let d = (n as u128) * (m as u128) + 1;
    16 * d * d * d * coefficient_words(n, m, bits)
}

/// A work estimate, in nanoseconds as [`intersection_work`], for [`intersect_curves`] when
/// the float filter decides with `crossings` crossings: two multi-modular resultants of
/// degree n m, and for each crossing the Bernstein coefficients of their square-free parts
/// over its enclosure (Descartes' test), each about (n m)^2 operations on numbers of the
/// resultant's size. Measured in release: random pairs n = m = 20 with 4 to 9 crossings
/// 0.9 to 1.3 s, n = m = 16 about 0.3 to 0.4 s, n = m = 3 about 1 ms.
pub fn filtered_intersection_work(n: usize, m: usize, bits: usize, crossings: usize) -> u128 {
    let d = (n as u128) * (m as u128) + 1;
    25 * (2 + crossings as u128) * d * d * coefficient_words(n, m, bits)
}

/// The estimated work of [`intersect_curves`] on `p` and `q`, in nanoseconds as
/// [`intersection_work`]: when every coordinate is a double and the float filter decides
/// (it runs here, in microseconds to milliseconds), [`filtered_intersection_work`] with its
/// number of crossings, else [`intersection_work`]. `bits` is the longest coordinate's
/// numerator and denominator together.
pub fn curve_pair_work(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> u128 {
    let bits = longest_coordinate(p).max(longest_coordinate(q));
    let (n, m) = (p.len().saturating_sub(1), q.len().saturating_sub(1));
    let filtered = as_doubles(p)
        .zip(as_doubles(q))
        .and_then(|(pf, qf)| certified_crossings_f64(&pf, &qf));
    match filtered {
        Some(crossings) => filtered_intersection_work(n, m, bits, crossings.len()),
        None => intersection_work(n, m, bits),
    }
}

/// The estimated work of [`self_intersections`] on `p`, in nanoseconds as
/// [`intersection_work`]: the divided difference (P(s) - P(t)) / (s - t) has degree n - 1 in
/// each variable and always goes through the exact solver.
pub fn self_intersection_work(p: &[[Rational; 2]]) -> u128 {
    let d = p.len().saturating_sub(2).max(1);
    intersection_work(d, d, longest_coordinate(p))
}

/// The bits of the longest coordinate, numerator and denominator together (at least 1).
fn longest_coordinate(p: &[[Rational; 2]]) -> usize {
    p.iter()
        .flatten()
        .map(|c| (c.numer().bits() + c.denom().bits()) as usize)
        .max()
        .unwrap_or(1)
}

/// The 64-bit words of a resultant coefficient (see [`intersection_work`]).
fn coefficient_words(n: usize, m: usize, bits: usize) -> u128 {
    ((n + m) as u128) * (bits as u128 + (n + m) as u128) / 64 + 1
}
