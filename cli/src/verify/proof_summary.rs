//! The report's summary of the symbolic proofs of the engine ([`crate::proofs`]).

use super::report::{Section, Status};
use crate::proofs::{proof_grid, prove_bezier_input, ProofRow, Shape};

/// Degrees proved while the report runs (the test suite proves the full grid: curves n <= 8,
/// tensors up to (4, 4), triangles N <= 6, with `cargo test --test symbolic_proofs`).
pub const REPORT_GRID: (usize, usize, usize) = (8, 3, 5);

fn describe(rows: &[ProofRow], shape: Shape) -> String {
    let of_shape: Vec<&ProofRow> = rows.iter().filter(|r| r.shape == shape).collect();
    let proved = of_shape.iter().filter(|r| r.identical).count();
    // Every method of one degree is compared with the same reference: count it once.
    let terms: usize = of_shape
        .iter()
        .filter(|r| r.method == blossom::Method::Bulk)
        .map(|r| r.terms)
        .sum();
    let degrees = match shape {
        Shape::Curve => format!("n = 0..={}", REPORT_GRID.0),
        Shape::Tensor => format!("(n, m) in 0..={} x 0..={}", REPORT_GRID.1, REPORT_GRID.1),
        Shape::Triangle => format!("n + m <= {}", REPORT_GRID.2),
    };
    let mut failures: Vec<String> = of_shape
        .iter()
        .filter(|r| !r.identical)
        .map(|r| format!("{} ({}, {})", r.method.name(), r.degree.0, r.degree.1))
        .collect();
    failures.truncate(5);
    let mut line = format!(
        "{} {degrees}: {proved}/{} proofs identical to the definition \
         (methods bulk, taylor-shift, closed-form, pyramid, polarisation; references of {terms} monomials in all)",
        shape.name(),
        of_shape.len()
    );
    if !failures.is_empty() {
        line.push_str(&format!("; NOT identical: {}", failures.join(", ")));
    }
    line
}

/// The proof section: every method against the subset-sum definition, as polynomials in all
/// coefficients and domain corners.
pub fn section() -> Section {
    let (c, t, tr) = REPORT_GRID;
    let rows = proof_grid(c, t, tr);
    let bezier = prove_bezier_input(c, t, tr);
    let ok = rows.iter().all(|r| r.identical) && bezier.iter().all(|r| r.identical);
    let mut findings: Vec<String> = [Shape::Curve, Shape::Tensor, Shape::Triangle]
        .iter()
        .map(|&s| describe(&rows, s))
        .collect();
    findings.push(format!(
        "the halving engine on Bézier input (power input written in the Bernstein basis, then \
         restrict_bezier_*): {}/{} proofs identical to the definition on the same grid",
        bezier.iter().filter(|r| r.identical).count(),
        bezier.len()
    ));
    findings.push(
        "the full grid (curves n <= 8, tensors (4, 4), triangles N <= 6) runs in \
         `cargo test --test symbolic_proofs`"
            .into(),
    );
    Section {
        title: "Symbolic proofs of the restriction methods".into(),
        source: "definitions (2), (8), (13); Theorems 1-3; inverse relations paper eqs. (2), (9), (19)-(21)"
            .into(),
        status: if ok {
            Status::Reproduced
        } else {
            Status::Unexplained
        },
        entries: vec![],
        findings,
    }
}
