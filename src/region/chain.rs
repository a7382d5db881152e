//! Chaining the boundary pieces into simple oriented loops of maximal edges.
//!
//! Every vertex has as many boundary pieces leaving as arriving (the boundary of a region
//! is a sum of closed loops). Around a vertex, counter-clockwise, the pieces alternate
//! between leaving (the result on their counter-clockwise side) and arriving; a walk that
//! arrives by a piece continues by the leaving piece next to it clockwise, so the result's
//! sector between them stays on its left ([`compare`] orders the pieces; it is needed only
//! where more than one piece leaves). Each closed walk is cut at every vertex it passes
//! twice (a boundary touching itself at a point), which leaves simple loops. Last,
//! consecutive edges on one input curve that continue each other are merged.

use super::angle::{compare, Branch};
use super::arrangement::Arrangement;
use std::collections::HashMap;

/// A boundary piece with its direction in the result.
#[derive(Clone, Copy, Debug)]
struct Directed {
    piece: usize,
    forward: bool,
}

/// A maximal edge: curve `curve` of the arrangement from parameter index `from` to `to`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Run {
    pub curve: usize,
    pub from: usize,
    pub to: usize,
}

impl Directed {
    fn start(&self, arr: &Arrangement) -> usize {
        let (lo, hi) = arr.end_vertices(self.piece);
        if self.forward {
            lo
        } else {
            hi
        }
    }

    fn end(&self, arr: &Arrangement) -> usize {
        let (lo, hi) = arr.end_vertices(self.piece);
        if self.forward {
            hi
        } else {
            lo
        }
    }

    /// The branch leaving the start vertex along the piece.
    fn leaving(&self, arr: &Arrangement) -> Branch {
        let (a, b) = arr.ends(self.piece);
        let (at, toward) = if self.forward { (a, b) } else { (b, a) };
        Branch {
            curve: arr.pieces[self.piece].curve,
            at: at.clone(),
            toward: toward.clone(),
        }
    }

    /// The branch leaving the end vertex back along the piece.
    fn arriving(&self, arr: &Arrangement) -> Branch {
        let (a, b) = arr.ends(self.piece);
        let (at, toward) = if self.forward { (b, a) } else { (a, b) };
        Branch {
            curve: arr.pieces[self.piece].curve,
            at: at.clone(),
            toward: toward.clone(),
        }
    }

    fn run(&self, arr: &Arrangement) -> Run {
        let p = &arr.pieces[self.piece];
        if self.forward {
            Run {
                curve: p.curve,
                from: p.k,
                to: p.k + 1,
            }
        } else {
            Run {
                curve: p.curve,
                from: p.k + 1,
                to: p.k,
            }
        }
    }
}

/// The simple loops of maximal edges bounding the result, given each group's verdict
/// (`Some(true)`: an edge along the representative, `Some(false)`: against it).
pub(crate) fn chain(arr: &Arrangement, verdicts: &[Option<bool>]) -> Vec<Vec<Run>> {
    let edges: Vec<Directed> = verdicts
        .iter()
        .enumerate()
        .filter_map(|(g, v)| {
            v.map(|forward| Directed {
                piece: arr.groups[g].rep,
                forward,
            })
        })
        .collect();
    let mut leaving: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, e) in edges.iter().enumerate() {
        leaving.entry(e.start(arr)).or_default().push(i);
    }
    let next = successors(arr, &edges, &leaving);
    let steps: Vec<Step> = edges
        .iter()
        .map(|e| Step {
            start: e.start(arr),
            end: e.end(arr),
            run: e.run(arr),
        })
        .collect();
    close_walks(&steps, &next)
}

/// A directed edge for [`close_walks`]: from vertex `start` to vertex `end`, as `run`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Step {
    pub start: usize,
    pub end: usize,
    pub run: Run,
}

/// The simple loops of maximal runs traced by directed edges (the walk continues after
/// `steps[i]` by `steps[next[i]]`): each closed walk, cut at every vertex it passes twice (a
/// loop is cut off the walk each time it returns to a vertex it has left), its consecutive
/// runs that continue each other merged.
pub(crate) fn close_walks(steps: &[Step], next: &[usize]) -> Vec<Vec<Run>> {
    let mut used = vec![false; steps.len()];
    let vertices = steps
        .iter()
        .map(|s| s.start.max(s.end) + 1)
        .max()
        .unwrap_or(0);
    // at[v]: the position on the stack of the step leaving v, usize::MAX when none is.
    let mut at = vec![usize::MAX; vertices];
    let (mut stack, mut loops): (Vec<usize>, Vec<Vec<Run>>) = (Vec::new(), Vec::new());
    for first in 0..steps.len() {
        let mut e = first;
        while !used[e] {
            used[e] = true;
            at[steps[e].start] = stack.len();
            stack.push(e);
            let p = at[steps[e].end];
            if p != usize::MAX {
                for &f in &stack[p..] {
                    at[steps[f].start] = usize::MAX;
                }
                loops.push(merge(stack.drain(p..).map(|i| steps[i].run).collect()));
            }
            e = next[e];
        }
        debug_assert!(stack.is_empty(), "a closed walk splits into closed loops");
    }
    loops
}

/// For each edge, the edge the walk continues by after it.
fn successors(
    arr: &Arrangement,
    edges: &[Directed],
    leaving: &HashMap<usize, Vec<usize>>,
) -> Vec<usize> {
    let mut next = vec![usize::MAX; edges.len()];
    let mut arriving: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, e) in edges.iter().enumerate() {
        arriving.entry(e.end(arr)).or_default().push(i);
    }
    for (v, outs) in leaving {
        let ins = &arriving[v];
        if let ([i], [o]) = (ins.as_slice(), outs.as_slice()) {
            next[*i] = *o;
            continue;
        }
        // Several leave: order every branch at v counter-clockwise.
        let mut around: Vec<(Branch, bool, usize)> = outs
            .iter()
            .map(|&o| (edges[o].leaving(arr), true, o))
            .chain(ins.iter().map(|&i| (edges[i].arriving(arr), false, i)))
            .collect();
        around.sort_by(|a, b| {
            let (ca, cb) = (&arr.curves[a.0.curve], &arr.curves[b.0.curve]);
            compare(ca, &a.0, cb, &b.0)
        });
        let n = around.len();
        for k in 0..n {
            if around[k].1 {
                continue;
            }
            // The first leaving branch clockwise from this arriving one.
            let o = (1..n)
                .map(|d| &around[(k + n - d) % n])
                .find(|b| b.1)
                .expect("a vertex with an arriving edge has a leaving one");
            next[around[k].2] = o.2;
        }
    }
    next
}

/// Merges consecutive runs that continue each other on one curve (cyclically).
fn merge(runs: Vec<Run>) -> Vec<Run> {
    let continues = |a: &Run, b: &Run| {
        a.curve == b.curve && a.to == b.from && (a.from < a.to) == (b.from < b.to)
    };
    let n = runs.len();
    // Start at a run that does not continue its predecessor.
    let start = (0..n)
        .find(|&i| !continues(&runs[(i + n - 1) % n], &runs[i]))
        .unwrap_or(0);
    let mut out: Vec<Run> = Vec::new();
    for d in 0..n {
        let r = runs[(start + d) % n];
        match out.last_mut() {
            Some(last) if continues(last, &r) => last.to = r.to,
            _ => out.push(r),
        }
    }
    out
}
