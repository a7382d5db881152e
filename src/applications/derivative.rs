//! Derivatives of curves and patches as Bézier objects of lower degree, through the blossom
//! with vector arguments.
//!
//! The blossom f of a form of degree n, extended to homogeneous arguments (points of weight 1,
//! vectors of weight 0, see [`crate::engine::BernsteinVectorStep`]), gives every derivative:
//!
//! * curve: d^k C / du^k (u) = n! / (n - k)! f(u^(n-k), delta^k), delta the unit vector of the
//!   parameter line; at u = 0 for a Bézier curve over [0, 1] this is eq. (10) of seed 004,
//!   n! / (n - k)! Delta^k b_0. The k-th derivative on [a, b] is the Bézier curve of degree
//!   n - k with control points n! / (n - k)! f(a^(n-k-j), b^j, delta^k), j = 0..=n - k (the
//!   restriction, eq. (1) of the subdivision paper, of the form f(·, delta^k));
//! * tensor patch (blossom eq. (9) of 004): d^(k+l) S / du^k dv^l has the control points
//!   n! / (n - k)! m! / (m - l)! f(a^(n-k-nu), b^nu, delta^k; c^(m-l-mu), d^mu, delta^l);
//! * triangle of total degree N: the k-th directional derivative D_(d_1) ... D_(d_k) S, with
//!   D_d S(x) = d/dh S(x + h d) at h = 0, has the control points
//!   N! / (N - k)! f(A^nu, B^mu, C^lambda, d_1, ..., d_k), nu + mu + lambda = N - k, on the
//!   triangle ABC (eq. (12) of the subdivision paper for the form f(·, d_1, ..., d_k)).
//!
//! The blossom is symmetric, so the vector arguments are fixed first, by k steps of weight 0
//! on the form as it is written (Bernstein: forward differences; scaled power basis: shifts
//! d_i -> d_(i+1); triangles: the directions' steps), which leaves a form of degree n - k;
//! for power input that form is then restricted by the engine ([`crate::engine::curve_net`],
//! [`crate::engine::tensor_net`], [`crate::engine::triangle_net`]) with the ordinary point steps, exactly as
//! [`crate::Method::Bulk`] restricts. Bézier input stays over its own domain, so the form left
//! after the vector steps already is the answer. Everything is ring arithmetic plus the exact
//! constants n! / (n - k)! (and 1 / C(n, i) of the scaled power basis), so the same code runs
//! on f64, rationals and symbolic polynomials.

use crate::error::{Error, ErrorKind, Result};
use crate::restrict::halving::{scaled_curve, scaled_tensor, scaled_triangle};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::halving::{
    curve_fix_in_place, curve_net, tensor_net, triangle_fix_in_place, triangle_net,
    BernsteinPairVectorStep, BernsteinVectorStep, CurveStep, PowerPairStep, PowerPairVectorStep,
    PowerStep, PowerVectorStep,
};
use crate::shape::point::Point;
use crate::shape::power::{PowerCurve, PowerSurface};
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::triangle_len;
use crate::{Rational, Ring};
use num_bigint::BigInt;

/// n! / (n - k)!, exactly (k <= n).
fn falling_factorial(n: usize, k: usize) -> Rational {
    let product: BigInt = (n - k + 1..=n).map(BigInt::from).product();
    Rational::from_integer(product)
}

/// Refuses a derivative of order `order` above `degree`, naming `field`.
fn check_order(order: usize, degree: usize, field: &str) -> Result<()> {
    if order > degree {
        return Err(Error::of(
            ErrorKind::Degree,
            field,
            format!("a derivative of order {order} of a form of degree {degree}"),
        ));
    }
    Ok(())
}

/// `level` (points of `dim` numbers) with `count` arguments `step` fixed.
fn fix_curve<T: Ring, S: CurveStep<T> + Clone>(
    mut level: Vec<T>,
    dim: usize,
    step: S,
    count: usize,
) -> Vec<T> {
    let len = curve_fix_in_place(&mut level, dim, &vec![step; count]);
    level.truncate(len);
    level
}

/// The tensor form `level` (rows of `cols` points of `dim` numbers) with `k` arguments `step`
/// fixed along u (whole rows as points) and `l` along v (in every row): rows of `cols - l`
/// points.
fn fix_tensor<T: Ring, S: CurveStep<T> + Clone>(
    level: Vec<T>,
    cols: usize,
    dim: usize,
    step: S,
    [k, l]: [usize; 2],
) -> Vec<T> {
    let mut level = fix_curve(level, cols * dim, step.clone(), k);
    let along_v = vec![step; l];
    let mut out = Vec::with_capacity(level.len() / cols * (cols - l));
    for row in level.chunks_mut(cols * dim) {
        let len = curve_fix_in_place(row, dim, &along_v);
        out.extend_from_slice(&row[..len]);
    }
    out
}

/// Every number of `flat` times the exact constant `k`.
fn scale_all<T: Ring>(flat: &mut [T], k: &Rational) {
    let k = T::from_rational(k);
    for x in flat {
        *x = x.mul(&k);
    }
}

