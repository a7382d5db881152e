//! The jobs of the patch, derivative and rational-surface work (`cli.md`, last section), read
//! with the same number rules and answered with the same one-line JSON as every other job:
//!
//! ```text
//! bezier-tensor      {"control_points": P, "rectangle": [a, b, c, d]}
//!                    -> {"kind", "degree": [n, m], "control_points"}        (every --method)
//! bezier-triangle    {"control_points": [{"a", "b", "c", "point"}, ...], "triangle": [P, Q, R]}
//!                    -> {"kind", "degree": N, "control_points": [{"a", "b", "c", "point"}, ...]}
//! derivative         {"control_points": [...], "order": k}
//!                    -> {"kind", "degree": n - k, "control_points"}
//! rational-tensor    {"numerator", "denominator", "rectangle", "degree"?}
//!                    -> {"kind", "degree": [n, m], "control_points", "weights"}
//! rational-triangle  {"numerator", "denominator", "triangle", "degree"?, "total_degree"?}
//!                    -> {"kind", "degree": N, "control_points": [{"a", "b", "c", "point", "weight"}, ...]}
//! ```
//!
//! # Methods
//!
//! The two Bézier restrictions follow `bezier-curve`: `bulk` (the default) runs the restriction engine on the
//! control points themselves (never leaving the Bernstein basis), `pyramid` evaluates the
//! blossom of the given net by de Casteljau's pyramid for every control point, `polarisation`
//! samples the patch and applies the inverse formula of seed 004 (two passes of (22), or
//! (23)), `specialised` runs a carried Bézier-input evaluator, and `taylor-shift`,
//! `closed-form` and `definition` write the patch in the power basis (exactly, by forward
//! differences) and restrict it like a `tensor` or `triangle` job. The other jobs have one
//! algorithm each.
//!
//! # Corners of a sub-triangle
//!
//! A corner of `bezier-triangle` is given by three barycentric coordinates (r, s, t). They must
//! add up to 1: exactly under `exact`, within 1e-9 under `f64`. Every method then uses
//! (r, s, 1 - r - s), so that all of them restrict to the same triangle.
//!
//! # Exact decisions under `--arithmetic f64`
//!
//! The rational jobs refuse a weight that is *exactly* zero, as `rational-curve` does: under
//! `f64` they read the numbers as written, compute exactly and round each number of the answer
//! once.

use super::answer::triangle_entries;
use super::args::MethodChoice;
use super::job::{
    array, corners, degree_value, field, number_grid, number_triangular_array, numbers, point,
    point_grid, triangular_array, MAX_DEGREE,
};
use super::spline_jobs::{exact_spelling, numbers_json, points_json, rounded};
use crate::number::{json_type, JsonNumber};
use crate::repeated;
use blossom::engine::{
    tensor_bernstein_to_power, triangle_bernstein_to_power, triangle_index, triangle_len,
};
use blossom::{
    bezier_tensor_blossom, bezier_triangle_blossom, restrict_power_surface,
    restrict_power_triangle, tensor_control_points_from_samples,
    triangle_control_points_from_samples,
};
use blossom::{Error, Field, Method, Point, Rational, Ring};
use blossom::{RationalPowerTriangle, RationalSurface};
use blossom::{TensorPatch, TriangularPatch};
use serde_json::{Map, Value};

/// The kinds answered here.
pub const KINDS: [&str; 5] = super::job::PATCH_KINDS;

/// The job object and its kind when `document` is a job of this module.
pub fn recognise(document: &Value) -> Option<(&Map<String, Value>, &'static str)> {
    super::job::recognise_kind(document, &KINDS)
}

