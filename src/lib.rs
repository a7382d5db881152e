//! # blossom
//!
//! Exact and fast Bézier subdivision through blossoms (polar forms).
#![forbid(unsafe_code)]

extern crate self as blossom;

pub mod ring;

pub use ring::{Ring, Rational};
