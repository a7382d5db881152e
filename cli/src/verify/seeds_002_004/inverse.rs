//! Seed 004, sections 2-4: the Bernstein polynomials as printed, the printed instances of the
//! inverse formula (Corollary 1, eq. (20), n = 2, 3; Corollary 2, eq. (22), n = 2, 3, 4), and
//! the printed summations (22) and (23) against Theorem 2, eq. (19).
//!
//! Every point b(x) of the parametrisation is a symbol of its own (see [`sample_name`]), so an
//! identity between combinations of samples holds for every parametrisation of the degree, and
//! the arguments (t_1, .., alpha, beta, the triangle's corners) are symbols too.

use super::entry;
use super::expr::{parse, sample_name};
use crate::verify::report::{Section, Status};
use blossom::bezier_curve_blossom;
use blossom::engine::binomial;
use blossom::{
    curve_blossom_from_samples as curve_blossom,
    curve_control_points_from_samples as curve_control_points,
    triangle_control_points_from_samples as triangle_control_points,
};
use blossom::{Poly, Rational, Ring};
use num_bigint::BigInt;
use std::cell::Cell;

const SOURCE: &str = "inverse relations paper";

/// The symbolic parametrisation of a curve: b(x) is the symbol `b[x]`.
fn symbolic_curve(x: &Poly) -> Vec<Poly> {
    vec![Poly::var(&sample_name(std::slice::from_ref(x)))]
}

fn symbolic_surface(u: &Poly, v: &Poly) -> Vec<Poly> {
    vec![Poly::var(&sample_name(&[u.clone(), v.clone()]))]
}

/// Corollary 1, eq. (20), as printed for n = 2 and 3.
const COROLLARY_1: [(usize, &str); 2] = [
    (2, "1/2*(4*b((t1 + t2)/2) - b(t1) - b(t2))"),
    (
        3,
        "1/6*(27*b((t1 + t2 + t3)/3) + b(t1) + b(t2) + b(t3) - 8*(b((t1 + t2)/2) + b((t2 + t3)/2) + b((t1 + t3)/2)))",
    ),
];

/// Corollary 2, eq. (22), as printed for n = 2, 3, 4 (b_0, .., b_n).
const COROLLARY_2: [(usize, &[&str]); 3] = [
    (2, &["b(alpha)", "-b(alpha)/2 - b(beta)/2 + 2*b((alpha + beta)/2)", "b(beta)"]),
    (
        3,
        &[
            "b(alpha)",
            "-b(alpha) + b(beta)/6 - 8/3*b((alpha + beta)/2) + 9/2*b((2*alpha + beta)/3)",
            "b(alpha)/6 - b(beta) - 8/3*b((alpha + beta)/2) + 9/2*b((alpha + 2*beta)/3)",
            "b(beta)",
        ],
    ),
    (
        4,
        &[
            "b(alpha)",
            "-3/2*b(alpha) - b(beta)/24 + 2*b((alpha + beta)/2) - 81/8*b((2*alpha + beta)/3) + 32/3*b((3*alpha + beta)/4)",
            "7*(b(alpha) + b(beta))/12 + 40/3*b((alpha + beta)/2) - 27/4*(b((2*alpha + beta)/3) + b((alpha + 2*beta)/3))",
            "-b(alpha)/24 - 3/2*b(beta) + 2*b((alpha + beta)/2) - 81/8*b((alpha + 2*beta)/3) + 32/3*b((alpha + 3*beta)/4)",
            "b(beta)",
        ],
    ),
];

fn vars(names: &[&str]) -> Vec<Poly> {
    names.iter().map(|n| Poly::var(n)).collect()
}

fn corollary_1() -> Section {
    let mut entries = Vec::new();
    for (n, printed) in COROLLARY_1 {
        let names: Vec<String> = (1..=n).map(|k| format!("t{k}")).collect();
        let args = vars(&names.iter().map(String::as_str).collect::<Vec<_>>());
        let computed = curve_blossom(n, &args, &symbolic_curve).expect("n arguments");
        entries.push(entry(
            format!("n = {n}: b[t1..t{n}]"),
            printed,
            computed[0].to_string(),
            computed[0] == parse(printed),
        ));
    }
    // "evaluating the parametrisation 2^n - 1 times" for distinct arguments.
    let mut counts = true;
    let mut shown = Vec::new();
    for n in 1..=8usize {
        let calls = Cell::new(0usize);
        let b = |t: &Rational| {
            calls.set(calls.get() + 1);
            vec![t.clone()]
        };
        let args: Vec<Rational> = (1..=n as i64).map(Rational::from_int).collect();
        curve_blossom(n, &args, &b).expect("n arguments");
        counts &= calls.get() == (1 << n) - 1;
        shown.push(format!("{n}: {}", calls.get()));
    }
    entries.push(entry(
        "evaluations for n distinct arguments",
        "2^n - 1",
        shown.join(", "),
        counts,
    ));
    Section::from_entries(
        "Corollary 1, eq. (20): the blossom from points of the curve, n = 2, 3",
        format!("{SOURCE}, section 3, Corollary 1"),
        entries,
        vec!["each b(x) is an independent symbol and t1, t2, t3 are symbols: the identities hold for every curve of the degree".into()],
        Status::Unexplained,
    )
}

