//! The Bézier-input evaluators of `blossom::restriction!` (`bezier_curve`, `bezier_tensor`,
//! `bezier_triangle`), proved symbolically: control points and domain corners are variables,
//! and each generated evaluator is identical, as a polynomial, to two independent algorithms
//! that never pass through the power basis: de Casteljau's pyramid on the blossom of the net
//! (seed 004, eqs. (2) and (9)), and the inverse (polarisation) formula of seed 004 applied to
//! points of the Bézier curve or patch (evaluated by de Casteljau). The table is snapshotted.

use crate::common::{q, repeated};
use blossom::{bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom};
use blossom::{
    curve_control_points_from_samples, tensor_control_points_from_samples,
    triangle_control_points_from_samples, BezierCurve, Poly, Rational, Ring, TensorPatch,
    TriangularPatch,
};

/// A point of one symbolic coordinate.
type P = [Poly; 1];
/// A generated curve evaluator with `L` control points.
type CurveFn<const L: usize> = fn(&[P; L], &Poly, &Poly) -> [P; L];
/// A generated tensor evaluator with an `R` x `C` net.
type TensorFn<const R: usize, const C: usize> = fn(&[[P; C]; R], &[Poly; 4]) -> [[P; C]; R];
/// A generated triangle evaluator with `L` control points.
type TriangleFn<const L: usize> = fn(&[P; L], &[[Poly; 2]; 3]) -> [P; L];

fn var(name: String) -> Poly {
    Poly::var(&name)
}

/// One row of the proof table.
struct Row {
    shape: &'static str,
    degree: String,
    terms: usize,
    pyramid: bool,
    polarisation: bool,
}

fn terms<'a>(points: impl IntoIterator<Item = &'a [Poly; 1]>) -> usize {
    points.into_iter().map(|p| p[0].num_terms()).sum()
}

fn prove_curve<const L: usize>(f: CurveFn<L>) -> Row {
    let n = L - 1;
    let ctrl: [[Poly; 1]; L] = std::array::from_fn(|i| [var(format!("b{i}"))]);
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let w = f(&ctrl, &a, &b);
    let net: Vec<Vec<Poly>> = ctrl.iter().map(|p| p.to_vec()).collect();
    let pyramid = (0..=n).all(|v| {
        let args = repeated(&a, n - v, &b, v);
        w[v].to_vec() == bezier_curve_blossom(&net, &args).unwrap()
    });
    let curve = BezierCurve::new(net.clone()).unwrap();
    let sampled = curve_control_points_from_samples(n, &a, &b, &|t: &Poly| curve.eval(t));
    let polarisation = (0..=n).all(|v| w[v].to_vec() == sampled[v]);
    Row {
        shape: "bezier_curve",
        degree: n.to_string(),
        terms: terms(&w),
        pyramid,
        polarisation,
    }
}

fn prove_tensor<const R: usize, const C: usize>(f: TensorFn<R, C>) -> Row {
    let (n, m) = (R - 1, C - 1);
    let ctrl: [[[Poly; 1]; C]; R] =
        std::array::from_fn(|i| std::array::from_fn(|j| [var(format!("b{i}_{j}"))]));
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let p = f(&ctrl, &rect);
    let net: Vec<Vec<Vec<Poly>>> = ctrl
        .iter()
        .map(|row| row.iter().map(|q| q.to_vec()).collect())
        .collect();
    let [a, b, c, d] = &rect;
    let pyramid = (0..=n).all(|nu| {
        (0..=m).all(|mu| {
            let us = repeated(a, n - nu, b, nu);
            let vs = repeated(c, m - mu, d, mu);
            p[nu][mu].to_vec() == bezier_tensor_blossom(&net, &us, &vs).unwrap()
        })
    });
    let patch = TensorPatch::new(net).unwrap();
    let sampled =
        tensor_control_points_from_samples((n, m), &rect, &|u: &Poly, v: &Poly| patch.eval(u, v));
    let polarisation = (0..=n).all(|nu| (0..=m).all(|mu| p[nu][mu].to_vec() == sampled[nu][mu]));
    Row {
        shape: "bezier_tensor",
        degree: format!("({n}, {m})"),
        terms: p.iter().map(terms).sum(),
        pyramid,
        polarisation,
    }
}

fn prove_triangle<const L: usize>(n: usize, f: TriangleFn<L>) -> Row {
    let ctrl: [[Poly; 1]; L] = std::array::from_fn(|k| [var(format!("b{k}"))]);
    let [a1, a2, b1, b2, c1, c2] = ["a1", "a2", "b1", "b2", "c1", "c2"].map(Poly::var);
    let tri = [[a1, a2], [b1, b2], [c1, c2]];
    let q = f(&ctrl, &tri);
    let patch = TriangularPatch::new(n, ctrl.iter().map(|p| p.to_vec()).collect()).unwrap();
    // Barycentric coordinates (u, v, 1 - u - v) of the corners.
    let bary = |[u, v]: &[Poly; 2]| [u.clone(), v.clone(), Poly::one().sub(u).sub(v)];
    let corners = tri.each_ref().map(bary);
    let mut pyramid = true;
    for (k, (nu, mu, la, _)) in patch.entries().enumerate() {
        let args: Vec<[Poly; 3]> = std::iter::repeat_n(corners[0].clone(), nu)
            .chain(std::iter::repeat_n(corners[1].clone(), mu))
            .chain(std::iter::repeat_n(corners[2].clone(), la))
            .collect();
        pyramid &= q[k].to_vec() == bezier_triangle_blossom(&patch, &args).unwrap();
    }
    let sampled = triangle_control_points_from_samples(n, &tri, &|u: &Poly, v: &Poly| {
        patch.eval(&[u.clone(), v.clone()])
    });
    let polarisation = (0..L).all(|k| q[k].to_vec() == sampled[k]);
    Row {
        shape: "bezier_triangle",
        degree: n.to_string(),
        terms: terms(&q),
        pyramid,
        polarisation,
    }
}

