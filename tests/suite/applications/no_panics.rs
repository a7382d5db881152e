//! No panic is reachable from the public API (issue 14, item 2): every input that used to
//! panic, overflow or abort on allocation is refused with an `Err` of a stated kind about a
//! named argument, and a randomized sweep of the changed functions over random sizes, NaN,
//! infinities and huge values never panics.

use crate::common::Rng;
use blossom::engine::{
    bspline_basis_on_span, checked_triangle_len, solve_rational_system, triangle_power_to_bernstein,
};
use blossom::{
    bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom, bspline_from_pieces,
    curve_blossom, polar_form, power_triangle_blossom, tensor_blossom, triangle_blossom, BSpline,
    Batch, Error, ErrorKind, KnotVector, Piece, PowerCurve, PowerSurface, PowerTriangle, Rational,
    RestrictionMap, TriangularPatch, MAX_ENTRIES,
};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The kind and field of an error.
fn what(e: Error) -> (ErrorKind, String) {
    (e.kind, e.field)
}

fn kind_field(kind: ErrorKind, field: &str) -> (ErrorKind, String) {
    (kind, field.to_string())
}

fn line() -> PowerCurve<f64> {
    PowerCurve::new(vec![vec![1.0], vec![2.0]]).unwrap()
}

fn unit_square() -> PowerSurface<f64> {
    PowerSurface::new(vec![vec![vec![1.0], vec![2.0]], vec![vec![3.0], vec![4.0]]]).unwrap()
}

fn bspline() -> BSpline<f64> {
    BSpline::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        vec![
            vec![1.0, 1.0],
            vec![2.0, 3.0],
            vec![4.0, 3.0],
            vec![3.0, 1.0],
        ],
    )
    .unwrap()
}