/// Reads, computes and writes the job `job` of kind `kind` in the arithmetic `T`.
pub fn solve<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    kind: &'static str,
    method: MethodChoice,
) -> Result<Value, Error> {
    let mut out = Map::new();
    out.insert("kind".into(), Value::from(kind));
    match kind {
        "bezier-tensor" => bezier_tensor::<T>(job, method, &mut out)?,
        "bezier-triangle" => bezier_triangle::<T>(job, method, &mut out)?,
        "derivative" => derivative::<T>(job, &mut out)?,
        "rational-tensor" => {
            rational_tensor_input::<T>(job)?;
            let (patch, degree) = rational_tensor_exact(&exact_spelling::<T>(job))?;
            out.insert("degree".into(), Value::from(vec![degree.0, degree.1]));
            let points: Vec<Vec<Point<T>>> = patch
                .rows()
                .map(|row| row.iter().map(|p| rounded(p)).collect())
                .collect();
            let weights: Vec<Vec<T>> = patch.weight_rows().map(|row| rounded(row)).collect();
            check_rounded_weights(weights.iter().enumerate().flat_map(|(i, row)| {
                row.iter()
                    .enumerate()
                    .map(move |(j, w)| (format!("weights[{i}][{j}]"), w))
            }))?;
            out.insert(
                "control_points".into(),
                grid_json(&points, "control_points")?,
            );
            let weights = weights
                .iter()
                .enumerate()
                .map(|(i, row)| numbers_json(row, &format!("weights[{i}]")))
                .collect::<Result<Vec<Value>, Error>>()?;
            out.insert("weights".into(), Value::Array(weights));
        }
        "rational-triangle" => {
            rational_triangle_input::<T>(job)?;
            let patch = rational_triangle_exact(&exact_spelling::<T>(job))?;
            let points: Vec<Point<T>> = patch.points().iter().map(|p| rounded(p)).collect();
            let weights: Vec<T> = rounded(patch.weights());
            check_rounded_weights(
                weights
                    .iter()
                    .enumerate()
                    .map(|(k, w)| (format!("control_points[{k}].weight"), w)),
            )?;
            let net = TriangularPatch::new(patch.degree(), points)?;
            let entries = triangle_entries(&net, Some(&weights))?;
            out.insert("degree".into(), Value::from(patch.degree()));
            out.insert("control_points".into(), Value::Array(entries));
        }
        other => {
            return Err(Error::new(
                "kind",
                format!("{other:?} is not a job of this module"),
            ))
        }
    }
    Ok(Value::Object(out))
}

/// A grid of points as a JSON array of rows; `path` names them in errors.
fn grid_json<T: JsonNumber>(rows: &[Vec<Point<T>>], path: &str) -> Result<Value, Error> {
    rows.iter()
        .enumerate()
        .map(|(i, row)| points_json(row, &format!("{path}[{i}]")))
        .collect::<Result<Vec<Value>, Error>>()
        .map(Value::Array)
}

/// Refuses a weight that is not zero exactly but rounds to zero (its rounded control point
/// would be meaningless).
fn check_rounded_weights<'a, T: Ring + 'a>(
    weights: impl Iterator<Item = (String, &'a T)>,
) -> Result<(), Error> {
    for (path, w) in weights {
        if w.is_zero() {
            return Err(Error::new(
                path,
                "the weight is not zero but rounds to zero in f64 (underflow)",
            ));
        }
    }
    Ok(())
}

/// The net of a `bezier-tensor` job, and the patch restricted to the rectangle by `method`:
/// Q[nu][mu] = b[a^(n-nu), b^nu; c^(m-mu), d^mu].
fn bezier_tensor<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    method: MethodChoice,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let patch = TensorPatch::new(point_grid::<T>(
        field(job, "control_points")?,
        "control_points",
    )?)?;
    let rect = numbers::<T, 4>(field(job, "rectangle")?, "rectangle")?;
    let (n, m) = patch.degree();
    let [a, b, c, d] = &rect;
    let net: Vec<Vec<Point<T>>> = match method {
        MethodChoice::Library(Method::Bulk) => patch.restrict(&rect).into_control_points(),
        MethodChoice::Library(Method::Pyramid) => (0..=n)
            .map(|nu| {
                (0..=m)
                    .map(|mu| {
                        bezier_tensor_blossom(
                            &patch.to_nested(),
                            &repeated(a, n - nu, b, nu),
                            &repeated(c, m - mu, d, mu),
                        )
                    })
                    .collect::<Result<_, _>>()
            })
            .collect::<Result<_, _>>()?,
        MethodChoice::Library(Method::Polarisation) => {
            tensor_control_points_from_samples((n, m), &rect, &|u, v| patch.eval(u, v))
        }
        MethodChoice::Specialised => {
            match super::specialised::specialised_bezier_tensor(&patch, &rect) {
                Some(result) => result?.into_control_points(),
                None => return Err(Error::new("--method", super::specialised::NOT_BUILT_IN)),
            }
        }
        MethodChoice::Library(method) => {
            let power = tensor_bernstein_to_power(&patch);
            restrict_power_surface(&power, &rect, method).into_control_points()
        }
    };
    out.insert("degree".into(), Value::from(vec![n, m]));
    out.insert("control_points".into(), grid_json(&net, "control_points")?);
    Ok(())
}

