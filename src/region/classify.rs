//! The exact winding numbers of both regions on both sides of each group of coincident
//! pieces, and the op's verdict: which groups bound the result, and which way.
//!
//! For a group with representative piece P over (a, b): a rational m strictly inside (a, b)
//! with P'(m) ≠ 0 (P' has finitely many zeros), X = P(m), T = P'(m). No curve passes through
//! X but the group's pieces (any other would have split the piece there). When T_y ≠ 0 the
//! ray from X along +x, with the crossings at X itself skipped, counts the winding number of
//! X + δ(1, 0) for an infinitesimal δ > 0 ([`ray_count`] with [`AtStart::Skip`]): the right
//! side of P when T_y > 0, the left side when T_y < 0. When T_y = 0 the ray along +y counts
//! the side X + δ(0, 1): the left side when T_x > 0, the right side when T_x < 0. Crossing P
//! from its right to its left adds +1 to a region's winding number for each of the region's
//! pieces in the group running P's way and -1 for each running against it, which gives the
//! other side.

use super::answer::BooleanOp;
use super::arrangement::Arrangement;
use super::curve::{rational_between, Curve};
use super::input::FillRule;
use super::winding::{ray_count, AtStart};
use crate::num::ring::Rational;
use num_traits::Zero;
use std::cmp::Ordering;

/// A rational parameter strictly inside the piece (a, b) where the curve's derivative is not
/// the zero vector.
fn sample(curve: &Curve, a: &crate::AlgebraicReal, b: &crate::AlgebraicReal) -> Rational {
    let mut m = rational_between(a, b);
    loop {
        let t = curve.tangent(&m);
        if !t[0].is_zero() || !t[1].is_zero() {
            return m;
        }
        // P' vanishes at m: try closer to a (finitely many zeros).
        m = rational_between(a, &crate::AlgebraicReal::from_rational(m));
    }
}

/// The exact winding numbers `[left, right][region]` beside the piece of `curve` between the
/// distinct parameters `a` and `b` (left and right of the curve's direction), where no curve
/// but the piece's own group passes through its inner points; `mult[r]` is the signed number
/// of the group's pieces of region r (+1 for one running the curve's way), `curves[r]` every
/// curve of region r (the piece's own curve among them).
pub(crate) fn sides_of_piece(
    curve: &Curve,
    a: &crate::AlgebraicReal,
    b: &crate::AlgebraicReal,
    mult: [i64; 2],
    curves: [Vec<&Curve>; 2],
) -> [[i64; 2]; 2] {
    let m = sample(curve, a, b);
    let x = curve.at(&m);
    let t = curve.tangent(&m);
    let (axis, shifted_is_right) = if !t[1].is_zero() {
        (0, t[1] > Rational::zero())
    } else {
        (1, t[0] < Rational::zero())
    };
    let mut sides = [[0; 2]; 2];
    for (r, region_curves) in curves.into_iter().enumerate() {
        let count = ray_count(region_curves, &x, axis, AtStart::Skip, Some((curve, &m)));
        let (left, right) = if shifted_is_right {
            (count + mult[r], count)
        } else {
            (count, count - mult[r])
        };
        sides[0][r] = left;
        sides[1][r] = right;
    }
    sides
}

/// For each group: `None` when it does not bound the result, `Some(true)` when it does with
/// the result on the left of its representative's direction, `Some(false)` when on the right.
pub(crate) fn boundary_groups(
    arr: &Arrangement,
    fills: [FillRule; 2],
    op: BooleanOp,
) -> Vec<Option<bool>> {
    arr.groups
        .iter()
        .map(|g| {
            let rep = &arr.pieces[g.rep];
            let curve = &arr.curves[rep.curve];
            let (a, b) = arr.ends(g.rep);
            let mut mult = [0, 0];
            for &i in &arr.members[g.members.clone()] {
                let piece = &arr.pieces[i];
                mult[arr.ids[piece.curve].region] += if piece.along { 1 } else { -1 };
            }
            let of_region = |r: usize| -> Vec<&Curve> {
                arr.curves
                    .iter()
                    .zip(&arr.ids)
                    .filter(|(_, id)| id.region == r)
                    .map(|(c, _)| c)
                    .collect()
            };
            let sides = sides_of_piece(curve, a, b, mult, [of_region(0), of_region(1)]);
            let keeps = |w: [i64; 2]| op.keeps(fills[0].inside(w[0]), fills[1].inside(w[1]));
            let (left, right) = (keeps(sides[0]), keeps(sides[1]));
            match left.cmp(&right) {
                Ordering::Equal => None,
                Ordering::Greater => Some(true),
                Ordering::Less => Some(false),
            }
        })
        .collect()
}
