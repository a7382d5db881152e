//! Stage 4 of the float path: which half-edges bound the result, and the loops they make.
//!
//! A half-edge bounds the result with the result on its left exactly when the operation
//! keeps the face on its left and not the face on its right (fill rules applied to both
//! regions' winding numbers there). Parts of zero area (an edge both sides keep or both
//! drop, a touching point) are thereby dropped: the answer is regularized. A walk that
//! arrives at a vertex continues by the first boundary half-edge clockwise from the one it
//! arrived by (its twin), which keeps the result's sector on its left; each closed walk is
//! cut at every vertex it passes twice and consecutive runs continuing one curve are merged
//! (`chain::close_walks`, shared with the exact stages).

use super::faces::Faces;
use super::graph::Graph;
use super::order::Around;
use crate::region::boolean::BooleanOp;
use crate::region::chain::{close_walks, Run, Step};
use crate::region::input::FillRule;

/// The loops bounding the result of `op`, as runs of parameter indices, or `None` when a
/// consistency check fails (a bug; the exact stages then answer).
pub(super) fn boundary(
    graph: &Graph<'_>,
    around: &Around,
    faces: &Faces,
    fills: [FillRule; 2],
    op: BooleanOp,
) -> Option<Vec<Vec<Run>>> {
    let keeps = |f: usize| {
        let w = faces.winding[f];
        op.keeps(fills[0].inside(w[0]), fills[1].inside(w[1]))
    };
    let n = graph.half_edges();
    let on: Vec<bool> = (0..n)
        .map(|h| keeps(faces.face[h]) && !keeps(faces.face[h ^ 1]))
        .collect();
    let edges: Vec<usize> = (0..n).filter(|&h| on[h]).collect();
    let mut index = vec![usize::MAX; n];
    for (i, &h) in edges.iter().enumerate() {
        index[h] = i;
    }
    let mut next = Vec::with_capacity(edges.len());
    for &h in &edges {
        let w = graph.dest(h);
        let mut t = h ^ 1;
        loop {
            t = around.clockwise(t, w);
            if on[t] {
                break;
            }
            if t == h ^ 1 {
                return None;
            }
        }
        next.push(index[t]);
    }
    let steps: Vec<Step> = edges
        .iter()
        .map(|&h| {
            let (curve, from, to) = graph.branch(h);
            Step {
                start: graph.origin(h),
                end: graph.dest(h),
                run: Run { curve, from, to },
            }
        })
        .collect();
    Some(close_walks(&steps, &next))
}
