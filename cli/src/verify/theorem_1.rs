//! Seed 004, Theorem 1, eq. (18): the multilinear polar form of a homogeneous form
//! ([`blossom::multilinear_polar_form`]), proved as a polynomial identity at small degrees,
//! shown to become eq. (19) under the substitution x_k = (t_k, 1) that the paper describes, and
//! cross-checked against the subset-sum blossom (2), (13), which does not compute through it.

use super::report::{Entry, Section, Status};
use super::seeds_002_004::expr::sample_name;
use blossom::engine::multinomial;
use blossom::{curve_blossom, homogeneous_curve_blossom, homogeneous_triangle_blossom};
use blossom::{multilinear_polar_form, polar_form, triangle_blossom};
use blossom::{Poly, PowerCurve, PowerSurface, Rational, Ring};
use num_bigint::BigInt;

/// Multi-indices alpha of length `d` with |alpha| = n, in lexicographic order.
fn multi_indices(d: usize, n: usize) -> Vec<Vec<usize>> {
    if d == 1 {
        return vec![vec![n]];
    }
    (0..=n)
        .rev()
        .flat_map(|k| {
            multi_indices(d - 1, n - k)
                .into_iter()
                .map(move |mut rest| {
                    rest.insert(0, k);
                    rest
                })
        })
        .collect()
}

fn coefficient_name(alpha: &[usize]) -> String {
    let parts: Vec<String> = alpha.iter().map(|k| k.to_string()).collect();
    format!("A_{}", parts.join("_"))
}

/// The general symmetric n-linear form on R^d, written without (18): f(x_1..x_n) =
/// sum_alpha A_alpha / C(n; alpha) [lambda^alpha] prod_k (lambda . x_k), the coefficient of
/// lambda^alpha in a product of linear forms in helper variables lambda_r (each term of the
/// product picks one coordinate of each argument, so this is the symmetric tensor with entries
/// A_alpha / C(n; alpha)).
fn general_form(n: usize, d: usize, args: &[Vec<Poly>]) -> Poly {
    let lambdas: Vec<String> = (0..d).map(|r| format!("lambda{r}")).collect();
    let mut prod = Poly::one();
    for x in args {
        let lin = (0..d).fold(Poly::zero(), |s, r| {
            s.add(&Poly::var(&lambdas[r]).mul(&x[r]))
        });
        prod = prod.mul(&lin);
    }
    let mut acc = Poly::zero();
    for alpha in multi_indices(d, n) {
        // Extract [lambda^alpha] by substituting and comparing: differentiate-free, through
        // the terms of the product.
        let mut coef = Poly::zero();
        for (mono, c) in prod.terms() {
            let matches = (0..d).all(|r| {
                let e = mono
                    .iter()
                    .find(|(v, _)| *v == lambdas[r])
                    .map_or(0, |(_, e)| *e as usize);
                e == alpha[r]
            });
            if matches {
                let rest: Vec<(&str, u32)> = mono
                    .iter()
                    .filter(|(v, _)| !v.starts_with("lambda"))
                    .map(|(v, e)| (v.as_str(), *e))
                    .collect();
                coef = coef.add(&Poly::monomial(c.clone(), &rest));
            }
        }
        let alpha_i: Vec<i64> = alpha[..d - 1].iter().map(|&k| k as i64).collect();
        let k = Rational::new(BigInt::from(1), multinomial(n as i64, &alpha_i));
        acc = acc.add(&coef.mul(&Poly::var(&coefficient_name(&alpha))).scale(&k));
    }
    acc
}

fn symbolic_points(name: &str, n: usize, d: usize) -> Vec<Vec<Poly>> {
    (1..=n)
        .map(|k| {
            (0..d)
                .map(|r| Poly::var(&format!("{name}{k}_{r}")))
                .collect()
        })
        .collect()
}

/// (18) applied to q(x) = f(x, .., x) gives back f, as polynomials in the coefficients A and
/// the coordinates of the arguments, for n = 1..=`max_n` on R^d.
pub fn polynomial_identity(max_n: usize, d: usize) -> bool {
    (1..=max_n).all(|n| {
        let args = symbolic_points("x", n, d);
        let direct = general_form(n, d, &args);
        let q = |x: &[Poly]| vec![general_form(n, d, &vec![x.to_vec(); n])];
        let by_18 = multilinear_polar_form(n, &args, d, &q).expect("n arguments");
        by_18[0] == direct
    })
}

