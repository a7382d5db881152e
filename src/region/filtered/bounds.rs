//! Rigorous enclosures in floating point shared by both float paths: signs, curve and
//! hodograph values at a parameter enclosure, the sign of a certified crossing, and the area
//! polynomial of a curve.
//!
//! Everything is computed in [`BoundedF64`] (a double with a rigorous bound on its distance
//! to the exact value of the same operations on the same inputs). A parameter t* known to lie
//! in an enclosure [lo, hi] of doubles around its correctly rounded double m enters as m with
//! the bound hi - lo (rounded up), which covers |t* - m|; evaluations by de Casteljau's
//! pyramid in convex form ([`ConvexStep`]) are then enclosures of the exact values at t*.
//!
//! **Area.** The signed area of a closed loop is the sum over its pieces of the integral of
//! (x - o) dy, for any constant o (the integral of o dy over a closed loop is zero); o is a
//! double near the middle of the input, which keeps the terms small. For a curve of degree n
//! with control points (x_i, y_i), the integrand (x(t) - o) y'(t) is a Bernstein polynomial
//! of degree 2n - 1 with coefficients
//! c_k = sum over i + j = k of C(n, i) C(n - 1, j) / C(2n - 1, k) (x_i - o) n (y_(j+1) - y_j),
//! so its antiderivative F(t) from 0 is the Bernstein polynomial of degree 2n with
//! coefficients f_0 = 0, f_(k+1) = f_k + c_k / (2n), and F(1) = f_(2n). A piece from a to b
//! contributes F(b) - F(a).

use crate::intersect::interval::ConvexStep;
use crate::num::bounded::{BoundedF64, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::region::input::MAX_REGION_DEGREE;
use crate::shape::flat::curve_pyramid_in_place;

/// The sign of an enclosure: `Some(±1)` when it excludes zero.
pub(super) fn sign(x: &BoundedF64) -> Option<i64> {
    if x.value() - x.error_bound() > 0.0 {
        Some(1)
    } else if x.value() + x.error_bound() < 0.0 {
        Some(-1)
    } else {
        None
    }
}

/// The parameter t* in `[lo, hi]` as its double `m` with the bound hi - lo.
pub(super) fn parameter(m: f64, [lo, hi]: [f64; 2]) -> BoundedF64 {
    BoundedF64::with_bound(m, (hi - lo).next_up())
}

/// Room for the de Casteljau pyramid of any curve or area polynomial of the region layer.
pub(super) const LEVEL: usize = 2 * (2 * MAX_REGION_DEGREE + 1);

/// An enclosure of the polynomial with Bernstein coefficients `coefficients` (each `dim`
/// numbers, at most [`LEVEL`] in all) at `t`: the first `dim` entries of the answer.
pub(super) fn evaluate(coefficients: &[BoundedF64], dim: usize, t: BoundedF64) -> [BoundedF64; 2] {
    let mut level = [BoundedF64::default(); LEVEL];
    let level = &mut level[..coefficients.len()];
    level.copy_from_slice(coefficients);
    curve_pyramid_in_place(level, dim, &ConvexStep::new(t));
    [level[0], if dim > 1 { level[1] } else { level[0] }]
}

/// The hodograph's control points n (p_(i+1) - p_i), flat (x, y, x, y, ...), in `out`;
/// returns how many numbers it wrote.
pub(super) fn hodograph(points: &[[f64; 2]], out: &mut [BoundedF64; LEVEL]) -> usize {
    let n = BoundedF64::exact((points.len() - 1) as f64);
    for (k, w) in points.windows(2).enumerate() {
        for a in 0..2 {
            out[2 * k + a] = BoundedF64::exact(w[1][a])
                .sub(&BoundedF64::exact(w[0][a]))
                .mul(&n);
        }
    }
    2 * (points.len() - 1)
}

/// C(n, k) (exact for the degrees taken, n <= 2 * 20: every partial product C(n, i) (n - i)
/// stays below 2^42, in word-size arithmetic).
fn binomial(n: usize, k: usize) -> u64 {
    (0..k).fold(1u64, |acc, i| acc * (n - i) as u64 / (i + 1) as u64)
}

/// The weights C(n, i) C(n - 1, j) / (2 C(2n - 1, i + j)) of the area coefficients, row i,
/// column j (n columns), for degree n: each the correctly rounded quotient of two integers
/// below 2^53 (IEEE division), so within u of the exact weight, relatively.
fn weights(n: usize) -> Vec<f64> {
    (0..=n)
        .flat_map(|i| {
            (0..n).map(move |j| {
                (binomial(n, i) * binomial(n - 1, j)) as f64
                    / (2 * binomial(2 * n - 1, i + j)) as f64
            })
        })
        .collect()
}

/// [`weights`] of every degree up to the region limit, made once.
fn weight_table(n: usize) -> &'static [f64] {
    static TABLE: std::sync::OnceLock<Vec<Vec<f64>>> = std::sync::OnceLock::new();
    &TABLE.get_or_init(|| {
        (0..=MAX_REGION_DEGREE)
            .map(|n| if n == 0 { Vec::new() } else { weights(n) })
            .collect()
    })[n]
}

