//! Degree elevation and reduction of tensor and triangular patches, and the true degree: exact
//! checks against independent computations (evaluation by de Casteljau, repeated degree-1
//! elevation written here, the inverse formula's built-in elevation, the curve reductions, and
//! integrals of the power form of products of polynomials, with no Gram matrix), the bad
//! inputs, and a snapshot of two reductions with exact L2 errors derived by hand.

use super::json::Json;
use crate::common::{q, Rng};
use blossom::engine::{bernstein_to_power, triangle_index, triangle_len};
use blossom::engine::{
    least_squares_matrix, tensor_bernstein_gram, tensor_least_squares_matrix,
    triangle_bernstein_gram, triangle_bernstein_to_power, triangle_elevation_matrix,
    triangle_least_squares_matrix,
};
use blossom::{
    elevate, elevate_tensor, elevate_triangle, reduce, reduce_tensor, reduce_triangle,
    tensor_control_points_from_samples, tensor_squared_l2_distance, tensor_true_degree,
    triangle_control_points_from_samples, triangle_squared_l2_distance, triangle_true_degree,
    true_degree,
};
use blossom::{BezierCurve, ErrorKind, Rational, Reduction, Ring, TensorPatch, TriangularPatch};
use num_bigint::BigInt;

type Net = Vec<Vec<Vec<Rational>>>;

fn random_tensor(rng: &mut Rng, (n, m): (usize, usize), dim: usize) -> TensorPatch<Rational> {
    let net: Net = (0..=n)
        .map(|_| (0..=m).map(|_| rng.point(dim)).collect())
        .collect();
    TensorPatch::new(net).unwrap()
}

fn random_triangle(rng: &mut Rng, n: usize, dim: usize) -> TriangularPatch<Rational> {
    TriangularPatch::new(n, (0..triangle_len(n)).map(|_| rng.point(dim)).collect()).unwrap()
}

/// A rational in [0, 1] with denominator up to 12.
fn unit(rng: &mut Rng) -> Rational {
    let d = (rng.next() % 12) as i64 + 1;
    q((rng.next() % (d as u64 + 1)) as i64, d)
}

fn factorial(n: usize) -> BigInt {
    (1..=n).map(BigInt::from).product()
}

// ---------------------------------------------------------------------------------------------
// Power forms and their exact integrals, independent of the Gram matrices.

/// A scalar polynomial sum c u^i v^j as its terms.
type Poly2 = Vec<((usize, usize), Rational)>;

/// The power form of coordinate `d` of a tensor patch (per variable `bernstein_to_power`).
fn tensor_power(p: &TensorPatch<Rational>, d: usize) -> Poly2 {
    let m = p.degree().1;
    // Along v for each row, then along u for each power of v.
    let rows: Vec<Vec<Vec<Rational>>> = p
        .to_nested()
        .iter()
        .map(|row| {
            let col: Vec<Vec<Rational>> = row.iter().map(|x| vec![x[d].clone()]).collect();
            bernstein_to_power(&col)
        })
        .collect();
    let mut out = Vec::new();
    for j in 0..=m {
        let col: Vec<Vec<Rational>> = rows.iter().map(|r| r[j].clone()).collect();
        for (i, c) in bernstein_to_power(&col).into_iter().enumerate() {
            out.push(((i, j), c[0].clone()));
        }
    }
    out
}

/// The power form in (u, v) = (s, t) of coordinate `d` of a triangular patch.
fn triangle_power(p: &TriangularPatch<Rational>, d: usize) -> Poly2 {
    let n = p.degree();
    let c = triangle_bernstein_to_power(p).to_nested().concat();
    (0..=n)
        .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
        .map(|(i, j)| ((i, j), c[triangle_index(n, i, j)][d].clone()))
        .collect()
}

/// int_0^1 int_0^1 u^i v^j du dv.
fn square_monomial(i: usize, j: usize) -> Rational {
    q(1, ((i + 1) * (j + 1)) as i64)
}

/// int_T u^i v^j du dv over the unit triangle = i! j! / (i + j + 2)!.
fn triangle_monomial(i: usize, j: usize) -> Rational {
    Rational::new(factorial(i) * factorial(j), factorial(i + j + 2))
}