/// (18) at x_k = (t_k, 1) for the homogenisation Q(t, s) = s^n b(t / s) of an *arbitrary*
/// parametrisation b of degree n (every value b(x) an independent symbol b\[x\]), against (19)
/// with the same symbols: identical combinations of the same samples, for n = 1..=`max_n`.
/// At a sum of N arguments s = N is a non-zero constant, so Q there is N^n b\[t / N\].
pub fn becomes_19(max_n: usize) -> bool {
    (1..=max_n).all(|n| {
        let ts: Vec<Poly> = (1..=n).map(|k| Poly::var(&format!("t{k}"))).collect();
        let homogeneous_args: Vec<Vec<Poly>> =
            ts.iter().map(|t| vec![t.clone(), Poly::one()]).collect();
        let q = |x: &[Poly]| {
            let s = x[1]
                .as_constant()
                .expect("s = N at a sum of N arguments (t, 1)");
            let t = x[0].scale(&(Rational::from_integer(1.into()) / &s));
            vec![Poly::var(&sample_name(&[t])).scale(&Ring::pow(&s, n as u32))]
        };
        let by_18 = multilinear_polar_form(n, &homogeneous_args, 2, &q).expect("n arguments");
        let affine: Vec<Vec<Poly>> = ts.iter().map(|t| vec![t.clone()]).collect();
        let by_19 = polar_form(n, &affine, 1, &|x| {
            vec![Poly::var(&sample_name(&[x[0].clone()]))]
        })
        .expect("n arguments");
        by_18 == by_19
    })
}

fn symbolic_curve(n: usize) -> PowerCurve<Poly> {
    crate::proofs::symbolic_curve(n)
}

/// The blossom through (18) of the homogenised curve at (t_k, 1) against the subset-sum
/// definition (2), symbolically, n = 0..=`max_n`; and at (t_k, s_k) with s_k != 1 against
/// prod s_k b(t_k / s_k) in exact rationals (the homogeneous extension of the blossom).
pub fn curve_cross_check(max_n: usize) -> (bool, bool) {
    let symbolic = (0..=max_n).all(|n| {
        let c = symbolic_curve(n);
        let ts: Vec<Poly> = (1..=n).map(|k| Poly::var(&format!("t{k}"))).collect();
        homogeneous_curve_blossom(&c, &ts).expect("n arguments")
            == curve_blossom(&c, &ts).expect("n arguments")
    });
    let q = |a: i64, b: i64| Rational::new(a.into(), b.into());
    let homogeneous = (1..=max_n).all(|n| {
        let c = PowerCurve::new(
            (0..=n as i64)
                .map(|i| vec![q(2 * i - 3, i + 1), q(i * i - 1, 3)])
                .collect(),
        )
        .expect("a curve");
        let pts: Vec<(Rational, Rational)> = (1..=n as i64)
            .map(|k| (q(3 * k - 5, 2), q(k + 1, 2 * k + 1)))
            .collect();
        let args: Vec<Vec<Rational>> = pts
            .iter()
            .map(|(t, s)| vec![t.clone(), s.clone()])
            .collect();
        let f = multilinear_polar_form(n, &args, 2, &|x| {
            blossom::homogeneous_curve(&c, x.try_into().expect("two coordinates"))
        })
        .expect("n arguments");
        let ratios: Vec<Rational> = pts.iter().map(|(t, s)| t / s).collect();
        let scale: Rational = pts.iter().map(|(_, s)| s.clone()).product();
        let want: Vec<Rational> = curve_blossom(&c, &ratios)
            .expect("n arguments")
            .iter()
            .map(|x| x * &scale)
            .collect();
        f == want
    });
    (symbolic, homogeneous)
}

