//! Triangles of a given total degree (a triangular array c_ij, i + j <= N): every method gives
//! the same exact net, and the net is right, checked by evaluation: the triangular de Casteljau
//! algorithm on the net (`TriangularPatch::eval`, which no restriction calls) at barycentric
//! (r, s, t) must equal S(r a + s b + t c) by Horner's rule on the array.

use crate::common::Rng;
use blossom::{
    restrict_power_surface_to_triangle, restrict_power_triangle, Method, PowerTriangle, Rational,
    Ring,
};

fn random_array(rng: &mut Rng, big_n: usize, dim: usize) -> PowerTriangle<Rational> {
    PowerTriangle::new(
        (0..=big_n)
            .map(|i| (0..=big_n - i).map(|_| rng.point(dim)).collect())
            .collect(),
    )
    .unwrap()
}

fn random_triangle(rng: &mut Rng) -> [[Rational; 2]; 3] {
    std::array::from_fn(|_| [rng.rational(), rng.rational()])
}

#[test]
fn every_method_restricts_a_triangular_array_exactly() {
    let mut rng = Rng(0x7d07a1);
    for big_n in 0..=7 {
        for _ in 0..3 {
            let s = random_array(&mut rng, big_n, 2);
            let tri = random_triangle(&mut rng);
            let nets: Vec<_> = Method::ALL
                .iter()
                .map(|&m| restrict_power_triangle(&s, &tri, m))
                .collect();
            for (net, method) in nets.iter().zip(Method::ALL) {
                assert_eq!(net.degree(), big_n, "{method:?}");
                assert_eq!(net, &nets[0], "{method:?} differs from bulk at N = {big_n}");
            }
            for _ in 0..4 {
                let (r, t) = (rng.rational(), rng.rational());
                let bary = [r.clone(), Rational::one().sub(&r).sub(&t), t];
                let at = |x: usize| {
                    (0..3).fold(Rational::zero(), |acc, k| acc.add(&bary[k].mul(&tri[k][x])))
                };
                assert_eq!(
                    nets[0].eval(&[bary[0].clone(), bary[1].clone()]),
                    s.eval(&at(0), &at(1)),
                    "N = {big_n}"
                );
            }
        }
    }
}

#[test]
fn a_grid_is_restricted_at_degree_n_plus_m() {
    // Checked against the grid's own Horner evaluation (PowerSurface::eval) at random points,
    // by de Casteljau on the net: neither goes through the conversion to a PowerTriangle.
    let mut rng = Rng(0x912d);
    for (n, m) in [(0, 1), (1, 1), (2, 1), (1, 3), (3, 2)] {
        let grid = rng.surface(n, m, 2);
        let tri = random_triangle(&mut rng);
        for method in Method::ALL {
            let net = restrict_power_surface_to_triangle(&grid, &tri, method);
            assert_eq!(net.degree(), n + m, "{method:?}");
            for _ in 0..3 {
                let (r, t) = (rng.rational(), rng.rational());
                let bary = [r.clone(), Rational::one().sub(&r).sub(&t), t];
                let at = |x: usize| {
                    (0..3).fold(Rational::zero(), |acc, k| acc.add(&bary[k].mul(&tri[k][x])))
                };
                assert_eq!(
                    net.eval(&[bary[0].clone(), bary[1].clone()]),
                    grid.eval(&at(0), &at(1)),
                    "{method:?} at ({n}, {m})"
                );
            }
        }
    }
}

#[test]
fn u_plus_v_on_a_one_by_one_grid_is_the_degree_one_triangle_it_is() {
    // c_00 = 0, c_01 = 1, c_10 = 1, c_11 = 0: S = u + v, true total degree 1, not 2.
    let one = Rational::one();
    let zero = Rational::zero();
    let grid = blossom::PowerSurface::new(vec![
        vec![vec![zero.clone()], vec![one.clone()]],
        vec![vec![one.clone()], vec![zero.clone()]],
    ])
    .unwrap();
    let s = PowerTriangle::from_surface(&grid);
    assert_eq!((s.degree(), s.true_degree()), (2, 1));
    let low = s.at_degree(s.true_degree()).unwrap();
    let tri = [
        [one.clone(), zero.clone()],
        [zero.clone(), one.clone()],
        [zero.clone(), zero.clone()],
    ];
    for method in Method::ALL {
        let patch = restrict_power_triangle(&low, &tri, method);
        // S at the corners a = (1, 0), b = (0, 1), c = (0, 0): 1, 1, 0.
        assert_eq!(patch.degree(), 1, "{method:?}");
        assert_eq!(
            [patch.get(1, 0), patch.get(0, 1), patch.get(0, 0)],
            [&vec![one.clone()], &vec![one.clone()], &vec![zero.clone()]],
            "{method:?}"
        );
    }
}
