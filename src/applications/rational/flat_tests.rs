//! The flat storage of the rational shapes against nested points and textbook algorithms: the
//! flat and nested constructors agree; evaluation equals the quotient of Bernstein sums and
//! restriction equals the projected blossoms of the homogeneous points, both written here on
//! nested vectors of exact rationals (sharing no code with the library); bad input is a named
//! error.

use super::*;
use crate::error::ErrorKind;
use crate::Rational;
use num_bigint::BigInt;
use num_traits::{One, Zero};

type Nested = Vec<Vec<Rational>>;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// Samples drawn from the shared test generator ([`crate::test_rng::XorShift`]).
struct Rng(crate::test_rng::XorShift);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(crate::test_rng::XorShift(seed))
    }

    fn below(&mut self, n: u64) -> u64 {
        self.0.next() % n
    }

    /// A rational in [-5, 5] with a denominator up to 4.
    fn rational(&mut self) -> Rational {
        q(self.below(41) as i64 - 20, self.below(4) as i64 + 1)
    }

    /// A weight in [1/3, 4]: positive, so that no textbook quotient divides by zero.
    fn weight(&mut self) -> Rational {
        q(self.below(12) as i64 + 1, 3)
    }

    fn point(&mut self, dim: usize) -> Vec<Rational> {
        (0..dim).map(|_| self.rational()).collect()
    }

    fn points(&mut self, count: usize, dim: usize) -> Nested {
        (0..count).map(|_| self.point(dim)).collect()
    }

    fn weights(&mut self, count: usize) -> Vec<Rational> {
        (0..count).map(|_| self.weight()).collect()
    }

    /// A parameter in [-1/2, 3/2].
    fn parameter(&mut self) -> Rational {
        q(self.below(13) as i64 - 3, 6)
    }
}

// ---- The textbook side: nested vectors, exact rationals, formulas written out. ----

fn factorial(n: usize) -> Rational {
    (1..=n as i64).fold(Rational::one(), |f, k| f * q(k, 1))
}

fn power(x: &Rational, k: usize) -> Rational {
    (0..k).fold(Rational::one(), |p, _| p * x)
}

/// B_i^n(t) = n! / (i! (n - i)!) t^i (1 - t)^(n - i).
fn bernstein(n: usize, i: usize, t: &Rational) -> Rational {
    factorial(n) / (factorial(i) * factorial(n - i)) * power(t, i) * power(&(q(1, 1) - t), n - i)
}

/// sum_k c_k p_k / sum_k c_k for coefficients c_k (Bernstein values times weights).
fn quotient(terms: &[(Rational, &Vec<Rational>)]) -> Option<Vec<Rational>> {
    let dim = terms[0].1.len();
    let den: Rational = terms.iter().map(|(c, _)| c.clone()).sum();
    if den.is_zero() {
        return None;
    }
    Some(
        (0..dim)
            .map(|k| terms.iter().map(|(c, p)| c * &p[k]).sum::<Rational>() / &den)
            .collect(),
    )
}

/// The rational Bézier curve at t as the quotient of its two Bernstein sums.
fn textbook_curve(points: &Nested, weights: &[Rational], t: &Rational) -> Option<Vec<Rational>> {
    let n = points.len() - 1;
    let terms: Vec<_> = (0..=n)
        .map(|i| (bernstein(n, i, t) * &weights[i], &points[i]))
        .collect();
    quotient(&terms)
}

/// The rational tensor patch at (s, t): sum over (i, j) of B_i^n(s) B_j^m(t) w_ij.
fn textbook_tensor(
    points: &[Nested],
    weights: &[Vec<Rational>],
    s: &Rational,
    t: &Rational,
) -> Option<Vec<Rational>> {
    let (n, m) = (points.len() - 1, points[0].len() - 1);
    let mut terms = Vec::new();
    for i in 0..=n {
        for j in 0..=m {
            let c = bernstein(n, i, s) * bernstein(m, j, t) * &weights[i][j];
            terms.push((c, &points[i][j]));
        }
    }
    quotient(&terms)
}

