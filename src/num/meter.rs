//! Work metering: a budget of work units, charged by the arithmetic as it is done, that stops
//! a computation when it is spent (feature `meter`, off by default).
//!
//! # What is charged
//!
//! One unit is about a nanosecond of the machine the constants were measured on (a 2-core
//! x86-64; `meter_calibration` below prints the measured time of each charged operation next
//! to its charge). Every operation of the two number types the command line computes in
//! charges *before* it computes, so that one huge operation is refused before it runs:
//!
//! * [`Rational`] (the [`Ring`](crate::Ring) and [`Field`](crate::Field) operations):
//!   [`RATIONAL_OPERATION`] plus, for operands of `s` bits together (numerators and
//!   denominators of both; num-bigint's `bits()` reports each length in O(1)), `25 s + s^2 /
//!   1024` units for a product or quotient ([`rational_cost`]) and `10 s + s^2 / 2048` for a
//!   sum or difference ([`rational_sum_cost`]). The gcd that keeps a result in lowest terms
//!   dominates; measured in CPU time, a product costs about 25 ns per bit up to a few thousand
//!   bits and a sum about half that, growing faster beyond;
//! * [`BoundedF64`](crate::BoundedF64): [`BOUNDED_OPERATION`] per operation; `scale` and
//!   `from_rational` also charge the building of the exact constant from its length (the algorithms
//!   build their constants, with a gcd each, right before they use them, and the conversion to
//!   the nearest double is itself a big division);
//! * [`binomial`](crate::engine::binomial): its `k` steps, each a product and an exact quotient;
//! * the pyramids of `shape/bezier.rs` (the blossom of a Bézier curve, tensor or triangular
//!   patch): [`POINT_ALLOCATION`] for every point they allocate (the sweep found the `f64`
//!   pyramid running three times as long as its arithmetic's charge without it).
//!
//! * the exact methods of the certified intersections, which compute with big integers and
//!   word-size residues directly: [`INTEGER_OPERATION`] plus [`INTEGER_WORD`] a word for each
//!   sum of big integers ([`integer_sums_cost`]: Descartes' halvings, Taylor shifts),
//!   [`INTEGER_OPERATION`] plus half a unit a pair of words for each product
//!   ([`integer_products_cost`]: sign evaluation at rationals and interval enclosures,
//!   pseudo-remainders, exact divisions, polynomial products), [`WORD_OPERATION`] a step of
//!   the modular resultants (evaluation, Euclid, interpolation, reconstruction), and
//!   `fibre_work` for the arithmetic in an algebraic extension. Measured against the CPU time
//!   of whole `blossom intersect` jobs (2026-12-07): 1.1 to 1.5 units per ns on curve pairs of
//!   degree 16-21, 1.8 on degree-200 `roots` jobs with long fractions (mostly rational
//!   arithmetic, charged as above).
//!
//! `f64`, `f32` and [`Poly`](crate::Poly) charge nothing. Code that computes with big rationals
//! through their operators instead of [`Ring`](crate::Ring) charges the same cost through
//! [`charge_rational`] (the exact matrix inverse and products of `num/linalg.rs`); the
//! constants the algorithms build from binomials (`Rational::new(binomial(..), ..)`) are not
//! charged themselves, but every one of them is used by a charged `scale` right after.
//!
//! # Starting and stopping
//!
//! With no meter started on the thread, a charge is one read of a thread-local cell: library
//! users and the library's own tests are unaffected. [`metered`] starts a meter with a limit,
//! runs a computation and returns its value, or [`OverBudget`] when a charge passed the limit:
//! that charge unwinds with [`std::panic::resume_unwind`] (which does not run the panic hook;
//! salsa's cancellation uses the same pattern), and [`metered`] catches exactly that payload
//! (any other panic goes on unwinding). Without the feature the charges compile to nothing.

