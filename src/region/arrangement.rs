//! The arrangement of all input curves: every curve split at its certified intersections
//! with every curve (itself included), the split points joined into vertices, and the
//! pieces that coincide merged into groups.
//!
//! * **Pairs.** Curves are sorted by the left side of their outward-rounded boxes; a sweep
//!   pairs each curve with the later ones whose left side is not beyond its right side and
//!   whose boxes meet. Only those pairs are intersected ([`intersect_curves`]); a pair whose
//!   boxes are disjoint provably does not meet. Each curve is also intersected with itself
//!   ([`self_intersections`]).
//! * **Parameters.** Each curve's parameters (0, 1, every intersection and every overlap end)
//!   are sorted and made distinct by exact comparison; consecutive ones bound its pieces.
//! * **Vertices.** A (curve, parameter) node is joined (union-find) with every node that is
//!   the same point: both sides of an intersection, the end of a curve and the start of the
//!   next one in its loop, a self-intersection's two parameters, the matching parameters of
//!   an overlap.
//! * **Groups.** An overlap pairs the pieces of both curves inside it, in order (after
//!   [`transfer`] has carried every parameter of one side inside the overlap to the other
//!   side, so both sides are split alike); the pairs are joined (union-find with the parity
//!   of their directions) into groups of coincident pieces. A group's representative is its
//!   piece of the lowest curve index, which is the order (region, loop, curve), and of the
//!   lower parameters on that curve.

use super::curve::{one, zero, Curve};
use super::prune::consecutive_meet_only_at_join;
pub(crate) use super::prune::one_to_one;
use super::transfer::transfer;
use crate::error::Result;
use crate::intersect::algebraic::AlgebraicReal;
use crate::intersect::curves::{intersect_curves, self_intersections, Overlap};
use std::cmp::Ordering;
use std::ops::ControlFlow;

/// Which input curve: region, loop, curve (the order of these is the priority of the spec).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct CurveId {
    pub region: usize,
    pub loop_index: usize,
    pub curve: usize,
}

/// A piece of a curve between two consecutive parameters.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    /// Index into the arrangement's curves.
    pub curve: usize,
    /// The piece runs from `params[curve][k]` to `params[curve][k + 1]`.
    pub k: usize,
    /// The group of coincident pieces it belongs to.
    pub group: usize,
    /// Whether it runs the same way as its group's representative.
    pub along: bool,
}

/// A group of coincident pieces.
#[derive(Clone, Debug)]
pub(crate) struct Group {
    /// The representative piece.
    pub rep: usize,
    /// Its pieces (the representative included): this range of the arrangement's
    /// `members`.
    pub members: std::ops::Range<usize>,
}

/// The split curves, vertices and groups.
pub(crate) struct Arrangement {
    /// The curves that trace more than a point, in (region, loop, curve) order.
    pub curves: Vec<Curve>,
    /// Which input curve each is.
    pub ids: Vec<CurveId>,
    /// Each curve's parameters, increasing, distinct, 0 and 1 included.
    pub params: Vec<Vec<AlgebraicReal>>,
    /// The vertex of each (curve, parameter index).
    pub vertex: Vec<Vec<usize>>,
    /// Every piece.
    pub pieces: Vec<Piece>,
    /// The groups of coincident pieces.
    pub groups: Vec<Group>,
    /// The pieces of every group, group after group ([`Group::members`]).
    pub members: Vec<usize>,
}

/// Union-find with the parity of each element relative to its root.
pub(crate) struct Joins {
    parent: Vec<usize>,
    parity: Vec<bool>,
}

impl Joins {
    pub(crate) fn new(n: usize) -> Self {
        Joins {
            parent: (0..n).collect(),
            parity: vec![false; n],
        }
    }

    pub(crate) fn find(&mut self, x: usize) -> (usize, bool) {
        let p = self.parent[x];
        if p == x {
            return (x, false);
        }
        let (root, up) = self.find(p);
        self.parent[x] = root;
        self.parity[x] ^= up;
        (root, self.parity[x])
    }

