//! The symbolic proofs of the carried evaluators (the proof grid of `blossom verify`).

use super::Shape;
use crate::proofs::{symbolic_curve, symbolic_surface, symbolic_triangle};
use blossom::{curve_control_points_from_samples, tensor_control_points_from_samples};
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
};
use blossom::{restrict_power_triangle, PowerTriangle};
use blossom::{triangle_control_points_from_samples, Poly, PowerCurve, Ring};
use blossom_grid::{
    restrict_bezier_curve_specialised, restrict_bezier_tensor_specialised,
    restrict_bezier_triangle_specialised, restrict_curve_specialised,
    restrict_power_triangle_specialised, restrict_tensor_specialised,
    restrict_triangle_specialised,
};
use std::cell::RefCell;
use std::collections::HashMap;

/// One symbolic proof: the carried evaluator of `shape`, run on polynomials (coefficients
/// `c_i` / `c_i_j` and domain corners as variables, one coordinate), against the definition
/// and the polarisation formula.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProofRow {
    /// Shape and degree.
    pub shape: Shape,
    /// Number of terms of the symbolic control points, summed over all points.
    pub terms: usize,
    /// Identical, as polynomials, to the subset-sum definition (eqs. (2), (8), (13)); for
    /// Bézier input, that of the curve whose Bernstein form the net is.
    pub definition: bool,
    /// Identical, as polynomials, to the polarisation formula (inverse-relations paper).
    pub polarisation: bool,
}

impl ProofRow {
    /// Identical to both independent algorithms.
    pub fn identical(&self) -> bool {
        self.definition && self.polarisation
    }

    /// `curve`, `tensor`, `triangle`.
    pub fn shape_name(&self) -> &'static str {
        self.shape.keyword()
    }

    /// `3` for a curve, `(3, 2)` for a surface.
    pub fn degree(&self) -> String {
        self.shape.degree_text()
    }
}

fn count_terms<P: AsRef<[Poly]>>(points: impl IntoIterator<Item = P>) -> usize {
    points
        .into_iter()
        .map(|p| p.as_ref().iter().map(Poly::num_terms).sum::<usize>())
        .sum()
}

/// `f` with its values remembered: the polarisation formula samples the same point for many
/// control points (on [a, b] the point (k a + l b) / (k + l) serves every w_v with k <= n - v
/// and l <= v), and symbolic samples are the expensive part of the proof. The formula and its
/// arguments are unchanged; only repeated evaluations are saved.
fn memoised<'f, K: std::hash::Hash + Eq + Clone + 'f, V: Clone + 'f>(
    f: impl Fn(&K) -> V + 'f,
) -> impl Fn(&K) -> V + 'f {
    let cache = RefCell::new(HashMap::new());
    move |k: &K| {
        if let Some(v) = cache.borrow().get(k) {
            return V::clone(v);
        }
        let v = f(k);
        cache.borrow_mut().insert(k.clone(), v.clone());
        v
    }
}

/// The point of the curve at a symbolic `t`, as sum c_i t^i with the powers of t formed once
/// (one product per term; Horner's nested products of growing polynomials cost several times
/// more on symbolic points). Any evaluation of the curve serves the polarisation formula,
/// which only needs its points.
fn curve_point(curve: &PowerCurve<Poly>, t: &Poly) -> Vec<Poly> {
    let mut power = Poly::one();
    let mut terms = Vec::with_capacity(curve.degree() + 1);
    for c in curve.coefficients() {
        terms.push(c[0].mul(&power));
        power = power.mul(t);
    }
    vec![terms.into_iter().sum()]
}

