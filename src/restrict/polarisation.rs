//! The inverse (polarisation) formula of seed 004: blossoms and control points from points of
//! the curve or surface alone, with no control points known beforehand. This module is its one
//! home: the closures' API below and [`crate::Method::Polarisation`] both call [`polar_form`],
//! the one implementation of Theorem 2, eq. (19):
//!
//! f(x_1..x_n) = 1/n! sum_{N=1..n} (-1)^(n-N) N^n sum_{i_1 < ... < i_N} q((x_i1 + ... + x_iN) / N),
//!
//! where q(x) = f(x, ..., x) is the curve or surface itself. Its instances:
//!
//! * curve blossom, Corollary 1, eq. (20), and tensor patches in two passes
//!   (`b[u_1..u_m; v_1..v_n] = b[u_1..u_m][v_1..v_n]`: the inner pass polarises v for a fixed
//!   u, which is again a polynomial of degree n in u, and the outer pass polarises that);
//! * triangle blossom at points of the parametric plane, eq. (21);
//! * control points of a curve on [alpha, beta], Corollary 2, eq. (22):
//!   b_i = b[alpha^(n-i), beta^i];
//! * control points of a triangle with corners a, b, c, Corollary 3, eq. (23):
//!   b_ijk = b[a^i, b^j, c^k].
//!
//! When arguments repeat, as they do at every control point (a^nu b^mu c^lambda), the subsets
//! are grouped by how many copies of each distinct argument they hold: a subset taking k_r of
//! the m_r copies of x_r occurs prod_r C(m_r, k_r) times (this is eq. (22) of 004 for curves
//! and (23) for triangles). Grouping changes the count of evaluations of q, from 2^n - 1 to
//! prod_r (m_r + 1) - 1, not the formula.
//!
//! The degree `n` is a parameter, not read off the closure: a parametrisation of degree below
//! `n` gets its degree-elevated blossom (the "built-in" elevation of section 4), and one of
//! degree above `n`, or a non-polynomial one such as `(t, ln t)`, gets the blossom of the
//! degree-`n` polynomial that the formula defines from its samples (degree reduction by the
//! inverse formula, Examples 2 and 3 of 004). The closures are only called at averages of the
//! arguments, so they need only be defined on the convex hull of the arguments.

#[cfg(doc)]
use crate::error::ErrorKind;
use crate::error::{check_arity, Result};
use crate::num::binomial::binomial;
use crate::restrict::nets::{repeated, tensor_net, triangle_net};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::point::{self, Point};
use crate::shape::power::{check_dims, PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::{Rational, Ring};
use num_bigint::BigInt;
use num_traits::One;

/// Groups equal arguments: `(distinct value, multiplicity)` in order of first appearance.
fn group<P: PartialEq + Clone>(args: &[P]) -> Vec<(P, usize)> {
    let mut groups: Vec<(P, usize)> = Vec::new();
    for x in args {
        match groups.iter_mut().find(|(y, _)| y == x) {
            Some((_, k)) => *k += 1,
            None => groups.push((x.clone(), 1)),
        }
    }
    groups
}

/// Calls `visit(counts)` for every vector `0 <= counts[r] <= mult[r]` except all zeros.
fn for_each_sub_multiset(mult: &[usize], visit: &mut dyn FnMut(&[usize])) {
    let mut counts = vec![0usize; mult.len()];
    loop {
        // Increment like an odometer.
        let mut r = 0;
        while r < mult.len() && counts[r] == mult[r] {
            counts[r] = 0;
            r += 1;
        }
        if r == mult.len() {
            return;
        }
        counts[r] += 1;
        visit(&counts);
    }
}

/// The symmetric n-affine form f(x_1..x_n) of a map `q` of degree n from an affine space of
/// points `Vec<T>` (one coordinate for curves, two for surfaces), eq. (19) of seed 004.
///
/// `q` is only ever called at averages of the arguments. For `n = 0` the form is the constant
/// `q(x)` for any x; it is evaluated at the origin.
///
/// # Errors
/// [`ErrorKind::Arity`] on `args` when `args.len() != n`; [`ErrorKind::Dimension`] on
/// `args[k]` when an argument does not have `dim` coordinates.
pub fn polar_form<T: Ring>(
    n: usize,
    args: &[Point<T>],
    dim: usize,
    q: &dyn Fn(&[T]) -> Point<T>,
) -> Result<Point<T>> {
    check_arity("args", args.len(), n)?;
    check_dims(args, dim, "args")?;
    Ok(polar_form_unchecked(n, args, dim, q))
}

/// [`polar_form`] on `n` arguments of `dim` coordinates each.
fn polar_form_unchecked<T: Ring>(
    n: usize,
    args: &[Point<T>],
    dim: usize,
    q: &dyn Fn(&[T]) -> Point<T>,
) -> Point<T> {
    debug_assert_eq!(args.len(), n);
    if n == 0 {
        return q(&vec![T::zero(); dim]);
    }
    let groups = group(args);
    let mult: Vec<usize> = groups.iter().map(|g| g.1).collect();
    let mut fact = BigInt::one();
    for k in 2..=n {
        fact *= BigInt::from(k);
    }
    let mut acc: Option<Point<T>> = None;
    for_each_sub_multiset(&mult, &mut |counts| {
        let size: usize = counts.iter().sum();
        // Multiplicity of this sub-multiset among the subsets, times the weight of (19).
        let mut weight = BigInt::from(size).pow(n as u32);
        for (&k, &m) in counts.iter().zip(&mult) {
            weight *= binomial(m as i64, k as i64);
        }
        if (n - size) % 2 == 1 {
            weight = -weight;
        }
        // Built once and converted once, then used on every coordinate of the sample (a
        // weight of about n log2(n) bits: its reduction is the dearest step of a term).
        let weight = T::from_rational(&Rational::new(weight, fact.clone()));
        // The average (sum_r k_r x_r) / size.
        let inv = Rational::new(BigInt::one(), BigInt::from(size));
        let mut avg = vec![T::zero(); groups[0].0.len()];
        for ((x, _), &k) in groups.iter().zip(counts) {
            if k > 0 {
                let kk = Rational::from_integer(BigInt::from(k)) * &inv;
                point::add_scaled_rational(&mut avg, &kk, x);
            }
        }
        let value = q(&avg);
        let acc = acc.get_or_insert_with(|| point::zero(value.len()));
        point::add_scaled(acc, &weight, &value);
    });
    acc.expect("n >= 1 gives at least one term")
}

/// The blossom b[t_1..t_n] of the curve `b` of degree `n = args.len()`, eq. (20).
///
/// ```
/// use blossom::curve_blossom_from_samples as curve_blossom;
/// use blossom::{Rational, Ring};
/// // b(t) = t^2 has the blossom t_1 t_2.
/// let square = |t: &Rational| vec![t.mul(t)];
/// let q = |n: i64| Rational::from_integer(n.into());
/// assert_eq!(curve_blossom(2, &[q(3), q(5)], &square)?, vec![q(15)]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn curve_blossom_from_samples<T: Ring>(
    degree: usize,
    args: &[T],
    b: &dyn Fn(&T) -> Point<T>,
) -> Result<Point<T>> {
    check_arity("args", args.len(), degree)?;
    let pts: Vec<Point<T>> = args.iter().map(|x| vec![x.clone()]).collect();
    Ok(polar_form_unchecked(degree, &pts, 1, &|u| b(&u[0])))
}

