//! Seed 002: the knot vectors of section 1, the de Boor points of the cubic example on
//! T = (0,0,0,0,1,2,4,5,6,6,6,6) (Theorem 2.2), F(0,8) by de Boor's algorithm (Theorem 2.3)
//! and the Curry-Schoenberg example (Theorem 2.4).

use super::expr::parse;
use super::{entry, num, point, show};
use crate::verify::report::{Section, Status};
use blossom::curve_blossom;
use blossom::{
    bspline_from_pieces as from_pieces, continuity_at as continuity, BSpline, KnotVector, Piece,
};
use blossom::{Poly, PowerCurve, Rational, Ring};

const SOURCE: &str = "de Boor points paper";

/// Ejemplo 1 as printed: the knots and the 8 de Boor points of a cubic.
const EXAMPLE_1_KNOTS: &str = "0, 0, 0, 0, 1, 2, 4, 5, 6, 6, 6, 6, 6";
pub const EXAMPLE_1_POINTS: [&str; 8] = [
    "(6, 3)", "(7, 8)", "(12, 5)", "(9, 0)", "(1, 0)", "(0, 6)", "(3, 8)", "(4, 4)",
];
/// Ejemplo 2 as printed.
const EXAMPLE_2_KNOTS: &str = "0, 1, 2, 3, 4, 5, 6, 7";
const EXAMPLE_2_POINTS: [&str; 4] = ["(0, 0)", "(3, 9)", "(6, 3)", "(9, 6)"];
/// The knot vector of the application of Theorem 2.2.
pub const THEOREM_2_2_KNOTS: &str = "0, 0, 0, 0, 1, 2, 4, 5, 6, 6, 6, 6";
/// The printed d_k = f_j(args) of that application: (k, j, args).
const THEOREM_2_2_POINTS: [(usize, usize, &str); 8] = [
    (1, 4, "0, 0, 0"),
    (2, 4, "0, 0, 1"),
    (3, 4, "0, 1, 2"),
    (4, 4, "1, 2, 4"),
    (5, 8, "2, 4, 5"),
    (6, 8, "4, 5, 6"),
    (7, 8, "5, 6, 6"),
    (8, 8, "6, 6, 6"),
];

/// Printed knots separated by commas.
pub fn knots(text: &str) -> Vec<Rational> {
    text.split(',').map(num).collect()
}

/// Printed points.
pub fn points(texts: &[&str]) -> Vec<Vec<Rational>> {
    texts.iter().map(|t| point(t)).collect()
}

