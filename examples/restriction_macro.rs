//! The restriction of example `restrict_runtime_degree`, for a degree known at compile time,
//! by the functions that `blossom::restriction!` generates: eq. (3) unrolled for that degree,
//! on fixed-size arrays, generic over the number type.
//!
//! `cargo run -p blossom --example restriction_macro`.

use blossom::{restrict_power_curve, BezierCurve, Method, PowerCurve, Rational, Ring};

// C(u) = sum_i c_i u^i of degree 5 on [a, b]: fn(&[[T; D]; 6], &T, &T) -> [[T; D]; 6], whose
// entry v is w_v = blossom(a^(5-v), b^v).
blossom::restriction!(name = restrict_quintic, shape = curve, degree = 5);

// A Bézier cubic over [0, 1] on [a, b]: the engine's de Casteljau steps, unrolled.
blossom::restriction!(name = split_cubic, shape = bezier_curve, degree = 3);

/// c_i = (1, (-1)^i / (i + 1)), the coefficients of `restrict_runtime_degree` at degree 5.
fn coefficients<T: Ring>() -> [[T; 2]; 6] {
    std::array::from_fn(|i| {
        let y = Rational::new(
            (if i % 2 == 0 { 1 } else { -1 }).into(),
            (i as i64 + 1).into(),
        );
        [T::one(), T::from_rational(&y)]
    })
}

pub fn main() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());

    // Exactly: the generated function equals the library's runtime-degree restriction.
    let (a, b) = (q(1, 4), q(3, 4));
    let w = restrict_quintic(&coefficients::<Rational>(), &a, &b);
    let c = PowerCurve::new(coefficients::<Rational>().map(Vec::from).to_vec()).unwrap();
    let runtime = restrict_power_curve(&c, &a, &b, Method::Bulk);
    assert_eq!(
        runtime.control_points(),
        w.clone().map(Vec::from).as_slice()
    );

    // In f64: the same function, another number type.
    let wf = restrict_quintic(&coefficients::<f64>(), &0.25, &0.75);
    for (p, q) in wf.iter().zip(&w) {
        for (x, y) in p.iter().zip(q) {
            assert!((x - blossom::rational_to_f64(y)).abs() <= 1e-14);
        }
    }
    println!(
        "quintic on [1/4, 3/4]: w_0 = {:?}",
        w[0].each_ref().map(|x| x.to_string())
    );

    // Bézier input: the left half of a cubic is de Casteljau's, bit for bit the engine's.
    let ctrl = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]];
    let left = split_cubic(&ctrl, &0.0, &0.5);
    let cubic = BezierCurve::new(ctrl.map(Vec::from).to_vec()).unwrap();
    let engine = cubic.subsegment(0.0..0.5);
    assert_eq!(engine.control_points(), left.map(Vec::from).as_slice());
    assert_eq!(left[3].to_vec(), cubic.eval(&0.5));
    println!("left half of the cubic: {left:?}");
}
