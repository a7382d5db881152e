//! Batches sharing one domain (`blossom::Batch`, `blossom::RestrictionMap`): every object
//! gets bit for bit what the engine gives it alone, a batch restricted by the map equals every
//! object restricted on its own by de Casteljau's pyramid in exact arithmetic (to rounding),
//! across block boundaries; the
//! parallel path equals the serial one bit for bit; shapes that do not fit are errors.

use crate::common::{exact, exact_points, repeated, Rng};
use blossom::rational_to_f64;
use blossom::{bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom};
use blossom::{Batch, RestrictionMap, BATCH_LANES as LANES};
use blossom::{Bezier, BezierCurve, Rational, TriangularPatch};

fn unit(rng: &mut Rng) -> f64 {
    (rng.next() % 2_000_001) as f64 / 1_000_000.0 - 1.0
}

fn close(x: f64, want: &Rational) {
    let y = rational_to_f64(want);
    assert!((x - y).abs() <= 1e-12 * (1.0 + y.abs()), "{x} vs {y}");
}

fn random_nets(rng: &mut Rng, count: usize, points: usize, dim: usize) -> Vec<Vec<Vec<f64>>> {
    (0..count)
        .map(|_| {
            (0..points)
                .map(|_| (0..dim).map(|_| unit(rng)).collect())
                .collect()
        })
        .collect()
}

#[test]
fn every_object_gets_the_answer_of_the_engine_on_it_alone() {
    // A block is one object with points of dim * LANES numbers: each lane must get exactly
    // (bit for bit) what `Bezier::subsegment` gives for its curve alone.
    let mut rng = Rng(600);
    let count = LANES + 3;
    let curves: Vec<[[f64; 3]; 6]> = (0..count)
        .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| unit(&mut rng))))
        .collect();
    let batch = Batch::from_arrays(&curves).unwrap();
    let map = RestrictionMap::curve(5, -0.75, 2.5).unwrap();
    let mut out = Batch::zeros(6, 3, count).unwrap();
    batch.restrict_into(&map, &mut out).unwrap();
    let got: Vec<[[f64; 3]; 6]> = out.to_arrays().unwrap();
    for (curve, got) in curves.iter().zip(&got) {
        let alone = Bezier::new(curve.to_vec()).unwrap().subsegment(-0.75..2.5);
        assert_eq!(alone.points(), &got[..]);
    }
    assert_eq!(batch.to_arrays::<6, 3>().unwrap(), curves);
    assert_eq!(batch.to_arrays::<5, 3>().unwrap_err().field, "K");
    assert_eq!(batch.to_arrays::<6, 2>().unwrap_err().field, "D");
}

#[test]
fn curve_batches_equal_each_curve_restricted_exactly() {
    let mut rng = Rng(601);
    for (n, dim, count) in [(3, 3, LANES + 7), (1, 2, 3), (6, 1, 2 * LANES), (0, 2, 5)] {
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        let nets = random_nets(&mut rng, count, n + 1, dim);
        let curves: Vec<BezierCurve<f64>> = nets
            .iter()
            .map(|p| BezierCurve::new(p.clone()).unwrap())
            .collect();
        let batch = Batch::from_curves(&curves).unwrap();
        let map = RestrictionMap::curve(n, a, b).unwrap();
        let mut out = Batch::zeros(n + 1, dim, count).unwrap();
        batch.restrict_into(&map, &mut out).unwrap();
        for (k, net) in nets.iter().enumerate() {
            let exact_net: Vec<Vec<Rational>> = exact_points(net);
            for j in 0..=n {
                let want =
                    bezier_curve_blossom(&exact_net, &repeated(&exact(a), n - j, &exact(b), j))
                        .unwrap();
                for (x, w) in want.iter().enumerate() {
                    close(out.get(k, j, x), w);
                }
            }
        }
    }
}

