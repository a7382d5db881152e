//! Changes of polynomial basis and of variable, all division-free (ring operations and exact
//! rational constants only), so that they run on floats, rationals and symbolic polynomials.
//!
//! Every algorithm runs on flat coordinates: points of `dim` coordinates one after another, as
//! the shapes store them. A stride larger than a point's dimension treats a run of points as
//! one long point (a whole row of a grid), which is how a pass along one variable of a surface
//! runs through the curve algorithm with no copy.
//!
//! * [`taylor_shift_flat`]: coefficients of C(u + a) from those of C(u), O(n^2);
//! * [`scale_argument_flat`]: coefficients of C(h u), O(n);
//! * [`power_to_bernstein_flat`]: power coefficients over [0, 1] to Bézier control points,
//!   O(n^2): u^i = sum_{v >= i} C(v, i) / C(n, i) B_v^n(u);
//! * [`triangle_power_to_bernstein`]: power coefficients in barycentric coordinates (s, t) to
//!   the control net of a triangular patch, O(N^3):
//!   s^i t^j = sum_{nu >= i, mu >= j} C(nu, i) C(mu, j) / (N! / (i! j! (N-i-j)!)) B_{nu mu}^N;
//! * [`bernstein_by_horner`]: power coefficients to the Bézier control points over any interval
//!   [r, s], by Horner's rule carried out in the Bernstein basis (module section below); O(n^2);
//! * [`triangle_bernstein_by_horner`]: the same for a surface on any triangle, O(N^4).
//! * [`bernstein_to_power_flat`]: the inverse of [`power_to_bernstein_flat`] by forward
//!   differences, c_k = C(n, k) Δ^k b_0, O(n^2); [`tensor_bernstein_to_power`] the same along
//!   both variables of a tensor patch;
//! * [`triangle_bernstein_to_power`]: the inverse of [`triangle_power_to_bernstein`],
//!   c_ij = N! / (i! j! (N-i-j)!) Δ_1^i Δ_2^j b_(0,0,N), O(N^3).
//!
//! [`taylor_shift`], [`scale_argument`], [`power_to_bernstein`] and [`bernstein_to_power`] are
//! the same algorithms on nested points (`&[Vec<T>]`), for callers that hold them: each copies
//! into one flat run, runs the flat form and copies back.

use crate::error::Result;
use crate::num::binomial::multinomial;
use crate::shape::bezier::{triangle_points, TensorPatch, TriangularPatch};
use crate::shape::point::{add_assign, add_scaled, Point};
use crate::shape::power::PowerSurface;
use crate::shape::power_triangle::PowerTriangle;
use crate::shape::simplex::{triangle_index, triangle_len};
use crate::{Rational, Ring};

fn scale_point<T: Ring>(p: &mut [T], k: &T) {
    for x in p.iter_mut() {
        *x = x.mul(k);
    }
}

/// Multiplies `p` by the constant `k`, converted to `T` once for all coordinates.
fn scale_point_rational<T: Ring>(p: &mut [T], k: &Rational) {
    scale_point(p, &T::from_rational(k));
}

/// Runs `f` on the coordinates of `points` copied into one flat run (stride: the first point's
/// dimension), then copies them back: the nested forms of the flat algorithms. Nothing runs on
/// an empty list or points without coordinates.
fn on_flat<T: Clone>(points: &mut [Point<T>], f: impl FnOnce(&mut [T], usize)) {
    let dim = points.first().map_or(0, Vec::len);
    if dim == 0 {
        return;
    }
    let mut flat = points.concat();
    f(&mut flat, dim);
    let mut values = flat.into_iter();
    for (x, y) in points.iter_mut().flatten().zip(&mut values) {
        *x = y;
    }
}

/// The number of whole points of `stride` coordinates in `c` (0 for a stride of 0).
fn count(c: &[impl Sized], stride: usize) -> usize {
    c.len().checked_div(stride).unwrap_or(0)
}

