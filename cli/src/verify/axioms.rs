//! The three axioms of the blossom (seed 002, Teorema 2.1; seed 000/001, section 2): symmetry,
//! multi-affinity in each argument, and the diagonal b(u, .., u) = C(u), proved symbolically
//! (every coefficient and every argument a variable) for every algorithm of the library at
//! small degrees: curves, tensor patches, triangles.
//!
//! Two kinds of algorithm are tested:
//!
//! * *blossoms*, which take n free arguments (the subset-sum definitions (2), (8), (13), the
//!   polarisation (20)/(21) of seed 004, Theorem 1's (18) on the homogenisation, the pyramid on
//!   the Bernstein net): the axioms are checked on them directly. Symmetry: every adjacent
//!   transposition of arguments (they generate the symmetric group) leaves the value unchanged;
//!   multi-affinity: for each argument k, f(.., (1 - l) y + l z, ..) = (1 - l) f(.., y, ..) +
//!   l f(.., z, ..) with symbolic l, y, z; diagonal: f(u, .., u) = C(u) with symbolic u.
//! * *restrictions* (every [`Method`], the halving engine on Bézier input, the carried
//!   generated evaluators), which only compute the values at repeated arguments,
//!   w_v(a, b) = b(a^(n-v), b^v) with symbolic a, b. Their blossom is recovered from each
//!   control point alone by polarising it in a (at degree n - v) and in b (at degree v), eq.
//!   (19), giving forms F_v(x_1..x_n). Multi-affinity of the blossom is what bounds the degrees
//!   (deg_a w_v <= n - v, deg_b w_v <= v) and makes F_v multi-affine; symmetry is that every
//!   F_v is the same symmetric form (F_v = F_0 for all v, and F_0 symmetric), which no single
//!   control point can show; the diagonal is w_v(u, u) = C(u) for every v and F_0(u..u) = C(u).
//!   A symmetric multi-affine form with diagonal C is C's blossom (it is unique), so the three
//!   together prove every control point is the blossom value, without the definition.

use super::report::{Entry, Section, Status};
use crate::proofs::{bernstein_tensor, bernstein_triangle, symbolic_curve, symbolic_surface};
use blossom::engine::power_to_bernstein;
use blossom::triangle_blossom_from_samples;
use blossom::{bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom};
use blossom::{curve_blossom, tensor_blossom, triangle_blossom};
use blossom::{curve_blossom_from_samples, tensor_blossom_from_samples};
use blossom::{homogeneous_curve_blossom, homogeneous_triangle_blossom, polar_form};
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
};
use blossom::{BezierCurve, Poly, PowerCurve, PowerSurface, Ring};
use std::collections::HashMap;

/// A form under test: its arguments, each a point (1 coordinate for curves and tensor patches,
/// 2 for triangles), in groups (one for curves and triangles, u then v for tensor patches).
pub type Form<'a> = &'a dyn Fn(&[Vec<Poly>]) -> Vec<Poly>;

type Boxed<'a> = Box<dyn Fn(&[Vec<Poly>]) -> Vec<Poly> + 'a>;

fn form<'a>(f: impl Fn(&[Vec<Poly>]) -> Vec<Poly> + 'a) -> Boxed<'a> {
    Box::new(f)
}

/// The axioms found for one algorithm at one degree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Axioms {
    /// Symmetric in the arguments of each group.
    pub symmetric: bool,
    /// Affine in each argument.
    pub multiaffine: bool,
    /// The diagonal is the polynomial.
    pub diagonal: bool,
}

impl Axioms {
    fn and(self, other: Axioms) -> Axioms {
        Axioms {
            symmetric: self.symmetric && other.symmetric,
            multiaffine: self.multiaffine && other.multiaffine,
            diagonal: self.diagonal && other.diagonal,
        }
    }

    /// All three hold.
    pub fn all(self) -> bool {
        self.symmetric && self.multiaffine && self.diagonal
    }
}

