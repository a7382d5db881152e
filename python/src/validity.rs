//! `Triangle.is_valid`, decided exactly: a planar triangle is valid when the Jacobian
//! J(s, t) = x_s y_t - x_t y_s of its map from the reference triangle is positive on the whole
//! closed triangle (bezier's definition; bezier decides it in float64 for degrees 1 to 3 only).
//!
//! J is a polynomial of degree 2(n - 1); its Bernstein coefficients over a triangle are computed
//! exactly (the derivatives by the library, their product by the Bernstein product rule
//! c_(a + b) += C(p; a) C(q; b) / C(p + q; a + b) u_a v_b with trinomials C). A vertex
//! coefficient is J's value there, so one that is <= 0 proves "invalid"; all coefficients > 0
//! prove J > 0 on that triangle (a convex combination). Otherwise the triangle is split into its
//! four midpoint sub-triangles (exactly, by the library's restriction) and each is examined.
//! When J > 0 on the closed triangle the coefficients converge to its values and the process
//! ends; when J < 0 somewhere a vertex of some sub-triangle eventually sees it. Only a J >= 0
//! that touches 0 at a non-dyadic point without changing sign is never decided: after
//! [`MAX_PIECES`] sub-triangles the answer is `None`.

use blossom::engine::multinomial;
use blossom::{bezier_triangle_derivative, Error, ErrorKind, Rational, TriangularPatch};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The most sub-triangles examined before giving up.
pub const MAX_PIECES: usize = 1 << 14;

/// The coefficient of each point of a scalar patch, in the library's order.
fn scalar_product(a: &[Rational], n: usize, b: &[Rational], m: usize) -> TriangularPatch<Rational> {
    let order = |n: usize| -> Vec<(usize, usize)> {
        (0..=n)
            .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
            .collect()
    };
    let tri = |n: usize, i: usize, j: usize| {
        multinomial(n as i64, &[i as i64, j as i64, (n - i - j) as i64])
    };
    let out_order = order(n + m);
    let index = |i: usize, j: usize| {
        out_order
            .iter()
            .position(|&p| p == (i, j))
            .expect("in range")
    };
    let mut out = vec![Rational::zero(); out_order.len()];
    for (&(i, j), u) in order(n).iter().zip(a) {
        if u.is_zero() {
            continue;
        }
        for (&(k, l), v) in order(m).iter().zip(b) {
            let w = Rational::new(tri(n, i, j) * tri(m, k, l), tri(n + m, i + k, j + l));
            out[index(i + k, j + l)] += w * u * v;
        }
    }
    TriangularPatch::from_coordinates(n + m, 1, out).expect("the product's size")
}

/// Component `x` of every point of a planar patch.
fn component(p: &TriangularPatch<Rational>, x: usize) -> Vec<Rational> {
    p.control_points()
        .into_iter()
        .map(|q| q[x].clone())
        .collect()
}

/// The Jacobian of a planar patch of degree n >= 1, as a scalar patch of degree 2(n - 1).
fn jacobian(p: &TriangularPatch<Rational>) -> Result<TriangularPatch<Rational>, Error> {
    let one = Rational::one;
    let d_s = bezier_triangle_derivative(p, &[vec![one(), Rational::zero(), -one()]])?;
    let d_t = bezier_triangle_derivative(p, &[vec![Rational::zero(), one(), -one()]])?;
    let k = p.degree() - 1;
    let a = scalar_product(&component(&d_s, 0), k, &component(&d_t, 1), k);
    let b = scalar_product(&component(&d_s, 1), k, &component(&d_t, 0), k);
    let diff = a
        .coordinates()
        .iter()
        .zip(b.coordinates())
        .map(|(x, y)| x - y)
        .collect();
    TriangularPatch::from_coordinates(2 * k, 1, diff)
}

/// Whether the planar patch is valid (J > 0 on the closed reference triangle), or `None` when
/// undecided after [`MAX_PIECES`] sub-triangles.
///
/// # Errors
/// [`ErrorKind::Dimension`] on `self.nodes` for a patch that is not planar.
pub fn is_valid(p: &TriangularPatch<Rational>) -> Result<Option<bool>, Error> {
    if p.dim() != 2 {
        return Err(Error::of(
            ErrorKind::Dimension,
            "self.nodes",
            format!(
                "validity is defined for planar triangles (dimension 2), found dimension {}",
                p.dim()
            ),
        ));
    }
    if p.degree() == 0 {
        return Ok(Some(false));
    }
    let half = Rational::new(BigInt::one(), BigInt::from(2));
    let zero = Rational::zero;
    let one = Rational::one;
    // Sub-triangles as the library's corners: the images of (1, 0), (0, 1), (0, 0).
    let quarters = [
        [
            [half.clone(), zero()],
            [zero(), half.clone()],
            [zero(), zero()],
        ],
        [
            [zero(), half.clone()],
            [half.clone(), zero()],
            [half.clone(), half.clone()],
        ],
        [
            [one(), zero()],
            [half.clone(), half.clone()],
            [half.clone(), zero()],
        ],
        [
            [half.clone(), half.clone()],
            [zero(), one()],
            [zero(), half.clone()],
        ],
    ];
    let mut pending = vec![jacobian(p)?];
    let mut examined = 0;
    while let Some(j) = pending.pop() {
        examined += 1;
        if examined > MAX_PIECES {
            return Ok(None);
        }
        let m = j.degree();
        let vertices = [j.get(m, 0), j.get(0, m), j.get(0, 0)];
        if vertices.iter().any(|v| !v[0].is_positive()) {
            return Ok(Some(false));
        }
        if j.coordinates().iter().all(Signed::is_positive) {
            continue;
        }
        for q in &quarters {
            pending.push(j.restrict(q));
        }
    }
    Ok(Some(true))
}
