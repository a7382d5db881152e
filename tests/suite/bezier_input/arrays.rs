//! The fixed-dimension front end (`Bezier`, `BezierTensor`, `BezierTriangle`) and the trait
//! family, exactly, against one de Casteljau pyramid per control point on the
//! runtime-dimension shapes (`bezier_*_blossom`, which the engine does not call).

use crate::common::{curve_by_pyramid, q, tensor_by_pyramid, triangle_by_pyramid, Rng};
use blossom::{
    Bezier, BezierCurve, BezierTensor, BezierTriangle, ErrorKind, Evaluate, Rational, Restrict,
    Ring, TensorPatch, TriangularPatch,
};

fn point3(rng: &mut Rng) -> [Rational; 3] {
    [rng.rational(), rng.rational(), rng.rational()]
}

fn as_vecs(points: &[[Rational; 3]]) -> Vec<Vec<Rational>> {
    points.iter().map(|p| p.to_vec()).collect()
}

#[test]
fn subsegment_is_the_blossom_at_every_control_point() {
    let mut rng = Rng(11);
    for n in [0, 1, 2, 3, 5, 8, 13, 24] {
        let points: Vec<[Rational; 3]> = (0..=n).map(|_| point3(&mut rng)).collect();
        let curve = Bezier::new(points.clone()).unwrap();
        let reference = BezierCurve::new(as_vecs(&points)).unwrap();
        let (a, b) = (rng.rational(), rng.rational());
        let got = curve.subsegment(a.clone()..b.clone());
        assert_eq!(
            as_vecs(got.points()),
            curve_by_pyramid(&reference, &a, &b),
            "n = {n}"
        );
        // The trait gives the same, and `_into` reuses its buffers.
        assert_eq!(Restrict::restrict(&curve, &[a.clone(), b.clone()]), got);
        let mut out = points.clone();
        let mut scratch = Vec::new();
        curve
            .subsegment_into(&a, &b, &mut out, &mut scratch)
            .unwrap();
        assert_eq!(out, got.points());
        // eval is the blossom on the diagonal, and the ends of a subsegment lie on the curve.
        assert_eq!(Evaluate::eval(&curve, &a), reference.eval(&a)[..]);
        assert_eq!(got.points()[0], curve.eval(&a));
        assert_eq!(got.points()[n], curve.eval(&b));
    }
}

#[test]
fn split_gives_both_halves_of_one_pyramid() {
    let mut rng = Rng(12);
    for n in [0, 1, 3, 7, 12] {
        let points: Vec<[Rational; 3]> = (0..=n).map(|_| point3(&mut rng)).collect();
        let curve = Bezier::new(points.clone()).unwrap();
        let reference = BezierCurve::new(as_vecs(&points)).unwrap();
        let t = rng.rational();
        let (left, right) = curve.split(&t);
        assert_eq!(
            as_vecs(left.points()),
            curve_by_pyramid(&reference, &q(0, 1), &t)
        );
        assert_eq!(
            as_vecs(right.points()),
            curve_by_pyramid(&reference, &t, &q(1, 1))
        );
    }
}

#[test]
fn blossoms_and_shapes_are_checked() {
    let curve = Bezier::new(vec![[q(1, 1)], [q(2, 1)], [q(4, 1)]]).unwrap();
    // b[t1, t2] of 1, 2, 4: (1-t1)(1-t2) + 2((1-t1) t2 + t1 (1-t2)) + 4 t1 t2 at (1/2, 1).
    assert_eq!(curve.blossom(&[q(1, 2), q(1, 1)]).unwrap(), [q(3, 1)]);
    let e = curve.blossom(&[q(1, 2)]).unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Arity, "args"));
    let e = Bezier::<f64, 2>::new(vec![]).unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Empty, "points"));
    let e = Bezier::<f64, 0>::new(vec![[]]).unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Dimension, "D"));
    let mut short = vec![[0.0]; 2];
    let e = Bezier::new(vec![[0.0], [1.0], [2.0]])
        .unwrap()
        .subsegment_into(&0.0, &1.0, &mut short, &mut Vec::new())
        .unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Shape, "out"));
    let e = BezierTensor::<f64, 1>::new((1, 2), vec![[0.0]; 5]).unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Shape, "points"));
    let e = BezierTriangle::<f64, 1>::new(2, vec![[0.0]; 5]).unwrap_err();
    assert_eq!((e.kind(), e.field.as_str()), (ErrorKind::Shape, "points"));
    // Degrees whose number of points overflows usize are refused, not a panic.
    let half = usize::MAX / 2;
    for degree in [(usize::MAX, 0), (0, usize::MAX), (half, 1), (1, half)] {
        let e = BezierTensor::<f64, 1>::new(degree, vec![[0.0]; 4]).unwrap_err();
        assert_eq!(
            (e.kind(), e.field.as_str()),
            (ErrorKind::TooLarge, "degree")
        );
    }
    for degree in [usize::MAX, half, 1 << (usize::BITS / 2 + 1)] {
        let e = BezierTriangle::<f64, 1>::new(degree, vec![[0.0]; 3]).unwrap_err();
        assert_eq!(
            (e.kind(), e.field.as_str()),
            (ErrorKind::TooLarge, "degree")
        );
    }
}