fn point(name: &str, k: usize) -> Vec<Poly> {
    (0..k).map(|r| Poly::var(&format!("{name}_{r}"))).collect()
}

fn affine(y: &[Poly], z: &[Poly], l: &Poly) -> Vec<Poly> {
    let one_minus = Poly::one().sub(l);
    y.iter()
        .zip(z)
        .map(|(a, b)| one_minus.mul(a).add(&l.mul(b)))
        .collect()
}

/// Checks the three axioms of `f` (arguments in groups of `groups[g]` points of `k`
/// coordinates) against the polynomial `diagonal` (one point per group).
pub fn check_form(groups: &[usize], k: usize, f: Form, diagonal: Form) -> Axioms {
    let total: usize = groups.iter().sum();
    let base: Vec<Vec<Poly>> = (0..total).map(|i| point(&format!("x{i}"), k)).collect();
    let at_base = f(&base);
    let mut symmetric = true;
    let mut start = 0;
    for &g in groups {
        for i in start..start + g.saturating_sub(1) {
            let mut swapped = base.clone();
            swapped.swap(i, i + 1);
            symmetric &= f(&swapped) == at_base;
        }
        start += g;
    }
    let (y, z, l) = (point("y", k), point("z", k), Poly::var("l"));
    let mut multiaffine = true;
    for i in 0..total {
        let with = |p: Vec<Poly>| {
            let mut a = base.clone();
            a[i] = p;
            f(&a)
        };
        let mixed = with(affine(&y, &z, &l));
        let combined = affine(&with(y.clone()), &with(z.clone()), &l);
        multiaffine &= mixed == combined;
    }
    let diag_points: Vec<Vec<Poly>> = (0..groups.len())
        .map(|g| point(&format!("p{g}"), k))
        .collect();
    let mut repeated = Vec::with_capacity(total);
    for (g, &size) in groups.iter().enumerate() {
        repeated.extend(std::iter::repeat_n(diag_points[g].clone(), size));
    }
    Axioms {
        symmetric,
        multiaffine,
        diagonal: f(&repeated) == diagonal(&diag_points),
    }
}

fn substitute(p: &Poly, values: &HashMap<String, Poly>) -> Poly {
    p.eval_in(|name| Some(values.get(name).cloned().unwrap_or_else(|| Poly::var(name))))
        .expect("every variable has a value")
}

/// One repeated argument of a restriction: the names of its coordinates (e.g. `a`, or `a1`,
/// `a2`) and how many times it is repeated in the control point.
#[derive(Clone)]
pub struct Slot {
    names: Vec<String>,
    copies: usize,
}

/// Polarises `w` in each slot at degree `copies`, at the arguments `args` (taken in order,
/// `copies` per slot), by eq. (19): the form of the control point.
fn polarise(
    w: &[Poly],
    slots: &[Slot],
    args: &[Vec<Poly>],
    bound: &HashMap<String, Poly>,
) -> Vec<Poly> {
    match slots.split_first() {
        None => w.iter().map(|p| substitute(p, bound)).collect(),
        Some((slot, rest)) => {
            let (mine, others) = args.split_at(slot.copies);
            polar_form(slot.copies, mine, slot.names.len(), &|y: &[Poly]| {
                let mut b = bound.clone();
                for (name, value) in slot.names.iter().zip(y) {
                    b.insert(name.clone(), value.clone());
                }
                polarise(w, rest, others, &b)
            })
            .expect("one argument per copy of the slot")
        }
    }
}

/// The degree of `p` in the point variables `names` jointly (its degree after scaling them
/// all by a fresh variable).
fn joint_degree(p: &Poly, names: &[String]) -> u32 {
    let t = Poly::var("deg_scale");
    let values: HashMap<String, Poly> = names
        .iter()
        .map(|n| (n.clone(), t.mul(&Poly::var(n))))
        .collect();
    substitute(p, &values).degree_in("deg_scale")
}

