//! Theorem 3, eq. (14), unrolled for one pair of degrees `(n, m)`, N = n + m:
//!
//! q_{nu mu} = sum_{i<=n, j<=m} c_ij / (N! / (i! j! (N-i-j)!)) sum_{i_a, i_b, j_a, j_b}
//! C(nu, i_a) C(mu, i_b) C(lambda, i_g) C(nu-i_a, j_a) C(mu-i_b, j_b) C(lambda-i_g, j_g)
//! a1^i_a b1^i_b c1^i_g a2^j_a b2^j_b c2^j_g,
//!
//! with lambda = N - nu - mu, i_g = i - i_a - i_b, j_g = j - j_a - j_b, over the bounds stated at
//! the end of the proof of Theorem 3. Those bounds are exactly the splits for which every one of
//! the six binomials is non-zero (i_a <= nu, i_b <= mu, i_g <= lambda, j_a <= nu - i_a, ...), so
//! the expansion enumerates the compositions i = i_a + i_b + i_g, j = j_a + j_b + j_g and emits
//! the non-zero ones.
//!
//! As (10)-(11) do for (9), the sum is regrouped by distributivity. Once (i, i_a, i_b) is fixed,
//! the sum over j, j_a, j_b depends only on the triple (nu', mu', lambda') = (nu - i_a, mu - i_b,
//! lambda - i_g), whose entries add up to N - i:
//!
//! q_{nu mu} = sum_{i<=n} sum_{i_a+i_b+i_g=i} C(nu, i_a) C(mu, i_b) C(lambda, i_g)
//! a1^i_a b1^i_b c1^i_g r_{nu-i_a, mu-i_b, lambda-i_g},
//!
//! r_{nu' mu' lambda'} = sum_{j<=m} c_ij / (N! / (i! j! (N-i-j)!)) sum_{j_a+j_b+j_g=j}
//! C(nu', j_a) C(mu', j_b) C(lambda', j_g) a2^j_a b2^j_b c2^j_g, where i = N - nu' - mu' - lambda'.
//!
//! Each point `rNU_MU_LA` is bound once and shared by every control point that needs it. This
//! gives O(N^5) scalar terms instead of the O(N^6) of the sextuple sum taken point by point.

use super::{
    array_type, coef, combination, fn_attrs, ident, reading, Monomials, Operand, Term, Weight,
};
use crate::constants::{binomial, trinomial, Frac};
use crate::model::Spec;
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::{BTreeSet, HashMap};

/// Parameter order of the monomials a1^i_a b1^i_b c1^i_g (u part) and a2^j_a b2^j_b c2^j_g (v part).
const NAMES: [&str; 6] = ["a1", "b1", "c1", "a2", "b2", "c2"];

/// The compositions (x, y, z) of `total` with x <= cap.0, y <= cap.1, z <= cap.2 (the splits
/// whose three binomials C(cap.0, x) C(cap.1, y) C(cap.2, z) are non-zero).
fn splits(total: usize, cap: (usize, usize, usize)) -> Vec<(usize, usize, usize)> {
    let mut out = Vec::new();
    for x in 0..=total.min(cap.0) {
        for y in 0..=(total - x).min(cap.1) {
            let z = total - x - y;
            if z <= cap.2 {
                out.push((x, y, z));
            }
        }
    }
    out
}

/// C(cap.0, x) C(cap.1, y) C(cap.2, z); `None` on overflow.
fn three_binomials(cap: (usize, usize, usize), split: (usize, usize, usize)) -> Option<u128> {
    let c = |n: usize, k: usize| binomial(n as u64, k as u64);
    c(cap.0, split.0)?
        .checked_mul(c(cap.1, split.1)?)?
        .checked_mul(c(cap.2, split.2)?)
}

/// `x^e` for the readings in comments.
fn power(x: &str, e: usize) -> Option<String> {
    match e {
        0 => None,
        1 => Some(x.to_string()),
        e => Some(format!("{x}^{e}")),
    }
}

