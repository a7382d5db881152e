//! What is built on restriction and on the shapes: batches of objects sharing a domain,
//! B-splines (seed 002), rational curves and surfaces, degree elevation and reduction of curves
//! and patches and the true degree (seed 004), and derivatives from the blossom with vector
//! arguments, and the exact error of somebody else's `f64` answer to a restriction (`check`).
//! Each module imports only the layers below it and its siblings listed before it here.

pub(crate) mod batch;
pub(crate) mod check;
pub(crate) mod degree;
pub(crate) mod derivative;
pub(crate) mod patch_degree;
pub(crate) mod rational;
pub(crate) mod spline;
pub(crate) mod true_degree;
