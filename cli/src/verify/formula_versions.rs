//! The printed versions of Theorem 3's ingredients where the two transcriptions (000, 001)
//! or the theorem and its proof differ: the count (15), the sum (16), Remark 1's count (21)
//! and the summation bounds under (14). Each version is implemented as printed, through the
//! one evaluator of eq. (14) ([`blossom::engine::restrict_triangle_with_formula`]), and compared with the
//! subset-sum definition (13).

use blossom::engine::{binomial, multinomial};
use blossom::engine::{restrict_triangle_with_formula, TriangleFormula, THEOREM_3};
use blossom::{Poly, PowerSurface, Rational};
use num_bigint::BigInt;

/// One printed version: a name, where it is printed, and the formula it gives.
pub struct Version {
    /// Short name, e.g. `(15) as printed in 000`.
    pub name: &'static str,
    /// What is printed, in words.
    pub printed: &'static str,
    /// The formula of (14) read with this version.
    pub formula: TriangleFormula,
}

/// Every version examined, the proof's final statement (which agrees) first.
pub fn versions() -> Vec<Version> {
    vec![
        Version {
            name: "(15) as printed in 001",
            printed: "|I| = C(nu,i_a) C(mu,i_b) C(N-nu-mu,i_g) C(nu-i_a,j_a) C(mu-i_b,j_b) C(N-nu-mu-i_g,j_g)",
            formula: THEOREM_3,
        },
        Version {
            name: "(15) as printed in 000",
            printed: "|I| = C(nu,i_a) C(mu,i_b) C(N-nu-mu,i_g) C(nu,j_a) C(mu,j_b) C(N-nu-mu,j_g); \
                      000's (16) sums this count over the (correct) denominator N!/(i! j! (N-i-j)!)",
            formula: TriangleFormula {
                count: |s| {
                    binomial(s.nu, s.i_alpha)
                        * binomial(s.mu, s.i_beta)
                        * binomial(s.lambda, s.i_gamma)
                        * binomial(s.nu, s.j_alpha)
                        * binomial(s.mu, s.j_beta)
                        * binomial(s.lambda, s.j_gamma)
                },
                ..THEOREM_3
            },
        },
        Version {
            name: "(16) as printed in 001",
            printed: "count of (15)-001 over the denominator C(N; i_a, i_b, j_a, j_b) = N!/(i_a! i_b! j_a! j_b! (N-i_a-i_b-j_a-j_b)!)",
            formula: TriangleFormula {
                denominator: |s| multinomial(s.big_n, &[s.i_alpha, s.i_beta, s.j_alpha, s.j_beta]),
                ..THEOREM_3
            },
        },
        Version {
            name: "(21) as printed (000 and 001)",
            printed: "|I| = C(nu,j_a) C(mu,j_b) C(N-nu-mu,j_g) C(nu-j_a,i_a) C(mu-j_b,i_b) C(N-nu-mu-j_g,j_g)",
            formula: TriangleFormula {
                count: |s| {
                    binomial(s.nu, s.j_alpha)
                        * binomial(s.mu, s.j_beta)
                        * binomial(s.lambda, s.j_gamma)
                        * binomial(s.nu - s.j_alpha, s.i_alpha)
                        * binomial(s.mu - s.j_beta, s.i_beta)
                        * binomial(s.lambda - s.j_gamma, s.j_gamma)
                },
                ..THEOREM_3
            },
        },
        Version {
            name: "(21) with its last factor C(N-nu-mu-j_g, i_g)",
            printed: "(21) corrected: the last binomial's lower index j_g replaced by i_g",
            formula: TriangleFormula {
                count: |s| {
                    binomial(s.nu, s.j_alpha)
                        * binomial(s.mu, s.j_beta)
                        * binomial(s.lambda, s.j_gamma)
                        * binomial(s.nu - s.j_alpha, s.i_alpha)
                        * binomial(s.mu - s.j_beta, s.i_beta)
                        * binomial(s.lambda - s.j_gamma, s.i_gamma)
                },
                ..THEOREM_3
            },
        },
        Version {
            name: "bounds under (14), theorem statement",
            printed: "lower i_a = max(0, i - mu - lambda) (the proof ends with max(0, i + nu - N))",
            formula: TriangleFormula {
                i_alpha: |s| (0.max(s.i - s.mu - s.lambda), s.i.min(s.nu)),
                ..THEOREM_3
            },
        },
        Version {
            name: "bounds under (14) in 000, every bound read as printed with a bar",
            printed: "000 labels each max(...) bound with a bar (upper) and the sums start at the summation variable itself; read as upper bounds, with sums from 0",
            formula: TriangleFormula {
                i_alpha: |s| (0, 0.max(s.i - s.mu - s.lambda)),
                i_beta: |s| (0, 0.max(s.i - s.i_alpha - s.lambda)),
                j_alpha: |s| (0, 0.max(s.j - (s.mu - s.i_beta) - (s.lambda - s.i_gamma))),
                j_beta: |s| (0, 0.max(s.j - s.j_alpha - (s.lambda - s.i_gamma))),
                ..THEOREM_3
            },
        },
        Version {
            name: "lower bound of j_a in the proof text",
            printed: "j_a >= j - (mu - i_b) - (lambda - i_g), without max(0, .)",
            formula: TriangleFormula {
                j_alpha: |s| (s.j - (s.mu - s.i_beta) - (s.lambda - s.i_gamma), s.j.min(s.nu - s.i_alpha)),
                ..THEOREM_3
            },
        },
    ]
}

