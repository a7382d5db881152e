//! Certified zeros and intersections.
//!
//! * `upoly`: integer polynomials, exact gcd, Yun's square-free factorisation;
//! * `isolate`: real root isolation by Descartes' rule on exact Bernstein coefficients;
//! * `algebraic`: real algebraic numbers ([`AlgebraicReal`]);
//! * `zeros`: zeros of a Bézier function with multiplicities ([`bezier_zeros`]);
//! * `modular`: arithmetic modulo word-size primes, interpolation, Chinese remaindering;
//! * `bivariate`: resultants and first subresultants of bivariate integer polynomials (multi-modular);
//! * `extension`: arithmetic in a real algebraic extension Q(alpha) by dynamic evaluation, and
//!   the fibre of a bivariate system over an algebraic abscissa;
//! * `components`: curves sharing a component (decomposition P = R(phi), overlaps, retracing);
//! * `intersections`: the answer of curve-curve intersection ([`Intersections`]: points and
//!   overlaps, exact);
//! * `curves`: curve-curve intersection ([`intersect_curves`]);
//! * `extrema`: the tight bounding box and the nearest point of a curve
//!   ([`tight_bounding_box`], [`nearest_point`]);
//! * `interval`: rigorous intervals, double-doubles and correct rounding for the filter;
//! * `pyramid`: the filter's point evaluations, unrolled for degrees 1 to 3;
//! * `filter`: the float filter of curve-curve intersection ([`certified_crossings_f64`]);
//! * `implicit`: exact proofs in fixed-width integers that a curve misses a quadratic (its
//!   parabola's implicit equation of one sign along the curve);
//! * `budget`: work estimates for callers that bound their work ([`budget`], public as
//!   `blossom::budget`);
//! * `rounded`: the `f64` answer for every input, filter first, exact path otherwise
//!   ([`intersect_curves_f64_rounded`]).

pub(crate) mod algebraic;
pub(crate) mod bivariate;
pub mod budget;
pub(crate) mod components;
pub(crate) mod curves;
mod display;
pub(crate) mod extension;
pub(crate) mod extrema;
pub(crate) mod filter;
pub(crate) mod implicit;
pub(crate) mod intersections;
pub(crate) mod interval;
pub(crate) mod isolate;
pub(crate) mod line;
pub(crate) mod methods;
pub(crate) mod modular;
pub(crate) mod pyramid;
pub(crate) mod rounded;
pub(crate) mod solve;
pub(crate) mod upoly;
pub(crate) mod zeros;

#[cfg(test)]
mod components_tests;
#[cfg(test)]
mod extension_tests;
#[cfg(test)]
mod extrema_tests;
#[cfg(test)]
mod filter_tests;
#[cfg(test)]
mod tests;