// Without the feature the charges are no-ops and the rest is unused.
#![cfg_attr(not(feature = "meter"), allow(dead_code))]

use crate::Rational;

/// Units charged by one operation of [`BoundedF64`](crate::BoundedF64).
pub const BOUNDED_OPERATION: u64 = 5;

/// Units charged for a new point (a vector's allocation and release) in the pyramids of
/// `shape/bezier.rs`, whose work in `f64` is as much in the allocations as in the arithmetic.
pub const POINT_ALLOCATION: u64 = 40;

/// Units charged by one operation of [`Rational`] on short operands (allocation, the gcd of
/// word-sized numbers).
pub const RATIONAL_OPERATION: u64 = 150;

/// The charge of one product or quotient of big rationals of `a` and `b` bits (numerator and
/// denominator together): `RATIONAL_OPERATION + 25 s + s^2 / 1024`, `s = a + b`.
#[inline]
pub fn rational_cost(a: u64, b: u64) -> u64 {
    let s = a.saturating_add(b);
    RATIONAL_OPERATION
        .saturating_add(s.saturating_mul(25))
        .saturating_add(s.saturating_mul(s) / 1024)
}

/// The charge of one sum or difference of big rationals of `a` and `b` bits:
/// `RATIONAL_OPERATION + 10 s + s^2 / 2048`, `s = a + b` (measured at about half a product's).
#[inline]
pub fn rational_sum_cost(a: u64, b: u64) -> u64 {
    let s = a.saturating_add(b);
    RATIONAL_OPERATION
        .saturating_add(s.saturating_mul(10))
        .saturating_add(s.saturating_mul(s) / 2048)
}

/// The charge of building the exact constant `k` (its reduction to lowest terms) and
/// converting it to the nearest double, the work of a `BoundedF64` operation with an exact
/// constant: the algorithms build their constants (binomials over binomials, the weights of
/// the polarisation formula) right before they use them. Measured (`meter_calibration`,
/// `Rational::new` of a power of 7 over powers of 2 and 3): 330 ns at 28 bits, 3.4 us at 432,
/// 55 us at 6903, about 300 + 8 s ns for s bits; the charge `300 + 10 s + s^2 / 4096` is 1.4
/// to 1.8 times that. (It was a product's charge, `RATIONAL_OPERATION + 25 s + s^2 / 1024`,
/// three times the cost: the budget sweep found `f64` jobs of the closed form and the
/// polarisation formula charged 2.2 to 2.6 units per ns, so that a job of 0.45 s was
/// refused under the default limit.)
#[inline]
fn constant_cost(k_bits: u64) -> u64 {
    BOUNDED_OPERATION
        .saturating_add(300)
        .saturating_add(k_bits.saturating_mul(10))
        .saturating_add(k_bits.saturating_mul(k_bits) / 4096)
}

/// The length of `k` in bits, numerator and denominator together.
#[inline]
fn bits(k: &Rational) -> u64 {
    k.numer().bits() + k.denom().bits()
}

/// A computation stopped by [`metered`]: its charges passed the limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OverBudget {
    /// The limit the meter was started with.
    pub limit: u64,
    /// The units charged when it stopped (the last charge, that passed the limit, included).
    pub charged: u64,
}

impl std::fmt::Display for OverBudget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the work passed the limit of {} units ({} charged)",
            self.limit, self.charged
        )
    }
}

impl std::error::Error for OverBudget {}

#[cfg(feature = "meter")]
mod active {
    use super::OverBudget;
    use std::cell::Cell;

    /// The value of [`LEFT`] when no meter runs.
    pub(super) const OFF: u64 = u64::MAX;

    thread_local! {
        /// The units the running meter still allows, [`OFF`] when none runs.
        pub(super) static LEFT: Cell<u64> = const { Cell::new(OFF) };
        /// The limit of the running meter.
        pub(super) static LIMIT: Cell<u64> = const { Cell::new(OFF) };
    }

