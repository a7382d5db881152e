//! Bézier shapes by de Casteljau's steps with shared work: the halving of the runtime engine
//! (`blossom::engine::curve_net`, `tensor_net`, `triangle_net`) unrolled for one degree.
//!
//! A Bézier net is the blossom's values at the corners of the reference domain; fixing one
//! argument is one de Casteljau step (eq. (2) of seed 004):
//!
//! * curve, argument t: x'_i = x_i + t (x_(i+1) - x_i);
//! * triangle, argument (s, t) (barycentric (s, t, 1 - s - t)):
//!   x'_ij = x_ij + s (x_(i+1)j - x_ij) + t (x_i(j+1) - x_ij).
//!
//! The control points over [a, b] are w_j = f(a^(n-j), b^j). The left half w_0..w_(s-1),
//! s = ceil((n + 1) / 2), shares n + 1 - s arguments a, the right half s arguments b: those are
//! fixed once, and each half is restricted the same way, down to single points: (3/2) n^2
//! steps. A tensor patch is the curve algorithm along u with whole rows as points, then along
//! v in every row. A triangle's control points f(A^ν, B^μ, C^λ) are split as boxes of
//! (ν, μ, λ): every output of a box shares its lower corner's arguments, which are fixed once,
//! and the box is cut in half along its widest side. The steps and their order are exactly the
//! runtime engine's, so the generated function and the engine agree bit for bit in f64; the
//! symbolic proofs check both against the definition independently.
//!
//! The input never leaves the Bernstein basis: every step is a convex combination when the
//! arguments lie in the reference domain, which keeps de Casteljau's accuracy in f64.

use super::{array_type, fn_attrs, ident};
use crate::model::Spec;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// The emitted statements of one generated function.
#[derive(Default)]
struct Emitter {
    stmts: Vec<TokenStream>,
}

impl Emitter {
    /// Binds `name = x + t (y - x)` coordinate by coordinate.
    fn lerp(
        &mut self,
        name: &str,
        x: &TokenStream,
        y: &TokenStream,
        t: &TokenStream,
    ) -> TokenStream {
        let id = ident(name.to_string());
        self.stmts.push(quote!(
            let #id: [T; D] = ::core::array::from_fn(|k| #x[k].add(&#t.mul(&#y[k].sub(&#x[k]))));
        ));
        quote!(#id)
    }

    /// Binds `name = c + s (a - c) + t (b - c)` coordinate by coordinate.
    fn triangle_step(
        &mut self,
        name: &str,
        [a, b, c]: [&TokenStream; 3],
        [s, t]: &[TokenStream; 2],
    ) -> TokenStream {
        let id = ident(name.to_string());
        self.stmts.push(quote!(
            let #id: [T; D] = ::core::array::from_fn(|k| {
                #c[k].add(&#s.mul(&#a[k].sub(&#c[k]))).add(&#t.mul(&#b[k].sub(&#c[k])))
            });
        ));
        quote!(#id)
    }

    /// One curve step with argument `t` on a level whose points are groups of `width` points
    /// (a whole row of a tensor net, or one point), naming point i of group g `{prefix}{i}`
    /// or `{prefix}{i}_{g}`.
    fn curve_step(
        &mut self,
        level: &[Vec<TokenStream>],
        t: &TokenStream,
        name: &dyn Fn(usize, usize) -> String,
    ) -> Vec<Vec<TokenStream>> {
        (0..level.len() - 1)
            .map(|i| {
                (0..level[i].len())
                    .map(|g| self.lerp(&name(i, g), &level[i][g], &level[i + 1][g], t))
                    .collect()
            })
            .collect()
    }
}

/// The halving of one curve-like level (groups of points as in [`Emitter::curve_step`]):
/// appends the outputs to `out` in order. `tag` names this pass and `ends` its two arguments;
/// `counts` is how many of each are fixed already; `leaf` names output j, group g.
struct CurvePass<'a> {
    tag: &'a str,
    ends: [(&'a str, TokenStream); 2],
    leaf: &'a dyn Fn(usize, usize) -> String,
}

impl CurvePass<'_> {
    fn node(
        &self,
        e: &mut Emitter,
        level: Vec<Vec<TokenStream>>,
        counts: [usize; 2],
        first: usize,
        out: &mut Vec<Vec<TokenStream>>,
    ) {
        let r = level.len();
        if r == 1 {
            out.extend(level);
            return;
        }
        let s = r.div_ceil(2);
        // (end, steps, outputs of the half, index of its first output)
        for (end, steps, size, start) in [(0, r - s, s, first), (1, s, r - s, first + s)] {
            let mut lvl = level.clone();
            let mut c = counts;
            for _ in 0..steps {
                c[end] += 1;
                let done = lvl.len() - 1 == 1 && size == 1;
                let (tag, ends) = (self.tag, &self.ends);
                let name = |i: usize, g: usize| {
                    if done {
                        (self.leaf)(start, g)
                    } else {
                        let mut s = format!("{tag}{}{}{}{}_{i}", ends[0].0, c[0], ends[1].0, c[1]);
                        if level[0].len() > 1 {
                            s.push_str(&format!("_{g}"));
                        }
                        s
                    }
                };
                lvl = e.curve_step(&lvl, &self.ends[end].1, &name);
            }
            self.node(e, lvl, c, start, out);
        }
    }
}

