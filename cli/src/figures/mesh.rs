//! Exact Bézier patches and curves as the f64 polylines a picture draws: the iso-parameter
//! lines of a patch, evaluated by the library's de Casteljau ([`TensorPatch::eval`],
//! [`TriangularPatch::eval`]), and the lines of its control net.

use super::scene::{Layer, Point3};
use blossom::{rational_to_f64, Error, Point, Rational, TensorPatch, TriangularPatch};

/// Iso-parameter lines per direction of a patch.
pub const ISO_LINES: usize = 10;
/// Samples along one iso-parameter line or one curve.
pub const SAMPLES: usize = 48;

/// An exact point as a point of the picture (missing coordinates 0).
pub fn point3(p: &[Rational]) -> Point3 {
    let mut out = [0.0; 3];
    for (o, x) in out.iter_mut().zip(p) {
        *o = rational_to_f64(x);
    }
    out
}

/// An f64 point as a point of the picture (missing coordinates 0).
pub fn point3_f64(p: &[f64]) -> Point3 {
    let mut out = [0.0; 3];
    for (o, x) in out.iter_mut().zip(p) {
        *o = *x;
    }
    out
}

/// An exact point converted to f64 coordinate by coordinate.
pub fn to_f64(p: &[Rational]) -> Point<f64> {
    p.iter().map(rational_to_f64).collect()
}

/// The patch with its control points rounded to f64.
pub fn tensor_f64(patch: &TensorPatch<Rational>) -> Result<TensorPatch<f64>, Error> {
    TensorPatch::new(
        patch
            .to_nested()
            .iter()
            .map(|row| row.iter().map(|p| to_f64(p)).collect())
            .collect(),
    )
}

/// The patch with its control points rounded to f64.
pub fn triangle_f64(patch: &TriangularPatch<Rational>) -> Result<TriangularPatch<f64>, Error> {
    TriangularPatch::new(
        patch.degree(),
        patch.control_points().iter().map(to_f64).collect(),
    )
}

fn fraction(k: usize, of: usize) -> f64 {
    k as f64 / of as f64
}

/// The lines s = k / ISO_LINES and t = k / ISO_LINES of P(s, t) = sum p_{nu mu} B_nu^n(s)
/// B_mu^m(t) over [0, 1]^2 (eq. (6) of seed 000 on the reference square).
pub fn tensor_iso_lines(patch: &TensorPatch<f64>) -> Vec<Vec<Point3>> {
    let mut lines = Vec::new();
    for k in 0..=ISO_LINES {
        let fixed = fraction(k, ISO_LINES);
        let along_t = (0..=SAMPLES)
            .map(|j| point3_f64(&patch.eval(&fixed, &fraction(j, SAMPLES))))
            .collect();
        let along_s = (0..=SAMPLES)
            .map(|j| point3_f64(&patch.eval(&fraction(j, SAMPLES), &fixed)))
            .collect();
        lines.push(along_t);
        lines.push(along_s);
    }
    lines
}

/// The lines on which one barycentric coordinate is k / ISO_LINES, of
/// T(s, t, r) = sum q_{nu mu lambda} N! / (nu! mu! lambda!) s^nu t^mu r^lambda (eq. (12) of seed
/// 000 on the patch's own triangle).
pub fn triangle_iso_lines(patch: &TriangularPatch<f64>) -> Vec<Vec<Point3>> {
    let mut lines = Vec::new();
    for k in 0..ISO_LINES {
        let fixed = fraction(k, ISO_LINES);
        let rest = 1.0 - fixed;
        for which in 0..3 {
            let line = (0..=SAMPLES)
                .map(|j| {
                    let a = rest * fraction(j, SAMPLES);
                    let b = rest - a;
                    let bary = match which {
                        0 => [fixed, a, b],
                        1 => [b, fixed, a],
                        _ => [a, b, fixed],
                    };
                    point3_f64(&patch.eval(&[bary[0], bary[1]]))
                })
                .collect();
            lines.push(line);
        }
    }
    lines
}

/// The rows p_{nu, .} and the columns p_{., mu} of a tensor net.
pub fn tensor_net_lines(net: &[Vec<Point3>]) -> Vec<Vec<Point3>> {
    let mut lines: Vec<Vec<Point3>> = net.to_vec();
    let columns = net.first().map_or(0, Vec::len);
    for mu in 0..columns {
        lines.push(net.iter().filter_map(|row| row.get(mu).copied()).collect());
    }
    lines
}

/// The lines of a triangular net of degree N on which nu, mu or lambda is constant.
pub fn triangle_net_lines(patch: &TriangularPatch<Rational>) -> Vec<Vec<Point3>> {
    let n = patch.degree();
    let at = |nu: usize, mu: usize| patch.try_get(nu, mu).map(point3);
    let mut lines = Vec::new();
    for c in 0..n {
        // nu = c, mu = c, lambda = c in turn.
        lines.push((0..=n - c).filter_map(|mu| at(c, mu)).collect());
        lines.push((0..=n - c).filter_map(|nu| at(nu, c)).collect());
        lines.push((0..=n - c).filter_map(|nu| at(nu, n - c - nu)).collect());
    }
    lines
}

/// The control points of a triangular patch as points of the picture.
pub fn triangle_points(patch: &TriangularPatch<Rational>) -> Vec<Point3> {
    patch.control_points().iter().map(point3).collect()
}

/// The control net of a tensor patch as points of the picture, `[nu][mu]`.
pub fn tensor_points(patch: &TensorPatch<Rational>) -> Vec<Vec<Point3>> {
    patch
        .to_nested()
        .iter()
        .map(|row| row.iter().map(|p| point3(p)).collect())
        .collect()
}

/// `count + 1` samples of a curve at t = a + (b - a) k / count.
pub fn sample(a: f64, b: f64, count: usize, f: impl Fn(f64) -> Option<Point3>) -> Vec<Point3> {
    (0..=count)
        .filter_map(|k| f(a + (b - a) * fraction(k, count)))
        .collect()
}

/// The layers of a curve drawn against the curve it approximates: the reference thick
/// underneath, the curve, its control polygon and the control points on top.
pub fn curve_against_reference(
    reference: Vec<Point3>,
    curve: Vec<Point3>,
    polygon: Vec<Point3>,
) -> Vec<Layer> {
    use super::palette::{CURVE, DOTS, NET, REFERENCE};
    vec![
        Layer::lines(vec![reference], REFERENCE, 6),
        Layer::lines(vec![curve], CURVE, 2),
        Layer::lines(vec![polygon.clone()], NET, 1),
        Layer::dots(polygon, DOTS, 5),
    ]
}