    /// Whether a meter runs on this thread.
    #[inline(always)]
    pub(super) fn on() -> bool {
        LEFT.with(Cell::get) != OFF
    }

    /// Charges `units`, stopping the computation when they pass what is left.
    #[inline(always)]
    pub(super) fn charge(units: u64) {
        LEFT.with(|left| {
            let l = left.get();
            if l != OFF {
                if units > l {
                    over(units - l);
                }
                left.set(l - units);
            }
        });
    }

    /// Stops the computation: `excess` units over the limit were charged.
    #[cold]
    #[inline(never)]
    fn over(excess: u64) -> ! {
        let limit = LIMIT.with(Cell::get);
        LEFT.with(|left| left.set(0));
        std::panic::resume_unwind(Box::new(OverBudget {
            limit,
            charged: limit.saturating_add(excess),
        }))
    }
}

/// Charges `units` of work to the meter running on this thread, if any; stops the computation
/// (see [`metered`]) when they pass its limit.
#[inline(always)]
pub fn charge_work(units: u64) {
    #[cfg(feature = "meter")]
    active::charge(units);
    #[cfg(not(feature = "meter"))]
    let _ = units;
}

/// The units charged so far by the meter running on this thread (0 when none runs).
#[cfg(feature = "meter")]
pub fn charged() -> u64 {
    let left = active::LEFT.with(std::cell::Cell::get);
    if left == active::OFF {
        0
    } else {
        active::LIMIT
            .with(std::cell::Cell::get)
            .min(active::OFF - 1)
            - left.min(active::OFF - 1)
    }
}

/// Charges one product or quotient of the big rationals `a` and `b` ([`rational_cost`]).
#[inline(always)]
pub fn charge_rational(a: &Rational, b: &Rational) {
    #[cfg(feature = "meter")]
    if active::on() {
        active::charge(rational_cost(bits(a), bits(b)));
    }
    #[cfg(not(feature = "meter"))]
    let _ = (a, b);
}

/// Charges one sum or difference of the big rationals `a` and `b` ([`rational_sum_cost`]).
#[inline(always)]
pub fn charge_rational_sum(a: &Rational, b: &Rational) {
    #[cfg(feature = "meter")]
    if active::on() {
        active::charge(rational_sum_cost(bits(a), bits(b)));
    }
    #[cfg(not(feature = "meter"))]
    let _ = (a, b);
}

/// Units of one in-place sum or difference of big integers, per 64-bit word of the longer
/// operand, beside [`INTEGER_OPERATION`] for the call.
pub const INTEGER_WORD: u64 = 1;

/// Units of one operation on big integers of one or two words (the call, a possible
/// allocation of the result).
pub const INTEGER_OPERATION: u64 = 8;

/// The words of a number of `bits` bits.
#[inline]
fn words(bits: u64) -> u64 {
    bits / 64 + 1
}

/// The charge of `count` sums or differences of big integers of at most `bits` bits:
/// `count (INTEGER_OPERATION + words)`.
#[inline]
pub fn integer_sums_cost(count: u64, bits: u64) -> u64 {
    count.saturating_mul(INTEGER_OPERATION.saturating_add(INTEGER_WORD.saturating_mul(words(bits))))
}

/// The charge of `count` products of big integers of `a` and `b` bits: half a unit per pair
/// of words (schoolbook, num-bigint's method while the shorter operand has at most 32 words),
/// and beyond that `u v (32 / v)^0.415 / 2` for `u >= v` words (Karatsuba's v^1.585 growth),
/// plus [`INTEGER_OPERATION`]; each `count` times. (At one unit a pair, the exact paths of
/// `blossom intersect` were charged 1.9 to 2.6 units per ns of CPU time: degree-200 roots
/// with 8-digit fractions, wiggly degree 16-21 graph pairs.)
#[inline]
pub fn integer_products_cost(count: u64, a: u64, b: u64) -> u64 {
    let (u, v) = (words(a.max(b)), words(a.min(b)));
    let pairs = if v <= 32 {
        u.saturating_mul(v)
    } else {
        (u as f64 * v as f64 * (32.0 / v as f64).powf(0.415)) as u64
    };
    count.saturating_mul(INTEGER_OPERATION.saturating_add(pairs / 2))
}

