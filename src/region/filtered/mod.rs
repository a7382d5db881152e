//! The float path of the booleans: the arrangement of every curve of both regions built and
//! decided in floating point with rigorous bounds, each degenerate contact decided exactly
//! where it is and nowhere else.
//!
//! It answers regions whose control points are doubles, in any arrangement: loops that cross
//! themselves and each other within one region, under either fill rule, shared vertices,
//! points of one loop on another's curve, coincident pieces, tangencies. The stages, one file
//! each, in the order they run (each imports only the ones before it, the shared exact
//! procedures of the region layer, and the enclosures of `bounds` and `measure`):
//!
//! 1. `graph`: every pair of curves whose boxes meet is decided by the cheapest proof that
//!    applies: a separating line at a loop's join (exact, on doubles), else the certified float
//!    filter (transversal crossings strictly inside both curves, correctly rounded parameters
//!    with enclosures), else fixed-width exact integers for a segment's contacts (below), else
//!    the exact intersector **on that pair alone**. Two segments go to fixed width first. Each curve's
//!    parameters are ordered by their enclosures, exactly where enclosures meet; equal
//!    parameters (several contacts at one point) are merged; the vertices, pieces and groups
//!    of coincident pieces follow as in the exact stages.
//! 2. `order`: the half-edges around each vertex in counter-clockwise order, from the classes
//!    and cross products of their tangents enclosed in floating point, exactly for the pairs
//!    that stay undecided (tangent branches, zero derivatives).
//! 3. `faces` (with `side`): faces are the cycles of the half-edge successor; winding numbers
//!    of both regions cross each half-edge by the signed count of its group's pieces, from one
//!    seed per connected component, an exact ray count on boxes at a join on the component's
//!    box (the exact stages' ray beside a piece when none decides).
//! 4. `walk`: the half-edges whose left face the operation keeps and whose right face it drops,
//!    chained into simple loops of maximal runs.
//! 5. `measure`: the loops' signed areas and the total in plain f64 with an a-priori error
//!    bound (hole or not from the sign), the parameters of the answer as [`Parameter`]s.
//!
//! **Why the answer is exact.** Every yes/no question (do two curves meet and where, are two
//! parameters equal, in which order do branches leave a vertex, what is the winding number of
//! a face) is answered either by a proof in floating point (an enclosure that excludes zero,
//! a filter's Krawczyk proof, comparisons of doubles, which are exact) or by exact
//! arithmetic; a tolerance never answers. Given the same decisions the float path and the
//! exact stages compute the same arrangement, so they give the same answer (the tests
//! compare them on random, degenerate and real font outlines). Should a consistency check
//! fail (which would be a bug) or an area enclosure be too wide, `run` answers `None` and the
//! exact stages answer.
//!
//! Integer and dyadic inputs (every font) are doubles, so all of the above applies to them,
//! and their degenerate contacts are decided in fixed-width integers before big ones: two
//! segments, and a segment and a quadratic or cubic that the filter leaves undecided (an end
//! on the segment, a tangent end), are intersected exactly in `i128` (`intersect::line`),
//! their parameters exact rationals in 64 bits compared without allocation, and the affine
//! maps that carry parameters across shared segments stay in that width while their numbers
//! fit. Only what does not fit, or a contact of two curves, takes big rationals.
//!
//! [`Parameter`]: crate::region::Parameter

mod bounds;
mod faces;
mod generic;
mod graph;
mod measure;
mod order;
mod side;
mod walk;

use super::answer::{BooleanOp, Outline, Report};
use super::input::Region;

