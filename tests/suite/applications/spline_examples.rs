//! Seed 002's worked examples as exact values, with snapshots, and the errors on bad input.

use super::json::Json;
use crate::common::q;
use blossom::{bspline_from_pieces, BSpline, KnotVector, Piece};
use blossom::{PowerCurve, Rational};

fn ints(v: &[i64]) -> Vec<Rational> {
    v.iter().map(|&k| q(k, 1)).collect()
}

fn pts(v: &[(i64, i64)]) -> Vec<Vec<Rational>> {
    v.iter().map(|&(x, y)| vec![q(x, 1), q(y, 1)]).collect()
}

/// The de Boor points d_1..d_8 of Ejemplo 1 of seed 002.
fn ejemplo_1_points() -> Vec<Vec<Rational>> {
    pts(&[
        (6, 3),
        (7, 8),
        (12, 5),
        (9, 0),
        (1, 0),
        (0, 6),
        (3, 8),
        (4, 4),
    ])
}

fn show(p: &[Rational]) -> Json {
    Json::strings(p)
}

macro_rules! snapshot {
    ($name:expr, $value:expr) => {
        insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"), prepend_module_to_snapshot => false}, {
            insta::assert_snapshot!($name, $value.pretty());
        });
    };
}

#[test]
fn curry_schoenberg_example() {
    let c = |rows: &[(i64, i64)]| PowerCurve::new(pts(rows)).unwrap();
    let pieces = vec![
        Piece {
            interval: [q(0, 1), q(1, 1)],
            curve: c(&[(0, 0), (1, 0), (0, 1)]),
        },
        Piece {
            interval: [q(1, 1), q(2, 1)],
            curve: c(&[(0, 0), (1, 0), (0, 0), (0, 1)]),
        },
        Piece {
            interval: [q(2, 1), q(3, 1)],
            curve: c(&[(0, -16), (1, 12)]),
        },
    ];
    let f = bspline_from_pieces(3, &pieces).unwrap();
    assert_eq!(
        f.knots(),
        ints(&[0, 0, 0, 0, 1, 1, 1, 2, 2, 3, 3, 3, 3]).as_slice()
    );
    let d: Vec<Vec<Rational>> = vec![
        vec![q(0, 1), q(0, 1)],
        vec![q(1, 3), q(0, 1)],
        vec![q(2, 3), q(1, 3)],
        vec![q(1, 1), q(1, 1)],
        vec![q(4, 3), q(2, 1)],
        vec![q(5, 3), q(4, 1)],
        vec![q(7, 3), q(12, 1)],
        vec![q(8, 3), q(16, 1)],
        vec![q(3, 1), q(20, 1)],
    ];
    assert_eq!(f.control_points(), d.as_slice());
    snapshot!(
        "spline_curry_schoenberg",
        Json::object([
            ("knots", show(f.knots())),
            (
                "de_boor_points",
                Json::array(f.control_points().iter().map(show))
            ),
            (
                "bezier_pieces",
                Json::array(f.bezier_pieces().iter().map(|b| Json::object([
                    ("interval", show(&b.interval)),
                    (
                        "control_points",
                        Json::array(b.curve.control_points().iter().map(show))
                    ),
                ])))
            ),
        ])
    );
}

#[test]
fn de_boor_example_f_of_four_fifths() {
    let f = BSpline::new(
        2,
        ints(&[0, 0, 0, 1, 2, 2, 2]),
        pts(&[(1, 1), (2, 3), (4, 3), (3, 1)]),
    )
    .unwrap();
    let (k, table) = f.de_boor(&q(4, 5)).unwrap();
    assert_eq!(k + 1, 3);
    assert_eq!(
        table[1],
        vec![vec![q(9, 5), q(13, 5)], vec![q(14, 5), q(3, 1)]]
    );
    assert_eq!(table[2], vec![vec![q(13, 5), q(73, 25)]]);
    snapshot!(
        "spline_de_boor_table",
        Json::object([
            ("span (1-based k)", Json::string(k + 1)),
            (
                "levels",
                Json::array(table.iter().map(|l| Json::array(l.iter().map(|p| show(p)))))
            ),
        ])
    );
}

#[test]
fn theorem_2_2_example_pieces() {
    let f = BSpline::new(
        3,
        ints(&[0, 0, 0, 0, 1, 2, 4, 5, 6, 6, 6, 6]),
        ejemplo_1_points(),
    )
    .unwrap();
    let pieces = f.power_pieces().unwrap();
    snapshot!(
        "spline_theorem_2_2_pieces",
        Json::array(
            pieces
                .iter()
                .zip(f.bezier_pieces())
                .map(|(p, b)| Json::object([
                    ("interval", show(&p.interval)),
                    (
                        "power_coefficients",
                        Json::array(p.curve.coefficients().iter().map(show))
                    ),
                    (
                        "bezier_points",
                        Json::array(b.curve.control_points().iter().map(show))
                    ),
                ]))
        )
    );
}

#[test]
fn bad_knot_vectors_and_parameters() {
    let e = |r: Result<KnotVector<Rational>, blossom::Error>| r.unwrap_err().to_string();
    assert_eq!(
        e(KnotVector::new(2, ints(&[0, 0, 0, 1, 1]))),
        "knots: a B-spline of degree 2 needs at least 6 knots (p + 1 <= m de Boor points), found 5"
    );
    assert_eq!(
        e(KnotVector::new(1, ints(&[0, 0, 2, 1, 3]))),
        "knots[3]: knots must be non-decreasing, found 1 after 2"
    );
    assert_eq!(
        e(KnotVector::new(1, ints(&[0, 1, 1, 1, 2]))),
        "knots[3]: the knot 1 has multiplicity above p + 1 = 2 (t_i < t_(i+p+1) fails)"
    );
    assert_eq!(
        e(KnotVector::new(0, ints(&[1, 1]))),
        "knots[1]: the knot 1 has multiplicity above p + 1 = 1 (t_i < t_(i+p+1) fails)"
    );
    // The printed Ejemplo 1 of seed 002: 13 knots for 8 points of a cubic.
    let bad = BSpline::new(
        3,
        ints(&[0, 0, 0, 0, 1, 2, 4, 5, 6, 6, 6, 6, 6]),
        ejemplo_1_points(),
    );
    assert_eq!(
        bad.unwrap_err().to_string(),
        "knots: 8 de Boor points of degree 3 need m + p + 1 = 12 knots, found 13"
    );
    let f = BSpline::new(
        3,
        ints(&[0, 1, 2, 3, 4, 5, 6, 7]),
        pts(&[(0, 0), (3, 9), (6, 3), (9, 6)]),
    )
    .unwrap();
    assert_eq!(f.domain(), (&q(3, 1), &q(4, 1)));
    assert_eq!(
        f.eval(&q(2, 1)).unwrap_err().to_string(),
        "t: the parameter 2 is outside the domain [3, 4] of the knot vector"
    );
    assert_eq!(f.eval(&q(9, 2)).unwrap_err().field, "t");
    // Uniform cubic: F(3) = (d_1 + 4 d_2 + d_3) / 6.
    assert_eq!(f.eval(&q(3, 1)).unwrap(), vec![q(3, 1), q(13, 2)]);
    assert!(BSpline::new(
        1,
        ints(&[0, 0, 1, 1]),
        vec![vec![q(0, 1)], vec![q(1, 1), q(2, 1)]]
    )
    .is_err());
    assert_eq!(
        BSpline::<Rational>::new(1, ints(&[0, 0, 1, 1]), vec![])
            .unwrap_err()
            .field,
        "control_points"
    );
}