#[test]
fn tensor_and_triangle_batches_equal_the_pyramid() {
    let mut rng = Rng(602);
    // Tensor (2, 1) patches on [a, b] x [c, d], points numbered row by row.
    let (n, m, dim, count) = (2, 1, 2, LANES + 1);
    let rect = [
        unit(&mut rng),
        unit(&mut rng),
        unit(&mut rng),
        unit(&mut rng),
    ];
    let nets = random_nets(&mut rng, count, (n + 1) * (m + 1), dim);
    let refs: Vec<&[Vec<f64>]> = nets.iter().map(Vec::as_slice).collect();
    let batch = Batch::from_nets((n + 1) * (m + 1), dim, &refs).unwrap();
    let map = RestrictionMap::tensor((n, m), rect).unwrap();
    let mut out = Batch::zeros(map.outputs(), dim, count).unwrap();
    batch.restrict_into(&map, &mut out).unwrap();
    let [a, b, c, d] = rect.map(exact);
    for (k, net) in nets.iter().enumerate().step_by(37) {
        let grid: Vec<Vec<Vec<Rational>>> = net.chunks(m + 1).map(exact_points).collect();
        for nu in 0..=n {
            for mu in 0..=m {
                let want = bezier_tensor_blossom(
                    &grid,
                    &repeated(&a, n - nu, &b, nu),
                    &repeated(&c, m - mu, &d, mu),
                )
                .unwrap();
                for (x, w) in want.iter().enumerate() {
                    close(out.get(k, nu * (m + 1) + mu, x), w);
                }
            }
        }
    }
    // Triangles of degree 3 on a sub-triangle given by (s, t) per corner.
    let (big_n, dim, count) = (3, 3, 300);
    let corners = [[0.5, 0.25], [0.125, 0.75], [0.0, 0.0]];
    let len = (big_n + 1) * (big_n + 2) / 2;
    let nets = random_nets(&mut rng, count, len, dim);
    let refs: Vec<&[Vec<f64>]> = nets.iter().map(Vec::as_slice).collect();
    let batch = Batch::from_nets(len, dim, &refs).unwrap();
    let map = RestrictionMap::triangle(big_n, corners).unwrap();
    let mut out = Batch::zeros(len, dim, count).unwrap();
    batch.restrict_into(&map, &mut out).unwrap();
    let bary = corners.map(|[s, t]| [exact(s), exact(t), exact(1.0 - s - t)]);
    for (k, net) in nets.iter().enumerate().step_by(41) {
        let patch = TriangularPatch::new(big_n, exact_points(net)).unwrap();
        for (idx, (nu, mu, la, _)) in patch.entries().enumerate() {
            let args: Vec<[Rational; 3]> = std::iter::repeat_n(bary[0].clone(), nu)
                .chain(std::iter::repeat_n(bary[1].clone(), mu))
                .chain(std::iter::repeat_n(bary[2].clone(), la))
                .collect();
            let want = bezier_triangle_blossom(&patch, &args).unwrap();
            for (x, w) in want.iter().enumerate() {
                close(out.get(k, idx, x), w);
            }
        }
    }
}

#[cfg(feature = "rayon")]
#[test]
fn parallel_equals_serial_bit_for_bit() {
    let mut rng = Rng(603);
    let count = 5 * LANES + 3;
    let nets = random_nets(&mut rng, count, 4, 3);
    let refs: Vec<&[Vec<f64>]> = nets.iter().map(Vec::as_slice).collect();
    let batch = Batch::from_nets(4, 3, &refs).unwrap();
    let map = RestrictionMap::curve(3, 0.125, 0.8).unwrap();
    let mut serial = Batch::zeros(4, 3, count).unwrap();
    let mut parallel = Batch::zeros(4, 3, count).unwrap();
    batch.restrict_into(&map, &mut serial).unwrap();
    batch.par_restrict_into(&map, &mut parallel).unwrap();
    assert_eq!(serial, parallel);
}

