//! Restriction of Bézier input (`BezierCurve::subsegment`, `TensorPatch::restrict`, `TriangularPatch::restrict`),
//! through the power basis and the bulk restriction, checked against de Casteljau's pyramid on
//! the blossom, which never leaves the Bernstein basis: exactly on random rational nets,
//! symbolically (every control point and the domain are variables), and in f64 with a measured
//! error. Bad corners are refused.

use crate::common::{
    curve_by_pyramid, exact, exact_points, restrict_bary, tensor_by_pyramid, triangle_by_pyramid,
    Rng,
};
use blossom::rational_to_f64;
use blossom::{BezierCurve, Poly, Rational, Ring, TensorPatch, TriangularPatch};

/// Random barycentric corners (s, t, 1 - s - t), exact.
fn corners(rng: &mut Rng) -> [[Rational; 3]; 3] {
    std::array::from_fn(|_| {
        let (s, t) = (rng.rational(), rng.rational());
        let r = Rational::from_integer(1.into()) - &s - &t;
        [s, t, r]
    })
}

#[test]
fn curves_equal_the_pyramid_exactly() {
    let mut rng = Rng(501);
    for n in 0..=8 {
        for dim in 1..=3 {
            let curve = BezierCurve::new((0..=n).map(|_| rng.point(dim)).collect()).unwrap();
            let (a, b) = (rng.rational(), rng.rational());
            let fast = curve.subsegment(a.clone()..b.clone());
            assert_eq!(
                fast.control_points(),
                curve_by_pyramid(&curve, &a, &b).as_slice()
            );
        }
    }
}

#[test]
fn tensor_patches_equal_the_pyramid_exactly() {
    let mut rng = Rng(502);
    for n in 0..=4 {
        for m in 0..=4 {
            let dim = 1 + (n + m) % 3;
            let net = (0..=n)
                .map(|_| (0..=m).map(|_| rng.point(dim)).collect())
                .collect();
            let patch = TensorPatch::new(net).unwrap();
            let rect = std::array::from_fn(|_| rng.rational());
            let fast = patch.restrict(&rect);
            assert_eq!(
                fast.to_nested(),
                tensor_by_pyramid(&patch, &rect).as_slice()
            );
        }
    }
}

#[test]
fn triangles_equal_the_pyramid_exactly() {
    let mut rng = Rng(503);
    for n in 0..=6 {
        for dim in 1..=2 {
            let len = (n + 1) * (n + 2) / 2;
            let patch =
                TriangularPatch::new(n, (0..len).map(|_| rng.point(dim)).collect()).unwrap();
            let tri = corners(&mut rng);
            let fast = restrict_bary(&patch, &tri);
            assert_eq!(
                fast.control_points(),
                triangle_by_pyramid(&patch, &tri).as_slice()
            );
        }
    }
}

#[test]
fn symbolic_identity_with_the_pyramid() {
    let v = |s: String| Poly::var(&s);
    for n in 0..=5 {
        let curve = BezierCurve::new((0..=n).map(|i| vec![v(format!("b{i}"))]).collect()).unwrap();
        let (a, b) = (Poly::var("a"), Poly::var("b"));
        let fast = curve.subsegment(a.clone()..b.clone());
        assert_eq!(
            fast.control_points(),
            curve_by_pyramid(&curve, &a, &b).as_slice()
        );
    }
    for (n, m) in [(1, 1), (2, 1), (2, 2), (3, 2)] {
        let net = (0..=n)
            .map(|i| (0..=m).map(|j| vec![v(format!("b{i}_{j}"))]).collect())
            .collect();
        let patch = TensorPatch::new(net).unwrap();
        let rect = ["a", "b", "c", "d"].map(Poly::var);
        let fast = patch.restrict(&rect);
        assert_eq!(
            fast.to_nested(),
            tensor_by_pyramid(&patch, &rect).as_slice()
        );
    }
    for n in 1..=3 {
        let len = (n + 1) * (n + 2) / 2;
        let patch =
            TriangularPatch::new(n, (0..len).map(|k| vec![v(format!("b{k}"))]).collect()).unwrap();
        let affine = [["a1", "a2"], ["b1", "b2"], ["c1", "c2"]].map(|c| c.map(Poly::var));
        let bary = affine
            .clone()
            .map(|[s, t]| [s.clone(), t.clone(), Poly::one().sub(&s).sub(&t)]);
        let fast = patch.restrict(&affine);
        assert_eq!(
            fast.control_points(),
            triangle_by_pyramid(&patch, &bary).as_slice()
        );
    }
}

/// f64 against the exact answer of the same inputs (every f64 input is exactly a rational):
/// the largest relative error over random curves in [-1, 1] on sub-intervals of [0, 1].
#[test]
fn f64_error_is_small_at_moderate_degree() {
    let mut rng = Rng(504);
    let mut worst: f64 = 0.0;
    for n in 1..=8 {
        for _ in 0..20 {
            let pts: Vec<Vec<f64>> = (0..=n).map(|_| vec![rng.unit(), rng.unit()]).collect();
            let a = (rng.next() % 1000) as f64 / 2000.0;
            let b = 0.5 + (rng.next() % 1000) as f64 / 2000.0;
            let float = BezierCurve::new(pts.clone()).unwrap().subsegment(a..b);
            let exact_curve = BezierCurve::new(exact_points(&pts)).unwrap();
            let want = exact_curve.subsegment((exact(a)).clone()..(exact(b)).clone());
            for (pf, pe) in float.control_points().iter().zip(want.control_points()) {
                for (x, y) in pf.iter().zip(pe) {
                    let y = rational_to_f64(y);
                    worst = worst.max((x - y).abs() / (1.0 + y.abs()));
                }
            }
        }
    }
    println!("largest relative f64 error, Bézier curves of degree 1..=8 in [-1, 1]^2: {worst:e}");
    assert!(worst < 1e-12, "{worst:e}");
}
