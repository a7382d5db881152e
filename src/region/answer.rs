//! The answer of a boolean: the operations, the result's loops of edges, how it was decided.
//! (The stages below it build these; [`super::boolean`] is the front that runs them.)

use super::input::Region;
use super::parameter::Parameter;

/// A boolean operation on two regions A and B.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BooleanOp {
    /// A ∩ B.
    Intersection,
    /// A ∪ B.
    Union,
    /// A - B.
    Difference,
    /// (A - B) ∪ (B - A).
    Xor,
}

impl BooleanOp {
    /// Whether a point inside A (`in_a`) and inside B (`in_b`) is inside the result.
    ///
    /// ```
    /// use blossom::region::BooleanOp;
    /// assert!(BooleanOp::Difference.keeps(true, false));
    /// assert!(!BooleanOp::Xor.keeps(true, true));
    /// ```
    pub fn keeps(self, in_a: bool, in_b: bool) -> bool {
        match self {
            BooleanOp::Intersection => in_a && in_b,
            BooleanOp::Union => in_a || in_b,
            BooleanOp::Difference => in_a && !in_b,
            BooleanOp::Xor => in_a != in_b,
        }
    }
}

/// One edge of a result loop: the input curve `curve` of loop `loop_index` of region `region`
/// (0 for A, 1 for B) between the parameters `from` and `to`, traversed from `from` to `to`
/// (`from > to` when it runs against the curve's direction). For
/// [`triangle_intersection`](super::triangle_intersection) the regions are the two triangles, `loop_index` is 0 and
/// `curve` the edge number 0, 1, 2 of that triangle (the spec's edge `3 * region + curve`).
#[derive(Clone, Debug)]
pub struct Edge {
    /// 0 for the first region, 1 for the second.
    pub region: usize,
    /// The loop of that region.
    pub loop_index: usize,
    /// The curve of that loop.
    pub curve: usize,
    /// The parameter where the edge starts: its correctly rounded double at once, its exact
    /// number on demand ([`Parameter::algebraic`]).
    pub from: Parameter,
    /// The parameter where the edge ends.
    pub to: Parameter,
}

impl Edge {
    /// The spec's edge number for [`triangle_intersection`](super::triangle_intersection): 0, 1, 2 for the first
    /// triangle's edges, 3, 4, 5 for the second's (`3 * region + curve`).
    ///
    /// ```
    /// use blossom::region::{triangle_intersection, Region};
    /// use blossom::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let t1 = Region::triangle(1, vec![[q(0), q(0)], [q(4), q(0)], [q(0), q(4)]])?;
    /// let t2 = Region::triangle(1, vec![[q(1), q(1)], [q(2), q(1)], [q(1), q(2)]])?;
    /// // t2 lies inside t1: the answer is t2, edges 3, 4, 5.
    /// let r = triangle_intersection(&t1, &t2)?;
    /// let mut numbers: Vec<usize> = r.loops[0].edges.iter().map(|e| e.triangle_edge()).collect();
    /// numbers.sort();
    /// assert_eq!(numbers, vec![3, 4, 5]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn triangle_edge(&self) -> usize {
        3 * self.region + self.curve
    }
}

/// One simple oriented loop of a result: counter-clockwise around the result's interior for
/// an outer loop, clockwise for a hole; the result lies to the left of every edge.
#[derive(Clone, Debug)]
pub struct ResultLoop {
    /// Whether the loop bounds a hole (runs clockwise).
    pub hole: bool,
    /// The edges in order, each ending exactly where the next begins and the last where the
    /// first begins.
    pub edges: Vec<Edge>,
}

