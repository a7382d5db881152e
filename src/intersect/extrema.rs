//! The tight bounding box and the nearest point of a Bézier curve, certified: both built on
//! the exact zeros of a derivative. The method, guarantee and limits are documented on
//! [`TightBox`] and [`NearestPoint`], where rustdoc shows them. The operations are methods of
//! the curve types ([`BezierCurve::bounding_box`], [`BezierCurve::nearest_point`], the same on
//! [`crate::Bezier`]); the free functions [`tight_bounding_box`], [`nearest_point`] and their
//! `_f64` forms are the same operations on a [`BezierCurve`], kept for existing callers.

use super::algebraic::{enclose, value_at, AlgebraicReal};
use super::upoly;
use super::zeros::{power_coefficients, roots_with_multiplicity};
use crate::error::{Error, ErrorKind, Result};
use crate::num::exact::{exact_coordinates, exact_values};
use crate::num::ring::Rational;
use crate::shape::bezier::BezierCurve;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// One extreme of a polynomial over [0, 1], exactly: its value and where it is attained (see
/// [`TightBox`]). `Display` writes `1 at t = 1/2`, or `1 everywhere`.
#[derive(Clone, Debug)]
pub struct Extreme {
    /// The extreme value, exactly.
    pub value: AlgebraicReal,
    /// Every parameter in [0, 1] where the value is attained, ascending; only `[0]` when the
    /// polynomial is constant (`everywhere`).
    pub at: Vec<AlgebraicReal>,
    /// Whether the polynomial is constant, so that every parameter attains the value.
    pub everywhere: bool,
}

/// The tight bounding box of a curve over [0, 1], one minimum and one maximum per coordinate,
/// **exact**: the answer of [`BezierCurve::bounding_box`] (and of [`crate::Bezier`]'s
/// method, [`tight_bounding_box`]). `Display` writes one line per coordinate,
/// `x0: min 0 at t = 0, max 2 at t = 1`.
///
/// Guarantee: each side is the exact extreme of that coordinate along the curve (an
/// [`AlgebraicReal`]), with every parameter attaining it; [`TightBox::outward`] rounds them
/// outwards, exactly, to the smallest box of doubles that holds the curve.
///
/// Limits: any degree and dimension, no budget enforced here (a cubic takes well under a
/// millisecond; the cost is one exact root isolation of degree n - 1 per coordinate).
///
/// ```
/// use blossom::Bezier;
/// let arch = Bezier::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])?;
/// let bounds = arch.bounding_box()?;
/// assert_eq!(bounds.max[1].value.to_string(), "1");
/// assert_eq!(bounds.outward(), (vec![0.0, 0.0], vec![2.0, 1.0]));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Method
///
/// Both are extremes over [0, 1] of a polynomial p(t) in the power basis, which are attained
/// at an end or at a zero of p'(t) inside:
///
/// * **bounding box**: for each coordinate, p = x_j(t), the coordinate of the curve (its
///   Bernstein coefficients are the control points' j-th coordinates); its minimum and maximum
///   are the sides of the tightest box holding the curve (not the control polygon's box, which
///   can be far larger);
/// * **nearest point** to q: p = D(t) = |P(t) - q|^2, whose minimum is the squared distance
///   from q to the curve.
///
/// The candidates 0, 1 and the zeros of p' in (0, 1) are exact (Yun's square-free
/// factorisation and Descartes' rule), and so are the values of p at them: each is an
/// [`AlgebraicReal`] (the resultant Res_t(f(t), c v - c p(t)) for the polynomial f of the
/// candidate). Which candidate is smallest is decided by exact comparison
/// ([`AlgebraicReal::compare`]), and every candidate of equal value is reported (a curve
/// symmetric about q has two nearest points). Interval Horner enclosures of p over the
/// candidates' isolating intervals only prune: a candidate whose enclosure lies wholly above
/// another's upper end cannot be the minimum, and is dropped before its exact value is built.
///
/// Rounding: [`AlgebraicReal::to_f64_down`] and [`AlgebraicReal::to_f64_up`] round exactly, so
/// [`TightBox::outward`] is the smallest box of doubles that contains the curve, and
/// [`AlgebraicReal::to_f64`] the correctly rounded value.
///
/// Cost: one exact root isolation of a polynomial of degree n - 1 (box, per coordinate) or
/// 2n - 1 (nearest point), and one resultant per surviving candidate; a cubic takes well
/// under a millisecond. There is no limit here; the caller bounds the degree.
#[derive(Clone, Debug)]
pub struct TightBox {
    /// The smallest value of each coordinate along the curve.
    pub min: Vec<Extreme>,
    /// The largest value of each coordinate along the curve.
    pub max: Vec<Extreme>,
}

