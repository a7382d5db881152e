//! Stage 1 of the float path: every curve of both regions split at every contact with every
//! curve (itself and the curves of its own region included), the split points joined into
//! vertices and coincident pieces into groups.
//!
//! **Contacts, pair by pair.** The pairs of curves whose boxes meet ([`for_each_meeting_pair`]) are
//! examined one by one, cheapest proof first:
//!
//! 1. consecutive curves of a loop that a line through their join separates meet only there
//!    (the exact test of `prune`, on doubles);
//! 2. a segment and a curve whose control points are integers on one dyadic scale within 60
//!    bits (every font; most doubles of nearby magnitudes; each curve's integers made once,
//!    [`Dyadic`]) are intersected exactly in fixed-width integers: two segments always
//!    ([`segment_contact_integers`]: crossings, ends on the other segment, shared vertices
//!    and collinear overlaps alike), a segment and a quadratic or cubic when the roots at
//!    the curve's ends leave a factor of degree 1 or of one sign on [0, 1]
//!    ([`segment_curve_integers`]: an end on the segment, a tangent end, no contact). The
//!    parameters are [`Parameter::small`] rationals compared without big integers;
//! 3. two curves, one a quadratic, with coordinates within 25 bits on one scale, are proved
//!    apart when the quadratic's implicit equation has one sign along the other curve
//!    ([`misses_quadratic_integers`], exact in `i128`): neighbouring curves of an outline
//!    and of its moved copies, which the filter below separates only by many subdivisions;
//! 4. the certified float filter ([`crossing_parameters_f64`]) proves every common point of the
//!    pair a transversal crossing strictly inside both curves and gives each parameter's
//!    correctly rounded double with an enclosure of doubles (a [`Parameter::crossing`], made
//!    exact only on demand);
//! 5. otherwise (an end on the other curve, a shared vertex, a tangency, an overlap) that pair
//!    alone is intersected exactly ([`intersect_curves_f64`]): its points and overlaps are
//!    exact [`AlgebraicReal`]s. The rest of the boolean stays in floating point.
//!
//! A curve that is not proved one-to-one (`prune`) is intersected with itself exactly.
//!
//! **Parameters.** Each curve's parameters (0, 1 and every contact) are sorted with
//! [`Parameter::compare`]: disjoint enclosures order two parameters at once; only where
//! enclosures meet are the exact numbers compared, so two contacts at one point of the plane
//! (three curves through one point, a crossing at another curve's end) are recognised
//! exactly and merged. Both sides of every overlap are split alike ([`transfer`], exact; an
//! affine map between segments, in fixed width while its numbers fit), as in the exact
//! stages; the vertices, pieces and groups then come from the same procedure
//! ([`assemble`]).

use crate::error::Result;
use crate::intersect::algebraic::{exact_f64, value_at, AlgebraicReal};
use crate::intersect::curves::{intersect_curves_f64, self_intersections_f64, Intersections};
use crate::intersect::filter::crossing_parameters_f64;
use crate::intersect::implicit::implicitly_apart;
use crate::intersect::line::{
    segment_contact_integers, segment_curve_integers, SegmentContact, SMALL_COORDINATE,
};
use crate::num::ring::Rational;
use crate::num::small::{common_scale, Dyadic, SmallRational};
use crate::region::arrangement::{
    assemble, for_each_meeting_pair, Assembled, CurveId, Group, Piece, Stretch,
};
use crate::region::curve::Curve as ExactCurve;
use crate::region::input::Doubles;
use crate::region::parameter::{Crossings, Parameter};
use crate::region::prune::{consecutive_meet_only_at_join, one_to_one};
use crate::region::straight::Straight;
use crate::region::transfer::transfer;
use crate::shape::array::Bezier;
use std::cell::OnceCell;
use std::cmp::Ordering;
use std::ops::ControlFlow;
use std::sync::Arc;

