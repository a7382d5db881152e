//! Degree elevation and reduction: symbolic proof that exact elevation equals the inverse
//! formula's built-in elevation, reproduction of lower-degree curves by every reduction,
//! optimality of the least-squares reductions, and Example 2 of seed 004 with a snapshot.

use crate::common::{q, Rng};
use blossom::curve_control_points_from_samples;
use blossom::engine::bernstein_gram;
use blossom::{elevate, reduce, squared_l2_distance, Reduction};
use blossom::{BezierCurve, Poly, Rational, Ring};

fn random_bezier(rng: &mut Rng, n: usize, dim: usize) -> BezierCurve<Rational> {
    BezierCurve::new((0..=n).map(|_| rng.point(dim)).collect()).unwrap()
}

#[test]
fn elevation_is_the_inverse_formula_at_the_higher_degree_symbolically() {
    // Control points are symbols: the identity holds for every curve of degree n.
    for n in 0..=4usize {
        let b =
            BezierCurve::new((0..=n).map(|i| vec![Poly::var(&format!("b{i}"))]).collect()).unwrap();
        for m in n..=n + 3 {
            let by_formula =
                curve_control_points_from_samples(m, &Poly::zero(), &Poly::one(), &|t| b.eval(t));
            assert_eq!(
                elevate(&b, m).unwrap().control_points(),
                by_formula.as_slice(),
                "n={n} m={m}"
            );
        }
    }
}

#[test]
fn elevation_keeps_the_curve() {
    let mut rng = Rng(50);
    for n in 0..=8 {
        let b = random_bezier(&mut rng, n, 2);
        let e = elevate(&b, n + 3).unwrap();
        for k in 0..=6 {
            let t = q(k, 5) - q(1, 10);
            assert_eq!(e.eval(&t), b.eval(&t));
        }
        assert_eq!(squared_l2_distance(&e, &b).unwrap(), q(0, 1));
    }
}

#[test]
fn every_reduction_reproduces_curves_of_the_lower_degree() {
    let mut rng = Rng(51);
    for m in 1..=5 {
        let b = random_bezier(&mut rng, m, 2);
        for n in m + 1..=m + 3 {
            let high = elevate(&b, n).unwrap();
            for method in Reduction::ALL {
                assert_eq!(
                    reduce(&high, m, method).unwrap(),
                    b,
                    "{method:?} {m} <- {n}"
                );
            }
        }
    }
}

#[test]
fn least_squares_are_optimal_and_keep_what_they_promise() {
    let mut rng = Rng(52);
    for n in 2..=7 {
        let b = random_bezier(&mut rng, n, 2);
        for m in 1..n {
            let ls = reduce(&b, m, Reduction::LeastSquares).unwrap();
            let lse = reduce(&b, m, Reduction::LeastSquaresEndpoints).unwrap();
            let interp = reduce(&b, m, Reduction::Interpolating).unwrap();
            let err = |c: &BezierCurve<Rational>| squared_l2_distance(c, &b).unwrap();
            assert!(
                err(&ls) <= err(&lse) && err(&lse) <= err(&interp),
                "n={n} m={m}"
            );
            for c in [&lse, &interp] {
                assert_eq!(c.control_points()[0], b.control_points()[0]);
                assert_eq!(c.control_points()[m], b.control_points()[n]);
            }
            // Residual orthogonal to every B_i^m (free) and to the interior ones (constrained):
            // int (x - b) B_i^m = sum_j G_mm[i][j] x_j - sum_k G_mn[i][k] b_k = 0.
            let (gmm, gmn) = (bernstein_gram(m, m), bernstein_gram(m, n));
            let residual = |x: &BezierCurve<Rational>, i: usize, d: usize| {
                let a: Rational = (0..=m)
                    .map(|j| &gmm[i][j] * &x.control_points()[j][d])
                    .sum();
                let c: Rational = (0..=n)
                    .map(|k| &gmn[i][k] * &b.control_points()[k][d])
                    .sum();
                a - c
            };
            for d in 0..2 {
                for i in 0..=m {
                    assert_eq!(residual(&ls, i, d), q(0, 1));
                    if i > 0 && i < m {
                        assert_eq!(residual(&lse, i, d), q(0, 1));
                    }
                }
            }
            // Perturbing any control point of the free optimum makes it worse.
            for i in 0..=m {
                let mut pts = ls.control_points().to_vec();
                pts[i][1] = &pts[i][1] + q(1, 1000);
                assert!(err(&BezierCurve::new(pts).unwrap()) > err(&ls));
            }
        }
    }
}

#[test]
fn floats_follow_the_exact_reductions() {
    let mut rng = Rng(53);
    let b = random_bezier(&mut rng, 8, 3);
    let to_f = |x: &Rational| blossom::rational_to_f64(x);
    let bf = BezierCurve::new(
        b.control_points()
            .iter()
            .map(|p| p.iter().map(to_f).collect())
            .collect(),
    )
    .unwrap();
    for method in Reduction::ALL {
        let exact = reduce(&b, 4, method).unwrap();
        let float = reduce(&bf, 4, method).unwrap();
        for (p, r) in exact.control_points().iter().zip(float.control_points()) {
            for (x, y) in p.iter().zip(r) {
                assert!(
                    (to_f(x) - y).abs() < 1e-8 * (1.0 + y.abs()),
                    "{method:?}: {x} vs {y}"
                );
            }
        }
    }
}
