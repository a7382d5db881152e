//! The symbolic proofs of the carried evaluators (the proof grid of `blossom verify`).

use super::Shape;
use crate::proofs::{symbolic_curve, symbolic_surface, symbolic_triangle};
use blossom::Poly;
use blossom::{bezier_curve_blossom, restrict_curve, restrict_tensor, restrict_triangle, Method};
use blossom_grid::{
    restrict_bezier_curve_specialised, restrict_curve_specialised, restrict_tensor_specialised,
    restrict_triangle_specialised,
};

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
    /// Bézier input, to de Casteljau's pyramid on the net, the definition of the blossom of a
    /// Bézier curve (seed 004, eq. (2)).
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

fn count_terms<'a>(points: impl IntoIterator<Item = &'a Vec<Poly>>) -> usize {
    points.into_iter().flatten().map(Poly::num_terms).sum()
}

/// Proves the carried curve evaluator of degree `n` (1..=16) symbolically.
pub fn prove_curve(n: usize) -> ProofRow {
    let curve = symbolic_curve(n);
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let w = restrict_curve_specialised(&curve, &a, &b).expect("a degree of the proof grid");
    ProofRow {
        shape: Shape::Curve(n),
        terms: count_terms(w.control_points()),
        definition: w == restrict_curve(&curve, &a, &b, Method::Definition),
        polarisation: w == restrict_curve(&curve, &a, &b, Method::Polarisation),
    }
}

/// Proves the carried tensor evaluator of bidegree `(n, m)` symbolically.
pub fn prove_tensor(n: usize, m: usize) -> ProofRow {
    let s = symbolic_surface(n, m);
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let p = restrict_tensor_specialised(&s, &rect).expect("a bidegree of the proof grid");
    ProofRow {
        shape: Shape::Tensor(n, m),
        terms: count_terms(p.control_points().iter().flatten()),
        definition: p == restrict_tensor(&s, &rect, Method::Definition),
        polarisation: p == restrict_tensor(&s, &rect, Method::Polarisation),
    }
}

/// Proves the carried triangle evaluator of degrees `(n, m)` symbolically.
pub fn prove_triangle(n: usize, m: usize) -> ProofRow {
    let s = symbolic_surface(n, m);
    let tri = symbolic_triangle();
    let q = restrict_triangle_specialised(&s, &tri).expect("degrees of the proof grid");
    ProofRow {
        shape: Shape::Triangle(n, m),
        terms: count_terms(q.control_points()),
        definition: q == restrict_triangle(&s, &tri, Method::Definition),
        polarisation: q == restrict_triangle(&s, &tri, Method::Polarisation),
    }
}

/// Proves the carried Bézier-curve evaluator of degree `n` (1..=16) symbolically: control
/// points `b_i` and the interval [a, b] are variables; the check are the pyramid on the net
/// and the inverse formula (22) of seed 004 applied to points of the curve.
pub fn prove_bezier_curve(n: usize) -> ProofRow {
    let net: Vec<Vec<Poly>> = (0..=n).map(|i| vec![Poly::var(&format!("b{i}"))]).collect();
    let curve = blossom::BezierCurve::new(net).expect("a non-empty polygon");
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let w = restrict_bezier_curve_specialised(&curve, &a, &b).expect("a carried degree");
    let by_pyramid: Vec<Vec<Poly>> = (0..=n)
        .map(|j| {
            let args = crate::repeated(&a, n - j, &b, j);
            bezier_curve_blossom(curve.control_points(), &args)
        })
        .collect();
    let by_inverse = blossom::curve_control_points_from_samples(n, &a, &b, &|t| curve.eval(t));
    ProofRow {
        shape: Shape::BezierCurve(n),
        terms: count_terms(w.control_points()),
        definition: w.control_points() == by_pyramid.as_slice(),
        polarisation: w.control_points() == by_inverse.as_slice(),
    }
}

/// The proof grid: curves 1..=10, tensor patches (1..=4) x (1..=4), triangles with
/// 1 <= n, m <= 3, Bézier curves 1..=10 (their evaluators are the carried ones, so this
/// proves the code the binary runs).
pub fn proof_table() -> Vec<ProofRow> {
    let mut rows: Vec<ProofRow> = (1..=10).map(prove_curve).collect();
    for n in 1..=4 {
        for m in 1..=4 {
            rows.push(prove_tensor(n, m));
        }
    }
    for n in 1..=3 {
        for m in 1..=3 {
            rows.push(prove_triangle(n, m));
        }
    }
    rows.extend((1..=10).map(prove_bezier_curve));
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
