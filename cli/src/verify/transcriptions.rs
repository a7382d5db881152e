//! Every formula that the two transcriptions of the subdivision paper (seeds 000 and 001)
//! print differently, beyond the ingredients of Theorem 3 that [`super::formula_versions`]
//! judges: eq. (11) (the factors of (9)), the reduction of b_ij^Delta to curve blossoms under
//! (13), and the upper bound of j_beta in the proof of Theorem 3. Each printed version is
//! implemented as printed and compared, as polynomials, with the subset-sum definitions (2),
//! (8), (13); a version that differs gets the smallest counterexample found.

use super::formula_versions::judge;
use super::report::{Entry, Section, Status};
use blossom::engine::TriangleFormula;
use blossom::engine::{binomial, THEOREM_3};
use blossom::{curve_blossom, restrict_power_surface, triangle_blossom, Method};
use blossom::{Poly, PowerCurve, PowerSurface, Rational, Ring};

const SOURCE: &str = "subdivision paper, proof of Theorem 2, eqs. (10)-(11)";

/// A printed version of eq. (11): the exponent of a in b^k a^(.) as a function of (n, i, k).
pub struct Eleven {
    /// Short name.
    pub name: &'static str,
    /// As printed.
    pub printed: &'static str,
    /// The exponent of a.
    pub a_exponent: fn(i64, i64, i64) -> i64,
}

/// The two printed versions of (11) (its first line; the second line, in v, d and c, is the
/// same in both).
pub const ELEVEN: [Eleven; 2] = [
    Eleven {
        name: "(11) as printed in 000",
        printed: "b_i~(u_1..u_n) = 1/C(n,i) sum_k C(nu,k) C(n-nu,i-k) b^k a^(i-k)",
        a_exponent: |_, i, k| i - k,
    },
    Eleven {
        name: "(11) as printed in 001",
        printed: "b_i~(u_1..u_n) = 1/C(n,i) sum_k C(nu,k) C(n-nu,i-k) b^k a^(n-k)",
        a_exponent: |n, _, k| n - k,
    },
];

/// The weight of u^i in b_i~(b^nu, a^(n-nu)) by (11) with the given exponent of `lo` (= a).
fn weight(
    n: i64,
    nu: i64,
    i: i64,
    lo: &Poly,
    hi: &Poly,
    a_exponent: fn(i64, i64, i64) -> i64,
) -> Poly {
    let mut w = Poly::zero();
    for k in 0.max(i + nu - n)..=i.min(nu) {
        let c = Rational::new(binomial(nu, k) * binomial(n - nu, i - k), binomial(n, i));
        let term = hi.pow(k as u32).mul(&lo.pow(a_exponent(n, i, k) as u32));
        w = w.add(&term.scale(&c));
    }
    w
}

/// Eq. (9) as the proof assembles it, p = sum c_ij b_i~ b_j~ (eq. (10)), with the u-factor
/// read by `eleven` and the v-factor as printed (in both transcriptions).
pub fn tensor_by_9(
    surface: &PowerSurface<Poly>,
    rect: &[Poly; 4],
    eleven: &Eleven,
) -> Vec<Vec<Poly>> {
    let (n, m) = surface.degree();
    let [a, b, c, d] = rect;
    (0..=n)
        .map(|nu| {
            (0..=m)
                .map(|mu| {
                    let mut acc = Poly::zero();
                    for (i, row) in surface.rows().enumerate() {
                        let wu = weight(n as i64, nu as i64, i as i64, a, b, eleven.a_exponent);
                        for (j, cij) in row.iter().enumerate() {
                            let wv = weight(m as i64, mu as i64, j as i64, c, d, |_, j, r| j - r);
                            acc = acc.add(&cij[0].mul(&wu).mul(&wv));
                        }
                    }
                    acc
                })
                .collect()
        })
        .collect()
}

/// The first bidegree (in increasing n + m) and control point where `eleven` differs from the
/// definition (8), or the largest n + m up to which it agrees.
pub fn judge_eleven(eleven: &Eleven, max_total: usize) -> Result<usize, String> {
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    for total in 0..=max_total {
        for n in 0..=total {
            let m = total - n;
            let s = crate::proofs::symbolic_surface(n, m);
            let want = restrict_power_surface(&s, &rect, Method::Definition);
            let got = tensor_by_9(&s, &rect, eleven);
            for (nu, row) in want.to_nested().iter().enumerate() {
                for (mu, w) in row.iter().enumerate() {
                    if w[0] != got[nu][mu] {
                        return Err(format!(
                            "(n, m) = ({n}, {m}): p_{nu}{mu} is {} by the definition (6)-(8), {} by this version",
                            w[0], got[nu][mu]
                        ));
                    }
                }
            }
        }
    }
    Ok(max_total)
}

