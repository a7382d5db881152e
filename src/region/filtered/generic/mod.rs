//! The float path's shortcut for the *generic* configuration: decided without building faces
//! (the general float path, [`super`], handles every configuration; this one answers the
//! common generic case in a fraction of its time, with each region's simplicity proved once
//! and kept on the region).
//!
//! It answers only regions whose control points are doubles, and only when it can **prove**
//! that the configuration is *generic*:
//!
//! * every loop is simple and the loops of one region are pairwise disjoint: each curve is
//!   one-to-one, consecutive curves of a loop meet only at their join, and every other pair of
//!   curves of one region either has disjoint boxes or no common point (the float filter
//!   [`crossing_parameters_f64`](crate::intersect::filter::crossing_parameters_f64) proves the empty answer) (module `split`);
//! * every common point of a curve of A and a curve of B is a transversal crossing strictly
//!   inside both curves (the filter's proof, which excludes ends, tangencies and overlaps);
//!   no point of the plane is then on more than two curves, and the crossings along a curve
//!   have disjoint enclosures, which orders them.
//!
//! The first item is a fact about each region alone: it is proved once per [`Region`] and
//! kept (a region reused in many booleans pays for it once). Where any of this is not
//! proved, `run` answers `None` and [`super::pipeline`] runs the
//! exact stages, which handle every configuration; so the answer never depends on which
//! path gave it (the tests compare the two on the same inputs).
//!
//! In the generic configuration the winding numbers need no ray per piece. The winding
//! number of region R just left of a loop L of R is the winding number around R's other
//! loops (constant along L, which meets none of them) plus 1 when L runs counter-clockwise
//! (its signed area is positive), and just right of it that sum minus 1 when L runs
//! clockwise. The winding number of the other region R' changes along L only at the
//! crossings, by the sign of cross(Q', P') where L's curve P crosses Q (moving from the
//! right of Q to its left adds 1). So one exact ray count per loop, at one of its vertices
//! (module `side`), and the crossing signs give every piece its four winding numbers
//! (module `walk`); the fill rules and the operation say which pieces bound the result and
//! which way. A crossing vertex has exactly four half-pieces around it, in the counter-
//! clockwise order +P', +Q', -P', -Q' when cross(P', Q') > 0 (else +P', -Q', -P', +Q'),
//! which is all the angular order the chaining needs.
//!
//! Signed areas and crossing signs are enclosed by [`BoundedF64`](crate::BoundedF64)
//! (rigorous running error bounds; a parameter known to lie in an enclosure of doubles
//! enters as its correctly rounded double with that radius) (the crossing signs in
//! `filtered::bounds`, the loops' areas in module `area`, the result's in module `measure`);
//! a sign is taken only when the enclosure excludes zero. The modules depend on each other
//! in the order of the stages: `split`, `area`, `side`, `walk`, `measure`. The parameters of the answer are
//! [`Parameter`](super::Parameter)s: the filter's correctly rounded doubles and enclosures,
//! made exact on demand.

mod area;
mod measure;
mod side;
mod split;
mod walk;

use crate::region::answer::{BooleanOp, Outline};
use crate::region::input::Region;

/// The boolean `op` of the two regions when every input number is a double and the
/// configuration is proved generic (module docs), else `None`.
pub(super) fn run(regions: &[&Region; 2], op: BooleanOp) -> Option<Outline> {
    let doubles = [regions[0].doubles()?, regions[1].doubles()?];
    for (region, d) in regions.iter().zip(doubles) {
        if !region.proved_simple(|| split::simple(d)) {
            return None;
        }
    }
    let arrangement = split::Split::build([doubles[0].as_slice(), doubles[1].as_slice()])?;
    let fills = [regions[0].fill(), regions[1].fill()];
    let mut areas = area::Areas::new(&arrangement);
    let windings = side::loop_windings(&arrangement, &mut areas)?;
    let loops = walk::boundary(&arrangement, &windings, fills, op)?;
    measure::answer(&mut areas, loops, doubles)
}