/// The cost of a pair of curves whose boxes meet, decided by the float filter or a proved
/// join, in nanoseconds: the filter on two cubics takes about 1.5 µs on a 2-core x86-64
/// machine (benches/intersect.rs); counted at 5 µs with its share of the later stages.
const PAIR_WORK: u128 = 5_000;
/// The cost of a pair of segments whose boxes meet, in nanoseconds: decided in fixed width
/// (about 0.3 µs) or by a proved join, counted at 2 µs with its share of the later stages
/// (a board of 7,200 unit squares touching at corners united with its copy moved by one
/// square: 91,395 pairs, 0.56 s in all, load 5).
const SEGMENT_PAIR_WORK: u128 = 2_000;
/// The cost of one box test of the ray that seeds a connected component's winding numbers,
/// in nanoseconds (one ray per loop against every curve bounds it: a component is at least a
/// loop, and most are seeded by a join on their box without a ray).
const RAY_WORK: u128 = 10;
/// The cost per curve beyond its pairs (its box, its parameters, the faces, the walk and the
/// area), in nanoseconds, counted generously.
const CURVE_WORK: u128 = 2_000;

/// The work estimate of [`run`] in nanoseconds when both regions are of doubles, else `None`:
/// every pair of curves whose boxes meet at [`PAIR_WORK`] ([`SEGMENT_PAIR_WORK`] for two
/// segments), every curve at [`CURVE_WORK`], and one box ray per loop against every curve at
/// [`RAY_WORK`] a curve. The pairs neither fixed width nor the filter decide go to the exact
/// intersector one by one; the caller's work meter bounds those.
pub(crate) fn work(regions: &[&Region; 2]) -> Option<u128> {
    let doubles = [regions[0].doubles()?, regions[1].doubles()?];
    let curves: Vec<&Vec<[f64; 2]>> = doubles.iter().flat_map(|d| d.iter().flatten()).collect();
    let boxes: Vec<[f64; 4]> = curves.iter().map(|c| graph::bbox(c)).collect();
    let pair_work: u128 = crate::region::arrangement::meeting_boxes(&boxes)
        .iter()
        .map(|&(i, j)| {
            if curves[i].len() == 2 && curves[j].len() == 2 {
                SEGMENT_PAIR_WORK
            } else {
                PAIR_WORK
            }
        })
        .sum();
    let (curves, loops) = (
        boxes.len() as u128,
        (doubles[0].len() + doubles[1].len()) as u128,
    );
    Some(pair_work + curves * CURVE_WORK + loops * curves * RAY_WORK)
}

/// The boolean `op` of the two regions when every input number is a double (module docs),
/// else `None`; `None` too when a consistency check fails, for the exact stages to answer.
pub(crate) fn run(regions: &[&Region; 2], op: BooleanOp) -> Result<Outline, &'static str> {
    let (Some(a), Some(b)) = (regions[0].doubles(), regions[1].doubles()) else {
        return Err("an input number is not a double");
    };
    if let Some(mut answer) = generic::run(regions, op) {
        answer.report.float_path = true;
        answer.report.generic = true;
        return Ok(answer);
    }
    general(regions, [a, b], op)
}

/// The general float path (stages 1 to 5 of the module docs) on regions of doubles `[a, b]`.
fn general(
    regions: &[&Region; 2],
    [a, b]: [&std::sync::Arc<crate::region::input::Doubles>; 2],
    op: BooleanOp,
) -> Result<Outline, &'static str> {
    let graph = graph::Graph::build([a, b]).map_err(|_| "an exact intersection failed")?;
    let around = order::around(&graph).map_err(|_| "an exact order failed")?;
    let mut areas = measure::Areas::new(&graph);
    let faces = faces::faces(&graph, &around, &mut areas)
        .map_err(|_| "an exact seed failed")?
        .ok_or("the winding numbers of a face disagree")?;
    let fills = [regions[0].fill(), regions[1].fill()];
    let loops = walk::boundary(&graph, &around, &faces, fills, op)
        .ok_or("a boundary walk does not close")?;
    let mut answer = measure::answer(&mut areas, loops)
        .ok_or("a loop's area sign or the area enclosure is not decided")?;
    let c = graph.counts;
    answer.report = Report {
        float_path: true,
        generic: false,
        reason: None,
        pairs: c.pairs,
        joins: c.joins,
        fixed_width: c.fixed_width,
        filtered: c.filtered,
        exact_pairs: c.exact,
        exact_self: c.exact_self,
        exact_orders: around.exact,
        area_seeds: faces.area_seeds,
        exact_seeds: faces.exact_seeds,
    };
    Ok(answer)
}

#[cfg(test)]
mod tests;