#[test]
fn triangular_patch_of_a_huge_degree_is_too_large() {
    for degree in [usize::MAX, usize::MAX / 2, 1 << 40] {
        let e = TriangularPatch::new(degree, vec![vec![0.0]]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    }
    // A degree whose count fits usize but exceeds the limit is refused as well, where it used
    // to be compared with the length of the list (and a wrapped count could match it).
    assert!(checked_triangle_len(1 << 20).unwrap() > MAX_ENTRIES);
    let e = TriangularPatch::new(1 << 20, vec![vec![0.0]]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    assert_eq!(checked_triangle_len(usize::MAX), None);
    // Valid input is unchanged.
    assert_eq!(
        TriangularPatch::new(1, vec![vec![1.0]; 3])
            .unwrap()
            .degree(),
        1
    );
}

#[test]
fn knot_vector_of_a_huge_degree_is_too_large() {
    let e = KnotVector::new(usize::MAX, vec![0.0, 1.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    let e = KnotVector::new(usize::MAX / 2, vec![0.0, 1.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    let e = BSpline::new(usize::MAX, vec![0.0, 1.0], vec![vec![0.0]]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Shape, "control_points"));
}

#[test]
fn triangular_patch_get_out_of_range() {
    let t = TriangularPatch::new(1, vec![vec![1.0], vec![2.0], vec![3.0]]).unwrap();
    assert_eq!(t.try_get(1, 0), Some(&[3.0][..]));
    assert_eq!(t.try_get(0, 1), Some(t.get(0, 1)));
    assert_eq!(t.try_get(1, 1), None);
    assert_eq!(t.try_get(usize::MAX, 1), None);
    assert_eq!(t.try_get(0, 2), None);
    // `get` keeps the indexing contract of its `# Panics` section.
    assert!(catch_unwind(|| t.get(2, 0).to_vec()).is_err());
}

#[test]
fn definition_blossoms_with_the_wrong_number_of_arguments() {
    let e = curve_blossom(&line(), &[1.0, 2.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    assert_eq!(curve_blossom(&line(), &[0.5]).unwrap(), vec![2.0]);
    let e = tensor_blossom(&unit_square(), &[], &[1.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "us"));
    let e = tensor_blossom(&unit_square(), &[1.0], &[1.0, 2.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "vs"));
    let e = triangle_blossom(&unit_square(), &[[1.0, 2.0]]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    let tri = PowerTriangle::from_surface(&unit_square());
    let e = power_triangle_blossom(&tri, &[]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    assert!(power_triangle_blossom(&tri, &[[0.0, 0.0], [0.0, 0.0]]).is_ok());
}

#[test]
fn polarisation_with_the_wrong_number_or_dimension_of_arguments() {
    let q = |x: &[f64]| vec![x[0] * x[0]];
    let e = polar_form(2, &[vec![1.0]], 1, &q).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    let e = polar_form(2, &[vec![1.0], vec![]], 1, &q).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Dimension, "args[1]"));
    assert_eq!(
        polar_form(2, &[vec![3.0], vec![5.0]], 1, &q).unwrap(),
        vec![15.0]
    );
}

#[test]
fn pyramid_blossoms_with_the_wrong_number_of_arguments() {
    let net = vec![vec![0.0], vec![1.0]];
    let e = bezier_curve_blossom(&net, &[]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    let e = bezier_curve_blossom::<f64>(&[], &[]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Empty, "control"));
    let e = bezier_curve_blossom(&[vec![0.0], vec![1.0, 2.0]], &[0.5]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Dimension, "control[1]"));
    assert_eq!(bezier_curve_blossom(&net, &[0.25]).unwrap(), vec![0.25]);
    let grid = vec![net.clone(), net.clone()];
    let e = bezier_tensor_blossom(&grid, &[0.5, 0.5], &[0.5]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "us"));
    let e = bezier_tensor_blossom(&grid, &[0.5], &[]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "vs"));
    let e = bezier_tensor_blossom(&[net.clone(), vec![vec![0.0]]], &[0.5], &[0.5]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Shape, "net[1]"));
    let t = TriangularPatch::new(1, vec![vec![1.0], vec![2.0], vec![3.0]]).unwrap();
    let e = bezier_triangle_blossom(&t, &[]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Arity, "args"));
    assert_eq!(
        bezier_triangle_blossom(&t, &[[1.0, 0.0, 0.0]]).unwrap(),
        vec![3.0]
    );
}

#[test]
fn triangle_power_to_bernstein_with_a_short_list() {
    // The array's own constructor refuses a short list, an impossible degree and a zero
    // dimension; the conversion refuses a grid whose total degree makes too large a net.
    let e = PowerTriangle::from_coordinates(2, 1, vec![1.0; 5]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Shape, "coordinates"));
    let e = PowerTriangle::from_coordinates(usize::MAX, 1, vec![1.0]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    let e = PowerTriangle::from_coordinates(1, 0, vec![1.0; 3]).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Dimension, "dim"));
    let long_row = PowerSurface::new(vec![vec![vec![1.0]; 8192]]).unwrap();
    let e = triangle_power_to_bernstein(&PowerTriangle::from_surface(&long_row)).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    let single = PowerTriangle::from_coordinates(0, 1, vec![7.0]).unwrap();
    assert_eq!(
        triangle_power_to_bernstein(&single).unwrap().get(0, 0),
        &[7.0][..]
    );
}

#[test]
fn bspline_eval_at_nan_and_infinities() {
    let f = bspline();
    for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(
            what(f.eval(&t).unwrap_err()),
            kind_field(ErrorKind::NotFinite, "t")
        );
        assert_eq!(
            what(f.de_boor(&t).unwrap_err()),
            kind_field(ErrorKind::NotFinite, "t")
        );
        let e = f.insert_knot(&t).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::NotFinite, "x"));
    }
    assert_eq!(
        what(f.eval(&3.0).unwrap_err()),
        kind_field(ErrorKind::Domain, "t")
    );
    assert!(f.eval(&2.0).is_ok());
}

