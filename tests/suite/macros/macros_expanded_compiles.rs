//! The source printed by `blossom expand` compiles on its own in a crate that depends on
//! `blossom` only: the files in `tests/macros_expanded/` (exactly what `expand_source` prints,
//! checked by `cli/tests/grid/expanded_files.rs`) are compiled here by `include!` and run
//! against the closed form.

use crate::common::q;
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
    PowerCurve, PowerSurface, Rational,
};

mod expanded {
    include!("../../macros_expanded/curve_3.rs");
    include!("../../macros_expanded/tensor_3_2.rs");
    include!("../../macros_expanded/triangle_3_2.rs");
}

#[test]
fn the_printed_functions_compute_the_closed_form() {
    let coef: [[Rational; 2]; 4] =
        std::array::from_fn(|i| [q(i as i64 + 1, 3), q(2 - i as i64, 5)]);
    let curve = PowerCurve::new(coef.iter().map(|p| p.to_vec()).collect()).unwrap();
    let (a, b) = (q(-1, 2), q(7, 3));
    let w = expanded::restrict_curve_3(&coef, &a, &b);
    let want = restrict_power_curve(&curve, &a, &b, Method::ClosedForm);
    assert_eq!(w.map(|p| p.to_vec()).to_vec(), want.control_points());

    let coef: [[[Rational; 1]; 3]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| [q(i as i64 * 3 - j as i64, 7)]));
    let surface = PowerSurface::new(
        coef.iter()
            .map(|r| r.iter().map(|p| p.to_vec()).collect())
            .collect(),
    )
    .unwrap();
    let rect = [q(1, 3), q(2, 3), q(1, 4), q(3, 4)];
    let p = expanded::restrict_tensor_3_2(&coef, &rect);
    let want = restrict_power_surface(&surface, &rect, Method::ClosedForm);
    let got: Vec<Vec<Vec<Rational>>> = p
        .iter()
        .map(|r| r.iter().map(|x| x.to_vec()).collect())
        .collect();
    assert_eq!(got, want.to_nested());

    let tri = [[q(0, 1), q(1, 2)], [q(1, 2), q(0, 1)], [q(1, 2), q(1, 2)]];
    let t = expanded::restrict_triangle_3_2(&coef, &tri);
    let want = restrict_power_surface_to_triangle(&surface, &tri, Method::ClosedForm);
    assert_eq!(t.map(|p| p.to_vec()).to_vec(), want.control_points());
}