/// The weight of c_ij in r_{nu' mu' lambda'} (the v part of (14), with its denominator), and its
/// unreduced reading; `None` on overflow.
fn v_weight(
    big_n: usize,
    i: usize,
    j: usize,
    tri: (usize, usize, usize),
) -> Option<(Weight, String)> {
    let den = trinomial(big_n as u64, i as u64, j as u64)?;
    let mut terms = Vec::new();
    let mut reading = Vec::new();
    for (ja, jb, jg) in splits(j, tri) {
        let count = three_binomials(tri, (ja, jb, jg))?;
        terms.push(Term {
            k: Frac::new(count, den)?,
            exps: vec![0, 0, 0, ja as u32, jb as u32, jg as u32],
        });
        let mono: Vec<String> = [("a2", ja), ("b2", jb), ("c2", jg)]
            .into_iter()
            .filter_map(|(v, e)| power(v, e))
            .collect();
        reading.push(format!(
            "C({},{ja}) C({},{jb}) C({},{jg}){}",
            tri.0,
            tri.1,
            tri.2,
            if mono.is_empty() {
                String::new()
            } else {
                format!(" {}", mono.join(" "))
            }
        ));
    }
    let reading = format!(
        "({}) / ({big_n}!/({i}! {j}! {}!))",
        reading.join(" + "),
        big_n - i - j
    );
    Some((Weight { terms }, reading))
}

/// Weights bound once per distinct value: equal weights (the constant 1 / C(N, i) of every
/// r with the same i, the same integer times the same monomial in several q) share one binding.
#[derive(Default)]
struct SharedWeights {
    bound: HashMap<Vec<(i128, i128, Vec<u32>)>, Operand>,
}

impl SharedWeights {
    /// The operand of `w`, bound as `name` (with the comment `name = text`) on first use.
    fn bind(
        &mut self,
        w: &Weight,
        name: &str,
        text: &str,
        monomials: &mut Monomials,
        stmts: &mut Vec<TokenStream>,
    ) -> Operand {
        let key: Vec<_> = w
            .terms
            .iter()
            .map(|t| (t.k.num, t.k.den, t.exps.clone()))
            .collect();
        if let Some(op) = self.bound.get(&key) {
            return op.clone();
        }
        let op = w.bind(name, &format!("{name} = {text}"), monomials, stmts);
        self.bound.insert(key, op.clone());
        op
    }
}

/// Which coefficients c_ij the input holds, and how they are passed.
enum Support {
    /// A grid i <= n, j <= m at total degree N = n + m (the paper's convention), `coef[i][j]`.
    Grid(usize, usize),
    /// A triangular array i + j <= N, `coef[k]` with k the position of (i, j) in lexicographic
    /// order (row i holds c_i0 .. c_i(N-i)).
    Total(usize),
}

impl Support {
    fn big_n(&self) -> usize {
        match *self {
            Support::Grid(n, m) => n + m,
            Support::Total(big_n) => big_n,
        }
    }

    /// The highest i of a coefficient.
    fn i_max(&self) -> usize {
        match *self {
            Support::Grid(n, _) => n,
            Support::Total(big_n) => big_n,
        }
    }

    /// The highest j of a coefficient in row i.
    fn j_max(&self, i: usize) -> usize {
        match *self {
            Support::Grid(_, m) => m,
            Support::Total(big_n) => big_n - i,
        }
    }

    /// The input expression of c_ij.
    fn input(&self, i: usize, j: usize) -> TokenStream {
        match *self {
            Support::Grid(..) => coef(&[i, j]),
            Support::Total(big_n) => {
                // Rows 0..i hold (N + 1) + N + ... + (N + 2 - i) entries.
                let before: usize = (0..i).map(|r| big_n + 1 - r).sum();
                coef(&[before + j])
            }
        }
    }
}

/// The generated function for a triangular patch from power coefficients c_ij with i <= n,
/// j <= m, N = n + m.
pub fn expand(spec: &Spec, n: usize, m: usize) -> Option<TokenStream> {
    expand_support(spec, Support::Grid(n, m))
}

/// The generated function for a triangular patch of total degree N from its triangular array
/// of power coefficients c_ij, i + j <= N: eq. (14) holds term by term for any such array.
pub fn expand_total(spec: &Spec, big_n: usize) -> Option<TokenStream> {
    expand_support(spec, Support::Total(big_n))
}

