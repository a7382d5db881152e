//! The inverse (polarisation) formula of seed 004, which gets the blossom from points of the
//! curve or surface alone.
//!
//! Theorem 2 / eq. (19), with its instances (20) (curves) and (21) (triangles):
//!
//! f(x_1..x_n) = 1/n! sum_{N=1..n} (-1)^(n-N) N^n sum_{i_1 < ... < i_N} q((x_i1 + ... + x_iN) / N)
//!
//! where q(x) = f(x, ..., x) is the curve or surface itself. Tensor patches are done in two
//! passes (`b[u; v] = b[u][v]`): the inner pass polarises v for a fixed u, which is again a
//! polynomial of degree n in u, and the outer pass polarises that.
//!
//! When arguments repeat, as they do at every control point (a^nu b^mu c^lambda), the subsets
//! are grouped by how many copies of each distinct argument they hold: a subset taking k_r of
//! the m_r copies of x_r occurs prod_r C(m_r, k_r) times (this is eq. (22) of 004 for curves
//! and (23) for triangles). Grouping changes the count of evaluations of q, from 2^n - 1 to
//! prod_r (m_r + 1) - 1, not the formula.

use crate::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::binomial::binomial;
use crate::blossoms::{repeated, tensor_net, triangle_net};
use crate::point::{self, Point};
use crate::power::{PowerCurve, PowerSurface};
use crate::{Rational, Ring};
use num_bigint::BigInt;
use num_traits::{One, Signed};

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
pub fn polar_form<T: Ring>(
    n: usize,
    args: &[Point<T>],
    dim: usize,
    q: &dyn Fn(&[T]) -> Point<T>,
) -> Point<T> {
    assert_eq!(args.len(), n, "a polar form of degree n takes n arguments");
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
        let weight = Rational::new(weight, fact.clone());
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
        match acc.as_mut() {
            Some(acc) => point::add_scaled_rational(acc, &weight, &value),
            None => acc = Some(point::scaled_rational(&value, &weight)),
        }
        debug_assert!(!weight.is_negative() || (n - size) % 2 == 1);
    });
    acc.expect("n >= 1 gives at least one term")
}

/// The blossom of `curve` at `args`, eq. (20), sampling only points of the curve.
pub fn curve_blossom<T: Ring>(curve: &PowerCurve<T>, args: &[T]) -> Point<T> {
    let pts: Vec<Point<T>> = args.iter().map(|x| vec![x.clone()]).collect();
    polar_form(curve.degree(), &pts, 1, &|u| curve.eval(&u[0]))
}

/// The blossom of `surface` at `(us; vs)` in two passes of eq. (20).
pub fn tensor_blossom<T: Ring>(surface: &PowerSurface<T>, us: &[T], vs: &[T]) -> Point<T> {
    let (n, m) = surface.degree();
    let ups: Vec<Point<T>> = us.iter().map(|x| vec![x.clone()]).collect();
    let vps: Vec<Point<T>> = vs.iter().map(|x| vec![x.clone()]).collect();
    let inner = |u: &[T]| polar_form(m, &vps, 1, &|v| surface.eval(&u[0], &v[0]));
    polar_form(n, &ups, 1, &inner)
}

/// The blossom of `surface` (total degree N = n + m) at points `(u_k, v_k)` of the plane,
/// eq. (21) (affine combinations of the points, so Cartesian coordinates serve as well as
/// barycentric ones).
pub fn triangle_blossom<T: Ring>(surface: &PowerSurface<T>, args: &[[T; 2]]) -> Point<T> {
    let (n, m) = surface.degree();
    let pts: Vec<Point<T>> = args.iter().map(|p| p.to_vec()).collect();
    polar_form(n + m, &pts, 2, &|x| surface.eval(&x[0], &x[1]))
}

/// Control points w_v = b[b^v, a^(n-v)] of `curve` on [a, b], eq. (22) of 004.
pub fn restrict_curve<T: Ring>(curve: &PowerCurve<T>, a: &T, b: &T) -> BezierCurve<T> {
    let n = curve.degree();
    let points = (0..=n)
        .map(|v| curve_blossom(curve, &repeated(b, v, a, n - v)))
        .collect();
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

/// Control points of `surface` on `rect = [a, b, c, d]` by two passes of eq. (22).
pub fn restrict_tensor<T: Ring>(surface: &PowerSurface<T>, rect: &[T; 4]) -> TensorPatch<T> {
    let points = tensor_net(surface.degree(), rect, |us, vs| {
        tensor_blossom(surface, us, vs)
    });
    TensorPatch::new(points).expect("a rectangular net")
}

/// Control points q_{nu mu lambda} = b[a^nu, b^mu, c^lambda] of `surface` on `tri`, eq. (23).
pub fn restrict_triangle<T: Ring>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (n, m) = surface.degree();
    let big_n = n + m;
    let points = triangle_net(big_n, tri, |args| triangle_blossom(surface, args));
    TriangularPatch::new(big_n, points).expect("a full triangular net")
}