/// The control points of a `bezier-triangle` job: entries `{"a": i, "b": j, "c": k, "point": p}`
/// in any order, every triple with i + j + k = N exactly once; the patch in the order of
/// [`TriangularPatch`].
fn triangle_net<T: JsonNumber>(value: &Value) -> Result<TriangularPatch<T>, Error> {
    let path = "control_points";
    let items = array(value, path, "an array of control points")?;
    if items.is_empty() {
        return Err(Error::new(
            path,
            "expected at least one control point, found none",
        ));
    }
    let mut big_n = None;
    let mut slots: Vec<Option<(usize, Point<T>)>> = Vec::new();
    let mut dim = None;
    for (k, item) in items.iter().enumerate() {
        let entry_path = format!("{path}[{k}]");
        let Value::Object(entry) = item else {
            return Err(Error::new(
                entry_path,
                format!(
                    "expected an object {{\"a\", \"b\", \"c\", \"point\"}}, found {}",
                    json_type(item)
                ),
            ));
        };
        let index = |name: &str| -> Result<usize, Error> {
            let at = format!("{entry_path}.{name}");
            let v = entry
                .get(name)
                .ok_or_else(|| Error::new(&at, "missing field"))?;
            degree_value(v, &at)
        };
        let (i, j, l) = (index("a")?, index("b")?, index("c")?);
        let sum = i + j + l;
        let n = *big_n.get_or_insert(sum);
        if sum != n {
            return Err(Error::new(
                &entry_path,
                format!(
                    "indices ({i}, {j}, {l}) add up to {sum}, but those of control_points[0] add up \
                     to {n} (every triple of one patch has the same sum, its degree)"
                ),
            ));
        }
        if n > MAX_DEGREE {
            return Err(Error::new(
                &entry_path,
                format!("expected a degree of at most {MAX_DEGREE}, found {n}"),
            ));
        }
        if slots.is_empty() {
            slots = vec![None; triangle_len(n)];
        }
        let p_path = format!("{entry_path}.point");
        let p = point::<T>(
            entry
                .get("point")
                .ok_or_else(|| Error::new(&p_path, "missing field"))?,
            &p_path,
            dim,
        )?;
        dim = Some(p.len());
        let slot = &mut slots[triangle_index(n, i, j)];
        if let Some((first, _)) = slot {
            return Err(Error::new(
                &entry_path,
                format!("indices ({i}, {j}, {l}) repeat those of control_points[{first}]"),
            ));
        }
        *slot = Some((k, p));
    }
    let n = big_n.unwrap_or(0);
    let mut points = Vec::with_capacity(slots.len());
    for (s, slot) in slots.into_iter().enumerate() {
        match slot {
            Some((_, p)) => points.push(p),
            None => {
                let (i, j) = (0..=n)
                    .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
                    .nth(s)
                    .unwrap_or((0, 0));
                return Err(Error::new(
                    path,
                    format!(
                        "the control point with indices ({i}, {j}, {}) is missing (a patch of \
                         degree {n} has {} points, one per triple)",
                        n - i - j,
                        triangle_len(n)
                    ),
                ));
            }
        }
    }
    TriangularPatch::new(n, points)
}

