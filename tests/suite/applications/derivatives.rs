//! Derivatives through the blossom with vector arguments, checked against differentiation of
//! the power form (an independent route: the coefficients i c_i of the derivative, restricted
//! by `Method::Definition` or `Method::ClosedForm`), against the forward-difference formula of
//! the CLI contract, and in f64 against the exact answer of the same f64 inputs.

use crate::common::{exact, q, Rng};
use blossom::engine::{
    bernstein_to_power, triangle_bernstein_to_power, triangle_index, triangle_power_to_bernstein,
};
use blossom::{
    bezier_derivative, bezier_tensor_derivative, bezier_triangle_derivative,
    power_curve_derivative, power_tensor_derivative, power_triangle_derivative,
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, BezierCurve,
    ErrorKind, Method, PowerCurve, PowerSurface, PowerTriangle, Rational, TensorPatch,
    TriangularPatch,
};

type Pt = Vec<Rational>;

fn bezier_curve(rng: &mut Rng, n: usize, dim: usize) -> BezierCurve<Rational> {
    BezierCurve::new((0..=n).map(|_| rng.point(dim)).collect()).unwrap()
}

fn tensor_patch(rng: &mut Rng, n: usize, m: usize, dim: usize) -> TensorPatch<Rational> {
    TensorPatch::new(
        (0..=n)
            .map(|_| (0..=m).map(|_| rng.point(dim)).collect())
            .collect(),
    )
    .unwrap()
}

fn triangular_patch(rng: &mut Rng, n: usize, dim: usize) -> TriangularPatch<Rational> {
    let len = (n + 1) * (n + 2) / 2;
    TriangularPatch::new(n, (0..len).map(|_| rng.point(dim)).collect()).unwrap()
}

fn times(p: &[Rational], k: &Rational) -> Pt {
    p.iter().map(|x| x * k).collect()
}

fn plus(p: &[Rational], r: &[Rational]) -> Pt {
    p.iter().zip(r).map(|(x, y)| x + y).collect()
}

/// (i + 1)(i + 2)...(i + k): the factor of c_(i+k) in the k-th derivative's c_i.
fn rising(i: usize, k: usize) -> Rational {
    (i + 1..=i + k).fold(q(1, 1), |acc, f| acc * q(f as i64, 1))
}

/// The power coefficients of the k-th derivative of sum c_i u^i.
fn differentiate(c: &[Pt], k: usize) -> Vec<Pt> {
    (0..c.len() - k)
        .map(|i| times(&c[i + k], &rising(i, k)))
        .collect()
}

/// The power coefficients of d^(k+l) / du^k dv^l of sum c_ij u^i v^j.
fn differentiate_grid(c: &[Vec<Pt>], [k, l]: [usize; 2]) -> Vec<Vec<Pt>> {
    (0..c.len() - k)
        .map(|i| {
            (0..c[0].len() - l)
                .map(|j| times(&c[i + k][j + l], &(rising(i, k) * rising(j, l))))
                .collect()
        })
        .collect()
}

/// The power grid of a Bézier tensor patch over [0, 1]^2: the curve conversion along u with
/// whole rows as points, then along v in every row.
fn tensor_to_power(patch: &TensorPatch<Rational>) -> Vec<Vec<Pt>> {
    let dim = patch.to_nested()[0][0].len();
    let rows: Vec<Pt> = patch.to_nested().iter().map(|r| r.concat()).collect();
    bernstein_to_power(&rows)
        .iter()
        .map(|row| {
            let points: Vec<Pt> = row.chunks(dim).map(<[Rational]>::to_vec).collect();
            bernstein_to_power(&points)
        })
        .collect()
}

/// n!/(n-k)! Delta^k b_i for every i, computed directly from the definition of the forward
/// differences.
fn forward_difference_formula(b: &[Pt], k: usize) -> Vec<Pt> {
    let n = b.len() - 1;
    let mut level = b.to_vec();
    for _ in 0..k {
        level = level
            .windows(2)
            .map(|w| w[1].iter().zip(&w[0]).map(|(y, x)| y - x).collect())
            .collect();
    }
    let factor = (n - k + 1..=n).fold(q(1, 1), |acc, f| acc * q(f as i64, 1));
    level.iter().map(|p| times(p, &factor)).collect()
}

