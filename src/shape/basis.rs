//! Changes of polynomial basis and of variable, all division-free (ring operations and exact
//! rational constants only), so that they run on floats, rationals and symbolic polynomials.
//!
//! * [`taylor_shift`]: coefficients of C(u + a) from those of C(u), O(n^2);
//! * [`scale_argument`]: coefficients of C(h u), O(n);
//! * [`power_to_bernstein`]: power coefficients over [0, 1] to Bézier control points, O(n^2):
//!   u^i = sum_{v >= i} C(v, i) / C(n, i) B_v^n(u);
//! * [`triangle_power_to_bernstein`]: power coefficients in barycentric coordinates (s, t) to
//!   the control net of a triangular patch, O(N^3):
//!   s^i t^j = sum_{nu >= i, mu >= j} C(nu, i) C(mu, j) / (N! / (i! j! (N-i-j)!)) B_{nu mu}^N;
//! * [`bernstein_by_horner`]: power coefficients to the Bézier control points over any interval
//!   [r, s], by Horner's rule carried out in the Bernstein basis (module section below); O(n^2);
//! * [`triangle_bernstein_by_horner`]: the same for a surface on any triangle, O(N^4).
//! * [`bernstein_to_power`]: the inverse of [`power_to_bernstein`] by forward differences,
//!   c_k = C(n, k) Δ^k b_0, O(n^2);
//! * [`triangle_bernstein_to_power`]: the inverse of [`triangle_power_to_bernstein`],
//!   c_ij = N! / (i! j! (N-i-j)!) Δ_1^i Δ_2^j b_(0,0,N), O(N^3).

use crate::error::Result;
use crate::num::binomial::multinomial;
use crate::shape::bezier::{check_triangle_net, TriangularPatch};
use crate::shape::point::Point;
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

/// Replaces the coefficients of C(u) = sum c_i u^i by those of C(u + a), in place, by repeated
/// synthetic division (n(n+1)/2 multiply-adds per coordinate).
pub fn taylor_shift<T: Ring>(c: &mut [Point<T>], a: &T) {
    let n = c.len().saturating_sub(1);
    for k in 0..n {
        for i in (k..n).rev() {
            let (lo, hi) = c.split_at_mut(i + 1);
            for (x, y) in lo[i].iter_mut().zip(&hi[0]) {
                x.add_assign(&a.mul(y));
            }
        }
    }
}

/// Replaces the coefficients of C(u) by those of C(h u): c_i becomes h^i c_i.
pub fn scale_argument<T: Ring>(c: &mut [Point<T>], h: &T) {
    let mut power = T::one();
    for ci in c.iter_mut().skip(1) {
        power = power.mul(h);
        scale_point(ci, &power);
    }
}

/// The binomial transform w_v = sum_{i <= v} C(v, i) e_i, in place, with additions only
/// (the Newton forward-difference table read backwards).
pub fn binomial_transform<T: Ring>(e: &mut [Point<T>]) {
    let n = e.len().saturating_sub(1);
    for k in (0..n).rev() {
        for i in k..n {
            let (lo, hi) = e.split_at_mut(i + 1);
            crate::shape::point::add_assign(&mut hi[0], &lo[i]);
        }
    }
}

/// The Bézier control points over [0, 1] of the polynomial with power coefficients `d`:
/// w_v = sum_{i <= v} C(v, i) / C(n, i) d_i.
pub fn power_to_bernstein<T: Ring>(d: &[Point<T>]) -> Vec<Point<T>> {
    let mut e: Vec<Point<T>> = d.to_vec();
    power_to_bernstein_in_place(&mut e);
    e
}

/// [`power_to_bernstein`] in place: the coefficients `d` become the control points.
pub fn power_to_bernstein_in_place<T: Ring>(d: &mut [Point<T>]) {
    scale_by_binomials(d, Binomials::Divide);
    binomial_transform(d);
}

/// Whether [`scale_by_binomials`] multiplies or divides.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Binomials {
    Multiply,
    Divide,
}