/// The k-th derivative (`order` = k) of the Bézier curve `curve` over [0, 1], as the Bézier
/// curve of degree n - k over [0, 1] (the hodograph for k = 1; the curve itself for k = 0).
///
/// Its control points are the forward-difference identity (eq. (10) of seed 004 at every
/// control point):
///
/// d^k b / dt^k (t) = n! / (n - k)! sum_(i=0..=n-k) Delta^k b_i B_i^(n-k)(t),
/// Delta^1 b_i = b_(i+1) - b_i, Delta^k b_i = Delta^(k-1) b_(i+1) - Delta^(k-1) b_i,
///
/// i.e. n! / (n - k)! b[0^(n-k-i), 1^i, delta^k] with delta the unit vector: k vector steps
/// ([`crate::engine::BernsteinVectorStep`]) on the control points, O(nk) subtractions per coordinate.
///
/// ```
/// use blossom::{bezier_derivative, BezierCurve};
/// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 3.0], vec![4.0, 0.0]])?;
/// let hodograph = bezier_derivative(&c, 1)?;
/// // 3 (b_(i+1) - b_i)
/// assert_eq!(hodograph.control_points(), &[vec![3.0, 6.0], vec![6.0, 3.0], vec![3.0, -9.0]]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// `order` ([`ErrorKind::Degree`]) when k exceeds the degree n.
pub fn bezier_derivative<T: Ring>(curve: &BezierCurve<T>, order: usize) -> Result<BezierCurve<T>> {
    let n = curve.degree();
    check_order(order, n, "order")?;
    let dim = curve.dim();
    let one = T::one();
    let mut flat = fix_curve(
        curve.coordinates().to_vec(),
        dim,
        BernsteinVectorStep(&one),
        order,
    );
    scale_all(&mut flat, &falling_factorial(n, order));
    BezierCurve::from_coordinates(dim, flat)
}

/// The k-th derivative (`order` = k) of the power curve `curve` on [a, b], as the Bézier curve
/// of degree n - k over [a, b]: control points n! / (n - k)! f(a^(n-k-j), b^j, delta^k), the
/// k shifts of the scaled power coefficients ([`crate::engine::PowerVectorStep`]) restricted by the
/// engine. The derivative is with respect to the curve's own parameter u.
///
/// # Errors
/// `order` ([`ErrorKind::Degree`]) when k exceeds the degree n.
pub fn power_curve_derivative<T: Ring>(
    curve: &PowerCurve<T>,
    order: usize,
    a: &T,
    b: &T,
) -> Result<BezierCurve<T>> {
    let n = curve.degree();
    check_order(order, n, "order")?;
    let dim = curve.dim();
    let one = T::one();
    let level = fix_curve(scaled_curve(curve), dim, PowerVectorStep(&one), order);
    let mut out = vec![T::zero(); level.len()];
    let (a, b) = (PowerStep(a), PowerStep(b));
    T::with_scratch(|scratch| curve_net(&level, dim, &a, &b, &mut out, scratch));
    scale_all(&mut out, &falling_factorial(n, order));
    BezierCurve::from_coordinates(dim, out)
}

/// The partial derivative d^(k+l) S / du^k dv^l (`order` = [k, l]) of the tensor patch
/// `patch` over [0, 1]^2, as the tensor patch of bidegree (n - k, m - l) over [0, 1]^2:
/// control points n! / (n - k)! m! / (m - l)! Delta_u^k Delta_v^l p_(nu mu), the vector steps
/// along u with whole rows as points, then along v in every row.
///
/// # Errors
/// `order[0]` or `order[1]` ([`ErrorKind::Degree`]) when k exceeds n or l exceeds m.
pub fn bezier_tensor_derivative<T: Ring>(
    patch: &TensorPatch<T>,
    order: [usize; 2],
) -> Result<TensorPatch<T>> {
    let (n, m) = patch.degree();
    check_order(order[0], n, "order[0]")?;
    check_order(order[1], m, "order[1]")?;
    let dim = patch.dim();
    let flat: Vec<T> = patch.coordinates().to_vec();
    let one = T::one();
    let mut flat = fix_tensor(flat, m + 1, dim, BernsteinVectorStep(&one), order);
    let k = falling_factorial(n, order[0]) * falling_factorial(m, order[1]);
    scale_all(&mut flat, &k);
    TensorPatch::from_coordinates((n - order[0], m - order[1]), dim, flat)
}

