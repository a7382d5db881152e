//! Seed 002, Ejemplo 1 (its Figura 1): the cubic B-spline F(t) = sum d_k N_k^3(t) with the de
//! Boor points d_1 = (6, 3), ..., d_8 = (4, 4) on the knot vector
//! T = (0, 0, 0, 0, 1, 2, 4, 5, 6, 6, 6, 6) of the application of Theorem 2.2 (the printed
//! 13-knot vector has one 6 too many, see `blossom verify`).
//!
//! The curve is evaluated by the library's de Boor algorithm ([`BSpline::eval`], Theorem 2.3:
//! F(t) = f_s(t, t, t), the blossom of the piece on the span of t); the images F(t_j) of the
//! distinct knots, where the polynomial pieces join, are marked on it.

use super::mesh::{point3, point3_f64, sample, to_f64};
use super::palette::{CURVE, DOTS, DOTS_3, NET, TEXT};
use super::scene::{Figure, Layer, Point3, View};
use crate::verify::seeds_002_004::splines::{knots, points, EXAMPLE_1_POINTS, THEOREM_2_2_KNOTS};
use blossom::{rational_to_f64, BSpline, Error, Rational};

/// The samples of the drawn curve.
const SAMPLES: usize = 400;
/// Where the names of the de Boor points and the knots go, relative to their dots.
const ABOVE: (i32, i32) = (9, -22);
const BELOW: (i32, i32) = (9, 4);

/// The exact B-spline of Ejemplo 1 on the corrected knot vector.
pub fn example_1() -> Result<BSpline<Rational>, Error> {
    BSpline::new(3, knots(THEOREM_2_2_KNOTS), points(&EXAMPLE_1_POINTS))
}

/// The distinct knots of the domain with F(t_j) by the de Boor algorithm, exactly.
pub fn knot_images(f: &BSpline<Rational>) -> Result<Vec<(Rational, Vec<Rational>)>, Error> {
    let mut distinct: Vec<Rational> = f.knots().to_vec();
    distinct.dedup();
    distinct
        .into_iter()
        .map(|t| Ok((t.clone(), f.eval(&t)?)))
        .collect()
}

/// The picture: the curve, the de Boor polygon with its points, the knot images.
pub fn figure() -> Result<Figure, Error> {
    let f = example_1()?;
    let fast = BSpline::new(
        3,
        f.knots().iter().map(rational_to_f64).collect(),
        f.control_points().iter().map(to_f64).collect(),
    )?;
    let (a, b) = fast.domain();
    let curve = sample(*a, *b, SAMPLES, |t| {
        fast.eval(&t).ok().map(|p| point3_f64(&p))
    });
    let polygon: Vec<Point3> = f.control_points().iter().map(point3).collect();
    let knots = knot_images(&f)?;
    let knot_points: Vec<Point3> = knots.iter().map(|(_, p)| point3(p)).collect();
    let layers = vec![
        Layer::lines(vec![polygon.clone()], NET, 1),
        Layer::lines(vec![curve], CURVE, 2),
        Layer::dots(polygon.clone(), DOTS, 5),
        Layer::dots(knot_points.clone(), DOTS_3, 4),
        Layer::Labels {
            items: polygon
                .iter()
                .enumerate()
                .map(|(k, p)| (*p, format!("d_{}", k + 1)))
                .collect(),
            colour: TEXT,
            offset: ABOVE,
        },
        Layer::Labels {
            items: knots
                .iter()
                .zip(&knot_points)
                .map(|((t, _), p)| (*p, format!("t = {t}")))
                .collect(),
            colour: CURVE,
            offset: BELOW,
        },
    ];
    Ok(Figure {
        file: "bspline_de_boor.svg",
        title: "Seed 002, Ejemplo 1: cubic B-spline on T = (0,0,0,0,1,2,4,5,6,6,6,6)".into(),
        legend: vec![
            (CURVE, "F(t) by de Boor's algorithm".into()),
            (DOTS, "de Boor points d_1 .. d_8".into()),
            (DOTS_3, "F(t_j) at the knots".into()),
            (NET, "de Boor polygon".into()),
        ],
        view: View::plane_around(&layers, true),
        layers,
    })
}
