//! Seed 004, Example 1: control points and weights of the circle arc
//! b(t) = ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)) on [alpha, beta], as a quadratic and,
//! formally, as a quartic; symbolic in alpha and beta, then at alpha = 0, beta = 1.

use super::expr::parse;
use super::{entry, point, show};
use crate::verify::report::{Section, Status};
use blossom::RationalCurve;
use blossom::{Poly, Rational, Ring};

/// Printed control points as ((x numerator, x denominator), (y numerator, y denominator)) and
/// weights, for degree n.
type Printed = (usize, &'static [([&'static str; 4], &'static str)]);
const QUADRATIC: Printed = (
    2,
    &[
        (
            ["1 - alpha^2", "1 + alpha^2", "2*alpha", "1 + alpha^2"],
            "1 + alpha^2",
        ),
        (
            [
                "1 - alpha*beta",
                "1 + alpha*beta",
                "alpha + beta",
                "1 + alpha*beta",
            ],
            "1 + alpha*beta",
        ),
        (
            ["1 - beta^2", "1 + beta^2", "2*beta", "1 + beta^2"],
            "1 + beta^2",
        ),
    ],
);
const QUARTIC: Printed = (
    4,
    &[
        (
            ["1 - alpha^2", "1 + alpha^2", "2*alpha", "1 + alpha^2"],
            "1 + alpha^2",
        ),
        (
            [
                "2 - alpha^2 - alpha*beta",
                "2 + alpha^2 + alpha*beta",
                "3*alpha + beta",
                "2 + alpha^2 + alpha*beta",
            ],
            "1 + (alpha^2 + alpha*beta)/2",
        ),
        (
            [
                "6 - alpha^2 - 4*alpha*beta - beta^2",
                "6 + alpha^2 + 4*alpha*beta + beta^2",
                "6*(alpha + beta)",
                "6 + alpha^2 + 4*alpha*beta + beta^2",
            ],
            "1 + (alpha^2 + 4*alpha*beta + beta^2)/6",
        ),
        (
            [
                "2 - alpha*beta - beta^2",
                "2 + alpha*beta + beta^2",
                "alpha + 3*beta",
                "2 + alpha*beta + beta^2",
            ],
            "1 + (alpha*beta + beta^2)/2",
        ),
        (
            ["1 - beta^2", "1 + beta^2", "2*beta", "1 + beta^2"],
            "1 + beta^2",
        ),
    ],
);
/// The printed polygon and weights of the quadratic for alpha = 0, beta = 1.
pub const UNIT_QUADRATIC: ([&str; 3], [&str; 3]) =
    (["(1, 0)", "(1, 1)", "(0, 1)"], ["1", "1", "2"]);
/// The printed polygon and weights of the quartic for alpha = 0, beta = 1.
pub const UNIT_QUARTIC: ([&str; 5], [&str; 5]) = (
    ["(1, 0)", "(1, 1/2)", "(5/7, 6/7)", "(1/3, 1)", "(0, 1)"],
    ["1", "1", "7/6", "3/2", "2"],
);

fn arc<T: Ring>() -> RationalCurve<T> {
    let k = |n: i64| T::from_int(n);
    RationalCurve::new(
        &[vec![k(1), k(0)], vec![k(0), k(2)], vec![k(-1), k(0)]],
        &[k(1), k(0), k(1)],
    )
    .expect("the arc is a valid rational curve")
}

fn section(
    title: &str,
    (n, printed): Printed,
    unit_points: &[&str],
    unit_weights: &[&str],
) -> Section {
    let alpha = Poly::var("alpha");
    let beta = Poly::var("beta");
    let h = arc::<Poly>()
        .homogeneous_control_points(&alpha, &beta, n)
        .expect("degree >= 2");
    let h = h.control_points();
    let mut entries = Vec::new();
    for (i, (fr, w)) in printed.iter().enumerate() {
        let [xn, xd, yn, yd] = fr.map(parse);
        // b_i = h_i / w_i as rational functions: h_x * den = num * h_w.
        let ok_x = h[i][0].mul(&xd) == xn.mul(&h[i][2]);
        let ok_y = h[i][1].mul(&yd) == yn.mul(&h[i][2]);
        entries.push(entry(
            format!("b_{i}"),
            format!("(({})/({}), ({})/({}))", fr[0], fr[1], fr[2], fr[3]),
            format!("({}, {}) / ({})", h[i][0], h[i][1], h[i][2]),
            ok_x && ok_y,
        ));
        entries.push(entry(
            format!("w_{i}"),
            *w,
            h[i][2].to_string(),
            h[i][2] == parse(w),
        ));
    }
    let q = |k: i64| Rational::from_int(k);
    let unit = arc::<Rational>()
        .bezier(&q(0), &q(1), Some(n))
        .expect("no zero weights on [0, 1]");
    let want_points: Vec<Vec<Rational>> = unit_points.iter().map(|p| point(p)).collect();
    let want_weights: Vec<Rational> = unit_weights.iter().map(|w| super::num(w)).collect();
    entries.push(entry(
        "alpha = 0, beta = 1: polygon",
        format!("{{{}}}", unit_points.join(", ")),
        format!(
            "{{{}}}",
            unit.points()
                .iter()
                .map(show)
                .collect::<Vec<_>>()
                .join(", ")
        ),
        unit.points() == want_points.as_slice(),
    ));
    entries.push(entry(
        "alpha = 0, beta = 1: weights",
        format!("{{{}}}", unit_weights.join(", ")),
        format!(
            "{{{}}}",
            unit.weights()
                .iter()
                .map(|w| w.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
        unit.weights() == want_weights.as_slice(),
    ));
    Section::from_entries(
        title,
        "inverse relations paper, section 4, Example 1",
        entries,
        vec![format!(
            "the homogeneous control points (w_i b_i, w_i) are blossom values of (1 - t^2, 2t, 1 + t^2) at alpha^({n}-i) beta^i \
             by the inverse formula (22) at degree {n}, with alpha and beta symbols; a printed b_i is compared as a rational \
             function (numerator * w_i = denominator * w_i b_i)"
        )],
        Status::Unexplained,
    )
}

/// The sections of Example 1.
pub fn sections() -> Vec<Section> {
    vec![
        section(
            "Example 1: circle arc as a quadratic",
            QUADRATIC,
            &UNIT_QUADRATIC.0,
            &UNIT_QUADRATIC.1,
        ),
        section(
            "Example 1: circle arc as a quartic (degree elevation built in)",
            QUARTIC,
            &UNIT_QUARTIC.0,
            &UNIT_QUARTIC.1,
        ),
    ]
}
