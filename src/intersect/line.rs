//! Exact intersections of a line segment with a curve, without resultants: the cheap exact
//! case behind [`intersect_curves`](super::curves::intersect_curves) whenever one of the two
//! curves is of degree 1 (the edges of font outlines and polygons).
//!
//! Let the segment be P(s) = p0 + s d (d = p1 - p0 ≠ 0) and the curve Q(t) (power form).
//! Q(t) lies on P's line exactly where f(t) = cross(d, Q(t) - p0) vanishes, a polynomial of
//! the curve's degree with rational coefficients; there P(s) = Q(t) for
//! s = g(t) = dot(Q(t) - p0, d) / |d|², and the point counts when s is in [0, 1]. The roots of f
//! in [0, 1] are isolated exactly (`zeros::roots_with_multiplicity`) and s is the algebraic
//! number g(t). P'(s) × Q'(t) = f'(t), so the contact is a tangency exactly when t is a
//! multiple root of f.
//!
//! When f is identically zero the curve lies on the line. For a second segment the common
//! part is decided by the two parameters g(q0), g(q1) of its ends on P: an overlap of positive
//! length, one common end point (a tangency: the derivatives are parallel), or nothing. A
//! curve of higher degree on the line is left to the general solver (`None`).

use super::algebraic::{round_polynomial_at, upoly_eval_q, value_at, AlgebraicReal};
use super::curves::{IntersectionPoint, Overlap};
use super::upoly;
use super::zeros::roots_with_multiplicity;
use crate::num::ring::{rational_to_f64, Rational};
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// The points and overlaps of the segment `p` (two control points) with the curve whose power
/// form is `qx`, `qy` (ascending, `q` its control points), with s on the segment and t on the
/// curve; `None` when the segment is a single point or a curve of degree over 1 lies on its
/// line (the general solver answers those).
pub(crate) fn segment_and_curve(
    p: &[[Rational; 2]],
    q: &[[Rational; 2]],
    qx: &[Rational],
    qy: &[Rational],
) -> Option<(Vec<IntersectionPoint>, Vec<Overlap>)> {
    let p0 = &p[0];
    let d = [&p[1][0] - &p0[0], &p[1][1] - &p0[1]];
    let norm = &d[0] * &d[0] + &d[1] * &d[1];
    if norm.is_zero() {
        return None;
    }
    // f(t) = d_x (qy(t) - p0_y) - d_y (qx(t) - p0_x); g(t) = ((qx - p0_x) d_x + (qy - p0_y) d_y) / |d|^2.
    let shifted = |c: &[Rational], o: &Rational| -> Vec<Rational> {
        let mut c = c.to_vec();
        c[0] = &c[0] - o;
        c
    };
    let (ux, uy) = (shifted(qx, &p0[0]), shifted(qy, &p0[1]));
    let f: Vec<Rational> = ux
        .iter()
        .zip(&uy)
        .map(|(x, y)| &d[0] * y - &d[1] * x)
        .collect();
    let g: Vec<Rational> = ux
        .iter()
        .zip(&uy)
        .map(|(x, y)| (&d[0] * x + &d[1] * y) / &norm)
        .collect();
    let (zero, one) = (Rational::zero(), Rational::one());
    if f.iter().all(Zero::is_zero) {
        return (q.len() == 2).then(|| collinear_segments(p, &g));
    }
    let roots = roots_in_unit_interval(f);
    let mut points = Vec::new();
    for (t, multiplicity) in roots {
        let (s, point) = match t.exact() {
            Some(t0) => {
                let s = upoly_eval_q(&g, t0);
                let point = [upoly_eval_q(qx, t0), upoly_eval_q(qy, t0)];
                (
                    AlgebraicReal::from_rational(s),
                    point.map(|c| rational_to_f64(&c)),
                )
            }
            None => (
                value_at(&g, &t),
                [round_polynomial_at(qx, &t), round_polynomial_at(qy, &t)],
            ),
        };
        if s.cmp_rational(&zero) == Ordering::Less || s.cmp_rational(&one) == Ordering::Greater {
            continue;
        }
        points.push(IntersectionPoint {
            s,
            t,
            tangent: multiplicity > 1,
            point,
        });
    }
    Some((points, Vec::new()))
}

/// The roots in [0, 1] of the non-zero rational polynomial f (ascending) with their
/// multiplicities, in increasing order. Roots at the ends 0 and 1 (a curve's end on the
/// segment, the common case in outlines) are divided out exactly first; a remaining factor of
/// degree 1 has its one rational root; only a factor of higher degree is isolated by the
/// general root finder.
fn roots_in_unit_interval(mut f: Vec<Rational>) -> Vec<(AlgebraicReal, usize)> {
    let (zero, one) = (Rational::zero(), Rational::one());
    let trim = |f: &mut Vec<Rational>| {
        while f.len() > 1 && f.last().is_some_and(Zero::is_zero) {
            f.pop();
        }
    };
    trim(&mut f);
    let mut ends = Vec::new();
    for end in [zero.clone(), one.clone()] {
        let mut multiplicity = 0;
        // f(end) = 0: f = (t - end) q, q from the top: q_(k-1) = f_k + end q_k.
        while f.len() > 1 && upoly_eval_q(&f, &end).is_zero() {
            let n = f.len() - 1;
            let mut q = vec![Rational::zero(); n];
            q[n - 1] = f[n].clone();
            for k in (1..n).rev() {
                q[k - 1] = &f[k] + &end * &q[k];
            }
            f = q;
            multiplicity += 1;
        }
        if multiplicity > 0 {
            ends.push((end, multiplicity));
        }
    }
    let mut roots: Vec<(AlgebraicReal, usize)> = match f.len() {
        0 | 1 => Vec::new(),
        2 => {
            let t = -&f[0] / &f[1];
            if t > zero && t < one {
                vec![(AlgebraicReal::from_rational(t), 1)]
            } else {
                Vec::new()
            }
        }
        _ => roots_with_multiplicity(&upoly::positive_multiple(&f), &zero, &one)
            .into_iter()
            .map(|r| (r.value, r.multiplicity))
            .collect(),
    };
    for (end, multiplicity) in ends {
        roots.push((AlgebraicReal::from_rational(end), multiplicity));
    }
    roots.sort_by(|a, b| a.0.compare(&b.0));
    roots
}

