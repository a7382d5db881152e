//! Degree reduction of a Bézier curve by the three methods, with the exact squared L2 error
//! int_0^1 |C(t) - R(t)|^2 dt of each (seed 004, section on degree change).
//!
//! `cargo run -p blossom --example degree_reduction`.
//!
//! * interpolating: the inverse formula (22) at the lower degree, sampling the curve (keeps
//!   both end points);
//! * least squares: the closest curve of the lower degree in L2 on [0, 1];
//! * least squares with end points: the closest one among those keeping both end points.

use blossom::{
    elevate, rational_to_f64, reduce, squared_l2_distance, BezierCurve, Rational, Reduction,
};

pub fn main() {
    let q = |n: i64| Rational::from_integer(n.into());
    let curve =
        |p: &[[i64; 2]]| BezierCurve::new(p.iter().map(|x| x.map(q).to_vec()).collect()).unwrap();

    // A quintic in the plane, reduced to a cubic, exactly.
    let quintic = curve(&[[0, 0], [1, 3], [2, -1], [3, 4], [5, 2], [6, 0]]);
    let mut errors = Vec::new();
    for method in Reduction::ALL {
        let cubic = reduce(&quintic, 3, method).unwrap();
        let e2 = squared_l2_distance(&quintic, &cubic).unwrap();
        println!(
            "{:>24}: squared L2 error {} = {:.3e}",
            method.name(),
            e2,
            rational_to_f64(&e2)
        );
        if method != Reduction::LeastSquares {
            // Both keep the end points.
            assert_eq!(cubic.control_points()[0], quintic.control_points()[0]);
            assert_eq!(cubic.control_points()[3], quintic.control_points()[5]);
        }
        errors.push((method, e2));
    }
    // Least squares is the smallest error of all; with end points kept it is the smallest of
    // the end-point-keeping ones.
    let error = |m: Reduction| errors.iter().find(|(r, _)| *r == m).unwrap().1.clone();
    assert!(error(Reduction::LeastSquares) <= error(Reduction::LeastSquaresEndpoints));
    assert!(error(Reduction::LeastSquaresEndpoints) <= error(Reduction::Interpolating));

    // A cubic written at degree 5 (exact elevation) is reduced back to itself by every method,
    // with error exactly 0.
    let cubic = curve(&[[0, 0], [1, 2], [3, 3], [4, 0]]);
    let elevated = elevate(&cubic, 5).unwrap();
    for method in Reduction::ALL {
        let back = reduce(&elevated, 3, method).unwrap();
        assert_eq!(back, cubic);
        assert_eq!(squared_l2_distance(&elevated, &back).unwrap(), q(0));
    }

    // The same in f64: the error agrees with the exact one.
    let float = BezierCurve::new(
        quintic
            .control_points()
            .iter()
            .map(|p| p.iter().map(rational_to_f64).collect())
            .collect(),
    )
    .unwrap();
    let e2 =
        squared_l2_distance(&float, &reduce(&float, 3, Reduction::LeastSquares).unwrap()).unwrap();
    let want = rational_to_f64(&error(Reduction::LeastSquares));
    assert!((e2 - want).abs() <= 1e-12 * want);
}