    /// Joins x and y with `flip` their relative parity.
    pub(crate) fn join(&mut self, x: usize, y: usize, flip: bool) {
        let (rx, px) = self.find(x);
        let (ry, py) = self.find(y);
        if rx != ry {
            self.parent[rx] = ry;
            self.parity[rx] = px ^ py ^ flip;
        }
    }
}

/// A pending identification of two (curve, parameter) nodes.
struct Same {
    a: (usize, AlgebraicReal),
    b: (usize, AlgebraicReal),
}

/// An overlap between curves `p` and `q` (possibly one curve retracing itself).
struct Shared {
    p: usize,
    q: usize,
    overlap: Overlap,
}

/// For curves i < j that follow each other in a loop and are proved to meet only at their
/// join ([`consecutive_meet_only_at_join`]): `Some(true)` when curve i ends at the join
/// (their one intersection is (1, 0)), `Some(false)` when curve j does ((0, 1)); `None`
/// when the exact intersector must answer.
pub(crate) fn proved_join(curves: &[Curve], next: &[usize], i: usize, j: usize) -> Option<bool> {
    if next[i] == j
        && next[j] != i
        && consecutive_meet_only_at_join(&curves[i].points, &curves[j].points)
    {
        Some(true)
    } else if next[j] == i
        && next[i] != j
        && consecutive_meet_only_at_join(&curves[j].points, &curves[i].points)
    {
        Some(false)
    } else {
        None
    }
}

/// The index of `x` among the sorted distinct `params` (present by construction).
fn index_of(params: &[AlgebraicReal], x: &AlgebraicReal) -> usize {
    params
        .binary_search_by(|p| p.compare(x))
        .expect("every split parameter was recorded")
}

/// The pairs of curves whose boxes meet, by a sweep over the boxes' left sides.
pub(crate) fn candidate_pairs(curves: &[Curve]) -> Vec<(usize, usize)> {
    let boxes: Vec<[f64; 4]> = curves.iter().map(|c| c.bbox).collect();
    meeting_boxes(&boxes)
}

/// The pairs (i, j), i < j, of boxes `[x_lo, y_lo, x_hi, y_hi]` that meet (closed boxes),
/// sorted ([`for_each_meeting_pair`], collected).
pub(crate) fn meeting_boxes(boxes: &[[f64; 4]]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::with_capacity(4 * boxes.len());
    let _ = for_each_meeting_pair(boxes, |i, j| {
        pairs.push((i, j));
        ControlFlow::<()>::Continue(())
    });
    if boxes.len() > SMALL_SWEEP {
        pairs.sort_unstable();
    }
    pairs
}

/// Up to this many boxes, every pair is tried in index order (cheaper than the sort).
const SMALL_SWEEP: usize = 16;

/// Calls `f(i, j)`, i < j, for each pair of boxes `[x_lo, y_lo, x_hi, y_hi]` that meet (closed
/// boxes), until it breaks: a sweep over the boxes ordered by their left side, each paired
/// with the later ones whose left side is not beyond its right side (a few boxes: every pair,
/// in index order). The order of the pairs is fixed by the boxes alone.
pub(crate) fn for_each_meeting_pair<B>(
    boxes: &[[f64; 4]],
    mut f: impl FnMut(usize, usize) -> ControlFlow<B>,
) -> ControlFlow<B> {
    let meet =
        |a: &[f64; 4], b: &[f64; 4]| a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
    if boxes.len() <= SMALL_SWEEP {
        for (i, a) in boxes.iter().enumerate() {
            for (j, b) in boxes.iter().enumerate().skip(i + 1) {
                if meet(a, b) {
                    f(i, j)?;
                }
            }
        }
        return ControlFlow::Continue(());
    }
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_unstable_by(|&i, &j| boxes[i][0].total_cmp(&boxes[j][0]));
    for (n, &i) in order.iter().enumerate() {
        let (a, rest) = (&boxes[i], &order[n + 1..]);
        for &j in rest {
            let b = &boxes[j];
            if b[0] > a[2] {
                break;
            }
            if a[1] <= b[3] && b[1] <= a[3] {
                f(i.min(j), i.max(j))?;
            }
        }
    }
    ControlFlow::Continue(())
}