/// The rational triangular patch at barycentric (s, t, 1 - s - t): sum over i + j + k = N of
/// N! / (i! j! k!) s^i t^j r^k w_ijk, the points listed in lexicographic order of (i, j).
fn textbook_triangle(
    n: usize,
    points: &Nested,
    weights: &[Rational],
    s: &Rational,
    t: &Rational,
) -> Option<Vec<Rational>> {
    let r = q(1, 1) - s - t;
    let mut terms = Vec::new();
    let mut idx = 0;
    for i in 0..=n {
        for j in 0..=n - i {
            let k = n - i - j;
            let c = factorial(n) / (factorial(i) * factorial(j) * factorial(k))
                * power(s, i)
                * power(t, j)
                * power(&r, k)
                * &weights[idx];
            terms.push((c, &points[idx]));
            idx += 1;
        }
    }
    quotient(&terms)
}

/// (w b, w) of every point.
fn homogeneous(points: &Nested, weights: &[Rational]) -> Nested {
    points
        .iter()
        .zip(weights)
        .map(|(p, w)| {
            let mut h: Vec<Rational> = p.iter().map(|x| x * w).collect();
            h.push(w.clone());
            h
        })
        .collect()
}

/// The blossom of the polynomial curve `h` at `args` by de Casteljau's recursion with one
/// argument per level: h_i <- (1 - x) h_i + x h_(i+1).
fn textbook_blossom(h: &Nested, args: &[Rational]) -> Vec<Rational> {
    let mut level = h.clone();
    for x in args {
        level = level
            .windows(2)
            .map(|pair| {
                pair[0]
                    .iter()
                    .zip(&pair[1])
                    .map(|(a, b)| (q(1, 1) - x) * a + x * b)
                    .collect()
            })
            .collect();
    }
    level.swap_remove(0)
}

/// The arguments a^(n - j), b^j.
fn args(a: &Rational, b: &Rational, n: usize, j: usize) -> Vec<Rational> {
    let mut v = vec![a.clone(); n - j];
    v.extend(vec![b.clone(); j]);
    v
}

/// (point, weight) of a homogeneous point.
fn project(h: Vec<Rational>) -> (Vec<Rational>, Rational) {
    let (w, n) = h.split_last().unwrap();
    (n.iter().map(|x| x / w).collect(), w.clone())
}

/// The triangular blossom at barycentric arguments, by the recursion
/// h_ijk <- u h_(i+1)jk + v h_i(j+1)k + w h_ij(k+1) on a map keyed by (i, j).
fn textbook_triangle_blossom(n: usize, h: &Nested, args: &[[Rational; 3]]) -> Vec<Rational> {
    let mut level: std::collections::BTreeMap<(usize, usize), Vec<Rational>> =
        std::collections::BTreeMap::new();
    let mut idx = 0;
    for i in 0..=n {
        for j in 0..=n - i {
            level.insert((i, j), h[idx].clone());
            idx += 1;
        }
    }
    for (r, [u, v, w]) in args.iter().enumerate() {
        let deg = n - r - 1;
        let mut next = std::collections::BTreeMap::new();
        for i in 0..=deg {
            for j in 0..=deg - i {
                let (a, b, c) = (&level[&(i + 1, j)], &level[&(i, j + 1)], &level[&(i, j)]);
                let p = (0..a.len())
                    .map(|k| u * &a[k] + v * &b[k] + w * &c[k])
                    .collect();
                next.insert((i, j), p);
            }
        }
        level = next;
    }
    level.remove(&(0, 0)).unwrap()
}

fn barycentric([s, t]: &[Rational; 2]) -> [Rational; 3] {
    [s.clone(), t.clone(), q(1, 1) - s - t]
}

// ---- The tests. ----