/// int f g of two power forms, monomial by monomial.
fn inner(f: &Poly2, g: &Poly2, monomial: fn(usize, usize) -> Rational) -> Rational {
    let mut acc = Rational::zero();
    for ((i, j), a) in f {
        for ((k, l), b) in g {
            acc += a * b * monomial(i + k, j + l);
        }
    }
    acc
}

fn minus(f: &Poly2, g: &Poly2) -> Poly2 {
    let mut out = f.clone();
    out.extend(g.iter().map(|(e, c)| (*e, -c)));
    out
}

/// The tensor basis patch B_i^n(u) B_j^m(v) (one coordinate).
fn tensor_basis((n, m): (usize, usize), (i, j): (usize, usize)) -> TensorPatch<Rational> {
    TensorPatch::new(
        (0..=n)
            .map(|a| {
                (0..=m)
                    .map(|b| vec![q((a == i && b == j) as i64, 1)])
                    .collect()
            })
            .collect(),
    )
    .unwrap()
}

/// The triangular basis patch B_k^n, k the lexicographic index (one coordinate).
fn triangle_basis(n: usize, k: usize) -> TriangularPatch<Rational> {
    TriangularPatch::new(
        n,
        (0..triangle_len(n))
            .map(|c| vec![q((c == k) as i64, 1)])
            .collect(),
    )
    .unwrap()
}

/// int over [0, 1]^2 of |a - b|^2 from the power forms.
fn tensor_l2_by_power(a: &TensorPatch<Rational>, b: &TensorPatch<Rational>) -> Rational {
    (0..a.to_nested()[0][0].len())
        .map(|d| {
            let r = minus(&tensor_power(a, d), &tensor_power(b, d));
            inner(&r, &r, square_monomial)
        })
        .sum()
}

fn triangle_l2_by_power(a: &TriangularPatch<Rational>, b: &TriangularPatch<Rational>) -> Rational {
    (0..a.control_points()[0].len())
        .map(|d| {
            let r = minus(&triangle_power(a, d), &triangle_power(b, d));
            inner(&r, &r, triangle_monomial)
        })
        .sum()
}

fn tensor_corners(p: &TensorPatch<Rational>) -> [Vec<Rational>; 4] {
    let (n, m) = p.degree();
    let c = p.to_nested();
    [
        c[0][0].clone(),
        c[0][m].clone(),
        c[n][0].clone(),
        c[n][m].clone(),
    ]
}

fn triangle_corners(p: &TriangularPatch<Rational>) -> [Vec<Rational>; 3] {
    let n = p.degree();
    [
        p.get(n, 0).to_vec(),
        p.get(0, n).to_vec(),
        p.get(0, 0).to_vec(),
    ]
}

// ---------------------------------------------------------------------------------------------
// Elevation.

#[test]
fn tensor_elevation_evaluates_like_the_original() {
    let mut rng = Rng(400);
    for (n, m) in [(0, 0), (1, 0), (0, 2), (1, 1), (2, 3), (3, 2), (4, 1)] {
        let p = random_tensor(&mut rng, (n, m), 2);
        for (a, b) in [(0, 0), (1, 0), (0, 2), (2, 3)] {
            let e = elevate_tensor(&p, (n + a, m + b)).unwrap();
            assert_eq!(e.degree(), (n + a, m + b));
            for _ in 0..8 {
                let (u, v) = (unit(&mut rng), unit(&mut rng));
                assert_eq!(e.eval(&u, &v), p.eval(&u, &v), "({n},{m}) + ({a},{b})");
            }
            // The inverse formula at the higher bidegree has elevation built in (eq. (22)).
            let rect = [q(0, 1), q(1, 1), q(0, 1), q(1, 1)];
            let built_in =
                tensor_control_points_from_samples((n + a, m + b), &rect, &|u, v| p.eval(u, v));
            assert_eq!(e.to_nested(), built_in.as_slice());
        }
    }
}

