//! Shared helpers of the integration tests, root and `cli/` alike: a tiny deterministic PRNG
//! and random inputs, the blossom argument lists, de Casteljau's pyramid as the reference
//! restriction of Bézier input, the rational n / d and the exact value of a double.
//!
//! Each test crate includes this one file (`#[path = ...] mod common;`) and uses part of it.
#![allow(dead_code)]

use blossom::{
    bezier_curve_blossom, bezier_tensor_blossom, bezier_triangle_blossom, BezierCurve, PowerCurve,
    PowerSurface, Rational, Ring, TensorPatch, TriangularPatch,
};
use num_bigint::BigInt;

/// SplitMix64: deterministic, dependency-free.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A rational p/q with |p| <= 20, 1 <= q <= 9.
    pub fn rational(&mut self) -> Rational {
        let p = (self.next() % 41) as i64 - 20;
        let q = (self.next() % 9) as i64 + 1;
        Rational::new(BigInt::from(p), BigInt::from(q))
    }

    /// A double in [-1, 1] on the grid of step 1/1000.
    pub fn unit(&mut self) -> f64 {
        (self.next() % 2001) as f64 / 1000.0 - 1.0
    }

    pub fn point(&mut self, dim: usize) -> Vec<Rational> {
        (0..dim).map(|_| self.rational()).collect()
    }

    pub fn curve(&mut self, n: usize, dim: usize) -> PowerCurve<Rational> {
        PowerCurve::new((0..=n).map(|_| self.point(dim)).collect()).unwrap()
    }

    pub fn surface(&mut self, n: usize, m: usize, dim: usize) -> PowerSurface<Rational> {
        PowerSurface::new(
            (0..=n)
                .map(|_| (0..=m).map(|_| self.point(dim)).collect())
                .collect(),
        )
        .unwrap()
    }
}

/// The blossom argument list `x^k y^l`.
pub fn repeated<X: Clone>(x: &X, k: usize, y: &X, l: usize) -> Vec<X> {
    std::iter::repeat_n(x.clone(), k)
        .chain(std::iter::repeat_n(y.clone(), l))
        .collect()
}

/// q_j = b[a^(n-j), b^j], each point on its own.
pub fn curve_by_pyramid<T: Ring>(curve: &BezierCurve<T>, a: &T, b: &T) -> Vec<Vec<T>> {
    let n = curve.degree();
    (0..=n)
        .map(|j| {
            bezier_curve_blossom(&curve.control_points().to_vec(), &repeated(a, n - j, b, j))
                .unwrap()
        })
        .collect()
}

/// p_(nu mu) = b[a^(n-nu), b^nu; c^(m-mu), d^mu], each point on its own.
pub fn tensor_by_pyramid<T: Ring>(patch: &TensorPatch<T>, rect: &[T; 4]) -> Vec<Vec<Vec<T>>> {
    let (n, m) = patch.degree();
    let [a, b, c, d] = rect;
    (0..=n)
        .map(|nu| {
            (0..=m)
                .map(|mu| {
                    bezier_tensor_blossom(
                        &patch.to_nested(),
                        &repeated(a, n - nu, b, nu),
                        &repeated(c, m - mu, d, mu),
                    )
                    .unwrap()
                })
                .collect()
        })
        .collect()
}

/// q_(nu mu lambda) = b[A^nu, B^mu, C^lambda], each point on its own, in the net's order.
pub fn triangle_by_pyramid<T: Ring>(
    patch: &TriangularPatch<T>,
    corners: &[[T; 3]; 3],
) -> Vec<Vec<T>> {
    patch
        .entries()
        .map(|(nu, mu, la, _)| {
            let args: Vec<[T; 3]> = std::iter::repeat_n(corners[0].clone(), nu)
                .chain(std::iter::repeat_n(corners[1].clone(), mu))
                .chain(std::iter::repeat_n(corners[2].clone(), la))
                .collect();
            bezier_triangle_blossom(patch, &args).unwrap()
        })
        .collect()
}

/// The rational n / d.
pub fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// The exact value of a double (finite by construction in the tests).
pub fn exact(x: f64) -> Rational {
    Rational::from_float(x).expect("a finite double")
}

/// The exact values of a list of points of doubles.
pub fn exact_points(points: &[Vec<f64>]) -> Vec<Vec<Rational>> {
    points
        .iter()
        .map(|p| p.iter().map(|&x| exact(x)).collect())
        .collect()
}

/// The restriction of `patch` to the sub-triangle whose corners the tests give by all three
/// barycentric coordinates, through the library's one convention: affine coordinates [s, t]
/// (the third coordinate is implied).
pub fn restrict_bary<T: Ring>(
    patch: &TriangularPatch<T>,
    corners: &[[T; 3]; 3],
) -> TriangularPatch<T> {
    patch.restrict(&corners.each_ref().map(|[s, t, _]| [s.clone(), t.clone()]))
}