#[test]
fn flat_and_nested_constructors_agree() {
    let mut rng = Rng::new(0x5eed_0a01);
    for n in 0..=4 {
        for dim in 1..=3 {
            let points = rng.points(n + 1, dim);
            let weights = rng.weights(n + 1);
            let c = RationalBezierCurve::new(points.clone(), weights.clone()).unwrap();
            let f = RationalBezierCurve::from_coordinates(dim, points.concat(), weights.clone())
                .unwrap();
            assert_eq!(c, f);
            assert_eq!(c.points(), points);
            assert_eq!(c.weights(), &weights[..]);
            assert_eq!(c.to_nested(), points);
            assert_eq!(c.coordinates(), points.concat().as_slice());

            let m = (n + dim) % 3;
            let net: Vec<Nested> = (0..=n).map(|_| rng.points(m + 1, dim)).collect();
            let w: Nested = (0..=n).map(|_| rng.weights(m + 1)).collect();
            let p = RationalTensorPatch::new(net.clone(), w.clone()).unwrap();
            let g = RationalTensorPatch::from_coordinates(
                (n, m),
                dim,
                net.concat().concat(),
                w.concat(),
            )
            .unwrap();
            assert_eq!(p, g);
            assert_eq!(p.to_nested(), (net.clone(), w.clone()));
            for (nu, row) in net.iter().enumerate() {
                assert_eq!(p.row(nu), *row);
                for (mu, b) in row.iter().enumerate() {
                    assert_eq!((p.get(nu, mu), p.weight(nu, mu)), (&b[..], &w[nu][mu]));
                }
            }

            let count = (n + 1) * (n + 2) / 2;
            let tri = rng.points(count, dim);
            let tw = rng.weights(count);
            let t = RationalTriangularPatch::new(n, tri.clone(), tw.clone()).unwrap();
            let h = RationalTriangularPatch::from_coordinates(n, dim, tri.concat(), tw.clone())
                .unwrap();
            assert_eq!(t, h);
            assert_eq!((t.to_nested(), t.weights()), (tri, &tw[..]));
        }
    }
}

#[test]
fn power_forms_flat_and_nested_agree() {
    let mut rng = Rng::new(0x5eed_0a02);
    for (n, m, dim) in [(0, 0, 1), (1, 2, 2), (2, 1, 3), (3, 3, 1)] {
        let num = rng.points(n + 1, dim);
        let den = rng.weights(m + 1);
        let c = RationalCurve::new(&num, &den).unwrap();
        let f = RationalCurve::from_coordinates(dim, num.concat(), den.clone()).unwrap();
        assert_eq!(c, f);
        assert_eq!(c.dim(), dim);
        let t = rng.parameter();
        assert_eq!(c.eval(&t).unwrap(), textbook_power_curve(&num, &den, &t));

        let grid: Vec<Nested> = (0..=n).map(|_| rng.points(m + 1, dim)).collect();
        let dgrid: Nested = (0..=n).map(|_| rng.weights(m + 1)).collect();
        let s = RationalSurface::new(&grid, &dgrid).unwrap();
        let g =
            RationalSurface::from_coordinates((n, m), dim, grid.concat().concat(), dgrid.concat())
                .unwrap();
        assert_eq!(s, g);

        let big_n = n + m;
        let rows: Vec<Nested> = (0..=big_n)
            .map(|i| rng.points(big_n + 1 - i, dim))
            .collect();
        let drows: Nested = (0..=big_n).map(|i| rng.weights(big_n + 1 - i)).collect();
        let p = RationalPowerTriangle::new(&rows, &drows).unwrap();
        let h = RationalPowerTriangle::from_coordinates(
            big_n,
            dim,
            rows.concat().concat(),
            drows.concat(),
        )
        .unwrap();
        assert_eq!(p, h);
    }
}

/// sum c_i t^i / sum d_i t^i.
fn textbook_power_curve(num: &Nested, den: &[Rational], t: &Rational) -> Vec<Rational> {
    let w: Rational = den.iter().enumerate().map(|(i, d)| d * power(t, i)).sum();
    (0..num[0].len())
        .map(|k| {
            num.iter()
                .enumerate()
                .map(|(i, c)| &c[k] * power(t, i))
                .sum::<Rational>()
                / &w
        })
        .collect()
}