/// The axioms of a restriction, from its control points `points` with their slots (see the
/// module documentation). `groups`, `k` and `diagonal` are those of [`check_form`].
pub fn check_restriction(
    groups: &[usize],
    k: usize,
    points: &[(Vec<Poly>, Vec<Slot>)],
    diagonal: Form,
) -> Axioms {
    let total: usize = groups.iter().sum();
    let base: Vec<Vec<Poly>> = (0..total).map(|i| point(&format!("x{i}"), k)).collect();
    let mut degrees = true;
    let mut on_diagonal = true;
    let diag_points: Vec<Vec<Poly>> = (0..groups.len())
        .map(|g| point(&format!("p{g}"), k))
        .collect();
    let want = diagonal(&diag_points);
    let mut forms = Vec::with_capacity(points.len());
    for (w, slots) in points {
        for slot in slots {
            degrees &= w
                .iter()
                .all(|p| joint_degree(p, &slot.names) as usize <= slot.copies);
        }
        // w at the diagonal: every slot of group g at the point p_g. The slots are listed
        // group by group, so walk them with the group sizes.
        let mut values = HashMap::new();
        let (mut g, mut used) = (0, 0);
        for slot in slots {
            while g + 1 < groups.len() && used == groups[g] {
                g += 1;
                used = 0;
            }
            for (name, value) in slot.names.iter().zip(&diag_points[g]) {
                values.insert(name.clone(), value.clone());
            }
            used += slot.copies;
        }
        on_diagonal &= w.iter().map(|p| substitute(p, &values)).collect::<Vec<_>>() == want;
        forms.push(polarise(w, slots, &base, &HashMap::new()));
    }
    let agree = forms.iter().all(|f| *f == forms[0]);
    let first = forms[0].clone();
    let names: Vec<String> = base.iter().flatten().map(|p| p.to_string()).collect();
    let form = |args: &[Vec<Poly>]| {
        let values: HashMap<String, Poly> = names
            .iter()
            .cloned()
            .zip(args.iter().flatten().cloned())
            .collect();
        first
            .iter()
            .map(|p| substitute(p, &values))
            .collect::<Vec<_>>()
    };
    let of_form = check_form(groups, k, &form, diagonal);
    Axioms {
        symmetric: agree,
        multiaffine: degrees,
        diagonal: on_diagonal,
    }
    .and(of_form)
}

impl Slot {
    /// A corner with coordinates named `names`, repeated `copies` times.
    pub fn new(names: &[&str], copies: usize) -> Slot {
        Slot {
            names: names.iter().map(|s| s.to_string()).collect(),
            copies,
        }
    }
}

fn slot(names: &[&str], copies: usize) -> Slot {
    Slot::new(names, copies)
}

/// One algorithm's result at one degree.
pub struct AxiomRow {
    /// `curve`, `tensor`, `triangle`.
    pub shape: &'static str,
    /// The degree as text.
    pub degree: String,
    /// The algorithm.
    pub algorithm: String,
    /// What was found.
    pub axioms: Axioms,
}

type CurveFn<'a> = Box<dyn Fn(&PowerCurve<Poly>, &Poly, &Poly) -> BezierCurve<Poly> + 'a>;

type CurveRestriction<'a> = (
    &'a str,
    Box<dyn Fn(&PowerCurve<Poly>, &Poly, &Poly) -> BezierCurve<Poly> + 'a>,
);

fn curve_restrictions() -> Vec<CurveRestriction<'static>> {
    let mut out: Vec<CurveRestriction> = Method::ALL
        .iter()
        .map(|&m| {
            let f: CurveFn = Box::new(move |c, a, b| restrict_power_curve(c, a, b, m));
            (m.name(), f)
        })
        .collect();
    out.push((
        "halving engine on Bézier input",
        Box::new(|c, a, b| {
            let net =
                BezierCurve::new(power_to_bernstein(&c.coefficients().to_vec())).expect("a net");
            net.subsegment(a.clone()..b.clone())
        }),
    ));
    #[cfg(feature = "carried-grid")]
    out.push((
        "generated evaluator (carried)",
        Box::new(|c, a, b| {
            crate::specialised::restrict_curve_specialised(c, a, b).expect("a carried degree")
        }),
    ));
    out
}