/// The point of the surface at symbolic (u, v), as sum c_ij u^i v^j with the powers formed once.
fn surface_point(surface: &blossom::PowerSurface<Poly>, u: &Poly, v: &Poly) -> Vec<Poly> {
    let (n, m) = surface.degree();
    let pu: Vec<Poly> = std::iter::successors(Some(Poly::one()), |p| Some(p.mul(u)))
        .take(n + 1)
        .collect();
    let pv: Vec<Poly> = std::iter::successors(Some(Poly::one()), |p| Some(p.mul(v)))
        .take(m + 1)
        .collect();
    let mut terms = Vec::with_capacity((n + 1) * (m + 1));
    for (i, row) in surface.rows().enumerate() {
        for (j, c) in row.iter().enumerate() {
            terms.push(c[0].mul(&pu[i].mul(&pv[j])));
        }
    }
    vec![terms.into_iter().sum()]
}

/// The polarisation formula (22) of seed 004 on [a, b]: control points from points of the curve.
fn curve_by_polarisation(curve: &PowerCurve<Poly>, a: &Poly, b: &Poly) -> Vec<Vec<Poly>> {
    let sample = memoised(|t: &Poly| curve_point(curve, t));
    curve_control_points_from_samples(curve.degree(), a, b, &sample)
}

/// Proves the carried curve evaluator of degree `n` (1..=16) symbolically.
pub fn prove_curve(n: usize) -> ProofRow {
    let curve = symbolic_curve(n);
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let w = restrict_curve_specialised(&curve, &a, &b).expect("a degree of the proof grid");
    ProofRow {
        shape: Shape::Curve(n),
        terms: count_terms(w.control_points()),
        definition: w == restrict_power_curve(&curve, &a, &b, Method::Definition),
        polarisation: w.control_points() == curve_by_polarisation(&curve, &a, &b).as_slice(),
    }
}

/// Proves the carried tensor evaluator of bidegree `(n, m)` symbolically.
pub fn prove_tensor(n: usize, m: usize) -> ProofRow {
    let s = symbolic_surface(n, m);
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let p = restrict_tensor_specialised(&s, &rect).expect("a bidegree of the proof grid");
    let sample = memoised(|(u, v): &(Poly, Poly)| surface_point(&s, u, v));
    let by_polarisation =
        tensor_control_points_from_samples((n, m), &rect, &|u, v| sample(&(u.clone(), v.clone())));
    ProofRow {
        shape: Shape::Tensor(n, m),
        terms: count_terms(p.to_nested().iter().flatten()),
        definition: p == restrict_power_surface(&s, &rect, Method::Definition),
        polarisation: p.to_nested() == by_polarisation.as_slice(),
    }
}

/// Proves the carried triangle evaluator of degrees `(n, m)` symbolically.
pub fn prove_triangle(n: usize, m: usize) -> ProofRow {
    let s = symbolic_surface(n, m);
    let tri = symbolic_triangle();
    let q = restrict_triangle_specialised(&s, &tri).expect("degrees of the proof grid");
    let sample = memoised(|(u, v): &(Poly, Poly)| surface_point(&s, u, v));
    let by_polarisation =
        triangle_control_points_from_samples(n + m, &tri, &|u, v| sample(&(u.clone(), v.clone())));
    ProofRow {
        shape: Shape::Triangle(n, m),
        terms: count_terms(q.control_points()),
        definition: q == restrict_power_surface_to_triangle(&s, &tri, Method::Definition),
        polarisation: q.control_points() == by_polarisation.as_slice(),
    }
}

/// Proves the carried Bézier-curve evaluator of degree `n` (1..=16) symbolically.
///
/// The control points are the Bernstein form b = M c of the symbolic power curve with
/// coefficients c_0..c_n ([`blossom::engine::power_to_bernstein`], an exact change of basis): M is
/// invertible, so an identity of polynomials in c is one in b (every net is the Bernstein form
/// of exactly one power curve, b = M c with c = M^-1 b). This keeps each symbolic value as
/// small as the curve's own (a net of independent symbols b_i makes every sample n times
/// larger) while the evaluator still runs on a symbolic net. The checks are the subset-sum
/// definition (2) of that curve and the inverse formula (22) applied to points of the curve.
pub fn prove_bezier_curve(n: usize) -> ProofRow {
    let power = symbolic_curve(n);
    let curve = blossom::BezierCurve::new(blossom::engine::power_to_bernstein(
        &power.coefficients().to_vec(),
    ))
    .expect("a non-empty polygon");
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let w = restrict_bezier_curve_specialised(&curve, &a, &b).expect("a carried degree");
    ProofRow {
        shape: Shape::BezierCurve(n),
        terms: count_terms(w.control_points()),
        definition: w == restrict_power_curve(&power, &a, &b, Method::Definition),
        polarisation: w.control_points() == curve_by_polarisation(&power, &a, &b).as_slice(),
    }
}