/// Units of one operation on residues modulo a word-size prime (a Montgomery product and a
/// sum, the step of a modular Horner or Euclid loop).
pub const WORD_OPERATION: u64 = 2;

/// Charges the exact methods of the intersection layer, which compute with big integers
/// and words directly rather than through [`Ring`](crate::Ring): `count` sums or differences
/// of integers of at most `bits` bits ([`integer_sums_cost`]).
#[inline(always)]
pub(crate) fn charge_integer_sums(count: u64, bits: u64) {
    #[cfg(feature = "meter")]
    if active::on() {
        active::charge(integer_sums_cost(count, bits));
    }
    #[cfg(not(feature = "meter"))]
    let _ = (count, bits);
}

/// Charges `count` products of big integers of `a` and `b` bits ([`integer_products_cost`]).
#[inline(always)]
pub(crate) fn charge_integer_products(count: u64, a: u64, b: u64) {
    #[cfg(feature = "meter")]
    if active::on() {
        active::charge(integer_products_cost(count, a, b));
    }
    #[cfg(not(feature = "meter"))]
    let _ = (count, a, b);
}

/// Charges `count` operations on residues modulo a word-size prime ([`WORD_OPERATION`] each).
#[inline(always)]
pub(crate) fn charge_word_operations(count: u64) {
    charge_work(WORD_OPERATION.saturating_mul(count));
}

/// Charges `count` new points ([`POINT_ALLOCATION`] each).
#[inline(always)]
pub(crate) fn charge_points(count: usize) {
    charge_work(POINT_ALLOCATION.saturating_mul(count as u64));
}

/// Charges the computation of `C(n, k)` step by step (`k` products and exact quotients by a
/// small integer, on numbers of at most `n` bits): `60 + 5 (n / 64 + 1)` units a step.
/// Measured (`meter_calibration`): 25 to 31 ns a step for `n` up to 64, 47 ns at `n = 256`
/// and 93 ns at `n = 1000`, so the charge is 1.5 to 2.6 times the time. (It was `100 + 10 (n / 64 + 1)`, four
/// times the time: the budget sweep found `f64` closed-form jobs of degree 78, whose work is
/// mostly binomials, charged 2.1 units per ns.)
#[inline(always)]
pub(crate) fn charge_binomial(n: i64, k: i64) {
    let steps = k.min(n - k).max(0).unsigned_abs();
    charge_work(steps * (60 + 5 * (n.unsigned_abs() / 64 + 1)));
}

/// Charges one operation of [`BoundedF64`](crate::BoundedF64).
#[inline(always)]
pub(crate) fn charge_bounded() {
    charge_work(BOUNDED_OPERATION);
}

/// Charges one operation of [`BoundedF64`](crate::BoundedF64) with the exact constant `k`
/// (converted to its nearest double).
#[inline(always)]
pub(crate) fn charge_bounded_constant(k: &Rational) {
    #[cfg(feature = "meter")]
    if active::on() {
        active::charge(constant_cost(bits(k)));
    }
    #[cfg(not(feature = "meter"))]
    let _ = k;
}

