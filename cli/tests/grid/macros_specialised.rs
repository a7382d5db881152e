//! The carried grid and its dispatch: exactly the documented degrees are carried, and each
//! carried evaluator agrees with the bulk restriction (f64, 3-D points, random inputs) and,
//! exactly, with the subset-sum definition on rationals for a sample.
#![cfg(feature = "carried-grid")]

use crate::common::{q, Rng};
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
    PowerCurve, PowerSurface, Rational,
};
use blossom_cli::specialised::{
    carried_degrees, carries, restrict_curve_specialised, restrict_tensor_specialised,
    restrict_triangle_specialised, Shape,
};

/// A 3-D point of doubles in [-1, 1].
fn point(rng: &mut Rng) -> Vec<f64> {
    (0..3).map(|_| rng.unit()).collect()
}

fn close(x: &[Vec<f64>], y: &[Vec<f64>]) -> bool {
    x.iter()
        .flatten()
        .zip(y.iter().flatten())
        .all(|(a, b)| (a - b).abs() <= 1e-9 * (1.0 + b.abs()))
}

#[test]
fn exactly_the_documented_curves_are_carried() {
    let mut rng = Rng(1);
    for n in 0..=18 {
        let curve = PowerCurve::new((0..=n).map(|_| point(&mut rng)).collect()).unwrap();
        let (a, b) = (rng.unit(), rng.unit() + 2.0);
        let got = restrict_curve_specialised(&curve, &a, &b);
        assert_eq!(got.is_some(), carries(Shape::Curve(n)), "curve {n}");
        assert_eq!(carries(Shape::Curve(n)), (1..=16).contains(&n));
        if let Some(w) = got {
            let want = restrict_power_curve(&curve, &a, &b, Method::Bulk);
            assert!(
                close(
                    &w.control_points().to_vec(),
                    &want.control_points().to_vec()
                ),
                "curve {n}"
            );
        }
    }
    assert!(carried_degrees().contains("curves of degree 1..=16"));
}

#[test]
fn exactly_the_documented_surfaces_are_carried() {
    let mut rng = Rng(2);
    for n in 0..=6 {
        for m in 0..=6 {
            let s = PowerSurface::new(
                (0..=n)
                    .map(|_| (0..=m).map(|_| point(&mut rng)).collect())
                    .collect(),
            )
            .unwrap();
            let rect = [rng.unit(), rng.unit() + 2.0, rng.unit(), rng.unit() + 2.0];
            let got = restrict_tensor_specialised(&s, &rect);
            assert_eq!(
                got.is_some(),
                n <= 5 && m <= 5 && (n, m) != (0, 0),
                "tensor ({n}, {m})"
            );
            if let Some(p) = got {
                let want = restrict_power_surface(&s, &rect, Method::Bulk);
                for (x, y) in p.to_nested().iter().zip(want.to_nested()) {
                    assert!(close(x, &y), "tensor ({n}, {m})");
                }
            }
            let tri = [
                [rng.unit(), rng.unit()],
                [rng.unit() + 2.0, rng.unit()],
                [rng.unit(), rng.unit() + 2.0],
            ];
            let got = restrict_triangle_specialised(&s, &tri);
            assert_eq!(
                got.is_some(),
                n <= 4 && m <= 4 && (n, m) != (0, 0),
                "triangle ({n}, {m})"
            );
            if let Some(q) = got {
                let want = restrict_power_surface_to_triangle(&s, &tri, Method::Bulk);
                assert!(
                    close(
                        &q.control_points().to_vec(),
                        &want.control_points().to_vec()
                    ),
                    "triangle ({n}, {m})"
                );
            }
        }
    }
}

/// Exactness on rationals, through the generated functions of the grid directly (2-D points,
/// one instantiation each: the dispatch above already instantiates every carried evaluator
/// for f64, and instantiating the whole grid a second time would double this test's build).
#[test]
fn carried_evaluators_are_exact_on_rationals() {
    use blossom_cli::specialised::grid;
    let coef: [[[Rational; 2]; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| [q(i as i64 - 2 * j as i64, 3), q((i * j) as i64 + 1, 7)])
    });
    let s = PowerSurface::new(
        coef.iter()
            .map(|r| r.iter().map(|p| p.to_vec()).collect())
            .collect(),
    )
    .unwrap();
    let tri = [[q(0, 1), q(1, 2)], [q(1, 2), q(0, 1)], [q(1, 2), q(1, 2)]];
    let got = grid::triangle_2_2(&coef, &tri);
    let want = restrict_power_surface_to_triangle(&s, &tri, Method::Definition);
    assert_eq!(got.map(|p| p.to_vec()).to_vec(), want.control_points());
    let rect = [q(1, 3), q(2, 3), q(-1, 4), q(3, 4)];
    let got = grid::tensor_2_2(&coef, &rect);
    let want = restrict_power_surface(&s, &rect, Method::Definition);
    let got: Vec<Vec<Vec<Rational>>> = got
        .iter()
        .map(|r| r.iter().map(|p| p.to_vec()).collect())
        .collect();
    assert_eq!(got, want.to_nested());
    let c: [[Rational; 1]; 17] = std::array::from_fn(|i| [q((i * i) as i64 - 7, i as i64 + 1)]);
    let curve = PowerCurve::new(c.iter().map(|p| p.to_vec()).collect()).unwrap();
    let got = grid::curve_16(&c, &q(-2, 3), &q(5, 4));
    let want = restrict_power_curve(&curve, &q(-2, 3), &q(5, 4), Method::Definition);
    assert_eq!(got.map(|p| p.to_vec()).to_vec(), want.control_points());
}
