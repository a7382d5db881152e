//! Certified zeros and intersections.
//!
//! * `upoly`: integer polynomials, exact gcd, Yun's square-free factorisation;
//! * `isolate`: real root isolation by Descartes' rule on exact Bernstein coefficients;
//! * `algebraic`: real algebraic numbers ([`AlgebraicReal`]);
//! * `zeros`: zeros of a Bézier function with multiplicities ([`bezier_zeros`]);
//! * `modular`: arithmetic modulo word-size primes, interpolation, Chinese remaindering;
//! * `bivariate`: resultants and first subresultants of bivariate integer polynomials (multi-modular);
//! * `curves`: curve-curve intersection ([`intersect_curves`]).

pub(crate) mod algebraic;
pub(crate) mod bivariate;
pub(crate) mod curves;
pub(crate) mod isolate;
pub(crate) mod modular;
pub(crate) mod solve;
pub(crate) mod upoly;
pub(crate) mod zeros;

#[cfg(test)]
mod tests;
