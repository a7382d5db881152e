//! Rational curves and surfaces through homogeneous blossoms: the rational Bézier forms agree
//! with N/w at every parameter, elevation through the degree argument agrees with exact
//! elevation of the homogeneous points, and the circle arc of seed 004 (with a snapshot).

use super::json::Json;
use crate::common::{q, Rng};
use blossom::{
    elevate, BSpline, ErrorKind, Rational, RationalBSpline, RationalCurve, RationalPowerTriangle,
    RationalSurface, Ring,
};

/// A denominator without zeros on [-1, 1]: c_0 = 5 and small other coefficients.
fn denominator(rng: &mut Rng, n: usize) -> Vec<Rational> {
    (0..=n)
        .map(|i| {
            if i == 0 {
                q(5, 1)
            } else {
                rng.rational() / q(40, 1)
            }
        })
        .collect()
}

#[test]
fn rational_bezier_forms_reproduce_the_curve() {
    let mut rng = Rng(60);
    for n in 0..=5 {
        let num: Vec<Vec<Rational>> = (0..=n).map(|_| rng.point(2)).collect();
        let den = denominator(&mut rng, (n + 1) % 4);
        let c = RationalCurve::new(&num, &den).unwrap();
        let (alpha, beta) = (q(-1, 2), q(3, 4));
        let own = c.degree();
        for degree in own..=own + 2 {
            let bez = c.bezier(&alpha, &beta, Some(degree)).unwrap();
            assert_eq!(bez.degree(), degree);
            for k in 0..=4 {
                let s = q(k, 4);
                let t = &alpha + (&beta - &alpha) * &s;
                assert_eq!(
                    bez.eval(&s).unwrap(),
                    c.eval(&t).unwrap(),
                    "n={n} degree={degree} s={s}"
                );
            }
            // Exact elevation of the own-degree points = the formula (22) at the higher degree.
            let by_formula = c.homogeneous_control_points(&alpha, &beta, degree).unwrap();
            assert_eq!(by_formula, bez.homogeneous());
            let low = c.bezier(&alpha, &beta, None).unwrap();
            let h = elevate(&low.homogeneous(), degree).unwrap();
            assert_eq!(h, by_formula);
        }
    }
}

#[test]
fn rational_surfaces_reproduce_the_surface() {
    let mut rng = Rng(61);
    for (n, m) in [(1, 1), (2, 1), (1, 2), (2, 2)] {
        let num: Vec<Vec<Vec<Rational>>> = (0..=n)
            .map(|_| (0..=m).map(|_| rng.point(3)).collect())
            .collect();
        let den: Vec<Vec<Rational>> = (0..=n)
            .map(|i| {
                (0..=m)
                    .map(|j| {
                        if i + j == 0 {
                            q(4, 1)
                        } else {
                            rng.rational() / q(50, 1)
                        }
                    })
                    .collect()
            })
            .collect();
        let s = RationalSurface::new(&num, &den).unwrap();
        let rect = [q(-1, 2), q(1, 2), q(0, 1), q(2, 3)];
        for degree in [(n, m), (n + 1, m + 1)] {
            let patch = s.tensor(&rect, Some(degree)).unwrap();
            assert_eq!(patch.degree(), degree);
            assert_eq!(patch.rows().len(), degree.0 + 1);
            for (a, b) in [(q(0, 1), q(0, 1)), (q(1, 3), q(3, 4)), (q(1, 1), q(1, 2))] {
                let u = &rect[0] + (&rect[1] - &rect[0]) * &a;
                let v = &rect[2] + (&rect[3] - &rect[2]) * &b;
                assert_eq!(patch.eval(&a, &b).unwrap(), s.eval(&u, &v).unwrap());
            }
        }
        let tri = [[q(0, 1), q(0, 1)], [q(1, 2), q(0, 1)], [q(0, 1), q(1, 2)]];
        for degree in [n + m, n + m + 1] {
            let patch = s.triangle(&tri, Some(degree)).unwrap();
            for bary in [
                [q(1, 1), q(0, 1), q(0, 1)],
                [q(1, 3), q(1, 3), q(1, 3)],
                [q(1, 6), q(1, 2), q(1, 3)],
            ] {
                let coord = |d: usize| (0..3).map(|k| &bary[k] * &tri[k][d]).sum::<Rational>();
                assert_eq!(
                    patch.eval(&[bary[0].clone(), bary[1].clone()]).unwrap(),
                    s.eval(&coord(0), &coord(1)).unwrap(),
                    "N = {degree}"
                );
            }
        }
        assert_eq!(
            s.triangle(&tri, Some(n + m - 1)).unwrap_err().field,
            "degree"
        );
    }
}

#[test]
fn nurbs_circle_through_homogeneous_de_boor() {
    // Two quarter circles as a quadratic NURBS on knots 0,0,0,1,2,2,2.
    // The arc of seed 004 on [0, 1]: points (1,0), (1,1), (0,1), weights 1, 1, 2; its mirror
    // image continues it on [1, 2].
    let f = RationalBSpline::new(
        2,
        [0, 0, 0, 1, 1, 2, 2, 2].map(|k| q(k, 1)).to_vec(),
        vec![
            vec![q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1)],
            vec![q(0, 1), q(1, 1)],
            vec![q(-1, 1), q(1, 1)],
            vec![q(-1, 1), q(0, 1)],
        ],
        vec![q(1, 1), q(1, 1), q(2, 1), q(1, 1), q(1, 1)],
    )
    .unwrap();
    for k in 0..=16 {
        let p = f.eval(&q(k, 8)).unwrap();
        assert_eq!(p[0].mul(&p[0]) + p[1].mul(&p[1]), q(1, 1), "t = {k}/8");
    }
    assert!(BSpline::new(2, vec![q(0, 1); 3], vec![vec![q(0, 1)]]).is_err());
}