/// The control points b_i = b[alpha^(n-i), beta^i], i = 0..n, of the curve `b` on
/// [alpha, beta] at degree `n`, Corollary 2, eq. (22).
pub fn curve_control_points_from_samples<T: Ring>(
    degree: usize,
    alpha: &T,
    beta: &T,
    b: &dyn Fn(&T) -> Point<T>,
) -> Vec<Point<T>> {
    (0..=degree)
        .map(|i| {
            let args: Vec<Point<T>> =
                repeated(&vec![alpha.clone()], degree - i, &vec![beta.clone()], i);
            polar_form_unchecked(degree, &args, 1, &|u| b(&u[0]))
        })
        .collect()
}

/// The blossom b[u_1..u_n; v_1..v_m] of the surface `s(u, v)` of bidegree `(n, m)`, in two
/// passes of eq. (20): for each u the inner pass polarises v, and the result, a function of
/// degree n in u, is polarised by the outer pass.
pub fn tensor_blossom_from_samples<T: Ring>(
    degree: (usize, usize),
    us: &[T],
    vs: &[T],
    s: &dyn Fn(&T, &T) -> Point<T>,
) -> Result<Point<T>> {
    check_arity("us", us.len(), degree.0)?;
    check_arity("vs", vs.len(), degree.1)?;
    Ok(tensor_blossom_unchecked(degree, us, vs, s))
}

fn tensor_blossom_unchecked<T: Ring>(
    (n, m): (usize, usize),
    us: &[T],
    vs: &[T],
    s: &dyn Fn(&T, &T) -> Point<T>,
) -> Point<T> {
    let ups: Vec<Point<T>> = us.iter().map(|x| vec![x.clone()]).collect();
    let vps: Vec<Point<T>> = vs.iter().map(|x| vec![x.clone()]).collect();
    let inner = |u: &[T]| polar_form_unchecked(m, &vps, 1, &|v| s(&u[0], &v[0]));
    polar_form_unchecked(n, &ups, 1, &inner)
}

/// The control net `[nu][mu]` = b[a^(n-nu) b^nu; c^(m-mu) d^mu] of the surface `s` on
/// `rect = [a, b, c, d]`, i.e. [a, b] x [c, d], at bidegree `(n, m)`: eq. (22) in two passes.
pub fn tensor_control_points_from_samples<T: Ring>(
    degree: (usize, usize),
    rect: &[T; 4],
    s: &dyn Fn(&T, &T) -> Point<T>,
) -> Vec<Vec<Point<T>>> {
    tensor_net(degree, rect, |us, vs| {
        tensor_blossom_unchecked(degree, us, vs, s)
    })
}