fn corollary_2() -> Section {
    let mut entries = Vec::new();
    let ab = vars(&["alpha", "beta"]);
    for (n, printed) in COROLLARY_2 {
        let computed = curve_control_points(n, &ab[0], &ab[1], &symbolic_curve);
        for (i, (p, c)) in printed.iter().zip(&computed).enumerate() {
            entries.push(entry(
                format!("n = {n}: b_{i}"),
                *p,
                c[0].to_string(),
                c[0] == parse(p),
            ));
        }
    }
    Section::from_entries(
        "Corollary 2, eq. (22): control points on [alpha, beta], n = 2, 3, 4",
        format!("{SOURCE}, section 4, Corollary 2"),
        entries,
        vec!["computed by Theorem 2, eq. (19), with symbolic alpha, beta and samples".into()],
        Status::Unexplained,
    )
}

fn rat(n: BigInt, d: BigInt) -> Rational {
    Rational::new(n, d)
}

fn factorial(n: usize) -> BigInt {
    (1..=n).map(BigInt::from).product()
}

/// Eq. (22) as printed: b_i = 1/n! sum_N (-1)^(n-N) N^n sum_I C(i, I) C(n-i, N-I) b(((N-I) alpha + I beta) / N).
fn printed_22(n: usize, i: usize, alpha: &Poly, beta: &Poly) -> Poly {
    let mut acc = Poly::zero();
    for big_n in 1..=n {
        let sign: i64 = if (n - big_n).is_multiple_of(2) { 1 } else { -1 };
        for big_i in 0..=i {
            let c = binomial(i as i64, big_i as i64)
                * binomial((n - i) as i64, big_n as i64 - big_i as i64);
            if c == BigInt::from(0) {
                continue;
            }
            let x = alpha
                .scale(&rat(BigInt::from(big_n - big_i), BigInt::from(big_n)))
                .add(&beta.scale(&rat(BigInt::from(big_i), BigInt::from(big_n))));
            let k = rat(
                BigInt::from(sign) * BigInt::from(big_n).pow(n as u32) * c,
                factorial(n),
            );
            acc = acc.add(&symbolic_curve(&x)[0].scale(&k));
        }
    }
    acc
}

/// Eq. (23) as printed: b_ijk = 1/n! sum_N (-1)^(n-N) N^n sum_J sum_K C(j, J) C(k, K) C(i, N-J-K)
/// b(((N-J-K) a + J b + K c) / N).
fn printed_23(n: usize, (i, j, k): (usize, usize, usize), corners: &[[Poly; 2]; 3]) -> Poly {
    let mut acc = Poly::zero();
    for big_n in 1..=n {
        let sign: i64 = if (n - big_n).is_multiple_of(2) { 1 } else { -1 };
        for big_j in 0..=j {
            for big_k in 0..=k {
                let rest = big_n as i64 - big_j as i64 - big_k as i64;
                let c = binomial(j as i64, big_j as i64)
                    * binomial(k as i64, big_k as i64)
                    * binomial(i as i64, rest);
                if c == BigInt::from(0) {
                    continue;
                }
                let w = [rest, big_j as i64, big_k as i64]
                    .map(|x| rat(BigInt::from(x), BigInt::from(big_n)));
                let coord =
                    |d: usize| (0..3).fold(Poly::zero(), |s, r| s.add(&corners[r][d].scale(&w[r])));
                let k_ = rat(
                    BigInt::from(sign) * BigInt::from(big_n).pow(n as u32) * c,
                    factorial(n),
                );
                acc = acc.add(&symbolic_surface(&coord(0), &coord(1))[0].scale(&k_));
            }
        }
    }
    acc
}

