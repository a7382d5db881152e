//! The engine's symbolic proofs: bulk restriction, closed forms (3), (9), (14), pyramid and
//! polarisation identical as polynomials to the subset-sum definitions, for curves n <= 8,
//! tensor patches (n, m) <= (4, 4) and triangles N = n + m <= 6.

use blossom::proofs::{prove_curve, prove_tensor, prove_triangle, OTHER_METHODS};
use blossom::{restrict_curve, Method, Poly, PowerCurve};

#[test]
fn curves_up_to_degree_8() {
    for n in 0..=8 {
        for row in prove_curve(n, &OTHER_METHODS) {
            assert!(row.identical, "{row:?}");
        }
    }
}

#[test]
fn tensor_patches_up_to_4_by_4() {
    for n in 0..=4 {
        for m in 0..=4 {
            for row in prove_tensor(n, m, &OTHER_METHODS) {
                assert!(row.identical, "{row:?}");
            }
        }
    }
}

#[test]
fn triangles_up_to_total_degree_6() {
    for big_n in 0..=6 {
        for n in 0..=big_n {
            for row in prove_triangle(n, big_n - n, &OTHER_METHODS) {
                assert!(row.identical, "{row:?}");
            }
        }
    }
}

/// The proofs can fail: a wrong input (one coefficient perturbed) is told apart.
#[test]
fn a_perturbed_curve_is_not_proved_equal() {
    let n = 4;
    let good = blossom::proofs::symbolic_curve(n);
    let mut coefficients = good.coefficients().to_vec();
    coefficients[2][0] = coefficients[2][0].clone() + Poly::var("c3");
    let bad = PowerCurve::new(coefficients).unwrap();
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    assert_ne!(
        restrict_curve(&good, &a, &b, Method::Definition),
        restrict_curve(&bad, &a, &b, Method::Bulk)
    );
}
