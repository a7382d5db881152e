//! Work estimates of the certified zeros and intersections, for a caller that bounds its work
//! (the `blossom` binary refuses a job whose estimate is over its budget before computing, and
//! stops one whose metered work passes it: `blossom::meter`, feature `meter`).
//!
//! Every estimate is in units of about a nanosecond of a 2-core x86-64 machine, the unit of
//! the work meter, and is an estimate, not a bound: it is calibrated against measured times
//! (stated on each function) so that a job is estimated within a small factor of its time at
//! the sizes a budget of about a second lets through. The sizes that drive the exact methods
//! are the degrees and the **bit length of the integers they compute with**: the coordinates
//! (or coefficients) over their common denominator, which for many short fractions is much
//! longer than any one of them (200 fractions with 8-digit denominators have a common
//! denominator of about 5,300 bits). [`common_denominator_bits`] measures it exactly.
//!
//! ```
//! use blossom::budget::{bezier_zeros_work, common_denominator_bits};
//! use blossom::Rational;
//! // 200 fractions with 8-digit denominators: 24 bits each, 3,580 over their common
//! // denominator (the lcm of 10^7 + 1, ..., 10^7 + 200).
//! let short: Vec<Rational> =
//!     (1..=200).map(|k| Rational::new(1.into(), (10_000_000 + k).into())).collect();
//! assert_eq!(common_denominator_bits(&short[..1]), 1);
//! assert!(common_denominator_bits(&short) > 3500);
//! // The estimate of the zeros of the degree-199 function with those coefficients sees them:
//! // several times that of small integers.
//! let whole: Vec<Rational> = (1..=200).map(|k| Rational::from_integer(k.into())).collect();
//! assert!(bezier_zeros_work(&short) > 4 * bezier_zeros_work(&whole));
//! ```

use super::algebraic::over_common_denominator;
use super::curves::as_doubles;
use super::filter::certified_crossings_f64;
use crate::num::ring::Rational;

/// The bits of the longest numerator once `values` are written over their common denominator
/// (the lcm of their denominators), at least 1: the length of the integers an exact method
/// that clears denominators computes with. Doubles share a power of two, so theirs is about
/// 53 bits plus the spread of their exponents; k fractions with distinct d-bit denominators
/// give about k d bits.
pub fn common_denominator_bits(values: &[Rational]) -> u64 {
    let (numerators, _) = over_common_denominator(values);
    numerators
        .iter()
        .map(|c| c.bits())
        .max()
        .unwrap_or(0)
        .max(1)
}

/// A work estimate for [`bezier_zeros`](crate::bezier_zeros) of degree `n` whose coefficients
/// have at most `bits` bits over their common denominator ([`common_denominator_bits`]).
///
/// The exact path clears denominators after the change to the power basis (whose integers
/// gain about n bits, the binomials), so it works with integers of b = bits + n bits: the
/// square-free test and Descartes' bisection of the degree-n polynomial, each halving about
/// n^2 / 2 additions of numbers of b + n bits (a halving point adds a bit per level, the
/// start coefficients the n-bit binomials), over a bisection tree of about n nodes for a
/// function without clustered zeros. The model is n^3 additions of words(b + 2 n) 64-bit
/// words, at 2 units a word, with 4 words more for the calls. Measured in release
/// (2026-12-07, 2-core machine): degree 200 with random 8-digit fractions (b about 5,500)
/// takes 0.86-0.89 s of CPU time when it finds 8-12 zeros, charged 1.6e9 units by the meter,
/// estimated 1.1-1.2e9 (one such function with 14 zeros close together took 16 s: the
/// estimate does not see clustering, the meter stops it).
pub fn zeros_work(n: usize, bits: u64) -> u128 {
    let d = n as u128 + 1;
    let words = (u128::from(bits) + 2 * n as u128) / 64 + 1;
    2 * d * d * d * (words + 4)
}

/// [`zeros_work`] of the Bézier function with Bernstein coefficients `coefficients`: its
/// degree and the bits of the coefficients over their common denominator.
pub fn bezier_zeros_work(coefficients: &[Rational]) -> u128 {
    zeros_work(
        coefficients.len().saturating_sub(1),
        common_denominator_bits(coefficients),
    )
}