/// The blossom b[x_1..x_N] of the surface `s(u, v)` as a triangular patch of total degree
/// `N = args.len()`, at points x_k = (u_k, v_k) of the parametric plane, eq. (21).
///
/// The formula only takes averages of the arguments, which are affine combinations, so
/// Cartesian coordinates serve as well as the paper's barycentric ones.
pub fn triangle_blossom_from_samples<T: Ring>(
    degree: usize,
    args: &[[T; 2]],
    s: &dyn Fn(&T, &T) -> Point<T>,
) -> Result<Point<T>> {
    check_arity("args", args.len(), degree)?;
    let pts: Vec<Point<T>> = args.iter().map(|p| p.to_vec()).collect();
    Ok(polar_form_unchecked(degree, &pts, 2, &|x| s(&x[0], &x[1])))
}

/// The control points b_ijk = b[a^i, b^j, c^k], i + j + k = N, of the surface `s` on the
/// triangle with corners `tri = [a, b, c]` at total degree `N`, Corollary 3, eq. (23); listed
/// in lexicographic order of `(i, j)` like [`crate::TriangularPatch`].
pub fn triangle_control_points_from_samples<T: Ring>(
    degree: usize,
    tri: &[[T; 2]; 3],
    s: &dyn Fn(&T, &T) -> Point<T>,
) -> Vec<Point<T>> {
    let corners: [Point<T>; 3] = tri.each_ref().map(|p| p.to_vec());
    triangle_net(degree, &corners, |args| {
        polar_form_unchecked(degree, args, 2, &|x| s(&x[0], &x[1]))
    })
}

/// Control points w_v = b[b^v, a^(n-v)] of `curve` on [a, b], eq. (22) of 004, sampling only
/// points of the curve.
pub(crate) fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let points = curve_control_points_from_samples(curve.degree(), a, b, &|u| curve.eval(u));
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

/// Control points of `surface` on `rect = [a, b, c, d]` by two passes of eq. (22).
pub(crate) fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let points =
        tensor_control_points_from_samples(surface.degree(), rect, &|u, v| surface.eval(u, v));
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b[a^nu, b^mu, c^lambda] of `surface` (total degree
/// N = n + m) on `tri`, eq. (23).
pub(crate) fn restrict_triangle<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let big_n = surface.degree();
    let points = triangle_control_points_from_samples(big_n, tri, &|u, v| surface.eval(u, v));
    TriangularPatch::new(big_n, points).expect("a full triangular net")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn argument_counts_are_checked() {
        let b = |t: &Rational| vec![t.clone()];
        let e = curve_blossom_from_samples(2, &[q(1, 1)], &b).unwrap_err();
        assert_eq!(
            e.to_string(),
            "args: a blossom of degree 2 takes 2 arguments, found 1"
        );
        let s = |u: &Rational, v: &Rational| vec![u.mul(v)];
        assert_eq!(
            tensor_blossom_from_samples((1, 1), &[q(1, 1)], &[], &s)
                .unwrap_err()
                .field,
            "vs"
        );
    }

    #[test]
    fn cubic_control_points_of_a_cubic() {
        // t^3 on [1, 2]: b[1^(3-i), 2^i] = 2^i.
        let cube = |t: &Rational| vec![t.pow(3)];
        let w = curve_control_points_from_samples(3, &q(1, 1), &q(2, 1), &cube);
        assert_eq!(
            w,
            vec![vec![q(1, 1)], vec![q(2, 1)], vec![q(4, 1)], vec![q(8, 1)]]
        );
    }

    #[test]
    fn tensor_and_triangle_of_uv() {
        // s(u, v) = u v: tensor blossom at (u1; v1) is u1 v1; triangle blossom of degree 2 at
        // (x1, x2) is (u1 v2 + u2 v1) / 2.
        let s = |u: &Rational, v: &Rational| vec![u.mul(v)];
        assert_eq!(
            tensor_blossom_from_samples((1, 1), &[q(3, 1)], &[q(5, 1)], &s).unwrap(),
            vec![q(15, 1)]
        );
        let x = [[q(1, 1), q(2, 1)], [q(3, 1), q(4, 1)]];
        assert_eq!(
            triangle_blossom_from_samples(2, &x, &s).unwrap(),
            vec![q(5, 1)]
        );
        let net =
            tensor_control_points_from_samples((1, 1), &[q(0, 1), q(1, 1), q(0, 1), q(2, 1)], &s);
        assert_eq!(net[1][1], vec![q(2, 1)]);
        let tri = [[q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], [q(0, 1), q(0, 1)]];
        let pts = triangle_control_points_from_samples(2, &tri, &s);
        // Only b[a, b] = 1/2 is non-zero (index (1, 1) in lexicographic order is 4).
        assert_eq!(pts[4], vec![q(1, 2)]);
        assert_eq!(pts.iter().filter(|p| p[0] != q(0, 1)).count(), 1);
    }
}