/// Appends the Bernstein coefficients f_0..f_2n of F(t), the integral of (x - o) dy from 0
/// to t (module docs), to `f`, each with one bound E on its error.
///
/// **The bound.** Plain `f64`: each term t = fl(fl(fl(x_i - o) fl(y_(j+1) - y_j)) w_ij) is
/// the exact term times (1 + δ) with |δ| <= γ_5 (two differences, the weight's conversion,
/// two products; γ_k = k u / (1 - k u)), up to an absolute η per product for underflow. A
/// coefficient f_k sums its terms in at most n + 2n additions (the terms of each c_k, then
/// the running sum), so |f̂_k - f_k| <= γ_(3n+5) S plus the underflow terms, where S is the
/// sum of |t| over every term of the curve (the exact |t| <= |t̂| (1 + γ_5)). The computed
/// S' is within a factor (1 + γ_(2n^2+2n)) of the sum of the |t̂|, so
/// E = (3n + 8) u S' (1 + 2^-20) + 2^-300 covers all of it for n <= 20 (the absolute term
/// covers any number of underflows of η = 2^-1074 each the run could make). Each f_k is that double with the
/// bound E (f_0 = 0 exactly, also with E, harmlessly).
fn area_coefficients(points: &[[f64; 2]], o: f64, f: &mut Vec<BoundedF64>) {
    const MARGIN: f64 = 1.0 + 1.0 / (1u64 << 20) as f64;
    const UNDERFLOWS: f64 =
        1.0 / (1u128 << 100) as f64 / (1u128 << 100) as f64 / (1u128 << 100) as f64;
    let n = points.len() - 1;
    let w = &weight_table(n)[..(n + 1) * n];
    let start = f.len();
    let (mut running, mut size) = (0.0, 0.0);
    f.push(BoundedF64::exact(0.0));
    for k in 0..2 * n {
        let mut c = 0.0;
        for i in k.saturating_sub(n - 1)..=k.min(n) {
            let j = k - i;
            let t = (points[i][0] - o) * (points[j + 1][1] - points[j][1]) * w[i * n + j];
            c += t;
            size += t.abs();
        }
        running += c;
        f.push(BoundedF64::exact(running));
    }
    let e = (3 * n + 8) as f64 * UNIT_ROUNDOFF * size * MARGIN + UNDERFLOWS;
    for v in &mut f[start..] {
        *v = BoundedF64::with_bound(v.value(), e);
    }
}

/// The area polynomials F (module docs of `measure`) of a boolean's curves, each made on
/// first use, all about one origin o (the middle of the curves' x range, which keeps the
/// terms small): curve c's coefficients are `coefficients[spans[c].0..spans[c].1]`, an
/// empty span when not made yet. Both float paths keep theirs in one.
pub(super) struct AreaPolynomials {
    coefficients: Vec<BoundedF64>,
    spans: Vec<(usize, usize)>,
    origin: f64,
}

impl AreaPolynomials {
    /// Room for `curves` curves whose boxes `[x_lo, y_lo, x_hi, y_hi]` are `boxes`.
    pub(super) fn new<'b>(curves: usize, boxes: impl Iterator<Item = &'b [f64; 4]>) -> Self {
        let (lo, hi) = boxes.fold((f64::MAX, f64::MIN), |(lo, hi), b| {
            (lo.min(b[0]), hi.max(b[2]))
        });
        AreaPolynomials {
            coefficients: Vec::new(),
            spans: vec![(0, 0); curves],
            origin: lo / 2.0 + hi / 2.0,
        }
    }

    /// The Bernstein coefficients of F for curve c with control points `points`.
    pub(super) fn of(&mut self, c: usize, points: &[[f64; 2]]) -> &[BoundedF64] {
        if self.spans[c].0 == self.spans[c].1 {
            let start = self.coefficients.len();
            area_coefficients(points, self.origin, &mut self.coefficients);
            self.spans[c] = (start, self.coefficients.len());
        }
        &self.coefficients[self.spans[c].0..self.spans[c].1]
    }
}

/// The exact sign of cross(P'(s*), Q'(t*)) at a certified crossing (s* in `s_box` around
/// `s`, t* in `t_box` around `t`), or `None` when the enclosure of the cross product does
/// not exclude zero.
pub(super) fn crossing_sign(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
    s: f64,
    s_box: [f64; 2],
    t: f64,
    t_box: [f64; 2],
) -> Option<i64> {
    let mut h = [BoundedF64::default(); LEVEL];
    let len = hodograph(p, &mut h);
    let a = evaluate(&h[..len], 2, parameter(s, s_box));
    let len = hodograph(q, &mut h);
    let b = evaluate(&h[..len], 2, parameter(t, t_box));
    sign(&a[0].mul(&b[1]).sub(&a[1].mul(&b[0])))
}
