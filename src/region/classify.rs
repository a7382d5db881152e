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

use super::angle::rational_between;
use super::arrangement::Arrangement;
use super::boolean::BooleanOp;
use super::curve::Curve;
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
            let m = sample(curve, a, b);
            let x = curve.at(&m);
            let t = curve.tangent(&m);
            let (axis, shifted_is_right) = if !t[1].is_zero() {
                (0, t[1] > Rational::zero())
            } else {
                (1, t[0] < Rational::zero())
            };
            let mut sides = [[false; 2]; 2]; // [left, right][region]
            for (r, fill) in fills.iter().enumerate() {
                let curves = arr
                    .curves
                    .iter()
                    .zip(&arr.ids)
                    .filter(|(_, id)| id.region == r)
                    .map(|(c, _)| c);
                let count = ray_count(curves, &x, axis, AtStart::Skip, Some((curve, &m)));
                let mult: i64 = g
                    .members
                    .iter()
                    .filter(|&&i| arr.ids[arr.pieces[i].curve].region == r)
                    .map(|&i| if arr.pieces[i].along { 1 } else { -1 })
                    .sum();
                let (left, right) = if shifted_is_right {
                    (count + mult, count)
                } else {
                    (count, count - mult)
                };
                sides[0][r] = fill.inside(left);
                sides[1][r] = fill.inside(right);
            }
            let left = op.keeps(sides[0][0], sides[0][1]);
            let right = op.keeps(sides[1][0], sides[1][1]);
            match left.cmp(&right) {
                Ordering::Equal => None,
                Ordering::Greater => Some(true),
                Ordering::Less => Some(false),
            }
        })
        .collect()
}