#[test]
fn bezier_curve_derivatives_are_the_forward_difference_formula() {
    let mut rng = Rng(700);
    for n in 0..=12 {
        let dim = 1 + n % 3;
        let b = bezier_curve(&mut rng, n, dim);
        for k in 0..=n {
            let d = bezier_derivative(&b, k).unwrap();
            assert_eq!(d.degree(), n - k);
            assert_eq!(
                d.control_points(),
                forward_difference_formula(&b.control_points().to_vec(), k).as_slice(),
                "n={n} k={k}"
            );
        }
        assert_eq!(bezier_derivative(&b, 0).unwrap(), b);
        let e = bezier_derivative(&b, n + 1).unwrap_err();
        assert_eq!((e.kind(), e.path()), (ErrorKind::Degree, "order"));
    }
    // Random degrees and orders as well.
    for _ in 0..20 {
        let n = (rng.next() % 13) as usize;
        let k = (rng.next() % (n as u64 + 1)) as usize;
        let b = bezier_curve(&mut rng, n, 2);
        assert_eq!(
            bezier_derivative(&b, k).unwrap().control_points(),
            forward_difference_formula(&b.control_points().to_vec(), k).as_slice()
        );
    }
}

#[test]
fn bezier_curve_derivatives_match_power_differentiation() {
    let mut rng = Rng(701);
    for n in 0..=10 {
        let b = bezier_curve(&mut rng, n, 2);
        let c = bernstein_to_power(&b.control_points().to_vec());
        for k in 0..=n {
            let power = PowerCurve::new(differentiate(&c, k)).unwrap();
            let want = restrict_power_curve(&power, &q(0, 1), &q(1, 1), Method::Definition);
            assert_eq!(bezier_derivative(&b, k).unwrap(), want, "n={n} k={k}");
        }
    }
}

#[test]
fn power_curve_derivatives_match_power_differentiation() {
    let mut rng = Rng(702);
    for n in 0..=12 {
        let curve = rng.curve(n, 2);
        let (a, b) = (rng.rational(), rng.rational());
        for k in 0..=n {
            let power = PowerCurve::new(differentiate(&curve.coefficients().to_vec(), k)).unwrap();
            let method = [Method::Definition, Method::ClosedForm][k % 2];
            let want = restrict_power_curve(&power, &a, &b, method);
            let got = power_curve_derivative(&curve, k, &a, &b).unwrap();
            assert_eq!(got, want, "n={n} k={k} [{a}, {b}]");
        }
        let e = power_curve_derivative(&curve, n + 1, &a, &b).unwrap_err();
        assert_eq!((e.kind(), e.path()), (ErrorKind::Degree, "order"));
    }
}

#[test]
fn tensor_derivatives_match_power_differentiation() {
    let mut rng = Rng(703);
    for (n, m) in [(0, 0), (1, 0), (0, 2), (2, 3), (4, 2), (3, 5)] {
        let patch = tensor_patch(&mut rng, n, m, 2);
        let from_bezier = tensor_to_power(&patch);
        let surface = rng.surface(n, m, 3);
        let rect = [
            rng.rational(),
            rng.rational(),
            rng.rational(),
            rng.rational(),
        ];
        let unit = [q(0, 1), q(1, 1), q(0, 1), q(1, 1)];
        for k in 0..=n {
            for l in 0..=m {
                let method = [Method::Definition, Method::ClosedForm][(k + l) % 2];
                let d = PowerSurface::new(differentiate_grid(&from_bezier, [k, l])).unwrap();
                let want = restrict_power_surface(&d, &unit, method);
                let got = bezier_tensor_derivative(&patch, [k, l]).unwrap();
                assert_eq!(got.degree(), (n - k, m - l));
                assert_eq!(got, want, "Bézier ({n}, {m}) order ({k}, {l})");

                let d =
                    PowerSurface::new(differentiate_grid(&surface.to_nested(), [k, l])).unwrap();
                let want = restrict_power_surface(&d, &rect, method);
                let got = power_tensor_derivative(&surface, [k, l], &rect).unwrap();
                assert_eq!(got, want, "power ({n}, {m}) order ({k}, {l})");
            }
        }
        for (order, path) in [([n + 1, 0], "order[0]"), ([0, m + 1], "order[1]")] {
            let e = bezier_tensor_derivative(&patch, order).unwrap_err();
            assert_eq!((e.kind(), e.path()), (ErrorKind::Degree, path));
            let e = power_tensor_derivative(&surface, order, &rect).unwrap_err();
            assert_eq!((e.kind(), e.path()), (ErrorKind::Degree, path));
        }
    }
}

