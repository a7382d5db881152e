//! Exact combinatorial constants, folded at expansion time into reduced rational literals.
//!
//! Everything is computed in `u128` with checked arithmetic: a constant that does not fit is an
//! error (never a silent wrap), and the degree limits ([`crate::MAX_CURVE_DEGREE`] and the others of [`crate::model`]) keep every constant
//! far below that bound.

/// `C(n, k)`, exactly; `Some(0)` when `k > n`, `None` on overflow.
pub fn binomial(n: u64, k: u64) -> Option<u128> {
    if k > n {
        return Some(0);
    }
    let k = k.min(n - k);
    let mut acc: u128 = 1;
    for i in 0..u128::from(k) {
        // acc = C(n, i) (n - i) / (i + 1): exact at every step.
        acc = acc.checked_mul(u128::from(n) - i)? / (i + 1);
    }
    Some(acc)
}

/// `N! / (i! j! (N - i - j)!)`, the denominator of eq. (13)/(14); `None` on overflow.
pub fn trinomial(big_n: u64, i: u64, j: u64) -> Option<u128> {
    // N! / (i! j! (N-i-j)!) = C(N, i) C(N - i, j).
    binomial(big_n, i)?.checked_mul(binomial(big_n.checked_sub(i)?, j)?)
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// A positive rational constant `num / den` in lowest terms, both fitting in `i128` (the
/// argument type of `Ring::scale_frac`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frac {
    /// Numerator, `> 0`.
    pub num: i128,
    /// Denominator, `> 0`.
    pub den: i128,
}

impl Frac {
    /// `num / den` reduced; `None` when `den == 0` or a reduced part exceeds `i128::MAX`.
    pub fn new(num: u128, den: u128) -> Option<Frac> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den).max(1);
        Some(Frac {
            num: i128::try_from(num / g).ok()?,
            den: i128::try_from(den / g).ok()?,
        })
    }

    /// Whether the constant is exactly 1 (then no `scale_frac` is emitted).
    pub fn is_one(self) -> bool {
        self.num == 1 && self.den == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials_are_exact() {
        assert_eq!(binomial(5, 2), Some(10));
        assert_eq!(binomial(5, 6), Some(0));
        assert_eq!(binomial(0, 0), Some(1));
        assert_eq!(binomial(64, 32), Some(1_832_624_140_942_590_534));
        assert_eq!(
            binomial(100, 50),
            Some(100_891_344_545_564_193_334_812_497_256)
        );
        assert_eq!(binomial(140, 70), None);
        assert_eq!(trinomial(5, 1, 1), Some(20));
    }

    #[test]
    fn fractions_are_reduced() {
        assert_eq!(Frac::new(6, 4), Some(Frac { num: 3, den: 2 }));
        assert!(Frac::new(3, 3).unwrap().is_one());
        assert_eq!(Frac::new(1, 0), None);
        assert_eq!(Frac::new(u128::MAX, 1), None);
    }
}