impl Arrangement {
    /// The arrangement of `curves` (in (region, loop, curve) order, single points removed)
    /// with the loops' successions `next` (`next[c]` is the curve whose start is the end of
    /// curve c).
    pub fn build(curves: Vec<Curve>, ids: Vec<CurveId>, next: &[usize]) -> Result<Arrangement> {
        let n = curves.len();
        let mut params: Vec<Vec<AlgebraicReal>> = vec![vec![zero(), one()]; n];
        let mut same = Vec::new();
        let mut shared = Vec::new();
        let mut record = |p: usize,
                          q: usize,
                          points: Vec<(AlgebraicReal, AlgebraicReal)>,
                          overlaps: Vec<Overlap>| {
            for (s, t) in points {
                params[p].push(s.clone());
                params[q].push(t.clone());
                same.push(Same {
                    a: (p, s),
                    b: (q, t),
                });
            }
            for overlap in overlaps {
                let ends = [&overlap.s[0], &overlap.s[1], &overlap.t[0], &overlap.t[1]];
                if ends[0].equals(ends[1]) || ends[2].equals(ends[3]) {
                    continue;
                }
                params[p].extend([overlap.s[0].clone(), overlap.s[1].clone()]);
                params[q].extend([overlap.t[0].clone(), overlap.t[1].clone()]);
                shared.push(Shared { p, q, overlap });
            }
        };
        let pairs = candidate_pairs(&curves);
        for &(i, j) in &pairs {
            match proved_join(&curves, next, i, j) {
                Some(true) => record(i, j, vec![(one(), zero())], Vec::new()),
                Some(false) => record(i, j, vec![(zero(), one())], Vec::new()),
                None => {
                    let found = intersect_curves(&curves[i].points, &curves[j].points)?;
                    let points = found.points.into_iter().map(|x| (x.s, x.t)).collect();
                    record(i, j, points, found.overlaps);
                }
            }
        }
        for (i, curve) in curves.iter().enumerate() {
            if one_to_one(&curve.points) {
                continue;
            }
            let found = self_intersections(&curve.points)?;
            let points = found.points.into_iter().map(|x| (x.s, x.t)).collect();
            record(i, i, points, found.overlaps);
        }
        for (c, &d) in next.iter().enumerate() {
            same.push(Same {
                a: (c, one()),
                b: (d, zero()),
            });
        }
        for p in params.iter_mut() {
            sort_distinct(p);
        }
        carry_across_overlaps(&curves, &shared, &mut params);

        let node = |c: usize, x: &AlgebraicReal| (c, index_of(&params[c], x));
        let joins: Vec<[(usize, usize); 2]> = same
            .iter()
            .map(|s| [node(s.a.0, &s.a.1), node(s.b.0, &s.b.1)])
            .collect();
        let stretches: Vec<Stretch> = shared
            .iter()
            .map(|sh| Stretch {
                p: sh.p,
                q: sh.q,
                s: [
                    index_of(&params[sh.p], &sh.overlap.s[0]),
                    index_of(&params[sh.p], &sh.overlap.s[1]),
                ],
                t: [
                    index_of(&params[sh.q], &sh.overlap.t[0]),
                    index_of(&params[sh.q], &sh.overlap.t[1]),
                ],
            })
            .collect();
        let lens: Vec<usize> = params.iter().map(Vec::len).collect();
        let Assembled {
            vertex,
            pieces,
            groups,
            members,
            ..
        } = assemble(&lens, &joins, &stretches);
        Ok(Arrangement {
            curves,
            ids,
            params,
            vertex,
            pieces,
            groups,
            members,
        })
    }

