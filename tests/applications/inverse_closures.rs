//! The inverse formula for closures against the engine's restriction (curves, tensor patches,
//! triangles), on non-polynomial closures, and the seed 002/004 verify sections.

mod common;

use blossom::inverse::{
    curve_blossom, curve_control_points, tensor_blossom, tensor_control_points,
    triangle_control_points,
};
use blossom::verify::seeds_002_004;
use blossom::verify::Status;
use blossom::{restrict_curve, restrict_tensor, restrict_triangle, Method, Rational};
use common::Rng;

#[test]
fn closures_give_the_engine_s_control_points() {
    let mut rng = Rng(70);
    for n in 0..=6 {
        let c = rng.curve(n, 2);
        let (a, b) = (rng.rational(), rng.rational());
        let pts = curve_control_points(n, &a, &b, &|t| c.eval(t));
        assert_eq!(
            pts.as_slice(),
            restrict_curve(&c, &a, &b, Method::Bulk).control_points()
        );
        let args: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        assert_eq!(
            curve_blossom(n, &args, &|t| c.eval(t)).unwrap(),
            blossom::blossoms::definition::curve_blossom(&c, &args)
        );
    }
    for (n, m) in [(0, 2), (1, 1), (2, 3), (3, 2)] {
        let s = rng.surface(n, m, 2);
        let rect: [Rational; 4] = std::array::from_fn(|_| rng.rational());
        let net = tensor_control_points((n, m), &rect, &|u, v| s.eval(u, v));
        assert_eq!(
            net.as_slice(),
            restrict_tensor(&s, &rect, Method::Bulk).control_points()
        );
        let us: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
        let vs: Vec<Rational> = (0..m).map(|_| rng.rational()).collect();
        assert_eq!(
            tensor_blossom((n, m), &us, &vs, &|u, v| s.eval(u, v)).unwrap(),
            blossom::blossoms::definition::tensor_blossom(&s, &us, &vs)
        );
        let tri: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
        let pts = triangle_control_points(n + m, &tri, &|u, v| s.eval(u, v));
        assert_eq!(
            pts.as_slice(),
            restrict_triangle(&s, &tri, Method::Bulk).control_points()
        );
    }
}

#[test]
fn non_polynomial_closures_interpolate_the_end_points() {
    // exp on [0, 1] as a quartic by eq. (22): b_0 = e^0, b_4 = e^1, and the curve is close.
    let pts = curve_control_points(4, &0.0f64, &1.0, &|t| vec![t.exp()]);
    let c = blossom::BezierCurve::new(pts).unwrap();
    assert_eq!(c.eval(&0.0)[0], 1.0);
    assert!((c.eval(&1.0)[0] - std::f64::consts::E).abs() < 1e-12);
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!((c.eval(&t)[0] - t.exp()).abs() < 1e-3, "t = {t}");
    }
}

#[test]
fn seed_002_and_004_sections_are_all_explained() {
    let sections = seeds_002_004::sections();
    assert!(sections.len() >= 14);
    for s in &sections {
        assert_ne!(s.status, Status::Unexplained, "{}", s.title);
        assert!(!s.entries.is_empty(), "{}", s.title);
        if s.status == Status::Explained {
            assert!(!s.findings.is_empty(), "{}", s.title);
        }
    }
    let text: Vec<String> = sections
        .iter()
        .map(|s| {
            let bad: Vec<String> = s
                .entries
                .iter()
                .filter(|e| !e.matches)
                .map(|e| {
                    format!(
                        "  {}: printed {} / computed {}",
                        e.label, e.printed, e.computed
                    )
                })
                .collect();
            format!("{} [{}]\n{}", s.title, s.status.name(), bad.join("\n"))
        })
        .collect();
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("verify_seeds_002_004_summary", text.join("\n"));
    });
}