/// The new corners P, Q, R of a `bezier-triangle` job, each as (r, s, 1 - r - s) after checking
/// that its three coordinates add up to 1 (exactly, or within 1e-9 under f64).
fn barycentric_corners<T: JsonNumber + Field>(value: &Value) -> Result<[[T; 3]; 3], Error> {
    let path = "triangle";
    let items = array(value, path, "an array of 3 corners")?;
    if items.len() != 3 {
        return Err(Error::new(
            path,
            format!("expected 3 corners, found {}", items.len()),
        ));
    }
    let mut out = Vec::with_capacity(3);
    for (k, item) in items.iter().enumerate() {
        let corner_path = format!("{path}[{k}]");
        let coordinates = array(
            item,
            &corner_path,
            "a corner (an array of 3 barycentric coordinates)",
        )?;
        if coordinates.len() != 3 {
            return Err(Error::new(
                &corner_path,
                format!(
                    "expected 3 barycentric coordinates, found {}",
                    coordinates.len()
                ),
            ));
        }
        let [r, s, t] = numbers::<T, 3>(item, &corner_path)?;
        let off = r.add(&s).add(&t).sub(&T::one());
        let tolerance = if T::EXACT {
            T::zero()
        } else {
            T::from_rational(&Rational::new(1.into(), 1_000_000_000.into()))
        };
        let distance = if off < T::zero() { off.neg() } else { off };
        let within = matches!(
            distance.partial_cmp(&tolerance),
            Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
        );
        if !within {
            return Err(Error::new(
                &corner_path,
                format!(
                    "barycentric coordinates must add up to 1 ({}), they add up to {}",
                    if T::EXACT { "exactly" } else { "within 1e-9" },
                    r.add(&s).add(&t)
                ),
            ));
        }
        let third = T::one().sub(&r).sub(&s);
        out.push([r, s, third]);
    }
    out.try_into()
        .map_err(|_| Error::new(path, "expected 3 corners"))
}

/// The patch of a `bezier-triangle` job restricted to the sub-triangle by `method`:
/// q_(nu mu lambda) = b[P^nu, Q^mu, R^lambda].
fn bezier_triangle<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    method: MethodChoice,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let patch = triangle_net::<T>(field(job, "control_points")?)?;
    let bary = barycentric_corners::<T>(field(job, "triangle")?)?;
    let big_n = patch.degree();
    // The corners in the (u, v) = (r, s) plane, where the patch's own corners are (1, 0),
    // (0, 1) and (0, 0).
    let plane = bary.each_ref().map(|[r, s, _]| [r.clone(), s.clone()]);
    let net: TriangularPatch<T> = match method {
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
        MethodChoice::Specialised => {
            match super::specialised::specialised_bezier_triangle(&patch, &plane) {
                Some(result) => result?,
                None => return Err(Error::new("--method", super::specialised::NOT_BUILT_IN)),
            }
        }
        MethodChoice::Library(method) => {
            restrict_power_triangle(&triangle_bernstein_to_power(&patch), &plane, method)
        }
    };
    out.insert("degree".into(), Value::from(big_n));
    out.insert(
        "control_points".into(),
        Value::Array(triangle_entries(&net, None)?),
    );
    Ok(())
}

/// The control points of the `order`-th derivative of the Bézier curve over [0, 1].
fn derivative<T: JsonNumber + Field>(
    job: &Map<String, Value>,
    out: &mut Map<String, Value>,
) -> Result<(), Error> {
    let curve = super::spline_jobs::control_points::<T>(job)?;
    let k = degree_value(field(job, "order")?, "order")?;
    let n = curve.degree();
    if k > n {
        return Err(Error::new(
            "order",
            format!("expected an order of at most {n} (the curve's degree), found {k}"),
        ));
    }
    let hodograph = blossom::bezier_derivative(&curve, k)?;
    out.insert("degree".into(), Value::from(n - k));
    out.insert(
        "control_points".into(),
        points_json(&hodograph.control_points().to_vec(), "control_points")?,
    );
    Ok(())
}

/// An optional degree field: absent or `null` is `None`.
fn optional<R>(
    job: &Map<String, Value>,
    name: &str,
    read: impl Fn(&Value) -> Result<R, Error>,
) -> Result<Option<R>, Error> {
    match job.get(name) {
        None | Some(Value::Null) => Ok(None),
        Some(v) => read(v).map(Some),
    }
}

/// `"degree": [n, m]`.
fn degree_pair(value: &Value) -> Result<(usize, usize), Error> {
    let items = array(value, "degree", "an array of 2 degrees")?;
    if items.len() != 2 {
        return Err(Error::new(
            "degree",
            format!("expected 2 degrees, found {}", items.len()),
        ));
    }
    Ok((
        degree_value(&items[0], "degree[0]")?,
        degree_value(&items[1], "degree[1]")?,
    ))
}

/// Pads a grid with `zero` to `rows` x `cols`.
fn pad<X: Clone>(grid: Vec<Vec<X>>, rows: usize, cols: usize, zero: &X) -> Vec<Vec<X>> {
    let mut grid: Vec<Vec<X>> = grid
        .into_iter()
        .map(|mut row| {
            row.resize(cols, zero.clone());
            row
        })
        .collect();
    grid.resize(rows, vec![zero.clone(); cols]);
    grid
}