fn printed_summations() -> Section {
    let ab = vars(&["alpha", "beta"]);
    let mut curve_ok = true;
    for n in 1..=6 {
        let computed = curve_control_points(n, &ab[0], &ab[1], &symbolic_curve);
        for (i, c) in computed.iter().enumerate() {
            curve_ok &= c[0] == printed_22(n, i, &ab[0], &ab[1]);
        }
    }
    let corners: [[Poly; 2]; 3] =
        [["a1", "a2"], ["b1", "b2"], ["c1", "c2"]].map(|[x, y]| [Poly::var(x), Poly::var(y)]);
    let mut triangle_ok = true;
    for n in 1..=4 {
        let computed = triangle_control_points(n, &corners, &symbolic_surface);
        let mut idx = 0;
        for i in 0..=n {
            for j in 0..=n - i {
                triangle_ok &= computed[idx][0] == printed_23(n, (i, j, n - i - j), &corners);
                idx += 1;
            }
        }
    }
    let entries = vec![
        entry(
            "eq. (22) for n = 1..6, every i",
            "1/n! sum_N (-1)^(n-N) N^n sum_I C(i,I) C(n-i,N-I) b(((N-I) alpha + I beta)/N)",
            format!("equal to Theorem 2, eq. (19), at alpha^(n-i) beta^i: {curve_ok}"),
            curve_ok,
        ),
        entry(
            "eq. (23) for n = 1..4, every i + j + k = n",
            "1/n! sum_N (-1)^(n-N) N^n sum_J sum_K C(j,J) C(k,K) C(i,N-J-K) b(((N-J-K) a + J b + K c)/N)",
            format!("equal to eq. (19) at a^i b^j c^k with symbolic corners: {triangle_ok}"),
            triangle_ok,
        ),
        entry(
            "index range in Corollary 3",
            "1 <= i, j, k <= n",
            "0 <= i, j, k <= n (the corners b_n00, b_0n0, b_00n have two zero indices)",
            false,
        ),
    ];
    Section::from_entries(
        "Corollaries 2 and 3, eqs. (22) and (23), as printed, against Theorem 2",
        format!("{SOURCE}, section 4, Corollaries 2 and 3"),
        entries,
        vec![
            "both printed summations are the subset sum (19) grouped by how many copies of each repeated argument a subset takes"
                .into(),
            "Corollary 3 prints 1 <= i, j, k <= n for the vertices; the formula is right for 0 <= i, j, k <= n, which the check \
             covers; it also writes b(u, w, w) for b(u, v, w)"
                .into(),
        ],
        Status::Explained,
    )
}

/// Section 2: B_i^n(t) as printed, against the de Casteljau algorithm (1).
fn bernstein() -> Section {
    let n = 3usize;
    let t = Poly::var("t");
    let b: Vec<Vec<Poly>> = (0..=n).map(|i| vec![Poly::var(&format!("b{i}"))]).collect();
    let de_casteljau =
        bezier_curve_blossom(&b, &vec![t.clone(); n]).expect("n arguments")[0].clone();
    let one_minus_t = Poly::one().sub(&t);
    let sum = |first: &Poly, second: &Poly| {
        (0..=n).fold(Poly::zero(), |acc, i| {
            let c = Rational::from_integer(binomial(n as i64, i as i64));
            acc.add(
                &b[i][0]
                    .mul(&first.pow(i as u32))
                    .mul(&second.pow((n - i) as u32))
                    .scale(&c),
            )
        })
    };
    let printed = sum(&one_minus_t, &t);
    let swapped = sum(&t, &one_minus_t);
    let entries = vec![
        entry(
            "b(t) = sum b_i B_i^3(t)",
            "B_i^n(t) = n!/(i!(n-i)!) (1-t)^i t^(n-i)",
            format!("de Casteljau (1) gives {de_casteljau}"),
            printed == de_casteljau,
        ),
        entry(
            "with the exponents exchanged",
            "B_i^n(t) = n!/(i!(n-i)!) t^i (1-t)^(n-i)",
            format!("equal to de Casteljau (1): {}", swapped == de_casteljau),
            swapped == de_casteljau,
        ),
    ];
    Section::from_entries(
        "Section 2: the Bernstein polynomials",
        format!("{SOURCE}, section 2"),
        entries,
        vec![
            "as printed, B_i^n puts b_0 at t = 1, against de Casteljau's algorithm (1) and b_0 = b[0, .., 0]; the exponents are \
             exchanged, and B_i^n(t) = C(n, i) t^i (1 - t)^(n - i) holds (proved for n = 3 with symbolic b_i and t)"
                .into(),
        ],
        Status::Explained,
    )
}

/// The sections of seed 004 on the inverse formula.
pub fn sections() -> Vec<Section> {
    vec![
        bernstein(),
        corollary_1(),
        corollary_2(),
        printed_summations(),
    ]
}
