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
//!
//! **Fixed width** ([`segment_contact_small`]). Two segments whose ends are small integers on
//! one dyadic scale (every font) are decided by the same formulas in `i128`, before big
//! integers: with e = q1 - q0 and c = cross(d, e), non-parallel segments meet at
//! s = cross(q0 - p0, e) / c, t = cross(q0 - p0, d) / c when both lie in [0, 1]; parallel
//! segments meet only when collinear, cross(d, q0 - p0) = 0, and then as above through
//! g(t) = dot(q0 + t e - p0, d) / |d|², now a fraction of two integers. Coordinates below
//! 2^30 keep every product below 2^63.
//!
//! A segment and a quadratic or cubic with such ends ([`segment_curve_small`]) take the same
//! path in `i128`: the power coefficients of Q are integers (binomial combinations of the
//! control points), so f has integer coefficients; its roots at 0 and 1 are divided out
//! exactly (synthetic division keeps integers), a remaining factor of degree 1 has its one
//! rational root, and a remaining factor of higher degree whose Bernstein coefficients on
//! [0, 1] all have one strict sign has no root there (the curve's ends touching the segment,
//! the common case in outlines, leave exactly these). Anything else, or a number that does
//! not fit, is left to big rationals (`None`).

use super::algebraic::{round_polynomial_at, upoly_eval_q, value_at, AlgebraicReal};
use super::intersections::{IntersectionPoint, Overlap};
use super::upoly;
use super::zeros::roots_with_multiplicity;
use crate::num::ring::{rational_to_f64, Rational};
use crate::num::small::SmallRational;
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

/// The common points of two segments decided in fixed width (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SegmentContact {
    /// No common point.
    Apart,
    /// One common point at s on the first segment and t on the second (a crossing, an end
    /// on the other segment, or collinear segments touching end to end).
    Point([SmallRational; 2]),
    /// Collinear segments sharing a stretch of positive length: s increasing on the first,
    /// t the matching ends on the second.
    Overlap {
        s: [SmallRational; 2],
        t: [SmallRational; 2],
    },
}

/// The largest magnitude of a scaled coordinate that the fixed-width stage takes: 2^60, so
/// that differences stay below 2^61 and a segment's cross and dot products below 2^123 (a
/// curve's larger sums are checked). Doubles of one binade scale to 53-bit integers, so
/// most double input whose exponents are close qualifies, not only integers.
pub(crate) const SMALL_COORDINATE: i64 = 1 << 60;

/// The common points of the segments `p` and `q` (two distinct ends each) in fixed-width
/// arithmetic, exactly; `None` when the coordinates are not small integers on one dyadic
/// scale or a parameter does not fit (the caller then intersects exactly in big rationals).
#[cfg(test)]
pub(crate) fn segment_contact_small(p: &[[f64; 2]], q: &[[f64; 2]]) -> Option<SegmentContact> {
    let [a, b] = crate::num::small::on_common_scale(p, q, SMALL_COORDINATE)?;
    segment_contact_integers([a[0], a[1]], [b[0], b[1]])
}

/// [`segment_contact_small`] on integer ends on one scale, each coordinate below
/// [`SMALL_COORDINATE`] in magnitude.
pub(crate) fn segment_contact_integers(
    [p0, p1]: [[i64; 2]; 2],
    [q0, q1]: [[i64; 2]; 2],
) -> Option<SegmentContact> {
    let w = |a: [i64; 2], b: [i64; 2]| [i128::from(b[0] - a[0]), i128::from(b[1] - a[1])];
    let cross = |a: [i128; 2], b: [i128; 2]| a[0] * b[1] - a[1] * b[0];
    let dot = |a: [i128; 2], b: [i128; 2]| a[0] * b[0] + a[1] * b[1];
    let (d, e, r) = (w(p0, p1), w(q0, q1), w(p0, q0));
    let c = cross(d, e);
    if c != 0 {
        // s = cross(r, e) / c and t = cross(r, d) / c in [0, 1], decided on the numerators
        // before any reduction.
        let (a, b) = (cross(r, e), cross(r, d));
        let within = |x: i128| {
            if c > 0 {
                0 <= x && x <= c
            } else {
                c <= x && x <= 0
            }
        };
        if !(within(a) && within(b)) {
            return Some(SegmentContact::Apart);
        }
        return Some(SegmentContact::Point([
            SmallRational::new(a, c)?,
            SmallRational::new(b, c)?,
        ]));
    }
    if cross(d, r) != 0 {
        return Some(SegmentContact::Apart);
    }
    // Collinear: s = g(t) = (dot(r, d) + t dot(e, d)) / |d|^2, with dot(e, d) != 0.
    let norm = dot(d, d);
    let s_at_0 = SmallRational::new(dot(r, d), norm)?;
    let slope = SmallRational::new(dot(e, d), norm)?;
    let s_at_1 = s_at_0.add(slope)?;
    let (lo, hi) = (s_at_0.min(s_at_1), s_at_0.max(s_at_1));
    let (lo, hi) = (lo.max(SmallRational::ZERO), hi.min(SmallRational::ONE));
    if lo > hi {
        return Some(SegmentContact::Apart);
    }
    let t_of = |s: SmallRational| s.sub(s_at_0)?.div(slope);
    Some(if lo == hi {
        SegmentContact::Point([lo, t_of(lo)?])
    } else {
        SegmentContact::Overlap {
            s: [lo, hi],
            t: [t_of(lo)?, t_of(hi)?],
        }
    })
}