/// Two segments on one line: `g` maps the second's parameter t to the first's, s = g(t)
/// (degree 1, ascending). An overlap of positive length, one common end (a tangency), or
/// nothing.
fn collinear_segments(
    p: &[[Rational; 2]],
    g: &[Rational],
) -> (Vec<IntersectionPoint>, Vec<Overlap>) {
    let (zero, one) = (Rational::zero(), Rational::one());
    // s of the second segment's ends; its parameter at s is (s - g0) / g1.
    let g1 = g.get(1).cloned().unwrap_or_else(Rational::zero);
    let (s_at_0, s_at_1) = (g[0].clone(), &g[0] + &g1);
    let (lo, hi) = if s_at_0 < s_at_1 {
        (s_at_0.clone(), s_at_1)
    } else {
        (s_at_1, s_at_0.clone())
    };
    let (lo, hi) = (lo.max(zero), hi.min(one));
    if lo > hi || g1.is_zero() {
        return (Vec::new(), Vec::new());
    }
    let t_of = |s: &Rational| (s - &s_at_0) / &g1;
    let exact = |x: Rational| AlgebraicReal::from_rational(x);
    if lo == hi {
        let point = [
            &p[0][0] + (&p[1][0] - &p[0][0]) * &lo,
            &p[0][1] + (&p[1][1] - &p[0][1]) * &lo,
        ];
        let t = t_of(&lo);
        return (
            vec![IntersectionPoint {
                s: exact(lo),
                t: exact(t),
                tangent: true,
                point: point.map(|c| rational_to_f64(&c)),
            }],
            Vec::new(),
        );
    }
    let (t_lo, t_hi) = (t_of(&lo), t_of(&hi));
    (
        Vec::new(),
        vec![Overlap {
            s: [exact(lo), exact(hi)],
            t: [exact(t_lo), exact(t_hi)],
        }],
    )
}

/// The answer of [`segment_and_curve`] with the roles of the two curves exchanged: the
/// segment is the second curve, so s and t swap (and each overlap is turned to run along the
/// first curve).
pub(crate) fn curve_and_segment(
    found: (Vec<IntersectionPoint>, Vec<Overlap>),
) -> (Vec<IntersectionPoint>, Vec<Overlap>) {
    let (points, overlaps) = found;
    let points = points
        .into_iter()
        .map(|x| IntersectionPoint {
            s: x.t,
            t: x.s,
            tangent: x.tangent,
            point: x.point,
        })
        .collect();
    let overlaps = overlaps
        .into_iter()
        .map(|o| {
            let [s0, s1] = o.t;
            let [t0, t1] = o.s;
            if s0.compare(&s1) == Ordering::Greater {
                Overlap {
                    s: [s1, s0],
                    t: [t1, t0],
                }
            } else {
                Overlap {
                    s: [s0, s1],
                    t: [t0, t1],
                }
            }
        })
        .collect();
    (points, overlaps)
}

#[cfg(test)]
mod tests {
    use crate::intersect::curves::{intersect_curves, intersect_general, Intersections};
    use crate::num::ring::Rational;
    use crate::test_rng::XorShift;

    /// Whether the two answers are the same: every parameter equal as an exact number.
    fn same(a: &Intersections, b: &Intersections) -> bool {
        a.points.len() == b.points.len()
            && a.overlaps.len() == b.overlaps.len()
            && a.points.iter().zip(&b.points).all(|(x, y)| {
                x.s.equals(&y.s) && x.t.equals(&y.t) && x.tangent == y.tangent && x.point == y.point
            })
            && a.overlaps
                .iter()
                .zip(&b.overlaps)
                .all(|(x, y)| (0..2).all(|k| x.s[k].equals(&y.s[k]) && x.t[k].equals(&y.t[k])))
    }

    /// Segments against segments, quadratics and cubics on a small grid (collinear pieces,
    /// shared ends, ends on curves, tangencies are frequent there), both orders: the shortcut
    /// gives exactly the general solver's answer.
    #[test]
    fn segments_agree_with_the_general_solver() {
        let mut rng = XorShift(0x0011_e5e9);
        let mut coordinate = || Rational::from_integer(((rng.next() % 5) as i64 - 2).into());
        let mut contacts = 0;
        for i in 0..400 {
            let degree = 1 + i % 3;
            let mut point = || [coordinate(), coordinate()];
            let segment = [point(), point()];
            if segment[0] == segment[1] {
                continue;
            }
            let curve: Vec<[Rational; 2]> = (0..=degree).map(|_| point()).collect();
            if curve.iter().all(|c| c == &curve[0]) {
                continue;
            }
            for (p, q) in [(&segment[..], &curve[..]), (&curve[..], &segment[..])] {
                let fast = intersect_curves(p, q).unwrap();
                let general = intersect_general(p, q).unwrap();
                assert!(
                    same(&fast, &general),
                    "case {i}: {p:?} {q:?}: {fast} against {general}"
                );
                contacts += fast.points.len() + fast.overlaps.len();
            }
        }
        assert!(contacts > 200, "the grid makes contacts: {contacts}");
    }
}
