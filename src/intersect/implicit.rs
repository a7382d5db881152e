//! Exact proofs that a curve misses a quadratic, through the quadratic's implicit equation, in
//! fixed-width integers (the case of font outlines: small integer or dyadic coordinates).
//!
//! **The parabola of a quadratic.** Let Q have control points q0, q1, q2 not on one line, and
//! for a point x let A0(x) = [q1 - x, q2 - x], A1(x) = [q2 - x, q0 - x] and
//! A2(x) = [q0 - x, q1 - x] ([u, v] = u_x v_y - u_y v_x), so that A0 + A1 + A2 = A =
//! [q1 - q0, q2 - q0] ≠ 0 and (A0, A1, A2) / A are the barycentric coordinates of x in the
//! triangle q0 q1 q2. Q(t) has the barycentric coordinates ((1 - t)^2, 2t (1 - t), t^2), so
//! f(x) = A1(x)^2 - 4 A0(x) A2(x) vanishes at every point of Q (f = 0 is Q's parabola). So a
//! curve P along which f has no zero has no common point with Q.
//!
//! **The test.** Each A_i is affine, so A_i(P(s)) = Σ_k A_i(p_k) B^n_k(s) for P of degree n
//! with control points p_k (the Bernstein basis sums to one). With a_ik = A_i(p_k),
//! g(s) = f(P(s)) = Σ_(j,k) (a_1j a_1k - 4 a_0j a_2k) B^n_j(s) B^n_k(s), and
//! B^n_j B^n_k = C(n, j) C(n, k) / C(2n, j + k) B^(2n)_(j+k): the Bernstein coefficient m of g
//! (degree 2n) is h_m / C(2n, m) with h_m = Σ_(j+k=m) C(n, j) C(n, k) (a_1j a_1k - 4 a_0j a_2k).
//! When every h_m has one strict sign, g has that sign on [0, 1] (the Bernstein basis is
//! non-negative and sums to one), so P misses Q. Every number is an integer: the coordinates
//! on one dyadic scale ([`crate::num::small::Dyadic`]) below 2^25 in magnitude, so that differences
//! are below 2^26, the a_ik below 2^53, products below 2^106, and h_m (at most four pairs of
//! products, each weighted at most 5 C(3, j) C(3, k) <= 45) below 2^116 in `i128`.
//!
//! The test decides no common point only; a zero of g, even outside Q's piece of the parabola,
//! leaves the pair to the other stages.

use crate::num::small::{common_scale, Dyadic};

/// The coordinates' bound of the test (module documentation).
pub(crate) const IMPLICIT_COORDINATE: i64 = 1 << 25;

/// C(n, k) for n <= 3.
const BINOMIAL: [[i64; 4]; 4] = [[1, 0, 0, 0], [1, 1, 0, 0], [1, 2, 1, 0], [1, 3, 3, 1]];

/// The cross product [u - x, v - x] of differences below 2^26: below 2^53, exact in `i64`.
#[inline(always)]
fn cross_from(x: [i64; 2], u: [i64; 2], v: [i64; 2]) -> i64 {
    (u[0] - x[0]) * (v[1] - x[1]) - (u[1] - x[1]) * (v[0] - x[0])
}

/// The exact product of two `i64` in `i128`.
#[inline(always)]
fn wide(a: i64, b: i64) -> i128 {
    i128::from(a) * i128::from(b)
}

/// Whether two curves given by their integers (each made once, [`Dyadic`]), one of them a
/// quadratic, are proved apart by [`misses_quadratic_integers`] on their common scale.
pub(crate) fn implicitly_apart(a: &Dyadic, b: &Dyadic) -> bool {
    let Some([pa, pb]) = common_scale(a, b, IMPLICIT_COORDINATE) else {
        return false;
    };
    let quadratic = |p: &[[i64; 2]; 4]| [p[0], p[1], p[2]];
    (b.len() == 3 && misses_quadratic_integers(&pa[..a.len()], quadratic(&pb)))
        || (a.len() == 3 && misses_quadratic_integers(&pb[..b.len()], quadratic(&pa)))
}

#[cfg(test)]
pub(crate) fn misses_quadratic(p: &[[f64; 2]], q: &[[f64; 2]]) -> bool {
    if q.len() != 3 || p.len() > 4 {
        return false;
    }
    crate::num::small::on_common_scale(p, q, IMPLICIT_COORDINATE)
        .is_some_and(|[a, b]| misses_quadratic_integers(&a[..p.len()], [b[0], b[1], b[2]]))
}