/// The axioms of every curve algorithm at degree `n`.
pub fn curve_rows(n: usize) -> Vec<AxiomRow> {
    let c = symbolic_curve(n);
    let diagonal = |p: &[Vec<Poly>]| c.eval(&p[0][0]);
    let scalars = |args: &[Vec<Poly>]| args.iter().map(|x| x[0].clone()).collect::<Vec<_>>();
    let net = power_to_bernstein(&c.coefficients().to_vec());
    let blossoms: Vec<(&str, Boxed)> = vec![
        (
            "definition (2)",
            form(|args| curve_blossom(&c, &scalars(args)).expect("n arguments")),
        ),
        (
            "polarisation (20)",
            form(|args| {
                curve_blossom_from_samples(n, &scalars(args), &|t| c.eval(t)).expect("n arguments")
            }),
        ),
        (
            "Theorem 1, (18) at (t, 1)",
            form(|args| homogeneous_curve_blossom(&c, &scalars(args)).expect("n arguments")),
        ),
        (
            "pyramid on the Bernstein net",
            form(|args| bezier_curve_blossom(&net, &scalars(args)).expect("n arguments")),
        ),
    ];
    let mut rows: Vec<AxiomRow> = blossoms
        .into_iter()
        .map(|(name, f)| AxiomRow {
            shape: "curve",
            degree: n.to_string(),
            algorithm: name.into(),
            axioms: check_form(&[n], 1, &*f, &diagonal),
        })
        .collect();
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    for (name, restrict) in curve_restrictions() {
        let w = restrict(&c, &a, &b);
        let points: Vec<(Vec<Poly>, Vec<Slot>)> = w
            .control_points()
            .iter()
            .enumerate()
            .map(|(v, p)| (p.to_vec(), vec![slot(&["a"], n - v), slot(&["b"], v)]))
            .collect();
        rows.push(AxiomRow {
            shape: "curve",
            degree: n.to_string(),
            algorithm: format!("{name} (restriction)"),
            axioms: check_restriction(&[n], 1, &points, &diagonal),
        });
    }
    rows
}

/// The axioms of every tensor-patch algorithm at bidegree (n, m).
pub fn tensor_rows(n: usize, m: usize) -> Vec<AxiomRow> {
    let s: PowerSurface<Poly> = symbolic_surface(n, m);
    let diagonal = |p: &[Vec<Poly>]| s.eval(&p[0][0], &p[1][0]);
    let split = |args: &[Vec<Poly>]| {
        let flat: Vec<Poly> = args.iter().map(|x| x[0].clone()).collect();
        (flat[..n].to_vec(), flat[n..].to_vec())
    };
    let net = bernstein_tensor(&s);
    let blossoms: Vec<(&str, Boxed)> = vec![
        (
            "definition (8)",
            form(|args| {
                let (us, vs) = split(args);
                tensor_blossom(&s, &us, &vs).expect("arguments")
            }),
        ),
        (
            "polarisation (20), two passes",
            form(|args| {
                let (us, vs) = split(args);
                tensor_blossom_from_samples((n, m), &us, &vs, &|u, v| s.eval(u, v))
                    .expect("arguments")
            }),
        ),
        (
            "pyramid on the Bernstein net",
            form(|args| {
                let (us, vs) = split(args);
                bezier_tensor_blossom(&net.to_nested(), &us, &vs).expect("arguments")
            }),
        ),
    ];
    let degree = format!("({n}, {m})");
    let mut rows: Vec<AxiomRow> = blossoms
        .into_iter()
        .map(|(name, f)| AxiomRow {
            shape: "tensor",
            degree: degree.clone(),
            algorithm: name.into(),
            axioms: check_form(&[n, m], 1, &*f, &diagonal),
        })
        .collect();
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let mut restrictions: Vec<(String, blossom::TensorPatch<Poly>)> = Method::ALL
        .iter()
        .map(|&meth| {
            (
                meth.name().to_string(),
                restrict_power_surface(&s, &rect, meth),
            )
        })
        .collect();
    restrictions.push(("halving engine on Bézier input".into(), net.restrict(&rect)));
    #[cfg(feature = "carried-grid")]
    if (n, m) != (0, 0) {
        restrictions.push((
            "generated evaluator (carried)".into(),
            crate::specialised::restrict_tensor_specialised(&s, &rect).expect("carried"),
        ));
    }
    for (name, patch) in restrictions {
        let mut points = Vec::new();
        for (nu, row) in patch.to_nested().iter().enumerate() {
            for (mu, p) in row.iter().enumerate() {
                let slots = vec![
                    slot(&["a"], n - nu),
                    slot(&["b"], nu),
                    slot(&["c"], m - mu),
                    slot(&["d"], mu),
                ];
                points.push((p.clone(), slots));
            }
        }
        rows.push(AxiomRow {
            shape: "tensor",
            degree: degree.clone(),
            algorithm: format!("{name} (restriction)"),
            axioms: check_restriction(&[n, m], 1, &points, &diagonal),
        });
    }
    rows
}

