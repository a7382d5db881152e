//! Restriction of Bézier input (`blossom::restrict_bezier_*`: forward differences to the power
//! basis, then the bulk power-basis restriction) against de Casteljau's pyramid on the blossom, which
//! never leaves the Bernstein basis, on many random inputs per degree and per kind of domain:
//! sub-intervals of [0, 1], intervals outside it, straddling it, reversed and degenerate;
//! sub-triangles inside the patch's domain, outside it, with reversed orientation and
//! degenerate. Besides the pyramid: the identities (the whole domain gives the input back, a
//! permutation of the corners permutes the net) and the composition of two restrictions.
//! Symbolically through the barycentric API (the sum check on `Poly`), and in f64 against the
//! exact answer of the same inputs, with the measured error printed.
//!
//! `subdivide.rs` has one random input per degree; this file widens the sample.

use blossom::rational_to_f64;
use blossom::{BezierCurve, Poly, Rational, Ring, TensorPatch, TriangularPatch};
use num_bigint::BigInt;

use crate::common::{
    curve_by_pyramid, exact, exact_points, restrict_bary, tensor_by_pyramid, triangle_by_pyramid,
    Rng,
};

/// The samplers this file needs on top of the shared generator.
trait Samplers {
    /// Uniform in 0..k.
    fn below(&mut self, k: u64) -> u64;
    /// A rational in [lo, hi] with a denominator of at most 12 parts of the range.
    fn rational_in(&mut self, lo: i64, hi: i64) -> Rational;
    /// f64 in [-1, 1] with 12 significant bits: exact as a rational.
    fn unit_f64(&mut self) -> f64;
}

impl Samplers for Rng {
    fn below(&mut self, k: u64) -> u64 {
        self.next() % k
    }

    fn rational_in(&mut self, lo: i64, hi: i64) -> Rational {
        let q = self.below(12) as i64 + 1;
        let k = self.below(q as u64 + 1) as i64;
        Rational::from_integer(BigInt::from(lo)) + r(k * (hi - lo), q)
    }

    fn unit_f64(&mut self) -> f64 {
        (self.below(4097) as f64 - 2048.0) / 2048.0
    }
}

