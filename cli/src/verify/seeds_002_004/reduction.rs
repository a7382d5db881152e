//! Seed 004, Example 2: the degree-10 curve, its printed control polygon, and its reductions to
//! degree 6 by the inverse formula and by least squares (free and with the end points kept),
//! with their exact squared L2 errors on [0, 1].

use super::expr::parse;
use super::{entry, point, sci, show};
use crate::verify::report::{Section, Status};
use blossom::engine::power_to_bernstein;
use blossom::{reduce, squared_l2_distance, Reduction};
use blossom::{BezierCurve, Poly, Rational};

/// The printed parametrisation, coordinate by coordinate.
pub const CURVE: [&str; 2] = [
    "t^10 - 3*t^8 + 2*t^7 - t^5 + t^2 + t - 3",
    "-2*t^10 + t^9 - t^7 + t^5 + t^3 + t^2",
];
/// The printed control polygon of degree 10.
pub const POLYGON: [&str; 11] = [
    "(-3, 0)",
    "(-29/10, 0)",
    "(-25/9, 1/45)",
    "(-79/30, 3/40)",
    "(-37/15, 1/6)",
    "(-575/252, 13/42)",
    "(-439/210, 11/21)",
    "(-19/10, 5/6)",
    "(-26/15, 56/45)",
    "(-9/5, 9/5)",
    "(-2, 1)",
];

/// The power coefficients of the printed curve, read from its formula.
pub fn power_coefficients() -> Vec<Vec<Rational>> {
    let coords: Vec<Poly> = CURVE.iter().map(|c| parse(c)).collect();
    (0..=10u32)
        .map(|k| {
            coords
                .iter()
                .map(|p| {
                    if k == 0 {
                        p.constant_term()
                    } else {
                        p.coefficient(&[("t", k)])
                    }
                })
                .collect()
        })
        .collect()
}

/// The degree-10 Bézier curve of Example 2 (control points by the library's basis change).
pub fn curve() -> BezierCurve<Rational> {
    BezierCurve::new(power_to_bernstein(&power_coefficients())).expect("11 points in the plane")
}

/// The three reductions to degree 6 with their squared L2 errors.
pub fn reductions() -> Vec<(Reduction, BezierCurve<Rational>, Rational)> {
    let b = curve();
    Reduction::ALL
        .into_iter()
        .map(|method| {
            let r = reduce(&b, 6, method).expect("6 < 10");
            let e = squared_l2_distance(&r, &b).expect("same dimension");
            (method, r, e)
        })
        .collect()
}

fn polygon() -> Section {
    let b = curve();
    let entries = POLYGON
        .iter()
        .zip(b.control_points())
        .enumerate()
        .map(|(i, (p, c))| entry(format!("b_{i}"), *p, show(c), point(p) == *c))
        .collect();
    Section::from_entries(
        "Example 2: the control polygon of the degree-10 curve",
        "inverse relations paper, section 4, Example 2",
        entries,
        vec!["computed from the printed b(t) by the Bernstein basis change (u^i = sum_v C(v, i)/C(n, i) B_v^n)".into()],
        Status::Unexplained,
    )
}

/// Sum of |second differences| of a polygon (both coordinates): a measure of oscillation.
fn wiggle(points: &[Vec<Rational>]) -> Rational {
    use num_traits::Signed;
    points
        .windows(3)
        .map(|w| {
            (0..w[0].len())
                .map(|d| (&w[0][d] - &w[1][d] * Rational::from_integer(2.into()) + &w[2][d]).abs())
                .sum::<Rational>()
        })
        .sum()
}

fn reductions_section() -> Section {
    let b = curve();
    let bp = b.control_points();
    let all = reductions();
    let get = |m: Reduction| all.iter().find(|r| r.0 == m).expect("every method");
    let (interp, ls, lse) = (
        get(Reduction::Interpolating),
        get(Reduction::LeastSquares),
        get(Reduction::LeastSquaresEndpoints),
    );
    let keeps = |r: &BezierCurve<Rational>| {
        r.control_points()[0] == bp[0] && r.control_points()[6] == bp[10]
    };
    let entries = vec![
        entry(
            "inverse formula keeps the end points",
            "keeps the endpoints of the original one",
            format!("b~_0 = {}, b~_6 = {}", show(&interp.1.control_points()[0]), show(&interp.1.control_points()[6])),
            keeps(&interp.1),
        ),
        entry(
            "least squares misses the end points",
            "does not pass through the first and last vertices",
            format!("b~_0 = {}, b~_6 = {}", show(&ls.1.control_points()[0]), show(&ls.1.control_points()[6])),
            !keeps(&ls.1),
        ),
        entry(
            "constrained least squares keeps the end points",
            "imposing the values of b(0) and b(1)",
            format!("b~_0 = {}, b~_6 = {}", show(&lse.1.control_points()[0]), show(&lse.1.control_points()[6])),
            keeps(&lse.1),
        ),
        entry(
            "least squares fits globally closer",
            "globally closer fitting",
            format!("squared L2 errors: least squares {}, with end points {}, inverse formula {}", sci(&ls.2, 6), sci(&lse.2, 6), sci(&interp.2, 6)),
            ls.2 < lse.2 && lse.2 < interp.2,
        ),
        entry(
            "inverse formula polygon oscillates less",
            "a control polygon that oscillates less",
            format!(
                "sum of |second differences|: inverse formula {}, least squares {}, with end points {}",
                sci(&wiggle(&interp.1.control_points().to_vec()), 4),
                sci(&wiggle(&ls.1.control_points().to_vec()), 4),
                sci(&wiggle(&lse.1.control_points().to_vec()), 4)
            ),
            wiggle(&interp.1.control_points().to_vec()) < wiggle(&ls.1.control_points().to_vec()),
        ),
    ];
    let mut findings: Vec<String> = all
        .iter()
        .map(|(m, r, e)| {
            let pts: Vec<String> = r
                .control_points()
                .iter()
                .map(|p| format!("({}, {})", sci(&p[0], 6), sci(&p[1], 6)))
                .collect();
            format!(
                "{}: squared L2 error int_0^1 |b~ - b|^2 dt = {} = {}; polygon {}",
                m.name(),
                e,
                sci(e, 6),
                pts.join(", ")
            )
        })
        .collect();
    findings.insert(0, "the paper shows the three reductions in Figures 2-4 only; the values below are computed exactly (the same as `reduce` jobs of `blossom restrict` give)".into());
    Section::from_entries(
        "Example 2: reductions to degree 6 and their L2 errors",
        "inverse relations paper, section 4, Example 2, Figures 2-4",
        entries,
        findings,
        Status::Unexplained,
    )
}

/// The sections of Example 2.
pub fn sections() -> Vec<Section> {
    vec![polygon(), reductions_section()]
}