#[test]
fn curve_evaluation_and_restriction_equal_the_textbook() {
    let mut rng = Rng::new(0x5eed_0a03);
    // One `out` and one scratch for every round: degrees and dimensions change under them.
    let mut out = RationalBezierCurve::from_coordinates(1, vec![q(0, 1)], vec![q(1, 1)]).unwrap();
    let (mut scratch, mut level) = (Vec::new(), Vec::new());
    let mut compared = 0;
    for round in 0..30 {
        let (n, dim) = (round % 6, 1 + round % 3);
        let points = rng.points(n + 1, dim);
        let mut weights = rng.weights(n + 1);
        if round % 5 == 4 {
            // A negative weight: accepted; the textbook quotient still applies where the
            // denominator does not vanish.
            weights[0] = -weights[0].clone();
        }
        let c = RationalBezierCurve::new(points.clone(), weights.clone()).unwrap();
        let mut x = vec![q(0, 1); dim];
        for _ in 0..3 {
            let t = rng.parameter();
            let want = textbook_curve(&points, &weights, &t);
            assert_eq!(c.eval(&t), want, "round {round}, t = {t}");
            match &want {
                Some(w) => {
                    c.eval_into(&t, &mut x, &mut level).unwrap();
                    assert_eq!(&x, w);
                }
                None => assert_eq!(
                    c.eval_into(&t, &mut x, &mut level).unwrap_err().kind,
                    ErrorKind::ZeroWeight
                ),
            }
        }
        let (a, b) = (rng.parameter(), rng.parameter());
        let h = homogeneous(&points, &weights);
        let want: Vec<_> = (0..=n)
            .map(|j| textbook_blossom(&h, &args(&a, &b, n, j)))
            .collect();
        if want.iter().any(|p| p[dim].is_zero()) {
            let e = c.subsegment(a.clone()..b.clone()).unwrap_err();
            assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "range"));
            continue;
        }
        let (want_points, want_weights): (Nested, Vec<Rational>) =
            want.into_iter().map(project).unzip();
        let part = c.subsegment(a.clone()..b.clone()).unwrap();
        assert_eq!(part.points(), want_points, "round {round} on [{a}, {b}]");
        assert_eq!(part.weights(), &want_weights[..]);
        c.subsegment_into(&a, &b, &mut out, &mut scratch).unwrap();
        assert_eq!(out, part);
        compared += 1;
    }
    assert!(compared >= 20, "only {compared} restrictions compared");
}

#[test]
fn tensor_evaluation_and_restriction_equal_the_textbook() {
    let mut rng = Rng::new(0x5eed_0a04);
    let mut out =
        RationalTensorPatch::from_coordinates((0, 0), 1, vec![q(0, 1)], vec![q(1, 1)]).unwrap();
    let (mut scratch, mut level) = (Vec::new(), Vec::new());
    let mut compared = 0;
    for round in 0..16 {
        let (n, m, dim) = (round % 4, (round / 2) % 3, 1 + round % 2);
        let net: Vec<Nested> = (0..=n).map(|_| rng.points(m + 1, dim)).collect();
        let w: Nested = (0..=n).map(|_| rng.weights(m + 1)).collect();
        let p = RationalTensorPatch::new(net.clone(), w.clone()).unwrap();
        let mut x = vec![q(0, 1); dim];
        for _ in 0..3 {
            let (s, t) = (rng.parameter(), rng.parameter());
            let want = textbook_tensor(&net, &w, &s, &t).unwrap();
            assert_eq!(p.eval(&s, &t).unwrap(), want);
            p.eval_into(&s, &t, &mut x, &mut level).unwrap();
            assert_eq!(x, want, "round {round}");
        }
        let rect = [
            rng.parameter(),
            rng.parameter(),
            rng.parameter(),
            rng.parameter(),
        ];
        // Along v in every row, then along u: h[a^(n-ν) b^ν; c^(m-μ) d^μ].
        let rows: Vec<Nested> = net
            .iter()
            .zip(&w)
            .map(|(r, wr)| homogeneous(r, wr))
            .collect();
        let net_h: Vec<Nested> = (0..=n)
            .map(|nu| {
                (0..=m)
                    .map(|mu| {
                        let column: Nested = rows
                            .iter()
                            .map(|r| textbook_blossom(r, &args(&rect[2], &rect[3], m, mu)))
                            .collect();
                        textbook_blossom(&column, &args(&rect[0], &rect[1], n, nu))
                    })
                    .collect()
            })
            .collect();
        if net_h.iter().flatten().any(|h| h[dim].is_zero()) {
            let e = p.restrict(&rect).unwrap_err();
            assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "rect"));
            continue;
        }
        let (want_points, want_weights): (Vec<Nested>, Nested) = net_h
            .into_iter()
            .map(|row| row.into_iter().map(project).unzip())
            .unzip();
        let part = p.restrict(&rect).unwrap();
        assert_eq!(
            part.to_nested(),
            (want_points, want_weights),
            "round {round}"
        );
        p.restrict_into(&rect, &mut out, &mut scratch).unwrap();
        assert_eq!(out, part);
        compared += 1;
    }
    assert!(compared >= 10, "only {compared} restrictions compared");
}

