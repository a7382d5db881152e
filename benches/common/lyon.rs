//! The cubic of the comparisons with lyon as lyon_geom's segment (for the benches and examples
//! that depend on lyon_geom; included by path).

/// The cubic with control points `c` as lyon_geom's segment.
pub fn lyon_cubic(c: &[[f64; 2]; 4]) -> lyon_geom::CubicBezierSegment<f64> {
    let p = |i: usize| lyon_geom::point(c[i][0], c[i][1]);
    lyon_geom::CubicBezierSegment {
        from: p(0),
        ctrl1: p(1),
        ctrl2: p(2),
        to: p(3),
    }
}