/// The power coefficients (triangular, degree N - 1) of delta_s d/ds + delta_t d/dt applied to
/// sum e_ij s^i t^j of degree N (`e[triangle_index(N, i, j)]`).
fn differentiate_triangle(e: &[Pt], big_n: usize, [ds, dt]: [&Rational; 2]) -> Vec<Pt> {
    let mut out = Vec::new();
    for i in 0..big_n {
        for j in 0..big_n - i {
            let along_s = times(
                &e[triangle_index(big_n, i + 1, j)],
                &(ds * q(i as i64 + 1, 1)),
            );
            let along_t = times(
                &e[triangle_index(big_n, i, j + 1)],
                &(dt * q(j as i64 + 1, 1)),
            );
            out.push(plus(&along_s, &along_t));
        }
    }
    out
}

#[test]
fn bezier_triangle_derivatives_match_power_differentiation() {
    let mut rng = Rng(704);
    for big_n in 0..=6 {
        let patch = triangular_patch(&mut rng, big_n, 2);
        for k in 0..=big_n {
            let directions: Vec<Pt> = (0..k)
                .map(|_| {
                    let (s, t) = (rng.rational(), rng.rational());
                    let r = -(&s + &t);
                    vec![s, t, r]
                })
                .collect();
            // Differentiate the power form in the barycentric (s, t) of the first two corners,
            // then back to the Bernstein basis of the lower degree.
            let mut e = triangle_bernstein_to_power(&patch).to_nested().concat();
            for (step, d) in directions.iter().enumerate() {
                e = differentiate_triangle(&e, big_n - step, [&d[0], &d[1]]);
            }
            let array = PowerTriangle::from_coordinates(big_n - k, patch.dim(), e.concat());
            let want = triangle_power_to_bernstein(&array.unwrap()).unwrap();
            let got = bezier_triangle_derivative(&patch, &directions).unwrap();
            assert_eq!(got, want, "N={big_n} k={k}");
        }
        assert_eq!(bezier_triangle_derivative(&patch, &[]).unwrap(), patch);
    }
}

#[test]
fn power_triangle_derivatives_match_power_differentiation() {
    // D_(d_1) ... D_(d_k) = sum over subsets A of {1..k} of prod_(i in A) d_i.u
    // prod_(i not in A) d_i.v d^k / du^|A| dv^(k-|A|): each term a surface of bidegree
    // (n - |A|, m - k + |A|), i.e. of total degree N - k, restricted on its own.
    let mut rng = Rng(705);
    for (n, m) in [(0, 0), (1, 0), (0, 3), (2, 1), (2, 3), (4, 2)] {
        let surface = rng.surface(n, m, 2);
        let big_n = n + m;
        let tri = [
            [rng.rational(), rng.rational()],
            [rng.rational(), rng.rational()],
            [rng.rational(), rng.rational()],
        ];
        for k in 0..=big_n {
            let directions: Vec<Pt> = (0..k).map(|_| rng.point(2)).collect();
            let method = [Method::Definition, Method::ClosedForm][k % 2];
            let mut want: Option<Vec<Pt>> = None;
            for mask in 0u32..1 << k {
                let a = mask.count_ones() as usize;
                if a > n || k - a > m {
                    continue;
                }
                let weight = (0..k).fold(q(1, 1), |acc, i| {
                    acc * &directions[i][if mask >> i & 1 == 1 { 0 } else { 1 }]
                });
                let d = differentiate_grid(&surface.to_nested(), [a, k - a]);
                let term = restrict_power_surface_to_triangle(
                    &PowerSurface::new(d).unwrap(),
                    &tri,
                    method,
                );
                assert_eq!(term.degree(), big_n - k);
                let term: Vec<Pt> = term
                    .control_points()
                    .iter()
                    .map(|p| times(p, &weight))
                    .collect();
                want = Some(match want {
                    None => term,
                    Some(acc) => acc.iter().zip(&term).map(|(x, y)| plus(x, y)).collect(),
                });
            }
            let got = power_triangle_derivative(
                &PowerTriangle::from_surface(&surface),
                &tri,
                &directions,
            )
            .unwrap();
            assert_eq!(got.degree(), big_n - k);
            assert_eq!(
                got.control_points(),
                want.expect("some term").as_slice(),
                "({n}, {m}) k={k}"
            );
        }
    }
}