fn eleven_sections() -> Vec<Section> {
    ELEVEN
        .iter()
        .map(|e| {
            let verdict = judge_eleven(e, 4);
            let (status, finding) = match &verdict {
                Ok(k) => (
                    Status::Reproduced,
                    format!(
                        "with (10) it gives eq. (9): every control point identical to the definition (8) as a polynomial in \
                         all coefficients and a, b, c, d, for every (n, m) with n + m <= {k}"
                    ),
                ),
                Err(cx) => (
                    Status::Explained,
                    format!(
                        "does not agree with the definition; counterexample: {cx}; b_i~ must be homogeneous of degree i in \
                         (a, b) (it is the blossom of u^i), so the exponent of a is i - k"
                    ),
                ),
            };
            Section {
                title: format!("Formula {}", e.name),
                source: SOURCE.into(),
                status,
                entries: vec![],
                findings: vec![format!("printed: {}", e.printed), finding],
            }
        })
        .collect()
}

/// b_i0^Delta((u_1, v_1)..(u_N, v_N)) against the curve blossom b_i~(u_1..u_N) of u^i at
/// degree N (and b_0j^Delta against b_j~(v_1..v_N)), as polynomials, for N <= `max_n`.
pub fn triangle_reduces_to_curves(max_n: usize) -> bool {
    (1..=max_n).all(|big_n| {
        let pts: Vec<[Poly; 2]> = (1..=big_n)
            .map(|k| [Poly::var(&format!("u{k}")), Poly::var(&format!("v{k}"))])
            .collect();
        (0..=big_n).all(|i| {
            let unit =
                |k: usize| -> Vec<Poly> { vec![if k == i { Poly::one() } else { Poly::zero() }] };
            let curve = PowerCurve::new((0..=big_n).map(unit).collect()).expect("a curve");
            // u^i as a surface of bidegree (N, 0) and v^i as one of bidegree (0, N).
            let su = PowerSurface::new((0..=big_n).map(|k| vec![unit(k)]).collect()).expect("grid");
            let sv = PowerSurface::new(vec![(0..=big_n).map(unit).collect()]).expect("grid");
            let us: Vec<Poly> = pts.iter().map(|p| p[0].clone()).collect();
            let vs: Vec<Poly> = pts.iter().map(|p| p[1].clone()).collect();
            triangle_blossom(&su, &pts).expect("N arguments")
                == curve_blossom(&curve, &us).expect("n arguments")
                && triangle_blossom(&sv, &pts).expect("N arguments")
                    == curve_blossom(&curve, &vs).expect("n arguments")
        })
    })
}

fn reduction_section() -> Section {
    let holds = triangle_reduces_to_curves(4);
    let entries = vec![
        Entry {
            label: "000".into(),
            printed: "b_i0^Delta((u_1, v_1)..(u_N, v_N)) = b_i~(u_1..u_N), b_0j^Delta(..) = b_j~(v_1..v_N)".into(),
            computed: format!(
                "{} for N = 1..4, every i, j (symbolic arguments)",
                if holds { "identical to the curve blossoms (2)" } else { "NOT identical" }
            ),
            matches: holds,
        },
        Entry {
            label: "001".into(),
            printed: "b_i0^Delta((u_1, v_1)..(u_N, v_N)) = b_i^Delta(u_1..u_N), b_0j^Delta(..) = b_j^Delta(v_1..v_N)".into(),
            computed: "b_i^Delta is defined nowhere (the triangle blossoms b_ij^Delta take N points, not N numbers); \
                       the identity that holds is 000's, with the curve blossom b_i~"
                .into(),
            matches: false,
        },
    ];
    Section::from_entries(
        "Formula under (13): b_i0^Delta and b_0j^Delta as curve blossoms (000 b_i~, 001 b_i^Delta)",
        "subdivision paper, section 3, after eq. (13)",
        entries,
        vec!["the 000 reading is proved: the triangle blossom of u^i (of v^j) at N points is the degree-N curve blossom \
              of u^i at their u-coordinates (of v^j at their v-coordinates)"
            .into()],
        if holds { Status::Explained } else { Status::Unexplained },
    )
}

