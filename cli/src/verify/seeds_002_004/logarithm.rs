//! Seed 004, Example 3: the logarithm b(t) = (t, ln t) on [1/2, 1] approximated by a cubic
//! through the inverse formula (22), and its L2 error against the best L2 cubic.
//!
//! Everything is exact: ln of a rational is a combination of the symbols ln2, ln3, ln5, ...
//! (by factoring), the control points are polynomials in those symbols, and the squared L2
//! errors are exact quadratic polynomials in them, from closed-form moments of ln. Only the
//! final decimal value uses approximations of ln p, by series accurate to about 1e-50.

use super::expr::parse;
use super::{entry, sci};
use crate::verify::report::{Section, Status};
use blossom::curve_control_points_from_samples;
use blossom::engine::bernstein_gram;
use blossom::engine::binomial;
use blossom::{elevate, squared_l2_distance};
use blossom::{BezierCurve, Poly, Rational, Ring};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed};

/// The printed control polygon of the cubic (x, y), with `ln2` for ln 2 etc.
pub const POLYGON: [[&str; 2]; 4] = [
    ["1/2", "-ln2"],
    ["2/3", "(65*ln2 - 43*ln3)/6"],
    ["5/6", "(27*ln5 + 4*ln2 - 43*ln3)/6"],
    ["1", "0"],
];
/// The printed squared L2 errors: of the cubic above, and of the best L2 cubic.
pub const ERRORS: [&str; 2] = ["2e-7", "1e-7"];

/// The exponents of the prime factorisation of a positive integer.
fn factor(mut n: BigInt) -> Vec<(BigInt, u32)> {
    let mut out = Vec::new();
    let mut p = BigInt::from(2);
    while &p * &p <= n {
        let mut e = 0;
        while n.is_multiple_of(&p) {
            n /= &p;
            e += 1;
        }
        if e > 0 {
            out.push((p.clone(), e));
        }
        p += 1;
    }
    if n > BigInt::one() {
        out.push((n, 1));
    }
    out
}

/// ln x for a positive rational x, as sum e_p ln p over its prime factorisation (symbols `lnP`).
pub fn ln_symbolic(x: &Rational) -> Poly {
    assert!(x.is_positive(), "ln of a positive number");
    let mut acc = Poly::zero();
    for (sign, n) in [(1i64, x.numer().clone()), (-1, x.denom().clone())] {
        for (p, e) in factor(n) {
            acc = acc.add(
                &Poly::var(&format!("ln{p}"))
                    .scale(&Rational::from_integer(BigInt::from(sign * e as i64))),
            );
        }
    }
    acc
}