/// Multiplies (or divides) each point `c[i]` by C(n, i), n = `c.len() - 1`.
///
/// The row is built by C(n, i) = C(n, i - 1) (n - i + 1) / i: in `i128` while the product
/// fits (each constant then reaches the ring once, through [`Ring::scale_frac`]), and past that
/// (n above about 125) in the ring itself, one `scale_frac` per step. Exact for rationals and
/// polynomials; for floats each constant is rounded once while it fits in `i128`, and after
/// that carries the rounding of its steps (a relative error below n times the unit roundoff).
/// No big-number arithmetic: it cost more than the restriction itself at small degrees.
fn scale_by_binomials<T: Ring>(c: &mut [Point<T>], how: Binomials) {
    let n = c.len().saturating_sub(1) as i128;
    // The factor of c[i]: C(n, i) or its inverse, as a ring constant.
    let factor = |k: i128| match how {
        Binomials::Multiply => T::one().scale_frac(k, 1),
        Binomials::Divide => T::one().scale_frac(1, k),
    };
    let mut row: Binomial<T> = Binomial::Small(1);
    for (i, ci) in c.iter_mut().enumerate().skip(1) {
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

/// The control net of the triangular patch of degree `n` whose power coefficients in the
/// barycentric coordinates (s, t) of corners a, b (the third, of c, being 1 - s - t) are
/// `d[triangle_index(n, i, j)]` = coefficient of s^i t^j.
///
/// Divides by the multinomials once, then applies the binomial transform along t for every
/// power of s and along s for every index of t: O(N^3) additions.
///
/// # Errors
/// As [`TriangularPatch::new`] for a net of degree `n` (about `n` and `d`): a degree whose
/// count of coefficients overflows or exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES), a list
/// `d` of another length, points of no or of different dimensions.
pub fn triangle_power_to_bernstein<T: Ring>(
    n: usize,
    d: &[Point<T>],
) -> Result<TriangularPatch<T>> {
    check_triangle_net(n, d, "n", "d")?;
    let ni = n as i64;
    // h[i][mu] = sum_{j <= mu} C(mu, j) e_ij for mu <= n - i.
    let mut h: Vec<Vec<Point<T>>> = (0..=n)
        .map(|i| {
            let mut row: Vec<Point<T>> = (0..=n - i)
                .map(|j| {
                    let mut e = d[triangle_index(n, i, j)].clone();
                    let m = multinomial(ni, &[i as i64, j as i64]);
                    if m != 1.into() {
                        scale_point_rational(&mut e, &Rational::new(1.into(), m));
                    }
                    e
                })
                .collect();
            binomial_transform(&mut row);
            row
        })
        .collect();
    // q[nu][mu] = sum_{i <= nu} C(nu, i) h[i][mu] for nu <= n - mu.
    let mut out: Vec<Option<Point<T>>> = vec![None; triangle_len(n)];
    for mu in 0..=n {
        let mut col: Vec<Point<T>> = (0..=n - mu)
            .map(|i| std::mem::take(&mut h[i][mu]))
            .collect();
        binomial_transform(&mut col);
        for (nu, q) in col.into_iter().enumerate() {
            out[triangle_index(n, nu, mu)] = Some(q);
        }
    }
    let points = out
        .into_iter()
        .map(|q| q.expect("every index is filled"))
        .collect();
    Ok(TriangularPatch::new(n, points).expect("a net of the right size"))
}

/// `out[k]` = Δ^k p_0, the forward differences of `points` (n(n+1)/2 subtractions per
/// coordinate), in place: after pass k, entry i >= k holds Δ^k p_(i-k), since
/// Δ^k p_(i-k) = Δ^(k-1) p_(i-k+1) - Δ^(k-1) p_(i-k).
fn forward_differences<T: Ring>(mut points: Vec<Point<T>>) -> Vec<Point<T>> {
    for k in 1..points.len() {
        for i in (k..points.len()).rev() {
            let (lo, hi) = points.split_at_mut(i);
            for (x, y) in hi[0].iter_mut().zip(&lo[i - 1]) {
                *x = x.sub(y);
            }
        }
    }
    points
}

/// The power coefficients of the Bézier curve over [0, 1] with control points `b` (the inverse
/// of [`power_to_bernstein`]): c_k = C(n, k) Δ^k b_0, the k-th forward difference scaled by a
/// binomial. O(n^2) subtractions and n scalings per coordinate.
pub fn bernstein_to_power<T: Ring>(b: &[Point<T>]) -> Vec<Point<T>> {
    let mut c = forward_differences(b.to_vec());
    scale_by_binomials(&mut c, Binomials::Multiply);
    c
}

/// The power coefficients `[i][j]` (of s^i t^j) of the tensor-product patch over [0, 1]^2 with
/// control points `net[i][j]`: c_ij = C(n, i) C(m, j) Δ_s^i Δ_t^j b_00, by
/// [`bernstein_to_power`] along t for every row, then along s for every column.
pub fn tensor_bernstein_to_power<T: Ring>(net: &[Vec<Point<T>>]) -> Vec<Vec<Point<T>>> {
    let rows: Vec<Vec<Point<T>>> = net.iter().map(|row| bernstein_to_power(row)).collect();
    let width = rows.first().map_or(0, Vec::len);
    let columns: Vec<Vec<Point<T>>> = (0..width)
        .map(|j| {
            let column: Vec<Point<T>> = rows.iter().map(|row| row[j].clone()).collect();
            bernstein_to_power(&column)
        })
        .collect();
    (0..rows.len())
        .map(|i| columns.iter().map(|column| column[i].clone()).collect())
        .collect()
}

/// The power coefficients in the barycentric coordinates (s, t) of corners 1 and 2 (the third
/// being 1 - s - t) of the triangular patch `patch` (the inverse of
/// [`triangle_power_to_bernstein`]): `out[triangle_index(N, i, j)]` = coefficient of s^i t^j =
/// N! / (i! j! (N-i-j)!) Δ_1^i Δ_2^j b_(0,0,N), where Δ_1 b_(nu,mu) = b_(nu+1,mu) - b_(nu,mu)
/// and Δ_2 b_(nu,mu) = b_(nu,mu+1) - b_(nu,mu). O(N^3) subtractions.
pub fn triangle_bernstein_to_power<T: Ring>(patch: &TriangularPatch<T>) -> Vec<Point<T>> {
    let n = patch.degree();
    let mut out: Vec<Option<Point<T>>> = vec![None; triangle_len(n)];
    // level[nu][mu] = Δ_2^j b_(nu, mu), nu + mu <= N - j.
    let mut level: Vec<Vec<Point<T>>> = (0..=n)
        .map(|nu| (0..=n - nu).map(|mu| patch.get(nu, mu).to_vec()).collect())
        .collect();
    for j in 0..=n {
        if j > 0 {
            level = (0..=n - j)
                .map(|nu| {
                    (0..=n - j - nu)
                        .map(|mu| {
                            let (hi, lo) = (&level[nu][mu + 1], &level[nu][mu]);
                            hi.iter().zip(lo).map(|(x, y)| x.sub(y)).collect()
                        })
                        .collect()
                })
                .collect();
        }
        let column: Vec<Point<T>> = level.iter().map(|row| row[0].clone()).collect();
        for (i, mut d) in forward_differences(column).into_iter().enumerate() {
            let k = multinomial(n as i64, &[i as i64, j as i64]);
            if k != 1.into() {
                scale_point_rational(&mut d, &Rational::from_integer(k));
            }
            out[triangle_index(n, i, j)] = Some(d);
        }
    }
    out.into_iter()
        .map(|d| d.expect("every i + j <= N is filled"))
        .collect()
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

/// The degree-(d + 1) Bézier form of `l(t) p(t)`, `p` of degree d = `p.len() - 1`, `l` linear
/// with control values `l = [l_0, l_1]`.
fn times_linear_bernstein<T: Ring>(p: &[Point<T>], [l0, l1]: [&T; 2]) -> Vec<Point<T>> {
    let d = p.len() - 1;
    let den = (d + 1) as i128;
    (0..=d + 1)
        .map(|j| {
            let mut q: Point<T> = vec![T::zero(); p[0].len()];
            if j <= d {
                let k = l0.scale_frac((d + 1 - j) as i128, den);
                crate::shape::point::add_scaled(&mut q, &k, &p[j]);
            }
            if j >= 1 {
                let k = l1.scale_frac(j as i128, den);
                crate::shape::point::add_scaled(&mut q, &k, &p[j - 1]);
            }
            q
        })
        .collect()
}

/// The Bézier control points over [r, s] (the curve's parameter u = (1 - t) r + t s) of the
/// polynomial sum c_i u^i with power coefficients `c`, by Horner's rule in the Bernstein
/// basis: O(n^2) ring operations per coordinate, no Taylor shift.
pub fn bernstein_by_horner<T: Ring>(c: &[Point<T>], r: &T, s: &T) -> Vec<Point<T>> {
    let mut acc: Vec<Point<T>> = vec![c[c.len() - 1].clone()];
    for ck in c.iter().rev().skip(1) {
        acc = times_linear_bernstein(&acc, [r, s]);
        for q in acc.iter_mut() {
            crate::shape::point::add_assign(q, ck);
        }
    }
    acc
}

/// The degree-(d + 1) triangular Bézier form of `l p`, `p` of degree `d` (lexicographic in
/// (i, j)), `l` linear with control values `[l_a, l_b, l_c]` at the corners.
fn times_linear_triangle<T: Ring>(p: &[Point<T>], d: usize, l: [&T; 3]) -> Vec<Point<T>> {
    let dim = p[0].len();
    let den = (d + 1) as i128;
    let mut out = Vec::with_capacity(triangle_len(d + 1));
    for i in 0..=d + 1 {
        for j in 0..=d + 1 - i {
            let k = d + 1 - i - j;
            let mut q: Point<T> = vec![T::zero(); dim];
            if i > 0 {
                let w = l[0].scale_frac(i as i128, den);
                crate::shape::point::add_scaled(&mut q, &w, &p[triangle_index(d, i - 1, j)]);
            }
            if j > 0 {
                let w = l[1].scale_frac(j as i128, den);
                crate::shape::point::add_scaled(&mut q, &w, &p[triangle_index(d, i, j - 1)]);
            }
            if k > 0 {
                let w = l[2].scale_frac(k as i128, den);
                crate::shape::point::add_scaled(&mut q, &w, &p[triangle_index(d, i, j)]);
            }
            out.push(q);
        }
    }
    out
}

/// The control net of degree `big_n` on the triangle with corners `tri = [a, b, c]` of
/// S(u, v) = sum c_ij u^i v^j (`coefficients[i][j]`; rows of any lengths, a grid or a triangular
/// array, with i + j <= `big_n` for every entry), by Horner's rule in the triangular Bernstein
/// basis: S = (..(Q_n u + Q_(n-1)) u + ..) + Q_0 with Q_i(v) = sum_j c_ij v^j, each Q_i built by
/// Horner in v, and the running sum and each Q_i raised to a common degree before they are
/// added (a raise is a product with the linear form 1 = (1, 1, 1)). O(N^4) per coordinate.
///
/// # Panics
///
/// When a row is empty or holds an entry with i + j > `big_n`.
pub fn triangle_bernstein_by_horner<T: Ring>(
    coefficients: &[Vec<Point<T>>],
    big_n: usize,
    tri: &[[T; 2]; 3],
) -> TriangularPatch<T> {
    assert!(
        coefficients
            .iter()
            .enumerate()
            .all(|(i, row)| !row.is_empty() && i + row.len() - 1 <= big_n),
        "every row non-empty and every entry of total degree at most the patch's"
    );
    let n = coefficients.len() - 1;
    let [a, b, c] = tri;
    let (u, v) = ([&a[0], &b[0], &c[0]], [&a[1], &b[1], &c[1]]);
    let one = T::one();
    let ones = [&one, &one, &one];
    // Q_i(v) in the Bernstein basis of its own degree (the row's length minus one).
    let row_form = |row: &[Point<T>]| -> (Vec<Point<T>>, usize) {
        let top = row.len() - 1;
        let mut acc = vec![row[top].clone()];
        for (d, cj) in (0..top).zip(row.iter().rev().skip(1)) {
            acc = times_linear_triangle(&acc, d, v);
            for q in acc.iter_mut() {
                crate::shape::point::add_assign(q, cj);
            }
        }
        (acc, top)
    };
    let raise = |mut p: Vec<Point<T>>, from: usize, to: usize| {
        for d in from..to {
            p = times_linear_triangle(&p, d, ones);
        }
        p
    };
    let (mut acc, mut degree) = row_form(&coefficients[n]);
    for i in (0..n).rev() {
        acc = times_linear_triangle(&acc, degree, u);
        degree += 1;
        let (q, q_degree) = row_form(&coefficients[i]);
        let common = degree.max(q_degree);
        acc = raise(acc, degree, common);
        let q = raise(q, q_degree, common);
        degree = common;
        for (x, y) in acc.iter_mut().zip(&q) {
            crate::shape::point::add_assign(x, y);
        }
    }
    let acc = raise(acc, degree, big_n);
    TriangularPatch::new(big_n, acc).expect("a full triangular net")
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
        use crate::shape::power::PowerSurface;
        // A (2, 3) net with distinct entries; de Casteljau (TensorPatch::eval) is independent.
        let net: Vec<Vec<Point<Rational>>> = (0..3)
            .map(|i| {
                (0..4)
                    .map(|j| vec![q(i * i - 3 * j + 1), q(j * j * i - 2)])
                    .collect()
            })
            .collect();
        let power = PowerSurface::new(tensor_bernstein_to_power(&net)).unwrap();
        let patch = TensorPatch::new(net).unwrap();
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
        let bez = BezierCurve::new(bernstein_by_horner(&c, &r, &s)).unwrap();
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
        for big_n in [5, 7] {
            let patch = triangle_bernstein_by_horner(&grid, big_n, &tri);
            let power = PowerSurface::new(grid.clone()).unwrap();
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
        let mut d = vec![vec![q(0)]; triangle_len(2)];
        d[triangle_index(2, 1, 1)] = vec![q(1)];
        let patch = triangle_power_to_bernstein(2, &d).unwrap();
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