#[test]
fn circle_arc_of_seed_004() {
    let arc = RationalCurve::new(
        &[
            vec![q(1, 1), q(0, 1)],
            vec![q(0, 1), q(2, 1)],
            vec![q(-1, 1), q(0, 1)],
        ],
        &[q(1, 1), q(0, 1), q(1, 1)],
    )
    .unwrap();
    let quad = arc.bezier(&q(0, 1), &q(1, 1), None).unwrap();
    let quartic = arc.bezier(&q(0, 1), &q(1, 1), Some(4)).unwrap();
    assert_eq!(
        quartic.weights(),
        &[q(1, 1), q(1, 1), q(7, 6), q(3, 2), q(2, 1)]
    );
    assert_eq!(quartic.points()[2], vec![q(5, 7), q(6, 7)]);
    let s = |v: &[Rational]| Json::strings(v);
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("nurbs_circle_arc", Json::object([
            ("quadratic", Json::object([("points", Json::array(quad.points().iter().map(&s))), ("weights", s(quad.weights()))])),
            ("quartic", Json::object([("points", Json::array(quartic.points().iter().map(&s))), ("weights", s(quartic.weights()))])),
        ]).pretty());
    });
}

#[test]
fn rational_triangles_from_triangular_arrays_and_at_their_true_degree() {
    let mut rng = Rng(0x2a771);
    let tri = [[q(0, 1), q(1, 3)], [q(1, 2), q(0, 1)], [q(-1, 4), q(1, 2)]];
    let barys = [
        [q(1, 1), q(0, 1), q(0, 1)],
        [q(1, 3), q(1, 3), q(1, 3)],
        [q(2, 3), q(-1, 2), q(5, 6)],
    ];
    let coord =
        |bary: &[Rational; 3], d: usize| (0..3).map(|k| &bary[k] * &tri[k][d]).sum::<Rational>();
    for big_n in 1..=4usize {
        let num: Vec<Vec<Vec<Rational>>> = (0..=big_n)
            .map(|i| (0..=big_n - i).map(|_| rng.point(2)).collect())
            .collect();
        let den: Vec<Vec<Rational>> = (0..=big_n)
            .map(|i| {
                (0..=big_n - i)
                    .map(|j| {
                        if i + j == 0 {
                            q(3, 1)
                        } else {
                            rng.rational() / q(40, 1)
                        }
                    })
                    .collect()
            })
            .collect();
        let s = RationalPowerTriangle::new(&num, &den).unwrap();
        assert_eq!(s.true_degree(), big_n);
        for degree in [big_n, big_n + 2] {
            let patch = s.triangle(&tri, Some(degree)).unwrap();
            assert_eq!(patch.degree(), degree);
            for bary in &barys {
                let (u, v) = (coord(bary, 0), coord(bary, 1));
                assert_eq!(
                    patch.eval(&[bary[0].clone(), bary[1].clone()]).unwrap(),
                    s.eval(&u, &v).unwrap(),
                    "N = {degree}"
                );
            }
        }
        let e = s.triangle(&tri, Some(big_n - 1)).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("degree", ErrorKind::Degree));
    }
    // x = (u + v) / (1 + u) on a (1, 1) grid: the u v terms are zero, true degree 1 < n + m = 2.
    let grid_num = vec![
        vec![vec![q(0, 1)], vec![q(1, 1)]],
        vec![vec![q(1, 1)], vec![q(0, 1)]],
    ];
    let grid_den = vec![vec![q(1, 1), q(0, 1)], vec![q(1, 1), q(0, 1)]];
    let s = RationalSurface::new(&grid_num, &grid_den).unwrap();
    let patch = s.triangle(&tri, Some(1)).unwrap();
    assert_eq!(patch.degree(), 1);
    for bary in &barys {
        let (u, v) = (coord(bary, 0), coord(bary, 1));
        assert_eq!(
            patch.eval(&[bary[0].clone(), bary[1].clone()]).unwrap(),
            s.eval(&u, &v).unwrap()
        );
    }
    assert_eq!(
        s.triangle(&tri, Some(0)).unwrap_err().kind(),
        ErrorKind::Degree
    );
    // Shapes: a denominator row of the wrong length, a numerator that is not triangular.
    let e = RationalPowerTriangle::new(
        &[vec![vec![q(1, 1)], vec![q(2, 1)]], vec![vec![q(3, 1)]]],
        &[vec![q(1, 1)], vec![q(1, 1)]],
    )
    .unwrap_err();
    assert_eq!((e.path(), e.kind()), ("denominator[0]", ErrorKind::Shape));
    let e = RationalPowerTriangle::new(
        &[
            vec![vec![q(1, 1)], vec![q(2, 1)]],
            vec![vec![q(3, 1)], vec![q(4, 1)]],
        ],
        &[vec![q(1, 1), q(0, 1)], vec![q(1, 1), q(0, 1)]],
    )
    .unwrap_err();
    assert_eq!((e.path(), e.kind()), ("numerator[1]", ErrorKind::Shape));
}
