//! Exact random cross-checks at degrees beyond the symbolic proofs, with big rationals, curves
//! up to degree 20 and triangles up to N = 10: every method against the subset-sum definition
//! (eqs. (2), (8), (13)), never a method against itself.
//!
//! The reference is `Method::Definition`; the methods compared with it are the other ones of
//! `Method::ALL` (bulk, closed form, pyramid, polarisation), none of which computes through
//! the definition or through one another. Each check records the methods it compared and
//! asserts that the default, `Method::Bulk`, was one of them. Besides, the end points and
//! corners of the definition's answer are the curve or surface evaluated by Horner's rule.

use crate::common::Rng;
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
    Rational,
};

/// The methods compared with the definition: every other one.
fn against_the_definition() -> impl Iterator<Item = Method> {
    Method::ALL
        .into_iter()
        .filter(|&method| method != Method::Definition)
}

/// `checked` holds the bulk path and every other method but the definition.
fn assert_compared_with_the_definition(checked: &[Method]) {
    assert!(checked.contains(&Method::Bulk), "{checked:?}");
    for method in against_the_definition() {
        assert!(checked.contains(&method), "{method:?} never checked");
    }
}

#[test]
fn curves_agree_up_to_degree_20() {
    let mut rng = Rng(1);
    let mut checked = Vec::new();
    for n in 0..=20 {
        let curve = rng.curve(n, 2);
        let (a, b) = (rng.rational(), rng.rational());
        let reference = restrict_power_curve(&curve, &a, &b, Method::Definition);
        // End points interpolate: w_0 = C(a), w_n = C(b).
        assert_eq!(reference.control_points()[0], curve.eval(&a));
        assert_eq!(reference.control_points()[n], curve.eval(&b));
        for method in against_the_definition() {
            assert_eq!(
                restrict_power_curve(&curve, &a, &b, method),
                reference,
                "{method:?} against the definition, n={n}"
            );
            checked.push(method);
        }
    }
    assert_compared_with_the_definition(&checked);
}

#[test]
fn tensor_patches_agree_up_to_6_by_6() {
    let mut rng = Rng(2);
    let mut checked = Vec::new();
    for n in 0..=6 {
        for m in 0..=6 {
            let s = rng.surface(n, m, 2);
            let rect: [Rational; 4] = std::array::from_fn(|_| rng.rational());
            let reference = restrict_power_surface(&s, &rect, Method::Definition);
            // Corners interpolate: p_00 = S(a, c), p_nm = S(b, d).
            assert_eq!(reference.to_nested()[0][0], s.eval(&rect[0], &rect[2]));
            assert_eq!(reference.to_nested()[n][m], s.eval(&rect[1], &rect[3]));
            for method in against_the_definition() {
                assert_eq!(
                    restrict_power_surface(&s, &rect, method),
                    reference,
                    "{method:?} against the definition, ({n},{m})"
                );
                checked.push(method);
            }
        }
    }
    assert_compared_with_the_definition(&checked);
}

#[test]
fn triangles_agree_up_to_total_degree_10() {
    let mut rng = Rng(3);
    let mut checked = Vec::new();
    for big_n in 0..=10 {
        for n in 0..=big_n {
            let m = big_n - n;
            let s = rng.surface(n, m, 1);
            let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
            let reference = restrict_power_surface_to_triangle(&s, &tri, Method::Definition);
            // Corners interpolate: q_{N00} = S(a), q_{0N0} = S(b), q_{00N} = S(c).
            assert_eq!(reference.get(big_n, 0), &s.eval(&tri[0][0], &tri[0][1]));
            assert_eq!(reference.get(0, big_n), &s.eval(&tri[1][0], &tri[1][1]));
            assert_eq!(reference.get(0, 0), &s.eval(&tri[2][0], &tri[2][1]));
            for method in against_the_definition() {
                // The per-point closed form and the polarisation formula are slow at N = 10:
                // sample.
                if big_n > 7
                    && n % 3 != 0
                    && matches!(method, Method::ClosedForm | Method::Polarisation)
                {
                    continue;
                }
                assert_eq!(
                    restrict_power_surface_to_triangle(&s, &tri, method),
                    reference,
                    "{method:?} against the definition, ({n},{m})"
                );
                checked.push(method);
            }
        }
    }
    assert_compared_with_the_definition(&checked);
}