#[test]
fn tensor_restriction_is_the_blossom_at_every_control_point() {
    let mut rng = Rng(13);
    for (n, m) in [(0, 0), (1, 0), (0, 3), (2, 3), (5, 4), (8, 7)] {
        let points: Vec<[Rational; 3]> = (0..(n + 1) * (m + 1)).map(|_| point3(&mut rng)).collect();
        let patch = BezierTensor::new((n, m), points.clone()).unwrap();
        let rows: Vec<Vec<Vec<Rational>>> = points.chunks(m + 1).map(as_vecs).collect();
        let reference = TensorPatch::new(rows).unwrap();
        let rect = [
            rng.rational(),
            rng.rational(),
            rng.rational(),
            rng.rational(),
        ];
        let got = patch.restrict(&rect);
        let want: Vec<Vec<Rational>> = tensor_by_pyramid(&reference, &rect).concat();
        assert_eq!(as_vecs(got.points()), want, "({n}, {m})");
        assert_eq!(got.degree(), (n, m));
        let at = [rect[0].clone(), rect[2].clone()];
        assert_eq!(
            patch.eval(&at[0], &at[1])[..],
            reference.eval(&at[0], &at[1])[..]
        );
        assert_eq!(got.get(0, 0), &patch.eval(&rect[0], &rect[2]));
    }
}

#[test]
fn triangle_restriction_is_the_blossom_at_every_control_point() {
    let mut rng = Rng(14);
    for big_n in [0, 1, 2, 3, 4, 6, 9, 12] {
        let len = (big_n + 1) * (big_n + 2) / 2;
        let points: Vec<[Rational; 3]> = (0..len).map(|_| point3(&mut rng)).collect();
        let patch = BezierTriangle::new(big_n, points.clone()).unwrap();
        let reference = TriangularPatch::new(big_n, as_vecs(&points)).unwrap();
        let corners: [[Rational; 2]; 3] = std::array::from_fn(|_| [rng.rational(), rng.rational()]);
        let bary = corners
            .each_ref()
            .map(|[s, t]| [s.clone(), t.clone(), q(1, 1) - s - t]);
        let got = patch.restrict(&corners);
        assert_eq!(
            as_vecs(got.points()),
            triangle_by_pyramid(&reference, &bary),
            "N = {big_n}"
        );
        assert_eq!(
            Restrict::restrict(&reference, &corners).control_points(),
            as_vecs(got.points())
        );
        assert_eq!(patch.eval(&corners[1])[..], reference.eval(&corners[1])[..]);
    }
}

#[test]
#[should_panic(expected = "control point (0, 3) of a triangle of degree 2")]
fn a_triangle_point_outside_the_simplex_is_not_another_point() {
    let t = BezierTriangle::<f64, 1>::new(2, vec![[0.0]; 6]).unwrap();
    let _ = t.get(0, 3);
}

#[test]
#[should_panic(expected = "control point (0, 3) of a patch of bidegree (1, 2)")]
fn a_tensor_point_past_its_row_is_not_the_next_row() {
    let p = BezierTensor::<f64, 1>::new((1, 2), vec![[0.0]; 6]).unwrap();
    let _ = p.get(0, 3);
}

/// `Ring::UNROLLED`: in `f64` (and `f32`) `Bezier::subsegment` runs the unrolled evaluators of
/// degrees 1..=8 (1..=24 with the feature `unrolled-high`), the other rings the engine; the unrolled code takes the engine's steps in the
/// engine's order, so in floating point it must agree with the engine run with a runtime width
/// (`blossom::engine::curve_net` with `dim: usize`, which never dispatches to it) to the last
/// bit, inside [0, 1] and extrapolating. (The exact tests above run the engine since the
/// rationals do not unroll.) `BezierCurve::subsegment` dispatches to the same unrolled code for
/// dimensions 1..=4, so it is checked against the engine too.
#[test]
fn unrolled_f64_path_equals_the_engine_bit_for_bit() {
    fn check<const D: usize>(rng: &mut Rng, n: usize) {
        let points: Vec<[f64; D]> = (0..=n)
            .map(|_| std::array::from_fn(|_| 4.0 * rng.unit() - 2.0))
            .collect();
        let runtime = BezierCurve::new(points.iter().map(|p| p.to_vec()).collect()).unwrap();
        for (a, b) in [(0.25, 0.75), (rng.unit(), rng.unit()), (-1.5, 2.25)] {
            let unrolled = Bezier::new(points.clone()).unwrap().subsegment(a..b);
            let mut engine = vec![0.0; (n + 1) * D];
            blossom::engine::curve_net(
                runtime.coordinates(),
                D,
                &blossom::engine::BernsteinStep(&a),
                &blossom::engine::BernsteinStep(&b),
                &mut engine,
                &mut Vec::new(),
            );
            let flat_front = runtime.subsegment(a..b);
            assert_eq!(
                flat_front.coordinates(),
                &engine[..],
                "BezierCurve, degree {n}"
            );
            for (u, e) in unrolled.points().iter().zip(engine.chunks(D)) {
                let (u, e): (Vec<u64>, Vec<u64>) = (
                    u.iter().map(|x| x.to_bits()).collect(),
                    e.iter().map(|x| x.to_bits()).collect(),
                );
                assert_eq!(u, e, "degree {n}, D = {D}, [{a}, {b}]");
            }
        }
    }
    let mut rng = Rng(29);
    const { assert!(<f64 as Ring>::UNROLLED) };
    const { assert!(<f32 as Ring>::UNROLLED) };
    const { assert!(!<Rational as Ring>::UNROLLED) };
    let unrolled = if cfg!(feature = "unrolled-high") {
        24
    } else {
        8
    };
    for n in 1..=unrolled {
        check::<2>(&mut rng, n);
        check::<3>(&mut rng, n);
    }
}