/// Replaces the coefficients of C(u) = sum c_i u^i (flat, `stride` coordinates each) by those
/// of C(u + a), in place, by repeated synthetic division (n(n+1)/2 multiply-adds per
/// coordinate).
pub fn taylor_shift_flat<T: Ring>(c: &mut [T], stride: usize, a: &T) {
    let n = count(c, stride).saturating_sub(1);
    for k in 0..n {
        for i in (k..n).rev() {
            let (lo, hi) = c.split_at_mut((i + 1) * stride);
            for (x, y) in lo[i * stride..].iter_mut().zip(&hi[..stride]) {
                x.add_assign(&a.mul(y));
            }
        }
    }
}

/// [`taylor_shift_flat`] on nested points.
pub fn taylor_shift<T: Ring>(c: &mut [Point<T>], a: &T) {
    on_flat(c, |flat, dim| taylor_shift_flat(flat, dim, a));
}

/// Replaces the coefficients of C(u) (flat, `stride` coordinates each) by those of C(h u):
/// c_i becomes h^i c_i.
pub fn scale_argument_flat<T: Ring>(c: &mut [T], stride: usize, h: &T) {
    if stride == 0 {
        return;
    }
    let mut power = T::one();
    for ci in c.chunks_exact_mut(stride).skip(1) {
        power = power.mul(h);
        scale_point(ci, &power);
    }
}

/// [`scale_argument_flat`] on nested points.
pub fn scale_argument<T: Ring>(c: &mut [Point<T>], h: &T) {
    on_flat(c, |flat, dim| scale_argument_flat(flat, dim, h));
}

/// The binomial transform w_v = sum_{i <= v} C(v, i) e_i of the points `e` (flat, `stride`
/// coordinates each), in place, with additions only (the Newton forward-difference table read
/// backwards).
fn binomial_transform<T: Ring>(e: &mut [T], stride: usize) {
    let n = count(e, stride).saturating_sub(1);
    for k in (0..n).rev() {
        for i in k..n {
            let (lo, hi) = e.split_at_mut((i + 1) * stride);
            add_assign(&mut hi[..stride], &lo[i * stride..]);
        }
    }
}

/// Replaces the power coefficients `d` (flat, `stride` coordinates each) of a polynomial by its
/// Bézier control points over [0, 1], in place: w_v = sum_{i <= v} C(v, i) / C(n, i) d_i.
pub fn power_to_bernstein_flat<T: Ring>(d: &mut [T], stride: usize) {
    scale_by_binomials(d, stride, Binomials::Divide);
    binomial_transform(d, stride);
}

/// [`power_to_bernstein_flat`] on nested points, into new ones.
pub fn power_to_bernstein<T: Ring>(d: &[Point<T>]) -> Vec<Point<T>> {
    let mut e = d.to_vec();
    on_flat(&mut e, power_to_bernstein_flat);
    e
}

/// Whether [`scale_by_binomials`] multiplies or divides.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Binomials {
    Multiply,
    Divide,
}

/// Multiplies (or divides) each point c_i of `c` (flat, `stride` coordinates each) by
/// C(n, i), n + 1 the number of points.
///
/// The row is built by C(n, i) = C(n, i - 1) (n - i + 1) / i: in `i128` while the product
/// fits (each constant then reaches the ring once, through [`Ring::scale_frac`]), and past that
/// (n above about 125) in the ring itself, one `scale_frac` per step. Exact for rationals and
/// polynomials; for floats each constant is rounded once while it fits in `i128`, and after
/// that carries the rounding of its steps (a relative error below n times the unit roundoff).
/// No big-number arithmetic: it cost more than the restriction itself at small degrees.
fn scale_by_binomials<T: Ring>(c: &mut [T], stride: usize, how: Binomials) {
    if stride == 0 {
        return;
    }
    let n = count(c, stride).saturating_sub(1) as i128;
    // The factor of c[i]: C(n, i) or its inverse, as a ring constant.
    let factor = |k: i128| match how {
        Binomials::Multiply => T::one().scale_frac(k, 1),
        Binomials::Divide => T::one().scale_frac(1, k),
    };
    let mut row: Binomial<T> = Binomial::Small(1);
    for (i, ci) in c.chunks_exact_mut(stride).enumerate().skip(1) {
        let i = i as i128;
        // The step factor (n - i + 1) / i, or its inverse.
        let (num, den) = match how {
            Binomials::Multiply => (n - i + 1, i),
            Binomials::Divide => (i, n - i + 1),
        };
        row = match row {
            Binomial::Small(k) => match k.checked_mul(n - i + 1) {
                Some(m) => Binomial::Small(m / i),
                None => Binomial::Ring(factor(k).scale_frac(num, den)),
            },
            Binomial::Ring(k) => Binomial::Ring(k.scale_frac(num, den)),
        };
        match &row {
            Binomial::Small(1) => {}
            Binomial::Small(k) => scale_point(ci, &factor(*k)),
            Binomial::Ring(k) => scale_point(ci, k),
        }
    }
}

