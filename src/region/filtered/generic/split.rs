//! The curves of both regions split at their certified crossings, once the configuration is
//! proved generic (see the module docs of [`super`]).

use crate::intersect::filter::crossing_parameters_f64;
use crate::intersect::implicit::implicitly_apart;
use crate::num::small::Dyadic;
use crate::region::arrangement::{for_each_meeting_pair, meeting_boxes, CurveId};
use crate::region::filtered::bounds::crossing_sign;
pub(super) use crate::region::filtered::graph::bbox;
use crate::region::prune::{consecutive_meet_only_at_join, one_to_one};
use std::ops::ControlFlow;

/// One input curve.
pub(super) struct Curve<'a> {
    pub points: &'a [[f64; 2]],
    pub id: CurveId,
    /// The index of its loop in [`Split::loops`].
    pub loop_no: usize,
    /// `[x_lo, y_lo, x_hi, y_hi]` of the control points (exact: comparisons of doubles).
    pub bbox: [f64; 4],
}

/// One loop: its region and the range of its curves (consecutive in [`Split::curves`]).
pub(super) struct Loop {
    pub region: usize,
    pub first: usize,
    pub len: usize,
}

/// A certified crossing of a curve P of A and a curve Q of B.
pub(super) struct Crossing {
    /// The correctly rounded parameters on both curves.
    pub nearest: [f64; 2],
    /// Their enclosures.
    pub enclosures: [[f64; 2]; 2],
    /// The sign (+1 or -1) of cross(P'(s), Q'(t)), the curve of side 0 and Q of side 1.
    pub sign: i64,
    /// The index of its pair of curves in [`Split::pairs`].
    pub pair: usize,
}

/// A crossing on one curve: which crossing and which side of it the curve is.
#[derive(Clone, Copy)]
pub(super) struct Mark {
    pub crossing: usize,
    pub side: usize,
}

/// The split curves.
pub(super) struct Split<'a> {
    pub curves: Vec<Curve<'a>>,
    pub loops: Vec<Loop>,
    pub crossings: Vec<Crossing>,
    /// Each curve's crossings in increasing order of its parameter.
    pub marks: Vec<Vec<Mark>>,
    /// The pairs of curves that cross.
    pub pairs: Vec<[CurveId; 2]>,
}

/// Whether the loops of one region (`doubles[l][c]`: the control points of curve c of loop
/// l) are proved simple and pairwise disjoint: each of at least three curves (a loop of one
/// or two is left to the general float path), each curve finite and one-to-one, consecutive curves
/// meeting only at their join, other curves whose boxes meet without a common point (module
/// docs of [`super`]).
pub(super) fn simple(doubles: &[Vec<Vec<[f64; 2]>>]) -> bool {
    let (mut boxes, mut owner, mut dyadic) = (Vec::new(), Vec::new(), Vec::new());
    for (l, curves) in doubles.iter().enumerate() {
        if curves.len() < 3 {
            return false;
        }
        for (c, points) in curves.iter().enumerate() {
            if !points.iter().all(|p| p[0].is_finite() && p[1].is_finite())
                || !one_to_one(points.as_slice())
            {
                return false;
            }
            boxes.push(bbox(points));
            owner.push((l, c));
            dyadic.push(Dyadic::of(points));
        }
    }
    // Pairs in the sweep's order, stopping at the first that is not proved apart (on
    // overlapping loops, early).
    let proved = |i: usize, j: usize| {
        let ((li, ci), (lj, cj)) = (owner[i], owner[j]);
        let (p, q) = (&doubles[li][ci], &doubles[lj][cj]);
        let len = doubles[li].len();
        if li == lj && (ci + 1) % len == cj {
            consecutive_meet_only_at_join(p, q)
        } else if li == lj && (cj + 1) % len == ci {
            consecutive_meet_only_at_join(q, p)
        } else {
            let apart =
                matches!((&dyadic[i], &dyadic[j]), (Some(a), Some(b)) if implicitly_apart(a, b));
            apart || crossing_parameters_f64(p, q).is_some_and(|x| x.is_empty())
        }
    };
    for_each_meeting_pair(&boxes, |i, j| {
        if proved(i, j) {
            ControlFlow::Continue(())
        } else {
            ControlFlow::Break(())
        }
    })
    .is_continue()
}

