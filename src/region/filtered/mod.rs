//! The float path of the booleans: the common configuration decided in floating point with
//! rigorous bounds, no big numbers; anything else is left to the exact pipeline.
//!
//! It answers only regions whose control points are doubles, and only when it can **prove**
//! that the configuration is *generic*:
//!
//! * every loop is simple and the loops of one region are pairwise disjoint: each curve is
//!   one-to-one, consecutive curves of a loop meet only at their join, and every other pair of
//!   curves of one region either has disjoint boxes or no common point (the float filter
//!   [`certified_crossings_f64`] proves the empty answer) (module `split`);
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
//! enters as its correctly rounded double with that radius) (module `measure`); a sign is
//! taken only when the enclosure excludes zero. The parameters of the answer are
//! [`Parameter`](super::Parameter)s: the filter's correctly rounded doubles and enclosures,
//! made exact on demand.

mod measure;
mod side;
mod split;
mod walk;

use super::boolean::{BooleanOp, Outline};
use super::input::Region;

/// The cost of a cross-region pair of curves whose boxes meet, in nanoseconds: the float
/// filter on two cubics takes about 1.5 µs on a 2-core x86-64 machine (benches/intersect.rs),
/// with the crossing signs, ordering and chaining; counted at 5 µs.
const PAIR_WORK: u128 = 5_000;
/// The cost per curve beyond its pairs (its box, its share of the ray counts, the walk and
/// the area), in nanoseconds, counted generously.
const CURVE_WORK: u128 = 2_000;

/// The work estimate of [`run`] in nanoseconds, when both regions are of doubles and proved
/// simple (see the module docs; the proof is made here if it was not, and kept): the
/// cross-region pairs of curves whose boxes meet, the curves, one ray count per loop against
/// every curve. `None` when the float path does not apply. Should the float path meet a
/// degenerate configuration among the pairs (an end point on a curve, a tangency, an
/// overlap) it leaves the answer to the exact stages, which the caller's work meter bounds.
pub(crate) fn work(regions: &[&Region; 2]) -> Option<u128> {
    let doubles = [regions[0].doubles()?, regions[1].doubles()?];
    for (region, d) in regions.iter().zip(doubles) {
        if !region.proved_simple(|| split::simple(d)) {
            return None;
        }
    }
    let mut boxes = Vec::new();
    let mut first_of_b = 0;
    for (r, d) in doubles.iter().enumerate() {
        if r == 1 {
            first_of_b = boxes.len();
        }
        boxes.extend(d.iter().flatten().map(|c| split::bbox(c)));
    }
    let pairs = crate::region::arrangement::meeting_boxes(&boxes)
        .into_iter()
        .filter(|&(i, j)| (i < first_of_b) != (j < first_of_b))
        .count() as u128;
    let (curves, loops) = (
        boxes.len() as u128,
        (doubles[0].len() + doubles[1].len()) as u128,
    );
    Some(pairs * PAIR_WORK + curves * CURVE_WORK + loops * curves * 50)
}

/// The boolean `op` of the two regions when every input number is a double and the
/// configuration is proved generic (module docs), else `None`.
pub(crate) fn run(regions: &[&Region; 2], op: BooleanOp) -> Option<Outline> {
    let doubles = [regions[0].doubles()?, regions[1].doubles()?];
    for (region, d) in regions.iter().zip(doubles) {
        if !region.proved_simple(|| split::simple(d)) {
            return None;
        }
    }
    let arrangement = split::Split::build([doubles[0].as_slice(), doubles[1].as_slice()])?;
    let fills = [regions[0].fill(), regions[1].fill()];
    let mut areas = measure::Areas::new(&arrangement);
    let windings = side::loop_windings(&arrangement, &mut areas)?;
    let loops = walk::boundary(&arrangement, &windings, fills, op)?;
    measure::answer(&mut areas, loops, doubles)
}

#[cfg(test)]
mod tests;