/// The running entry of a row of binomials: an integer while it fits, then a ring constant.
enum Binomial<T> {
    Small(i128),
    Ring(T),
}

/// The control net of the triangular patch of degree N whose power coefficients in the
/// barycentric coordinates (s, t) of corners a, b (the third, of c, being 1 - s - t) are
/// those of `surface`: c_ij is the coefficient of s^i t^j (a triangular array, or any rows
/// with i + j <= N, absent coefficients being zero).
///
/// Divides by the multinomials once, then applies the binomial transform along t for every
/// power of s and along s for every index of t: O(N^3) additions.
///
/// # Errors
/// [`ErrorKind::TooLarge`](crate::ErrorKind::TooLarge) on `degree` when the net's
/// (N + 1)(N + 2) / 2 points overflow or exceed [`MAX_ENTRIES`](crate::MAX_ENTRIES) (a grid
/// taken at a large total degree).
pub fn triangle_power_to_bernstein<T: Ring>(
    surface: &PowerTriangle<T>,
) -> Result<TriangularPatch<T>> {
    let (n, dim) = (surface.degree(), surface.dim());
    let mut d = vec![T::zero(); triangle_points(n, "degree")? * dim];
    for (i, j, c) in surface.terms() {
        let at = triangle_index(n, i, j) * dim;
        d[at..at + dim].clone_from_slice(c);
    }
    Ok(triangle_power_to_bernstein_flat(n, dim, d))
}

/// [`triangle_power_to_bernstein`] on the full array `d` (flat, `dim` coordinates per point,
/// d_ij at [`triangle_index(n, i, j)`](triangle_index)), transformed in place into the net.
pub(crate) fn triangle_power_to_bernstein_flat<T: Ring>(
    n: usize,
    dim: usize,
    mut d: Vec<T>,
) -> TriangularPatch<T> {
    debug_assert_eq!(d.len(), triangle_len(n) * dim);
    let ni = n as i64;
    // Row i becomes h[i][mu] = sum_{j <= mu} C(mu, j) e_ij for mu <= n - i.
    for i in 0..=n {
        let row = &mut d[triangle_index(n, i, 0) * dim..triangle_index(n, i, n - i) * dim + dim];
        for (j, e) in row.chunks_exact_mut(dim).enumerate() {
            let m = multinomial(ni, &[i as i64, j as i64]);
            if m != 1.into() {
                scale_point_rational(e, &Rational::new(1.into(), m));
            }
        }
        binomial_transform(row, dim);
    }
    // q[nu][mu] = sum_{i <= nu} C(nu, i) h[i][mu] for nu <= n - mu, column by column.
    let mut column = Vec::with_capacity((n + 1) * dim);
    for mu in 0..=n {
        column.clear();
        for i in 0..=n - mu {
            let at = triangle_index(n, i, mu) * dim;
            column.extend_from_slice(&d[at..at + dim]);
        }
        binomial_transform(&mut column, dim);
        for (nu, q) in column.chunks_exact(dim).enumerate() {
            let at = triangle_index(n, nu, mu) * dim;
            d[at..at + dim].clone_from_slice(q);
        }
    }
    TriangularPatch::from_raw(n, dim, d)
}