#[test]
fn bad_orders_and_directions_are_refused() {
    let mut rng = Rng(706);
    let patch = triangular_patch(&mut rng, 2, 1);
    let good = vec![q(1, 1), q(-1, 2), q(-1, 2)];
    let cases: [(Vec<Pt>, ErrorKind, &str); 5] = [
        (vec![good.clone(); 3], ErrorKind::Degree, "directions"),
        (
            vec![good.clone(), vec![q(1, 1), q(1, 1)]],
            ErrorKind::Domain,
            "directions[1]",
        ),
        (vec![vec![]], ErrorKind::Domain, "directions[0]"),
        (
            vec![vec![q(1, 1), q(0, 1), q(0, 1)]],
            ErrorKind::Domain,
            "directions[0]",
        ),
        (
            vec![good.clone(), vec![q(1, 3), q(1, 3), q(1, 3)]],
            ErrorKind::Domain,
            "directions[1]",
        ),
    ];
    for (directions, kind, path) in cases {
        let e = bezier_triangle_derivative(&patch, &directions).unwrap_err();
        assert_eq!((e.kind(), e.path()), (kind, path), "{directions:?}");
    }
    // f64: a barycentric direction must add up to exactly 0.
    let patch64 = TriangularPatch::new(1, vec![vec![1.0], vec![2.0], vec![4.0]]).unwrap();
    let e = bezier_triangle_derivative(&patch64, &[vec![0.1, 0.2, -0.3]]).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Domain, "directions[0]"));
    let d = bezier_triangle_derivative(&patch64, &[vec![0.5, 0.25, -0.75]]).unwrap();
    // 0.5 (q_100 - q_001) + 0.25 (q_010 - q_001) = 0.5 * 3 + 0.25 * 1.
    assert_eq!(d.control_points(), &[vec![1.75]]);

    let surface = rng.surface(1, 1, 2);
    let tri = [[q(0, 1), q(0, 1)], [q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)]];
    let cases: [(Vec<Pt>, ErrorKind, &str); 4] = [
        (
            vec![vec![q(1, 1), q(0, 1)]; 3],
            ErrorKind::Degree,
            "directions",
        ),
        (vec![vec![q(1, 1)]], ErrorKind::Domain, "directions[0]"),
        (
            vec![vec![q(1, 1), q(2, 1)], vec![q(1, 1), q(2, 1), q(0, 1)]],
            ErrorKind::Domain,
            "directions[1]",
        ),
        (vec![vec![]], ErrorKind::Domain, "directions[0]"),
    ];
    for (directions, kind, path) in cases {
        let e =
            power_triangle_derivative(&PowerTriangle::from_surface(&surface), &tri, &directions)
                .unwrap_err();
        assert_eq!((e.kind(), e.path()), (kind, path), "{directions:?}");
    }
    // A constant has no derivative of order 1 in these functions' convention (order <= degree).
    let constant = BezierCurve::new(vec![vec![q(3, 1)]]).unwrap();
    let e = bezier_derivative(&constant, 1).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Degree, "order"));
    // Empty input never reaches the derivatives: the shapes refuse it.
    let e = BezierCurve::<f64>::new(vec![]).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Empty, "control_points"));
    let e = PowerCurve::<f64>::new(vec![]).unwrap_err();
    assert_eq!((e.kind(), e.path()), (ErrorKind::Empty, "coefficients"));
    let e = TensorPatch::<f64>::new(vec![vec![]]).unwrap_err();
    assert_eq!(
        (e.kind(), e.path()),
        (ErrorKind::Empty, "control_points[0]")
    );
}

