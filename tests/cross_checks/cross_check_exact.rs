//! Exact random cross-checks at degrees beyond the symbolic proofs: every method against the
//! bulk path, with big rationals, curves up to degree 20 and triangles up to N = 10.

mod common;

use blossom::{restrict_curve, restrict_tensor, restrict_triangle, Method, Rational};
use common::Rng;

#[test]
fn curves_agree_up_to_degree_20() {
    let mut rng = Rng(1);
    for n in 0..=20 {
        let curve = rng.curve(n, 2);
        let (a, b) = (rng.rational(), rng.rational());
        let bulk = restrict_curve(&curve, &a, &b, Method::Bulk);
        // End points interpolate: w_0 = C(a), w_n = C(b).
        assert_eq!(bulk.control_points()[0], curve.eval(&a));
        assert_eq!(bulk.control_points()[n], curve.eval(&b));
        for method in Method::ALL {
            assert_eq!(
                restrict_curve(&curve, &a, &b, method),
                bulk,
                "{method:?} n={n}"
            );
        }
    }
}

#[test]
fn tensor_patches_agree_up_to_6_by_6() {
    let mut rng = Rng(2);
    for n in 0..=6 {
        for m in 0..=6 {
            let s = rng.surface(n, m, 2);
            let rect: [Rational; 4] = std::array::from_fn(|_| rng.rational());
            let bulk = restrict_tensor(&s, &rect, Method::Bulk);
            assert_eq!(bulk.control_points()[n][m], s.eval(&rect[1], &rect[3]));
            for method in Method::ALL {
                assert_eq!(
                    restrict_tensor(&s, &rect, method),
                    bulk,
                    "{method:?} ({n},{m})"
                );
            }
        }
    }
}

#[test]
fn triangles_agree_up_to_total_degree_10() {
    let mut rng = Rng(3);
    for big_n in 0..=10 {
        for n in 0..=big_n {
            let m = big_n - n;
            let s = rng.surface(n, m, 1);
            let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
            let bulk = restrict_triangle(&s, &tri, Method::Bulk);
            // Corners interpolate: q_{N00} = S(a), q_{0N0} = S(b), q_{00N} = S(c).
            assert_eq!(bulk.get(big_n, 0), &s.eval(&tri[0][0], &tri[0][1]));
            assert_eq!(bulk.get(0, big_n), &s.eval(&tri[1][0], &tri[1][1]));
            assert_eq!(bulk.get(0, 0), &s.eval(&tri[2][0], &tri[2][1]));
            for method in Method::ALL {
                // The per-point closed form and the definition are slow at N = 10: sample.
                if big_n > 7
                    && n % 3 != 0
                    && matches!(method, Method::ClosedForm | Method::Polarisation)
                {
                    continue;
                }
                assert_eq!(
                    restrict_triangle(&s, &tri, method),
                    bulk,
                    "{method:?} ({n},{m})"
                );
            }
        }
    }
}