/// The axioms of every triangle algorithm for the surface of bidegree (n, m) as a triangular
/// patch of total degree n + m.
pub fn triangle_rows(n: usize, m: usize) -> Vec<AxiomRow> {
    let big_n = n + m;
    let s: PowerSurface<Poly> = symbolic_surface(n, m);
    let diagonal = |p: &[Vec<Poly>]| s.eval(&p[0][0], &p[0][1]);
    let pairs = |args: &[Vec<Poly>]| {
        args.iter()
            .map(|x| [x[0].clone(), x[1].clone()])
            .collect::<Vec<_>>()
    };
    let patch = bernstein_triangle(&s);
    let blossoms: Vec<(&str, Boxed)> = vec![
        (
            "definition (13)",
            form(|args| triangle_blossom(&s, &pairs(args)).expect("N arguments")),
        ),
        (
            "polarisation (21)",
            form(|args| {
                triangle_blossom_from_samples(big_n, &pairs(args), &|u, v| s.eval(u, v))
                    .expect("N arguments")
            }),
        ),
        (
            "Theorem 1, (18) at (u, v, 1)",
            form(|args| homogeneous_triangle_blossom(&s, &pairs(args)).expect("N arguments")),
        ),
        (
            "pyramid on the Bernstein net",
            form(|args| {
                let bary: Vec<[Poly; 3]> = args
                    .iter()
                    .map(|x| {
                        [
                            x[0].clone(),
                            x[1].clone(),
                            Poly::one().sub(&x[0]).sub(&x[1]),
                        ]
                    })
                    .collect();
                bezier_triangle_blossom(&patch, &bary).expect("N arguments")
            }),
        ),
    ];
    let degree = format!("({n}, {m})");
    let mut rows: Vec<AxiomRow> = blossoms
        .into_iter()
        .map(|(name, f)| AxiomRow {
            shape: "triangle",
            degree: degree.clone(),
            algorithm: name.into(),
            axioms: check_form(&[big_n], 2, &*f, &diagonal),
        })
        .collect();
    let tri = crate::proofs::symbolic_triangle();
    let mut restrictions: Vec<(String, blossom::TriangularPatch<Poly>)> = Method::ALL
        .iter()
        .map(|&meth| {
            (
                meth.name().to_string(),
                restrict_power_surface_to_triangle(&s, &tri, meth),
            )
        })
        .collect();
    restrictions.push((
        "halving engine on Bézier input".into(),
        patch.restrict(&tri),
    ));
    #[cfg(feature = "carried-grid")]
    if (n, m) != (0, 0) && n <= 4 && m <= 4 {
        restrictions.push((
            "generated evaluator (carried)".into(),
            crate::specialised::restrict_triangle_specialised(&s, &tri).expect("carried"),
        ));
    }
    for (name, net) in restrictions {
        let points: Vec<(Vec<Poly>, Vec<Slot>)> = net
            .entries()
            .map(|(nu, mu, la, p)| {
                let slots = vec![
                    slot(&["a1", "a2"], nu),
                    slot(&["b1", "b2"], mu),
                    slot(&["c1", "c2"], la),
                ];
                (p.to_vec(), slots)
            })
            .collect();
        rows.push(AxiomRow {
            shape: "triangle",
            degree: degree.clone(),
            algorithm: format!("{name} (restriction)"),
            axioms: check_restriction(&[big_n], 2, &points, &diagonal),
        });
    }
    rows
}