/// One input curve that traces more than a point.
pub(super) struct Curve<'a> {
    pub points: &'a [[f64; 2]],
    pub id: CurveId,
    /// `[x_lo, y_lo, x_hi, y_hi]` of the control points (exact: comparisons of doubles).
    pub bbox: [f64; 4],
    /// The exact curve, made on first use (only curves in a degenerate contact need it).
    exact: OnceCell<ExactCurve>,
    /// A straight quadratic's kind (module `straight`).
    pub straight: Option<Straight>,
    /// The control points as integers on their own dyadic scale, when they are (degree at
    /// most 3, coordinates of near binades): the fixed-width stages' input.
    dyadic: Option<Dyadic>,
}

impl Curve<'_> {
    /// Whether its points are a linear function of a chord parameter: a segment, or a
    /// straight quadratic (module `straight`).
    fn has_chord(&self) -> bool {
        self.points.len() == 2 || self.straight.is_some()
    }
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
    /// Pairs of segments intersected exactly in fixed-width integers.
    pub fixed_width: usize,
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
    /// The pieces of every group, group after group ([`Group::members`]).
    pub members: Vec<usize>,
    pub counts: ContactCounts,
}

/// Two (curve, parameter) nodes that are one point of the plane: each curve with the place
/// where the parameter was recorded among its parameters ([`Ranks`]).
type Same = [(usize, usize); 2];

/// An overlap of curves p and q: its exact ends on p (increasing) and the matching ends on
/// q.
struct Shared {
    p: usize,
    q: usize,
    s: [Parameter; 2],
    t: [Parameter; 2],
    /// Where s and t were recorded among the parameters of p and q ([`Ranks`]).
    at: [[usize; 2]; 2],
}

/// The exact contacts of one pair of curves (i, j): common points as (s on i, t on j), and
/// overlaps of positive length.
struct Contacts {
    i: usize,
    j: usize,
    points: Vec<[Parameter; 2]>,
    overlaps: Vec<[[Parameter; 2]; 2]>,
}

impl Contacts {
    /// The answer of the exact intersection of curves i and j.
    fn exact(i: usize, j: usize, found: Intersections) -> Contacts {
        let known = |x: &AlgebraicReal| Parameter::known(x.clone());
        Contacts {
            i,
            j,
            points: found
                .points
                .iter()
                .map(|x| [known(&x.s), known(&x.t)])
                .collect(),
            overlaps: found
                .overlaps
                .iter()
                .filter(|o| !o.s[0].equals(&o.s[1]) && !o.t[0].equals(&o.t[1]))
                .map(|o| [o.s.each_ref().map(known), o.t.each_ref().map(known)])
                .collect(),
        }
    }

    /// The contacts of curves i and j in fixed-width integers when their control points
    /// allow it: two chords (segments or straight quadratics), or a chord and a quadratic or
    /// cubic (module `line`); `None` otherwise. A straight quadratic's chord parameters u
    /// become its parameters φ⁻¹(u) (module `straight`).
    fn fixed_width(i: usize, j: usize, a: &Curve<'_>, b: &Curve<'_>) -> Option<Contacts> {
        if !(a.has_chord() || b.has_chord()) {
            return None;
        }
        let [pa, pb] = common_scale(a.dyadic.as_ref()?, b.dyadic.as_ref()?, SMALL_COORDINATE)?;
        let chord = |c: &Curve<'_>, p: &[[i64; 2]; 4]| [p[0], p[c.points.len() - 1]];
        let on = |c: &Curve<'_>, u: SmallRational| Parameter::on_chord(u, c.straight);
        let (mut points, mut overlaps) = (Vec::new(), Vec::new());
        match (a.has_chord(), b.has_chord()) {
            (true, true) => match segment_contact_integers(chord(a, &pa), chord(b, &pb))? {
                SegmentContact::Apart => {}
                SegmentContact::Point([s, t]) => points.push([on(a, s), on(b, t)]),
                SegmentContact::Overlap { s, t } => {
                    overlaps.push([s.map(|x| on(a, x)), t.map(|x| on(b, x))]);
                }
            },
            (true, false) => points.extend(
                segment_curve_integers(chord(a, &pa), &pb[..b.points.len()])?
                    .into_iter()
                    .map(|[s, t]| [on(a, s), Parameter::small(t)]),
            ),
            (false, _) => points.extend(
                segment_curve_integers(chord(b, &pb), &pa[..a.points.len()])?
                    .into_iter()
                    .map(|[t, s]| [Parameter::small(s), on(b, t)]),
            ),
        }
        Some(Contacts {
            i,
            j,
            points,
            overlaps,
        })
    }
}

