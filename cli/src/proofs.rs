//! Symbolic proofs: every restriction method, run on [`Poly`] inputs whose coefficients and
//! domain corners are variables, yields polynomials identical to those of the subset-sum
//! definition. Identity of the polynomials is a proof that the methods agree for that degree
//! and every input, not a sample.
//!
//! The same comparison takes any candidate function in place of a method
//! ([`prove_curve_candidate`], [`prove_tensor_candidate`], [`prove_triangle_candidate`]), so
//! that a wrong one, e.g. eq. (14) with a misprinted ingredient, can be shown to fail it.

use blossom::engine::{power_to_bernstein, power_to_bernstein_flat, triangle_power_to_bernstein};
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method, Ring,
};
use blossom::{
    BezierCurve, Poly, PowerCurve, PowerSurface, PowerTriangle, TensorPatch, TriangularPatch,
};

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

fn count_terms<P: AsRef<[Poly]>>(points: impl Iterator<Item = P>) -> usize {
    points
        .map(|p| p.as_ref().iter().map(Poly::num_terms).sum::<usize>())
        .sum()
}

/// A candidate restriction of curves: the control points on [a, b] of a power-basis curve.
pub type CurveCandidate<'a> = &'a dyn Fn(&PowerCurve<Poly>, &Poly, &Poly) -> BezierCurve<Poly>;

/// A candidate restriction of tensor patches: the net on `[a, b, c, d]`.
pub type TensorCandidate<'a> = &'a dyn Fn(&PowerSurface<Poly>, &[Poly; 4]) -> TensorPatch<Poly>;

/// A candidate restriction of triangular patches: the net on the triangle with corners `tri`.
pub type TriangleCandidate<'a> =
    &'a dyn Fn(&PowerSurface<Poly>, &[[Poly; 2]; 3]) -> TriangularPatch<Poly>;

/// One candidate restriction, any function of the symbolic input, against the definition:
/// the same comparison as a [`ProofRow`], named by the caller instead of by a [`Method`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CandidateProof {
    /// The shape.
    pub shape: Shape,
    /// `(n, m)`; `m = 0` for curves.
    pub degree: (usize, usize),
    /// What the candidate is, in words.
    pub name: String,
    /// Number of monomials in all control points of the definition (size of what is proved).
    pub terms: usize,
    /// Whether the candidate's control points are identical polynomials.
    pub identical: bool,
}

/// The symbolic input of one shape and degree and the definition's answer on it: every proof,
/// of a method or of a candidate, is [`Reference::identical`], the one comparison.
struct Reference<I, O> {
    shape: Shape,
    degree: (usize, usize),
    input: I,
    answer: O,
    terms: usize,
}

impl<I, O: PartialEq> Reference<I, O> {
    /// Whether `candidate` gives the definition's answer on the symbolic input, as
    /// polynomials (identical coefficients of every monomial).
    fn identical(&self, candidate: &dyn Fn(&I) -> O) -> bool {
        candidate(&self.input) == self.answer
    }

    fn method_row(&self, method: Method, candidate: &dyn Fn(&I) -> O) -> ProofRow {
        ProofRow {
            shape: self.shape,
            degree: self.degree,
            method,
            terms: self.terms,
            identical: self.identical(candidate),
        }
    }

    fn candidate_proof(&self, name: &str, candidate: &dyn Fn(&I) -> O) -> CandidateProof {
        CandidateProof {
            shape: self.shape,
            degree: self.degree,
            name: name.to_string(),
            terms: self.terms,
            identical: self.identical(candidate),
        }
    }
}

type CurveInput = (PowerCurve<Poly>, [Poly; 2]);
type TensorInput = (PowerSurface<Poly>, [Poly; 4]);
type TriangleInput = (PowerSurface<Poly>, [[Poly; 2]; 3]);