/// A work estimate for [`intersect_curves`](crate::intersect_curves) on curves of degrees `n`
/// and `m` whose power coefficients, after clearing denominators, have at most `bits` bits,
/// when the exact solver answers (the float filter did not decide): the resultant has degree
/// n m and coefficients of about (n + m) (bits + n + m) bits, and with refinement by
/// quadratic interval refinement the measured cost grows as (n m)^2 operations on numbers of
/// that size (log-log slope 1.98 from n = m = 8 to 20). Measured in release (2026-12-06,
/// 2-core machine), random pairs with coordinates k / q (|k| <= 20, q <= 7): n = m = 20
/// 0.6-1.6 s, 24 3.1-5.2 s, 28 3.9-7.1 s; self-intersections (this estimate at degree n - 1)
/// of degree 20 about 0.6 s, 24 0.9-2.4 s, 28 5-6 s. The constant puts the measured times
/// within 0.5 to 2 times the estimate from degree 20 to 28.
pub fn intersection_work(n: usize, m: usize, bits: u64) -> u128 {
    let d = (n as u128) * (m as u128) + 1;
    200 * d * d * coefficient_words(n, m, bits)
}

/// A work estimate, as [`intersection_work`], for [`intersect_curves`](crate::intersect_curves)
/// when the float filter decides with `crossings` crossings: two multi-modular resultants of
/// degree n m, and for each crossing the Bernstein coefficients of their square-free parts
/// over its enclosure (Descartes' test), each about (n m)^2 operations on numbers of the
/// resultant's size. Measured in release (2026-12-06, 2-core machine): random pairs with
/// six-decimal coordinates, n = m = 20 0.55-1.5 s, 24 3.7-4.3 s, 28 7.9-13 s, n = m = 3
/// about 1 ms; within 0.9 to 1.3 times the estimate from degree 20 to 28.
pub fn filtered_intersection_work(n: usize, m: usize, bits: u64, crossings: usize) -> u128 {
    let d = (n as u128) * (m as u128) + 1;
    12 * (2 + crossings as u128) * d * d * coefficient_words(n, m, bits)
}

/// The estimated work of [`intersect_curves`](crate::intersect_curves) on `p` and `q`, as
/// [`intersection_work`]: when every coordinate is a double and the float filter decides (it
/// runs here, in microseconds to milliseconds), [`filtered_intersection_work`] with its
/// number of crossings, else [`intersection_work`]. `bits` is [`common_denominator_bits`] of
/// each curve's coordinates, the longer of the two.
pub fn curve_pair_work(p: &[[Rational; 2]], q: &[[Rational; 2]]) -> u128 {
    let bits = curve_bits(p).max(curve_bits(q));
    let (n, m) = (p.len().saturating_sub(1), q.len().saturating_sub(1));
    let filtered = as_doubles(p)
        .zip(as_doubles(q))
        .and_then(|(pf, qf)| certified_crossings_f64(&pf, &qf));
    match filtered {
        Some(crossings) => filtered_intersection_work(n, m, bits, crossings.len()),
        None => intersection_work(n, m, bits),
    }
}

/// The estimated work of [`self_intersections`](crate::self_intersections) on `p`, as
/// [`intersection_work`]: the divided difference (P(s) - P(t)) / (s - t) has degree n - 1 in
/// each variable and always goes through the exact solver.
pub fn self_intersection_work(p: &[[Rational; 2]]) -> u128 {
    let d = p.len().saturating_sub(2).max(1);
    intersection_work(d, d, curve_bits(p))
}

/// [`common_denominator_bits`] of a curve's coordinates.
fn curve_bits(p: &[[Rational; 2]]) -> u64 {
    let coordinates: Vec<Rational> = p.iter().flatten().cloned().collect();
    common_denominator_bits(&coordinates)
}

/// The 64-bit words of a resultant coefficient (see [`intersection_work`]).
fn coefficient_words(n: usize, m: usize, bits: u64) -> u128 {
    ((n + m) as u128) * (u128::from(bits) + (n + m) as u128) / 64 + 1
}
