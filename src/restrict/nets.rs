//! The control nets of restriction as lists of blossom arguments: x^k y^l for a curve, eq. (6)
//! for a tensor patch and eq. (12) for a triangle, shared by the per-point algorithms.

use crate::shape::point::Point;

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
    let mut points = Vec::with_capacity(crate::shape::simplex::triangle_len(big_n));
    for nu in 0..=big_n {
        for mu in 0..=big_n - nu {
            let mut args = repeated(a, nu, b, mu);
            args.extend(std::iter::repeat_n(c.clone(), big_n - nu - mu));
            points.push(blossom(&args));
        }
    }
    points
}