impl TightBox {
    /// The smallest box of doubles that contains the curve: each minimum rounded down and
    /// each maximum rounded up, exactly. `(lower corner, upper corner)`.
    pub fn outward(&self) -> (Vec<f64>, Vec<f64>) {
        (
            self.min.iter().map(|e| e.value.to_f64_down()).collect(),
            self.max.iter().map(|e| e.value.to_f64_up()).collect(),
        )
    }
}

/// The points of a curve nearest to a given point, **exact**: the answer of
/// [`BezierCurve::nearest_point`] (and of [`crate::Bezier`]'s method, [`nearest_point`]).
///
/// Guarantee: the squared distance is exact (an [`AlgebraicReal`]); every parameter
/// attaining it is listed (a curve symmetric about the point has two), with the nearest
/// points' coordinates exact. The method is that of [`TightBox`] on D(t) = |P(t) - q|^2,
/// a polynomial of degree 2n. Limits: any degree and dimension, no budget enforced here.
/// `Display` writes `squared distance 9 at t = 1/4, point (1, 0)`.
///
/// ```
/// use blossom::BezierCurve;
/// let line = BezierCurve::new(vec![vec![0.0, 0.0], vec![4.0, 0.0]])?;
/// let nearest = line.nearest_point(&[1.0, 3.0])?;
/// assert_eq!(nearest.to_string(), "squared distance 9 at t = 1/4, point (1, 0)");
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct NearestPoint {
    /// The squared distance from the point to the curve, exactly.
    pub squared_distance: AlgebraicReal,
    /// Every parameter in [0, 1] of a nearest point, ascending (only `[0]` when every point
    /// of the curve is at the same distance, which for a polynomial curve means the curve is
    /// a single point).
    pub at: Vec<AlgebraicReal>,
    /// The nearest points P(t) for the parameters of `at`, each coordinate exactly.
    pub points: Vec<Vec<AlgebraicReal>>,
    /// Whether every parameter is at the same distance.
    pub everywhere: bool,
}

/// The tight bounding box of the Bézier curve `curve` over [0, 1], **exact** ([`TightBox`]
/// states the guarantee, method and limits). The same as the method
/// [`BezierCurve::bounding_box`].
///
/// ```
/// use blossom::{tight_bounding_box, BezierCurve, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// // The quadratic (0, 0), (1, 2), (2, 0) peaks at y(1/2) = 1, below its control point's 2.
/// let arch = BezierCurve::new(vec![
///     vec![q(0, 1), q(0, 1)],
///     vec![q(1, 1), q(2, 1)],
///     vec![q(2, 1), q(0, 1)],
/// ])?;
/// let bounds = tight_bounding_box(&arch);
/// assert_eq!(bounds.max[1].value.exact(), Some(&q(1, 1)));
/// assert_eq!(bounds.max[1].at[0].exact(), Some(&q(1, 2)));
/// assert_eq!(bounds.outward(), (vec![0.0, 0.0], vec![2.0, 1.0]));
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn tight_bounding_box(curve: &BezierCurve<Rational>) -> TightBox {
    box_of(curve.coordinates(), curve.dim())
}