/// An output as an owned point: a bound value moves, a point of the input is cloned.
fn owned(p: &TokenStream) -> TokenStream {
    if p.to_string().starts_with("ctrl") {
        quote!(#p.clone())
    } else {
        p.clone()
    }
}

fn points(ids: impl IntoIterator<Item = TokenStream>) -> Vec<Vec<TokenStream>> {
    ids.into_iter().map(|p| vec![p]).collect()
}

fn index(indices: &[usize]) -> TokenStream {
    let idx = indices.iter().map(|&i| Literal::usize_unsuffixed(i));
    quote!(ctrl #([#idx])*)
}

/// The generated function for a Bézier curve of degree `n` over [0, 1].
pub fn curve(spec: &Spec, n: usize) -> TokenStream {
    let mut e = Emitter::default();
    let leaf = |j: usize, _: usize| format!("w{j}");
    let pass = CurvePass {
        tag: "",
        ends: [("a", quote!(a)), ("b", quote!(b))],
        leaf: &leaf,
    };
    let mut out = Vec::new();
    pass.node(
        &mut e,
        points((0..=n).map(|i| index(&[i]))),
        [0, 0],
        0,
        &mut out,
    );
    let outputs: Vec<TokenStream> = out.iter().map(|p| owned(&p[0])).collect();
    let unused = (n == 0).then(|| quote!(let _ = (a, b);));
    let stmts = &e.stmts;
    let ty = array_type(&[n + 1]);
    let s = (n + 1).div_ceil(2);
    let doc = vec![
        format!("Restriction of the Bézier curve of degree {n} over [0, 1] with control points `ctrl` to the"),
        format!("interval [a, b]: the control points w_j = f(a^({n}-j), b^j), j = 0..={n}, of its blossom f,"),
        "by de Casteljau's steps x + t (y - x) with shared work: the first half of the outputs".into(),
        format!("(w_0..w_{}) fixes {} arguments a once, the second half {s} arguments b, and each half", s - 1, n + 1 - s),
        "is halved again down to single points ((3/2) n^2 steps; the runtime engine's order, so".into(),
        "`blossom::engine::curve_net` gives the same answer bit for bit). No change of basis.".into(),
        "`ctrl[i]` is b_i; points have `D` coordinates. Generated by `blossom::restriction!`.".into(),
    ];
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(ctrl: &#ty, a: &T, b: &T) -> #ty {
            #unused
            #(#stmts)*
            [#(#outputs),*]
        }
    }
}

/// The generated function for a tensor-product Bézier patch of bidegree (n, m).
pub fn tensor(spec: &Spec, n: usize, m: usize) -> TokenStream {
    let mut e = Emitter::default();
    // Along u with whole rows as points.
    let row_leaf = |nu: usize, mu: usize| format!("r{nu}_{mu}");
    let pass = CurvePass {
        tag: "u",
        ends: [("a", quote!(a)), ("b", quote!(b))],
        leaf: &row_leaf,
    };
    let net: Vec<Vec<TokenStream>> = (0..=n)
        .map(|i| (0..=m).map(|j| index(&[i, j])).collect())
        .collect();
    let mut rows = Vec::new();
    pass.node(&mut e, net, [0, 0], 0, &mut rows);
    // Along v in every row.
    let mut result = Vec::new();
    for (nu, row) in rows.into_iter().enumerate() {
        let leaf = move |mu: usize, _: usize| format!("w{nu}_{mu}");
        let tag = format!("v{nu}_");
        let pass = CurvePass {
            tag: &tag,
            ends: [("c", quote!(c)), ("d", quote!(d))],
            leaf: &leaf,
        };
        let mut out = Vec::new();
        pass.node(&mut e, points(row), [0, 0], 0, &mut out);
        let ids: Vec<TokenStream> = out.iter().map(|p| owned(&p[0])).collect();
        result.push(quote!([#(#ids),*]));
    }
    let unused = (n == 0 || m == 0).then(|| quote!(let _ = (a, b, c, d);));
    let stmts = &e.stmts;
    let ty = array_type(&[n + 1, m + 1]);
    let doc = vec![
        format!("Restriction of the tensor-product Bézier patch of bidegree ({n}, {m}) over [0, 1]^2 with control net"),
        "`ctrl[i][j]` to the rectangle [a, b] x [c, d] (`rect = [a, b, c, d]`): the control points".into(),
        format!("p_(nu mu) = f(a^({n}-nu), b^nu; c^({m}-mu), d^mu) of its blossom f (eq. (9) of seed 004: the curve"),
        "algorithm along u with whole rows as points, then along v in every row), each pass by".into(),
        "de Casteljau's steps with shared work as for curves: O(nm(n + m)) steps, no change of basis.".into(),
        "Points have `D` coordinates. Generated by `blossom::restriction!`.".into(),
    ];
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(ctrl: &#ty, rect: &[T; 4]) -> #ty {
            let [a, b, c, d] = rect;
            #unused
            #(#stmts)*
            [#(#result),*]
        }
    }
}

/// A box of triangle outputs, as in the runtime engine: (ν, μ, λ) = offset + (x, y, z) with
/// lo <= (x, y, z) <= hi and x + y + z = degree.
#[derive(Clone, Copy)]
struct TriangleBox {
    degree: usize,
    lo: [usize; 3],
    hi: [usize; 3],
    offset: [usize; 3],
}

impl TriangleBox {
    fn tightened(mut self) -> Option<Self> {
        let r = self.degree;
        for k in 0..3 {
            let (p, q) = ((k + 1) % 3, (k + 2) % 3);
            let others_lo = self.lo[p] + self.lo[q];
            if others_lo > r {
                return None;
            }
            self.lo[k] = self.lo[k].max(r.saturating_sub(self.hi[p] + self.hi[q]));
            self.hi[k] = self.hi[k].min(r - others_lo);
            if self.lo[k] > self.hi[k] {
                return None;
            }
        }
        Some(self)
    }
}

/// A triangular level of degree d: `[i][j]` for i + j <= d.
type Level = Vec<Vec<TokenStream>>;

struct TrianglePass {
    total: usize,
    corners: [[TokenStream; 2]; 3],
    levels: usize,
}

impl TrianglePass {
    fn step(
        &mut self,
        e: &mut Emitter,
        level: &Level,
        corner: usize,
        leaf: Option<String>,
    ) -> Level {
        let d = level.len() - 1;
        self.levels += 1;
        let tag = self.levels;
        (0..d)
            .map(|i| {
                (0..d - i)
                    .map(|j| {
                        let name = leaf.clone().unwrap_or_else(|| format!("t{tag}_{i}_{j}"));
                        e.triangle_step(
                            &name,
                            [&level[i + 1][j], &level[i][j + 1], &level[i][j]],
                            &self.corners[corner],
                        )
                    })
                    .collect()
            })
            .collect()
    }

    fn node(
        &mut self,
        e: &mut Emitter,
        level: &Level,
        node: TriangleBox,
        out: &mut [Option<TokenStream>],
    ) {
        let Some(node) = node.tightened() else {
            return;
        };
        let fixed: usize = node.lo.iter().sum();
        if fixed > 0 {
            let mut lvl = level.clone();
            let mut left = fixed;
            for (k, &count) in node.lo.iter().enumerate() {
                for _ in 0..count {
                    left -= 1;
                    // The last step onto a single point names the output.
                    let leaf = (left == 0 && node.degree == fixed).then(|| {
                        let [nu, mu, _] = [0, 1, 2].map(|q| node.offset[q] + node.lo[q]);
                        format!("w{nu}_{mu}")
                    });
                    lvl = self.step(e, &lvl, k, leaf);
                }
            }
            let inner = TriangleBox {
                degree: node.degree - fixed,
                lo: [0; 3],
                hi: [0, 1, 2].map(|k| node.hi[k] - node.lo[k]),
                offset: [0, 1, 2].map(|k| node.offset[k] + node.lo[k]),
            };
            self.node(e, &lvl, inner, out);
            return;
        }
        if node.degree <= 2 {
            self.small_box(e, level, node, out);
            return;
        }
        let k = (0..3)
            .max_by_key(|&k| node.hi[k] - node.lo[k])
            .expect("three sides");
        let mid = (node.lo[k] + node.hi[k]) / 2;
        let mut low = node;
        low.hi[k] = mid;
        let mut high = node;
        high.lo[k] = mid + 1;
        self.node(e, level, low, out);
        self.node(e, level, high, out);
    }
}

impl TrianglePass {
    /// A box of degree at most 2, as the engine's `small_box`: for degree 2 one step per first
    /// argument (A before B before C), shared, then each output's second step.
    fn small_box(
        &mut self,
        e: &mut Emitter,
        level: &Level,
        node: TriangleBox,
        out: &mut [Option<TokenStream>],
    ) {
        let mut outputs = Vec::new();
        for x in node.lo[0]..=node.hi[0] {
            for y in node.lo[1]..=node.hi[1] {
                let Some(z) = node.degree.checked_sub(x + y) else {
                    continue;
                };
                if z < node.lo[2] || z > node.hi[2] {
                    continue;
                }
                let ks: Vec<usize> = [x, y, z]
                    .into_iter()
                    .enumerate()
                    .flat_map(|(k, c)| std::iter::repeat_n(k, c))
                    .collect();
                let [nu, mu] = [node.offset[0] + x, node.offset[1] + y];
                outputs.push(((nu, mu), ks));
            }
        }
        let name = |(nu, mu): (usize, usize)| format!("w{nu}_{mu}");
        match node.degree {
            0 => {
                let ((nu, mu), _) = outputs[0];
                out[triangle_index(self.total, nu, mu)] = Some(level[0][0].clone());
            }
            1 => {
                for (at, ks) in &outputs {
                    let point = self.step(e, level, ks[0], Some(name(*at)));
                    out[triangle_index(self.total, at.0, at.1)] = Some(point[0][0].clone());
                }
            }
            _ => {
                for k in 0..3 {
                    let mut shared = None;
                    for (at, ks) in outputs.iter().filter(|(_, ks)| ks[0] == k) {
                        let tmp = shared
                            .get_or_insert_with(|| self.step(e, level, k, None))
                            .clone();
                        let point = self.step(e, &tmp, ks[1], Some(name(*at)));
                        out[triangle_index(self.total, at.0, at.1)] = Some(point[0][0].clone());
                    }
                }
            }
        }
    }
}

fn triangle_index(n: usize, nu: usize, mu: usize) -> usize {
    nu * (n + 1) - nu * nu.saturating_sub(1) / 2 + mu
}

/// The generated function for a triangular Bézier patch of degree `big_n`.
pub fn triangle(spec: &Spec, big_n: usize) -> TokenStream {
    let mut e = Emitter::default();
    let len = (big_n + 1) * (big_n + 2) / 2;
    let level: Level = (0..=big_n)
        .map(|i| {
            (0..=big_n - i)
                .map(|j| index(&[triangle_index(big_n, i, j)]))
                .collect()
        })
        .collect();
    let mut pass = TrianglePass {
        total: big_n,
        corners: [
            [quote!(a1), quote!(a2)],
            [quote!(b1), quote!(b2)],
            [quote!(c1), quote!(c2)],
        ],
        levels: 0,
    };
    let mut out = vec![None; len];
    let root = TriangleBox {
        degree: big_n,
        lo: [0; 3],
        hi: [big_n; 3],
        offset: [0; 3],
    };
    pass.node(&mut e, &level, root, &mut out);
    let outputs: Vec<TokenStream> = out
        .into_iter()
        .map(|p| owned(&p.expect("the boxes cover every output")))
        .collect();
    let unused = (big_n == 0).then(|| quote!(let _ = (a1, a2, b1, b2, c1, c2);));
    let stmts = &e.stmts;
    let ty = array_type(&[len]);
    let doc = vec![
        format!("Restriction of the triangular Bézier patch of degree N = {big_n} with control net `ctrl` (b_(nu mu lambda)"),
        "in lexicographic order of (nu, mu), nu the exponent of the first barycentric coordinate) to the".into(),
        "sub-triangle with corners `tri = [a, b, c]`, each given by its first two barycentric coordinates".into(),
        "(a1, a2) with respect to the patch's own domain (the third is 1 - a1 - a2): the control points".into(),
        "q_(nu mu lambda) = f(a^nu, b^mu, c^lambda) of its blossom f, in the same order, by de Casteljau's".into(),
        "barycentric steps x + s (x_a - x) + t (x_b - x) with shared work: the outputs are split into boxes".into(),
        "of (nu, mu, lambda) whose common arguments are fixed once (the runtime engine's order).".into(),
        "Points have `D` coordinates. Generated by `blossom::restriction!`.".into(),
    ];
    let attrs = fn_attrs(spec, &doc);
    let (vis, name) = (&spec.vis, &spec.name);
    quote! {
        #attrs
        #vis fn #name<T: ::blossom::Ring, const D: usize>(ctrl: &#ty, tri: &[[T; 2]; 3]) -> #ty {
            let [[a1, a2], [b1, b2], [c1, c2]] = tri;
            #unused
            #(#stmts)*
            [#(#outputs),*]
        }
    }
}