fn expand_support(spec: &Spec, support: Support) -> Option<TokenStream> {
    let big_n = support.big_n();
    let n = support.i_max();
    let j_max = |i: usize| support.j_max(i);
    let input_point = |i: usize, j: usize| (support.input(i, j), format!("c_{i}{j}"));
    // The triples (nu', mu', lambda') of the shared points r, by i = N - nu' - mu' - lambda',
    // in lexicographic order of (nu', mu'); with the (j, weight) of each.
    let mut r_table = Vec::new();
    for i in 0..=n {
        let total = big_n - i;
        for nu in 0..=total {
            for mu in 0..=total - nu {
                let tri = (nu, mu, total - nu - mu);
                let ws = (0..=j_max(i))
                    .map(|j| v_weight(big_n, i, j, tri).map(|w| (j, w)))
                    .collect::<Option<Vec<_>>>()?;
                r_table.push((i, tri, ws));
            }
        }
    }
    // The control points: (nu, mu, lambda) in lexicographic order, with their u-part terms
    // (constant, monomial a1^i_a b1^i_b c1^i_g, the triple of r).
    let mut q_table = Vec::new();
    for nu in 0..=big_n {
        for mu in 0..=big_n - nu {
            let la = big_n - nu - mu;
            let mut terms = Vec::new();
            for i in 0..=n {
                for (ia, ib, ig) in splits(i, (nu, mu, la)) {
                    let count = three_binomials((nu, mu, la), (ia, ib, ig))?;
                    let exps = vec![ia as u32, ib as u32, ig as u32, 0, 0, 0];
                    terms.push((count, exps, (nu - ia, mu - ib, la - ig)));
                }
            }
            q_table.push(((nu, mu, la), terms));
        }
    }

    let mut monomials = Monomials::new(&NAMES);
    let all: BTreeSet<Vec<u32>> = r_table
        .iter()
        .flat_map(|(_, _, ws)| ws.iter())
        .flat_map(|(_, (w, _))| w.terms.iter().map(|t| t.exps.clone()))
        .chain(
            q_table
                .iter()
                .flat_map(|(_, ts)| ts.iter().map(|t| t.1.clone())),
        )
        .collect();
    monomials.bind_all(&all);

    // The shared points r of the v part.
    let mut shared = SharedWeights::default();
    let mut weight_stmts = Vec::new();
    let mut r_stmts = Vec::new();
    for (i, (nu, mu, la), ws) in &r_table {
        let mut items: Vec<(TokenStream, Operand)> = Vec::new();
        let mut terms: Vec<(Operand, String)> = Vec::new();
        for (j, (w, text)) in ws {
            let name = format!("w{nu}_{mu}_{la}_c{i}_{j}");
            let op = shared.bind(w, &name, text, &mut monomials, &mut weight_stmts);
            let (point, point_name) = input_point(*i, *j);
            items.push((point, op.clone()));
            terms.push((op, point_name));
        }
        let id = ident(format!("r{nu}_{mu}_{la}"));
        let doc = format!(
            " r_({nu} {mu} {la}) = {} (i = {i}: the v part of (14), shared)",
            reading(&terms)
        );
        let sum = combination(&items);
        r_stmts.push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
    }

    // The u-part weights: an integer times a monomial.
    let mut point_stmts = Vec::new();
    let mut points = Vec::new();
    for ((nu, mu, la), ts) in &q_table {
        let mut items: Vec<(TokenStream, Operand)> = Vec::new();
        let mut terms: Vec<(Operand, String)> = Vec::new();
        for (count, exps, (rn, rm, rl)) in ts {
            let w = Weight {
                terms: vec![Term {
                    k: Frac::new(*count, 1)?,
                    exps: exps.clone(),
                }],
            };
            let name = format!("{}_times{count}", monomials.ident_name(exps));
            let text = format!("{count} {}", monomials.display(exps));
            let op = shared.bind(&w, &name, &text, &mut monomials, &mut weight_stmts);
            let r = ident(format!("r{rn}_{rm}_{rl}"));
            items.push((quote!(#r), op.clone()));
            terms.push((op, format!("r{rn}_{rm}_{rl}")));
        }
        let sum = combination(&items);
        let id = ident(format!("q{nu}_{mu}_{la}"));
        let doc = format!(
            " q_({nu} {mu} {la}) = blossom(a^{nu}, b^{mu}, c^{la}) = {}",
            reading(&terms)
        );
        point_stmts.push(quote!(#[doc = #doc] let #id: [T; D] = #sum;));
        points.push(id);
    }

    let p = monomials.pattern_names();
    let mono_stmts = monomials.statements();
    let mono_doc = " Powers and products a1^i_a b1^i_b c1^i_g and a2^j_a b2^j_b c2^j_g of the \
                    corners' coordinates, each computed once.";
    let mono_doc = (!mono_stmts.is_empty()).then(|| quote!(#[doc = #mono_doc]));
    let out_ty = array_type(&[(big_n + 1) * (big_n + 2) / 2]);
    let (pa1, pb1, pc1, pa2, pb2, pc2) = (&p[0], &p[1], &p[2], &p[3], &p[4], &p[5]);
    let (in_ty, surface, input_doc) = match support {
        Support::Grid(n, m) => (
            array_type(&[n + 1, m + 1]),
            format!("sum_{{i<={n}, j<={m}}} c_ij u^i v^j"),
            vec![String::from(
                "`coef[i][j]` is c_ij; points have `D` coordinates. Generated by `blossom::restriction!`.",
            )],
        ),
        Support::Total(_) => (
            array_type(&[(big_n + 1) * (big_n + 2) / 2]),
            format!("sum_{{i+j<={big_n}}} c_ij u^i v^j"),
            vec![
                String::from("`coef` is the triangular array c_00, .., c_0N, c_10, .., c_N0, row after row (row i"),
                String::from("holds N + 1 - i); points have `D` coordinates. Generated by `blossom::restriction!`."),
            ],
        ),
    };
    let (param, mut doc) = (quote!(coef), vec![
        format!("Restriction of the power-basis surface S(u, v) = {surface}, of total degree"),
        format!("N = {big_n}, to the triangle with corners `tri = [a, b, c]`, a = (a1, a2), b = (b1, b2), c = (c1, c2):"),
        "the triangular Bézier control points q_(nu mu lambda) = blossom(a^nu, b^mu, c^lambda) (eq. (12)),".into(),
        "listed in lexicographic order of (nu, mu), computed by Theorem 3, eq. (14), unrolled:".into(),
        String::new(),
        format!("q_(nu mu lambda) = sum_ij c_ij / ({big_n}! / (i! j! ({big_n}-i-j)!)) sum_(i_a, i_b, j_a, j_b)"),
        "C(nu, i_a) C(mu, i_b) C(lambda, i_g) C(nu-i_a, j_a) C(mu-i_b, j_b) C(lambda-i_g, j_g)".into(),
        "a1^i_a b1^i_b c1^i_g a2^j_a b2^j_b c2^j_g, with the bounds at the end of the proof of Theorem 3,".into(),
        "regrouped (as (10)-(11) regroup (9)) so that the sums over j, j_a, j_b are shared:".into(),
        String::new(),
        "q_(nu mu lambda) = sum_i sum_(i_a+i_b+i_g=i) C(nu, i_a) C(mu, i_b) C(lambda, i_g) a1^i_a b1^i_b c1^i_g".into(),
        "r_(nu-i_a, mu-i_b, lambda-i_g),".into(),
        format!("r_(nu' mu' lambda') = sum_j c_ij / ({big_n}! / (i! j! ({big_n}-i-j)!)) sum_(j_a+j_b+j_g=j) C(nu', j_a) C(mu', j_b)"),
        format!("C(lambda', j_g) a2^j_a b2^j_b c2^j_g, with i = {big_n} - nu' - mu' - lambda'."),
        String::new(),
    ]);
    doc.extend(input_doc);
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    Some(quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(#param: &#in_ty, tri: &[[T; 2]; 3]) -> #out_ty {
            let [[#pa1, #pa2], [#pb1, #pb2], [#pc1, #pc2]] = tri;
            #mono_doc
            #(#mono_stmts)*
            #(#weight_stmts)*
            #(#r_stmts)*
            #(#point_stmts)*
            [#(#points),*]
        }
    })
}