/// Replaces the points of `p` (flat, `stride` coordinates each) by their forward differences,
/// Δ^k p_0 at position k (n(n+1)/2 subtractions per coordinate): after pass k, entry i >= k
/// holds Δ^k p_(i-k), since Δ^k p_(i-k) = Δ^(k-1) p_(i-k+1) - Δ^(k-1) p_(i-k).
fn forward_differences<T: Ring>(p: &mut [T], stride: usize) {
    let len = count(p, stride);
    for k in 1..len {
        for i in (k..len).rev() {
            let (lo, hi) = p.split_at_mut(i * stride);
            for (x, y) in hi[..stride].iter_mut().zip(&lo[(i - 1) * stride..]) {
                *x = x.sub(y);
            }
        }
    }
}

/// Replaces the control points `b` (flat, `stride` coordinates each) of a Bézier curve over
/// [0, 1] by its power coefficients, in place (the inverse of [`power_to_bernstein_flat`]):
/// c_k = C(n, k) Δ^k b_0, the k-th forward difference scaled by a binomial. O(n^2)
/// subtractions and n scalings per coordinate.
pub fn bernstein_to_power_flat<T: Ring>(b: &mut [T], stride: usize) {
    forward_differences(b, stride);
    scale_by_binomials(b, stride, Binomials::Multiply);
}

/// [`bernstein_to_power_flat`] on nested points, into new ones.
pub fn bernstein_to_power<T: Ring>(b: &[Point<T>]) -> Vec<Point<T>> {
    let mut c = b.to_vec();
    on_flat(&mut c, bernstein_to_power_flat);
    c
}

/// The power form (coefficient c_ij of s^i t^j) of the tensor-product patch over [0, 1]^2 with
/// control points p_ij: c_ij = C(n, i) C(m, j) Δ_s^i Δ_t^j p_00, by
/// [`bernstein_to_power_flat`] along t for every row, then along s with whole rows as points.
pub fn tensor_bernstein_to_power<T: Ring>(patch: &TensorPatch<T>) -> PowerSurface<T> {
    let (_, m) = patch.degree();
    let dim = patch.dim();
    let width = (m + 1) * dim;
    let mut c = patch.coordinates().to_vec();
    for row in c.chunks_exact_mut(width) {
        bernstein_to_power_flat(row, dim);
    }
    bernstein_to_power_flat(&mut c, width);
    PowerSurface::from_raw(m + 1, dim, c)
}

/// The power form in the barycentric coordinates (s, t) of corners 1 and 2 (the third being
/// 1 - s - t) of the triangular patch `patch`, a triangular array of the patch's degree (the
/// inverse of [`triangle_power_to_bernstein`]): the coefficient of s^i t^j is
/// N! / (i! j! (N-i-j)!) Δ_1^i Δ_2^j b_(0,0,N), where Δ_1 b_(nu,mu) = b_(nu+1,mu) - b_(nu,mu)
/// and Δ_2 b_(nu,mu) = b_(nu,mu+1) - b_(nu,mu). O(N^3) subtractions.
pub fn triangle_bernstein_to_power<T: Ring>(patch: &TriangularPatch<T>) -> PowerTriangle<T> {
    let (n, dim) = (patch.degree(), patch.dim());
    let mut out = vec![T::zero(); triangle_len(n) * dim];
    // level, a triangular net of degree N - j: [nu][mu] = Δ_2^j b_(nu, mu), nu + mu <= N - j.
    let mut level = patch.coordinates().to_vec();
    let mut column = Vec::with_capacity((n + 1) * dim);
    for j in 0..=n {
        if j > 0 {
            // From degree N - j + 1 to N - j in place: entry (nu, mu) moves to an index no
            // greater than its own, and reads only entries not yet overwritten.
            let (from, to) = (n - j + 1, n - j);
            for nu in 0..=to {
                for mu in 0..=to - nu {
                    let (lo, at) = (
                        triangle_index(from, nu, mu) * dim,
                        triangle_index(to, nu, mu),
                    );
                    for x in 0..dim {
                        level[at * dim + x] = level[lo + dim + x].sub(&level[lo + x]);
                    }
                }
            }
            level.truncate(triangle_len(n - j) * dim);
        }
        column.clear();
        for nu in 0..=n - j {
            let at = triangle_index(n - j, nu, 0) * dim;
            column.extend_from_slice(&level[at..at + dim]);
        }
        forward_differences(&mut column, dim);
        for (i, d) in column.chunks_exact_mut(dim).enumerate() {
            let k = multinomial(n as i64, &[i as i64, j as i64]);
            if k != 1.into() {
                scale_point_rational(d, &Rational::from_integer(k));
            }
            let at = triangle_index(n, i, j) * dim;
            out[at..at + dim].clone_from_slice(d);
        }
    }
    PowerTriangle::triangular(n, dim, out)
}