#[test]
fn triangle_elevation_evaluates_like_the_original() {
    let mut rng = Rng(401);
    let tri = [[q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], [q(0, 1), q(0, 1)]];
    for n in 0..=4 {
        let p = random_triangle(&mut rng, n, 2);
        for k in 0..=3 {
            let e = elevate_triangle(&p, n + k).unwrap();
            for _ in 0..8 {
                let (s, t) = (unit(&mut rng), unit(&mut rng));
                // Any point of the plane, inside the triangle or not.
                assert_eq!(
                    e.eval(&[s.clone(), t.clone()]),
                    p.eval(&[s.clone(), t.clone()]),
                    "{n} + {k}"
                );
            }
            let built_in = triangle_control_points_from_samples(n + k, &tri, &|u, v| {
                p.eval(&[u.clone(), v.clone()])
            });
            assert_eq!(
                e.control_points(),
                built_in.as_slice(),
                "eq. (23) {n} + {k}"
            );
        }
    }
}

/// One step of triangle elevation, written here: b'_ijk = (i b_(i-1)jk + j b_i(j-1)k
/// + k b_ij(k-1)) / (N + 1).
fn elevate_once(p: &TriangularPatch<Rational>) -> TriangularPatch<Rational> {
    let n = p.degree();
    let dim = p.control_points()[0].len();
    let mut out = Vec::new();
    for i in 0..=n + 1 {
        for j in 0..=n + 1 - i {
            let k = n + 1 - i - j;
            let mut acc = vec![Rational::zero(); dim];
            let mut add = |w: usize, x: &[Rational]| {
                for (a, y) in acc.iter_mut().zip(x) {
                    *a += y * Rational::from_integer(w.into());
                }
            };
            if i > 0 {
                add(i, p.get(i - 1, j));
            }
            if j > 0 {
                add(j, p.get(i, j - 1));
            }
            if k > 0 {
                add(k, p.get(i, j));
            }
            out.push(
                acc.iter()
                    .map(|a| a / Rational::from_integer((n + 1).into()))
                    .collect(),
            );
        }
    }
    TriangularPatch::new(n + 1, out).unwrap()
}

