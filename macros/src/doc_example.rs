fn main() {
    use blossom::Rational;

    blossom::restriction! {
        /// The cubic restriction of eq. (3).
        vis = pub,
        name = restrict_cubic,
        shape = curve,
        degree = 3,
    }

    blossom::restriction!(name = restrict_patch, shape = tensor, degree = (2, 1));
    blossom::restriction!(name = restrict_tri, shape = triangle, degree = (1, 1));

    // C(u) = u^3 on [1, 2]: control points 1, 2, 4, 8 (the blossom b(2^v, 1^(3-v)) = 2^v).
    let coef = [[0.0], [0.0], [0.0], [1.0]];
    assert_eq!(restrict_cubic(&coef, &1.0, &2.0), [[1.0], [2.0], [4.0], [8.0]]);

    // The same function runs exactly on rationals, with 2-D points.
    let q = |n: i64| Rational::from_integer(n.into());
    let coef = [[q(1), q(0)], [q(0), q(1)], [q(0), q(0)], [q(1), q(0)]];
    let w = restrict_cubic(&coef, &q(0), &q(1));
    assert_eq!(w[3], [q(2), q(1)]); // C(1) = c0 + c1 + c2 + c3

    // S(u, v) = u v on [0, 1] x [0, 1]: p_(nu mu) = (nu / 2) mu.
    let mut c = [[[0.0]; 2]; 3];
    c[1][1] = [1.0];
    let p = restrict_patch(&c, &[0.0, 1.0, 0.0, 1.0]);
    assert_eq!(p, [[[0.0], [0.0]], [[0.0], [0.5]], [[0.0], [1.0]]]);

    // S(u, v) = u on the triangle a = (1, 0), b = (0, 1), c = (0, 0): q = blossom of u.
    let mut c = [[[0.0]; 2]; 2];
    c[1][0] = [1.0];
    let q = restrict_tri(&c, &[[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]);
    // (nu, mu) = (0,0), (0,1), (0,2), (1,0), (1,1), (2,0)
    assert_eq!(q, [[0.0], [0.0], [0.0], [0.5], [0.5], [1.0]]);

    // Bézier input: the cubic with control points (0,0), (1,2), (3,3), (4,0) on [0, 1/2] is its
    // left half by de Casteljau: (0,0), (1/2,1), (5/4,7/4), (2,15/8).
    blossom::restriction!(name = split_cubic, shape = bezier_curve, degree = 3);
    let ctrl = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]];
    let left = split_cubic(&ctrl, &0.0, &0.5);
    assert_eq!(left, [[0.0, 0.0], [0.5, 1.0], [1.25, 1.75], [2.0, 1.875]]);
}
