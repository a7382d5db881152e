//! Seed 004, section 4, Example 3: the curve b(t) = (t, ln t) on [1/2, 1] approximated by the
//! cubic Bézier curve whose control points are the values b[alpha^(3-i), beta^i] of the
//! inverse formula (22), as if b were a cubic. The control points are exact combinations of
//! ln 2, ln 3, ln 5 (computed by `verify`'s Example 3), evaluated here with ln p to about 50
//! digits and rounded to f64.
//!
//! Two pictures: the cubic with its control polygon against ln t, and the error of the cubic,
//! y(s) - ln x(s) along its parameter s (x(s) = t exactly, so this is the vertical distance).

use super::mesh::{curve_against_reference, point3, point3_f64, sample};
use super::palette::{CURVE, DOTS, NET, REFERENCE};
use super::scene::{Figure, Layer, Point3, View};
use crate::verify::seeds_002_004::logarithm::{cubic, value};
use blossom::{rational_to_f64, BezierCurve, Error, Rational};

/// The samples of each drawn curve.
const SAMPLES: usize = 200;

/// The control points of the cubic, exact up to the ~50-digit values of ln 2, ln 3, ln 5.
pub fn control_points() -> Vec<Vec<Rational>> {
    cubic()
        .iter()
        .map(|p| p.iter().map(value).collect())
        .collect()
}

fn bezier() -> Result<(Vec<Point3>, BezierCurve<f64>), Error> {
    let exact = control_points();
    let polygon: Vec<Point3> = exact.iter().map(|p| point3(p)).collect();
    let fast = BezierCurve::new(
        exact
            .iter()
            .map(|p| p.iter().map(rational_to_f64).collect())
            .collect(),
    )?;
    Ok((polygon, fast))
}

/// The cubic and its control polygon against ln t.
pub fn figure() -> Result<Figure, Error> {
    let (polygon, fast) = bezier()?;
    let curve = sample(0.0, 1.0, SAMPLES, |s| Some(point3_f64(&fast.eval(&s))));
    let ln = sample(0.5, 1.0, SAMPLES, |t| Some([t, t.ln(), 0.0]));
    let layers = curve_against_reference(ln, curve, polygon);
    Ok(Figure {
        file: "ln_cubic.svg",
        title: "Seed 004, Example 3: ln t on [1/2, 1] and the cubic of formula (22)".into(),
        legend: vec![
            (REFERENCE, "(t, ln t)".into()),
            (CURVE, "the cubic".into()),
            (DOTS, "control points b~_0 .. b~_3".into()),
            (NET, "control polygon".into()),
        ],
        view: View::plane_around(&layers, false),
        layers,
    })
}

/// The error y(s) - ln x(s) of the cubic against x(s).
pub fn error_figure() -> Result<Figure, Error> {
    let (_, fast) = bezier()?;
    let error = sample(0.0, 1.0, SAMPLES, |s| {
        let p = fast.eval(&s);
        match p[..] {
            [x, y] => Some([x, y - x.ln(), 0.0]),
            _ => None,
        }
    });
    let axis = vec![[0.5, 0.0, 0.0], [1.0, 0.0, 0.0]];
    let layers = vec![
        Layer::lines(vec![axis], REFERENCE, 2),
        Layer::lines(vec![error], CURVE, 2),
    ];
    Ok(Figure {
        file: "ln_cubic_error.svg",
        title: "Seed 004, Example 3: the error y(s) - ln x(s) of the cubic".into(),
        legend: vec![(CURVE, "error against x(s) = t".into())],
        view: View::plane_around(&layers, false),
        layers,
    })
}
