//! Seed 004, section 4, Example 1: the circle arc b(t) = ((1 - t^2) / (1 + t^2), 2t / (1 + t^2))
//! on [alpha, beta] = [0, 1], a quarter of the unit circle, as a rational Bézier curve
//! sum w_i b_i B_i^n(s) / sum w_i B_i^n(s) of degree n = 2 and, with degree elevation built in,
//! n = 4.
//!
//! The homogeneous control points (w_i b_i, w_i) are the blossom values of
//! (1 - t^2, 2t, 1 + t^2) at alpha^(n-i) beta^i (the inverse formula (22));
//! [`RationalCurve::bezier`] computes them exactly at the curve's own degree and elevates.
//! The picture draws the rational curve from those points and weights (labelled), over the exact
//! arc (cos theta, sin theta).

use super::mesh::{curve_against_reference, point3, point3_f64, sample, to_f64};
use super::palette::{CURVE, DOTS, NET, REFERENCE, TEXT};
use super::scene::{Figure, Layer, Point3, View};
use blossom::{rational_to_f64, Error, Rational, RationalBezierCurve, RationalCurve, Ring};

/// The samples of each drawn curve.
const SAMPLES: usize = 200;

/// The arc as a rational curve: numerator (1 - t^2, 2t), denominator 1 + t^2.
pub fn arc() -> Result<RationalCurve<Rational>, Error> {
    let k = |n: i64| Rational::from_int(n);
    RationalCurve::new(
        &[vec![k(1), k(0)], vec![k(0), k(2)], vec![k(-1), k(0)]],
        &[k(1), k(0), k(1)],
    )
}

/// The rational Bézier form of the arc on [0, 1] at degree `n` (2 or more), exactly.
pub fn arc_bezier(n: usize) -> Result<RationalBezierCurve<Rational>, Error> {
    arc()?.bezier(&Rational::from_int(0), &Rational::from_int(1), Some(n))
}

/// The picture of the arc at degree `n` with its control polygon and weights.
pub fn figure(file: &'static str, n: usize) -> Result<Figure, Error> {
    let exact = arc_bezier(n)?;
    let fast = RationalBezierCurve::new(
        exact.points().iter().map(to_f64).collect(),
        exact.weights().iter().map(rational_to_f64).collect(),
    )?;
    let curve = sample(0.0, 1.0, SAMPLES, |s| fast.eval(&s).map(|p| point3_f64(&p)));
    let circle = sample(0.0, std::f64::consts::FRAC_PI_2, SAMPLES, |a| {
        Some([a.cos(), a.sin(), 0.0])
    });
    let polygon: Vec<Point3> = exact.points().iter().map(point3).collect();
    let mut layers = curve_against_reference(circle, curve, polygon.clone());
    layers.extend([Layer::Labels {
        items: polygon
            .iter()
            .zip(exact.weights())
            .enumerate()
            .map(|(i, (p, w))| (*p, format!("w_{i} = {w}")))
            .collect(),
        colour: TEXT,
        offset: (9, -22),
    }]);
    let name = if n == 2 { "quadratic" } else { "quartic" };
    Ok(Figure {
        file,
        title: format!("Seed 004, Example 1: the quarter circle as a rational {name} (n = {n})"),
        legend: vec![
            (REFERENCE, "the circle (cos a, sin a)".into()),
            (CURVE, "sum w_i b_i B_i / sum w_i B_i".into()),
            (DOTS, format!("control points b_0 .. b_{n}")),
            (NET, "control polygon".into()),
        ],
        view: View::plane_around(&layers, true),
        layers,
    })
}

/// The quadratic and the quartic.
pub fn figures() -> Result<Vec<Figure>, Error> {
    Ok(vec![
        figure("circle_quadratic.svg", 2)?,
        figure("circle_quartic.svg", 4)?,
    ])
}