#[test]
fn triangle_elevation_by_multinomials_is_repeated_degree_one_elevation() {
    let mut rng = Rng(402);
    for n in 0..=4 {
        let p = random_triangle(&mut rng, n, 3);
        let mut stepped = p.clone();
        for k in 0..=4 {
            assert_eq!(
                elevate_triangle(&p, n + k).unwrap(),
                stepped,
                "{n} -> {}",
                n + k
            );
            stepped = elevate_once(&stepped);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Reduction.

#[test]
fn every_patch_reduction_reproduces_patches_of_the_lower_degree() {
    let mut rng = Rng(403);
    for (low, high) in [
        ((1, 1), (2, 2)),
        ((1, 2), (3, 2)),
        ((2, 1), (2, 4)),
        ((2, 2), (3, 3)),
        ((1, 3), (3, 4)),
        ((0, 2), (0, 3)),
    ] {
        let p = random_tensor(&mut rng, low, 2);
        let e = elevate_tensor(&p, high).unwrap();
        for method in Reduction::ALL {
            assert_eq!(
                reduce_tensor(&e, low, method).unwrap(),
                p,
                "{method:?} {low:?} <- {high:?}"
            );
        }
    }
    for low in 1..=3 {
        let p = random_triangle(&mut rng, low, 2);
        for high in low + 1..=low + 2 {
            let e = elevate_triangle(&p, high).unwrap();
            for method in Reduction::ALL {
                assert_eq!(
                    reduce_triangle(&e, low, method).unwrap(),
                    p,
                    "{method:?} {low} <- {high}"
                );
            }
        }
    }
    // Degree 0 by least squares: the constants.
    let c = random_tensor(&mut rng, (0, 0), 2);
    let e = elevate_tensor(&c, (2, 3)).unwrap();
    assert_eq!(
        reduce_tensor(&e, (0, 0), Reduction::LeastSquares).unwrap(),
        c
    );
    let c = random_triangle(&mut rng, 0, 2);
    let e = elevate_triangle(&c, 3).unwrap();
    assert_eq!(reduce_triangle(&e, 0, Reduction::LeastSquares).unwrap(), c);
}

#[test]
fn gram_matrices_are_power_form_integrals() {
    for (a, b) in [((0, 0), (1, 2)), ((2, 1), (1, 3)), ((2, 2), (3, 3))] {
        let g = tensor_bernstein_gram(a, b);
        for i in 0..=a.0 {
            for j in 0..=a.1 {
                let f = tensor_power(&tensor_basis(a, (i, j)), 0);
                for k in 0..=b.0 {
                    for l in 0..=b.1 {
                        let h = tensor_power(&tensor_basis(b, (k, l)), 0);
                        assert_eq!(
                            g[i * (a.1 + 1) + j][k * (b.1 + 1) + l],
                            inner(&f, &h, square_monomial),
                            "{a:?} {b:?}"
                        );
                    }
                }
            }
        }
    }
    for (m, n) in [(0, 0), (0, 2), (1, 3), (2, 2), (3, 4)] {
        let g = triangle_bernstein_gram(m, n);
        for (i, row) in g.iter().enumerate() {
            let f = triangle_power(&triangle_basis(m, i), 0);
            for (j, x) in row.iter().enumerate() {
                let h = triangle_power(&triangle_basis(n, j), 0);
                assert_eq!(*x, inner(&f, &h, triangle_monomial), "{m} {n} [{i}][{j}]");
            }
        }
    }
}

#[test]
fn tensor_least_squares_are_orthogonal_and_keep_the_corners() {
    let mut rng = Rng(404);
    for (from, to) in [
        ((2, 2), (1, 1)),
        ((3, 3), (2, 2)),
        ((3, 2), (1, 2)),
        ((2, 4), (2, 2)),
    ] {
        let b = random_tensor(&mut rng, from, 2);
        let ls = reduce_tensor(&b, to, Reduction::LeastSquares).unwrap();
        let lse = reduce_tensor(&b, to, Reduction::LeastSquaresEndpoints).unwrap();
        let interp = reduce_tensor(&b, to, Reduction::Interpolating).unwrap();
        let corners = [(0, 0), (0, to.1), (to.0, 0), (to.0, to.1)];
        for d in 0..2 {
            let (rl, rle) = (
                minus(&tensor_power(&ls, d), &tensor_power(&b, d)),
                minus(&tensor_power(&lse, d), &tensor_power(&b, d)),
            );
            for i in 0..=to.0 {
                for j in 0..=to.1 {
                    let basis = tensor_power(&tensor_basis(to, (i, j)), 0);
                    assert!(
                        inner(&rl, &basis, square_monomial).is_zero(),
                        "{from:?}->{to:?}"
                    );
                    if !corners.contains(&(i, j)) {
                        assert!(inner(&rle, &basis, square_monomial).is_zero());
                    }
                }
            }
        }
        assert_eq!(tensor_corners(&lse), tensor_corners(&b));
        assert_eq!(tensor_corners(&interp), tensor_corners(&b));
        let err = |p: &TensorPatch<Rational>| tensor_squared_l2_distance(p, &b).unwrap();
        assert!(
            err(&ls) <= err(&lse) && err(&lse) <= err(&interp),
            "{from:?}->{to:?}"
        );
        assert!(
            err(&ls) < err(&lse),
            "random input: the corners cost something"
        );
        // The unconstrained optimum is separable: the curve reduction along u, then along v.
        let rows: Vec<Vec<Vec<Rational>>> = b
            .to_nested()
            .iter()
            .map(|row| {
                let c = BezierCurve::new(row.clone()).unwrap();
                let r = if to.1 < from.1 {
                    reduce(&c, to.1, Reduction::LeastSquares).unwrap()
                } else {
                    c
                };
                r.into_control_points()
            })
            .collect();
        let sep: Net = if to.0 < from.0 {
            let cols: Vec<Vec<Vec<Rational>>> = (0..=to.1)
                .map(|j| {
                    let c = BezierCurve::new(rows.iter().map(|r| r[j].clone()).collect()).unwrap();
                    reduce(&c, to.0, Reduction::LeastSquares)
                        .unwrap()
                        .into_control_points()
                })
                .collect();
            (0..=to.0)
                .map(|i| cols.iter().map(|c| c[i].clone()).collect())
                .collect()
        } else {
            rows
        };
        assert_eq!(ls.to_nested(), sep.as_slice());
    }
}

#[test]
fn triangle_least_squares_are_orthogonal_and_keep_the_corners() {
    let mut rng = Rng(405);
    for (from, to) in [(2, 1), (3, 1), (3, 2), (4, 2), (5, 3)] {
        let b = random_triangle(&mut rng, from, 2);
        let ls = reduce_triangle(&b, to, Reduction::LeastSquares).unwrap();
        let lse = reduce_triangle(&b, to, Reduction::LeastSquaresEndpoints).unwrap();
        let interp = reduce_triangle(&b, to, Reduction::Interpolating).unwrap();
        let corners = [
            triangle_index(to, to, 0),
            triangle_index(to, 0, to),
            triangle_index(to, 0, 0),
        ];
        for d in 0..2 {
            let rl = minus(&triangle_power(&ls, d), &triangle_power(&b, d));
            let rle = minus(&triangle_power(&lse, d), &triangle_power(&b, d));
            for k in 0..triangle_len(to) {
                let basis = triangle_power(&triangle_basis(to, k), 0);
                assert!(
                    inner(&rl, &basis, triangle_monomial).is_zero(),
                    "{from}->{to}"
                );
                if !corners.contains(&k) {
                    assert!(inner(&rle, &basis, triangle_monomial).is_zero());
                }
            }
        }
        assert_eq!(triangle_corners(&lse), triangle_corners(&b));
        assert_eq!(triangle_corners(&interp), triangle_corners(&b));
        let err = |p: &TriangularPatch<Rational>| triangle_squared_l2_distance(p, &b).unwrap();
        assert!(
            err(&ls) < err(&lse) && err(&lse) <= err(&interp),
            "{from}->{to}"
        );
        // Moving any control point of the free optimum makes it worse.
        for k in 0..triangle_len(to) {
            let mut pts = ls.control_points().to_vec();
            pts[k][0] += q(1, 1000);
            assert!(err(&TriangularPatch::new(to, pts).unwrap()) > err(&ls));
        }
    }
}

#[test]
fn squared_l2_distances_are_power_form_integrals() {
    let mut rng = Rng(406);
    for (a, b) in [((0, 0), (1, 1)), ((2, 1), (1, 3)), ((3, 3), (2, 2))] {
        let (pa, pb) = (random_tensor(&mut rng, a, 2), random_tensor(&mut rng, b, 2));
        let e = tensor_squared_l2_distance(&pa, &pb).unwrap();
        assert_eq!(e, tensor_l2_by_power(&pa, &pb));
        assert_eq!(e, tensor_squared_l2_distance(&pb, &pa).unwrap());
        assert!(tensor_squared_l2_distance(&pa, &pa).unwrap().is_zero());
    }
    for (a, b) in [(0, 1), (2, 2), (3, 1), (4, 2)] {
        let (pa, pb) = (
            random_triangle(&mut rng, a, 3),
            random_triangle(&mut rng, b, 3),
        );
        let e = triangle_squared_l2_distance(&pa, &pb).unwrap();
        assert_eq!(e, triangle_l2_by_power(&pa, &pb));
        assert_eq!(e, triangle_squared_l2_distance(&pb, &pa).unwrap());
    }
    // Means by hand: the best constant for u v over the square is 1/4, for u + v over the
    // triangle 2/3 (twice the integral 1/3 over the area 1/2).
    let uv = TensorPatch::new(vec![
        vec![vec![q(0, 1)], vec![q(0, 1)]],
        vec![vec![q(0, 1)], vec![q(1, 1)]],
    ])
    .unwrap();
    let mean = reduce_tensor(&uv, (0, 0), Reduction::LeastSquares).unwrap();
    assert_eq!(mean.to_nested(), &[vec![vec![q(1, 4)]]]);
    let sum = TriangularPatch::new(1, vec![vec![q(0, 1)], vec![q(1, 1)], vec![q(1, 1)]]).unwrap();
    let mean = reduce_triangle(&sum, 0, Reduction::LeastSquares).unwrap();
    assert_eq!(mean.control_points(), &[vec![q(2, 3)]]);
}

#[test]
fn floats_follow_the_exact_patch_reductions() {
    let mut rng = Rng(407);
    let to_f = |x: &Rational| blossom::rational_to_f64(x);
    let close = |x: &Rational, y: &f64| (to_f(x) - y).abs() < 1e-9 * (1.0 + y.abs());
    let t = random_tensor(&mut rng, (4, 3), 3);
    let tf = TensorPatch::new(
        t.to_nested()
            .iter()
            .map(|r| r.iter().map(|p| p.iter().map(to_f).collect()).collect())
            .collect(),
    )
    .unwrap();
    let s = random_triangle(&mut rng, 4, 3);
    let sf = TriangularPatch::new(
        4,
        s.control_points()
            .iter()
            .map(|p| p.iter().map(to_f).collect())
            .collect(),
    )
    .unwrap();
    for method in Reduction::ALL {
        let (exact, float) = (
            reduce_tensor(&t, (2, 2), method).unwrap(),
            reduce_tensor(&tf, (2, 2), method).unwrap(),
        );
        for (r, rf) in exact.to_nested().iter().zip(&float.to_nested()) {
            for (p, pf) in r.iter().zip(rf) {
                assert!(p.iter().zip(pf).all(|(x, y)| close(x, y)), "{method:?}");
            }
        }
        let (exact, float) = (
            reduce_triangle(&s, 2, method).unwrap(),
            reduce_triangle(&sf, 2, method).unwrap(),
        );
        for (p, pf) in exact.control_points().iter().zip(float.control_points()) {
            assert!(p.iter().zip(pf).all(|(x, y)| close(x, y)), "{method:?}");
        }
    }
    let e = elevate_triangle(&sf, 6).unwrap();
    assert!(triangle_squared_l2_distance(&e, &sf).unwrap().abs() < 1e-12);
}

// ---------------------------------------------------------------------------------------------
// True degree.

#[test]
fn true_degrees_of_elevated_low_degree_objects() {
    let mut rng = Rng(408);
    for m in 0..=3 {
        let c = BezierCurve::new((0..=m).map(|_| rng.point(2)).collect()).unwrap();
        assert_eq!(
            true_degree(&c),
            (m, c.clone()),
            "random curves are of full degree"
        );
        for n in m + 1..=m + 3 {
            assert_eq!(true_degree(&elevate(&c, n).unwrap()), (m, c.clone()));
        }
    }
    for low in [(0, 0), (1, 0), (0, 2), (1, 1), (2, 1), (1, 3)] {
        let p = random_tensor(&mut rng, low, 2);
        assert_eq!(tensor_true_degree(&p), (low, p.clone()));
        for high in [
            (low.0 + 1, low.1),
            (low.0, low.1 + 2),
            (low.0 + 2, low.1 + 1),
        ] {
            let e = elevate_tensor(&p, high).unwrap();
            assert_eq!(
                tensor_true_degree(&e),
                (low, p.clone()),
                "{low:?} <- {high:?}"
            );
        }
    }
    for low in 0..=3 {
        let p = random_triangle(&mut rng, low, 2);
        assert_eq!(triangle_true_degree(&p), (low, p.clone()));
        for high in low + 1..=low + 2 {
            let e = elevate_triangle(&p, high).unwrap();
            assert_eq!(
                triangle_true_degree(&e),
                (low, p.clone()),
                "{low} <- {high}"
            );
        }
    }
    // u + v at degree 2 (written by hand: q_200 = q_020 = q_110 = 1, q_101 = q_011 = 1/2,
    // q_002 = 0) is of degree 1.
    let uv2 = TriangularPatch::new(
        2,
        vec![
            vec![q(0, 1)],
            vec![q(1, 2)],
            vec![q(1, 1)],
            vec![q(1, 2)],
            vec![q(1, 1)],
            vec![q(1, 1)],
        ],
    )
    .unwrap();
    let (d, low) = triangle_true_degree(&uv2);
    assert_eq!(d, 1);
    assert_eq!(
        low.control_points(),
        &[vec![q(0, 1)], vec![q(1, 1)], vec![q(1, 1)]]
    );
    // A patch quadratic in u only and linear in v, with one control point moved off it, is of
    // full bidegree again.
    let p = random_tensor(&mut rng, (2, 1), 1);
    let mut net = elevate_tensor(&p, (3, 3)).unwrap().into_control_points();
    net[1][2][0] += q(1, 1);
    assert_eq!(
        tensor_true_degree(&TensorPatch::new(net).unwrap()).0,
        (3, 3)
    );
}

// ---------------------------------------------------------------------------------------------
// Bad input.

#[test]
fn bad_degrees_and_shapes_are_errors() {
    let mut rng = Rng(409);
    let t = random_tensor(&mut rng, (2, 3), 2);
    let s = random_triangle(&mut rng, 3, 2);
    let degree = |e: blossom::Error| {
        assert_eq!(
            (e.kind(), e.path()),
            (ErrorKind::Degree, "to_degree"),
            "{e}"
        );
    };
    // Elevation to a lower degree, or a degree too large to count.
    degree(elevate_tensor(&t, (1, 3)).unwrap_err());
    degree(elevate_tensor(&t, (2, 2)).unwrap_err());
    degree(elevate_tensor(&t, (usize::MAX, 3)).unwrap_err());
    degree(elevate_tensor(&t, (1 << 40, 1 << 40)).unwrap_err());
    degree(elevate_triangle(&s, 2).unwrap_err());
    degree(triangle_elevation_matrix(3, 2).unwrap_err());
    degree(elevate_triangle(&s, usize::MAX).unwrap_err());
    degree(elevate_triangle(&s, usize::MAX / 2).unwrap_err());
    for method in Reduction::ALL {
        // Higher in one variable, or no lower in either.
        degree(reduce_tensor(&t, (3, 2), method).unwrap_err());
        degree(reduce_tensor(&t, (2, 3), method).unwrap_err());
        degree(reduce_triangle(&s, 3, method).unwrap_err());
        degree(reduce_triangle(&s, 4, method).unwrap_err());
    }
    // Degree 0 where the degree drops: only least squares can.
    for method in [Reduction::Interpolating, Reduction::LeastSquaresEndpoints] {
        degree(reduce_tensor(&t, (0, 3), method).unwrap_err());
        degree(reduce_tensor(&t, (1, 0), method).unwrap_err());
        degree(reduce_triangle(&s, 0, method).unwrap_err());
    }
    degree(
        tensor_least_squares_matrix((2, 3), (0, 1), Reduction::LeastSquaresEndpoints).unwrap_err(),
    );
    degree(triangle_least_squares_matrix(3, 0, Reduction::LeastSquaresEndpoints).unwrap_err());
    degree(least_squares_matrix(3, 0, Reduction::LeastSquaresEndpoints).unwrap_err());
    assert!(reduce_tensor(&t, (0, 0), Reduction::LeastSquares).is_ok());
    assert!(reduce_triangle(&s, 0, Reduction::LeastSquares).is_ok());
    // A variable of degree 0 in both stays at 0 for every method.
    let flat = random_tensor(&mut rng, (0, 3), 2);
    for method in Reduction::ALL {
        assert_eq!(
            reduce_tensor(&flat, (0, 2), method).unwrap().degree(),
            (0, 2)
        );
    }
    // The interpolating method has no matrix.
    for e in [
        tensor_least_squares_matrix((2, 3), (1, 1), Reduction::Interpolating).unwrap_err(),
        triangle_least_squares_matrix(3, 1, Reduction::Interpolating).unwrap_err(),
    ] {
        assert_eq!((e.kind(), e.path()), (ErrorKind::Invalid, "method"));
    }
    // Distances between patches of different dimensions.
    let t1 = random_tensor(&mut rng, (1, 1), 1);
    let s3 = random_triangle(&mut rng, 2, 3);
    for e in [
        tensor_squared_l2_distance(&t, &t1).unwrap_err(),
        triangle_squared_l2_distance(&s, &s3).unwrap_err(),
    ] {
        assert_eq!(
            (e.kind(), e.path()),
            (ErrorKind::Dimension, "control_points")
        );
    }
    // Empty and misshapen nets never reach the functions: the constructors refuse them.
    let e = TensorPatch::<Rational>::new(vec![]).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Empty, "control_points"));
    let e = TensorPatch::new(vec![vec![vec![q(1, 1)]], vec![]]).unwrap_err();
    assert_eq!(
        (e.kind(), e.path()),
        (ErrorKind::Shape, "control_points[1]")
    );
    let e = TriangularPatch::new(2, vec![vec![q(1, 1)]; 5]).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Shape, "control_points"));
}

