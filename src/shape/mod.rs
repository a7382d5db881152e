//! Shapes: points, the simplex index of triangular nets, polynomial curves and surfaces in the
//! power basis and in the Bernstein basis, each with its own evaluation (Horner's rule,
//! de Casteljau's algorithm on the blossom), and the changes of basis between them. This layer
//! imports only the numbers.

pub(crate) mod array;
pub(crate) mod basis;
pub(crate) mod bezier;
pub(crate) mod coords;
pub(crate) mod eval_linear;
pub(crate) mod eval_many;
pub(crate) mod flat;
pub(crate) mod halving;
pub(crate) mod point;
pub(crate) mod power;
pub(crate) mod power_triangle;
pub(crate) mod simplex;
pub(crate) mod traits;
pub(crate) mod two_pass;
pub(crate) mod unrolled;