fn j_beta_versions() -> [(&'static str, &'static str, TriangleFormula); 2] {
    [
        (
            "000",
            "j_beta <= min(j - j_alpha, mu - i_beta): the upper bound of j_beta",
            THEOREM_3,
        ),
        (
            "001",
            "underline(j_beta) <= min(j - j_alpha, mu - i_beta), read as the sum's lower limit being that min",
            TriangleFormula {
                j_beta: |s| {
                    let hi = (s.j - s.j_alpha).min(s.mu - s.i_beta);
                    (hi, hi)
                },
                ..THEOREM_3
            },
        ),
    ]
}

fn j_beta_section() -> Section {
    let mut entries = Vec::new();
    for (name, printed, formula) in j_beta_versions() {
        let verdict = judge(&formula, 4);
        let computed = match (&verdict.proved_up_to, &verdict.counterexample) {
            (Some(k), _) => {
                format!("eq. (14) with it agrees with the definition (13) for n + m <= {k}")
            }
            (None, Some(cx)) => format!("eq. (14) with it differs from the definition: {cx}"),
            (None, None) => "no verdict".into(),
        };
        entries.push(Entry {
            label: name.into(),
            printed: printed.into(),
            computed,
            matches: verdict.proved_up_to.is_some(),
        });
    }
    let ok = entries[0].matches && !entries[1].matches;
    Section::from_entries(
        "Formula: the upper bound of j_beta in the proof of Theorem 3 (000 j_beta, 001 underline j_beta)",
        "subdivision paper, proof of Theorem 3, after eq. (20)",
        entries,
        vec!["000's statement is the upper bound of Theorem 3's statement; 001 underlines j_beta, which as a bound of \
              the sum gives a single term, and as an inequality about the lower bound leaves the upper one unstated"
            .into()],
        if ok { Status::Explained } else { Status::Unexplained },
    )
}

/// Every transcription difference, with where it is judged.
fn summary_section(judged: &[Section]) -> Section {
    let status_of = |prefix: &str| {
        judged
            .iter()
            .find(|s| s.title.starts_with(prefix))
            .map(|s| s.status)
    };
    type Row<'a> = (&'a str, &'a str, &'a str, Option<Status>, Option<Status>);
    let rows: [Row; 3] = [
        (
            "(11)",
            "000: b^k a^(i-k); 001: b^k a^(n-k)",
            "000 right",
            status_of("Formula (11) as printed in 000"),
            status_of("Formula (11) as printed in 001"),
        ),
        (
            "(15)",
            "000: C(nu,j_a) C(mu,j_b) C(N-nu-mu,j_g); 001: C(nu-i_a,j_a) C(mu-i_b,j_b) C(N-nu-mu-i_g,j_g)",
            "001 right",
            status_of("Formula (15) as printed in 001"),
            status_of("Formula (15) as printed in 000"),
        ),
        (
            "(16) and the formula before (15)",
            "000: denominator C(N; i, j); 001: C(N; i_a, i_b, j_a, j_b)",
            "000's denominator right (with 001's count)",
            status_of("Formula (15) as printed in 001"),
            status_of("Formula (16) as printed in 001"),
        ),
    ];
    let entries = rows
        .iter()
        .map(|(label, printed, claim, right, wrong)| {
            let ok = *right == Some(Status::Reproduced) && *wrong == Some(Status::Explained);
            Entry {
                label: label.to_string(),
                printed: printed.to_string(),
                computed: format!(
                    "{claim}: the right version {}, the other refuted: {}",
                    if *right == Some(Status::Reproduced) {
                        "proved"
                    } else {
                        "NOT proved"
                    },
                    *wrong == Some(Status::Explained)
                ),
                matches: ok,
            }
        })
        .collect();
    Section::from_entries(
        "Transcriptions 000 and 001: the formulas they print differently",
        "the subdivision paper's two transcriptions, compared line by line",
        entries,
        vec![
            "judged in their own sections: (11), (15), (16) (and the unnumbered formula before (15), whose 001 \
             denominator is (16)'s), the bounds under (14) (000 marks every bound with a bar), the reduction under (13), \
             the bound of j_beta in the proof of Theorem 3"
                .into(),
            "printed differently without a formula at stake: 001 states problem (3) with n, m in R^3 and c_ij in N \
             (000: n, m in N, c_ij in R^3); 000 writes the index nu as v in Theorems 1-2 and 001 in Theorem 3; b~ is \
             typeset b^~ (000) and b\\tilde\\sim (001)"
                .into(),
        ],
        Status::Unexplained,
    )
}

/// The sections, the summary last.
pub fn sections(earlier: &[Section]) -> Vec<Section> {
    let mut out = eleven_sections();
    out.push(reduction_section());
    out.push(j_beta_section());
    let mut all: Vec<Section> = earlier.to_vec();
    all.extend(out.iter().cloned());
    out.push(summary_section(&all));
    out
}