/// The common points of the segment `p` and the quadratic or cubic `q` as (s on `p`, t on
/// `q`), increasing in s, in fixed-width arithmetic (module doc); `None` when the
/// coordinates are not small integers on one dyadic scale, a number does not fit, the curve
/// lies on the segment's line, or a root of f inside (0, 1) is irrational or not isolated by
/// the sign test (the caller then intersects exactly in big rationals).
#[cfg(test)]
pub(crate) fn segment_curve_small(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
) -> Option<Vec<[SmallRational; 2]>> {
    let [a, b] = crate::num::small::on_common_scale(p, q, SMALL_COORDINATE)?;
    segment_curve_integers([a[0], a[1]], &b[..q.len()])
}

/// [`segment_curve_small`] on integer control points on one scale, each coordinate below
/// [`SMALL_COORDINATE`] in magnitude.
pub(crate) fn segment_curve_integers(
    p: [[i64; 2]; 2],
    q: &[[i64; 2]],
) -> Option<Vec<[SmallRational; 2]>> {
    let n = q.len().wrapping_sub(1);
    if !(2..=3).contains(&n) {
        return None;
    }
    // Fixed-size storage (n <= 3): no allocation but the answer's.
    let [p0, p1] = p.map(|c| c.map(i128::from));
    let mut c = [[0i128; 2]; 4];
    for (ci, qi) in c.iter_mut().zip(q) {
        *ci = [i128::from(qi[0]) - p0[0], i128::from(qi[1]) - p0[1]];
    }
    let d = [p1[0] - p0[0], p1[1] - p0[1]];
    // Power coefficients of Q - p0 (ascending): sum_k (-1)^(k-i) C(n,k) C(k,i) c_i t^k, below
    // 8 * 2^61 in magnitude.
    const BINOMIAL: [[i128; 4]; 4] = [[1, 0, 0, 0], [1, 1, 0, 0], [1, 2, 1, 0], [1, 3, 3, 1]];
    let mut power = [[0i128; 2]; 4];
    for (k, a) in power.iter_mut().enumerate().take(n + 1) {
        for (i, ci) in c.iter().enumerate().take(k + 1) {
            let sign = if (k - i) % 2 == 0 { 1 } else { -1 };
            let w = BINOMIAL[n][k] * BINOMIAL[k][i] * sign;
            *a = [a[0] + w * ci[0], a[1] + w * ci[1]];
        }
    }
    // f(t) = cross(d, Q(t) - p0) (its first `len` coefficients), and every sum below, checked.
    let mut f = [0i128; 4];
    for (fk, a) in f.iter_mut().zip(&power).take(n + 1) {
        *fk = d[0]
            .checked_mul(a[1])?
            .checked_sub(d[1].checked_mul(a[0])?)?;
    }
    let mut len = n + 1;
    if f[..len].iter().all(|&x| x == 0) {
        return None;
    }
    let (mut roots, mut found_roots) = ([SmallRational::ZERO; 4], 0);
    for end in [0i128, 1] {
        let at_end = |f: &[i128]| {
            if end == 0 {
                Some(f[0])
            } else {
                f.iter().try_fold(0i128, |acc, &x| acc.checked_add(x))
            }
        };
        while len > 1 && at_end(&f[..len])? == 0 {
            // f = (t - end) r: r_(k-1) = f_k + end r_k, from the top.
            let m = len - 1;
            let mut r = [0i128; 4];
            r[m - 1] = f[m];
            for k in (1..m).rev() {
                r[k - 1] = f[k].checked_add(end * r[k])?;
            }
            f = r;
            len = m;
            let root = SmallRational::integer(end as i64);
            if found_roots == 0 || roots[found_roots - 1] != root {
                roots[found_roots] = root;
                found_roots += 1;
            }
        }
    }
    while len > 1 && f[len - 1] == 0 {
        len -= 1;
    }
    match len {
        1 => {}
        2 => {
            let t = SmallRational::new(-f[0], f[1])?;
            if SmallRational::ZERO < t && t < SmallRational::ONE {
                roots[found_roots] = t;
                found_roots += 1;
            }
        }
        _ => {
            // Bernstein coefficients of the remaining factor r (degree m) on [0, 1], times
            // C(m, j): b_j = sum_(i <= j) C(m - i, j - i) r_i; one strict sign: no root.
            let m = len - 1;
            let mut signs = [0i128; 4];
            for (j, sign) in signs.iter_mut().enumerate().take(m + 1) {
                let mut b = 0i128;
                for (i, fi) in f.iter().enumerate().take(j + 1) {
                    b = b.checked_add(BINOMIAL[m - i][j - i].checked_mul(*fi)?)?;
                }
                *sign = b.signum();
            }
            if signs[..=m].iter().any(|&x| x == 0 || x != signs[0]) {
                return None;
            }
        }
    }
    // s = dot(Q(t) - p0, d) / |d|^2 at each root t = a / b: Q(t) - p0 = sum_k power_k a^k
    // b^(n - k) / b^n.
    let norm = d[0]
        .checked_mul(d[0])?
        .checked_add(d[1].checked_mul(d[1])?)?;
    let mut found = Vec::with_capacity(found_roots);
    for &t in &roots[..found_roots] {
        let (a, b) = (i128::from(t.numer()), i128::from(t.denom()));
        let mut num = 0i128;
        let mut scale = 1i128;
        for (k, a_k) in power.iter().enumerate().take(n + 1) {
            let mut w = a_k[0]
                .checked_mul(d[0])?
                .checked_add(a_k[1].checked_mul(d[1])?)?;
            for _ in 0..k {
                w = w.checked_mul(a)?;
            }
            for _ in k..n {
                w = w.checked_mul(b)?;
            }
            num = num.checked_add(w)?;
        }
        for _ in 0..n {
            scale = scale.checked_mul(b)?;
        }
        let s = SmallRational::new(num, norm.checked_mul(scale)?)?;
        if SmallRational::ZERO <= s && s <= SmallRational::ONE {
            found.push([s, t]);
        }
    }
    found.sort();
    Some(found)
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

    /// Control points of doubles as their exact values (the general solver's input).
    fn exact_points(x: &[[f64; 2]]) -> Vec<[Rational; 2]> {
        x.iter()
            .map(|c| c.map(|v| Rational::from_float(v).unwrap()))
            .collect()
    }

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

    /// Segments on a small grid, on dyadic scales, and in every order: the fixed-width answer
    /// is the general solver's (resultants and big rationals), parameter for parameter.
    #[test]
    fn fixed_width_segments_agree_with_the_general_solver() {
        use super::{segment_contact_small, SegmentContact};
        let mut rng = XorShift(0x5e95);
        let mut kinds = [0; 3];
        for i in 0..3000 {
            let scale = [1.0, 0.25, 1024.0, 3.0 / 64.0, 0.1][i % 5];
            let mut point = || {
                let mut c = || ((rng.next() % 7) as f64 - 3.0) * scale;
                [c(), c()]
            };
            let (p, mut q) = ([point(), point()], [point(), point()]);
            if i % 3 == 0 {
                // Ends on p's line, at multiples of half its length: collinear pieces.
                let mut on_line = || {
                    let k = (rng.next() % 7) as f64 / 2.0 - 1.0;
                    [0, 1].map(|c| p[0][c] + k * (p[1][c] - p[0][c]))
                };
                q = [on_line(), on_line()];
            }
            if p[0] == p[1] || q[0] == q[1] {
                continue;
            }
            // Small integers always fit; multiples of 0.1 (53-bit integers on one scale) fit
            // unless a reduced parameter needs more than 64 bits.
            let Some(small) = segment_contact_small(&p, &q) else {
                assert_eq!(i % 5, 4, "small coordinates fit: {p:?} {q:?}");
                continue;
            };
            let general = intersect_general(&exact_points(&p), &exact_points(&q)).unwrap();
            let big = |x: &super::SmallRational| x.to_rational();
            match small {
                SegmentContact::Apart => {
                    assert!(
                        general.points.is_empty() && general.overlaps.is_empty(),
                        "{p:?} {q:?}"
                    );
                    kinds[0] += 1;
                }
                SegmentContact::Point([s, t]) => {
                    assert!(general.overlaps.is_empty() && general.points.len() == 1);
                    let x = &general.points[0];
                    assert_eq!((x.s.exact(), x.t.exact()), (Some(&big(&s)), Some(&big(&t))));
                    kinds[1] += 1;
                }
                SegmentContact::Overlap { s, t } => {
                    assert!(general.points.is_empty() && general.overlaps.len() == 1);
                    let o = &general.overlaps[0];
                    for k in 0..2 {
                        assert_eq!(o.s[k].exact(), Some(&big(&s[k])), "{p:?} {q:?}");
                        assert_eq!(o.t[k].exact(), Some(&big(&t[k])), "{p:?} {q:?}");
                    }
                    kinds[2] += 1;
                }
            }
        }
        assert!(
            kinds.iter().all(|&k| k > 30),
            "every kind of contact: {kinds:?}"
        );
        // Beyond the fixed width: the caller falls back.
        // Doubles of distant binades (1e-30 and 1) do not share a 60-bit scale: big rationals.
        assert_eq!(
            segment_contact_small(&[[1e-30, 0.0], [1.0, 1.0]], &[[0.0, 1.0], [1.0, 0.0]]),
            None
        );
        // 0.1 and 1 do: the crossing of the diagonals is exact in fixed width.
        let tenth = segment_contact_small(&[[0.1, 0.0], [1.0, 1.0]], &[[0.0, 1.0], [1.0, 0.0]]);
        assert!(matches!(tenth, Some(SegmentContact::Point(_))));
    }

    /// Segments against quadratics and cubics on a small grid (ends on the segment, tangent
    /// ends and curves through the segment's line are frequent there), on dyadic scales:
    /// wherever the fixed-width stage answers, its points are the general solver's.
    #[test]
    fn fixed_width_segment_and_curve_agree_with_the_general_solver() {
        use super::segment_curve_small;
        let mut rng = XorShift(0x5e9c);
        let (mut answered, mut points) = (0, 0);
        for i in 0..3000 {
            let scale = [1.0, 0.5, 256.0, 5.0 / 32.0, 0.1][i % 5];
            let degree = 2 + i % 2;
            let mut point = || {
                let mut c = || ((rng.next() % 5) as f64 - 2.0) * scale;
                [c(), c()]
            };
            let segment = [point(), point()];
            let mut curve: Vec<[f64; 2]> = (0..=degree).map(|_| point()).collect();
            if i % 3 == 0 {
                // A curve that starts on the segment's line with a tangent along it.
                curve[0] = segment[0];
                curve[1] = [0, 1].map(|c| 2.0 * segment[1][c] - segment[0][c]);
            }
            if segment[0] == segment[1] || curve.iter().all(|c| c == &curve[0]) {
                continue;
            }
            let Some(small) = segment_curve_small(&segment, &curve) else {
                continue;
            };
            let general =
                intersect_general(&exact_points(&segment), &exact_points(&curve)).unwrap();
            assert!(general.overlaps.is_empty());
            assert_eq!(small.len(), general.points.len(), "{segment:?} {curve:?}");
            for ([s, t], x) in small.iter().zip(&general.points) {
                assert_eq!(x.s.exact(), Some(&s.to_rational()), "{segment:?} {curve:?}");
                assert_eq!(x.t.exact(), Some(&t.to_rational()), "{segment:?} {curve:?}");
            }
            answered += 1;
            points += small.len();
        }
        assert!(
            answered > 1000 && points > 500,
            "{answered} answered, {points} points"
        );
    }
}