/// A symbolic triangular array of total degree N: c_i_j for i + j <= N, one coordinate.
fn symbolic_power_triangle(big_n: usize) -> PowerTriangle<Poly> {
    PowerTriangle::new(
        (0..=big_n)
            .map(|i| {
                (0..=big_n - i)
                    .map(|j| vec![Poly::var(&format!("c{i}_{j}"))])
                    .collect()
            })
            .collect(),
    )
    .expect("a triangular array")
}

/// The point of a triangular array at symbolic (u, v), with the powers formed once.
fn power_triangle_point(surface: &PowerTriangle<Poly>, u: &Poly, v: &Poly) -> Vec<Poly> {
    let big_n = surface.degree();
    let pu: Vec<Poly> = std::iter::successors(Some(Poly::one()), |p| Some(p.mul(u)))
        .take(big_n + 1)
        .collect();
    let pv: Vec<Poly> = std::iter::successors(Some(Poly::one()), |p| Some(p.mul(v)))
        .take(big_n + 1)
        .collect();
    vec![surface
        .terms()
        .map(|(i, j, c)| c[0].mul(&pu[i].mul(&pv[j])))
        .sum()]
}

/// The inverse formula (23) of seed 004 on `tri`, from points of `surface`.
fn power_triangle_by_polarisation(
    surface: &PowerTriangle<Poly>,
    tri: &[[Poly; 2]; 3],
) -> Vec<Vec<Poly>> {
    let sample = memoised(|(u, v): &(Poly, Poly)| power_triangle_point(surface, u, v));
    triangle_control_points_from_samples(surface.degree(), tri, &|u, v| {
        sample(&(u.clone(), v.clone()))
    })
}

/// Proves the carried evaluator of triangular arrays of total degree `big_n` symbolically:
/// coefficients c_i_j (i + j <= N) and the corners are variables.
pub fn prove_triangle_total(big_n: usize) -> ProofRow {
    let s = symbolic_power_triangle(big_n);
    let tri = symbolic_triangle();
    let q = restrict_power_triangle_specialised(&s, &tri).expect("a carried total degree");
    ProofRow {
        shape: Shape::TriangleTotal(big_n),
        terms: count_terms(q.control_points()),
        definition: q == restrict_power_triangle(&s, &tri, Method::Definition),
        polarisation: q.control_points() == power_triangle_by_polarisation(&s, &tri).as_slice(),
    }
}

/// Proves the carried Bézier tensor evaluator of bidegree `(n, m)` symbolically: the net is
/// the Bernstein form of the symbolic surface (b = M c along u and along v, an exact and
/// invertible change of basis, as for [`prove_bezier_curve`]); the checks are the definition
/// (8) of that surface and two passes of the inverse formula (22) on its points.
pub fn prove_bezier_tensor(n: usize, m: usize) -> ProofRow {
    let s = symbolic_surface(n, m);
    let rows: Vec<Vec<Vec<Poly>>> = s
        .coefficients()
        .iter()
        .map(|row| blossom::engine::power_to_bernstein(&row.to_vec()))
        .collect();
    let columns: Vec<Vec<Vec<Poly>>> = (0..=m)
        .map(|j| {
            let column: Vec<Vec<Poly>> = rows.iter().map(|r| r[j].clone()).collect();
            blossom::engine::power_to_bernstein(&column)
        })
        .collect();
    let net: Vec<Vec<Vec<Poly>>> = (0..=n)
        .map(|i| columns.iter().map(|c| c[i].clone()).collect())
        .collect();
    let patch = blossom::TensorPatch::new(net).expect("a rectangular net");
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let p = restrict_bezier_tensor_specialised(&patch, &rect).expect("a carried bidegree");
    let sample = memoised(|(u, v): &(Poly, Poly)| surface_point(&s, u, v));
    let by_polarisation =
        tensor_control_points_from_samples((n, m), &rect, &|u, v| sample(&(u.clone(), v.clone())));
    ProofRow {
        shape: Shape::BezierTensor(n, m),
        terms: count_terms(p.to_nested().iter().flatten()),
        definition: p == restrict_power_surface(&s, &rect, Method::Definition),
        polarisation: p.to_nested() == by_polarisation.as_slice(),
    }
}