/// The triangle blossom through (18) of the homogenisation at (u_k, v_k, 1) against the
/// subset-sum definition (13), symbolically, for every (n, m) with n + m <= `max_total`.
pub fn triangle_cross_check(max_total: usize) -> bool {
    (0..=max_total).all(|big_n| {
        (0..=big_n).all(|n| {
            let s: PowerSurface<Poly> = crate::proofs::symbolic_surface(n, big_n - n);
            let args: Vec<[Poly; 2]> = (1..=big_n)
                .map(|k| [Poly::var(&format!("u{k}")), Poly::var(&format!("v{k}"))])
                .collect();
            homogeneous_triangle_blossom(&s, &args).expect("N arguments")
                == triangle_blossom(&s, &args).expect("N arguments")
        })
    })
}

fn entry(label: &str, printed: &str, computed: String, matches: bool) -> Entry {
    Entry {
        label: label.into(),
        printed: printed.into(),
        computed,
        matches,
    }
}

/// The section of Theorem 1.
pub fn section() -> Section {
    let (max_n, max_19, max_curve, max_tri) = (4, 6, 6, 4);
    let id2 = polynomial_identity(max_n, 2);
    let id3 = polynomial_identity(3, 3);
    let to_19 = becomes_19(max_19);
    let (curve_sym, curve_hom) = curve_cross_check(max_curve);
    let tri = triangle_cross_check(max_tri);
    let yes = |b: bool| if b { "identical" } else { "NOT identical" };
    let entries = vec![
        entry(
            "(18) on R^2, n = 1..4",
            "f(x_1..x_n) = 1/n! sum_N (-1)^(n-N) sum_{i_1<..<i_N} q(x_i1 + .. + x_iN)",
            format!("{} to the general symmetric n-linear form (symbolic coefficients and arguments)", yes(id2)),
            id2,
        ),
        entry(
            "(18) on R^3, n = 1..3",
            "the same",
            format!("{} to the general symmetric n-linear form", yes(id3)),
            id3,
        ),
        entry(
            "(18) -> (19), n = 1..6",
            "substitute q(x_1 + .. + x_N) by N^n q((x_1 + .. + x_N)/N)",
            format!(
                "(18) of Q(t, s) = s^n b(t/s) at x_k = (t_k, 1): {} combination of the samples b[.] to (19)",
                yes(to_19)
            ),
            to_19,
        ),
        entry(
            "curve blossom through (18), n = 0..6",
            "b(t_1..t_n) = F((t_1, 1), .., (t_n, 1))",
            format!("{} to the subset-sum blossom (2) as polynomials", yes(curve_sym)),
            curve_sym,
        ),
        entry(
            "homogeneous extension, n = 1..6",
            "F((t_1, s_1), .., (t_n, s_n)) = s_1 .. s_n b(t_1/s_1, .., t_n/s_n)",
            format!("{} at rational (t_k, s_k), s_k != 1", if curve_hom { "equal" } else { "NOT equal" }),
            curve_hom,
        ),
        entry(
            "triangle blossom through (18), N = 0..4",
            "b((u_1, v_1)..(u_N, v_N)) = F((u_1, v_1, 1), ..)",
            format!("{} to the subset-sum blossom (13) as polynomials", yes(tri)),
            tri,
        ),
    ];
    Section::from_entries(
        "Theorem 1, eq. (18): the multilinear polar form of a homogeneous form",
        "inverse relations paper, section 3, Theorem 1, eqs. (14)-(19)",
        entries,
        vec![
            "eq. (18) is implemented once, generically over Ring, as blossom::multilinear_polar_form (2^n - 1 values of q \
             at sums of the arguments), apart from Theorem 2's grouped affine (19) (blossom::polar_form)"
                .into(),
            "the general symmetric n-linear form on R^d is built without (18): A_alpha / C(n; alpha) times the coefficient of \
             lambda^alpha in prod_k (lambda . x_k); q is its diagonal"
                .into(),
            "the substitution of the paper: at x_k = (t_k, 1) a sum of N arguments is N ((t_i1 + .. + t_iN)/N, 1), and \
             homogeneity of degree n turns q there into N^n b((t_i1 + .. + t_iN)/N), term by term (19)"
                .into(),
        ],
        Status::Unexplained,
    )
}
