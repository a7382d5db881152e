//! The applications layer of the library: batches, degree change, derivatives, rational
//! curves and surfaces, B-splines and the inverse formula for closures.

mod json;

mod batched;
mod degree_change;
mod derivatives;
mod examples_run;
mod f32_accuracy;
mod interop;
mod inverse_closures;
mod no_panics;
mod nurbs_rational;
mod patch_degree;
mod spline_bspline;
mod spline_examples;
mod spline_surface;