/// Proves the carried Bézier triangle evaluator of degree `big_n` symbolically: the net is the
/// triangular Bernstein form ([`blossom::engine::triangle_power_to_bernstein`], exact and invertible) of
/// the symbolic array c_i_j in the barycentric coordinates (s, t) of the patch's first two
/// corners, so the patch's domain is the triangle (1, 0), (0, 1), (0, 0) of the (s, t) plane and
/// the sub-triangle's corners (a1, a2), (b1, b2), (c1, c2) are variables of that plane. The
/// checks are the definition (13) of the array and the inverse formula (23) on its points.
pub fn prove_bezier_triangle(big_n: usize) -> ProofRow {
    let s = symbolic_power_triangle(big_n);
    let patch = blossom::engine::triangle_power_to_bernstein(&s)
        .expect("a power triangle of a carried degree");
    let tri = symbolic_triangle();
    let q = restrict_bezier_triangle_specialised(&patch, &tri).expect("a carried degree");
    ProofRow {
        shape: Shape::BezierTriangle(big_n),
        terms: count_terms(q.control_points()),
        definition: q == restrict_power_triangle(&s, &tri, Method::Definition),
        polarisation: q.control_points() == power_triangle_by_polarisation(&s, &tri).as_slice(),
    }
}

/// The proof grid: every evaluator the binary carries, run on symbolic polynomials: curves
/// 1..=16, tensor patches (n, m) with 0 <= n, m <= 5, triangles with 0 <= n, m <= 4 ((0, 0)
/// excepted for both), Bézier curves 1..=16, triangular arrays of total degree 1..=6, Bézier
/// tensor patches (n, m) with 0 <= n, m <= 4 ((0, 0) excepted) and Bézier triangles 1..=6.
pub fn proof_table() -> Vec<ProofRow> {
    let mut rows: Vec<ProofRow> = (1..=16).map(prove_curve).collect();
    for n in 0..=5 {
        for m in 0..=5 {
            if (n, m) != (0, 0) {
                rows.push(prove_tensor(n, m));
            }
        }
    }
    for n in 0..=4 {
        for m in 0..=4 {
            if (n, m) != (0, 0) {
                rows.push(prove_triangle(n, m));
            }
        }
    }
    rows.extend((1..=16).map(prove_bezier_curve));
    rows.extend((1..=6).map(prove_triangle_total));
    for n in 0..=4 {
        for m in 0..=4 {
            if (n, m) != (0, 0) {
                rows.push(prove_bezier_tensor(n, m));
            }
        }
    }
    rows.extend((1..=6).map(prove_bezier_triangle));
    rows
}

/// The proof table as aligned text, one row per evaluator.
pub fn proof_table_text(rows: &[ProofRow]) -> String {
    let mut out = format!(
        "{:<12} {:>7} {:>7}  {:<10} {:<12} {}\n",
        "shape", "degree", "terms", "definition", "polarisation", "identical"
    );
    let yes = |b: bool| if b { "yes" } else { "NO" };
    for r in rows {
        out += &format!(
            "{:<12} {:>7} {:>7}  {:<10} {:<12} {}\n",
            r.shape_name(),
            r.degree(),
            r.terms,
            yes(r.definition),
            yes(r.polarisation),
            yes(r.identical())
        );
    }
    out
}