/// The degrees of the report: curves 1..=4, tensor patches (n, m) in 1..=2, triangles of total
/// degree 1..=3.
pub fn all_rows() -> Vec<AxiomRow> {
    let mut rows = Vec::new();
    for n in 1..=4 {
        rows.extend(curve_rows(n));
    }
    for n in 1..=2 {
        for m in 1..=2 {
            rows.extend(tensor_rows(n, m));
        }
    }
    for big_n in 1..=3 {
        for n in 0..=big_n {
            rows.extend(triangle_rows(n, big_n - n));
        }
    }
    rows
}

/// The section: one entry per shape and algorithm, over all its degrees.
pub fn section() -> Section {
    let rows = all_rows();
    let mut keys: Vec<(&str, String)> = Vec::new();
    for r in &rows {
        if !keys.iter().any(|(s, a)| *s == r.shape && *a == r.algorithm) {
            keys.push((r.shape, r.algorithm.clone()));
        }
    }
    let entries: Vec<Entry> = keys
        .iter()
        .map(|(shape, algorithm)| {
            let mine: Vec<&AxiomRow> = rows
                .iter()
                .filter(|r| r.shape == *shape && r.algorithm == *algorithm)
                .collect();
            let count = |f: fn(&Axioms) -> bool| mine.iter().filter(|r| f(&r.axioms)).count();
            let degrees: Vec<&str> = mine.iter().map(|r| r.degree.as_str()).collect();
            let total = mine.len();
            let (s, a, d) = (
                count(|x| x.symmetric),
                count(|x| x.multiaffine),
                count(|x| x.diagonal),
            );
            Entry {
                label: format!("{shape}: {algorithm}"),
                printed: "symmetric, multi-affine, diagonal = the polynomial".into(),
                computed: format!(
                    "degrees {}: symmetric {s}/{total}, multi-affine {a}/{total}, diagonal {d}/{total}",
                    degrees.join(", ")
                ),
                matches: s == total && a == total && d == total,
            }
        })
        .collect();
    Section::from_entries(
        "The blossom axioms, proved symbolically for every algorithm",
        "de Boor points paper, Teorema 2.1 i)-iii); subdivision paper, section 2; inverse relations paper, section 2",
        entries,
        vec![
            format!(
                "{} proofs: curves n = 1..4, tensor patches (n, m) in 1..2 x 1..2, triangles of total degree 1..3; every \
                 coefficient, argument and corner a variable, so each holds for every input of that degree",
                rows.len()
            ),
            "blossoms (n free arguments): symmetry by every adjacent transposition, multi-affinity by f(.., (1-l) y + l z, ..) \
             = (1-l) f(.., y, ..) + l f(.., z, ..) in each argument, diagonal f(u, .., u) = C(u)"
                .into(),
            "restrictions (values at repeated corners only): each control point is polarised in each corner at its \
             multiplicity (eq. (19)); multi-affinity = the degree bounds this needs, symmetry = all control points give \
             one and the same symmetric form, diagonal = every control point at a = b (= c) is the polynomial; the unique \
             blossom is the only form passing all three, so this proves the nets without comparing with the definition"
                .into(),
        ],
        Status::Unexplained,
    )
}