// Horner's rule in the Bernstein basis. The variable u on [r, s] is the linear Bézier curve
// with control points r, s; a product of a degree-d Bézier form p with a linear form with
// control values (l_0, l_1) is the degree-(d + 1) form
//   q_j = (d + 1 - j)/(d + 1) l_0 p_j + j/(d + 1) l_1 p_(j-1),
// and a constant has every control point equal to itself at any degree. Horner's rule
// P <- u P + c_k (k = n-1..0) therefore builds the Bernstein form over [r, s] with ring
// operations and rational constants only, and without going through a Taylor shift: this is
// the basis change of the pyramid, kept independent of the Taylor shift and of the engine. On a triangle the
// linear forms u, v have the corners' coordinates as control values and the product rule is
//   q_(i,j,k) = (i l_a p_(i-1,j,k) + j l_b p_(i,j-1,k) + k l_c p_(i,j,k-1)) / (d + 1).

/// The degree-(d + 1) Bézier form of `l(t) p(t)`, `p` of degree d (flat, `stride`
/// coordinates per point), `l` linear with control values `l = [l_0, l_1]`.
fn times_linear_bernstein<T: Ring>(p: &[T], stride: usize, [l0, l1]: [&T; 2]) -> Vec<T> {
    let d = count(p, stride) - 1;
    let den = (d + 1) as i128;
    let mut out = vec![T::zero(); (d + 2) * stride];
    for (j, q) in out.chunks_exact_mut(stride).enumerate() {
        if j <= d {
            let k = l0.scale_frac((d + 1 - j) as i128, den);
            add_scaled(q, &k, &p[j * stride..(j + 1) * stride]);
        }
        if j >= 1 {
            let k = l1.scale_frac(j as i128, den);
            add_scaled(q, &k, &p[(j - 1) * stride..j * stride]);
        }
    }
    out
}

/// The Bézier control points over [r, s] (the curve's parameter u = (1 - t) r + t s) of the
/// polynomial sum c_i u^i with power coefficients `c` (flat, `stride` coordinates each), by
/// Horner's rule in the Bernstein basis: O(n^2) ring operations per coordinate, no Taylor
/// shift. Empty for no coefficient or a stride of 0.
pub fn bernstein_by_horner<T: Ring>(c: &[T], stride: usize, r: &T, s: &T) -> Vec<T> {
    let len = count(c, stride);
    if len == 0 {
        return Vec::new();
    }
    let mut acc = c[(len - 1) * stride..len * stride].to_vec();
    for ck in c[..len * stride].chunks_exact(stride).rev().skip(1) {
        acc = times_linear_bernstein(&acc, stride, [r, s]);
        for q in acc.chunks_exact_mut(stride) {
            add_assign(q, ck);
        }
    }
    acc
}

/// The degree-(d + 1) triangular Bézier form of `l p`, `p` of degree `d` (lexicographic in
/// (i, j), flat, `dim` coordinates per point), `l` linear with control values `[l_a, l_b, l_c]`
/// at the corners.
fn times_linear_triangle<T: Ring>(p: &[T], dim: usize, d: usize, l: [&T; 3]) -> Vec<T> {
    let den = (d + 1) as i128;
    let mut out = vec![T::zero(); triangle_len(d + 1) * dim];
    let at = |i, j| triangle_index(d, i, j) * dim;
    for i in 0..=d + 1 {
        for j in 0..=d + 1 - i {
            let k = d + 1 - i - j;
            let start = triangle_index(d + 1, i, j) * dim;
            let q = &mut out[start..start + dim];
            if i > 0 {
                let w = l[0].scale_frac(i as i128, den);
                add_scaled(q, &w, &p[at(i - 1, j)..at(i - 1, j) + dim]);
            }
            if j > 0 {
                let w = l[1].scale_frac(j as i128, den);
                add_scaled(q, &w, &p[at(i, j - 1)..at(i, j - 1) + dim]);
            }
            if k > 0 {
                let w = l[2].scale_frac(k as i128, den);
                add_scaled(q, &w, &p[at(i, j)..at(i, j) + dim]);
            }
        }
    }
    out
}