/// max |x - exact| / max |exact| over all coordinates: the normwise relative error of `got`.
fn relative_error(got: &[Vec<f64>], want: &[Pt]) -> f64 {
    let mut err = q(0, 1);
    let mut size = q(0, 1);
    for (g, w) in got.iter().zip(want) {
        for (x, y) in g.iter().zip(w) {
            let d = exact(*x) - y;
            let d = if d < q(0, 1) { -d } else { d };
            let y = if *y < q(0, 1) { -y.clone() } else { y.clone() };
            err = err.max(d);
            size = size.max(y);
        }
    }
    if size == q(0, 1) {
        return blossom::rational_to_f64(&err);
    }
    blossom::rational_to_f64(&(err / size))
}

fn exact_all(points: &[Vec<f64>]) -> Vec<Pt> {
    points
        .iter()
        .map(|p| p.iter().map(|&x| exact(x)).collect())
        .collect()
}

/// The exact directions of f64 directions.
fn exact_directions(directions: &[Vec<f64>]) -> Vec<Pt> {
    exact_all(directions)
}

/// The bound asserted on every relative error below: a few hundred units of roundoff.
const F64_BOUND: f64 = 1e-13;

#[test]
fn f64_curve_derivatives_are_close_to_the_exact_ones_of_the_same_inputs() {
    let mut rng = Rng(707);
    for n in [16usize, 32] {
        let mut worst = [0.0f64; 2];
        for _ in 0..2 {
            let pts: Vec<Vec<f64>> = (0..=n).map(|_| vec![rng.unit(), rng.unit()]).collect();
            let b64 = BezierCurve::new(pts.clone()).unwrap();
            let b = BezierCurve::new(exact_all(&pts)).unwrap();
            let c64 = PowerCurve::new(pts.clone()).unwrap();
            let c = PowerCurve::new(exact_all(&pts)).unwrap();
            let (a64, bb64) = (-0.375, 0.8125);
            let (a, bb) = (exact(a64), exact(bb64));
            for k in 1..=n {
                let got = bezier_derivative(&b64, k).unwrap();
                let want = bezier_derivative(&b, k).unwrap();
                worst[0] = worst[0].max(relative_error(
                    &got.control_points().to_vec(),
                    &want.control_points().to_vec(),
                ));
                if k <= 4 || k >= n - 1 || k == n / 2 {
                    let got = power_curve_derivative(&c64, k, &a64, &bb64).unwrap();
                    let want = power_curve_derivative(&c, k, &a, &bb).unwrap();
                    worst[1] = worst[1].max(relative_error(
                        &got.control_points().to_vec(),
                        &want.control_points().to_vec(),
                    ));
                }
            }
        }
        println!(
            "degree {n}: largest relative error: Bézier curve (k = 1..=n) {:.2e}, power curve on [-0.375, 0.8125] (k = 1..4, n/2, n-1, n) {:.2e}",
            worst[0], worst[1]
        );
        assert!(
            worst.iter().all(|w| *w < F64_BOUND),
            "degree {n}: {worst:?}"
        );
    }
}