/// The curve of degree `n` on [a, b] and the definition's control points.
fn curve_reference(n: usize) -> Reference<CurveInput, BezierCurve<Poly>> {
    let curve = symbolic_curve(n);
    let [a, b] = vars(["a", "b"]);
    let answer = restrict_power_curve(&curve, &a, &b, Method::Definition);
    let terms = count_terms(answer.control_points().iter());
    Reference {
        shape: Shape::Curve,
        degree: (n, 0),
        input: (curve, [a, b]),
        answer,
        terms,
    }
}

/// The (n, m) patch on [a, b] x [c, d] and the definition's net.
fn tensor_reference(n: usize, m: usize) -> Reference<TensorInput, TensorPatch<Poly>> {
    let surface = symbolic_surface(n, m);
    let rect = vars(["a", "b", "c", "d"]);
    let answer = restrict_power_surface(&surface, &rect, Method::Definition);
    let terms = count_terms(answer.to_nested().iter().flatten());
    Reference {
        shape: Shape::Tensor,
        degree: (n, m),
        input: (surface, rect),
        answer,
        terms,
    }
}

/// The surface of bidegree (n, m) as a triangular patch of total degree n + m on the
/// triangle with symbolic corners, and the definition's net.
fn triangle_reference(n: usize, m: usize) -> Reference<TriangleInput, TriangularPatch<Poly>> {
    let surface = symbolic_surface(n, m);
    let tri = symbolic_triangle();
    let answer = restrict_power_surface_to_triangle(&surface, &tri, Method::Definition);
    let terms = count_terms(answer.control_points().iter());
    Reference {
        shape: Shape::Triangle,
        degree: (n, m),
        input: (surface, tri),
        answer,
        terms,
    }
}

/// Proves each of `methods` against the definition for the curve of degree `n` on [a, b].
pub fn prove_curve(n: usize, methods: &[Method]) -> Vec<ProofRow> {
    let reference = curve_reference(n);
    methods
        .iter()
        .map(|&method| {
            reference.method_row(method, &|(curve, [a, b])| {
                restrict_power_curve(curve, a, b, method)
            })
        })
        .collect()
}

/// Runs `candidate` through the comparison of [`prove_curve`]: identical as polynomials to the
/// definition for the curve of degree `n` on [a, b], or not.
pub fn prove_curve_candidate(n: usize, name: &str, candidate: CurveCandidate) -> CandidateProof {
    curve_reference(n).candidate_proof(name, &|(curve, [a, b])| candidate(curve, a, b))
}

/// Proves each of `methods` against the definition for the (n, m) patch on [a, b] x [c, d].
pub fn prove_tensor(n: usize, m: usize, methods: &[Method]) -> Vec<ProofRow> {
    let reference = tensor_reference(n, m);
    methods
        .iter()
        .map(|&method| {
            reference.method_row(method, &|(surface, rect)| {
                restrict_power_surface(surface, rect, method)
            })
        })
        .collect()
}

/// Runs `candidate` through the comparison of [`prove_tensor`] for the (n, m) patch.
pub fn prove_tensor_candidate(
    n: usize,
    m: usize,
    name: &str,
    candidate: TensorCandidate,
) -> CandidateProof {
    tensor_reference(n, m).candidate_proof(name, &|(surface, rect)| candidate(surface, rect))
}

/// The symbolic triangle with corners (a1, a2), (b1, b2), (c1, c2).
pub fn symbolic_triangle() -> [[Poly; 2]; 3] {
    let [a1, a2, b1, b2, c1, c2] = vars(["a1", "a2", "b1", "b2", "c1", "c2"]);
    [[a1, a2], [b1, b2], [c1, c2]]
}

/// Proves each of `methods` against the definition for the surface of bidegree (n, m) as a
/// triangular patch of total degree n + m on the triangle with symbolic corners.
pub fn prove_triangle(n: usize, m: usize, methods: &[Method]) -> Vec<ProofRow> {
    let reference = triangle_reference(n, m);
    methods
        .iter()
        .map(|&method| {
            reference.method_row(method, &|(surface, tri)| {
                restrict_power_surface_to_triangle(surface, tri, method)
            })
        })
        .collect()
}