impl<'a> Split<'a> {
    /// The curve before `c` in its loop.
    pub fn prev(&self, c: usize) -> usize {
        let l = &self.loops[self.curves[c].loop_no];
        l.first + (c - l.first + l.len - 1) % l.len
    }

    /// The split of the curves of both regions (`doubles[r][l][c]`: the control points of
    /// curve c of loop l of region r, each region proved [`simple`]), or `None` when the
    /// configuration is not proved generic: only pairs of curves of different regions are
    /// examined.
    pub fn build(doubles: [&'a [Vec<Vec<[f64; 2]>>]; 2]) -> Option<Split<'a>> {
        let count = |r: &[Vec<Vec<[f64; 2]>>]| r.iter().map(Vec::len).sum::<usize>();
        let curves = count(doubles[0]) + count(doubles[1]);
        let mut split = Split {
            curves: Vec::with_capacity(curves),
            loops: Vec::with_capacity(doubles[0].len() + doubles[1].len()),
            crossings: Vec::with_capacity(8),
            marks: Vec::new(),
            pairs: Vec::with_capacity(8),
        };
        for (region, loops) in doubles.iter().enumerate() {
            for (loop_index, curves) in loops.iter().enumerate() {
                let loop_no = split.loops.len();
                split.loops.push(Loop {
                    region,
                    first: split.curves.len(),
                    len: curves.len(),
                });
                for (curve, points) in curves.iter().enumerate() {
                    split.curves.push(Curve {
                        points,
                        id: CurveId {
                            region,
                            loop_index,
                            curve,
                        },
                        loop_no,
                        bbox: bbox(points),
                    });
                }
            }
        }
        split.marks = vec![Vec::new(); split.curves.len()];
        let boxes: Vec<[f64; 4]> = split.curves.iter().map(|c| c.bbox).collect();
        for (i, j) in meeting_boxes(&boxes) {
            if split.curves[i].id.region != split.curves[j].id.region {
                split.pair(i, j)?;
            }
        }
        for c in 0..split.curves.len() {
            split.order_marks(c)?;
        }
        Some(split)
    }

    /// Records the crossings of curves i < j of different regions, or `None` when they are
    /// not proved generic.
    fn pair(&mut self, i: usize, j: usize) -> Option<()> {
        let (p, q) = (self.curves[i].points, self.curves[j].points);
        let crossings = crossing_parameters_f64(p, q)?;
        if crossings.is_empty() {
            return Some(());
        }
        let pair = self.pairs.len();
        self.pairs.push([self.curves[i].id, self.curves[j].id]);
        for x in crossings {
            let sign = crossing_sign(p, q, x.s, x.s_enclosure, x.t, x.t_enclosure)?;
            let k = self.crossings.len();
            self.crossings.push(Crossing {
                nearest: [x.s, x.t],
                enclosures: [x.s_enclosure, x.t_enclosure],
                sign,
                pair,
            });
            self.marks[i].push(Mark {
                crossing: k,
                side: 0,
            });
            self.marks[j].push(Mark {
                crossing: k,
                side: 1,
            });
        }
        Some(())
    }

    /// The enclosure of a mark's parameter.
    pub fn enclosure(&self, m: Mark) -> [f64; 2] {
        self.crossings[m.crossing].enclosures[m.side]
    }

    /// Sorts curve c's marks by parameter; `None` when two enclosures meet (the order is not
    /// proved).
    fn order_marks(&mut self, c: usize) -> Option<()> {
        let mut marks = std::mem::take(&mut self.marks[c]);
        marks.sort_by(|a, b| self.enclosure(*a)[0].total_cmp(&self.enclosure(*b)[0]));
        let ordered = marks
            .windows(2)
            .all(|w| self.enclosure(w[0])[1] < self.enclosure(w[1])[0]);
        self.marks[c] = marks;
        ordered.then_some(())
    }
}
