//! `"kind": "bezier-triangle"`: the triangular patch of degree N whose control point with
//! indices (i, j, k) is the blossom value at A^i B^j C^k, restricted to the sub-triangle P, Q, R
//! given by barycentric coordinates (adding up to 1: exactly under `exact`, within 1e-9 under
//! `f64`; every method then uses (r, s, 1 - r - s)): q = b[P^nu, Q^mu, R^lambda]. The methods
//! as for `bezier-curve`.

use super::{entries, restricted, specialised, Number};
use crate::jobs::kind::prelude::*;
use blossom::engine::{triangle_bernstein_to_power, triangle_index, triangle_len};
use blossom::{bezier_triangle_blossom, restrict_power_triangle};
use blossom::{triangle_control_points_from_samples, TriangularPatch};

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct BezierTriangle<T> {
    /// The control points with their indices, in any order.
    control_points: List<Entry<T>>,
    /// P, Q, R by their barycentric coordinates.
    triangle: Corners<T, 3>,
}

/// One control point of the job.
#[derive(Debug, Deserialize)]
#[serde(
    bound = "T: Reading",
    expecting = "an object {\"a\", \"b\", \"c\", \"point\"}"
)]
struct Entry<T> {
    a: Degree,
    b: Degree,
    c: Degree,
    point: crate::jobs::read::Point<T>,
}

/// The measured factors of the estimate ([`Calibration`]).
#[rustfmt::skip]
const CALIBRATION: Calibration = [[2.4, 6.3], [5.7, 2.9], [6.2, 0.43], [3.7, 3.0], [17.0, 0.86], [7.5, 1.2]];

/// The patch of the entries: every triple with i + j + k = N exactly once, the points of one
/// dimension.
fn net<T: Number>(items: Vec<Entry<T>>) -> Result<TriangularPatch<T>, Error> {
    let path = "control_points";
    if items.is_empty() {
        return Err(Error::new(
            path,
            "expected at least one control point, found none",
        ));
    }
    let n = items[0].a.0 + items[0].b.0 + items[0].c.0;
    let mut slots: Vec<Option<(usize, Vec<T>)>> = Vec::new();
    for (k, Entry { a, b, c, point }) in items.into_iter().enumerate() {
        let here = format!("{path}[{k}]");
        let (i, j, l) = (a.0, b.0, c.0);
        if i + j + l != n {
            return Err(Error::new(
                &here,
                format!(
                    "indices ({i}, {j}, {l}) add up to {}, but those of control_points[0] add up \
                     to {n} (every triple of one patch has the same sum, its degree)",
                    i + j + l
                ),
            ));
        }
        if n > MAX_DEGREE {
            return Err(Error::new(
                &here,
                format!("expected a degree of at most {MAX_DEGREE}, found {n}"),
            ));
        }
        if slots.is_empty() {
            slots = vec![None; triangle_len(n)];
        }
        let dim = slots.iter().flatten().next().map(|(_, p)| p.len());
        if let Some(d) = dim.filter(|d| *d != point.0.len()) {
            return Err(Error::new(
                format!("{here}.point"),
                format!("expected {}, found {}", coordinates(d), point.0.len()),
            ));
        }
        let slot = &mut slots[triangle_index(n, i, j)];
        if let Some((first, _)) = slot {
            return Err(Error::new(
                &here,
                format!("indices ({i}, {j}, {l}) repeat those of control_points[{first}]"),
            ));
        }
        *slot = Some((k, point.0));
    }
    let mut points = Vec::with_capacity(slots.len());
    for (s, slot) in slots.into_iter().enumerate() {
        let Some((_, p)) = slot else {
            let (i, j) = (0..=n)
                .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
                .nth(s)
                .unwrap_or((0, 0));
            return Err(Error::new(
                path,
                format!(
                    "the control point with indices ({i}, {j}, {}) is missing (a patch of degree \
                     {n} has {} points, one per triple)",
                    n - i - j,
                    triangle_len(n)
                ),
            ));
        };
        points.push(p);
    }
    TriangularPatch::new(n, points)
}

/// The corners, each (r, s, 1 - r - s) after checking that its coordinates add up to 1.
fn barycentric<T: Number>(corners: [[T; 3]; 3]) -> Result<[[T; 3]; 3], Error> {
    let (tolerance, within) = match <T as Reading>::EXACT {
        true => (T::zero(), "exactly"),
        false => (
            T::from_rational(&Rational::new(1.into(), 1_000_000_000.into())),
            "within 1e-9",
        ),
    };
    let mut out = corners.clone();
    for (k, [r, s, t]) in corners.into_iter().enumerate() {
        let sum = r.add(&s).add(&t);
        let off = sum.sub(&T::one());
        let distance = if off < T::zero() { off.neg() } else { off };
        #[allow(clippy::neg_cmp_op_on_partial_ord)] // a NaN distance is refused too
        if !(distance <= tolerance) {
            let message = format!(
                "barycentric coordinates must add up to 1 ({within}), they add up to {sum}"
            );
            return Err(Error::new(format!("triangle[{k}]"), message));
        }
        out[k][2] = T::one().sub(&r).sub(&s);
    }
    Ok(out)
}

/// The up-front estimate: a `triangle`'s.
impl<T: Reading> Estimate for BezierTriangle<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let entries = self.control_points.0.len() as f64;
        // N from the number of entries (N + 1)(N + 2) / 2.
        let big_n = ((8.0 * entries + 1.0).sqrt() - 3.0).max(0.0) / 2.0 + 1.0;
        let d = self.control_points.0.first().map_or(1, |e| e.point.0.len());
        let sizes = (big_n, entries, d.max(1) as f64);
        super::triangle::estimate(env, "control_points", sizes, &CALIBRATION)
    }
}

impl<T: Number> Kind for BezierTriangle<T> {
    fn solve(self, context: &Context) -> Result<Value, Error> {
        let patch = net(self.control_points.0)?;
        let bary = barycentric(self.triangle.0)?;
        let big_n = patch.degree();
        // The corners in the (u, v) = (r, s) plane, where the patch's own corners are (1, 0),
        // (0, 1) and (0, 0).
        let plane = bary.each_ref().map(|[r, s, _]| [r.clone(), s.clone()]);
        let net = match context.method {
            MethodChoice::Library(Method::Bulk) => patch.restrict(&plane),
            MethodChoice::Library(Method::Pyramid) => {
                let points = (0..=big_n)
                    .flat_map(|nu| (0..=big_n - nu).map(move |mu| (nu, mu)))
                    .map(|(nu, mu)| {
                        let args: Vec<[T; 3]> = std::iter::repeat_n(bary[0].clone(), nu)
                            .chain(std::iter::repeat_n(bary[1].clone(), mu))
                            .chain(std::iter::repeat_n(bary[2].clone(), big_n - nu - mu))
                            .collect();
                        bezier_triangle_blossom(&patch, &args)
                    })
                    .collect::<Result<_, _>>()?;
                TriangularPatch::new(big_n, points)?
            }
            MethodChoice::Library(Method::Polarisation) => {
                let points = triangle_control_points_from_samples(big_n, &plane, &|u, v| {
                    patch.eval(&[u.clone(), v.clone()])
                });
                TriangularPatch::new(big_n, points)?
            }
            MethodChoice::Specialised => specialised::bezier_triangle(&patch, &plane)?,
            MethodChoice::Library(method) => {
                restrict_power_triangle(&triangle_bernstein_to_power(&patch), &plane, method)
            }
        };
        restricted(big_n, entries(&net, None))
    }
}