// ---------------------------------------------------------------------------------------------
// The figures: two reductions with their exact errors.

#[test]
fn patch_reductions_snapshot() {
    // The graph (u, v, u^3 v^3) of bidegree (3, 3): p_ij = (i/3, j/3, [i = j = 3]).
    let cubic = TensorPatch::new(
        (0..=3)
            .map(|i| {
                (0..=3)
                    .map(|j| vec![q(i, 3), q(j, 3), q((i == 3 && j == 3) as i64, 1)])
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    // The graph (u, v, u^2 v) over the unit triangle at degree 3: q_ijk = (i/3, j/3, z) with
    // z = 1/3 at (2, 1, 0) (u^2 v = s^2 t = B_210 / 3), else 0.
    let graph = TriangularPatch::new(
        3,
        (0..=3i64)
            .flat_map(|i| (0..=3 - i).map(move |j| (i, j)))
            .map(|(i, j)| {
                vec![
                    q(i, 3),
                    q(j, 3),
                    if (i, j) == (2, 1) { q(1, 3) } else { q(0, 1) },
                ]
            })
            .collect(),
    )
    .unwrap();
    let mut tensor = Vec::new();
    let mut triangle = Vec::new();
    for method in Reduction::ALL {
        let r = reduce_tensor(&cubic, (2, 2), method).unwrap();
        let e = tensor_squared_l2_distance(&r, &cubic).unwrap();
        assert_eq!(e, tensor_l2_by_power(&r, &cubic));
        tensor.push((method, r, e));
        let r = reduce_triangle(&graph, 2, method).unwrap();
        let e = triangle_squared_l2_distance(&r, &graph).unwrap();
        assert_eq!(e, triangle_l2_by_power(&r, &graph));
        triangle.push((method, r, e));
    }
    // By hand. Square: the best quadratic for u^3 misses it by ||P_3||^2 / 20^2 = 1/2800
    // (P_3 = 20u^3 - 30u^2 + 12u - 1, the shifted Legendre polynomial), so the separable optimum
    // errs by (1/7)^2 - (1/7 - 1/2800)^2 = 799/7840000; interpolation at 0, 1/2, 1 gives
    // I(u) = (3u^2 - u)/2 and ||u^3 v^3 - I(u) I(v)||^2 = 1/49 - 2 (3/20)^2 + (19/120)^2
    // = 337/705600. Triangle: interpolation at the corners and edge midpoints gives u v / 2, and
    // int_T (u^2 v - u v / 2)^2 = 1/840 - 1/420 + 1/720 = 1/5040.
    assert_eq!(tensor[0].2, q(337, 705600));
    assert_eq!(tensor[1].2, q(799, 7840000));
    assert_eq!(triangle[0].2, q(1, 5040));
    let coords = |p: &[Rational]| Json::strings(p);
    let figure = |m: Reduction, pts: Json, e: &Rational| {
        Json::object([
            ("method", Json::string(m.name())),
            ("control_points", pts),
            ("squared_l2_error", Json::string(e)),
            (
                "squared_l2_error_approx",
                Json::string(format!("{:.6e}", blossom::rational_to_f64(e))),
            ),
        ])
    };
    let value = Json::object([
        (
            "tensor (u, v, u^3 v^3), (3, 3) -> (2, 2), over [0, 1]^2",
            Json::array(tensor.iter().map(|(m, r, e)| {
                figure(
                    *m,
                    Json::array(
                        r.to_nested()
                            .iter()
                            .map(|row| Json::array(row.iter().map(|p| coords(p)))),
                    ),
                    e,
                )
            })),
        ),
        (
            "triangle (u, v, u^2 v), 3 -> 2, over the unit triangle",
            Json::array(triangle.iter().map(|(m, r, e)| {
                figure(*m, Json::array(r.control_points().iter().map(&coords)), e)
            })),
        ),
    ]);
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("patch_degree_reductions", value.pretty());
    });
}