/// The curves that trace more than a point, in (region, loop, curve) order, and each one's
/// successor in its loop.
fn collect<'a>(doubles: [&'a Doubles; 2]) -> (Vec<Curve<'a>>, Vec<usize>) {
    let total: usize = doubles.iter().flat_map(|d| d.iter()).map(Vec::len).sum();
    let (mut curves, mut next) = (Vec::with_capacity(total), Vec::with_capacity(total));
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
                    straight: Straight::of(points),
                    dyadic: Dyadic::of(points),
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

/// Where each recorded parameter of each curve ended up after the parameters were sorted and
/// made distinct: the place of recorded parameter k of curve c is `index[offset[c] + k]`.
struct Ranks {
    offset: Vec<usize>,
    index: Vec<usize>,
}

impl Ranks {
    /// The place of recorded parameter `k` of curve `c`.
    fn of(&self, c: usize, k: usize) -> usize {
        self.index[self.offset[c] + k]
    }

    /// A parameter was inserted at place `at` of curve `c`: the later ones move up.
    fn inserted(&mut self, c: usize, at: usize) {
        let range = self.offset[c]..self.offset[c + 1];
        for i in &mut self.index[range] {
            if *i >= at {
                *i += 1;
            }
        }
    }
}

/// Sorts each curve's parameters exactly and removes duplicates (keeping, of equal ones, the
/// first recorded: a curve end or an exact number before a crossing, whose exact number is
/// then not needed), and says where each recorded one went. The sort moves indices, and the
/// parameters move once, in place.
fn sort_distinct(params: &mut [Vec<Parameter>]) -> Result<Ranks> {
    let mut offset = Vec::with_capacity(params.len() + 1);
    let mut total = 0;
    for p in params.iter() {
        offset.push(total);
        total += p.len();
    }
    offset.push(total);
    let mut index = vec![0; total];
    let (mut order, mut kept, mut done) = (Vec::new(), Vec::new(), Vec::new());
    let mut failed = None;
    for (c, p) in params.iter_mut().enumerate() {
        let n = p.len();
        order.clear();
        order.extend(0..n);
        // Stable: of equal parameters the first recorded comes first.
        order.sort_by(|&a, &b| compare(&p[a], &p[b], &mut failed));
        kept.clear();
        let rank = &mut index[offset[c]..offset[c + 1]];
        for &k in &order {
            let same = kept
                .last()
                .is_some_and(|&last| compare(&p[last], &p[k], &mut failed) == Ordering::Equal);
            if !same {
                kept.push(k);
            }
            rank[k] = kept.len() - 1;
        }
        let distinct = kept.len();
        // The permutation that puts the kept ones first, in order (the others after them),
        // applied in place by following its cycles: afterwards p[i] is the old p[kept[i]].
        let mut is_kept = std::mem::take(&mut done);
        is_kept.clear();
        is_kept.resize(n, false);
        for &k in &kept {
            is_kept[k] = true;
        }
        kept.extend((0..n).filter(|&k| !is_kept[k]));
        is_kept.iter_mut().for_each(|x| *x = false);
        for i in 0..n {
            if is_kept[i] {
                continue;
            }
            let mut j = i;
            loop {
                is_kept[j] = true;
                let k = kept[j];
                if k == i {
                    break;
                }
                p.swap(j, k);
                j = k;
            }
        }
        done = is_kept;
        p.truncate(distinct);
    }
    failed.map_or(Ok(Ranks { offset, index }), Err)
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
        let mut pairs: Vec<[CurveId; 2]> = Vec::with_capacity(curves.len());
        let mut crossed = Vec::with_capacity(curves.len());
        let mut exact = Vec::with_capacity(curves.len());
        // The pairs in the sweep's order (fixed by the boxes; no sort needed).
        let mut meeting = Vec::with_capacity(4 * boxes.len());
        let _ = for_each_meeting_pair(&boxes, |i, j| {
            meeting.push((i, j));
            ControlFlow::<()>::Continue(())
        });
        for (i, j) in meeting {
            counts.pairs += 1;
            if proved_join(&curves, &next, i, j) {
                counts.joins += 1;
                continue;
            }
            let (p, q) = (curves[i].points, curves[j].points);
            // A segment: fixed width first (it decides two segments always, and a segment with
            // a curve whose end lies on it, which the filter cannot).
            if let Some(found) = Contacts::fixed_width(i, j, &curves[i], &curves[j]) {
                counts.fixed_width += 1;
                if !(found.points.is_empty() && found.overlaps.is_empty()) {
                    exact.push(found);
                }
                continue;
            }
            // Two curves, one a quadratic: its parabola's implicit equation of one sign along
            // the other proves them apart in fixed width (most neighbouring pairs of an
            // outline end here, which the filter separates only by many subdivisions).
            if let (Some(a), Some(b)) = (&curves[i].dyadic, &curves[j].dyadic) {
                if implicitly_apart(a, b) {
                    counts.fixed_width += 1;
                    continue;
                }
            }
            match crossing_parameters_f64(p, q) {
                Some(found) => {
                    counts.filtered += 1;
                    if !found.is_empty() {
                        crossed.push((pairs.len(), i, j, found));
                        pairs.push([curves[i].id, curves[j].id]);
                    }
                }
                None => {
                    counts.exact += 1;
                    exact.push(Contacts::exact(i, j, intersect_curves_f64(p, q)?));
                }
            }
        }
        for (c, curve) in curves.iter().enumerate() {
            if !one_to_one(curve.points) {
                counts.exact_self += 1;
                exact.push(Contacts::exact(c, c, self_intersections_f64(curve.points)?));
            }
        }
        // Phase 2: the parameters.
        let all = Crossings::new([doubles_arc[0].clone(), doubles_arc[1].clone()], pairs);
        // Room for each curve's parameters: its ends and its contacts.
        let mut room = vec![2usize; curves.len()];
        let mut contacts = next.len();
        for (_, i, j, found) in &crossed {
            room[*i] += found.len();
            room[*j] += found.len();
            contacts += found.len();
        }
        for c in &exact {
            room[c.i] += c.points.len() + 2 * c.overlaps.len();
            room[c.j] += c.points.len() + 2 * c.overlaps.len();
            contacts += c.points.len();
        }
        let mut params: Vec<Vec<Parameter>> = room
            .iter()
            .map(|&r| {
                let mut p = Vec::with_capacity(r);
                p.extend([Parameter::end(false), Parameter::end(true)]);
                p
            })
            .collect();
        let mut same: Vec<Same> = Vec::with_capacity(contacts);
        let mut shared = Vec::new();
        let record = |params: &mut Vec<Vec<Parameter>>,
                      same: &mut Vec<Same>,
                      p: usize,
                      s: Parameter,
                      q: usize,
                      t: Parameter| {
            // (p and q are one curve for a self-intersection.)
            let at_s = params[p].len();
            params[p].push(s);
            same.push([(p, at_s), (q, params[q].len())]);
            params[q].push(t);
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
        for Contacts {
            i,
            j,
            points,
            overlaps,
        } in exact
        {
            for [s, t] in points {
                record(&mut params, &mut same, i, s, j, t);
            }
            for [s, t] in overlaps {
                let at_s = params[i].len();
                params[i].extend(s.iter().cloned());
                let at_t = params[j].len();
                params[j].extend(t.iter().cloned());
                let at = [[at_s, at_s + 1], [at_t, at_t + 1]];
                shared.push(Shared {
                    p: i,
                    q: j,
                    s,
                    t,
                    at,
                });
            }
        }
        // Each curve's end 1 (recorded second) is the next curve's end 0 (recorded first).
        for (c, &d) in next.iter().enumerate() {
            same.push([(c, 1), (d, 0)]);
        }
        let mut ranks = sort_distinct(&mut params)?;
        carry_across_overlaps(&curves, &shared, &mut params, &mut ranks)?;
        // Phase 3: vertices, pieces, groups.
        let joins: Vec<[(usize, usize); 2]> = same
            .iter()
            .map(|&[(a, x), (b, y)]| [(a, ranks.of(a, x)), (b, ranks.of(b, y))])
            .collect();
        let stretches: Vec<Stretch> = shared
            .iter()
            .map(|sh| Stretch {
                p: sh.p,
                q: sh.q,
                s: sh.at[0].map(|k| ranks.of(sh.p, k)),
                t: sh.at[1].map(|k| ranks.of(sh.q, k)),
            })
            .collect();
        let lens: Vec<usize> = params.iter().map(Vec::len).collect();
        let Assembled {
            vertex,
            vertices,
            pieces,
            groups,
            members,
        } = assemble(&lens, &joins, &stretches);
        Ok(Graph {
            curves,
            params,
            vertex,
            vertices,
            pieces,
            groups,
            members,
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
    ranks: &mut Ranks,
) -> Result<()> {
    if shared.is_empty() {
        return Ok(());
    }
    // Between two segments, each direction's affine map.
    let maps: Vec<[Option<Affine>; 2]> = shared
        .iter()
        .map(|sh| {
            let (p, q) = (&curves[sh.p], &curves[sh.q]);
            let chords = p.has_chord() && q.has_chord();
            [
                chords.then(|| Affine::new(&sh.s, &sh.t, [p, q])),
                chords.then(|| Affine::new(&sh.t, &sh.s, [q, p])),
            ]
        })
        .collect();
    let mut work: Vec<(usize, Parameter)> = Vec::new();
    let mut queued = vec![false; params.len()];
    for sh in shared {
        for c in [sh.p, sh.q] {
            if !std::mem::replace(&mut queued[c], true) {
                work.extend(params[c].iter().map(|x| (c, x.clone())));
            }
        }
    }
    // The overlaps each curve takes part in, with its side (0: p, 1: q).
    let mut sides: Vec<Vec<(usize, usize)>> = vec![Vec::new(); params.len()];
    for (k, sh) in shared.iter().enumerate() {
        sides[sh.p].push((k, 0));
        sides[sh.q].push((k, 1));
    }
    while let Some((from, x)) = work.pop() {
        for &(k, side) in &sides[from] {
            let sh = &shared[k];
            let (to, from_range, to_range, map) = if side == 0 {
                (sh.q, &sh.s, &sh.t, &maps[k][0])
            } else {
                (sh.p, &sh.t, &sh.s, &maps[k][1])
            };
            if !strictly_inside(&x, from_range)? {
                continue;
            }
            let image = map.as_ref().map(|m| m.image(&x, [from_range, to_range]));
            let t = match image.transpose()?.flatten() {
                Some(t) => t,
                None => Parameter::known(transfer(
                    curves[from].exact(),
                    x.algebraic()?,
                    curves[to].exact(),
                    (to_range[0].algebraic()?, to_range[1].algebraic()?),
                )),
            };
            let mut failed = None;
            let at = params[to].binary_search_by(|p| compare(p, &t, &mut failed));
            if let Some(e) = failed {
                return Err(e);
            }
            if let Err(at) = at {
                params[to].insert(at, t.clone());
                ranks.inserted(to, at);
                work.push((to, t));
            }
        }
    }
    Ok(())
}

/// Whether x lies strictly between the two ends of `range` (in either order): enclosures
/// first, exact comparisons only where they meet.
fn strictly_inside(x: &Parameter, range: &[Parameter; 2]) -> Result<bool> {
    let [a, b] = range;
    let (lo, hi) = if a.compare(b)? == Ordering::Greater {
        (b, a)
    } else {
        (a, b)
    };
    Ok(x.compare(lo)? == Ordering::Greater && x.compare(hi)? == Ordering::Less)
}

/// The affine map v = shift + slope u taking one overlap's ends on one chord to its ends on
/// the other, in chord parameters (a segment's own parameter, a straight quadratic's u): in
/// fixed width while its numbers fit, else, between two segments, in big rationals (the
/// overlap ends of two segments are rational).
struct Affine {
    small: Option<[SmallRational; 2]>,
    big: OnceCell<[Rational; 2]>,
    /// The kind of the target when it is a straight quadratic.
    target: Option<Straight>,
    /// Whether both curves are segments (chord parameter = curve parameter).
    segments: bool,
}

impl Affine {
    fn new(from: &[Parameter; 2], to: &[Parameter; 2], curves: [&Curve<'_>; 2]) -> Affine {
        let small = || {
            let [s0, s1, t0, t1] =
                [&from[0], &from[1], &to[0], &to[1]].map(Parameter::chord_coordinate);
            let (s0, s1, t0, t1) = (s0?, s1?, t0?, t1?);
            let slope = t1.sub(t0)?.div(s1.sub(s0)?)?;
            Some([t0.sub(s0.mul(slope)?)?, slope])
        };
        Affine {
            small: small(),
            big: OnceCell::new(),
            target: curves[1].straight,
            segments: curves.iter().all(|c| c.points.len() == 2),
        }
    }

    /// `[shift, slope]` in big rationals, made once from the overlap's `ends` (its ends on the
    /// source, then on the target).
    fn big(&self, ends: [&[Parameter; 2]; 2]) -> Result<&[Rational; 2]> {
        if let Some(b) = self.big.get() {
            return Ok(b);
        }
        let mut end = [
            [Rational::default(), Rational::default()],
            [Rational::default(), Rational::default()],
        ];
        for (e, side) in end.iter_mut().zip(ends) {
            for (v, x) in e.iter_mut().zip(side) {
                *v = x
                    .algebraic()?
                    .exact()
                    .cloned()
                    .expect("the overlap of two segments has rational ends");
            }
        }
        let [[s0, s1], [t0, t1]] = end;
        let slope = (&t1 - &t0) / (&s1 - &s0);
        Ok(self.big.get_or_init(|| [&t0 - &s0 * &slope, slope]))
    }

    /// The image of x, exactly; `None` when neither fixed width nor (between segments) big
    /// rationals apply, for the caller's exact transfer. `ends` as for [`Affine::big`].
    fn image(&self, x: &Parameter, ends: [&[Parameter; 2]; 2]) -> Result<Option<Parameter>> {
        if let (Some([shift, slope]), Some(s)) = (self.small, x.chord_coordinate()) {
            if let Some(t) = s.mul(slope).and_then(|v| v.add(shift)) {
                return Ok(Some(Parameter::on_chord(t, self.target)));
            }
        }
        if !self.segments {
            return Ok(None);
        }
        let [shift, slope] = self.big(ends)?;
        let x = x.algebraic()?;
        Ok(Some(Parameter::known(match x.exact() {
            Some(s) => AlgebraicReal::from_rational(shift + s * slope),
            None => value_at(&[shift.clone(), slope.clone()], x),
        })))
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
        for &i in &self.members[self.groups[g].members.clone()] {
            let piece = &self.pieces[i];
            m[self.curves[piece.curve].id.region] += if piece.along { 1 } else { -1 };
        }
        m
    }
}
