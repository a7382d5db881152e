//! Regions bounded by Bézier curves: exact winding numbers, certified booleans, the region
//! of a planar Bézier triangle and the intersection of two of them.
//!
//! A [`Region`] is loops of 2-D polynomial Bézier curves with exact rational control points
//! and a [`FillRule`]. [`Region::winding`] gives the exact winding number of a point,
//! [`boolean`] the regularized result of [`BooleanOp`] on two regions as oriented simple
//! loops of [`Edge`]s (pieces of input curves between exact [`Parameter`]s) with an
//! enclosure of its area, [`simplify`] one region's overlap removal in the same form,
//! [`triangle_intersection`] the same for two [`Region::triangle`]s.
//!
//! API notes (for callers that followed the first sketch): the work estimates
//! [`boolean_work`] and [`Region::winding_work`] return `u128` nanoseconds, like
//! [`intersection_work`](crate::budget::intersection_work) and the other estimates of the crate, not
//! `f64`; a Bézier triangle is a [`Region`] built by [`Region::triangle`] (no separate type),
//! and an [`Edge`] of [`triangle_intersection`] names the triangle as `region` and its edge as
//! `curve` (the spec's edge number is `3 * region + curve`); [`Region::windings`] answers many
//! points with the curves prepared once.
//!
//! # Certified
//!
//! Every decision is exact for the input numbers: whether a point is on a curve, inside or
//! outside; where curves meet, touch or run together (the certified intersections of
//! [`intersect_curves`](crate::intersect_curves) and
//! [`self_intersections`](crate::self_intersections)); which pieces coincide; which pieces
//! bound the result; how the boundary continues at a vertex. Floating point only prunes
//! (outward-rounded bounding boxes that separate prove the separation) or proves a sign by
//! rigorous interval arithmetic (`crossing`), the exact path running whenever it does not. Parameters are
//! [`AlgebraicReal`](crate::AlgebraicReal)s, so their `to_f64` is correctly rounded.
//!
//! # Two paths, one answer
//!
//! Regions whose control points are doubles (every font, every SVG path read as doubles,
//! integers and dyadic rationals) take the **float path** (`filtered`), in any arrangement:
//! loops crossing themselves and each other, shared vertices, vertices on curves, coincident
//! pieces, tangencies. It builds the arrangement in floating point with certified tests and
//! decides each degenerate contact exactly *where it is*: a pair of curves the certified
//! filter cannot settle is intersected exactly on its own (a segment without resultants,
//! `intersect::line`), two parameters are compared exactly only where their enclosures meet,
//! two branches at a vertex only when their tangents and curvatures do not order them. Its
//! shortcut for the generic configuration (each region's loops simple and disjoint, proved
//! once per region and kept, every contact a transversal crossing) skips the faces
//! altogether. [`RegionResult::report`] says which path answered and what took exact
//! arithmetic. Regions with a rational that is not a double (1/3) go through the exact stages
//! below, as does the float path's input should one of its consistency checks fail (never
//! seen: the tests compare both on random, degenerate and real font outlines). The parameters
//! of the answer are [`Parameter`]s: correctly rounded doubles and enclosures at once, exact
//! algebraic numbers on demand.
//!
//! # The exact stages, one file each
//!
//! 1. `input` checks the loops; `curve` puts each input curve in power form with an
//!    outward-rounded box and, on demand, its breaks into pieces monotone in x or y.
//! 2. `arrangement`: every pair of curves of both regions whose boxes meet (found by a sweep
//!    over the boxes sorted by their left side, so curves far apart cost nothing) is
//!    intersected exactly, and every curve with itself, except where `prune` proves the
//!    answer at once: consecutive curves of a loop that a line through their join separates
//!    meet only there, and a curve moving strictly forward along one direction does not
//!    cross itself (both proofs exact). The parameters found split each
//!    curve into pieces. Parameters that are the same point of the plane (an intersection
//!    (s, t), a curve's end and the next curve's start, a self-intersection, the ends of an
//!    overlap) are joined by union-find into vertices. Where two curves overlap, the pieces
//!    of both inside the overlap are paired in order and merged into one *group* of
//!    coincident pieces (a parameter that splits one side only, a self-crossing of a curve on
//!    a stretch another curve overlaps, is carried over to the other side exactly by
//!    `transfer`). Each group's *representative* is the piece of the lowest
//!    (region, loop, curve), and of its pass with the lower parameters.
//! 3. `classify`: each group gets the exact winding numbers of A and of B on both its sides.
//!    At a rational parameter m strictly inside the representative (where P'(m) ≠ 0), the
//!    point X = P(m) lies on the group's curves and on no other. A ray from X along +x (or +y
//!    when the tangent there is horizontal) counts the crossings of all curves except the
//!    passes through X itself (`winding`, whose half-open counting of heights makes curve ends
//!    and turning points count once): that is the winding number just off X on one side;
//!    the other side differs by the signed number of the group's pieces of that region
//!    (+1 for a piece running the representative's way). The fill rules and the op then say
//!    whether the result lies on each side; a group is an edge of the result exactly when the
//!    answers differ, oriented so that the result lies on its left. Parts of zero area (a
//!    shared edge that both sides exclude, a touching point) are thereby dropped: the answer
//!    is regularized.
//! 4. `chain`: the edges are chained at vertices. At a vertex with one edge out it continues
//!    there; where several leave, the edges are ordered by angle (`angle`: the class of the
//!    leading direction, then the order of the two branches along an axis-parallel line
//!    close enough to the vertex, decided exactly) and the walk turns into the first edge
//!    clockwise from the one it came in by, which keeps the result's sector on its left.
//!    Each closed walk is split at every vertex it passes twice, so loops are simple, and
//!    consecutive edges continuing the same input curve are merged (maximal edges). A loop
//!    whose exact signed area is negative is a hole.
//! 5. `area`: the area of the result is the sum over its edges of the exact integral of
//!    x dy over each piece, F(to) - F(from) for the antiderivative F of x(t) y'(t); at
//!    algebraic parameters each value is enclosed by interval Horner over the parameter's
//!    isolating interval, refined until the enclosure meets the width the answer promises.
//!
//! # Output
//!
//! A [`RegionResult`] names pieces of input curves; it also gives them as geometry.
//! [`RegionResult::geometry`] cuts each edge's piece out of its input curve in doubles, of the
//! input curve's degree (a piece of a line is a line, of a quadratic a quadratic, of a cubic a
//! cubic): consecutive pieces share their end point bit for bit and every loop closes exactly;
//! a parameter 0 or 1 gives the input's own control point, every other coordinate is within
//! 17 n 2^-53 M of the exact piece's (n the degree, M the largest absolute input coordinate;
//! 7 n 2^-53 M for input of doubles up to degree 8), by float restrictions only.
//! [`RegionResult::to_region`] makes that a [`Region`] (nonzero rule) so that booleans chain,
//! and [`RegionResult::svg`] writes it as SVG path data (`M`, `L`, `Q`, `C`, `Z`, numbers in
//! shortest round-trip form). SVG path data comes in through [`Region::from_svg_path`] and
//! [`parse_svg_path`] (commands M, L, H, V, Q, T, C, S, Z, every number exact). With the
//! feature `kurbo`, `Region::from_bez_path`, `RegionResult::to_bez_path` and `binary_op`
//! (linesweeper's one call) do the same for kurbo's `BezPath`.
//!
//! # Limits
//!
//! Curve degrees 1 to [`MAX_REGION_DEGREE`]. On the exact stages the cost is dominated by
//! the exact intersections of the curve pairs whose boxes meet, on the float path by the
//! float filter on those pairs and by the pairs it leaves to exact arithmetic;
//! [`boolean_work`] estimates it before any is computed (for the float path, without the
//! exact pairs).

mod angle;
mod answer;
mod area;
mod arrangement;
mod boolean;
mod chain;
mod classify;
mod crossing;
mod curve;
mod filtered;
mod input;
mod output;
mod parameter;
mod pipeline;
mod prune;
mod straight;
mod svg;
mod transfer;
mod winding;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_curved;
#[cfg(test)]
mod tests_grid;

#[cfg(feature = "kurbo")]
pub use crate::interop::kurbo_region::binary_op;
pub use answer::{BooleanOp, Edge, RegionResult, Report, ResultLoop};
pub use boolean::{boolean, boolean_work, simplify, simplify_work, triangle_intersection};
pub use input::{FillRule, Region, MAX_REGION_DEGREE};
pub use parameter::Parameter;
pub use svg::parse_svg_path;
#[cfg(feature = "kurbo")]
pub(crate) use svg::Subpaths;
pub use winding::{Position, Winding};
