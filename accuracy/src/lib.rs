//! The accuracy harness of blossom (a crate of its own, outside the binary's build): measured
//! error of floating-point restriction against the exact answer: the
//! power-input methods one at a time (this file), and the sweep of every f64 path against
//! the exact answer and a stable reference on the same inputs ([`sweep`], [`mod@reference`]).
//!
//! The input is exact; it is rounded once to f64, restricted in f64 by a method, and each
//! coordinate of the result is compared with the exact restriction of the exact input. The
//! error is relative to the size of the answer: |float - exact| / max(1, max |exact|).

pub mod dyadic;
pub mod reference;
pub mod sweep;

use blossom::rational_to_f64;
use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method,
};
use blossom::{PowerCurve, PowerSurface, Rational};

fn error_of(exact: &[&[Rational]], float: &[Vec<f64>]) -> f64 {
    let scale = exact
        .iter()
        .flat_map(|p| p.iter())
        .map(|x| rational_to_f64(x).abs())
        .fold(1.0f64, f64::max);
    exact
        .iter()
        .zip(float)
        .flat_map(|(e, f)| e.iter().zip(f.iter()))
        .map(|(e, f)| (rational_to_f64(e) - f).abs() / scale)
        .fold(0.0, f64::max)
}

fn to_f64(p: &[Rational]) -> Vec<f64> {
    p.iter().map(rational_to_f64).collect()
}

/// Relative error of `method` in f64 on `curve` restricted to [a, b].
pub fn curve_error(
    curve: &PowerCurve<Rational>,
    a: &Rational,
    b: &Rational,
    method: Method,
) -> f64 {
    let exact = restrict_power_curve(curve, a, b, Method::Bulk);
    let fc = PowerCurve::new(curve.coefficients().iter().map(to_f64).collect())
        .expect("same shape as the exact curve");
    let float = restrict_power_curve(&fc, &rational_to_f64(a), &rational_to_f64(b), method);
    error_of(
        &exact.control_points().iter().collect::<Vec<_>>(),
        &float.control_points().to_vec(),
    )
}

fn surface_to_f64(s: &PowerSurface<Rational>) -> PowerSurface<f64> {
    PowerSurface::new(
        s.coefficients()
            .iter()
            .map(|row| row.iter().map(to_f64).collect())
            .collect(),
    )
    .expect("same shape as the exact surface")
}

/// Relative error of `method` in f64 on `surface` restricted to the rectangle `rect`.
pub fn tensor_error(surface: &PowerSurface<Rational>, rect: &[Rational; 4], method: Method) -> f64 {
    let exact = restrict_power_surface(surface, rect, Method::Bulk);
    let float = restrict_power_surface(
        &surface_to_f64(surface),
        &rect.each_ref().map(rational_to_f64),
        method,
    );
    error_of(
        &exact.points().iter().collect::<Vec<_>>(),
        &float.points().to_vec(),
    )
}

/// Relative error of `method` in f64 on `surface` restricted to the triangle `tri`.
pub fn triangle_error(
    surface: &PowerSurface<Rational>,
    tri: &[[Rational; 2]; 3],
    method: Method,
) -> f64 {
    let exact = restrict_power_surface_to_triangle(surface, tri, Method::Bulk);
    let ftri = tri.each_ref().map(|p| p.each_ref().map(rational_to_f64));
    let float = restrict_power_surface_to_triangle(&surface_to_f64(surface), &ftri, method);
    error_of(
        &exact.control_points().iter().collect::<Vec<_>>(),
        &float.control_points().to_vec(),
    )
}