#[test]
fn knot_vectors_containing_nan_or_infinities() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = KnotVector::new(1, vec![0.0, 0.0, bad, 1.0, 1.0]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::NotFinite, "knots[2]"));
        let e = BSpline::new(1, vec![0.0, 0.0, 1.0, bad], vec![vec![0.0], vec![1.0]]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::NotFinite, "knots[3]"));
        let e = bspline_basis_on_span(&[0.0, 0.0, bad, 1.0], 1, 1).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::NotFinite, "knots[2]"));
        let piece = Piece {
            interval: [0.0, bad],
            curve: line(),
        };
        let e = bspline_from_pieces(1, &[piece]).unwrap_err();
        assert_eq!(
            what(e),
            kind_field(ErrorKind::NotFinite, "pieces[0].interval[1]")
        );
    }
    let e = bspline_basis_on_span(&[0.0, 0.0, 1.0, 1.0], 1, 0).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Domain, "s"));
    let e = bspline_basis_on_span(&[0.0, 0.0, 1.0, 1.0], 1, 2).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Domain, "s"));
    let e = bspline_basis_on_span(&[0.0, 1.0], usize::MAX, usize::MAX).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Domain, "s"));
    assert_eq!(
        bspline_basis_on_span(&[0.0, 0.0, 1.0, 1.0], 1, 1)
            .unwrap()
            .len(),
        2
    );
}

#[test]
fn pieces_of_a_huge_degree_are_too_large() {
    let piece = Piece {
        interval: [0.0, 1.0],
        curve: line(),
    };
    let e = bspline_from_pieces(usize::MAX, std::slice::from_ref(&piece)).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    let e = bspline_from_pieces(MAX_ENTRIES, std::slice::from_ref(&piece)).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
}

#[test]
fn batch_zeros_with_an_overflowing_product() {
    let e = Batch::zeros(usize::MAX, 2, 1).unwrap_err();
    assert_eq!(
        what(e),
        kind_field(ErrorKind::TooLarge, "points * dim * len")
    );
    let e = Batch::zeros(1 << 20, 1 << 20, 1 << 20).unwrap_err();
    assert_eq!(e.kind, ErrorKind::TooLarge);
    let e = Batch::zeros(4, 3, usize::MAX).unwrap_err();
    assert_eq!(e.kind, ErrorKind::TooLarge);
    let e = Batch::zeros(MAX_ENTRIES, 1, 1).unwrap_err();
    assert_eq!(e.kind, ErrorKind::TooLarge);
    let b = Batch::zeros(4, 3, 10).unwrap();
    assert_eq!(
        (b.len(), b.as_slice().len()),
        (10, 4 * 3 * blossom::BATCH_LANES)
    );
}