    /// The parameters of piece `i`: (from, to), increasing.
    pub fn ends(&self, i: usize) -> (&AlgebraicReal, &AlgebraicReal) {
        let p = &self.pieces[i];
        (&self.params[p.curve][p.k], &self.params[p.curve][p.k + 1])
    }

    /// The vertices of piece `i` at its lower and upper parameter.
    pub fn end_vertices(&self, i: usize) -> (usize, usize) {
        let p = &self.pieces[i];
        (self.vertex[p.curve][p.k], self.vertex[p.curve][p.k + 1])
    }
}

/// An overlap by parameter indices: curve `p` from index `s[0]` to `s[1]` (increasing)
/// traces the same points as curve `q` from index `t[0]` to `t[1]` (either way), both sides
/// split alike.
pub(crate) struct Stretch {
    pub p: usize,
    pub q: usize,
    pub s: [usize; 2],
    pub t: [usize; 2],
}

/// The vertices, pieces and groups of an arrangement (see [`assemble`]).
pub(crate) struct Assembled {
    /// The vertex of each (curve, parameter index).
    pub vertex: Vec<Vec<usize>>,
    /// How many vertices.
    pub vertices: usize,
    /// Every piece, by curve then parameter index.
    pub pieces: Vec<Piece>,
    /// The groups of coincident pieces.
    pub groups: Vec<Group>,
    /// The pieces of every group, group after group ([`Group::members`]).
    pub members: Vec<usize>,
}

/// The vertices, pieces and groups of curves split at `lens[c]` sorted distinct parameters
/// each: (curve, index) nodes joined by `joins` (two nodes that are one point of the plane)
/// and by the matching ends inside every overlap `stretches`, whose pieces are paired in
/// order into groups (union-find with the parity of their directions). Pieces are numbered by
/// curve then parameter, so the first piece met of a group is its representative (lowest
/// curve, then lowest parameters). One procedure for the exact stages and the float path,
/// which differ only in how they find and compare the parameters.
pub(crate) fn assemble(
    lens: &[usize],
    joins: &[[(usize, usize); 2]],
    stretches: &[Stretch],
) -> Assembled {
    let n = lens.len();
    let mut offset = Vec::with_capacity(n + 1);
    let mut total = 0;
    for &len in lens {
        offset.push(total);
        total += len;
    }
    let mut nodes = Joins::new(total);
    for [(a, i), (b, j)] in joins {
        nodes.join(offset[*a] + i, offset[*b] + j, false);
    }
    // Pieces, and the pairs of pieces that overlaps make coincident.
    let mut first = Vec::with_capacity(n);
    let mut pieces = Vec::with_capacity(total - n);
    for (c, &len) in lens.iter().enumerate() {
        first.push(pieces.len());
        for k in 0..len - 1 {
            pieces.push(Piece {
                curve: c,
                k,
                group: 0,
                along: true,
            });
        }
    }
    let mut groups = Joins::new(pieces.len());
    for sh in stretches {
        let ([i0, i1], [j0, j1]) = (sh.s, sh.t);
        let forward = j0 < j1;
        debug_assert_eq!(
            i1 - i0,
            j0.abs_diff(j1),
            "both sides of an overlap split alike"
        );
        for k in 0..=(i1 - i0) {
            let j = if forward { j0 + k } else { j0 - k };
            nodes.join(offset[sh.p] + i0 + k, offset[sh.q] + j, false);
            if k < i1 - i0 {
                let piece_q = if forward { j } else { j - 1 };
                groups.join(first[sh.p] + i0 + k, first[sh.q] + piece_q, !forward);
            }
        }
    }
    // Number the vertices.
    let mut vertex_of_root = vec![usize::MAX; total];
    let mut vertices = 0usize;
    let mut vertex = Vec::with_capacity(n);
    for (c, &len) in lens.iter().enumerate() {
        let mut row = Vec::with_capacity(len);
        for k in 0..len {
            let (root, _) = nodes.find(offset[c] + k);
            if vertex_of_root[root] == usize::MAX {
                vertex_of_root[root] = vertices;
                vertices += 1;
            }
            row.push(vertex_of_root[root]);
        }
        vertex.push(row);
    }
    let mut group_of_root = vec![usize::MAX; pieces.len()];
    let mut out: Vec<Group> = Vec::new();
    let mut rep_parity = Vec::new();
    // Each piece's group, and each group's size; then the members group after group.
    let mut sizes: Vec<usize> = Vec::new();
    for (i, piece) in pieces.iter_mut().enumerate() {
        let (root, parity) = groups.find(i);
        if group_of_root[root] == usize::MAX {
            group_of_root[root] = out.len();
            out.push(Group {
                rep: i,
                members: 0..0,
            });
            rep_parity.push(parity);
            sizes.push(0);
        }
        let g = group_of_root[root];
        sizes[g] += 1;
        piece.group = g;
        piece.along = parity == rep_parity[g];
    }
    let mut start = 0;
    for (group, size) in out.iter_mut().zip(&sizes) {
        group.members = start..start;
        start += size;
    }
    let mut members = vec![0; pieces.len()];
    for (i, piece) in pieces.iter().enumerate() {
        let range = &mut out[piece.group].members;
        members[range.end] = i;
        range.end += 1;
    }
    Assembled {
        vertex,
        vertices,
        pieces,
        groups: out,
        members,
    }
}

