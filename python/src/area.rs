//! The signed area enclosed by a closed chain of planar Bézier curves (`Triangle.area`,
//! `CurvedPolygon.area`), exactly: by Green's theorem the area is
//! (1/2) sum over the edges of the integral of x y' - y x' over [0, 1], and for an edge of
//! degree n with control points (x_i, y_i) that integral is, with the product rule of
//! Bernstein polynomials (the integral of B_i^n B_j^(n-1) is
//! C(n, i) C(n - 1, j) / (2n C(2n - 1, i + j))),
//!
//! ```text
//! (1/2) int (x y' - y x') = sum_{i, j} C(n, i) C(n - 1, j) / (4 C(2n - 1, i + j))
//!                           * (x_i (y_(j+1) - y_j) - y_i (x_(j+1) - x_j)).
//! ```
//!
//! Computed in exact rationals (floats read exactly), then rounded once: the float64 answer is
//! the correctly rounded exact area. Positive for counterclockwise boundaries, as bezier's.
//! [`edge_area_f64`] evaluates the same sum in doubles (where only a sign or an approximate
//! value is wanted: the orientation of a font's contours).

use blossom::engine::binomial;
use blossom::{BezierCurve, Rational};
use num_bigint::BigInt;
use num_traits::Zero;

/// The contribution (1/2) int (x y' - y x') of one planar edge.
pub fn edge_area(edge: &BezierCurve<Rational>) -> Rational {
    let n = edge.degree();
    if n == 0 {
        return Rational::zero();
    }
    let p: Vec<&[Rational]> = edge.coordinates().chunks_exact(2).collect();
    let n64 = n as i64;
    let mut sum = Rational::zero();
    for (i, pi) in p.iter().enumerate() {
        for j in 0..n {
            let dx = &p[j + 1][0] - &p[j][0];
            let dy = &p[j + 1][1] - &p[j][1];
            let cross = &pi[0] * dy - &pi[1] * dx;
            if cross.is_zero() {
                continue;
            }
            let weight = Rational::new(
                binomial(n64, i as i64) * binomial(n64 - 1, j as i64),
                BigInt::from(4) * binomial(2 * n64 - 1, (i + j) as i64),
            );
            sum += weight * cross;
        }
    }
    sum
}

/// [`edge_area`] of control points given as doubles, evaluated in doubles (not certified: each
/// term rounded).
pub fn edge_area_f64(points: &[[f64; 2]]) -> f64 {
    let n = points.len().saturating_sub(1);
    let choose = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |c, i| c * (n - i) as f64 / (i + 1) as f64)
    };
    let mut sum = 0.0;
    for (i, pi) in points.iter().enumerate() {
        for j in 0..n {
            let (dx, dy) = (
                points[j + 1][0] - points[j][0],
                points[j + 1][1] - points[j][1],
            );
            let cross = pi[0] * dy - pi[1] * dx;
            sum += choose(n, i) * choose(n - 1, j) / (4.0 * choose(2 * n - 1, i + j)) * cross;
        }
    }
    sum
}

/// The signed area of the closed chain `edges`.
pub fn chain_area<'a>(edges: impl IntoIterator<Item = &'a BezierCurve<Rational>>) -> Rational {
    edges.into_iter().map(edge_area).sum()
}
