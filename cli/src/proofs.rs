//! Symbolic proofs: every restriction method, run on [`Poly`] inputs whose coefficients and
//! domain corners are variables, yields polynomials identical to those of the subset-sum
//! definition. Identity of the polynomials is a proof that the methods agree for that degree
//! and every input, not a sample.

use blossom::{restrict_curve, restrict_tensor, restrict_triangle, Method};
use blossom::{Poly, PowerCurve, PowerSurface};

/// The shape a proof is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A curve of degree n.
    Curve,
    /// A tensor-product patch of bidegree (n, m).
    Tensor,
    /// A triangular patch of total degree n + m.
    Triangle,
}

impl Shape {
    /// Lowercase name.
    pub fn name(self) -> &'static str {
        match self {
            Shape::Curve => "curve",
            Shape::Tensor => "tensor",
            Shape::Triangle => "triangle",
        }
    }
}

/// One proof: a method against the definition for one shape and degree.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProofRow {
    /// The shape.
    pub shape: Shape,
    /// `(n, m)`; `m = 0` for curves.
    pub degree: (usize, usize),
    /// The method compared with the definition.
    pub method: Method,
    /// Number of monomials in all control points of the definition (size of what is proved).
    pub terms: usize,
    /// Whether the method's control points are identical polynomials.
    pub identical: bool,
}

/// The power-basis curve of degree `n` with one coordinate and coefficients `c0..cn`.
pub fn symbolic_curve(n: usize) -> PowerCurve<Poly> {
    PowerCurve::new((0..=n).map(|i| vec![Poly::var(&format!("c{i}"))]).collect())
        .expect("a non-empty curve")
}

/// The power-basis surface of bidegree (n, m) with coefficients `c_i_j`.
pub fn symbolic_surface(n: usize, m: usize) -> PowerSurface<Poly> {
    PowerSurface::new(
        (0..=n)
            .map(|i| {
                (0..=m)
                    .map(|j| vec![Poly::var(&format!("c_{i}_{j}"))])
                    .collect()
            })
            .collect(),
    )
    .expect("a non-empty grid")
}

fn vars<const K: usize>(names: [&str; K]) -> [Poly; K] {
    names.map(Poly::var)
}

fn count_terms<'a>(points: impl Iterator<Item = &'a Vec<Poly>>) -> usize {
    points.flat_map(|p| p.iter()).map(Poly::num_terms).sum()
}

/// Proves each of `methods` against the definition for the curve of degree `n` on [a, b].
pub fn prove_curve(n: usize, methods: &[Method]) -> Vec<ProofRow> {
    let curve = symbolic_curve(n);
    let [a, b] = vars(["a", "b"]);
    let reference = restrict_curve(&curve, &a, &b, Method::Definition);
    let terms = count_terms(reference.control_points().iter());
    methods
        .iter()
        .map(|&method| ProofRow {
            shape: Shape::Curve,
            degree: (n, 0),
            method,
            terms,
            identical: restrict_curve(&curve, &a, &b, method) == reference,
        })
        .collect()
}

/// Proves each of `methods` against the definition for the (n, m) patch on [a, b] x [c, d].
pub fn prove_tensor(n: usize, m: usize, methods: &[Method]) -> Vec<ProofRow> {
    let surface = symbolic_surface(n, m);
    let rect = vars(["a", "b", "c", "d"]);
    let reference = restrict_tensor(&surface, &rect, Method::Definition);
    let terms = count_terms(reference.control_points().iter().flatten());
    methods
        .iter()
        .map(|&method| ProofRow {
            shape: Shape::Tensor,
            degree: (n, m),
            method,
            terms,
            identical: restrict_tensor(&surface, &rect, method) == reference,
        })
        .collect()
}

/// The symbolic triangle with corners (a1, a2), (b1, b2), (c1, c2).
pub fn symbolic_triangle() -> [[Poly; 2]; 3] {
    let [a1, a2, b1, b2, c1, c2] = vars(["a1", "a2", "b1", "b2", "c1", "c2"]);
    [[a1, a2], [b1, b2], [c1, c2]]
}

/// Proves each of `methods` against the definition for the surface of bidegree (n, m) as a
/// triangular patch of total degree n + m on the triangle with symbolic corners.
pub fn prove_triangle(n: usize, m: usize, methods: &[Method]) -> Vec<ProofRow> {
    let surface = symbolic_surface(n, m);
    let tri = symbolic_triangle();
    let reference = restrict_triangle(&surface, &tri, Method::Definition);
    let terms = count_terms(reference.control_points().iter());
    methods
        .iter()
        .map(|&method| ProofRow {
            shape: Shape::Triangle,
            degree: (n, m),
            method,
            terms,
            identical: restrict_triangle(&surface, &tri, method) == reference,
        })
        .collect()
}

/// Every method other than the definition itself.
pub const OTHER_METHODS: [Method; 4] = [
    Method::Bulk,
    Method::ClosedForm,
    Method::Pyramid,
    Method::Polarisation,
];

/// The proof grid of the engine: curves n <= `max_curve`, tensor patches up to
/// (`max_tensor`, `max_tensor`), triangles with n + m <= `max_triangle`.
pub fn proof_grid(max_curve: usize, max_tensor: usize, max_triangle: usize) -> Vec<ProofRow> {
    let mut rows = Vec::new();
    for n in 0..=max_curve {
        rows.extend(prove_curve(n, &OTHER_METHODS));
    }
    for n in 0..=max_tensor {
        for m in 0..=max_tensor {
            rows.extend(prove_tensor(n, m, &OTHER_METHODS));
        }
    }
    for big_n in 0..=max_triangle {
        for n in 0..=big_n {
            rows.extend(prove_triangle(n, big_n - n, &OTHER_METHODS));
        }
    }
    rows
}