#[test]
fn restriction_maps_of_huge_degrees() {
    for degree in [20_000, 1 << 40, usize::MAX] {
        let e = RestrictionMap::curve(degree, 0.0, 1.0).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
        let e = RestrictionMap::triangle(degree, [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
        let e = RestrictionMap::tensor((degree, 1), [0.0, 1.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
        let e = RestrictionMap::tensor((1, degree), [0.0, 1.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "degree"));
    }
    // A map that fits one-dimensional blocks but not the scratch of a block of a higher
    // dimension is refused by `restrict_into`, naming the map.
    let map = RestrictionMap::curve(3000, 0.0, 1.0).unwrap();
    let batch = Batch::zeros(3001, 12, 1).unwrap();
    let mut out = Batch::zeros(3001, 12, 1).unwrap();
    let e = batch.restrict_into(&map, &mut out).unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::TooLarge, "map"));
    // Small maps keep working.
    let map = RestrictionMap::curve(3, 0.0, 0.5).unwrap();
    let batch = Batch::zeros(4, 2, 3).unwrap();
    let mut out = Batch::zeros(4, 2, 3).unwrap();
    assert!(batch.restrict_into(&map, &mut out).is_ok());
}

#[test]
fn solve_rational_system_with_points_of_the_wrong_dimension() {
    let one = Rational::from_integer(1.into());
    let m = vec![vec![one.clone()]];
    let e = solve_rational_system(&m, &[vec![1.0, 2.0]], 1, "m").unwrap_err();
    assert_eq!(what(e), kind_field(ErrorKind::Dimension, "rhs[0]"));
    assert_eq!(
        solve_rational_system(&m, &[vec![2.0]], 1, "m").unwrap(),
        vec![vec![2.0]]
    );
}

/// A random size: small, around the limits, or huge.
fn size(rng: &mut Rng) -> usize {
    match rng.next() % 6 {
        0 => (rng.next() % 6) as usize,
        1 => (rng.next() % 40) as usize,
        2 => MAX_ENTRIES >> (rng.next() % 12),
        3 => usize::MAX - (rng.next() % 4) as usize,
        4 => 1 << (rng.next() % 64),
        _ => (rng.next() as usize) >> (rng.next() % 64),
    }
}

/// A random number: ordinary, NaN, an infinity or huge.
fn number(rng: &mut Rng) -> f64 {
    match rng.next() % 8 {
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => f64::NEG_INFINITY,
        3 => f64::MAX,
        4 => -1e300,
        _ => rng.unit() * 4.0,
    }
}

fn numbers(rng: &mut Rng, n: usize) -> Vec<f64> {
    (0..n.min(12)).map(|_| number(rng)).collect()
}

fn points(rng: &mut Rng, n: usize) -> Vec<Vec<f64>> {
    let dim = 1 + (rng.next() % 2) as usize;
    (0..n.min(12))
        .map(|_| {
            let d = if rng.next().is_multiple_of(10) {
                dim + 1
            } else {
                dim
            };
            numbers(rng, d)
        })
        .collect()
}

#[test]
fn random_sizes_nan_and_huge_values_never_panic() {
    let mut rng = Rng(14);
    let mut refused = 0;
    for round in 0..3000 {
        let (a, b, c) = (size(&mut rng), size(&mut rng), size(&mut rng));
        let small = (rng.next() % 5) as usize;
        let xs = numbers(&mut rng, small + 1);
        let pts = points(&mut rng, small + 2);
        let knots = {
            let mut k = numbers(&mut rng, 2 * small + 4);
            if rng.next().is_multiple_of(2) {
                k.sort_by(f64::total_cmp);
            }
            k
        };
        let case = round % 12;
        let outcome = catch_unwind(AssertUnwindSafe(|| -> bool {
            match case {
                0 => TriangularPatch::new(a, pts.clone()).is_err(),
                1 => KnotVector::new(a, knots.clone()).is_err(),
                2 => BSpline::new(small, knots.clone(), pts.clone())
                    .map(|f| xs.iter().all(|t| f.eval(t).is_err()))
                    .unwrap_or(true),
                3 => Batch::zeros(a, b, c).is_err(),
                4 => RestrictionMap::curve(a, xs[0], 1.0).is_err(),
                5 => RestrictionMap::triangle(a, [[xs[0], 0.0], [0.0, 1.0], [0.0, 0.0]]).is_err(),
                6 => RestrictionMap::tensor((a, b), [0.0, 1.0, xs[0], 1.0]).is_err(),
                7 => PowerTriangle::from_coordinates(small, 1, pts.concat())
                    .map_or(true, |s| triangle_power_to_bernstein(&s).is_err()),
                8 => bezier_curve_blossom(&pts, &xs).is_err(),
                9 => bspline_basis_on_span(&knots, small, a % 8).is_err(),
                10 => {
                    let curve = PowerCurve::new(pts.clone());
                    curve.map_or(true, |c| curve_blossom(&c, &xs).is_err())
                }
                _ => {
                    let piece = Piece {
                        interval: [xs[0], xs[0] + 1.0],
                        curve: line(),
                    };
                    // Degrees within the limit are valid, and cost O(p^3): keep them small.
                    let degree = if a > MAX_ENTRIES { a } else { a % 8 };
                    bspline_from_pieces(degree, &[piece]).is_err()
                }
            }
        }));
        match outcome {
            Ok(err) => refused += usize::from(err),
            Err(_) => panic!("round {round} (case {case}) panicked: sizes {a} {b} {c}, {xs:?}"),
        }
    }
    // The sweep reaches the refusals it is meant to probe.
    assert!(refused > 1000, "only {refused} refusals");
}