/// The outcome of one version against the definition.
pub struct Verdict {
    /// Identical to the definition as polynomials for every (n, m) with n + m <= the bound.
    pub proved_up_to: Option<usize>,
    /// The first disagreement found, in words.
    pub counterexample: Option<String>,
}

fn monomial_surface(n: usize, m: usize, i: usize, j: usize) -> PowerSurface<Rational> {
    let one = <Rational as blossom::Ring>::one();
    let zero = <Rational as blossom::Ring>::zero();
    PowerSurface::new(
        (0..=n)
            .map(|a| {
                (0..=m)
                    .map(|b| {
                        vec![if (a, b) == (i, j) {
                            one.clone()
                        } else {
                            zero.clone()
                        }]
                    })
                    .collect()
            })
            .collect(),
    )
    .expect("a non-empty grid")
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// Compares `formula` with the definition: symbolically for n + m <= `symbolic_max`, and by
/// first searching, for the same degrees, the smallest monomial u^i v^j and control point
/// where they differ on the triangle a = (1, 2), b = (3, -1), c = (-2, 5/2).
pub fn judge(formula: &TriangleFormula, symbolic_max: usize) -> Verdict {
    let tri = [[q(1, 1), q(2, 1)], [q(3, 1), q(-1, 1)], [q(-2, 1), q(5, 2)]];
    for big_n in 1..=symbolic_max {
        for n in 0..=big_n {
            let m = big_n - n;
            for i in 0..=n {
                for j in 0..=m {
                    let s = monomial_surface(n, m, i, j);
                    let want = blossom::restrict_power_surface_to_triangle(
                        &s,
                        &tri,
                        blossom::Method::Definition,
                    );
                    let got = restrict_triangle_with_formula(formula, &s, &tri);
                    for ((nu, mu, la, w), (_, _, _, g)) in want.entries().zip(got.entries()) {
                        if w != g {
                            return Verdict {
                                proved_up_to: None,
                                counterexample: Some(format!(
                                    "S(u, v) = u^{i} v^{j} as a patch of degree (n, m) = ({n}, {m}), \
                                     triangle a = (1, 2), b = (3, -1), c = (-2, 5/2): \
                                     q_{{{nu}{mu}{la}}} is {} by the definition (13), {} by this version",
                                    w[0], g[0]
                                )),
                            };
                        }
                    }
                }
            }
        }
    }
    let tri = crate::proofs::symbolic_triangle();
    for big_n in 0..=symbolic_max {
        for n in 0..=big_n {
            let s = crate::proofs::symbolic_surface(n, big_n - n);
            let want =
                blossom::restrict_power_surface_to_triangle(&s, &tri, blossom::Method::Definition);
            let got: blossom::TriangularPatch<Poly> =
                restrict_triangle_with_formula(formula, &s, &tri);
            if want != got {
                return Verdict {
                    proved_up_to: None,
                    counterexample: Some(format!(
                        "differs from the definition as a polynomial at (n, m) = ({n}, {})",
                        big_n - n
                    )),
                };
            }
        }
    }
    Verdict {
        proved_up_to: Some(symbolic_max),
        counterexample: None,
    }
}

/// The first case, in increasing N, where the proof's lower bound of j_a without max(0, .) is
/// negative, i.e. where a sum taken literally would visit a negative index (harmless only
/// because C(n, k) = 0 for k < 0).
pub fn negative_j_alpha_bound() -> Option<String> {
    for big_n in 1..=6i64 {
        for n in 0..=big_n {
            let m = big_n - n;
            for nu in 0..=big_n {
                for mu in 0..=big_n - nu {
                    let lambda = big_n - nu - mu;
                    for i in 0..=n {
                        for j in 0..=m {
                            for ia in 0.max(i + nu - big_n)..=i.min(nu) {
                                for ib in 0.max(i - ia - lambda)..=(i - ia).min(mu) {
                                    let ig = i - ia - ib;
                                    let lo = j - (mu - ib) - (lambda - ig);
                                    if lo < 0 {
                                        return Some(format!(
                                            "(n, m) = ({n}, {m}), (nu, mu, lambda) = ({nu}, {mu}, {lambda}), \
                                             u^{i} v^{j}, i_a = {ia}, i_b = {ib}: the bound is {lo}"
                                        ));
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    None
}
