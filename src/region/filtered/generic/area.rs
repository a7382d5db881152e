//! The signed areas of the generic configuration: the area polynomials of the curves
//! ([`AreaPolynomials`], the integral of (x - o) dy of module `bounds`) evaluated at the
//! split positions, and the sign of a loop's area.

use super::split::{Mark, Split};
use crate::num::bounded::BoundedF64;
use crate::num::ring::Ring;
use crate::region::filtered::bounds::{evaluate, parameter, sign, AreaPolynomials};

/// The area polynomials of the curves, evaluated at their positions.
pub(super) struct Areas<'s, 'a> {
    pub(super) split: &'s Split<'a>,
    polynomials: AreaPolynomials,
}

impl<'s, 'a> Areas<'s, 'a> {
    pub(super) fn new(split: &'s Split<'a>) -> Self {
        let boxes = split.curves.iter().map(|c| &c.bbox);
        Areas {
            split,
            polynomials: AreaPolynomials::new(split.curves.len(), boxes),
        }
    }

    /// F_c at position `k` of curve c (0: its start, `marks.len() + 1`: its end, else the
    /// crossing `marks[k - 1]`).
    pub(super) fn at(&mut self, c: usize, k: usize) -> BoundedF64 {
        let f = self.polynomials.of(c, self.split.curves[c].points);
        let marks = &self.split.marks[c];
        if k == 0 {
            return f[0];
        }
        if k == marks.len() + 1 {
            return f[f.len() - 1];
        }
        let m: Mark = marks[k - 1];
        let x = &self.split.crossings[m.crossing];
        evaluate(f, 1, parameter(x.nearest[m.side], x.enclosures[m.side]))[0]
    }
}

/// The sign of the signed area of loop `l` of the input, or `None` when its enclosure does
/// not exclude zero.
pub(super) fn loop_area_sign(areas: &mut Areas<'_, '_>, l: usize) -> Option<i64> {
    let lp = &areas.split.loops[l];
    let mut sum = BoundedF64::exact(0.0);
    for c in lp.first..lp.first + lp.len {
        let end = areas.split.marks[c].len() + 1;
        sum = sum.add(&areas.at(c, end));
    }
    sign(&sum)
}