fn list(v: &[Rational]) -> String {
    v.iter()
        .map(|x| x.to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

/// The power-basis piece on the span with the paper's (1-based) index j, by the recursive
/// definition of the B-splines (Definition 1.1), independent of blossoms and de Boor.
fn piece_on(f: &BSpline<Rational>, j: usize) -> PowerCurve<Rational> {
    let t = f.knots();
    let pieces = f.power_pieces().expect("valid pieces");
    pieces
        .into_iter()
        .find(|pc| pc.interval == [t[j - 1].clone(), t[j].clone()])
        .expect("a non-empty span")
        .curve
}

fn knot_vectors() -> Section {
    let mut entries = Vec::new();
    let mut findings = Vec::new();
    let t1 = knots(EXAMPLE_1_KNOTS);
    let d1 = points(&EXAMPLE_1_POINTS);
    let bad = BSpline::new(3, t1.clone(), d1.clone()).err();
    entries.push(entry(
        "Ejemplo 1: T for 8 de Boor points of degree 3",
        format!("({EXAMPLE_1_KNOTS}), 13 knots"),
        match &bad {
            Some(e) => format!("rejected: {e}"),
            None => "accepted".into(),
        },
        bad.is_none(),
    ));
    let fixed: Vec<Rational> = t1[..12].to_vec();
    let multiplicity = KnotVector::new(3, t1.clone()).err();
    let ok = BSpline::new(3, fixed.clone(), d1).is_ok();
    findings.push(format!(
        "Ejemplo 1 prints 13 knots, but m + p + 1 = 8 + 3 + 1 = 12, and the knot 6 then has multiplicity 5 > p + 1 = 4 \
         ({}); with one 6 fewer, T = ({}), the knot vector of the application of Theorem 2.2, is valid: {ok}",
        multiplicity.map(|e| e.to_string()).unwrap_or_default(),
        list(&fixed)
    ));
    let t2 = knots(EXAMPLE_2_KNOTS);
    let f2 = BSpline::new(3, t2, points(&EXAMPLE_2_POINTS));
    entries.push(entry(
        "Ejemplo 2: T for 4 de Boor points of degree 3",
        format!("({EXAMPLE_2_KNOTS}), 8 knots"),
        match &f2 {
            Ok(f) => format!(
                "valid; domain [t_4, t_5] = [{}, {}]",
                f.domain().0,
                f.domain().1
            ),
            Err(e) => format!("rejected: {e}"),
        },
        f2.is_ok(),
    ));
    Section::from_entries(
        "Section 1, Ejemplos 1 and 2: knot vectors",
        format!("{SOURCE}, Definition 1.1, Ejemplos 1 and 2"),
        entries,
        findings,
        Status::Explained,
    )
}

fn parallel(u: &[Rational], v: &[Rational]) -> bool {
    let cross = u[0].mul(&v[1]).sub(&u[1].mul(&v[0]));
    let dot = u[0].mul(&v[0]).add(&u[1].mul(&v[1]));
    Ring::is_zero(&cross) && dot > Rational::from_integer(0.into())
}

fn sub(u: &[Rational], v: &[Rational]) -> Vec<Rational> {
    u.iter().zip(v).map(|(x, y)| x.sub(y)).collect()
}

/// Observations 1) and 2) of section 1 on Ejemplo 1 (with the corrected knot vector).
fn observations() -> Section {
    let t: Vec<Rational> = knots(THEOREM_2_2_KNOTS);
    let d = points(&EXAMPLE_1_POINTS);
    let f = BSpline::new(3, t.clone(), d.clone()).expect("valid");
    let pieces = f.bezier_pieces();
    let (first, last) = (&pieces[0], &pieces[pieces.len() - 1]);
    let b0 = first.curve.control_points();
    let bl = last.curve.control_points();
    // F'(a) = p (b_1 - b_0) / (b - a) at the start of a piece, p (b_p - b_{p-1}) / (b - a) at its end.
    let start_tangent = sub(&b0[1], &b0[0]);
    let end_tangent = sub(&bl[3], &bl[2]);
    let f0 = f.eval(&t[0]).expect("in the domain");
    let f6 = f.eval(&t[11]).expect("in the domain");
    let entries = vec![
        entry("F(t_1) = d_1", show(&d[0]), show(&f0), f0 == d[0]),
        entry(
            "first side tangent at t_1",
            format!("d_2 - d_1 = {}", show(&sub(&d[1], &d[0]))),
            format!("F'(0) parallel to {}", show(&start_tangent)),
            parallel(&start_tangent, &sub(&d[1], &d[0])),
        ),
        entry("F(t_{m+1}) = d_m", show(&d[7]), show(&f6), f6 == d[7]),
        entry(
            "last side tangent at t_{m+1}",
            format!("d_8 - d_7 = {}", show(&sub(&d[7], &d[6]))),
            format!("F'(6) parallel to {}", show(&end_tangent)),
            parallel(&end_tangent, &sub(&d[7], &d[6])),
        ),
    ];
    Section::from_entries(
        "Section 1, Observaciones 1) and 2): clamped ends",
        format!("{SOURCE}, section 1, Observación, on Ejemplo 1's de Boor points"),
        entries,
        vec!["checked on Ejemplo 1's de Boor points with the 12-knot vector of section 2 (the printed 13-knot vector is invalid); \
              the tangents come from the Bézier pieces, computed as blossom values".into()],
        Status::Unexplained,
    )
}

/// The application of Theorem 2.2 on T = (0,0,0,0,1,2,4,5,6,6,6,6).
fn theorem_2_2() -> Section {
    let t = knots(THEOREM_2_2_KNOTS);
    let d = points(&EXAMPLE_1_POINTS);
    let p = 3;
    let f = BSpline::new(p, t.clone(), d.clone()).expect("valid");
    let mut entries = Vec::new();
    for (k, j, args) in THEOREM_2_2_POINTS {
        let printed_args = knots(args);
        let window: Vec<Rational> = t[k..k + p].to_vec(); // t_{k+1}..t_{k+p}, 1-based
        let piece = piece_on(&f, j);
        let value = curve_blossom(&piece, &printed_args).expect("p arguments");
        let ok = window == printed_args && value == d[k - 1] && (j - p..=j).contains(&k);
        entries.push(entry(
            format!("d_{k}"),
            format!("f_{j}({args})"),
            format!(
                "f_{j}(t_{}, .., t_{}) = f_{j}({}) = {}",
                k + 1,
                k + p,
                list(&window),
                show(&value)
            ),
            ok,
        ));
    }
    // Theorem 2.2 on the spans the example skips.
    let mut others = true;
    for j in [5usize, 6, 7] {
        let piece = piece_on(&f, j);
        for k in j - p..=j {
            others &= curve_blossom(&piece, &t[k..k + p]).expect("p arguments") == d[k - 1];
        }
    }
    let mut samples = true;
    for pc in f.power_pieces().expect("valid") {
        let [a, b] = &pc.interval;
        for x in [
            a.clone(),
            (a + b) / Rational::from_integer(2.into()),
            b.clone(),
        ] {
            samples &= f.eval(&x).ok() == Some(pc.curve.eval(&x));
        }
    }
    Section::from_entries(
        "Theorem 2.2: the de Boor points of the cubic on T = (0,0,0,0,1,2,4,5,6,6,6,6)",
        format!("{SOURCE}, Teorema 2.2 and its Ejemplo de aplicación"),
        entries,
        vec![
            "the example names no de Boor points; Ejemplo 1's d_1..d_8 serve. The pieces F_4 on [0, 1] and F_8 on [5, 6] are \
             computed by the recursive definition of N_i^3 (Definition 1.1), not by blossoms, and blossomed by the subset-sum \
             definition; each printed argument list is the knot window t_{k+1}..t_{k+3}, and each blossom value is d_k"
                .into(),
            format!("the spans j = 5, 6, 7, which the example skips, give their de Boor points the same way: {others}"),
            format!("de Boor's algorithm equals every power-basis piece at its ends and midpoint: {samples}"),
        ],
        Status::Unexplained,
    )
}

/// The printed steps of F(0,8) (k = 3, p = 2): (label, printed formula, printed value).
const DE_BOOR_KNOTS: &str = "0, 0, 0, 1, 2, 2, 2";
const DE_BOOR_POINTS: [&str; 4] = ["(1, 1)", "(2, 3)", "(4, 3)", "(3, 1)"];
/// (label, i, r, printed weight w_i^r, printed step "0,2 (2, 3) + 0,8 (2, 3)" as its two
/// terms, printed result).
type Step = (
    &'static str,
    usize,
    usize,
    &'static str,
    [(&'static str, &'static str); 2],
    &'static str,
);
const DE_BOOR_STEPS: [Step; 3] = [
    (
        "d_2^1",
        2,
        1,
        "0,8",
        [("0,2", "(2; 3)"), ("0,8", "(2; 3)")],
        "(1.8; 2.6)",
    ),
    (
        "d_3^1",
        3,
        1,
        "0,4",
        [("0,6", "(2; 3)"), ("0,4", "(4; 3)")],
        "(2.8; 3.0)",
    ),
    (
        "d_3^2",
        3,
        2,
        "0,8",
        [("0,2", "(1.8; 2.6)"), ("0,8", "(2.8; 3.0)")],
        "(2.6; 2.92)",
    ),
];

fn de_boor_example() -> Section {
    let t = knots(DE_BOOR_KNOTS);
    let d = points(&DE_BOOR_POINTS);
    let (p, k) = (2usize, 3usize);
    let x = num("0,8");
    let f = BSpline::new(p, t.clone(), d).expect("valid");
    let (span, table) = f.de_boor(&x).expect("in the domain");
    let piece = piece_on(&f, k);
    let mut entries = vec![entry(
        "span k",
        "3 (t_3 = 0 < 0,8 < 1 = t_4)",
        format!("{}", span + 1),
        span + 1 == k,
    )];
    let mut findings = Vec::new();
    for (label, i, r, w, terms, value) in DE_BOOR_STEPS {
        // w_i^r = (t - t_i) / (t_{i+p+1-r} - t_i), 1-based.
        let weight = (&x - &t[i - 1]) / (&t[i + p - r] - &t[i - 1]);
        entries.push(entry(
            format!("w_{}^{r}", i),
            w,
            weight.to_string(),
            weight == num(w),
        ));
        let computed = &table[r][i - (k - p + r)];
        let step: Vec<Rational> = {
            let (a, pa) = (num(terms[0].0), point(terms[0].1));
            let (b, pb) = (num(terms[1].0), point(terms[1].1));
            pa.iter().zip(&pb).map(|(u, v)| &a * u + &b * v).collect()
        };
        entries.push(entry(
            format!("{label} step"),
            format!(
                "{} {} + {} {}",
                terms[0].0, terms[0].1, terms[1].0, terms[1].1
            ),
            format!("= {} against {label} = {}", show(&step), show(computed)),
            step == *computed,
        ));
        if step != *computed {
            findings.push(format!(
                "the step for {label} prints {} for d_{}^{}, but d_{}^{} = {}; with it the step gives {}, the printed result",
                terms[0].1,
                i - 1,
                r - 1,
                i - 1,
                r - 1,
                show(&table[r - 1][i - 1 - (k - p + r - 1)]),
                show(computed)
            ));
        }
        entries.push(entry(
            label,
            value,
            show(computed),
            point(value) == *computed,
        ));
        // Claim (1): d_i^r = f_k(t_{i+1}, .., t_k, x^r, t_{k+1}, .., t_{i+p-r}).
        let mut args: Vec<Rational> = t[i..k].to_vec();
        args.extend(std::iter::repeat_n(x.clone(), r));
        args.extend_from_slice(&t[k..i + p - r]);
        let blossom = curve_blossom(&piece, &args).expect("p arguments");
        entries.push(entry(
            format!("{label} = f_3(...) (claim (1))"),
            format!("f_3({})", list(&args)),
            show(&blossom),
            blossom == *computed,
        ));
    }
    let direct = piece.eval(&x);
    entries.push(entry(
        "F(0,8)",
        "(2.6, 2.92)",
        format!("{} from the power-basis piece", show(&direct)),
        direct == point("(2.6; 2.92)"),
    ));
    findings.push(
        "claim (1) of the proof of Theorem 2.3 is checked against the blossom of the piece on [t_3, t_4] computed from the recursive \
         definition of N_i^2 (Definition 1.1) and the subset-sum blossom, not from de Boor's algorithm"
            .into(),
    );
    Section::from_entries(
        "Theorem 2.3: F(0,8) by de Boor's algorithm",
        format!("{SOURCE}, Teorema 2.3 and its Ejemplo de aplicación"),
        entries,
        findings,
        Status::Explained,
    )
}

/// The Curry-Schoenberg example: printed de Boor points (k, j, args, value).
const CS_POINTS: [(usize, usize, &str, &str); 10] = [
    (1, 4, "0, 0, 0", "(0, 0)"),
    (2, 4, "0, 0, 1", "(1/3, 0)"),
    (3, 4, "0, 1, 1", "(2/3, 1/3)"),
    (4, 4, "1, 1, 1", "(1, 1)"),
    (4, 7, "1, 1, 1", "(1, 1)"),
    (5, 7, "1, 1, 2", "(4/3, 2)"),
    (6, 7, "1, 2, 2", "(5/3, 4)"),
    (7, 7, "2, 2, 3", "(7/3, 12)"),
    (8, 9, "2, 3, 3", "(8/3, 16)"),
    (9, 9, "3, 3, 3", "(3, 20)"),
];
const CS_KNOTS: &str = "0, 0, 0, 0, 1, 1, 1, 2, 2, 3, 3, 3, 3";
/// The printed blossoms f_4, f_7, f_9 (paper's t_1, t_2, t_3 as the arguments).
const CS_BLOSSOMS: [(usize, [&str; 2]); 3] = [
    (4, ["(t1 + t2 + t3)/3", "(t1*t2 + t1*t3 + t2*t3)/3"]),
    (7, ["(t1 + t2 + t3)/3", "t1*t2*t3"]),
    (9, ["(t1 + t2 + t3)/3", "4*(t1 + t2 + t3) - 16"]),
];

fn curry_schoenberg_pieces() -> Vec<Piece<Rational>> {
    // (t, t^2) on [0, 1], (t, t^3) on [1, 2], (t, 12 t - 16) on [2, 3].
    let c = |rows: &[[i64; 2]]| {
        PowerCurve::new(
            rows.iter()
                .map(|[x, y]| vec![Rational::from_int(*x), Rational::from_int(*y)])
                .collect(),
        )
        .expect("valid")
    };
    vec![
        Piece {
            interval: [num("0"), num("1")],
            curve: c(&[[0, 0], [1, 0], [0, 1]]),
        },
        Piece {
            interval: [num("1"), num("2")],
            curve: c(&[[0, 0], [1, 0], [0, 0], [0, 1]]),
        },
        Piece {
            interval: [num("2"), num("3")],
            curve: c(&[[0, -16], [1, 12]]),
        },
    ]
}

fn curry_schoenberg() -> Section {
    let p = 3;
    let pieces = curry_schoenberg_pieces();
    let padded = |i: usize| {
        let mut c = pieces[i].curve.coefficients().to_vec();
        c.resize(p + 1, vec![Rational::from_int(0); 2]);
        PowerCurve::new(c).expect("valid")
    };
    let mut entries = Vec::new();
    let r1 = continuity(&padded(0), &padded(1), &num("1"));
    let r2 = continuity(&padded(1), &padded(2), &num("2"));
    entries.push(entry(
        "continuity at e_2 = 1",
        "C^0 (continua)",
        format!("C^{r1}"),
        r1 == 0,
    ));
    entries.push(entry(
        "continuity at e_3 = 2",
        "C^1 (continuamente diferenciable)",
        format!("C^{r2}"),
        r2 == 1,
    ));
    let f = from_pieces(p, &pieces).expect("the example is a spline");
    entries.push(entry(
        "T",
        format!("({CS_KNOTS})"),
        format!("({})", list(f.knots())),
        f.knots() == knots(CS_KNOTS),
    ));
    for (j, printed) in CS_BLOSSOMS {
        let piece = [4usize, 7, 9]
            .iter()
            .position(|&x| x == j)
            .expect("printed span");
        let args: Vec<Poly> = ["t1", "t2", "t3"].iter().map(|v| Poly::var(v)).collect();
        let sym = PowerCurve::new(
            padded(piece)
                .coefficients()
                .iter()
                .map(|c| c.iter().map(Poly::from_rational).collect())
                .collect(),
        )
        .expect("valid");
        let computed = curve_blossom(&sym, &args).expect("p arguments");
        let want: Vec<Poly> = printed.iter().map(|s| parse(s)).collect();
        entries.push(entry(
            format!("f_{j}(t1, t2, t3)"),
            format!("({}, {})", printed[0], printed[1]),
            format!("({}, {})", computed[0], computed[1]),
            computed == want,
        ));
    }
    let t = f.knots();
    for (k, j, args, value) in CS_POINTS {
        let piece = [4usize, 7, 9]
            .iter()
            .position(|&x| x == j)
            .expect("printed span");
        let printed_args = knots(args);
        let by_blossom = curve_blossom(&padded(piece), &printed_args).expect("p arguments");
        let window = t[k..k + p].to_vec();
        let ok = by_blossom == point(value)
            && window == printed_args
            && f.control_points()[k - 1] == by_blossom;
        entries.push(entry(
            format!("d_{k} from f_{j}"),
            format!("f_{j}({args}) = {value}"),
            format!(
                "f_{j}(t_{}, .., t_{}) = f_{j}({}) = {}",
                k + 1,
                k + p,
                list(&window),
                show(&by_blossom)
            ),
            ok,
        ));
    }
    // The printed range "9 - 2 <= i <= 9" of the last span; Theorem 2.2 gives 9 - 3 <= i <= 9.
    let extra: Vec<String> = (6..=7)
        .map(|k| {
            let v = curve_blossom(&padded(2), &t[k..k + p]).expect("p arguments");
            format!(
                "d_{k} = f_9({}) = {} (from f_7: {})",
                list(&t[k..k + p]),
                show(&v),
                show(&f.control_points()[k - 1])
            )
        })
        .collect();
    let printed_low = 9 - 2;
    entries.push(entry(
        "range of k for j = 9",
        "9 - 2 <= i <= 9",
        format!(
            "9 - {p} <= i <= 9 (Theorem 2.2: k = j - p..j); {}",
            extra.join("; ")
        ),
        printed_low == 9 - p,
    ));
    Section::from_entries(
        "Theorem 2.4 (Curry-Schoenberg): the spline (t, t^2), (t, t^3), (t, 12t - 16) as a cubic B-spline",
        format!("{SOURCE}, Teorema 2.4 and its Ejemplo"),
        entries,
        vec![
            "the knot multiplicities come from the continuity computed exactly at each breakpoint (Taylor coefficients of the \
             two pieces), and the library computes every de Boor point from every span that defines it and checks they agree"
                .into(),
            "the last span [t_9, t_10] = [2, 3] defines d_6..d_9, not only d_7..d_9 as the printed range 9 - 2 <= i <= 9 says; \
             the example then lists only d_8 and d_9; d_6 and d_7 from f_9 equal those from f_7, as Theorem 2.4 requires"
                .into(),
        ],
        Status::Explained,
    )
}

/// Ejemplo 2 computed: the cubic B-spline on T = (0, 1, .., 7) with the printed d_1..d_4 is
/// one polynomial piece on [t_4, t_5] = [3, 4]; its de Boor points as blossom values of that
/// piece (Theorem 2.2), its Bézier points against the uniform-cubic conversion, and its ends
/// against Observación 1 (T is not clamped, so d_1 need not be on the curve).
fn ejemplo_2() -> Section {
    let t = knots(EXAMPLE_2_KNOTS);
    let d = points(&EXAMPLE_2_POINTS);
    let p = 3;
    let f = BSpline::new(p, t.clone(), d.clone()).expect("Ejemplo 2 is a valid B-spline");
    let (lo, hi) = (f.domain().0.clone(), f.domain().1.clone());
    let piece = piece_on(&f, 4);
    let mut entries = vec![entry(
        "domain [t_{p+1}, t_{m+1}]",
        "[t_4, t_5] (Definición 1.1, m = 4, p = 3)",
        format!("[{lo}, {hi}], one non-empty span"),
        [lo.clone(), hi.clone()] == [t[3].clone(), t[4].clone()],
    )];
    for k in 1..=4 {
        let window = &t[k..k + p];
        let value = curve_blossom(&piece, window).expect("p arguments");
        entries.push(entry(
            format!("d_{k} = f_4(t_{}, .., t_{})", k + 1, k + p),
            show(&d[k - 1]),
            format!("f_4({}) = {}", list(window), show(&value)),
            value == d[k - 1],
        ));
    }
    // Uniform cubic B-spline to Bézier on [t_4, t_5]: the textbook one-third rule.
    let third = |x: i64, y: i64, z: i64, w: i64, den: i64| -> Vec<Rational> {
        (0..2)
            .map(|c| {
                (Rational::from_int(x) * &d[0][c]
                    + Rational::from_int(y) * &d[1][c]
                    + Rational::from_int(z) * &d[2][c]
                    + Rational::from_int(w) * &d[3][c])
                    / Rational::from_int(den)
            })
            .collect()
    };
    let rule = [
        ("(d_1 + 4 d_2 + d_3)/6", third(1, 4, 1, 0, 6)),
        ("(2 d_2 + d_3)/3", third(0, 2, 1, 0, 3)),
        ("(d_2 + 2 d_3)/3", third(0, 1, 2, 0, 3)),
        ("(d_2 + 4 d_3 + d_4)/6", third(0, 1, 4, 1, 6)),
    ];
    let bezier = f.bezier_pieces();
    let control = bezier[0].curve.control_points();
    for (i, (formula, want)) in rule.iter().enumerate() {
        entries.push(entry(
            format!("Bézier point b_{i} on [3, 4]"),
            *formula,
            format!(
                "{} (from the blossom values of the B-spline's pieces)",
                show(&control[i])
            ),
            control[i] == *want,
        ));
    }
    let at = |x: &Rational| f.eval(x).expect("in the domain");
    let (start, end) = (at(&lo), at(&hi));
    let clamped = t[..=p].iter().all(|x| *x == t[0]);
    entries.push(entry(
        "Observación 1: d_1 on the curve at t_4",
        "only when t_1 = .. = t_4",
        format!(
            "t_1..t_4 = {} are {}; F(3) = {} (power piece: {}), d_1 = {}",
            list(&t[..=p]),
            if clamped { "equal" } else { "distinct" },
            show(&start),
            show(&piece.eval(&lo)),
            show(&d[0])
        ),
        !clamped && start != d[0] && start == piece.eval(&lo),
    ));
    entries.push(entry(
        "Observación 2: d_4 on the curve at t_5",
        "only when t_5 = .. = t_8",
        format!(
            "F(4) = {} (power piece: {}), d_4 = {}",
            show(&end),
            show(&piece.eval(&hi)),
            show(&d[3])
        ),
        end != d[3] && end == piece.eval(&hi),
    ));
    let coefficients: Vec<String> = piece.coefficients().iter().map(show).collect();
    Section::from_entries(
        "Ejemplo 2: the cubic B-spline on T = (0, 1, .., 7), computed",
        format!("{SOURCE}, section 1, Ejemplo 2 (figura 2)"),
        entries,
        vec![
            format!(
                "F on [3, 4] from the recursive definition of N_i^3 (Definición 1.1), in powers of u: coefficients {}",
                coefficients.join(", ")
            ),
            "the printed d_1..d_4 are the blossom values of that one piece at the knot windows (1, 2, 3), (2, 3, 4), \
             (3, 4, 5), (4, 5, 6), as Theorem 2.2 says; the curve starts at (d_1 + 4 d_2 + d_3)/6 and ends at \
             (d_2 + 4 d_3 + d_4)/6, not at d_1 and d_4, since T is not clamped"
                .into(),
        ],
        Status::Unexplained,
    )
}

/// The sections of seed 002.
pub fn sections() -> Vec<Section> {
    vec![
        knot_vectors(),
        ejemplo_2(),
        observations(),
        theorem_2_2(),
        de_boor_example(),
        curry_schoenberg(),
    ]
}
