//! Which pieces bound the result, and the loops they make (see the module docs of
//! [`super`]).
//!
//! Pieces are numbered by position: piece k of curve c runs from position k to k + 1, where
//! position 0 is the curve's start, position m + 1 its end and position i in 1..=m its i-th
//! crossing. Vertices are the crossings (their index) and the joins (the join at the end of
//! curve c is vertex `crossings + c`).

use super::side::LoopWindings;
use super::split::Split;
use crate::region::boolean::BooleanOp;
use crate::region::chain::{close_walks, Run, Step};
use crate::region::input::FillRule;

/// A loop of the answer as runs of positions.
pub(super) type BoundaryLoop = Vec<Run>;

/// A boundary piece with its direction in the result.
#[derive(Clone, Copy)]
struct Directed {
    curve: usize,
    k: usize,
    forward: bool,
}

/// The vertex at position k of curve c.
fn vertex(split: &Split<'_>, c: usize, k: usize) -> usize {
    let marks = &split.marks[c];
    let joins = split.crossings.len();
    if k == 0 {
        joins + split.prev(c)
    } else if k == marks.len() + 1 {
        joins + c
    } else {
        marks[k - 1].crossing
    }
}

impl Directed {
    fn start(&self, split: &Split<'_>) -> usize {
        vertex(split, self.curve, self.k + usize::from(!self.forward))
    }
    fn end(&self, split: &Split<'_>) -> usize {
        vertex(split, self.curve, self.k + usize::from(self.forward))
    }
    fn run(&self) -> Run {
        let (a, b) = (self.k, self.k + 1);
        let (from, to) = if self.forward { (a, b) } else { (b, a) };
        Run {
            curve: self.curve,
            from,
            to,
        }
    }
    /// At a crossing vertex at one of its ends: the slot of its half-piece there, 0..4 in the
    /// counter-clockwise order of the rays +P', +Q' (or -Q'), -P', -Q' (or +Q') (module docs
    /// of [`super`]): whether the piece leaves the vertex along its curve (it starts there)
    /// or back against it (it ends there).
    fn slot(&self, split: &Split<'_>, at_start: bool) -> usize {
        // The position of the vertex on the curve: the piece's start when it is where the
        // piece (in the curve's direction) begins.
        let piece_begins_here = at_start == self.forward;
        let k = if piece_begins_here {
            self.k
        } else {
            self.k + 1
        };
        let mark = split.marks[self.curve][k - 1];
        let x = &split.crossings[mark.crossing];
        // +P' is slot 0, -P' slot 2; +Q' is slot 1 when cross(P', Q') > 0, else 3.
        let along = if mark.side == 0 {
            0
        } else if x.sign > 0 {
            1
        } else {
            3
        };
        if piece_begins_here {
            along
        } else {
            (along + 2) % 4
        }
    }
}

/// The loops bounding the result of `op`, or `None` when a consistency check fails (which
/// would be a bug; the exact path then answers).
pub(super) fn boundary(
    split: &Split<'_>,
    windings: &[LoopWindings],
    fills: [FillRule; 2],
    op: BooleanOp,
) -> Option<Vec<BoundaryLoop>> {
    let mut edges = Vec::new();
    for (l, lp) in split.loops.iter().enumerate() {
        let w = &windings[l];
        let (r, fill_own, fill_other) = (lp.region, fills[lp.region], fills[1 - lp.region]);
        let keeps = |own: i64, other: i64| {
            let (in_own, in_other) = (fill_own.inside(own), fill_other.inside(other));
            if r == 0 {
                op.keeps(in_own, in_other)
            } else {
                op.keeps(in_other, in_own)
            }
        };
        let mut other = w.other;
        for d in 0..lp.len {
            let c = lp.first + (w.start - lp.first + d) % lp.len;
            let marks = &split.marks[c];
            for k in 0..=marks.len() {
                let (left, right) = (keeps(w.own[0], other), keeps(w.own[1], other));
                if left != right {
                    edges.push(Directed {
                        curve: c,
                        k,
                        forward: left,
                    });
                }
                if let Some(m) = marks.get(k) {
                    // Along P = curves[0] across Q: cross(Q', P') = -sign; along Q across P:
                    // cross(P', Q') = sign.
                    let sign = split.crossings[m.crossing].sign;
                    other += if m.side == 0 { -sign } else { sign };
                }
            }
        }
        if other != w.other {
            debug_assert!(
                false,
                "the winding number returns to its start around a loop"
            );
            return None;
        }
    }
    let next = successors(split, &edges)?;
    let steps: Vec<Step> = edges
        .iter()
        .map(|e| Step {
            start: e.start(split),
            end: e.end(split),
            run: e.run(),
        })
        .collect();
    Some(close_walks(&steps, &next))
}

/// For each edge the edge after it: the only one leaving its end vertex, or at a crossing
/// where two leave, the first leaving clockwise from the arriving one (which keeps the
/// result's sector on the left). `None` when the counts do not match (a bug).
fn successors(split: &Split<'_>, edges: &[Directed]) -> Option<Vec<usize>> {
    let vertices = split.crossings.len() + split.curves.len();
    // At most two edges leave a vertex (a crossing has four half-pieces, a join two).
    let mut leaving: Vec<([usize; 2], usize)> = vec![([usize::MAX; 2], 0); vertices];
    for (i, e) in edges.iter().enumerate() {
        let (slots, count) = &mut leaving[e.start(split)];
        *slots.get_mut(*count)? = i;
        *count += 1;
    }
    let mut next = vec![usize::MAX; edges.len()];
    for (i, e) in edges.iter().enumerate() {
        let v = e.end(split);
        let (slots, count) = &leaving[v];
        next[i] = match &slots[..*count] {
            [o] => *o,
            outs @ [_, _] if v < split.crossings.len() => {
                let arriving = e.slot(split, false);
                // Clockwise from the arriving slot: slots arriving - 1, arriving - 2, ...
                (1..4).map(|d| (arriving + 4 - d) % 4).find_map(|s| {
                    outs.iter()
                        .copied()
                        .find(|&o| edges[o].slot(split, true) == s)
                })?
            }
            _ => return None,
        };
    }
    Some(next)
}