#[test]
fn triangle_evaluation_and_restriction_equal_the_textbook() {
    let mut rng = Rng::new(0x5eed_0a05);
    let mut out =
        RationalTriangularPatch::from_coordinates(0, 1, vec![q(0, 1)], vec![q(1, 1)]).unwrap();
    let (mut scratch, mut level) = (Vec::new(), Vec::new());
    let mut compared = 0;
    for round in 0..12 {
        let (n, dim) = (round % 4, 1 + round % 3);
        let count = (n + 1) * (n + 2) / 2;
        let points = rng.points(count, dim);
        let weights = rng.weights(count);
        let p = RationalTriangularPatch::new(n, points.clone(), weights.clone()).unwrap();
        let mut x = vec![q(0, 1); dim];
        for _ in 0..3 {
            let at = [rng.parameter(), rng.parameter()];
            let want = textbook_triangle(n, &points, &weights, &at[0], &at[1]);
            assert_eq!(p.eval(&at), want);
            if let Some(want) = want {
                p.eval_into(&at, &mut x, &mut level).unwrap();
                assert_eq!(x, want, "round {round}");
            }
        }
        let corners = [
            [rng.parameter(), rng.parameter()],
            [rng.parameter(), rng.parameter()],
            [rng.parameter(), rng.parameter()],
        ];
        let bary = corners.each_ref().map(barycentric);
        let h = homogeneous(&points, &weights);
        let mut want = Vec::new();
        for nu in 0..=n {
            for mu in 0..=n - nu {
                let mut a = vec![bary[0].clone(); nu];
                a.extend(vec![bary[1].clone(); mu]);
                a.extend(vec![bary[2].clone(); n - nu - mu]);
                want.push(textbook_triangle_blossom(n, &h, &a));
            }
        }
        if want.iter().any(|p| p[dim].is_zero()) {
            let e = p.restrict(&corners).unwrap_err();
            assert_eq!(
                (e.kind, e.field.as_str()),
                (ErrorKind::ZeroWeight, "corners")
            );
            continue;
        }
        let (want_points, want_weights): (Nested, Vec<Rational>) =
            want.into_iter().map(project).unzip();
        let part = p.restrict(&corners).unwrap();
        assert_eq!(
            (part.to_nested(), part.weights()),
            (want_points, &want_weights[..])
        );
        p.restrict_into(&corners, &mut out, &mut scratch).unwrap();
        assert_eq!(out, part);
        compared += 1;
    }
    assert!(compared >= 8, "only {compared} restrictions compared");
}