/// Whether x lies strictly between a and b (in either order), exactly.
pub(crate) fn strictly_between(x: &AlgebraicReal, a: &AlgebraicReal, b: &AlgebraicReal) -> bool {
    let (lo, hi) = if a.compare(b) == Ordering::Greater {
        (b, a)
    } else {
        (a, b)
    };
    x.compare(lo) == Ordering::Greater && x.compare(hi) == Ordering::Less
}

/// Sorts exactly and removes duplicates.
fn sort_distinct(p: &mut Vec<AlgebraicReal>) {
    p.sort_by(|a, b| a.compare(b));
    p.dedup_by(|a, b| a.compare(b) == Ordering::Equal);
}

/// Inserts `x` into the sorted distinct `p` unless present; whether it was new.
fn insert(p: &mut Vec<AlgebraicReal>, x: AlgebraicReal) -> bool {
    match p.binary_search_by(|y| y.compare(&x)) {
        Ok(_) => false,
        Err(at) => {
            p.insert(at, x);
            true
        }
    }
}

/// Makes both sides of every overlap split alike: each parameter strictly inside one side's
/// range is carried to the other side ([`transfer`]) until nothing new appears (a carried
/// parameter may lie inside a further overlap). Most are there already (a third curve that
/// crosses the stretch is reported on both sides); the ones that are not are the crossings
/// of a curve's other pass with the stretch, which [`intersect_curves`] does not list inside
/// an overlap's range.
fn carry_across_overlaps(curves: &[Curve], shared: &[Shared], params: &mut [Vec<AlgebraicReal>]) {
    loop {
        let mut changed = false;
        for sh in shared {
            let o = &sh.overlap;
            for (from, to, from_range, to_range) in
                [(sh.p, sh.q, &o.s, &o.t), (sh.q, sh.p, &o.t, &o.s)]
            {
                let inner: Vec<AlgebraicReal> = params[from]
                    .iter()
                    .filter(|x| strictly_between(x, &from_range[0], &from_range[1]))
                    .cloned()
                    .collect();
                for x in inner {
                    let t = transfer(&curves[from], &x, &curves[to], (&to_range[0], &to_range[1]));
                    changed |= insert(&mut params[to], t);
                }
            }
        }
        if !changed {
            return;
        }
    }
}
