//! Stage 1 of the float path: every curve of both regions split at every contact with every
//! curve (itself and the curves of its own region included), the split points joined into
//! vertices and coincident pieces into groups.
//!
//! **Contacts, pair by pair.** The pairs of curves whose boxes meet ([`meeting_boxes`]) are
//! examined one by one, cheapest proof first:
//!
//! 1. consecutive curves of a loop that a line through their join separates meet only there
//!    (the exact test of `prune`, on doubles);
//! 2. the certified float filter ([`certified_crossings_f64`]) proves every common point of the
//!    pair a transversal crossing strictly inside both curves and gives each parameter's
//!    correctly rounded double with an enclosure of doubles (a [`Parameter::crossing`], made
//!    exact only on demand);
//! 3. otherwise (an end on the other curve, a shared vertex, a tangency, an overlap) that pair
//!    alone is intersected exactly ([`intersect_curves_f64`]): its points and overlaps are
//!    exact [`AlgebraicReal`]s. The rest of the boolean stays in floating point.
//!
//! A curve that is not proved one-to-one (`prune`) is intersected with itself exactly.
//!
//! **Parameters.** Each curve's parameters (0, 1 and every contact) are sorted with
//! [`Parameter::compare`]: disjoint enclosures order two parameters at once; only where
//! enclosures meet are the exact numbers compared, so two contacts at one point of the plane
//! (three curves through one point, a crossing at another curve's end) are recognised
//! exactly and merged. Both sides of every overlap are split alike ([`transfer`], exact), as
//! in the exact stages; the vertices, pieces and groups then come from the same procedure
//! ([`assemble`]).

use crate::error::Result;
use crate::intersect::algebraic::{exact_f64, value_at, AlgebraicReal};
use crate::intersect::curves::{intersect_curves_f64, self_intersections_f64, Overlap};
use crate::intersect::filter::certified_crossings_f64;
use crate::num::ring::Rational;
use crate::region::arrangement::{
    assemble, meeting_boxes, strictly_between, Assembled, CurveId, Group, Piece, Stretch,
};
use crate::region::curve::Curve as ExactCurve;
use crate::region::input::Doubles;
use crate::region::parameter::{Crossings, Parameter};
use crate::region::prune::{consecutive_meet_only_at_join, one_to_one};
use crate::region::transfer::transfer;
use crate::shape::array::Bezier;
use std::cell::OnceCell;
use std::cmp::Ordering;
use std::sync::Arc;

/// One input curve that traces more than a point.
pub(super) struct Curve<'a> {
    pub points: &'a [[f64; 2]],
    pub id: CurveId,
    /// `[x_lo, y_lo, x_hi, y_hi]` of the control points (exact: comparisons of doubles).
    pub bbox: [f64; 4],
    /// The exact curve, made on first use (only curves in a degenerate contact need it).
    exact: OnceCell<ExactCurve>,
}

impl Curve<'_> {
    /// The exact curve (power form and the exact stages' derived data), made once.
    pub fn exact(&self) -> &ExactCurve {
        self.exact.get_or_init(|| {
            let points = self
                .points
                .iter()
                .map(|p| [exact_f64(p[0]), exact_f64(p[1])])
                .collect();
            ExactCurve::new(&Bezier::new(points).expect("a validated curve"))
        })
    }
}

/// `[x_lo, y_lo, x_hi, y_hi]` of the control points.
pub(super) fn bbox(points: &[[f64; 2]]) -> [f64; 4] {
    let mut b = [points[0][0], points[0][1], points[0][0], points[0][1]];
    for p in points {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    b
}

/// How the contacts were decided (the counts of [`Report`](crate::region::Report)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct ContactCounts {
    /// Pairs of curves whose boxes meet.
    pub pairs: usize,
    /// Pairs proved by the float filter (crossings or nothing).
    pub filtered: usize,
    /// Consecutive curves proved to meet only at their join.
    pub joins: usize,
    /// Pairs intersected exactly (a contact the filter could not decide).
    pub exact: usize,
    /// Curves intersected exactly with themselves.
    pub exact_self: usize,
}

/// The split curves, their vertices and groups.
pub(super) struct Graph<'a> {
    pub curves: Vec<Curve<'a>>,
    /// Each curve's parameters, increasing and distinct, 0 and 1 included.
    pub params: Vec<Vec<Parameter>>,
    /// The vertex of each (curve, parameter index).
    pub vertex: Vec<Vec<usize>>,
    /// How many vertices.
    pub vertices: usize,
    pub pieces: Vec<Piece>,
    pub groups: Vec<Group>,
    pub counts: ContactCounts,
}