macro_rules! curves {
    ($($n:literal => $name:ident),*) => {{
        $(blossom::restriction!(name = $name, shape = bezier_curve, degree = $n);)*
        vec![$(prove_curve($name::<Poly, 1>)),*]
    }};
}

macro_rules! tensors {
    ($(($n:literal, $m:literal) => $name:ident),*) => {{
        $(blossom::restriction!(name = $name, shape = bezier_tensor, degree = ($n, $m));)*
        vec![$(prove_tensor($name::<Poly, 1>)),*]
    }};
}

macro_rules! triangles {
    ($($n:literal => $name:ident),*) => {{
        $(blossom::restriction!(name = $name, shape = bezier_triangle, degree = $n);)*
        vec![$(prove_triangle($n, $name::<Poly, 1>)),*]
    }};
}

#[test]
fn every_bezier_evaluator_is_proved() {
    let mut rows = curves!(1 => c1, 2 => c2, 3 => c3, 4 => c4, 5 => c5, 6 => c6, 7 => c7, 8 => c8);
    rows.extend(tensors!(
        (1, 1) => t11, (1, 2) => t12, (2, 1) => t21, (2, 2) => t22,
        (2, 3) => t23, (3, 2) => t32, (3, 3) => t33, (0, 2) => t02
    ));
    rows.extend(triangles!(1 => r1, 2 => r2, 3 => r3, 4 => r4, 5 => r5));
    let mut text = format!(
        "{:<16} {:>7} {:>7}  {:<8} {}\n",
        "shape", "degree", "terms", "pyramid", "polarisation"
    );
    let yes = |b: bool| if b { "yes" } else { "NO" };
    for r in &rows {
        text += &format!(
            "{:<16} {:>7} {:>7}  {:<8} {}\n",
            r.shape,
            r.degree,
            r.terms,
            yes(r.pyramid),
            yes(r.polarisation)
        );
    }
    for r in &rows {
        assert!(r.pyramid && r.polarisation, "not proved:\n{text}");
    }
    insta::with_settings!({
        snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"),
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("macros_bezier_proof_table", text);
    });
}

/// The same generated code in f64 and exactly: a cubic 2-D restriction of a known curve.
#[test]
fn bezier_cubic_in_f64_and_exact() {
    blossom::restriction!(name = cubic, shape = bezier_curve, degree = 3);
    // The cubic with control points (0,0), (1,2), (3,3), (4,0) on [1/4, 3/4], against the
    // pyramid in exact arithmetic and within 1e-15 in f64.
    let pts = [[0, 0], [1, 2], [3, 3], [4, 0]];
    let exact_ctrl = pts.map(|p| p.map(|x| q(x, 1)));
    let (a, b) = (q(1, 4), q(3, 4));
    let w = cubic(&exact_ctrl, &a, &b);
    let net: Vec<Vec<Rational>> = exact_ctrl.iter().map(|p| p.to_vec()).collect();
    for (v, wv) in w.iter().enumerate() {
        let args = repeated(&a, 3 - v, &b, v);
        assert_eq!(wv.to_vec(), bezier_curve_blossom(&net, &args).unwrap());
    }
    let float_ctrl = pts.map(|p| p.map(|x| x as f64));
    let wf = cubic(&float_ctrl, &0.25, &0.75);
    for (wf, w) in wf.iter().zip(&w) {
        for (x, y) in wf.iter().zip(w) {
            assert!((x - blossom::rational_to_f64(y)).abs() <= 1e-15);
        }
    }
}

/// The generated Bézier evaluators take the runtime engine's steps in the engine's order, so
/// in f64 they agree with it bit for bit, also on extrapolating domains. (Consistency, not
/// independence: the symbolic proofs above are the independent check.)
#[test]
fn generated_bezier_evaluators_equal_the_engine_bit_for_bit() {
    use blossom::{Bezier, BezierTensor, BezierTriangle};
    blossom::restriction!(name = c7, shape = bezier_curve, degree = 7);
    blossom::restriction!(name = t32, shape = bezier_tensor, degree = (3, 2));
    blossom::restriction!(name = r5, shape = bezier_triangle, degree = 5);
    let mut rng = crate::common::Rng(77);
    let mut p3 = || -> [f64; 3] { std::array::from_fn(|_| rng.unit()) };
    let curve: [[f64; 3]; 8] = std::array::from_fn(|_| p3());
    let net: [[[f64; 3]; 3]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| p3()));
    let tri: [[f64; 3]; 21] = std::array::from_fn(|_| p3());
    for (a, b) in [(0.25, 0.75), (-2.5, 1.75), (0.3, 0.301)] {
        let engine = Bezier::new(curve.to_vec()).unwrap().subsegment(a..b);
        assert_eq!(&c7(&curve, &a, &b)[..], engine.points());
        let rect = [a, b, b, a];
        let patch = BezierTensor::new((3, 2), net.concat()).unwrap();
        assert_eq!(t32(&net, &rect).concat(), patch.restrict(&rect).points());
        let corners = [[a, 0.125], [0.5, b], [b - a, a]];
        let patch = BezierTriangle::new(5, tri.to_vec()).unwrap();
        assert_eq!(&r5(&tri, &corners)[..], patch.restrict(&corners).points());
    }
}
