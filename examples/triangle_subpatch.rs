//! A triangular Bézier patch restricted to a sub-triangle, exactly and in f64.
//!
//! `cargo run -p blossom --example triangle_subpatch`.
//!
//! A patch of degree N over its triangle, in barycentric coordinates (s, t, r), s + t + r = 1,
//! restricted to the sub-triangle with corners A, B, C is the patch of degree N with control
//! points q_(nu mu lambda) = b[A^nu, B^mu, C^lambda], b the blossom (eq. (12) of the
//! subdivision paper): the same surface, reparametrised so that the point (σ, τ, ρ) of the new
//! patch is σ A + τ B + ρ C. Every point of the domain is given by its affine coordinates
//! [s, t] (r = 1 - s - t is implied), the one convention of the library's triangles.

use blossom::{rational_to_f64, BezierTriangle, Rational, TriangularPatch};

pub fn main() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let int = |v: [i64; 3]| v.map(|x| q(x, 1)).to_vec();

    // A quadratic patch in 3-D; points in lexicographic order of (nu, mu):
    // (0,0) (0,1) (0,2) (1,0) (1,1) (2,0).
    let net = [
        [0, 0, 0],
        [1, 2, 0],
        [2, 0, 1],
        [0, 1, 3],
        [1, 1, 1],
        [0, 2, 2],
    ];
    let patch = TriangularPatch::new(2, net.map(int).to_vec()).unwrap();

    // The sub-triangle A = (1/2, 1/4, 1/4), B = (1/4, 1/2, 1/4), C = (1/4, 1/4, 1/2), by
    // [s, t].
    let corners = [[q(1, 2), q(1, 4)], [q(1, 4), q(1, 2)], [q(1, 4), q(1, 4)]];
    let sub = patch.restrict(&corners);

    // Its corner control points are the patch's points at A, B, C ...
    assert_eq!(sub.get(2, 0), &patch.eval(&corners[0]));
    assert_eq!(sub.get(0, 2), &patch.eval(&corners[1]));
    assert_eq!(sub.get(0, 0), &patch.eval(&corners[2]));
    // ... and everywhere it is the same surface: sub(σ, τ, ρ) = patch(σ A + τ B + ρ C).
    for at in [[q(1, 3), q(1, 3)], [q(1, 2), q(0, 1)], [q(1, 5), q(3, 5)]] {
        let bary = [at[0].clone(), at[1].clone(), q(1, 1) - &at[0] - &at[1]];
        let point: [Rational; 2] =
            std::array::from_fn(|k| (0..3).fold(q(0, 1), |acc, c| acc + &bary[c] * &corners[c][k]));
        assert_eq!(sub.eval(&at), patch.eval(&point));
    }
    println!(
        "exact sub-patch: q_110 = {:?}",
        sub.get(1, 1)
            .iter()
            .map(|x| x.to_string())
            .collect::<Vec<_>>()
    );

    // In f64, with fixed-dimension points: the same corners.
    let float = BezierTriangle::new(2, net.map(|p| p.map(|x| x as f64)).to_vec()).unwrap();
    let sub_f = float.restrict(&[[0.5, 0.25], [0.25, 0.5], [0.25, 0.25]]);
    for (p, want) in sub_f.points().iter().zip(sub.control_points()) {
        for (x, y) in p.iter().zip(want) {
            assert!((x - rational_to_f64(y)).abs() <= 1e-15 * (1.0 + x.abs()));
        }
    }
    println!("f64 sub-patch: {:?}", sub_f.points());
}