/// The partial derivative d^(k+l) S / du^k dv^l (`order` = [k, l]) of the power surface
/// `surface` on `rect = [a, b, c, d]`, i.e. [a, b] x [c, d], as the tensor patch of bidegree
/// (n - k, m - l) over that rectangle: control points
/// n! / (n - k)! m! / (m - l)! f(a^(n-k-nu), b^nu, delta^k; c^(m-l-mu), d^mu, delta^l).
///
/// # Errors
/// `order[0]` or `order[1]` ([`ErrorKind::Degree`]) when k exceeds n or l exceeds m.
pub fn power_tensor_derivative<T: Ring>(
    surface: &PowerSurface<T>,
    order: [usize; 2],
    rect: &[T; 4],
) -> Result<TensorPatch<T>> {
    let (n, m) = surface.degree();
    check_order(order[0], n, "order[0]")?;
    check_order(order[1], m, "order[1]")?;
    let dim = surface.dim();
    let one = T::one();
    let level = fix_tensor(
        scaled_tensor(surface),
        m + 1,
        dim,
        PowerVectorStep(&one),
        order,
    );
    let cols = m + 1 - order[1];
    let mut out = vec![T::zero(); level.len()];
    let steps = rect.each_ref().map(PowerStep);
    T::with_scratch(|scratch| tensor_net(&level, cols, dim, steps.each_ref(), &mut out, scratch));
    let k = falling_factorial(n, order[0]) * falling_factorial(m, order[1]);
    scale_all(&mut out, &k);
    TensorPatch::from_coordinates((n - order[0], cols - 1), dim, out)
}

/// The directional derivative D_(d_1) ... D_(d_k) of the triangular patch `patch` (degree N),
/// `directions` = [d_1, ..., d_k], each a barycentric direction (three coordinates w.r.t. the
/// patch's corners, in the order of the net's indices, adding up to 0), as the triangular
/// patch of degree N - k over the same triangle: control points
/// N! / (N - k)! b[A^nu, B^mu, C^lambda, d_1, ..., d_k] (k vector steps
/// [`crate::engine::BernsteinPairVectorStep`] on the net). No directions: the patch itself.
///
/// # Errors
/// `directions` ([`ErrorKind::Degree`]) when k exceeds N; `directions[i]`
/// ([`ErrorKind::Domain`]) when d_i does not have three coordinates or they do not add up to
/// 0 ([`Ring::is_zero`] of the sum: exact under exact arithmetic, a sum that rounds to exactly
/// 0 under f64).
pub fn bezier_triangle_derivative<T: Ring>(
    patch: &TriangularPatch<T>,
    directions: &[Point<T>],
) -> Result<TriangularPatch<T>> {
    let big_n = patch.degree();
    check_order(directions.len(), big_n, "directions")?;
    let mut pairs = Vec::with_capacity(directions.len());
    for (i, d) in directions.iter().enumerate() {
        let [s, t, r] = d.as_slice() else {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("directions[{i}]"),
                format!(
                    "a barycentric direction has 3 coordinates, found {}",
                    d.len()
                ),
            ));
        };
        if !s.add(t).add(r).is_zero() {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("directions[{i}]"),
                "the coordinates of a barycentric direction must add up to 0",
            ));
        }
        pairs.push([s.clone(), t.clone()]);
    }
    let steps: Vec<_> = pairs.iter().map(BernsteinPairVectorStep).collect();
    let dim = patch.dim();
    let mut flat = patch.coordinates().to_vec();
    let degree = triangle_fix_in_place(&mut flat, big_n, dim, &steps);
    flat.truncate(triangle_len(degree) * dim);
    scale_all(&mut flat, &falling_factorial(big_n, directions.len()));
    TriangularPatch::from_coordinates(degree, dim, flat)
}

/// The directional derivative D_(d_1) ... D_(d_k) of the power surface `surface` (of total
/// degree N: a triangular array, or a grid taken at N = n + m by [`PowerTriangle::from_surface`]), `directions` = [d_1, ..., d_k] each a vector (du, dv) of
/// the (u, v) plane, as the triangular patch of degree N - k on the triangle `tri`: control
/// points N! / (N - k)! f(A^nu, B^mu, C^lambda, d_1, ..., d_k), the vector steps
/// ([`crate::engine::PowerPairVectorStep`]) on the scaled power coefficients, then the engine's
/// restriction to `tri`.
///
/// # Errors
/// `directions` ([`ErrorKind::Degree`]) when k exceeds N; `directions[i]`
/// ([`ErrorKind::Domain`]) when d_i does not have two coordinates.
pub fn power_triangle_derivative<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
    directions: &[Point<T>],
) -> Result<TriangularPatch<T>> {
    let big_n = surface.degree();
    check_order(directions.len(), big_n, "directions")?;
    let mut pairs = Vec::with_capacity(directions.len());
    for (i, d) in directions.iter().enumerate() {
        let [du, dv] = d.as_slice() else {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("directions[{i}]"),
                format!(
                    "a direction of the (u, v) plane has 2 coordinates, found {}",
                    d.len()
                ),
            ));
        };
        pairs.push([du.clone(), dv.clone()]);
    }
    let steps: Vec<_> = pairs.iter().map(PowerPairVectorStep).collect();
    let dim = surface.dim();
    let mut level = scaled_triangle(surface);
    let degree = triangle_fix_in_place(&mut level, big_n, dim, &steps);
    level.truncate(triangle_len(degree) * dim);
    let mut out = vec![T::zero(); level.len()];
    let corners = tri.each_ref().map(PowerPairStep);
    T::with_scratch(|scratch| {
        triangle_net(&level, degree, dim, corners.each_ref(), &mut out, scratch)
    });
    scale_all(&mut out, &falling_factorial(big_n, directions.len()));
    TriangularPatch::from_coordinates(degree, dim, out)
}
