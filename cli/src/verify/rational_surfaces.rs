//! Rational surfaces worked and checked: control points and weights of rational patches from a
//! parametrisation, by the blossoms of its homogeneous form (seed 004, section 4, extended to
//! surfaces: [`blossom::RationalSurface::tensor`], [`blossom::RationalSurface::triangle`]).
//!
//! * a quarter cylinder ((1 - u^2)/(1 + u^2), 2u/(1 + u^2), v) on [0, 1]^2, bidegree (2, 1);
//! * a torus patch (R = 2, r = 1) at bidegree (2, 2), both angles on a quarter turn;
//! * a spherical triangle from the inverse stereographic projection
//!   x = (2u, 2v, u^2 + v^2 - 1)/(1 + u^2 + v^2) on the triangle (0, 0), (1, 0), (0, 1), as a
//!   rational quadratic triangle (eq. (23) at degree 2, the true total degree of the
//!   homogeneous form) and as the degree-4 patch of the (2, 2) grid's convention N = n + m.
//!
//! Each patch is evaluated exactly at many rational parameters against the parametrisation
//! (written out here, not through the library's evaluation of the surface), and every point is
//! checked to lie on the surface by its implicit equation.

use super::report::{Entry, Section, Status};
use super::seeds_002_004::show;
use blossom::{Point, Rational, RationalSurface, Ring};