fn r(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

fn one() -> Rational {
    r(1, 1)
}

/// The kinds of interval [a, b] relative to the domain [0, 1] of the input.
#[derive(Clone, Copy, Debug)]
enum Interval {
    Inside,
    Outside,
    Straddling,
    Reversed,
    Degenerate,
}

const INTERVALS: [Interval; 5] = [
    Interval::Inside,
    Interval::Outside,
    Interval::Straddling,
    Interval::Reversed,
    Interval::Degenerate,
];

fn interval(rng: &mut Rng, kind: Interval) -> (Rational, Rational) {
    match kind {
        Interval::Inside => {
            let (x, y) = (rng.rational_in(0, 1), rng.rational_in(0, 1));
            if x <= y {
                (x, y)
            } else {
                (y, x)
            }
        }
        Interval::Outside => {
            if rng.below(2) == 0 {
                (rng.rational_in(1, 3), rng.rational_in(3, 5))
            } else {
                (rng.rational_in(-4, -2), rng.rational_in(-2, 0))
            }
        }
        Interval::Straddling => (rng.rational_in(-2, 0), rng.rational_in(1, 3)),
        Interval::Reversed => {
            let (x, y) = (rng.rational_in(-2, 3), rng.rational_in(-2, 3));
            if x > y {
                (x, y)
            } else {
                (y + one(), x)
            }
        }
        Interval::Degenerate => {
            let x = rng.rational_in(-2, 3);
            (x.clone(), x)
        }
    }
}

/// The kinds of sub-triangle relative to the patch's own domain.
#[derive(Clone, Copy, Debug)]
enum Triangle {
    /// Corners with non-negative barycentric coordinates.
    Inside,
    /// Corners anywhere in the plane, mostly outside the domain.
    Outside,
    /// An inside triangle with two corners swapped (the other orientation).
    Reversed,
    /// Three collinear corners.
    Collinear,
    /// One point three times.
    Point,
}

const TRIANGLES: [Triangle; 5] = [
    Triangle::Inside,
    Triangle::Outside,
    Triangle::Reversed,
    Triangle::Collinear,
    Triangle::Point,
];

fn bary(s: Rational, t: Rational) -> [Rational; 3] {
    let rest = one() - &s - &t;
    [s, t, rest]
}

fn inside_corner(rng: &mut Rng) -> [Rational; 3] {
    let q = rng.below(12) as i64 + 1;
    let i = rng.below(q as u64 + 1) as i64;
    let j = rng.below((q - i) as u64 + 1) as i64;
    bary(r(i, q), r(j, q))
}

fn triangle(rng: &mut Rng, kind: Triangle) -> [[Rational; 3]; 3] {
    match kind {
        Triangle::Inside => std::array::from_fn(|_| inside_corner(rng)),
        Triangle::Outside => {
            std::array::from_fn(|_| bary(rng.rational_in(-2, 3), rng.rational_in(-3, 2)))
        }
        Triangle::Reversed => {
            let [a, b, c] = std::array::from_fn(|_| inside_corner(rng));
            [b, a, c]
        }
        Triangle::Collinear => {
            let (p, q) = (inside_corner(rng), inside_corner(rng));
            let t = rng.rational_in(-1, 2);
            let on_line: [Rational; 3] =
                std::array::from_fn(|k| p[k].clone() + (q[k].clone() - &p[k]) * &t);
            [p, on_line, q]
        }
        Triangle::Point => {
            let p = bary(rng.rational_in(-1, 2), rng.rational_in(-1, 2));
            [p.clone(), p.clone(), p]
        }
    }
}

fn random_curve(rng: &mut Rng, n: usize, dim: usize) -> BezierCurve<Rational> {
    BezierCurve::new((0..=n).map(|_| rng.point(dim)).collect()).unwrap()
}

fn random_tensor(rng: &mut Rng, n: usize, m: usize, dim: usize) -> TensorPatch<Rational> {
    TensorPatch::new(
        (0..=n)
            .map(|_| (0..=m).map(|_| rng.point(dim)).collect())
            .collect(),
    )
    .unwrap()
}

fn random_triangle(rng: &mut Rng, n: usize, dim: usize) -> TriangularPatch<Rational> {
    let len = (n + 1) * (n + 2) / 2;
    TriangularPatch::new(n, (0..len).map(|_| rng.point(dim)).collect()).unwrap()
}

#[test]
fn curves_equal_the_pyramid_on_every_kind_of_interval() {
    let mut rng = Rng(0x5EED_0001);
    let mut cases = 0;
    for n in 0..=8 {
        for dim in 1..=3 {
            for kind in INTERVALS {
                for _ in 0..4 {
                    let curve = random_curve(&mut rng, n, dim);
                    let (a, b) = interval(&mut rng, kind);
                    let fast = curve.subsegment(a.clone()..b.clone());
                    assert_eq!(
                        fast.control_points(),
                        curve_by_pyramid(&curve, &a, &b).as_slice(),
                        "degree {n}, dim {dim}, {kind:?} [{a}, {b}]"
                    );
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 9 * 3 * 5 * 4);
}

#[test]
fn tensor_patches_equal_the_pyramid_on_every_kind_of_rectangle() {
    let mut rng = Rng(0x5EED_0002);
    for n in 0..=5 {
        for m in 0..=5 {
            for dim in 1..=3 {
                // Both directions draw their own kind, so that e.g. a reversed u meets an
                // outside v.
                let ku = INTERVALS[(n + 2 * m + dim) % 5];
                let kv = INTERVALS[(3 * n + m + 2 * dim) % 5];
                let patch = random_tensor(&mut rng, n, m, dim);
                let (a, b) = interval(&mut rng, ku);
                let (c, d) = interval(&mut rng, kv);
                let rect = [a, b, c, d];
                let fast = patch.restrict(&rect);
                assert_eq!(
                    fast.to_nested(),
                    tensor_by_pyramid(&patch, &rect).as_slice(),
                    "bidegree ({n}, {m}), dim {dim}, {ku:?} x {kv:?}"
                );
            }
        }
    }
}

#[test]
fn triangles_equal_the_pyramid_on_every_kind_of_sub_triangle() {
    let mut rng = Rng(0x5EED_0003);
    for n in 0..=6 {
        for dim in 1..=3 {
            for kind in TRIANGLES {
                for _ in 0..2 {
                    let patch = random_triangle(&mut rng, n, dim);
                    let corners = triangle(&mut rng, kind);
                    let fast = restrict_bary(&patch, &corners);
                    assert_eq!(fast.degree(), n);
                    assert_eq!(
                        fast.control_points(),
                        triangle_by_pyramid(&patch, &corners).as_slice(),
                        "degree {n}, dim {dim}, {kind:?} {corners:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_whole_domain_gives_the_input_back() {
    let mut rng = Rng(0x5EED_0004);
    let (zero, unit) = (r(0, 1), one());
    for n in 0..=8 {
        let curve = random_curve(&mut rng, n, 2);
        assert_eq!(curve.subsegment(zero.clone()..unit.clone()), curve);
        let mut reversed = curve.control_points().to_vec();
        reversed.reverse();
        assert_eq!(
            curve
                .subsegment(unit.clone()..zero.clone())
                .control_points(),
            reversed.as_slice()
        );
    }
    for (n, m) in [(0, 3), (2, 2), (4, 1), (5, 5)] {
        let patch = random_tensor(&mut rng, n, m, 3);
        let whole = [zero.clone(), unit.clone(), zero.clone(), unit.clone()];
        assert_eq!(patch.restrict(&whole), patch);
    }
    let e = |k: usize| -> [Rational; 3] { std::array::from_fn(|i| r((i == k) as i64, 1)) };
    for n in 0..=6 {
        let patch = random_triangle(&mut rng, n, 2);
        assert_eq!(restrict_bary(&patch, &[e(0), e(1), e(2)]), patch);
        // Corners (e_1, e_2, e_0): the point of indices (nu, mu, lambda) of the answer is the
        // point (lambda, nu, mu) of the input.
        let rotated = restrict_bary(&patch, &[e(1), e(2), e(0)]);
        for (nu, mu, la, q) in rotated.entries() {
            assert_eq!(q, patch.get(la, nu), "degree {n}, ({nu}, {mu}, {la})");
        }
    }
}

/// Restricting to [a, b] and then to [c, d] of the new parameter is restricting to
/// [a + (b - a) c, a + (b - a) d]; likewise for sub-triangles, whose corners combine
/// barycentrically.
#[test]
fn two_restrictions_compose() {
    let mut rng = Rng(0x5EED_0005);
    for n in 0..=8 {
        let curve = random_curve(&mut rng, n, 2);
        let (a, b) = interval(&mut rng, INTERVALS[n % 5]);
        let (c, d) = interval(&mut rng, INTERVALS[(n + 2) % 5]);
        let once = curve.subsegment(a.clone()..b.clone());
        let twice = once.subsegment(c.clone()..d.clone());
        let h = b.clone() - &a;
        let direct = curve.subsegment((a.clone() + &h * &c).clone()..(a + &h * &d).clone());
        assert_eq!(twice, direct, "degree {n}");
    }
    for n in 0..=6 {
        let patch = random_triangle(&mut rng, n, 2);
        let outer = triangle(&mut rng, TRIANGLES[n % 5]);
        let inner = triangle(&mut rng, TRIANGLES[(n + 1) % 5]);
        let twice = restrict_bary(&restrict_bary(&patch, &outer), &inner);
        // Corner k of the composition: sum_j inner[k][j] outer[j].
        let combined: [[Rational; 3]; 3] = std::array::from_fn(|k| {
            std::array::from_fn(|i| (0..3).map(|j| &inner[k][j] * &outer[j][i]).sum())
        });
        let direct = restrict_bary(&patch, &combined);
        assert_eq!(twice, direct, "degree {n}");
    }
}

/// Every control point and every corner coordinate a variable; the corners pass the
/// barycentric check symbolically (s + t + (1 - s - t) - 1 is the zero polynomial).
#[test]
fn symbolic_triangles_through_barycentric_corners() {
    let v = |s: String| Poly::var(&s);
    for n in 0..=3 {
        let len = (n + 1) * (n + 2) / 2;
        let patch = TriangularPatch::new(
            n,
            (0..len)
                .map(|k| vec![v(format!("x{k}")), v(format!("y{k}"))])
                .collect(),
        )
        .unwrap();
        let corners = ["a", "b", "c"].map(|name| {
            let (s, t) = (v(format!("{name}1")), v(format!("{name}2")));
            let rest = Poly::one().sub(&s).sub(&t);
            [s, t, rest]
        });
        let fast = restrict_bary(&patch, &corners);
        assert_eq!(
            fast.control_points(),
            triangle_by_pyramid(&patch, &corners).as_slice(),
            "degree {n}"
        );
    }
}

/// A symbolic curve of dimension 2 on a symbolic interval, and its reversal.
#[test]
fn symbolic_curves_and_reversal() {
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    for n in 0..=4 {
        let curve = BezierCurve::new(
            (0..=n)
                .map(|i| vec![Poly::var(&format!("x{i}")), Poly::var(&format!("y{i}"))])
                .collect(),
        )
        .unwrap();
        let forward = curve.subsegment(a.clone()..b.clone());
        assert_eq!(
            forward.control_points(),
            curve_by_pyramid(&curve, &a, &b).as_slice()
        );
        let mut backward = curve.subsegment(b.clone()..a.clone()).into_control_points();
        backward.reverse();
        assert_eq!(forward.control_points(), backward.as_slice(), "degree {n}");
    }
}

/// The largest |float - exact| over all coordinates, relative to the largest |coordinate| of
/// the input net.
fn relative_error(float: &[Vec<f64>], exact: &[Vec<Rational>], input_size: f64) -> f64 {
    float
        .iter()
        .zip(exact)
        .flat_map(|(p, q)| p.iter().zip(q))
        .map(|(x, y)| (x - rational_to_f64(y)).abs() / input_size)
        .fold(0.0, f64::max)
}

fn input_size(points: &[Vec<f64>]) -> f64 {
    points
        .iter()
        .flatten()
        .fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()))
}

/// f64 against the exact answer of the same inputs (every f64 is a rational), degrees 0..=8,
/// 3-D points in [-1, 1], intervals inside [0, 1] (asserted) and outside it (printed, loosely
/// asserted: the power basis amplifies rounding by about |b - a|^n and (1 + |a|)^n there).
#[test]
fn f64_curves_against_the_exact_answer() {
    let mut rng = Rng(0x5EED_0006);
    let mut worst_inside: f64 = 0.0;
    let mut worst_outside: f64 = 0.0;
    for n in 0..=8 {
        for trial in 0..40 {
            let pts: Vec<Vec<f64>> = (0..=n)
                .map(|_| (0..3).map(|_| rng.unit_f64()).collect())
                .collect();
            let inside = trial % 2 == 0;
            let (a, b) = if inside {
                let (x, y) = ((rng.unit_f64() + 1.0) / 2.0, (rng.unit_f64() + 1.0) / 2.0);
                (x.min(y), x.max(y))
            } else {
                (rng.unit_f64() * 2.0 - 1.0, rng.unit_f64() * 2.0 + 1.0)
            };
            let float = BezierCurve::new(pts.clone()).unwrap().subsegment(a..b);
            let exact_curve = BezierCurve::new(exact_points(&pts)).unwrap();
            let want = exact_curve.subsegment((exact(a)).clone()..(exact(b)).clone());
            let e = relative_error(
                &float.control_points().to_vec(),
                &want.control_points().to_vec(),
                input_size(&pts),
            );
            if inside {
                worst_inside = worst_inside.max(e);
            } else {
                worst_outside = worst_outside.max(e);
            }
        }
    }
    println!("f64 curves, degree 0..=8, [a, b] in [0, 1]: max relative error {worst_inside:e}");
    println!("f64 curves, degree 0..=8, a in [-3, 1], b in [-1, 3]: max relative error {worst_outside:e}");
    assert!(worst_inside < 1e-9, "{worst_inside:e}");
    assert!(worst_outside < 1e-6, "{worst_outside:e}");
}

/// f64 tensor patches (bidegrees up to (6, 6)) and triangles (degrees up to 6) on
/// sub-domains of their own domain, against the exact answer of the same inputs.
#[test]
fn f64_patches_against_the_exact_answer() {
    let mut rng = Rng(0x5EED_0007);
    let mut worst_tensor: f64 = 0.0;
    for n in 0..=6 {
        for m in 0..=6 {
            let net: Vec<Vec<Vec<f64>>> = (0..=n)
                .map(|_| {
                    (0..=m)
                        .map(|_| (0..3).map(|_| rng.unit_f64()).collect())
                        .collect()
                })
                .collect();
            let rect: [f64; 4] = std::array::from_fn(|_| (rng.unit_f64() + 1.0) / 2.0);
            let float = TensorPatch::new(net.clone()).unwrap().restrict(&rect);
            let exact_net = net.iter().map(|row| exact_points(row)).collect();
            let want = TensorPatch::new(exact_net)
                .unwrap()
                .restrict(&rect.map(exact));
            let size = input_size(&net.concat());
            for (fr, er) in float.to_nested().iter().zip(want.to_nested()) {
                worst_tensor = worst_tensor.max(relative_error(fr, &er, size));
            }
        }
    }
    let mut worst_triangle: f64 = 0.0;
    for n in 0..=6 {
        for _ in 0..10 {
            let len = (n + 1) * (n + 2) / 2;
            let pts: Vec<Vec<f64>> = (0..len)
                .map(|_| (0..3).map(|_| rng.unit_f64()).collect())
                .collect();
            // Corners inside the domain with s = i / q, t = j / q rounded to f64 (q <= 12), and
            // the third coordinate 1 - s - t as f64 computes it; retried until the f64 sum is
            // exactly 1 (the documented check). The algorithm reads s and t only, so the exact
            // reference is the affine form with the same s and t.
            let corners: [[f64; 3]; 3] = std::array::from_fn(|_| loop {
                let q = rng.below(12) + 1;
                let i = rng.below(q + 1);
                let j = rng.below(q - i + 1);
                let (s, t) = (i as f64 / q as f64, j as f64 / q as f64);
                let rest = 1.0 - s - t;
                if s + t + rest == 1.0 {
                    break [s, t, rest];
                }
            });
            let float = restrict_bary(&TriangularPatch::new(n, pts.clone()).unwrap(), &corners);
            let exact_patch = TriangularPatch::new(n, exact_points(&pts)).unwrap();
            let want = exact_patch.restrict(&corners.map(|[s, t, _]| [exact(s), exact(t)]));
            worst_triangle = worst_triangle.max(relative_error(
                &float.control_points().to_vec(),
                &want.control_points().to_vec(),
                input_size(&pts),
            ));
        }
    }
    println!("f64 tensor patches, bidegree <= (6, 6), rectangles in [0, 1]^2: max relative error {worst_tensor:e}");
    println!("f64 triangles, degree 0..=6, sub-triangles of the domain (corners i/q, q <= 12): max relative error {worst_triangle:e}");
    assert!(worst_tensor < 1e-9, "{worst_tensor:e}");
    assert!(worst_triangle < 1e-9, "{worst_triangle:e}");
}
