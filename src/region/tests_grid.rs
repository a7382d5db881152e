//! Booleans of random unions of axis-parallel rectangles on a small integer grid, against an
//! independent exact method: every unit cell lies wholly inside or outside each input and
//! each result, so the exact area of a result is the number of cells whose centre the op
//! keeps, with the inputs' winding numbers at the centre counted by a plain crossing test on
//! integer rectangles (written here, not the library's). The result's own loops are checked
//! the same way: their winding number at every cell centre is 1 inside the result and 0
//! outside. The small grid makes shared edges, partial overlaps, touching corners, holes and
//! coincident loops common.

use super::tests::{assert_well_formed, q};
use super::{boolean, BooleanOp, FillRule, Region, RegionResult};
use crate::num::ring::Rational;
use crate::shape::array::Bezier;

/// A rectangle [x0, x1] x [y0, y1], counter-clockwise or clockwise.
#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: i64,
    y0: i64,
    x1: i64,
    y1: i64,
    ccw: bool,
}

impl Rect {
    fn corners(&self) -> Vec<(i64, i64)> {
        let c = vec![
            (self.x0, self.y0),
            (self.x1, self.y0),
            (self.x1, self.y1),
            (self.x0, self.y1),
        ];
        if self.ccw {
            c
        } else {
            c.into_iter().rev().collect()
        }
    }

    /// Winding number around the cell centre (cx + 1/2, cy + 1/2).
    fn winding(&self, cx: i64, cy: i64) -> i64 {
        let inside = self.x0 <= cx && cx < self.x1 && self.y0 <= cy && cy < self.y1;
        match (inside, self.ccw) {
            (false, _) => 0,
            (true, true) => 1,
            (true, false) => -1,
        }
    }
}

struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> i64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n) as i64
    }

    fn rect(&mut self) -> Rect {
        let (a, b) = (self.below(6), self.below(6));
        let (c, d) = (self.below(6), self.below(6));
        Rect {
            x0: a.min(b),
            x1: a.max(b) + 1,
            y0: c.min(d),
            y1: c.max(d) + 1,
            ccw: self.below(3) != 0,
        }
    }
}

fn region_of(rects: &[Rect], fill: FillRule) -> Region {
    let loops = rects
        .iter()
        .map(|r| {
            let c = r.corners();
            (0..4)
                .map(|i| {
                    let (a, b) = (c[i], c[(i + 1) % 4]);
                    Bezier::new(vec![[q(a.0, 1), q(a.1, 1)], [q(b.0, 1), q(b.1, 1)]]).unwrap()
                })
                .collect()
        })
        .collect();
    Region::new(loops, fill).unwrap()
}

/// The winding number of the result's loops around (cx + 1/2, cy + 1/2), by signed
/// crossings of the ray to the right with the straight edges (exact rationals).
fn result_winding(regions: &[&Region], r: &RegionResult, cx: i64, cy: i64) -> i64 {
    let (px, py) = (q(2 * cx + 1, 2), q(2 * cy + 1, 2));
    let mut w = 0;
    for lp in &r.loops {
        for e in &lp.edges {
            let c = &regions[e.region].loops()[e.loop_index][e.curve];
            let exact =
                |p: &crate::region::Parameter| p.algebraic().unwrap().exact().unwrap().clone();
            let (from, to) = (exact(&e.from), exact(&e.to));
            let at = |t: &Rational| c.eval(t);
            let (a, b) = (at(&from), at(&to));
            let up = a[1] <= py && py < b[1];
            let down = b[1] <= py && py < a[1];
            if up || down {
                // x of the crossing at height py.
                let x = &a[0] + (&b[0] - &a[0]) * (&py - &a[1]) / (&b[1] - &a[1]);
                if x > px {
                    w += if up { 1 } else { -1 };
                }
            }
        }
    }
    w
}

#[test]
fn random_rectangle_unions_against_cell_counts() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let ops = [
        BooleanOp::Intersection,
        BooleanOp::Union,
        BooleanOp::Difference,
        BooleanOp::Xor,
    ];
    for case in 0..60 {
        let (na, nb) = (1 + rng.below(3) as usize, 1 + rng.below(3) as usize);
        let ra: Vec<Rect> = (0..na).map(|_| rng.rect()).collect();
        let rb: Vec<Rect> = (0..nb).map(|_| rng.rect()).collect();
        let fa = if rng.below(2) == 0 {
            FillRule::NonZero
        } else {
            FillRule::EvenOdd
        };
        let fb = if rng.below(2) == 0 {
            FillRule::NonZero
        } else {
            FillRule::EvenOdd
        };
        let (a, b) = (region_of(&ra, fa), region_of(&rb, fb));
        for op in ops {
            let r = boolean(&a, &b, op).unwrap();
            assert_well_formed(&[&a, &b], &r);
            let mut cells = 0;
            for cx in 0..7 {
                for cy in 0..7 {
                    let wa: i64 = ra.iter().map(|r| r.winding(cx, cy)).sum();
                    let wb: i64 = rb.iter().map(|r| r.winding(cx, cy)).sum();
                    let keep = op.keeps(fa.inside(wa), fb.inside(wb));
                    cells += keep as i64;
                    let w = result_winding(&[&a, &b], &r, cx, cy);
                    assert_eq!(
                        w, keep as i64,
                        "case {case} {op:?} cell ({cx}, {cy}): {ra:?} {fa:?} / {rb:?} {fb:?}"
                    );
                }
            }
            let exact = cells as f64;
            assert!(
                r.area[0] <= exact && exact <= r.area[1],
                "case {case} {op:?}: area {:?}, {cells} cells",
                r.area
            );
        }
    }
}
