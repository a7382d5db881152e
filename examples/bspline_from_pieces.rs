//! A piecewise polynomial written as a B-spline (Curry-Schoenberg, Theorem 2.4 of seed 002)
//! and evaluated by de Boor's algorithm (Theorem 2.3).
//!
//! `cargo run -p blossom --example bspline_from_pieces`.
//!
//! Three cubic pieces of the plane on [0, 1], [1, 2], [2, 4]. Where two pieces meet with
//! continuity C^r the breakpoint becomes a knot of multiplicity p - r (here p = 3), and the de
//! Boor points are blossom values of the pieces: d_k = f_s(t_(k+1), ..., t_(k+p)) (Theorem 2.2).

use blossom::{bspline_from_pieces, continuity_at, Piece, PowerCurve, Rational};

pub fn main() {
    let q = |n: i64| Rational::from_integer(n.into());
    let poly = |c: &[[i64; 2]]| PowerCurve::new(c.iter().map(|p| p.map(q).to_vec()).collect());

    // F_0(u) = (u, u^3) on [0, 1].
    let f0 = poly(&[[0, 0], [1, 0], [0, 0], [0, 1]]).unwrap();
    // F_1 = F_0 + (u - 1)^3 (1, 0) on [1, 2]: value, slope and curvature agree at 1, so C^2.
    let f1 = poly(&[[-1, 0], [4, 0], [-3, 0], [1, 1]]).unwrap();
    // F_2 = F_1 + (u - 2)^2 (0, 1) on [2, 4]: value and slope agree at 2, so C^1.
    let f2 = poly(&[[-1, 4], [4, -4], [-3, 1], [1, 1]]).unwrap();
    let pieces = vec![
        Piece {
            interval: [q(0), q(1)],
            curve: f0,
        },
        Piece {
            interval: [q(1), q(2)],
            curve: f1,
        },
        Piece {
            interval: [q(2), q(4)],
            curve: f2,
        },
    ];
    assert_eq!(continuity_at(&pieces[0].curve, &pieces[1].curve, &q(1)), 2);
    assert_eq!(continuity_at(&pieces[1].curve, &pieces[2].curve, &q(2)), 1);

    let spline = bspline_from_pieces(3, &pieces).unwrap();
    // End knots of multiplicity p + 1 = 4; 1 once (C^2), 2 twice (C^1).
    assert_eq!(spline.knots(), &[0, 0, 0, 0, 1, 2, 2, 4, 4, 4, 4].map(q));
    assert_eq!(spline.control_points().len(), 7);

    // De Boor's algorithm gives back every piece, exactly, on its interval.
    for piece in &pieces {
        let [a, b] = &piece.interval;
        for k in 0..=4 {
            let u = a + (b - a) * Rational::new(k.into(), 4.into());
            assert_eq!(spline.eval(&u).unwrap(), piece.curve.eval(&u));
        }
    }
    println!(
        "knots: {}",
        spline
            .knots()
            .iter()
            .map(|t| t.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
    for d in spline.control_points() {
        println!("de Boor point ({}, {})", d[0], d[1]);
    }
    // Outside the domain [0, 4] de Boor's algorithm is an error, not an extrapolation.
    assert!(spline.eval(&q(5)).is_err());
}