/// [`misses_quadratic`] on integer control points on one scale, each coordinate below
/// [`IMPLICIT_COORDINATE`] in magnitude.
pub(crate) fn misses_quadratic_integers(p: &[[i64; 2]], q: [[i64; 2]; 3]) -> bool {
    // The degree fixed at compile time: the loops unrolled, no bounds checks.
    match p.len() {
        2 => misses::<2>(p.try_into().expect("two points"), q),
        3 => misses::<3>(p.try_into().expect("three points"), q),
        4 => misses::<4>(p.try_into().expect("four points"), q),
        _ => false,
    }
}

/// [`misses_quadratic_integers`] for a curve of `N` points (degree `N - 1`).
#[inline(always)]
fn misses<const N: usize>(p: &[[i64; 2]; N], [q0, q1, q2]: [[i64; 2]; 3]) -> bool {
    let n = N - 1;
    if cross_from(q0, q1, q2) == 0 {
        return false;
    }
    // a[i][k] = A_i(p_k); first at the ends, whose values f(p_0) = h_0 and f(p_n) = h_2n
    // must have one sign (else P meets the parabola: undecided at once).
    let mut a = [[0i64; N]; 3];
    let fill = |a: &mut [[i64; N]; 3], k: usize| {
        let x = p[k];
        a[0][k] = cross_from(x, q1, q2);
        a[1][k] = cross_from(x, q2, q0);
        a[2][k] = cross_from(x, q0, q1);
        (wide(a[1][k], a[1][k]) - 4 * wide(a[0][k], a[2][k])).signum()
    };
    if fill(&mut a, 0) * fill(&mut a, n) != 1 {
        return false;
    }
    for k in 1..n {
        fill(&mut a, k);
    }
    let sign = (wide(a[1][0], a[1][0]) - 4 * wide(a[0][0], a[2][0])).signum();
    for m in 1..2 * n {
        let mut h = 0i128;
        for j in m.saturating_sub(n)..=m.min(n) {
            let k = m - j;
            let weight = i128::from(BINOMIAL[n][j] * BINOMIAL[n][k]);
            h += weight * (wide(a[1][j], a[1][k]) - 4 * wide(a[0][j], a[2][k]));
        }
        if h.signum() != sign {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::curves::intersect_curves_f64;
    use crate::test_rng::XorShift;

    /// Whenever the test says "no common point", the exact intersector finds none; and it
    /// does say so for most pairs of small-integer curves that the exact intersector finds
    /// apart (it cannot be a constant `false`).
    #[test]
    fn misses_only_curves_the_exact_intersector_finds_apart() {
        let mut r = XorShift(0x1a2b_3c4d_5e6f_7081);
        let mut int = |k: u64| (r.next() % (2 * k + 1)) as f64 - k as f64;
        let (mut proved, mut apart) = (0, 0);
        for trial in 0..600 {
            let n = 1 + trial % 3;
            let q: Vec<[f64; 2]> = (0..3).map(|_| [int(40), int(40)]).collect();
            // Halves as well as integers: the dyadic scale.
            let p: Vec<[f64; 2]> = (0..=n).map(|_| [int(80) / 2.0, int(80) / 2.0]).collect();
            let exact = intersect_curves_f64(&p, &q).unwrap();
            let none = exact.points.is_empty() && exact.overlaps.is_empty();
            apart += usize::from(none);
            if misses_quadratic(&p, &q) {
                assert!(none, "{p:?} {q:?}: {exact:?}");
                proved += 1;
            }
        }
        assert!(proved * 2 > apart, "proved {proved} of {apart} pairs apart");
    }

    /// A curve and the same quadratic moved a little (the neighbouring copies of a glyph):
    /// apart, and proved so; on the quadratic itself and through it, never.
    #[test]
    fn copies_side_by_side_are_proved_apart_and_touching_ones_are_not() {
        let q = [[0.0, 0.0], [100.0, 300.0], [400.0, 320.0]];
        let moved = q.map(|[x, y]| [x + 20.0, y - 5.0]);
        assert!(intersect_curves_f64(&moved, &q).unwrap().points.is_empty());
        assert!(misses_quadratic(&moved, &q));
        // A segment from one end of q: a common point, never proved apart.
        assert!(!misses_quadratic(&[[0.0, 0.0], [50.0, -50.0]], &q));
        // A chord of q crosses it at its ends.
        assert!(!misses_quadratic(&[[0.0, 0.0], [400.0, 320.0]], &q));
        // Not a quadratic on the implicit side, or a straight one: undecided.
        assert!(!misses_quadratic(
            &q,
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]
        ));
        assert!(!misses_quadratic(
            &moved,
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]
        ));
        // Coordinates beyond the fixed-width bound: undecided.
        let far = q.map(|[x, y]| [x * 1e9, y]);
        assert!(!misses_quadratic(&moved, &far));
    }
}