/// The parametrisation (t, ln t) on symbolic constants.
fn log_curve(t: &Poly) -> Vec<Poly> {
    let x = t
        .as_constant()
        .expect("the inverse formula samples rational parameters");
    vec![t.clone(), ln_symbolic(&x)]
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// int_1^2 u^j ln u du = 2^(j+1)/(j+1) ln2 - (2^(j+1) - 1)/(j+1)^2.
fn moment_u(j: usize) -> Poly {
    let p = BigInt::from(2).pow(j as u32 + 1);
    let k = BigInt::from(j + 1);
    Poly::var("ln2")
        .scale(&Rational::new(p.clone(), k.clone()))
        .sub(&Poly::constant(Rational::new(p - 1, &k * &k)))
}

/// int_0^1 B_i^n(s) ln(1 + s) ds, through int_0^1 s^k ln(1 + s) ds = sum_j C(k, j) (-1)^(k-j) int_1^2 u^j ln u du.
fn bernstein_log_moment(n: usize, i: usize) -> Poly {
    let s_moment = |k: usize| {
        (0..=k).fold(Poly::zero(), |acc, j| {
            let c = binomial(k as i64, j as i64) * if (k - j).is_multiple_of(2) { 1 } else { -1 };
            acc.add(&moment_u(j).scale(&Rational::from_integer(c)))
        })
    };
    let mut acc = Poly::zero();
    for l in 0..=n - i {
        let c = binomial(n as i64, i as i64)
            * binomial((n - i) as i64, l as i64)
            * if l % 2 == 0 { 1 } else { -1 };
        acc = acc.add(&s_moment(i + l).scale(&Rational::from_integer(c)));
    }
    acc
}

/// The y-part of the squared L2 error int_{1/2}^1 (P(t) - ln t)^2 dt of the cubic with
/// ordinates `y` on [1/2, 1], and the errors of the best L2 cubics (free, and through both
/// end points), all exact. With
/// t = (1 + s)/2: dt = ds/2 and ln t = ln(1 + s) - ln 2 =: L(s).
pub fn l2_errors(n: usize, y: &[Poly]) -> L2Errors {
    let ln2 = Poly::var("ln2");
    let g = bernstein_gram(n, n);
    // nu_i = int B_i^n L ds.
    let nu: Vec<Vec<Poly>> = (0..=n)
        .map(|i| vec![bernstein_log_moment(n, i).sub(&ln2.scale(&q(1, n as i64 + 1)))])
        .collect();
    // int_0^1 L^2 ds = 2 - 2 ln2 - ln2^2.
    let l2 = Poly::from_int(2)
        .sub(&ln2.scale(&q(2, 1)))
        .sub(&ln2.mul(&ln2));
    let quad = |c: &[Poly]| {
        let mut acc = Poly::zero();
        for i in 0..=n {
            for j in 0..=n {
                acc = acc.add(&c[i].mul(&c[j]).scale(&g[i][j]));
            }
        }
        acc
    };
    let dot = |c: &[Poly]| (0..=n).fold(Poly::zero(), |acc, i| acc.add(&c[i].mul(&nu[i][0])));
    let half = q(1, 2);
    let error = quad(y).sub(&dot(y).scale(&q(2, 1))).add(&l2).scale(&half);
    let best: Vec<Poly> = blossom::engine::solve_rational_system(&g, &nu, 1, "gram")
        .expect("the Gram matrix is invertible")
        .into_iter()
        .map(|p| p[0].clone())
        .collect();
    let best_error = l2.sub(&dot(&best)).scale(&half);
    // With both end points kept (y_0 = -ln 2, y_n = ln 1 = 0): the interior normal equations.
    let ends = [ln2.neg(), Poly::zero()];
    let inner: Vec<Vec<Rational>> = (1..n).map(|i| g[i][1..n].to_vec()).collect();
    let rhs: Vec<Vec<Poly>> = (1..n)
        .map(|i| {
            vec![nu[i][0]
                .sub(&ends[0].scale(&g[i][0]))
                .sub(&ends[1].scale(&g[i][n]))]
        })
        .collect();
    let mut kept = vec![ends[0].clone()];
    kept.extend(
        blossom::engine::solve_rational_system(&inner, &rhs, 1, "gram")
            .expect("invertible")
            .into_iter()
            .map(|p| p[0].clone()),
    );
    kept.push(ends[1].clone());
    let kept_error = quad(&kept)
        .sub(&dot(&kept).scale(&q(2, 1)))
        .add(&l2)
        .scale(&half);
    L2Errors {
        error,
        best_error,
        best,
        kept_error,
    }
}

/// The exact squared L2 errors of Example 3.
pub struct L2Errors {
    /// Of the given cubic.
    pub error: Poly,
    /// Of the best L2 cubic.
    pub best_error: Poly,
    /// The ordinates of the best L2 cubic.
    pub best: Vec<Poly>,
    /// Of the best L2 cubic through both end points.
    pub kept_error: Poly,
}

/// atanh(z) = sum z^(2k+1)/(2k+1), `terms` terms.
fn atanh(z: &Rational, terms: usize) -> Rational {
    let z2 = z * z;
    let mut power = z.clone();
    let mut acc = Rational::from_integer(0.into());
    for k in 0..terms {
        acc += &power / Rational::from_integer(BigInt::from(2 * k + 1));
        power *= &z2;
    }
    acc
}

/// Rational approximations of ln 2, ln 3, ln 5 within about 1e-55.
pub fn ln_values() -> [(String, Rational); 3] {
    let two = Rational::from_integer(2.into());
    let ln2 = &two * atanh(&q(1, 3), 60);
    let ln3 = &ln2 + &two * atanh(&q(1, 5), 45);
    let ln5 = &ln2 * &two + &two * atanh(&q(1, 9), 35);
    [
        ("ln2".into(), ln2),
        ("ln3".into(), ln3),
        ("ln5".into(), ln5),
    ]
}

/// The value of an expression in ln2, ln3, ln5.
pub fn value(p: &Poly) -> Rational {
    let vals = ln_values();
    p.eval(|name| vals.iter().find(|(n, _)| n == name).map(|(_, v)| v.clone()))
        .expect("only ln2, ln3, ln5 occur")
}

/// The cubic of Example 3 by the inverse formula (22) on [1/2, 1]: (x, y) control points.
pub fn cubic() -> Vec<Vec<Poly>> {
    curve_control_points_from_samples(
        3,
        &Poly::constant(q(1, 2)),
        &Poly::constant(q(1, 1)),
        &log_curve,
    )
}

fn section() -> Section {
    let pts = cubic();
    let mut entries = Vec::new();
    for (i, (printed, c)) in POLYGON.iter().zip(&pts).enumerate() {
        let ok = c[0] == parse(printed[0]) && c[1] == parse(printed[1]);
        entries.push(entry(
            format!("b~_{i}"),
            format!("({}, {})", printed[0], printed[1]),
            format!("({}, {})", c[0], c[1]),
            ok,
        ));
    }
    // x: the control abscissae are those of the line t on [1/2, 1], so the x-error is zero.
    let xs: Vec<Vec<Rational>> = pts
        .iter()
        .map(|p| vec![p[0].as_constant().expect("rational abscissa")])
        .collect();
    let line = BezierCurve::new(vec![vec![q(1, 2)], vec![q(1, 1)]]).expect("a line");
    let x_error = squared_l2_distance(
        &BezierCurve::new(xs).expect("4 points"),
        &elevate(&line, 3).expect("3 >= 1"),
    )
    .expect("1-d");
    let ys: Vec<Poly> = pts.iter().map(|p| p[1].clone()).collect();
    let L2Errors {
        error,
        best_error,
        best,
        kept_error,
    } = l2_errors(3, &ys);
    let (e, be, ke) = (
        value(&error) + &x_error,
        value(&best_error),
        value(&kept_error),
    );
    entries.push(entry(
        "L2 error of the cubic",
        ERRORS[0],
        format!("{} (exactly {} + {})", sci(&e, 6), x_error, error),
        sci(&e, 1) == ERRORS[0],
    ));
    entries.push(entry(
        "L2 error of the best L2 cubic",
        ERRORS[1],
        format!("{} (exactly {best_error})", sci(&be, 6)),
        sci(&be, 1) == ERRORS[1],
    ));
    let best_pts: Vec<String> = best.iter().map(|p| sci(&value(p), 8)).collect();
    let sqrt = |x: &Rational| blossom::rational_to_f64(x).sqrt();
    Section::from_entries(
        "Example 3: ln t on [1/2, 1] as a cubic, and its L2 error",
        "inverse relations paper, section 4, Example 3",
        entries,
        vec![
            "ln of a rational is written exactly as a combination of ln2, ln3, ln5; the samples of (22) at 1/2, 2/3, 3/4, 5/6, 1 give \
             the printed polygon identically"
                .into(),
            format!(
                "the error is int_(1/2)^1 |b~(t) - b(t)|^2 dt, computed exactly from closed-form moments of ln and evaluated with ln p to \
                 about 50 digits: {} for the cubic of (22), {} for the best L2 cubic, ratio {:.3}; the L2 norms (square roots) are \
                 {:.4e} and {:.4e}",
                sci(&e, 6),
                sci(&be, 6),
                blossom::rational_to_f64(&(&e / &be)),
                sqrt(&e),
                sqrt(&be)
            ),
            format!("the best L2 cubic has ordinates {} (and abscissae those of t)", best_pts.join(", ")),
            format!(
                "what holds instead of the printed 10^-7: the best L2 cubic errs by {} (about 3.5e-8), so the cubic of (22) is {:.2} \
                 times worse, not of the same size; the best L2 cubic through both end points errs by {} (exactly {kept_error})",
                sci(&be, 6),
                blossom::rational_to_f64(&(&e / &be)),
                sci(&ke, 6)
            ),
            format!(
                "a reading under which the printed 10^-7 holds: the best L2 cubic that keeps both end points (as the cubic of (22) \
                 does) errs by {}, close to 10^-7 (though it rounds to 9e-8), while the free best L2 cubic is 3 times smaller",
                sci(&ke, 6)
            ),
            format!("x-coordinate error {x_error}: the cubic reproduces x = t exactly"),
        ],
        Status::Explained,
    )
}

/// The sections of Example 3.
pub fn sections() -> Vec<Section> {
    vec![section()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn logarithms_factor() {
        assert_eq!(ln_symbolic(&q(5, 6)), parse("ln5 - ln2 - ln3"));
        assert_eq!(ln_symbolic(&q(1, 1)), Poly::zero());
        let ln2 = value(&Poly::var("ln2"));
        assert!((blossom::rational_to_f64(&ln2) - std::f64::consts::LN_2).abs() < 1e-16);
    }

    /// Composite Simpson on [1/2, 1] with 2000 panels.
    fn simpson(f: impl Fn(f64) -> f64) -> f64 {
        let k = 2000;
        let h = 0.5 / k as f64;
        let mut acc = f(0.5) + f(1.0);
        for i in 1..k {
            acc += f(0.5 + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        acc * h / 3.0
    }

    fn cubic_at(y: &[f64], t: f64) -> f64 {
        let s = 2.0 * t - 1.0;
        let c = BezierCurve::new(y.iter().map(|v| vec![*v]).collect()).unwrap();
        c.eval(&s)[0]
    }

    #[test]
    fn exact_errors_agree_with_quadrature() {
        let ys: Vec<Poly> = cubic().iter().map(|p| p[1].clone()).collect();
        let errs = l2_errors(3, &ys);
        let yf: Vec<f64> = ys
            .iter()
            .map(|p| blossom::rational_to_f64(&value(p)))
            .collect();
        let by_simpson = simpson(|t| (cubic_at(&yf, t) - t.ln()).powi(2));
        let exact = blossom::rational_to_f64(&value(&errs.error));
        assert!(
            (by_simpson - exact).abs() < 1e-12,
            "{by_simpson} vs {exact}"
        );
        // The best L2 cubic: its error by quadrature, and no perturbation of it does better.
        let best: Vec<f64> = errs
            .best
            .iter()
            .map(|p| blossom::rational_to_f64(&value(p)))
            .collect();
        let best_simpson = simpson(|t| (cubic_at(&best, t) - t.ln()).powi(2));
        let best_exact = blossom::rational_to_f64(&value(&errs.best_error));
        assert!(
            (best_simpson - best_exact).abs() < 1e-12,
            "{best_simpson} vs {best_exact}"
        );
        for i in 0..4 {
            for d in [-1e-4, 1e-4] {
                let mut y = best.clone();
                y[i] += d;
                assert!(simpson(|t| (cubic_at(&y, t) - t.ln()).powi(2)) > best_simpson);
            }
        }
        let kept = blossom::rational_to_f64(&value(&errs.kept_error));
        assert!(best_exact < kept && kept < exact);
    }
}