/// Runs `work` under a meter of `limit` units on this thread: its value, or [`OverBudget`]
/// when its charges passed the limit (the computation is then abandoned; its values are
/// dropped as unwinding goes). Any other panic of `work` goes on unwinding.
///
/// A meter started inside another counts against both: when it ends, what it charged is
/// taken from the outer one's allowance (checked at the outer one's next charge).
///
/// ```
/// use blossom::meter::metered;
/// use blossom::{Rational, Ring};
/// let third = Rational::new(1.into(), 3.into());
/// // A few operations fit in 10^6 units ...
/// assert_eq!(metered(1_000_000, || third.mul(&third)), Ok(Rational::new(1.into(), 9.into())));
/// // ... a power of a huge exponent does not (`Ring::pow`: the inherent `Ratio::pow` of
/// // num-rational is not metered).
/// let over = metered(1_000_000, || Ring::pow(&third, 1 << 20)).unwrap_err();
/// assert_eq!(over.limit, 1_000_000);
/// assert!(over.charged > over.limit);
/// ```
#[cfg(feature = "meter")]
pub fn metered<R>(limit: u64, work: impl FnOnce() -> R) -> Result<R, OverBudget> {
    use std::cell::Cell;
    /// Restores the outer meter however `work` ends.
    struct Restore {
        left: u64,
        limit: u64,
        started: u64,
    }
    impl Drop for Restore {
        fn drop(&mut self) {
            let spent = self.started - active::LEFT.with(Cell::get).min(self.started);
            let left = if self.left == active::OFF {
                active::OFF
            } else {
                self.left.saturating_sub(spent)
            };
            active::LEFT.with(|c| c.set(left));
            active::LIMIT.with(|c| c.set(self.limit));
        }
    }
    // A limit of OFF would read as "no meter".
    let started = limit.min(active::OFF - 1);
    let _restore = Restore {
        left: active::LEFT.with(|c| c.replace(started)),
        limit: active::LIMIT.with(|c| c.replace(limit)),
        started,
    };
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)) {
        Ok(value) => Ok(value),
        Err(payload) => match payload.downcast::<OverBudget>() {
            Ok(over) => Err(*over),
            Err(other) => std::panic::resume_unwind(other),
        },
    }
}

#[cfg(all(test, feature = "meter"))]
pub(crate) mod tests {
    use super::*;
    use crate::{BoundedF64, Field, Ring};
    use num_bigint::BigInt;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn charges_stop_at_the_limit_and_nothing_without_a_meter() {
        // No meter: nothing is charged, nothing stops.
        let x = q(2, 3).pow(4000);
        assert!(x.numer().bits() > 4000);
        // Under a meter, every operation is charged before it runs.
        let small = metered(10 * RATIONAL_OPERATION, || q(1, 3).add(&q(1, 6)));
        assert_eq!(small, Ok(q(1, 2)));
        let long = metered(100_000, || x.mul(&x)).unwrap_err();
        assert_eq!(long.limit, 100_000);
        assert!(long.charged >= rational_cost(2 * x.numer().bits(), 2 * x.numer().bits()));
        // Doubles with a bound: a constant each.
        let y = BoundedF64::exact(0.5);
        let n = 1000;
        let run = metered(n * BOUNDED_OPERATION, || {
            (0..n).fold(y, |acc, _| acc.mul(&y)).value()
        });
        assert_eq!(run, Ok(0.5f64.powi(1001)));
        assert!(metered(n * BOUNDED_OPERATION, || {
            (0..=n).fold(y, |acc, _| acc.divide(&y)).value()
        })
        .is_err());
        // The meter is off again afterwards.
        assert!(!active::on());
    }

    #[test]
    fn other_panics_go_through_and_meters_nest() {
        let panicked = std::panic::catch_unwind(|| metered(100, || panic!("not a budget")));
        assert!(panicked.is_err());
        assert!(!active::on());
        let outer = metered(1_000, || {
            let inner = metered(10_000, || {
                for _ in 0..10 {
                    charge_work(60);
                }
            });
            assert_eq!(inner, Ok(()));
            assert_eq!(charged(), 600);
            // The inner meter's 600 units count against the outer 1000.
            charge_work(500);
        });
        assert_eq!(
            outer,
            Err(OverBudget {
                limit: 1_000,
                charged: 1_100
            })
        );
    }