#[test]
fn buffers_are_reused_once_grown() {
    let c = RationalBezierCurve::from_coordinates(
        2,
        vec![0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 4.0, 0.0],
        vec![1.0, 0.5, 2.0, 1.0],
    )
    .unwrap();
    let (mut out, mut scratch) = (c.subsegment(0.0..1.0).unwrap(), Vec::new());
    c.subsegment_into(&0.25, &0.75, &mut out, &mut scratch)
        .unwrap();
    let before = (
        out.coordinates().as_ptr(),
        out.weights().as_ptr(),
        scratch.as_ptr(),
    );
    c.subsegment_into(&0.1, &0.6, &mut out, &mut scratch)
        .unwrap();
    assert_eq!(
        before,
        (
            out.coordinates().as_ptr(),
            out.weights().as_ptr(),
            scratch.as_ptr()
        )
    );
    let (mut x, mut level) = ([0.0; 2], Vec::new());
    c.eval_into(&0.5, &mut x, &mut level).unwrap();
    let grown = level.as_ptr();
    c.eval_into(&0.7, &mut x, &mut level).unwrap();
    assert_eq!(grown, level.as_ptr());
}

#[test]
fn bad_input_is_a_named_error() {
    let e = |r: crate::error::Result<RationalBezierCurve<f64>>| {
        let e = r.unwrap_err();
        (e.kind, e.field)
    };
    let shape = ErrorKind::Shape;
    assert_eq!(
        e(RationalBezierCurve::from_coordinates(
            2,
            vec![1.0; 5],
            vec![1.0; 2]
        )),
        (shape, "coordinates".into())
    );
    assert_eq!(
        e(RationalBezierCurve::from_coordinates(
            0,
            vec![1.0],
            vec![1.0]
        )),
        (ErrorKind::Dimension, "dim".into())
    );
    assert_eq!(
        e(RationalBezierCurve::from_coordinates(1, vec![], vec![])),
        (ErrorKind::Empty, "coordinates".into())
    );
    assert_eq!(
        e(RationalBezierCurve::from_coordinates(
            2,
            vec![1.0; 4],
            vec![1.0; 3]
        )),
        (shape, "weights".into())
    );
    assert_eq!(
        e(RationalBezierCurve::new(
            vec![vec![1.0], vec![1.0, 2.0]],
            vec![1.0; 2]
        )),
        (ErrorKind::Dimension, "points[1]".into())
    );

    // Zero and negative weights are accepted (as before): a zero weight is a point with no
    // pull; evaluation fails where the denominator vanishes, restriction where a weight of
    // the part does.
    let c = RationalBezierCurve::from_coordinates(1, vec![0.0, 5.0, 1.0], vec![1.0, 0.0, -1.0])
        .unwrap();
    assert_eq!(c.eval(&0.5), None);
    // At 1/4: (B_0 0 + B_1 5 0 - B_2 1) / (B_0 - B_2) with B = (9, 6, 1) / 16.
    assert_eq!(c.eval(&0.25), Some(vec![-0.0625 / 0.5]));
    let e = c.eval_into(&0.5, &mut [0.0], &mut Vec::new()).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "t"));
    let e = c.subsegment(0.0..0.5).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "range"));
    assert!(
        e.message
            .starts_with("the weight w_2 of the part over [0, 0.5] is zero"),
        "{e}"
    );
    let e = c
        .eval_into(&0.25, &mut [0.0, 0.0], &mut Vec::new())
        .unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::Dimension, "out"));

    let e =
        RationalTensorPatch::from_coordinates((1, 1), 1, vec![0.0; 3], vec![1.0; 3]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "coordinates"));
    let e =
        RationalTensorPatch::from_coordinates((1, 1), 1, vec![0.0; 4], vec![1.0; 3]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "weights"));
    let e = RationalTensorPatch::new(
        vec![vec![vec![0.0]], vec![vec![1.0]]],
        vec![vec![1.0], vec![1.0, 2.0]],
    )
    .unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "weights[1]"));
    let e =
        RationalTensorPatch::new(vec![vec![vec![0.0]], vec![]], vec![vec![1.0]; 2]).unwrap_err();
    assert_eq!(e.field, "points[1]");
    // w(s, t) = 1 - 2s vanishes on s = 1/2.
    let p =
        RationalTensorPatch::from_coordinates((1, 0), 1, vec![0.0, 1.0], vec![1.0, -1.0]).unwrap();
    let e = p.restrict(&[0.5, 1.0, 0.0, 1.0]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "rect"));
    assert!(
        e.message
            .starts_with("the weight w_00 of the part over [0.5, 1] x [0, 1]"),
        "{e}"
    );
    let e = p
        .eval_into(&0.5, &0.0, &mut [0.0], &mut Vec::new())
        .unwrap_err();
    assert_eq!(
        (e.kind, e.field.as_str()),
        (ErrorKind::ZeroWeight, "(s, t)")
    );
    let e = p
        .eval_into(&0.25, &0.0, &mut [], &mut Vec::new())
        .unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::Dimension, "out"));

    let e =
        RationalTriangularPatch::from_coordinates(1, 2, vec![0.0; 5], vec![1.0; 3]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "coordinates"));
    let e =
        RationalTriangularPatch::from_coordinates(1, 1, vec![0.0; 3], vec![1.0; 4]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "weights"));
    let e = RationalTriangularPatch::new(1, vec![vec![0.0]; 2], vec![1.0; 3]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "points"));
    // Weights -1 at a = [1, 0], 1 at b = [0, 1], 1 at c = [0, 0] (lexicographic order: c, b,
    // a): w = -s + t + r vanishes at [1/2, 0].
    let p =
        RationalTriangularPatch::from_coordinates(1, 1, vec![1.0, 2.0, 3.0], vec![1.0, 1.0, -1.0])
            .unwrap();
    let e = p
        .restrict(&[[1.0, 0.0], [0.0, 1.0], [0.5, 0.0]])
        .unwrap_err();
    assert_eq!(
        (e.kind, e.field.as_str()),
        (ErrorKind::ZeroWeight, "corners")
    );
    assert!(e.message.starts_with("the weight w_001 of the part"), "{e}");
    let e = p
        .eval_into(&[0.5, 0.0], &mut [0.0], &mut Vec::new())
        .unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ErrorKind::ZeroWeight, "at"));

    let e = RationalCurve::from_coordinates(2, vec![1.0; 3], vec![1.0]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "numerator"));
    let e = RationalCurve::from_coordinates(1, vec![1.0], vec![0.0, 0.0]).unwrap_err();
    assert_eq!(
        (e.kind, e.field.as_str()),
        (ErrorKind::ZeroWeight, "denominator")
    );
    let e = RationalSurface::from_coordinates((1, 0), 1, vec![1.0, 2.0], vec![1.0]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "denominator"));
    let e = RationalSurface::from_coordinates((1, 0), 1, vec![1.0], vec![1.0]).unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (shape, "numerator"));
    let e = RationalPowerTriangle::from_coordinates(1, 1, vec![1.0; 3], vec![0.0; 3]).unwrap_err();
    assert_eq!(
        (e.kind, e.field.as_str()),
        (ErrorKind::ZeroWeight, "denominator")
    );
}

#[test]
fn zero_weights_and_low_degrees_are_errors() {
    let q = |n: i64| q(n, 1);
    // 1 / t on [0, 1]: w_0 = w(0) = 0.
    let c = RationalCurve::new(&[vec![q(1)]], &[q(0), q(1)]).unwrap();
    let e = c.bezier(&q(0), &q(1), None).unwrap_err();
    assert_eq!(e.field, "denominator");
    assert!(e.message.starts_with("weight w_0 is zero"), "{e}");
    assert_eq!(c.bezier(&q(1), &q(2), Some(0)).unwrap_err().field, "degree");
    assert_eq!(
        RationalCurve::new(&[vec![q(1)]], &[q(0)])
            .unwrap_err()
            .field,
        "denominator"
    );
    assert_eq!(
        RationalCurve::<Rational>::new(&[], &[q(1)])
            .unwrap_err()
            .field,
        "numerator"
    );
    let e = RationalBSpline::new(
        1,
        vec![q(0), q(0), q(1), q(1)],
        vec![vec![q(0)], vec![q(1)]],
        vec![q(1), q(0)],
    );
    assert_eq!(e.unwrap_err().field, "weights[1]");
}
