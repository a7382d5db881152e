//! The inverse (polarisation) formula for closures, `*_from_samples` (curves, tensor patches,
//! triangles), against algorithms that never call it, and on non-polynomial closures.
//!
//! Why not against `Method::Polarisation`: that method is the same `polar_form` applied to
//! the closure `|t| curve.eval(t)`, so the comparison would check the formula against itself.
//! The references here are independent of it:
//!
//! * for closures of power-basis shapes, the subset-sum definitions (2), (8), (13) of the
//!   blossom (`blossom::curve_blossom`, `tensor_blossom`, `triangle_blossom`, and the
//!   restrictions by `Method::Definition`);
//! * for closures of Bézier shapes (evaluated by de Casteljau), de Casteljau's pyramid on the
//!   blossom of the net (`blossom::bezier_curve_blossom` and its tensor and triangle forms),
//!   which never leaves the Bernstein basis.

use crate::common::{curve_by_pyramid, tensor_by_pyramid, triangle_by_pyramid, Rng};
use blossom::{
    bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom,
    curve_blossom_from_samples, curve_control_points_from_samples, restrict_power_curve,
    restrict_power_surface, restrict_power_surface_to_triangle, tensor_blossom_from_samples,
    tensor_control_points_from_samples, triangle_blossom_from_samples,
    triangle_control_points_from_samples, BezierCurve, Method, Rational, Ring, TensorPatch,
    TriangularPatch,
};

/// The bidegrees of the surface tests: a triangle of total degree n + m besides.
const BIDEGREES: [(usize, usize); 4] = [(0, 2), (1, 1), (2, 3), (3, 2)];

/// Barycentric coordinates (u, v, 1 - u - v) of the point (u, v) of the parametric plane.
fn bary([u, v]: &[Rational; 2]) -> [Rational; 3] {
    let w = Rational::one().sub(u).sub(v);
    [u.clone(), v.clone(), w]
}

#[test]
fn closures_of_power_forms_give_the_definition_s_blossoms() {
    let mut rng = Rng(70);
    for n in 0..=6 {
        let c = rng.curve(n, 2);
        let (a, b) = (rng.rational(), rng.rational());
        let pts = curve_control_points_from_samples(n, &a, &b, &|t| c.eval(t));
        assert_eq!(
            pts.as_slice(),
            restrict_power_curve(&c, &a, &b, Method::Definition).control_points(),
            "curve n={n}"
        );
        let args: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        assert_eq!(
            curve_blossom_from_samples(n, &args, &|t| c.eval(t)).unwrap(),
            blossom::curve_blossom(&c, &args).unwrap(),
            "curve n={n}"
        );
    }
    for (n, m) in BIDEGREES {
        let s = rng.surface(n, m, 2);
        let rect: [Rational; 4] = std::array::from_fn(|_| rng.rational());
        let net = tensor_control_points_from_samples((n, m), &rect, &|u, v| s.eval(u, v));
        assert_eq!(
            net.as_slice(),
            restrict_power_surface(&s, &rect, Method::Definition).to_nested(),
            "tensor ({n}, {m})"
        );
        let us: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        let vs: Vec<Rational> = (0..m).map(|_| rng.rational()).collect();
        assert_eq!(
            tensor_blossom_from_samples((n, m), &us, &vs, &|u, v| s.eval(u, v)).unwrap(),
            blossom::tensor_blossom(&s, &us, &vs).unwrap(),
            "tensor ({n}, {m})"
        );
        let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
        let pts = triangle_control_points_from_samples(n + m, &tri, &|u, v| s.eval(u, v));
        assert_eq!(
            pts.as_slice(),
            restrict_power_surface_to_triangle(&s, &tri, Method::Definition).control_points(),
            "triangle ({n}, {m})"
        );
        let args: Vec<[Rational; 2]> = (0..n + m)
            .map(|_| [rng.rational(), rng.rational()])
            .collect();
        assert_eq!(
            triangle_blossom_from_samples(n + m, &args, &|u, v| s.eval(u, v)).unwrap(),
            blossom::triangle_blossom(&s, &args).unwrap(),
            "triangle ({n}, {m})"
        );
    }
}

#[test]
fn closures_of_bezier_forms_give_de_casteljau_s_blossoms() {
    let mut rng = Rng(71);
    for n in 0..=6 {
        let net: Vec<Vec<Rational>> = (0..=n).map(|_| rng.point(2)).collect();
        let curve = BezierCurve::new(net.clone()).unwrap();
        let (a, b) = (rng.rational(), rng.rational());
        assert_eq!(
            curve_control_points_from_samples(n, &a, &b, &|t| curve.eval(t)),
            curve_by_pyramid(&curve, &a, &b),
            "curve n={n}"
        );
        let args: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        assert_eq!(
            curve_blossom_from_samples(n, &args, &|t| curve.eval(t)).unwrap(),
            bezier_curve_blossom(&net, &args).unwrap(),
            "curve n={n}"
        );
    }
    for (n, m) in BIDEGREES {
        let net: Vec<Vec<Vec<Rational>>> = (0..=n)
            .map(|_| (0..=m).map(|_| rng.point(2)).collect())
            .collect();
        let patch = TensorPatch::new(net.clone()).unwrap();
        let rect: [Rational; 4] = std::array::from_fn(|_| rng.rational());
        assert_eq!(
            tensor_control_points_from_samples((n, m), &rect, &|u, v| patch.eval(u, v)),
            tensor_by_pyramid(&patch, &rect),
            "tensor ({n}, {m})"
        );
        let us: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        let vs: Vec<Rational> = (0..m).map(|_| rng.rational()).collect();
        assert_eq!(
            tensor_blossom_from_samples((n, m), &us, &vs, &|u, v| patch.eval(u, v)).unwrap(),
            bezier_tensor_blossom(&net, &us, &vs).unwrap(),
            "tensor ({n}, {m})"
        );
        // The triangle of total degree N = n + m, its parametric plane the first two
        // barycentric coordinates: the closure is the patch at (u, v, 1 - u - v).
        let big_n = n + m;
        let points = (0..(big_n + 1) * (big_n + 2) / 2)
            .map(|_| rng.point(2))
            .collect();
        let patch = TriangularPatch::new(big_n, points).unwrap();
        let at = |u: &Rational, v: &Rational| patch.eval(&[u.clone(), v.clone()]);
        let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
        assert_eq!(
            triangle_control_points_from_samples(big_n, &tri, &at),
            triangle_by_pyramid(&patch, &tri.each_ref().map(bary)),
            "triangle N={big_n}"
        );
        let args: Vec<[Rational; 2]> = (0..big_n)
            .map(|_| [rng.rational(), rng.rational()])
            .collect();
        let bary_args: Vec<[Rational; 3]> = args.iter().map(bary).collect();
        assert_eq!(
            triangle_blossom_from_samples(big_n, &args, &at).unwrap(),
            bezier_triangle_blossom(&patch, &bary_args).unwrap(),
            "triangle N={big_n}"
        );
    }
}

#[test]
fn non_polynomial_closures_interpolate_the_end_points() {
    // exp on [0, 1] as a quartic by eq. (22): b_0 = e^0, b_4 = e^1, and the curve is close.
    let pts = curve_control_points_from_samples(4, &0.0f64, &1.0, &|t| vec![t.exp()]);
    let c = BezierCurve::new(pts).unwrap();
    assert_eq!(c.eval(&0.0)[0], 1.0);
    assert!((c.eval(&1.0)[0] - std::f64::consts::E).abs() < 1e-12);
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!((c.eval(&t)[0] - t.exp()).abs() < 1e-3, "t = {t}");
    }
}