    /// The thread's CPU time per call of `f` over `reps` calls, in ns (Linux; not disturbed by
    /// other processes' load): the timing of the calibration tables.
    pub(crate) fn time(reps: u32, f: &mut dyn FnMut()) -> f64 {
        let cpu = || -> f64 {
            let text = std::fs::read_to_string("/proc/thread-self/schedstat").unwrap();
            text.split_whitespace().next().unwrap().parse().unwrap()
        };
        let start = cpu();
        for _ in 0..reps {
            f();
        }
        (cpu() - start) / f64::from(reps)
    }

    /// Prints, for each charged operation, the measured time per operation next to its charge
    /// (units are meant to be about a nanosecond). Run on request:
    /// `cargo test --release -p blossom --lib --features meter meter_calibration -- --ignored --nocapture`.
    #[test]
    #[ignore = "a timing table; run on request in release"]
    fn meter_calibration() {
        println!(
            "{:>8} {:>12} {:>12} {:>12} {:>10}",
            "bits", "add ns", "mul ns", "div ns", "charge"
        );
        for digits in [1usize, 5, 10, 20, 40, 80, 160, 320, 640, 1280, 2560] {
            let big = |seed: u8| -> Rational {
                let n: String = (0..digits)
                    .map(|k| char::from(b'1' + (k as u8 * 7 + seed) % 9))
                    .collect();
                let d: String = (0..digits)
                    .map(|k| char::from(b'1' + (k as u8 * 3 + seed) % 9))
                    .collect();
                Rational::new(n.parse().unwrap(), d.parse().unwrap())
            };
            let (a, b) = (big(1), big(4));
            let reps = (2_000_000 / (digits * digits + 10)).max(20) as u32;
            let mut sink = Rational::from_integer(0.into());
            let add = time(reps, &mut || sink = a.add(&b));
            let mul = time(reps, &mut || sink = a.mul(&b));
            let div = time(reps, &mut || sink = a.divide(&b));
            std::hint::black_box(&sink);
            println!(
                "{:>8} {add:>12.0} {mul:>12.0} {div:>12.0} {:>10}",
                bits(&a),
                rational_cost(bits(&a), bits(&b))
            );
        }
        let (x, y) = (BoundedF64::exact(1.0 / 3.0), BoundedF64::exact(0.7));
        assert_eq!(charged(), 0);
        let reps = 10_000_000;
        let step = |acc: &mut BoundedF64| *acc = std::hint::black_box(*acc).mul(&y).add(&x);
        let mut acc = x;
        let off = time(reps, &mut || step(&mut acc));
        let on = metered(u64::MAX, || time(reps, &mut || step(&mut acc))).unwrap();
        std::hint::black_box(acc);
        println!(
            "BoundedF64 mul + add: {off:.1} ns without a meter, {on:.1} ns under one, for a \
             charge of {}",
            2 * BOUNDED_OPERATION
        );
        // A whole f64 restriction: degree 400 in 3-D by the engine and by the closed form.
        let coefficients: Vec<Vec<BoundedF64>> = (0..=400)
            .map(|i| {
                (0..3)
                    .map(|j| BoundedF64::exact(f64::from(i * 3 + j) / 7.0))
                    .collect()
            })
            .collect();
        let curve = crate::PowerCurve::new(coefficients).unwrap();
        let (a, b) = (BoundedF64::exact(0.25), BoundedF64::exact(0.75));
        for method in [crate::Method::Bulk, crate::Method::ClosedForm] {
            let mut run = || {
                std::hint::black_box(crate::restrict_power_curve(&curve, &a, &b, method));
            };
            let off = time(3, &mut run);
            let on = metered(u64::MAX, || time(3, &mut run)).unwrap();
            println!(
                "f64 degree-400 curve, {method:?}: {:.2} ms without a meter, {:.2} ms under one",
                off / 1e6,
                on / 1e6
            );
        }
    }
}