/// [`tight_bounding_box`] of a curve of doubles, each read exactly: the same as the method
/// [`BezierCurve::bounding_box`].
///
/// ```
/// use blossom::{tight_bounding_box_f64, BezierCurve};
/// let c = BezierCurve::new(vec![vec![0.0], vec![3.0], vec![0.0]])?;
/// assert_eq!(tight_bounding_box_f64(&c)?.outward(), (vec![0.0], vec![1.5]));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `control_points[i][j]` for a NaN or an infinity.
pub fn tight_bounding_box_f64(curve: &BezierCurve<f64>) -> Result<TightBox> {
    let exact = exact_coordinates("control_points", curve.coordinates(), curve.dim())?;
    Ok(box_of(&exact, curve.dim()))
}

/// The tight box of the curve with flat control points `coordinates` (`dim` per point, at
/// least one point): the one implementation behind the functions and methods.
pub(crate) fn box_of(coordinates: &[Rational], dim: usize) -> TightBox {
    let (mut min, mut max) = (Vec::new(), Vec::new());
    for j in 0..dim {
        let coordinate: Vec<Rational> = coordinates.iter().skip(j).step_by(dim).cloned().collect();
        let p = power_coefficients(&coordinate);
        let candidates = critical_parameters(&p);
        min.push(extreme(&p, &candidates, Ordering::Less));
        max.push(extreme(&p, &candidates, Ordering::Greater));
    }
    TightBox { min, max }
}

/// The points of the Bézier curve `curve` over [0, 1] nearest to `q`, **exact**
/// ([`NearestPoint`] states the guarantee and limits). The same as the method
/// [`BezierCurve::nearest_point`].
///
/// ```
/// use blossom::{nearest_point, BezierCurve, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// // The parabola (u, u^2), u = 2t - 1, is nearest to (0, 1) at u = ±1/sqrt(2), twice.
/// let parabola = BezierCurve::new(vec![
///     vec![q(-1, 1), q(1, 1)],
///     vec![q(0, 1), q(-1, 1)],
///     vec![q(1, 1), q(1, 1)],
/// ])?;
/// let nearest = nearest_point(&parabola, &[q(0, 1), q(1, 1)])?;
/// assert_eq!(nearest.squared_distance.exact(), Some(&q(3, 4)));
/// assert_eq!(nearest.at.len(), 2);
/// assert_eq!(nearest.points[1][1].exact(), Some(&q(1, 2)));
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::Dimension`] on `q` when it has not the curve's dimension.
pub fn nearest_point(curve: &BezierCurve<Rational>, q: &[Rational]) -> Result<NearestPoint> {
    nearest_of(curve.coordinates(), curve.dim(), q, "q")
}

/// [`nearest_point`] for a curve and a point of doubles, each read exactly: the same as the
/// method [`BezierCurve::nearest_point`].
///
/// ```
/// use blossom::{nearest_point_f64, BezierCurve};
/// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![2.0, 0.0]])?;
/// assert_eq!(nearest_point_f64(&c, &[1.0, 1.0])?.squared_distance.to_string(), "1");
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// [`ErrorKind::NotFinite`] on `control_points[i][j]` or `q[j]` for a NaN or an infinity, and as
/// [`nearest_point`].
pub fn nearest_point_f64(curve: &BezierCurve<f64>, q: &[f64]) -> Result<NearestPoint> {
    let exact = exact_coordinates("control_points", curve.coordinates(), curve.dim())?;
    nearest_of(&exact, curve.dim(), &exact_values("q", q)?, "q")
}

/// The nearest points to `q` (named `q_field` in errors) of the curve with flat control
/// points `coordinates` (`dim` per point): the one implementation behind the functions and
/// methods.
pub(crate) fn nearest_of(
    coordinates: &[Rational],
    dim: usize,
    q: &[Rational],
    q_field: &str,
) -> Result<NearestPoint> {
    if q.len() != dim {
        return Err(Error::of(
            ErrorKind::Dimension,
            q_field,
            format!(
                "expected a point of {dim} coordinates (the curve's dimension), found {}",
                q.len()
            ),
        ));
    }
    let coordinates: Vec<Vec<Rational>> = (0..dim)
        .map(|j| {
            let c: Vec<Rational> = coordinates.iter().skip(j).step_by(dim).cloned().collect();
            power_coefficients(&c)
        })
        .collect();
    // D(t) = sum_j (x_j(t) - q_j)^2.
    let mut distance: Vec<Rational> = Vec::new();
    for (x, qj) in coordinates.iter().zip(q) {
        let mut shifted = x.clone();
        shifted[0] -= qj;
        add_assign(&mut distance, &square(&shifted));
    }
    let best = extreme(&distance, &critical_parameters(&distance), Ordering::Less);
    let points = best
        .at
        .iter()
        .map(|t| coordinates.iter().map(|x| value_at(x, t)).collect())
        .collect();
    Ok(NearestPoint {
        squared_distance: best.value,
        at: best.at,
        points,
        everywhere: best.everywhere,
    })
}

