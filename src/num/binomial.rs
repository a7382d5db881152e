//! Exact binomial and multinomial coefficients as big integers, zero outside their range.
//!
//! The closed forms (3), (9), (14) sum products of binomials over index ranges; with the
//! convention `C(n, k) = 0` for `k < 0` or `k > n` a sum may run over a wider range than the
//! paper's bounds without changing its value, which is how the printed bound variants are
//! compared in `src/verify/formula_versions.rs`.

use num_bigint::BigInt;
use num_traits::{One, Zero};

/// `C(n, k)`, exactly; zero when `k < 0`, `k > n` or `n < 0`.
pub fn binomial(n: i64, k: i64) -> BigInt {
    if n < 0 || k < 0 || k > n {
        return BigInt::zero();
    }
    let k = k.min(n - k);
    crate::num::meter::charge_binomial(n, k);
    let mut acc = BigInt::one();
    for i in 0..k {
        // acc = C(n, i) * (n - i) / (i + 1), exact at every step.
        acc = acc * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    acc
}

/// The multinomial `n! / (k_1! ... k_r! (n - k_1 - ... - k_r)!)`, exactly; zero when any part
/// is negative or the parts exceed `n`.
pub fn multinomial(n: i64, parts: &[i64]) -> BigInt {
    let mut rest = n;
    let mut acc = BigInt::one();
    for &k in parts {
        acc *= binomial(rest, k);
        if k < 0 {
            return BigInt::zero();
        }
        rest -= k;
    }
    if rest < 0 {
        BigInt::zero()
    } else {
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials_follow_pascal_and_vanish_outside() {
        for n in 1..30i64 {
            for k in 0..=n {
                assert_eq!(
                    binomial(n, k),
                    binomial(n - 1, k - 1) + binomial(n - 1, k),
                    "C({n},{k})"
                );
            }
            assert_eq!(binomial(n, -1), BigInt::zero());
            assert_eq!(binomial(n, n + 1), BigInt::zero());
        }
        assert_eq!(binomial(64, 32).to_string(), "1832624140942590534");
        assert_eq!(
            binomial(100, 50).to_string(),
            "100891344545564193334812497256"
        );
    }

    #[test]
    fn multinomials_match_factorials() {
        // 6! / (1! 2! 3!) = 60
        assert_eq!(multinomial(6, &[1, 2]), BigInt::from(60));
        assert_eq!(multinomial(5, &[2, 2]), BigInt::from(30));
        assert_eq!(multinomial(3, &[2, 2]), BigInt::zero());
        assert_eq!(multinomial(3, &[-1, 2]), BigInt::zero());
    }
}

/// The meter's charge for binomials against their time (the companion of the meter's own
/// calibration table, `num::meter`).
#[cfg(all(test, feature = "meter"))]
mod calibration {
    use super::binomial;
    use crate::num::meter::tests::time;
    use crate::num::meter::{charged, metered};

    /// Prints the time of a binomial's steps next to their charge (units are meant to be
    /// about a nanosecond). Run on request: `cargo test --release -p blossom --lib --features
    /// meter binomial_calibration -- --ignored --nocapture`.
    #[test]
    #[ignore = "a timing table; run on request in release"]
    fn binomial_calibration() {
        for n in [16i64, 64, 256, 1000] {
            let reps = 20_000;
            let mut sink = num_bigint::BigInt::from(0);
            let t = time(reps, &mut || sink = binomial(n, n / 2));
            std::hint::black_box(&sink);
            let before = charged();
            let units = metered(u64::MAX, || {
                binomial(n, n / 2);
                charged()
            })
            .unwrap()
                - before;
            println!(
                "C({n}, {}): {:.1} ns a step, charged {:.1} units a step",
                n / 2,
                t / (n / 2) as f64,
                units as f64 / (n / 2) as f64
            );
        }
    }
}