/// The regularized result of a boolean as oriented simple loops, with an enclosure of its
/// area. It keeps (shared handles to) the two input regions its edges are pieces of.
#[derive(Clone, Debug)]
pub struct RegionResult {
    /// The loops, in no particular order; none for an empty result.
    pub loops: Vec<ResultLoop>,
    /// `[lo, hi]`, lo <= exact area <= hi, with hi - lo <= 2^-40 B, B the area of the
    /// smallest axis-parallel box holding every input control point (`[0, 0]` for an empty
    /// result).
    pub area: [f64; 2],
    /// The regions the edges name: `inputs[e.region]`.
    pub(crate) inputs: [Region; 2],
    /// How it was decided.
    pub(crate) report: Report,
}

/// What the stages of a boolean compute: the loops and the area enclosure of
/// [`RegionResult`], before the inputs are attached.
pub(crate) struct Outline {
    pub loops: Vec<ResultLoop>,
    pub area: [f64; 2],
    pub report: Report,
}

/// How a boolean was decided: which path answered and what, if anything, took exact
/// arithmetic ([`RegionResult::report`]). Every decision is exact either way; this says
/// where the time went.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// Whether the float path answered. When it did not, the exact stages did: an input
    /// number that is not a double (a rational such as 1/3), or a consistency check or an
    /// area enclosure of the float path that failed (`reason`).
    pub float_path: bool,
    /// Whether the float path's shortcut for the generic configuration answered: each
    /// region's loops simple and pairwise disjoint (proved once per region and kept), every
    /// contact between the regions a transversal crossing (the counts below are then 0).
    pub generic: bool,
    /// Why the exact stages answered, when they did.
    pub reason: Option<&'static str>,
    /// Pairs of curves whose boxes meet (each examined).
    pub pairs: usize,
    /// Of those, consecutive curves of a loop proved to meet only at their join.
    pub joins: usize,
    /// Of those, pairs decided exactly in fixed-width integers (control points that are small
    /// integers on one dyadic scale, as in every font): a segment or straight quadratic with
    /// any curve (crossings, shared vertices, ends on the other curve, collinear overlaps), or
    /// two curves proved apart by a quadratic's implicit equation; no big integers.
    pub fixed_width: usize,
    /// Of those, pairs decided by the certified float filter (transversal crossings or none).
    pub filtered: usize,
    /// Of those, pairs intersected exactly in big rationals: a contact the filter cannot
    /// decide (an end on a curve, a shared vertex, a tangency, an overlap) between curves
    /// the fixed-width stage does not take.
    pub exact_pairs: usize,
    /// Curves not proved one-to-one, intersected exactly with themselves.
    pub exact_self: usize,
    /// Comparisons of two half-edges at a vertex decided exactly (tangent branches, zero
    /// derivatives).
    pub exact_orders: usize,
    /// Connected components whose winding numbers were seeded from the sign of a face's area
    /// (no join on a side of the component's box decided).
    pub area_seeds: usize,
    /// Connected components seeded by an exact ray (nothing cheaper decided).
    pub exact_seeds: usize,
}

impl RegionResult {
    /// The regions whose curves the edges are pieces of: `inputs()[edge.region]` (for
    /// [`simplify`](super::simplify), the simplified region and the empty region).
    pub fn inputs(&self) -> &[Region; 2] {
        &self.inputs
    }

    /// How the boolean was decided: the float path or the exact stages, and which contacts,
    /// orders and seeds took exact arithmetic.
    ///
    /// ```
    /// use blossom::region::{boolean, BooleanOp, FillRule, Region};
    /// use blossom::Bezier;
    /// let square = |x: f64, y: f64| -> Region {
    ///     let c = [[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]];
    ///     let sides = (0..4).map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap());
    ///     Region::from_f64(vec![sides.collect()], FillRule::NonZero).unwrap()
    /// };
    /// // Two squares sharing an edge: the float path, the shared edge decided exactly in
    /// // fixed-width integers (the corners are small integers).
    /// let r = boolean(&square(0.0, 0.0), &square(1.0, 0.0), BooleanOp::Union)?;
    /// assert!(r.report().float_path && r.report().fixed_width > 0);
    /// assert_eq!(r.report().exact_pairs, 0);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn report(&self) -> &Report {
        &self.report
    }
}