#[test]
fn f64_tensor_derivatives_are_close_to_the_exact_ones_of_the_same_inputs() {
    let mut rng = Rng(708);
    for n in [16usize, 32] {
        let mut worst = [0.0f64; 2];
        // Bidegree (n, 3): the exact restriction of (32, 32) would take seconds.
        let grid: Vec<Vec<Vec<f64>>> = (0..=n)
            .map(|_| (0..=3).map(|_| vec![rng.unit()]).collect())
            .collect();
        let exact_grid: Vec<Vec<Pt>> = grid.iter().map(|row| exact_all(row)).collect();
        let p64 = TensorPatch::new(grid.clone()).unwrap();
        let p = TensorPatch::new(exact_grid.clone()).unwrap();
        let s64 = PowerSurface::new(grid).unwrap();
        let s = PowerSurface::new(exact_grid).unwrap();
        let rect64 = [-0.375, 0.8125, 0.25, 1.5];
        let rect = rect64.map(exact);
        for order in [[1, 0], [0, 1], [1, 1], [2, 3], [n / 2, 1], [n, 3]] {
            let got = bezier_tensor_derivative(&p64, order).unwrap();
            let want = bezier_tensor_derivative(&p, order).unwrap();
            worst[0] = worst[0].max(relative_error(
                &got.to_nested().concat(),
                &want.to_nested().concat(),
            ));
            let got = power_tensor_derivative(&s64, order, &rect64).unwrap();
            let want = power_tensor_derivative(&s, order, &rect).unwrap();
            worst[1] = worst[1].max(relative_error(
                &got.to_nested().concat(),
                &want.to_nested().concat(),
            ));
        }
        println!(
            "degree ({n}, 3): largest relative error: Bézier tensor {:.2e}, power tensor on [-0.375, 0.8125] x [0.25, 1.5] {:.2e} (orders (1,0) (0,1) (1,1) (2,3) (n/2,1) (n,3))",
            worst[0], worst[1]
        );
        assert!(
            worst.iter().all(|w| *w < F64_BOUND),
            "degree {n}: {worst:?}"
        );
    }
}

#[test]
fn f64_triangle_derivatives_are_close_to_the_exact_ones_of_the_same_inputs() {
    let mut rng = Rng(709);
    for n in [16usize, 32] {
        let mut worst = [0.0f64; 2];
        let len = (n + 1) * (n + 2) / 2;
        let pts: Vec<Vec<f64>> = (0..len).map(|_| vec![rng.unit()]).collect();
        let t64 = TriangularPatch::new(n, pts.clone()).unwrap();
        let t = TriangularPatch::new(n, exact_all(&pts)).unwrap();
        let bary = [vec![0.5, 0.25, -0.75], vec![-1.0, 0.625, 0.375]];
        for k in [1usize, 2, 5, n] {
            let dirs64: Vec<Vec<f64>> = (0..k).map(|i| bary[i % 2].clone()).collect();
            let got = bezier_triangle_derivative(&t64, &dirs64).unwrap();
            let want = bezier_triangle_derivative(&t, &exact_directions(&dirs64)).unwrap();
            worst[0] = worst[0].max(relative_error(
                &got.control_points().to_vec(),
                &want.control_points().to_vec(),
            ));
        }
        // Bidegree (n/2, n/2): a triangular form of total degree n.
        let grid: Vec<Vec<Vec<f64>>> = (0..=n / 2)
            .map(|_| (0..=n / 2).map(|_| vec![rng.unit()]).collect())
            .collect();
        let s64 = PowerSurface::new(grid.clone()).unwrap();
        let s = PowerSurface::new(grid.iter().map(|row| exact_all(row)).collect()).unwrap();
        let tri64 = [[0.0, 0.0], [0.75, 0.125], [-0.25, 0.5]];
        let tri = tri64.map(|[u, v]| [exact(u), exact(v)]);
        let plane = [vec![0.625, -0.5], vec![0.25, 1.0]];
        for k in [1usize, n / 2] {
            let dirs64: Vec<Vec<f64>> = (0..k).map(|i| plane[i % 2].clone()).collect();
            let got =
                power_triangle_derivative(&PowerTriangle::from_surface(&s64), &tri64, &dirs64)
                    .unwrap();
            let want = power_triangle_derivative(
                &PowerTriangle::from_surface(&s),
                &tri,
                &exact_directions(&dirs64),
            )
            .unwrap();
            worst[1] = worst[1].max(relative_error(
                &got.control_points().to_vec(),
                &want.control_points().to_vec(),
            ));
        }
        println!(
            "degree {n}: largest relative error: Bézier triangle (k = 1, 2, 5, N) {:.2e}, power triangle (k = 1, N/2) {:.2e}",
            worst[0], worst[1]
        );
        assert!(
            worst.iter().all(|w| *w < F64_BOUND),
            "degree {n}: {worst:?}"
        );
    }
}
