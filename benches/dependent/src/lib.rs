//! What the timing binaries of this crate share: the random numbers and the textbook split.

/// xorshift64*, uniform doubles in [0, 1).
pub struct Rng(pub u64);

impl Rng {
    /// The next double in [0, 1).
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The textbook restriction to [a, b] (0 < b) of a curve held in a fixed-size array, as a user
/// writes it: de Casteljau at b keeping the left part, then at a / b keeping the right part.
/// The compiler unrolls it for each N and D.
pub fn textbook<const N: usize, const D: usize>(
    ctrl: &[[f64; D]; N],
    a: f64,
    b: f64,
) -> [[f64; D]; N] {
    let mut out = *ctrl;
    for r in 1..N {
        for i in (r..N).rev() {
            let (low, high) = out.split_at_mut(i);
            for (y, x) in high[0].iter_mut().zip(&low[i - 1]) {
                *y = x + b * (*y - x);
            }
        }
    }
    let t = a / b;
    for r in 1..N {
        for i in 0..N - r {
            let (low, high) = out.split_at_mut(i + 1);
            for (x, y) in low[i].iter_mut().zip(&high[0]) {
                *x += t * (y - *x);
            }
        }
    }
    out
}