/// Runs `candidate` through the comparison of [`prove_triangle`] for the surface of bidegree
/// (n, m) on the symbolic triangle; e.g. eq. (14) read with a printed variant of one of its
/// ingredients, through [`blossom::engine::restrict_triangle_with_formula`].
pub fn prove_triangle_candidate(
    n: usize,
    m: usize,
    name: &str,
    candidate: TriangleCandidate,
) -> CandidateProof {
    triangle_reference(n, m).candidate_proof(name, &|(surface, tri)| candidate(surface, tri))
}

/// Every method other than the definition itself.
pub const OTHER_METHODS: [Method; 5] = [
    Method::Bulk,
    Method::TaylorShift,
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

/// The surface as a tensor-product Bézier patch over [0, 1]^2: rows to the Bernstein basis
/// along v, then columns along u ([`power_to_bernstein`], an exact change of basis).
pub fn bernstein_tensor<T: Ring>(surface: &PowerSurface<T>) -> TensorPatch<T> {
    let (dim, (n, m)) = (surface.dim(), surface.degree());
    let cols = m + 1;
    let mut net = surface.coordinates().to_vec();
    for row in net.chunks_exact_mut(cols * dim) {
        power_to_bernstein_flat(row, dim);
    }
    power_to_bernstein_flat(&mut net, cols * dim);
    TensorPatch::from_coordinates((n, m), dim, net).expect("a rectangular net")
}

/// The surface, of total degree N = n + m, as a triangular Bézier patch on the reference
/// triangle a = (1, 0), b = (0, 1), c = (0, 0): a point (u, v) has barycentric coordinates
/// (u, v, 1 - u - v) ([`triangle_power_to_bernstein`], an exact change of basis).
pub fn bernstein_triangle<T: Ring>(surface: &PowerSurface<T>) -> TriangularPatch<T> {
    triangle_power_to_bernstein(&PowerTriangle::from_surface(surface))
        .expect("a net of the surface's total degree")
}

/// The name of the Bézier-input proofs in [`prove_bezier_input`].
pub const BEZIER_INPUT: &str = "halving engine on Bézier input";

/// The restriction engine on *Bézier* input, against the definition on the power input: the
/// symbolic power form is written in the Bernstein basis over the reference domain
/// ([`power_to_bernstein`], [`triangle_power_to_bernstein`], exact changes of basis that the
/// engine never calls), then restricted by [`BezierCurve::subsegment`],
/// [`TensorPatch::restrict`] and [`TriangularPatch::restrict`], whose de Casteljau
/// steps never leave the Bernstein basis. Same grid as [`proof_grid`].
pub fn prove_bezier_input(
    max_curve: usize,
    max_tensor: usize,
    max_triangle: usize,
) -> Vec<CandidateProof> {
    let mut rows = Vec::new();
    for n in 0..=max_curve {
        rows.push(
            curve_reference(n).candidate_proof(BEZIER_INPUT, &|(curve, [a, b])| {
                let bezier = BezierCurve::new(power_to_bernstein(&curve.coefficients().to_vec()))
                    .expect("n + 1 points");
                bezier.subsegment(a.clone()..b.clone())
            }),
        );
    }
    for n in 0..=max_tensor {
        for m in 0..=max_tensor {
            rows.push(
                tensor_reference(n, m).candidate_proof(BEZIER_INPUT, &|(surface, rect)| {
                    bernstein_tensor(surface).restrict(rect)
                }),
            );
        }
    }
    for big_n in 0..=max_triangle {
        for n in 0..=big_n {
            let m = big_n - n;
            rows.push(
                triangle_reference(n, m).candidate_proof(BEZIER_INPUT, &|(surface, tri)| {
                    bernstein_triangle(surface).restrict(tri)
                }),
            );
        }
    }
    rows
}