/// The numerator and denominator grids of a rational surface job, padded with zeros to one
/// shape (the larger size in each variable), and the degree asked for.
struct RationalGrids<U> {
    numerator: Vec<Vec<Point<U>>>,
    denominator: Vec<Vec<U>>,
}

fn rational_grids<U: JsonNumber>(job: &Map<String, Value>) -> Result<RationalGrids<U>, Error> {
    let numerator = point_grid::<U>(field(job, "numerator")?, "numerator")?;
    let denominator = number_grid::<U>(field(job, "denominator")?, "denominator")?;
    let rows = numerator.len().max(denominator.len());
    let cols = numerator[0].len().max(denominator[0].len());
    if rows > MAX_DEGREE + 1 || cols > MAX_DEGREE + 1 {
        return Err(Error::new(
            "numerator",
            format!(
                "expected a degree of at most {MAX_DEGREE} in each variable (at most {} rows and \
                 columns)",
                MAX_DEGREE + 1
            ),
        ));
    }
    let dim = numerator[0][0].len();
    let zero_point = vec![U::zero(); dim];
    Ok(RationalGrids {
        numerator: pad(numerator, rows, cols, &zero_point),
        denominator: pad(denominator, rows, cols, &U::zero()),
    })
}

/// A `rational-tensor` job read in the arithmetic `U`.
struct RationalTensorJob<U> {
    grids: RationalGrids<U>,
    rect: [U; 4],
    degree: Option<(usize, usize)>,
}

fn rational_tensor_input<U: JsonNumber>(
    job: &Map<String, Value>,
) -> Result<RationalTensorJob<U>, Error> {
    Ok(RationalTensorJob {
        grids: rational_grids::<U>(job)?,
        rect: numbers::<U, 4>(field(job, "rectangle")?, "rectangle")?,
        degree: optional(job, "degree", degree_pair)?,
    })
}

/// The rational tensor patch of a `rational-tensor` job, computed exactly, and its bidegree.
fn rational_tensor_exact(
    job: &Map<String, Value>,
) -> Result<(blossom::RationalTensorPatch<Rational>, (usize, usize)), Error> {
    let RationalTensorJob {
        grids,
        rect,
        degree,
    } = rational_tensor_input::<Rational>(job)?;
    let surface = RationalSurface::new(&grids.numerator, &grids.denominator)?;
    let degree = degree.unwrap_or(surface.degree());
    Ok((surface.tensor(&rect, Some(degree))?, degree))
}

/// A `rational-triangle` job read in the arithmetic `U`: the surface (from grids, or from
/// triangular arrays with `"total_degree"`), the triangle and the degree asked for.
struct RationalTriangleJob<U> {
    surface: RationalPowerTriangle<U>,
    triangle: [[U; 2]; 3],
    degree: Option<usize>,
}

fn rational_triangle_input<U: JsonNumber + Field>(
    job: &Map<String, Value>,
) -> Result<RationalTriangleJob<U>, Error> {
    let surface = match optional(job, "total_degree", |v| degree_value(v, "total_degree"))? {
        Some(big_n) => {
            let numerator = triangular_array::<U>(field(job, "numerator")?, "numerator", big_n)?;
            let denominator =
                number_triangular_array::<U>(field(job, "denominator")?, "denominator", big_n)?;
            RationalPowerTriangle::new(&numerator, &denominator)?
        }
        None => {
            let grids = rational_grids::<U>(job)?;
            let surface = RationalSurface::new(&grids.numerator, &grids.denominator)?;
            RationalPowerTriangle::from_surface(&surface)
        }
    };
    let triangle = corners::<U, 3>(field(job, "triangle")?, "triangle")?;
    let degree = optional(job, "degree", |v| degree_value(v, "degree"))?;
    Ok(RationalTriangleJob {
        surface,
        triangle,
        degree,
    })
}

/// The rational triangular patch of a `rational-triangle` job, computed exactly.
fn rational_triangle_exact(
    job: &Map<String, Value>,
) -> Result<blossom::RationalTriangularPatch<Rational>, Error> {
    let RationalTriangleJob {
        surface,
        triangle,
        degree,
    } = rational_triangle_input::<Rational>(job)?;
    surface.triangle(&triangle, degree)
}