fn r(n: i64) -> Rational {
    Rational::from_int(n)
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// A coefficient grid of bidegree (n, m) from `(i, j, value)` entries.
fn grid(n: usize, m: usize, terms: &[(usize, usize, i64)]) -> Vec<Vec<Rational>> {
    let mut g = vec![vec![r(0); m + 1]; n + 1];
    for &(i, j, v) in terms {
        g[i][j] = r(v);
    }
    g
}

fn surface(
    n: usize,
    m: usize,
    coords: &[&[(usize, usize, i64)]],
    w: &[(usize, usize, i64)],
) -> RationalSurface<Rational> {
    let grids: Vec<Vec<Vec<Rational>>> = coords.iter().map(|c| grid(n, m, c)).collect();
    let numerator: Vec<Vec<Point<Rational>>> = (0..=n)
        .map(|i| {
            (0..=m)
                .map(|j| grids.iter().map(|g| g[i][j].clone()).collect())
                .collect()
        })
        .collect();
    RationalSurface::new(&numerator, &grid(n, m, w)).expect("a valid rational surface")
}

/// (1 - u^2)/(1 + u^2), 2u/(1 + u^2): the rational cosine and sine.
fn cos_sin(u: &Rational) -> (Rational, Rational) {
    let d = r(1) + u * u;
    ((r(1) - u * u) / &d, r(2) * u / &d)
}

fn params(k: i64) -> Vec<Rational> {
    (0..=k).map(|i| q(i, k)).collect()
}

fn entry(
    label: impl Into<String>,
    printed: impl Into<String>,
    computed: String,
    matches: bool,
) -> Entry {
    Entry {
        label: label.into(),
        printed: printed.into(),
        computed,
        matches,
    }
}

fn net_text(points: &[Vec<Point<Rational>>], weights: &[Vec<Rational>]) -> String {
    points
        .iter()
        .zip(weights)
        .map(|(pr, wr)| {
            pr.iter()
                .zip(wr)
                .map(|(p, w)| format!("{} w {w}", show(p)))
                .collect::<Vec<_>>()
                .join("; ")
        })
        .collect::<Vec<_>>()
        .join(" | ")
}

/// An implicit equation, named, and whether a point satisfies it.
type Implicit<'a> = (&'a str, &'a dyn Fn(&[Rational]) -> bool);

/// A tensor patch on [0, 1]^2 checked against `param` and the implicit equation `on` at a
/// `k + 1` by `k + 1` grid of rational parameters.
fn tensor_section(
    title: &str,
    s: &RationalSurface<Rational>,
    param: &dyn Fn(&Rational, &Rational) -> Vec<Rational>,
    on: Implicit,
    k: i64,
) -> Section {
    let rect = [r(0), r(1), r(0), r(1)];
    let patch = s.tensor(&rect, None).expect("no zero weight on [0, 1]^2");
    let (mut agree, mut lie, mut total) = (0, 0, 0);
    for u in params(k) {
        for v in params(k) {
            total += 1;
            let got = patch.eval(&u, &v).expect("positive weights");
            agree += usize::from(got == param(&u, &v));
            lie += usize::from((on.1)(&got));
        }
    }
    let weights_positive = patch.weights().iter().all(|w| *w > r(0));
    let (points, weights) = patch.to_nested();
    let (n, m) = s.degree();
    let entries = vec![
        entry(
            "patch = parametrisation",
            format!("at the {total} parameters (i/{k}, j/{k})"),
            format!("{agree}/{total} points identical"),
            agree == total,
        ),
        entry(
            "points on the surface",
            on.0,
            format!("{lie}/{total} points satisfy it exactly"),
            lie == total,
        ),
        entry(
            "weights",
            "positive (the patch has no pole on [0, 1]^2)",
            if weights_positive {
                "all positive"
            } else {
                "NOT all positive"
            }
            .to_string(),
            weights_positive,
        ),
    ];
    Section::from_entries(
        title,
        "inverse relations paper, section 4 (homogeneous control points by the inverse formula (22), two passes)",
        entries,
        vec![
            format!(
                "RationalSurface::tensor on [0, 1]^2 at bidegree ({n}, {m}): control points and weights [nu][mu] = {}",
                net_text(&points, &weights)
            ),
            "the parametrisation is written out with (1 - u^2)/(1 + u^2), 2u/(1 + u^2), not evaluated by the library".into(),
        ],
        Status::Unexplained,
    )
}

fn cylinder() -> Section {
    // ((1 - u^2), 2u, v (1 + u^2)) / (1 + u^2), bidegree (2, 1).
    let s = surface(
        2,
        1,
        &[
            &[(0, 0, 1), (2, 0, -1)],
            &[(1, 0, 2)],
            &[(0, 1, 1), (2, 1, 1)],
        ],
        &[(0, 0, 1), (2, 0, 1)],
    );
    let param = |u: &Rational, v: &Rational| {
        let (c, s) = cos_sin(u);
        vec![c, s, v.clone()]
    };
    let on = |p: &[Rational]| &p[0] * &p[0] + &p[1] * &p[1] == r(1);
    tensor_section(
        "Rational surfaces: a quarter cylinder as a rational tensor patch of bidegree (2, 1)",
        &s,
        &param,
        ("x^2 + y^2 = 1", &on),
        8,
    )
}

fn torus() -> Section {
    // R = 2, r = 1: ((3 + v^2)(1 - u^2), (3 + v^2) 2u, 2v (1 + u^2)) / ((1 + u^2)(1 + v^2)).
    let s = surface(
        2,
        2,
        &[
            &[(0, 0, 3), (0, 2, 1), (2, 0, -3), (2, 2, -1)],
            &[(1, 0, 6), (1, 2, 2)],
            &[(0, 1, 2), (2, 1, 2)],
        ],
        &[(0, 0, 1), (2, 0, 1), (0, 2, 1), (2, 2, 1)],
    );
    let param = |u: &Rational, v: &Rational| {
        let (ct, st) = cos_sin(u);
        let (cp, sp) = cos_sin(v);
        let rho = r(2) + &cp;
        vec![&rho * &ct, &rho * &st, sp]
    };
    let on = |p: &[Rational]| {
        let rho2 = &p[0] * &p[0] + &p[1] * &p[1];
        let s = &rho2 + &p[2] * &p[2] + r(3);
        &s * &s == r(16) * rho2
    };
    tensor_section(
        "Rational surfaces: a torus patch (R = 2, r = 1) as a rational tensor patch of bidegree (2, 2)",
        &s,
        &param,
        ("(x^2 + y^2 + z^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + y^2)", &on),
        8,
    )
}

fn project(h: &[Rational]) -> Vec<Rational> {
    let w = &h[h.len() - 1];
    h[..h.len() - 1].iter().map(|x| x / w).collect()
}

fn sphere() -> Section {
    let s = surface(
        2,
        2,
        &[
            &[(1, 0, 2)],
            &[(0, 1, 2)],
            &[(2, 0, 1), (0, 2, 1), (0, 0, -1)],
        ],
        &[(0, 0, 1), (2, 0, 1), (0, 2, 1)],
    );
    let tri = [[r(0), r(0)], [r(1), r(0)], [r(0), r(1)]];
    let param = |u: &Rational, v: &Rational| {
        let d = r(1) + u * u + v * v;
        vec![r(2) * u / &d, r(2) * v / &d, (u * u + v * v - r(1)) / &d]
    };
    let on = |p: &[Rational]| p.iter().map(|x| x * x).sum::<Rational>() == r(1);
    // The quadratic: the homogeneous form has true total degree 2, which
    // `RationalSurface::triangle` accepts although the grid is (2, 2).
    let rational_quadratic = s
        .triangle(&tri, Some(2))
        .expect("no zero weight on the triangle");
    let quadratic = rational_quadratic.homogeneous();
    let quartic = s
        .triangle(&tri, None)
        .expect("no zero weight on the triangle");
    let quartic_h = quartic.homogeneous();
    let k = 7;
    let (mut agree2, mut agree4, mut lie, mut total) = (0, 0, 0, 0);
    for i in 0..=k {
        for j in 0..=k - i {
            let bary = [q(i, k), q(j, k), q(k - i - j, k)];
            let u = &bary[0] * &tri[0][0] + &bary[1] * &tri[1][0] + &bary[2] * &tri[2][0];
            let v = &bary[0] * &tri[0][1] + &bary[1] * &tri[1][1] + &bary[2] * &tri[2][1];
            let want = param(&u, &v);
            let got2 = rational_quadratic
                .eval(&[bary[0].clone(), bary[1].clone()])
                .expect("positive weights");
            total += 1;
            agree2 += usize::from(got2 == want);
            agree4 += usize::from(
                quartic.eval(&[bary[0].clone(), bary[1].clone()]).as_ref() == Some(&want),
            );
            lie += usize::from(on(&got2));
        }
    }
    let elevated = blossom::elevate_triangle(&quadratic, 4).expect("a higher degree");
    let weights2: Vec<Rational> = quadratic
        .control_points()
        .iter()
        .map(|p| p[3].clone())
        .collect();
    let positive = weights2.iter().all(|w| *w > r(0));
    let corners_ok = [(2, 0), (0, 2), (0, 0)]
        .iter()
        .zip(&tri)
        .all(|(&(i, j), c)| project(quadratic.get(i, j)) == param(&c[0], &c[1]));
    let entries = vec![
        entry(
            "quadratic triangle = parametrisation",
            format!("at the {total} barycentric points (i, j, {k}-i-j)/{k}"),
            format!("{agree2}/{total} points identical"),
            agree2 == total,
        ),
        entry("points on the sphere", "x^2 + y^2 + z^2 = 1", format!("{lie}/{total} exactly"), lie == total),
        entry(
            "corners",
            "b_200, b_020, b_002 = x(a), x(b), x(c)",
            format!(
                "{}, {}, {}",
                show(&project(quadratic.get(2, 0))),
                show(&project(quadratic.get(0, 2))),
                show(&project(quadratic.get(0, 0)))
            ),
            corners_ok,
        ),
        entry(
            "weights of the quadratic",
            "positive",
            weights2.iter().map(|w| w.to_string()).collect::<Vec<_>>().join(", "),
            positive,
        ),
        entry(
            "RationalSurface::triangle (degree 4 for a (2, 2) grid)",
            "the same patch",
            format!(
                "{agree4}/{total} points identical; its homogeneous net is the quadratic's elevated twice: {}",
                elevated == quartic_h
            ),
            agree4 == total && elevated == quartic_h,
        ),
    ];
    let net: Vec<String> = (0..=2usize)
        .flat_map(|i| (0..=2 - i).map(move |j| (i, j)))
        .map(|(i, j)| {
            let p = quadratic.get(i, j);
            format!("b_{i}{j}{} = {} w {}", 2 - i - j, show(&project(p)), p[3])
        })
        .collect();
    Section::from_entries(
        "Rational surfaces: a spherical triangle as a rational quadratic triangle",
        "inverse relations paper, section 4, eq. (23) on the homogeneous form (2u, 2v, u^2 + v^2 - 1, 1 + u^2 + v^2)",
        entries,
        vec![
            format!("control points and weights (b_ijk at a^i b^j c^k): {}", net.join("; ")),
            "the patch is the image of the parameter triangle (0, 0), (1, 0), (0, 1) under the inverse stereographic \
             projection x = (2u, 2v, u^2 + v^2 - 1)/(1 + u^2 + v^2): the spherical triangle with corners (0, 0, -1), \
             (1, 0, 0), (0, 1, 0), two edges on the great circles y = 0 and x = 0 and the third on the small circle \
             through (0, 0, 1), the image of the line u + v = 1; it is not the octant, whose three great-circle edges \
             are not all images of lines under one stereographic projection (a non-degenerate octant needs degree 4, \
             Farin-Piper-Worsey), which is not constructed here"
                .into(),
            "the quadratic is RationalSurface::triangle at degree 2, the true total degree of the homogeneous form \
             (eq. (23) at degree 2); without a degree it takes the grid's n + m = 2 + 2 = 4 (the paper's convention) \
             and gives the same surface degree-elevated twice (checked against blossom::elevate_triangle)"
                .into(),
        ],
        Status::Unexplained,
    )
}

/// The sections.
pub fn sections() -> Vec<Section> {
    vec![cylinder(), torus(), sphere()]
}
