//! The one pseudo-random generator of the library's unit tests: xorshift64 (Marsaglia,
//! shifts 13, 7, 17), deterministic from its seed. Each test module keeps its own sampling
//! methods (`below`, `small`, `int`, ...) on top of [`XorShift::next`].

/// Xorshift64 state; the seed must be non-zero.
pub(crate) struct XorShift(pub(crate) u64);

impl XorShift {
    /// The next 64 pseudo-random bits.
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}