/// 0, the zeros of p' in (0, 1) and 1, ascending (only 0 when p is constant).
fn critical_parameters(p: &[Rational]) -> Vec<AlgebraicReal> {
    let (zero, one) = (Rational::zero(), Rational::one());
    let integer = upoly::from_rationals(p);
    if upoly::degree(&integer).unwrap_or(0) == 0 {
        return vec![AlgebraicReal::from_rational(zero)];
    }
    let mut out = vec![AlgebraicReal::from_rational(zero.clone())];
    let slope = upoly::derivative(&integer);
    if !upoly::is_zero(&slope) {
        out.extend(
            roots_with_multiplicity(&slope, &zero, &one)
                .into_iter()
                .map(|r| r.value)
                .filter(|t| {
                    t.cmp_rational(&zero) == Ordering::Greater
                        && t.cmp_rational(&one) == Ordering::Less
                }),
        );
    }
    out.push(AlgebraicReal::from_rational(one));
    out
}

/// The smallest (`want = Less`) or largest (`Greater`) value of p over the `candidates`
/// (ascending, distinct, at least one), and every candidate attaining it.
fn extreme(p: &[Rational], candidates: &[AlgebraicReal], want: Ordering) -> Extreme {
    let everywhere = upoly::degree(&upoly::from_rationals(p)).unwrap_or(0) == 0;
    // Pruning by enclosures over intervals refined to 2^-64: a candidate whose enclosure lies
    // wholly on the wrong side of another's cannot be the extreme.
    let width = Rational::new(1.into(), num_bigint::BigInt::one() << 64u32);
    let enclosures: Vec<(Rational, Rational)> = candidates
        .iter()
        .map(|t| {
            let mut t = t.clone();
            t.refine_to(&width);
            let (lo, hi) = t.interval();
            enclose(p, lo, hi)
        })
        .collect();
    let survives: Vec<bool> = match want {
        Ordering::Less => {
            let bar = enclosures.iter().map(|e| &e.1).min().expect("a candidate");
            enclosures.iter().map(|e| &e.0 <= bar).collect()
        }
        _ => {
            let bar = enclosures.iter().map(|e| &e.0).max().expect("a candidate");
            enclosures.iter().map(|e| &e.1 >= bar).collect()
        }
    };
    let values: Vec<(&AlgebraicReal, AlgebraicReal)> = candidates
        .iter()
        .zip(survives)
        .filter(|(_, keep)| *keep)
        .map(|(t, _)| (t, value_at(p, t)))
        .collect();
    let best = values
        .iter()
        .map(|(_, v)| v)
        .reduce(|a, b| if b.compare(a) == want { b } else { a })
        .expect("the candidate with the best enclosure survives")
        .clone();
    let at = values
        .iter()
        .filter(|(_, v)| v.equals(&best))
        .map(|(t, _)| (*t).clone())
        .collect();
    Extreme {
        value: best,
        at,
        everywhere,
    }
}

/// p^2 for a rational polynomial (ascending).
fn square(p: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::zero(); (2 * p.len()).saturating_sub(1)];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in p.iter().enumerate() {
            out[i + j] += a * b;
        }
    }
    out
}

/// acc += p for rational polynomials (ascending).
fn add_assign(acc: &mut Vec<Rational>, p: &[Rational]) {
    if acc.len() < p.len() {
        acc.resize(p.len(), Rational::zero());
    }
    for (a, b) in acc.iter_mut().zip(p) {
        *a += b;
    }
}