/// Two (curve, parameter) nodes that are one point of the plane.
type Same = [(usize, Parameter); 2];

/// An overlap of curves p and q with its exact ends.
struct Shared {
    p: usize,
    q: usize,
    overlap: Overlap,
}

/// The curves that trace more than a point, in (region, loop, curve) order, and each one's
/// successor in its loop.
fn collect<'a>(doubles: [&'a Doubles; 2]) -> (Vec<Curve<'a>>, Vec<usize>) {
    let (mut curves, mut next) = (Vec::new(), Vec::new());
    for (region, loops) in doubles.iter().enumerate() {
        for (loop_index, lp) in loops.iter().enumerate() {
            let first = curves.len();
            for (curve, points) in lp.iter().enumerate() {
                if points.iter().all(|p| *p == points[0]) {
                    continue;
                }
                curves.push(Curve {
                    points,
                    id: CurveId {
                        region,
                        loop_index,
                        curve,
                    },
                    bbox: bbox(points),
                    exact: OnceCell::new(),
                });
                next.push(curves.len());
            }
            if curves.len() > first {
                *next.last_mut().expect("the loop has a curve") = first;
            }
        }
    }
    (curves, next)
}

/// Whether curve j follows curve i in its loop (and not also the other way round) and a line
/// through their join separates them.
fn proved_join(curves: &[Curve<'_>], next: &[usize], i: usize, j: usize) -> bool {
    let ordered = |a: usize, b: usize| {
        next[a] == b
            && next[b] != a
            && consecutive_meet_only_at_join(curves[a].points, curves[b].points)
    };
    ordered(i, j) || ordered(j, i)
}

/// The exact order of two parameters of one curve, recording the first error.
fn compare(a: &Parameter, b: &Parameter, failed: &mut Option<crate::Error>) -> Ordering {
    a.compare(b).unwrap_or_else(|e| {
        failed.get_or_insert(e);
        Ordering::Equal
    })
}

/// Sorts the parameters exactly and removes duplicates (keeping, of equal ones, the first:
/// a curve end or an exact number before a crossing, whose exact number is then not needed).
fn sort_distinct(p: &mut Vec<Parameter>) -> Result<()> {
    let mut failed = None;
    p.sort_by(|a, b| compare(a, b, &mut failed));
    p.dedup_by(|a, b| compare(a, b, &mut failed) == Ordering::Equal);
    failed.map_or(Ok(()), Err)
}

/// The index of `x` among the sorted distinct `params` (present by construction).
fn index_of(params: &[Parameter], x: &Parameter) -> Result<usize> {
    let mut failed = None;
    let found = params.binary_search_by(|p| compare(p, x, &mut failed));
    if let Some(e) = failed {
        return Err(e);
    }
    Ok(found.expect("every split parameter was recorded"))
}

impl<'a> Graph<'a> {
    /// The arrangement of the curves of both regions (`doubles[r][l][c]`: the control points of
    /// curve c of loop l of region r); `doubles_arc` are the same, shared, for the parameters
    /// that make their exact numbers later.
    pub fn build(doubles_arc: [&'a Arc<Doubles>; 2]) -> Result<Graph<'a>> {
        let doubles: [&'a Doubles; 2] = [doubles_arc[0].as_ref(), doubles_arc[1].as_ref()];
        let (curves, next) = collect(doubles);
        let mut counts = ContactCounts::default();
        let boxes: Vec<[f64; 4]> = curves.iter().map(|c| c.bbox).collect();
        // Phase 1: every pair decided, the filter's crossings kept as doubles.
        let mut pairs: Vec<[CurveId; 2]> = Vec::new();
        let mut crossed = Vec::new();
        let mut exact = Vec::new();
        for (i, j) in meeting_boxes(&boxes) {
            counts.pairs += 1;
            if proved_join(&curves, &next, i, j) {
                counts.joins += 1;
                continue;
            }
            match certified_crossings_f64(curves[i].points, curves[j].points) {
                Some(found) => {
                    counts.filtered += 1;
                    if !found.is_empty() {
                        crossed.push((pairs.len(), i, j, found));
                        pairs.push([curves[i].id, curves[j].id]);
                    }
                }
                None => {
                    counts.exact += 1;

                    exact.push((
                        i,
                        j,
                        intersect_curves_f64(curves[i].points, curves[j].points)?,
                    ));
                }
            }
        }
        for (c, curve) in curves.iter().enumerate() {
            if !one_to_one(curve.points) {
                counts.exact_self += 1;
                exact.push((c, c, self_intersections_f64(curve.points)?));
            }
        }
        // Phase 2: the parameters.
        let all = Crossings::new([doubles_arc[0].clone(), doubles_arc[1].clone()], pairs);
        let mut params: Vec<Vec<Parameter>> = curves
            .iter()
            .map(|_| vec![Parameter::end(false), Parameter::end(true)])
            .collect();
        let mut same: Vec<Same> = Vec::new();
        let mut shared = Vec::new();
        let record = |params: &mut Vec<Vec<Parameter>>,
                      same: &mut Vec<Same>,
                      p: usize,
                      s: Parameter,
                      q: usize,
                      t: Parameter| {
            params[p].push(s.clone());
            params[q].push(t.clone());
            same.push([(p, s), (q, t)]);
        };
        for (pair, i, j, found) in crossed {
            for x in found {
                let at = |side: usize, nearest: f64| {
                    Parameter::crossing(
                        all.clone(),
                        pair,
                        side,
                        x.s_enclosure,
                        x.t_enclosure,
                        nearest,
                    )
                };
                record(&mut params, &mut same, i, at(0, x.s), j, at(1, x.t));
            }
        }
        for (i, j, found) in exact {
            for x in found.points {
                let (s, t) = (Parameter::known(x.s), Parameter::known(x.t));
                record(&mut params, &mut same, i, s, j, t);
            }
            for overlap in found.overlaps {
                let ends = [&overlap.s[0], &overlap.s[1], &overlap.t[0], &overlap.t[1]];
                if ends[0].equals(ends[1]) || ends[2].equals(ends[3]) {
                    continue;
                }
                for e in 0..2 {
                    params[i].push(Parameter::known(overlap.s[e].clone()));
                    params[j].push(Parameter::known(overlap.t[e].clone()));
                }
                shared.push(Shared {
                    p: i,
                    q: j,
                    overlap,
                });
            }
        }
        for (c, &d) in next.iter().enumerate() {
            same.push([(c, Parameter::end(true)), (d, Parameter::end(false))]);
        }
        for p in params.iter_mut() {
            sort_distinct(p)?;
        }
        carry_across_overlaps(&curves, &shared, &mut params)?;
        // Phase 3: vertices, pieces, groups.
        let mut joins = Vec::with_capacity(same.len());
        for [(a, x), (b, y)] in &same {
            joins.push([
                (*a, index_of(&params[*a], x)?),
                (*b, index_of(&params[*b], y)?),
            ]);
        }
        let mut stretches = Vec::with_capacity(shared.len());
        for sh in &shared {
            let at =
                |c: usize, x: &AlgebraicReal| index_of(&params[c], &Parameter::known(x.clone()));
            stretches.push(Stretch {
                p: sh.p,
                q: sh.q,
                s: [at(sh.p, &sh.overlap.s[0])?, at(sh.p, &sh.overlap.s[1])?],
                t: [at(sh.q, &sh.overlap.t[0])?, at(sh.q, &sh.overlap.t[1])?],
            });
        }
        let lens: Vec<usize> = params.iter().map(Vec::len).collect();
        let Assembled {
            vertex,
            vertices,
            pieces,
            groups,
        } = assemble(&lens, &joins, &stretches);
        Ok(Graph {
            curves,
            params,
            vertex,
            vertices,
            pieces,
            groups,
            counts,
        })
    }
}

/// Makes both sides of every overlap split alike: each parameter strictly inside one side's
/// range is carried to the other side exactly until nothing new appears (the exact stages do
/// the same on exact numbers). A worklist holds the parameters not yet carried, so each is
/// carried once per overlap. Between two segments the carried parameter is the affine image
/// t0 + (s - s0)(t1 - t0)/(s1 - s0) (both trace the common stretch at constant speed), else
/// [`transfer`] finds it on the curve.
fn carry_across_overlaps(
    curves: &[Curve<'_>],
    shared: &[Shared],
    params: &mut [Vec<Parameter>],
) -> Result<()> {
    if shared.is_empty() {
        return Ok(());
    }
    // Each overlap's range on each side as doubles around it.
    let span = |r: &[AlgebraicReal; 2]| {
        let (a, b) = (r[0].to_f64(), r[1].to_f64());
        [a.min(b).next_down(), a.max(b).next_up()]
    };
    let spans: Vec<[[f64; 2]; 2]> = shared
        .iter()
        .map(|sh| [span(&sh.overlap.s), span(&sh.overlap.t)])
        .collect();
    // Between two segments, each direction's affine map, made once.
    let maps: Vec<[Option<Affine>; 2]> = shared
        .iter()
        .map(|sh| {
            let segments = curves[sh.p].points.len() == 2 && curves[sh.q].points.len() == 2;
            let o = &sh.overlap;
            [
                segments.then(|| Affine::new(&o.s, &o.t)),
                segments.then(|| Affine::new(&o.t, &o.s)),
            ]
        })
        .collect();
    let mut work: Vec<(usize, Parameter)> = Vec::new();
    for sh in shared {
        for c in [sh.p, sh.q] {
            work.extend(params[c].iter().map(|x| (c, x.clone())));
        }
    }
    while let Some((from, x)) = work.pop() {
        for (k, (sh, span)) in shared.iter().zip(&spans).enumerate() {
            let o = &sh.overlap;
            for (side_from, to, from_range, to_range, [lo, hi]) in [
                (sh.p, sh.q, &o.s, &o.t, span[0]),
                (sh.q, sh.p, &o.t, &o.s, span[1]),
            ] {
                if side_from != from {
                    continue;
                }
                let [a, b] = x.enclosure();
                if b < lo || a > hi {
                    continue;
                }
                let exact = x.algebraic()?;
                // Inside by the enclosures alone (lo, hi are outward around the ends).
                let clearly_inside = a > lo.next_up().next_up() && b < hi.next_down().next_down();
                if !clearly_inside && !strictly_between(exact, &from_range[0], &from_range[1]) {
                    continue;
                }
                let t = if let Some(map) = &maps[k][usize::from(side_from != sh.p)] {
                    map.image(exact)
                } else {
                    transfer(
                        curves[from].exact(),
                        exact,
                        curves[to].exact(),
                        (&to_range[0], &to_range[1]),
                    )
                };
                let t = Parameter::known(t);
                let mut failed = None;
                let at = params[to].binary_search_by(|p| compare(p, &t, &mut failed));
                if let Some(e) = failed {
                    return Err(e);
                }
                if let Err(at) = at {
                    params[to].insert(at, t.clone());
                    work.push((to, t));
                }
            }
        }
    }
    Ok(())
}

/// The affine map t = shift + slope s taking one overlap's ends on one segment to its ends
/// on the other (rational: the overlap ends of two segments are).
struct Affine {
    shift: Rational,
    slope: Rational,
}

impl Affine {
    fn new(from: &[AlgebraicReal; 2], to: &[AlgebraicReal; 2]) -> Affine {
        let end = |x: &AlgebraicReal| {
            x.exact()
                .cloned()
                .expect("the overlap of two segments has rational ends")
        };
        let (s0, s1, t0, t1) = (end(&from[0]), end(&from[1]), end(&to[0]), end(&to[1]));
        let slope = (&t1 - &t0) / (&s1 - &s0);
        Affine {
            shift: &t0 - &s0 * &slope,
            slope,
        }
    }

    /// The image of x, exactly.
    fn image(&self, x: &AlgebraicReal) -> AlgebraicReal {
        match x.exact() {
            Some(s) => AlgebraicReal::from_rational(&self.shift + s * &self.slope),
            None => value_at(&[self.shift.clone(), self.slope.clone()], x),
        }
    }
}

/// Half-edges: group g runs along its representative piece as half-edge 2g (from the lower
/// parameter to the higher) and against it as 2g + 1. Each leaves its *origin* vertex.
impl Graph<'_> {
    /// How many half-edges.
    pub fn half_edges(&self) -> usize {
        2 * self.groups.len()
    }

    /// Half-edge h as (curve, index of the parameter it leaves, index it runs toward).
    pub fn branch(&self, h: usize) -> (usize, usize, usize) {
        let p = &self.pieces[self.groups[h / 2].rep];
        if h.is_multiple_of(2) {
            (p.curve, p.k, p.k + 1)
        } else {
            (p.curve, p.k + 1, p.k)
        }
    }

    /// The vertex half-edge h leaves.
    pub fn origin(&self, h: usize) -> usize {
        let (c, at, _) = self.branch(h);
        self.vertex[c][at]
    }

    /// The vertex half-edge h arrives at.
    pub fn dest(&self, h: usize) -> usize {
        let (c, _, toward) = self.branch(h);
        self.vertex[c][toward]
    }

    /// The signed number of group g's pieces of each region (+1 for a piece running the
    /// representative's way): how much each region's winding number grows from the right
    /// of the representative to its left.
    pub fn multiplicity(&self, g: usize) -> [i64; 2] {
        let mut m = [0, 0];
        for &i in &self.groups[g].members {
            let piece = &self.pieces[i];
            m[self.curves[piece.curve].id.region] += if piece.along { 1 } else { -1 };
        }
        m
    }
}
