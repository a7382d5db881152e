//! The four independent blossom algorithms, each for curves, tensor-product patches and
//! triangular patches:
//!
//! | module | curves | tensor patches | triangles |
//! |---|---|---|---|
//! | [`definition`] (subset sums) | eq. (2) | eqs. (7)-(8) | eq. (13) |
//! | [`closed_form`] (per control point) | Theorem 1, eq. (3) | Theorem 2, eq. (9) | Theorem 3, eq. (14) |
//! | [`pyramid`] (de Casteljau) | eq. (2) of 004 | eq. (9) of 004 | barycentric steps |
//! | [`polarisation`] (inverse formula) | eqs. (20), (22) of 004 | two passes | eqs. (21), (23) of 004 |
//!
//! Their blossom evaluations are independent; the pyramid takes its Bernstein form over its
//! reference domain from the bulk change of basis ([`crate::restrict`]). The tests prove all of
//! them identical to the definition as polynomials.

pub mod closed_form;
pub mod definition;
pub mod polarisation;
pub mod pyramid;

use crate::point::Point;

/// The argument list `x^k y^l` of a blossom.
pub(crate) fn repeated<X: Clone>(x: &X, k: usize, y: &X, l: usize) -> Vec<X> {
    let mut v = vec![x.clone(); k];
    v.extend(std::iter::repeat_n(y.clone(), l));
    v
}

/// The control net `[nu][mu]` = `blossom(b^nu a^(n-nu); d^mu c^(m-mu))` of eq. (6).
pub(crate) fn tensor_net<X: Clone, P>(
    (n, m): (usize, usize),
    [a, b, c, d]: &[X; 4],
    blossom: impl Fn(&[X], &[X]) -> P,
) -> Vec<Vec<P>> {
    (0..=n)
        .map(|nu| {
            (0..=m)
                .map(|mu| blossom(&repeated(b, nu, a, n - nu), &repeated(d, mu, c, m - mu)))
                .collect()
        })
        .collect()
}

/// The control points `blossom(a^nu b^mu c^lambda)` of eq. (12), lexicographic in (nu, mu).
pub(crate) fn triangle_net<X: Clone, T>(
    big_n: usize,
    [a, b, c]: &[X; 3],
    blossom: impl Fn(&[X]) -> Point<T>,
) -> Vec<Point<T>> {
    let mut points = Vec::with_capacity(crate::bezier::triangle_len(big_n));
    for nu in 0..=big_n {
        for mu in 0..=big_n - nu {
            let mut args = repeated(a, nu, b, mu);
            args.extend(std::iter::repeat_n(c.clone(), big_n - nu - mu));
            points.push(blossom(&args));
        }
    }
    points
}