/// The control net of degree N on the triangle with corners `tri = [a, b, c]` of the surface
/// S(u, v) = sum c_ij u^i v^j of total degree N (rows of any lengths, a grid or a triangular
/// array), by Horner's rule in the triangular Bernstein basis:
/// S = (..(Q_n u + Q_(n-1)) u + ..) + Q_0 with Q_i(v) = sum_j c_ij v^j, each Q_i built by
/// Horner in v, and the running sum and each Q_i raised to a common degree before they are
/// added (a raise is a product with the linear form 1 = (1, 1, 1)). O(N^4) per coordinate.
pub fn triangle_bernstein_by_horner<T: Ring>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    let (big_n, dim) = (surface.degree(), surface.dim());
    let [a, b, c] = tri;
    let (u, v) = ([&a[0], &b[0], &c[0]], [&a[1], &b[1], &c[1]]);
    let one = T::one();
    let ones = [&one, &one, &one];
    // Q_i(v) in the Bernstein basis of its own degree (the row's length minus one).
    let row_form = |row: crate::Points<'_, T>| -> (Vec<T>, usize) {
        let top = row.len() - 1;
        let mut acc = row[top].to_vec();
        for (d, cj) in (0..top).zip(row.iter().rev().skip(1)) {
            acc = times_linear_triangle(&acc, dim, d, v);
            for q in acc.chunks_exact_mut(dim) {
                add_assign(q, cj);
            }
        }
        (acc, top)
    };
    let raise = |mut p: Vec<T>, from: usize, to: usize| {
        for d in from..to {
            p = times_linear_triangle(&p, dim, d, ones);
        }
        p
    };
    let mut rows = surface.rows().rev();
    let (mut acc, mut degree) = row_form(rows.next().expect("at least one row"));
    for row in rows {
        acc = times_linear_triangle(&acc, dim, degree, u);
        degree += 1;
        let (q, q_degree) = row_form(row);
        let common = degree.max(q_degree);
        acc = raise(acc, degree, common);
        let q = raise(q, q_degree, common);
        degree = common;
        add_assign(&mut acc, &q);
    }
    let acc = raise(acc, degree, big_n);
    TriangularPatch::from_raw(big_n, dim, acc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    fn frac(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn tensor_power_form_evaluates_to_the_patch() {
        use crate::shape::bezier::TensorPatch;
        // A (2, 3) net with distinct entries; de Casteljau (TensorPatch::eval) is independent.
        let net: Vec<Vec<Point<Rational>>> = (0..3)
            .map(|i| {
                (0..4)
                    .map(|j| vec![q(i * i - 3 * j + 1), q(j * j * i - 2)])
                    .collect()
            })
            .collect();
        let patch = TensorPatch::new(net).unwrap();
        let power = tensor_bernstein_to_power(&patch);
        for (s, t) in [
            (frac(1, 3), frac(2, 5)),
            (frac(-2, 1), frac(7, 4)),
            (q(0), q(1)),
        ] {
            assert_eq!(power.eval(&s, &t), patch.eval(&s, &t));
        }
    }

    #[test]
    fn horner_bernstein_form_evaluates_to_the_power_form() {
        use crate::shape::bezier::BezierCurve;
        use crate::shape::power::PowerCurve;
        // C(u) = (3 - u + 2u^2 - 5u^4, u^3) on [r, s] = [-2/3, 5/2]: the Bézier form at t is C
        // at (1 - t) r + t s, for t inside and outside [0, 1].
        let c = vec![
            vec![q(3), q(0)],
            vec![q(-1), q(0)],
            vec![q(2), q(0)],
            vec![q(0), q(1)],
            vec![q(-5), q(0)],
        ];
        let (r, s) = (frac(-2, 3), frac(5, 2));
        let bez =
            BezierCurve::from_coordinates(2, bernstein_by_horner(&c.concat(), 2, &r, &s)).unwrap();
        let power = PowerCurve::new(c).unwrap();
        for t in [frac(0, 1), frac(1, 1), frac(1, 3), frac(-7, 4), frac(9, 5)] {
            let u = r.add(&t.mul(&s.sub(&r)));
            assert_eq!(bez.eval(&t), power.eval(&u), "t = {t}");
        }
    }

    #[test]
    fn horner_triangle_form_evaluates_to_the_power_form() {
        use crate::shape::power::PowerSurface;
        // S(u, v) = 1 - 2u + 3uv^2 - u^2 v + 4v^3 (n = m = 2, padded to N = 5) on a triangle.
        let mut grid = vec![vec![vec![q(0)]; 4]; 3];
        grid[0][0] = vec![q(1)];
        grid[1][0] = vec![q(-2)];
        grid[1][2] = vec![q(3)];
        grid[2][1] = vec![q(-1)];
        grid[0][3] = vec![q(4)];
        let tri = [[frac(1, 2), q(-1)], [q(3), frac(2, 7)], [q(-2), q(2)]];
        let power = PowerSurface::new(grid).unwrap();
        for big_n in [5, 7] {
            let surface = PowerTriangle::from_surface(&power)
                .at_degree(big_n)
                .unwrap();
            let patch = triangle_bernstein_by_horner(&surface, &tri);
            for bary in [
                [frac(1, 3), frac(1, 3), frac(1, 3)],
                [q(2), frac(-1, 2), frac(-1, 2)],
            ] {
                let u = bary[0]
                    .mul(&tri[0][0])
                    .add(&bary[1].mul(&tri[1][0]))
                    .add(&bary[2].mul(&tri[2][0]));
                let v = bary[0]
                    .mul(&tri[0][1])
                    .add(&bary[1].mul(&tri[1][1]))
                    .add(&bary[2].mul(&tri[2][1]));
                assert_eq!(
                    patch.eval(&[bary[0].clone(), bary[1].clone()]),
                    power.eval(&u, &v),
                    "N = {big_n}"
                );
            }
        }
    }

    #[test]
    fn taylor_shift_matches_expansion() {
        // 1 + 2u + 3u^2 at u + 2: 1 + 2(u+2) + 3(u+2)^2 = 17 + 14u + 3u^2
        let mut c = vec![vec![q(1)], vec![q(2)], vec![q(3)]];
        taylor_shift(&mut c, &q(2));
        assert_eq!(c, vec![vec![q(17)], vec![q(14)], vec![q(3)]]);
        scale_argument(&mut c, &q(-1));
        assert_eq!(c, vec![vec![q(17)], vec![q(-14)], vec![q(3)]]);
    }

    #[test]
    fn bernstein_of_monomials() {
        // u^2 in degree 3: control points 0, 0, 1/3, 1.
        let d = vec![vec![q(0)], vec![q(0)], vec![q(1)], vec![q(0)]];
        let w = power_to_bernstein(&d);
        let third = Rational::new(1.into(), 3.into());
        assert_eq!(w, vec![vec![q(0)], vec![q(0)], vec![third], vec![q(1)]]);
    }

    #[test]
    fn triangle_bernstein_of_s_times_t() {
        // s t in degree 2 is B_{110}^2 / 2: only q_{110} = 1/2 is non-zero.
        let mut d = vec![q(0); triangle_len(2)];
        d[triangle_index(2, 1, 1)] = q(1);
        let surface = PowerTriangle::from_coordinates(2, 1, d).unwrap();
        let patch = triangle_power_to_bernstein(&surface).unwrap();
        // The inverse brings the array back.
        assert_eq!(triangle_bernstein_to_power(&patch), surface);
        for (nu, mu, _, p) in patch.entries() {
            let want = if (nu, mu) == (1, 1) {
                Rational::new(1.into(), 2.into())
            } else {
                q(0)
            };
            assert_eq!(p, &vec![want], "q_{nu}{mu}");
        }
    }
}
