//! What the benches share: one deterministic generator of inputs, and the cubic of the
//! comparisons with lyon as lyon_geom's segment.

/// SplitMix64 in [0, 1).
pub struct Rng(pub u64);

impl Rng {
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A 3-D point in [-1, 1]^3.
    #[allow(dead_code)]
    pub fn point(&mut self) -> [f64; 3] {
        std::array::from_fn(|_| 2.0 * self.unit() - 1.0)
    }
}

/// The cubic with control points `c` as lyon_geom's segment (the peer of the intersection
/// comparisons).
#[allow(dead_code)]
pub fn lyon_cubic(c: &[[f64; 2]; 4]) -> lyon_geom::CubicBezierSegment<f64> {
    let p = |i: usize| lyon_geom::point(c[i][0], c[i][1]);
    lyon_geom::CubicBezierSegment {
        from: p(0),
        ctrl1: p(1),
        ctrl2: p(2),
        to: p(3),
    }
}
