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
    let starts: Vec<usize> = edges.iter().map(|e| e.start(arr)).collect();
    let ends: Vec<usize> = edges.iter().map(|e| e.end(arr)).collect();
    let runs: Vec<Run> = edges.iter().map(|e| e.run(arr)).collect();
    close_walks(&starts, &ends, &next, &runs)
}

/// The simple loops of maximal runs traced by directed edges (edge i runs from vertex
/// `starts[i]` to `ends[i]` as `runs[i]`, and the walk continues after it by `next[i]`):
/// each closed walk, cut at every vertex it passes twice, its consecutive runs that continue
/// each other merged.
pub(crate) fn close_walks(
    starts: &[usize],
    ends: &[usize],
    next: &[usize],
    runs: &[Run],
) -> Vec<Vec<Run>> {
    let mut used = vec![false; next.len()];
    let vertices = starts.iter().chain(ends).max().map_or(0, |v| v + 1);
    let mut at = vec![usize::MAX; vertices];
    let mut loops = Vec::new();
    for start in 0..next.len() {
        if used[start] {
            continue;
        }
        let mut walk = Vec::new();
        let mut e = start;
        while !used[e] {
            used[e] = true;
            walk.push(e);
            e = next[e];
        }
        debug_assert_eq!(e, start, "a walk closes where it started");
        for simple in split_at_repeats(starts, ends, &walk, &mut at) {
            loops.push(merge(simple.iter().map(|&i| runs[i]).collect()));
        }
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
        around.sort_by(|a, b| compare(&arr.curves, &a.0, &b.0));
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

/// Cuts a closed walk at every vertex it passes twice.
/// `at[v]` is scratch indexed by vertex, `usize::MAX` everywhere on entry and on return.
fn split_at_repeats(
    starts: &[usize],
    ends: &[usize],
    walk: &[usize],
    at: &mut [usize],
) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut stack: Vec<usize> = Vec::new();
    for &e in walk {
        at[starts[e]] = stack.len();
        stack.push(e);
        let p = at[ends[e]];
        if p != usize::MAX {
            let piece: Vec<usize> = stack.drain(p..).collect();
            for &f in &piece {
                at[starts[f]] = usize::MAX;
            }
            out.push(piece);
        }
    }
    debug_assert!(stack.is_empty(), "a closed walk splits into closed loops");
    out
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