#[test]
fn shapes_that_do_not_fit_are_errors() {
    let map = RestrictionMap::curve(3, 0.0, 0.5).unwrap();
    let batch = Batch::zeros(3, 2, 10).unwrap(); // quadratics
    let mut out = Batch::zeros(4, 2, 10).unwrap();
    assert_eq!(
        batch.restrict_into(&map, &mut out).unwrap_err().field,
        "map"
    );
    let batch = Batch::zeros(4, 2, 10).unwrap();
    let mut out = Batch::zeros(4, 3, 10).unwrap();
    assert_eq!(
        batch.restrict_into(&map, &mut out).unwrap_err().field,
        "out"
    );
    let mut out = Batch::zeros(4, 2, 11).unwrap();
    assert_eq!(
        batch.restrict_into(&map, &mut out).unwrap_err().field,
        "out"
    );
    assert_eq!(
        RestrictionMap::curve(3, f64::NAN, 1.0).unwrap_err().field,
        "a"
    );
    assert_eq!(
        RestrictionMap::tensor((1, 1), [0.0, 1.0, f64::INFINITY, 1.0])
            .unwrap_err()
            .field,
        "rect[2]"
    );
    assert_eq!(
        RestrictionMap::triangle(2, [[0.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]])
            .unwrap_err()
            .field,
        "corners[1][1]"
    );
    let p = |x: f64| vec![x, 0.0];
    let err = Batch::from_nets(2, 2, &[&[p(0.0), p(1.0)], &[p(0.0)]]).unwrap_err();
    assert_eq!(err.field, "nets[1]");
    let err = Batch::from_nets(2, 2, &[&[p(0.0), vec![1.0]]]).unwrap_err();
    assert_eq!(err.field, "nets[0][1]");
    let curves = [
        BezierCurve::new(vec![p(0.0), p(1.0)]).unwrap(),
        BezierCurve::new(vec![p(0.0), p(1.0), p(2.0)]).unwrap(),
    ];
    assert_eq!(Batch::from_curves(&curves).unwrap_err().field, "curves[1]");
    assert_eq!(Batch::from_curves(&[]).unwrap_err().field, "curves");
}

/// Objects in the caller's own layout (`RestrictionMap::restrict_arrays`): each answer is bit
/// for bit the engine's on the object alone (`Bezier::subsegment`, `BezierTriangle::restrict`,
/// which pack nothing) and, for curves, the block engine's (`Batch::restrict_into`), across a
/// partial last block, in 2-D and 3-D.
#[test]
fn arrays_in_the_callers_layout_equal_each_object_alone() {
    let mut rng = Rng(77);
    let count = LANES + 37;
    let curves: Vec<[[f64; 2]; 4]> = (0..count)
        .map(|_| std::array::from_fn(|_| [unit(&mut rng), unit(&mut rng)]))
        .collect();
    let (a, b) = (-0.3, 0.8);
    let mut out = vec![[[f64::NAN; 2]; 4]; count];
    RestrictionMap::curve(3, a, b)
        .unwrap()
        .restrict_arrays(&curves, &mut out)
        .unwrap();
    // Curves are restricted in place, one by one (the unrolled evaluators); the block engine
    // of `Batch` (a runtime width of BATCH_LANES numbers per point, no unrolled code) is the
    // independent reference, and `Bezier::subsegment` the object alone.
    let map = RestrictionMap::curve(3, a, b).unwrap();
    let mut blocks = Batch::zeros(4, 2, count).unwrap();
    Batch::from_arrays(&curves)
        .unwrap()
        .restrict_into(&map, &mut blocks)
        .unwrap();
    let by_blocks = blocks.to_arrays::<4, 2>().unwrap();
    for ((curve, answer), block_answer) in curves.iter().zip(&out).zip(&by_blocks) {
        assert_eq!(answer, block_answer);
        let alone = Bezier::new(curve.to_vec()).unwrap().subsegment(a..b);
        assert_eq!(&answer[..], alone.points());
    }
    let corners = [[0.1, 0.2], [0.7, 0.1], [0.3, 0.6]];
    let triangles: Vec<[[f64; 3]; 6]> = (0..count)
        .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| unit(&mut rng))))
        .collect();
    let mut out = vec![[[0.0; 3]; 6]; count];
    RestrictionMap::triangle(2, corners)
        .unwrap()
        .restrict_arrays(&triangles, &mut out)
        .unwrap();
    for (t, answer) in triangles.iter().zip(&out) {
        let alone = blossom::BezierTriangle::new(2, t.to_vec())
            .unwrap()
            .restrict(&corners);
        assert_eq!(&answer[..], alone.points());
    }
}

#[test]
fn arrays_that_do_not_fit_the_map_are_errors() {
    let map = RestrictionMap::curve(3, 0.0, 1.0).unwrap();
    let quads = vec![[[0.0; 2]; 3]; 4];
    let err = map.restrict_arrays(&quads, &mut quads.clone()).unwrap_err();
    assert_eq!(err.field, "input");
    let cubics = vec![[[0.0; 2]; 4]; 4];
    let err = map
        .restrict_arrays(&cubics, &mut [[[0.0; 2]; 4]; 3])
        .unwrap_err();
    assert_eq!(err.field, "output");
}
