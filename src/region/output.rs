//! A boolean's answer as geometry: the pieces of the input curves its edges name, cut out in
//! doubles with exactly shared ends ([`RegionResult::geometry`]), as a [`Region`] again
//! ([`RegionResult::to_region`]) and as SVG path data ([`RegionResult::svg`]).
//!
//! **How a piece is cut.** An edge is the input curve between the parameters `from` and `to`.
//! Its control points are the restriction of the input curve's control points (as doubles:
//! the region's own doubles, or its exact numbers rounded to the nearest double) to
//! [`from.to_f64()`, `to.to_f64()`] by the restriction engine of the crate (de Casteljau steps
//! x + t (y - x)), so the piece keeps the input curve's degree. Then each vertex of a loop gets
//! one point, written into both pieces that meet there: where either parameter is a curve's
//! end (0 or 1, [`Parameter::curve_end`](super::Parameter::curve_end)) the input curve's own
//! control point, otherwise the end of the incoming piece as computed.
//!
//! **Error bound.** Let u = 2^-53, n the degree of the input curve and M the largest absolute
//! value of a coordinate of a control point of the two input regions. Each coordinate of each
//! control point of a piece (its ends included) lies within 17 n u M of the exact piece's
//! f(a^(n-j), b^j) (f the blossom of the exact input curve, a and b the exact parameters):
//!
//! * input numbers that are not doubles are rounded once, off by at most u M; the blossom at
//!   arguments in [0, 1] is a convex combination of the control points, so the piece moves by
//!   at most u M;
//! * the parameters are correctly rounded, off by at most u; moving one argument of the
//!   blossom by d moves its value by d times a blossom of the differences of consecutive
//!   control points, at most 2 M: 2 n u M for the n arguments;
//! * every step x + t (y - x) of the restriction (t in [0, 1], |x|, |y| <= M) is rounded three
//!   times, off by at most 5 u M, and the convex steps after it do not enlarge an error: the
//!   engine (degrees 1..=8) is n steps deep, 5 n u M; the two subdivisions of the higher
//!   degrees (`shape/two_pass.rs`) are 2n steps deep, 10 n u M, and their one division moves
//!   the second cut by another relative u, 2 n u M more.
//!
//! That is 7 n u M for input of doubles and degree at most 8 (2.4e-15 M for a cubic) and at
//! most (14 n + 1) u M otherwise; 17 n u M leaves room for the second-order terms. No big
//! number is touched: the cost is that of the float restrictions, a few dozen nanoseconds a
//! piece.

use super::boolean::{Edge, RegionResult};
use super::input::{FillRule, Region};
use super::parameter::Parameter;
use crate::error::{Error, ErrorKind, Result};
use crate::num::ring::rational_to_f64;
use crate::shape::array::Bezier;
use crate::shape::flat::curve_subsegment_fixed;
use std::borrow::Cow;

/// The control points (as doubles) of the input curve an edge is a piece of: the region's own
/// doubles, or its exact numbers rounded to the nearest double.
fn curve_of<'a>(inputs: &'a [Region; 2], e: &Edge) -> Cow<'a, [[f64; 2]]> {
    let region = &inputs[e.region];
    match region.doubles() {
        Some(d) => Cow::Borrowed(&d[e.loop_index][e.curve]),
        None => Cow::Owned(
            region.loops()[e.loop_index][e.curve]
                .points()
                .iter()
                .map(|p| [rational_to_f64(&p[0]), rational_to_f64(&p[1])])
                .collect(),
        ),
    }
}

/// The input curve's own control point where `p` is its end 0 or 1.
fn end_point(points: &[[f64; 2]], p: &Parameter) -> Option<[f64; 2]> {
    p.curve_end().map(|one| {
        if one {
            points[points.len() - 1]
        } else {
            points[0]
        }
    })
}

/// The pieces of one result loop, each vertex's point chosen once and written into both
/// pieces that meet there.
fn loop_pieces(
    edges: &[Edge],
    inputs: &[Region; 2],
    scratch: &mut Vec<f64>,
) -> Vec<Bezier<f64, 2>> {
    let curves: Vec<Cow<'_, [[f64; 2]]>> = edges.iter().map(|e| curve_of(inputs, e)).collect();
    let mut pieces: Vec<Vec<[f64; 2]>> = edges
        .iter()
        .zip(&curves)
        .map(|(e, points)| {
            let mut out = vec![[0.0; 2]; points.len()];
            curve_subsegment_fixed::<f64, 2>(
                points.as_flattened(),
                &e.from.to_f64(),
                &e.to.to_f64(),
                out.as_flattened_mut(),
                scratch,
            );
            out
        })
        .collect();
    let k = edges.len();
    for i in 0..k {
        let previous = (i + k - 1) % k;
        let last = pieces[previous].len() - 1;
        let vertex = end_point(&curves[i], &edges[i].from)
            .or_else(|| end_point(&curves[previous], &edges[previous].to))
            .unwrap_or(pieces[previous][last]);
        pieces[previous][last] = vertex;
        pieces[i][0] = vertex;
    }
    pieces
        .into_iter()
        .map(|points| Bezier::new(points).expect("a piece has the n + 1 >= 2 points of its curve"))
        .collect()
}

/// `x` in the shortest form that reads back as the same double: Rust's shortest round-trip
/// digits, plain (`0.5`, `-3`) or with an exponent (`1e21`, `1.5e-7`), whichever is shorter.
fn write_number(out: &mut String, x: f64) {
    let plain = format!("{x}");
    let exponent = format!("{x:e}");
    out.push_str(if exponent.len() < plain.len() {
        &exponent
    } else {
        &plain
    });
}

impl RegionResult {
    /// The result's loops as curves of doubles: `geometry()[l][e]` is edge e of
    /// `loops[l]`, the piece of its input curve between `from` and `to`, in the edge's
    /// direction, of the input curve's degree (a piece of a line is a line, of a quadratic a
    /// quadratic, of a cubic a cubic).
    ///
    /// Guaranteed: consecutive pieces share their end point bit for bit, and the last piece of
    /// a loop ends exactly where the first starts (so [`Region::from_f64`] accepts the loops:
    /// [`RegionResult::to_region`]); where a parameter is a curve's end 0 or 1 the point is the
    /// input curve's own control point (rounded to the nearest double when the input is not
    /// doubles). Every other coordinate is within 17 n 2^-53 M of the exact piece's, n the
    /// input curve's degree and M the largest absolute value of a coordinate of the input
    /// regions' control points (7 n 2^-53 M for input of doubles and degree at most 8); the
    /// derivation is in the source of `src/region/output.rs`. The pieces are cut by float
    /// restrictions only, no big numbers: a few dozen nanoseconds a piece. A vertex where the
    /// result's boundary touches itself belongs to two loops, and each loop computes its point
    /// on its own (the two agree within the bound, not necessarily bit for bit).
    ///
    /// ```
    /// use blossom::region::{boolean, BooleanOp, FillRule, Region};
    /// use blossom::Bezier;
    /// let square = |x: f64, y: f64| -> Vec<Bezier<f64, 2>> {
    ///     let c = [[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]];
    ///     (0..4).map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap()).collect()
    /// };
    /// let a = Region::from_f64(vec![square(0.0, 0.0)], FillRule::NonZero)?;
    /// let b = Region::from_f64(vec![square(1.0, 1.0)], FillRule::NonZero)?;
    /// let r = boolean(&a, &b, BooleanOp::Intersection)?;
    /// let loops = r.geometry();
    /// // The unit square [1, 2] x [1, 2]: four lines, each starting where the last ended.
    /// assert_eq!(loops.len(), 1);
    /// let lines = &loops[0];
    /// assert_eq!(lines.len(), 4);
    /// for (i, line) in lines.iter().enumerate() {
    ///     assert_eq!(line.degree(), 1);
    ///     assert_eq!(line.points()[0], lines[(i + 3) % 4].points()[1]);
    /// }
    /// let mut corners: Vec<[f64; 2]> = lines.iter().map(|l| l.points()[0]).collect();
    /// corners.sort_by(|p, q| p.partial_cmp(q).unwrap());
    /// assert_eq!(corners, vec![[1.0, 1.0], [1.0, 2.0], [2.0, 1.0], [2.0, 2.0]]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn geometry(&self) -> Vec<Vec<Bezier<f64, 2>>> {
        let mut scratch = Vec::new();
        self.loops
            .iter()
            .map(|l| loop_pieces(&l.edges, &self.inputs, &mut scratch))
            .collect()
    }

    /// The result as a [`Region`] under [`FillRule::NonZero`], its loops the curves of
    /// [`RegionResult::geometry`] (outer loops counter-clockwise, holes clockwise, so the
    /// nonzero rule fills exactly the result, up to the bound stated there), so that booleans
    /// chain: `boolean(&r.to_region()?, &c, op)`. An empty result gives the empty region.
    ///
    /// ```
    /// use blossom::region::{boolean, BooleanOp, FillRule, Region};
    /// use blossom::Bezier;
    /// let square = |x: f64, y: f64| -> Result<Region, blossom::Error> {
    ///     let c = [[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]];
    ///     let sides = (0..4).map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]));
    ///     Region::from_f64(vec![sides.collect::<Result<_, _>>()?], FillRule::NonZero)
    /// };
    /// let union = boolean(&square(0.0, 0.0)?, &square(1.0, 1.0)?, BooleanOp::Union)?;
    /// // (A ∪ B) - C, C the square [1, 3] x [0, 2]: area 7 - 3 = 4.
    /// let r = boolean(&union.to_region()?, &square(1.0, 0.0)?, BooleanOp::Difference)?;
    /// assert!(r.area[0] <= 4.0 && 4.0 <= r.area[1]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] (from [`Region::from_f64`]) when a coordinate overflowed, which
    /// only input coordinates near the largest double can make happen.
    pub fn to_region(&self) -> Result<Region> {
        Region::from_f64(self.geometry(), FillRule::NonZero)
    }

    /// [`RegionResult::geometry`], checked to be drawable by the path formats (degree 1 to 3,
    /// finite coordinates).
    ///
    /// # Errors
    /// [`ErrorKind::Degree`] on `loops[l].edges[e]` for a piece of degree over 3,
    /// [`ErrorKind::NotFinite`] there for a coordinate that overflowed.
    pub(crate) fn drawable(&self) -> Result<Vec<Vec<Bezier<f64, 2>>>> {
        let geometry = self.geometry();
        for (l, pieces) in geometry.iter().enumerate() {
            for (e, piece) in pieces.iter().enumerate() {
                let field = || format!("loops[{l}].edges[{e}]");
                if piece.degree() > 3 {
                    return Err(Error::of(
                        ErrorKind::Degree,
                        field(),
                        format!(
                            "a piece of degree {} has no path command (lines, quadratics and \
                             cubics only)",
                            piece.degree()
                        ),
                    ));
                }
                if piece.points().iter().flatten().any(|x| !x.is_finite()) {
                    return Err(Error::of(
                        ErrorKind::NotFinite,
                        field(),
                        "a coordinate overflowed the range of doubles",
                    ));
                }
            }
        }
        Ok(geometry)
    }

    /// The result as SVG path data: subpath i for `loops[i]`, an absolute `M` to where its
    /// first edge starts, then each edge as one command of its input curve's kind (`L` for a
    /// piece of a line, `Q` of a quadratic, `C` of a cubic) with the control points of
    /// [`RegionResult::geometry`] (so consecutive edges share one written end point), and `Z`
    /// closing every subpath. Points are written `x,y`, tokens separated by one space, each
    /// number in the shortest form that reads back as the same double (`0.5`, `-3`, `1e21`:
    /// Rust's shortest round-trip digits, with an exponent where that is shorter). An empty
    /// result gives the empty string; [`Region::from_svg_path`] reads the text back.
    ///
    /// `None` when an edge has degree over 3 (SVG has no command for it), or a coordinate
    /// overflowed (input coordinates near the largest double only).
    ///
    /// ```
    /// use blossom::region::{boolean, BooleanOp, FillRule, Region};
    /// let a = Region::from_svg_path("M 0 0 H 2 V 2 H 0 Z", FillRule::NonZero)?;
    /// let b = Region::from_svg_path("M 1 1 h 2 v 2 h -2 z", FillRule::NonZero)?;
    /// let r = boolean(&a, &b, BooleanOp::Intersection)?;
    /// let svg = r.svg().expect("lines only");
    /// assert!(svg.starts_with("M ") && svg.ends_with(" Z"));
    /// assert_eq!(svg.matches('L').count(), 4);
    /// // Read back, it is the same square.
    /// let back = Region::from_svg_path(&svg, FillRule::NonZero)?;
    /// let again = boolean(&back, &a, BooleanOp::Intersection)?;
    /// assert!(again.area[0] <= 1.0 && 1.0 <= again.area[1]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn svg(&self) -> Option<String> {
        let geometry = self.drawable().ok()?;
        let mut out = String::new();
        let point = |out: &mut String, p: &[f64; 2]| {
            out.push(' ');
            write_number(out, p[0]);
            out.push(',');
            write_number(out, p[1]);
        };
        for pieces in &geometry {
            if !out.is_empty() {
                out.push(' ');
            }
            out.push('M');
            point(&mut out, &pieces[0].points()[0]);
            for piece in pieces {
                out.push(' ');
                // `drawable` checked the degree: 1, 2 or 3.
                out.push(match piece.degree() {
                    1 => 'L',
                    2 => 'Q',
                    _ => 'C',
                });
                for p in &piece.points()[1..] {
                    point(&mut out, p);
                }
            }
            out.push_str(" Z");
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::write_number;
    use crate::intersect::algebraic::exact_f64;
    use crate::num::parse::parse_f64;
    use crate::num::ring::{rational_to_f64, Rational};
    use crate::region::{boolean, parse_svg_path, BooleanOp, FillRule, Region, RegionResult};
    use crate::shape::array::Bezier;
    use crate::test_rng::XorShift;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    /// A closed loop of curves of doubles through the given control points: each curve's
    /// points, the last point of one being the first of the next (and of the first).
    fn loop_f64(curves: &[&[[f64; 2]]]) -> Vec<Bezier<f64, 2>> {
        curves
            .iter()
            .map(|c| Bezier::new(c.to_vec()).unwrap())
            .collect()
    }

    fn region_f64(loops: Vec<Vec<Bezier<f64, 2>>>) -> Region {
        Region::from_f64(loops, FillRule::NonZero).unwrap()
    }

    fn square_f64(x: f64, y: f64, w: f64, h: f64) -> Region {
        let c = [[x, y], [x + w, y], [x + w, y + h], [x, y + h]];
        region_f64(vec![(0..4)
            .map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap())
            .collect()])
    }

    /// The region [0, 2] x [0, 2] whose bottom side is the quadratic (0, 0), (1, -2), (2, 0)
    /// (y = -4 t (1 - t), x = 2 t) and the region [0, 3] x [0, 3] whose bottom side is the
    /// cubic (0, 0), (1, -3), (2, -3), (3, 0) (y = -9 t (1 - t), x = 3 t), shifted.
    fn cup(cubic: bool, dx: f64) -> Region {
        if cubic {
            region_f64(vec![loop_f64(&[
                &[
                    [dx, 0.0],
                    [dx + 1.0, -3.0],
                    [dx + 2.0, -3.0],
                    [dx + 3.0, 0.0],
                ],
                &[[dx + 3.0, 0.0], [dx + 3.0, 3.0]],
                &[[dx + 3.0, 3.0], [dx, 3.0]],
                &[[dx, 3.0], [dx, 0.0]],
            ])])
        } else {
            region_f64(vec![loop_f64(&[
                &[[dx, 0.0], [dx + 1.0, -2.0], [dx + 2.0, 0.0]],
                &[[dx + 2.0, 0.0], [dx + 2.0, 2.0]],
                &[[dx + 2.0, 2.0], [dx, 2.0]],
                &[[dx, 2.0], [dx, 0.0]],
            ])])
        }
    }

    /// The blossom of exact control points at exact arguments, by the Bernstein coefficients
    /// of the arguments: multiplying out prod_k ((1 - t_k) + t_k x), the coefficient of x^i
    /// weighs point i (independent of the restriction engine).
    fn blossom(points: &[[Rational; 2]], args: &[Rational]) -> [Rational; 2] {
        let mut weights = vec![q(1, 1)];
        for t in args {
            let mut next = vec![q(0, 1); weights.len() + 1];
            for (i, w) in weights.iter().enumerate() {
                next[i] += (q(1, 1) - t) * w;
                next[i + 1] += t * w;
            }
            weights = next;
        }
        let mut out = [q(0, 1), q(0, 1)];
        for (w, p) in weights.iter().zip(points) {
            out[0] += w * &p[0];
            out[1] += w * &p[1];
        }
        out
    }

    /// The largest absolute coordinate of the control points of both inputs.
    fn largest(r: &RegionResult) -> f64 {
        r.inputs
            .iter()
            .flat_map(|region| region.loops().iter().flatten())
            .flat_map(|c| c.points().iter().flatten())
            .map(|x| rational_to_f64(x).abs())
            .fold(0.0, f64::max)
    }

    /// Checks every piece of `r` against the exact restriction at the exact (rational)
    /// parameters within `factor` n 2^-53 M, the shared ends bit for bit, and the curve ends
    /// as the input's own control points. Returns the number of pieces checked.
    fn check_pieces(r: &RegionResult, factor: f64) -> usize {
        let geometry = r.geometry();
        assert_eq!(geometry.len(), r.loops.len());
        let m = largest(r);
        let mut checked = 0;
        for (lp, pieces) in r.loops.iter().zip(&geometry) {
            assert_eq!(pieces.len(), lp.edges.len());
            for (i, (e, piece)) in lp.edges.iter().zip(pieces).enumerate() {
                let input = &r.inputs[e.region].loops()[e.loop_index][e.curve];
                let n = input.degree();
                assert_eq!(
                    piece.degree(),
                    n,
                    "the piece keeps the input curve's degree"
                );
                let a = e.from.algebraic().unwrap().exact().unwrap().clone();
                let b = e.to.algebraic().unwrap().exact().unwrap().clone();
                let bound = factor * n as f64 * f64::EPSILON / 2.0 * m;
                for (j, got) in piece.points().iter().enumerate() {
                    let mut args = vec![a.clone(); n - j];
                    args.extend(vec![b.clone(); j]);
                    let want = blossom(input.points(), &args);
                    for k in 0..2 {
                        let error = rational_to_f64(&(exact_f64(got[k]) - &want[k])).abs();
                        assert!(
                            error <= bound,
                            "point {j} of edge {i}: {got:?}, exact {want:?}, error {error:e} \
                             over {bound:e}"
                        );
                    }
                }
                // Shared ends, bit for bit.
                let next = &pieces[(i + 1) % pieces.len()];
                let (end, start) = (piece.points()[n], next.points()[0]);
                assert_eq!(end.map(f64::to_bits), start.map(f64::to_bits));
                // A curve's end is the input's own control point.
                let own = |one: bool| {
                    let p = &input.points()[if one { n } else { 0 }];
                    [rational_to_f64(&p[0]), rational_to_f64(&p[1])].map(f64::to_bits)
                };
                if let Some(one) = e.from.curve_end() {
                    assert_eq!(piece.points()[0].map(f64::to_bits), own(one));
                }
                if let Some(one) = e.to.curve_end() {
                    assert_eq!(piece.points()[n].map(f64::to_bits), own(one));
                }
                checked += 1;
            }
        }
        checked
    }

    #[test]
    fn pieces_of_lines_quadratics_and_cubics_are_the_exact_restrictions() {
        // Rectangles cutting the cups: the quadratic meets y = -3/4 at t = 1/4, 3/4, the
        // cubic meets y = -2 at t = 1/3, 2/3, the rectangles' lines at rational parameters.
        let cut = |y: f64| square_f64(-1.0, y, 6.0, 4.0);
        let cases = [
            (cup(false, 0.0), cut(-0.75)),
            (cup(true, 0.0), cut(-2.0)),
            (cup(true, 0.5), cup(false, 0.25)),
            (
                square_f64(0.0, 0.0, 3.0, 3.0),
                square_f64(1.0, 1.0, 3.0, 3.0),
            ),
        ];
        let mut pieces = 0;
        let mut reversed = 0;
        for (a, b) in &cases {
            for op in [
                BooleanOp::Intersection,
                BooleanOp::Union,
                BooleanOp::Difference,
                BooleanOp::Xor,
            ] {
                let r = boolean(a, b, op).unwrap();
                let exact = r
                    .loops
                    .iter()
                    .flat_map(|l| &l.edges)
                    .all(|e| e.from.algebraic().unwrap().exact().is_some());
                if !exact {
                    // cup against cup crosses at irrational parameters: checked below.
                    continue;
                }
                // Input of doubles, degree <= 8: the tighter bound 7 n u M.
                pieces += check_pieces(&r, 7.0);
                reversed += r
                    .loops
                    .iter()
                    .flat_map(|l| &l.edges)
                    .filter(|e| e.from.to_f64() > e.to.to_f64())
                    .count();
            }
        }
        assert!(
            pieces > 60 && reversed > 10,
            "{pieces} pieces, {reversed} reversed"
        );
    }

    #[test]
    fn pieces_of_rational_input_and_irrational_parameters() {
        // Exact input that is not doubles (thirds), rounded once: the bound 17 n u M. The
        // cup of quadratic (0, 0), (1/3, -2/3), (2/3, 0) (y = -4/3 t (1 - t)) meets
        // y = -1/4 at t = 1/4, 3/4; every other crossing is of lines.
        let p = |x: i64, xd: i64, y: i64, yd: i64| [q(x, xd), q(y, yd)];
        let line = |a: [Rational; 2], b: [Rational; 2]| Bezier::new(vec![a, b]).unwrap();
        let thirds = Region::new(
            vec![vec![
                Bezier::new(vec![p(0, 1, 0, 1), p(1, 3, -2, 3), p(2, 3, 0, 1)]).unwrap(),
                line(p(2, 3, 0, 1), p(2, 3, 2, 3)),
                line(p(2, 3, 2, 3), p(0, 1, 2, 3)),
                line(p(0, 1, 2, 3), p(0, 1, 0, 1)),
            ]],
            FillRule::NonZero,
        )
        .unwrap();
        let corners = [
            p(-1, 3, -1, 4),
            p(5, 3, -1, 4),
            p(5, 3, 1, 3),
            p(-1, 3, 1, 3),
        ];
        let cut = Region::new(
            vec![(0..4)
                .map(|i| line(corners[i].clone(), corners[(i + 1) % 4].clone()))
                .collect()],
            FillRule::NonZero,
        )
        .unwrap();
        assert!(cut.doubles().is_none() && thirds.doubles().is_none());
        let mut pieces = 0;
        for op in [
            BooleanOp::Intersection,
            BooleanOp::Difference,
            BooleanOp::Union,
        ] {
            let r = boolean(&thirds, &cut, op).unwrap();
            pieces += check_pieces(&r, 17.0);
        }
        assert!(pieces >= 12, "{pieces}");
        // Irrational parameters (cup against cup): the shared ends and the ends of the
        // pieces against the exact points of the curves at the parameters' enclosures.
        let (a, b) = (cup(true, 0.5), cup(false, 0.25));
        let r = boolean(&a, &b, BooleanOp::Intersection).unwrap();
        let geometry = r.geometry();
        for (lp, pieces) in r.loops.iter().zip(&geometry) {
            for (i, (e, piece)) in lp.edges.iter().zip(pieces).enumerate() {
                let next = &pieces[(i + 1) % pieces.len()];
                assert_eq!(
                    piece.points()[piece.degree()].map(f64::to_bits),
                    next.points()[0].map(f64::to_bits)
                );
                let input = &r.inputs[e.region].loops()[e.loop_index][e.curve];
                for (t, got) in [
                    (&e.from, piece.points()[0]),
                    (&e.to, piece.points()[piece.degree()]),
                ] {
                    let [lo, hi] = t.enclosure();
                    for end in [lo, hi] {
                        let want = blossom(input.points(), &vec![exact_f64(end); input.degree()]);
                        for k in 0..2 {
                            let error = (got[k] - rational_to_f64(&want[k])).abs();
                            assert!(error < 1e-14, "{got:?} against {want:?}");
                        }
                    }
                }
            }
        }
    }

    /// Booleans of `to_region` answers, against areas known exactly.
    #[test]
    fn to_region_chains_booleans() {
        let (a, b) = (
            square_f64(0.0, 0.0, 2.0, 2.0),
            square_f64(1.0, 1.0, 2.0, 2.0),
        );
        let union = boolean(&a, &b, BooleanOp::Union).unwrap();
        let u = union.to_region().unwrap();
        assert_eq!(u.fill(), FillRule::NonZero);
        assert_eq!(u.loops().len(), 1);
        assert_eq!(u.loops()[0].len(), 8);
        // (A ∪ B) ∩ [1, 4] x [-1, 1.5]: the pieces [1, 2] x [0, 1.5] of A and
        // [2, 3] x [1, 1.5] of B: 1.5 + 0.5 = 2.
        let c = square_f64(1.0, -1.0, 3.0, 2.5);
        let r = boolean(&u, &c, BooleanOp::Intersection).unwrap();
        assert!(r.area[0] <= 2.0 && 2.0 <= r.area[1], "{:?}", r.area);
        // A hole survives the round trip: [0, 4]^2 - [1, 2]^2, then minus [3, 5] x [0, 4].
        let framed = boolean(
            &square_f64(0.0, 0.0, 4.0, 4.0),
            &square_f64(1.0, 1.0, 1.0, 1.0),
            BooleanOp::Difference,
        )
        .unwrap();
        assert_eq!(framed.loops.iter().filter(|l| l.hole).count(), 1);
        let back = framed.to_region().unwrap();
        let r = boolean(
            &back,
            &square_f64(3.0, 0.0, 2.0, 4.0),
            BooleanOp::Difference,
        )
        .unwrap();
        assert!(r.area[0] <= 11.0 && 11.0 <= r.area[1], "{:?}", r.area);
        // Curved pieces: (cup ∪ square) ∩ square is the square again (area 4 for
        // [4, 6] x [-1, 1]), through the rounded cubic pieces.
        let cup_region = cup(true, 0.0);
        let s = square_f64(2.0, -1.0, 2.0, 2.0);
        let joined = boolean(&cup_region, &s, BooleanOp::Union)
            .unwrap()
            .to_region()
            .unwrap();
        let r = boolean(&joined, &s, BooleanOp::Intersection).unwrap();
        assert!((r.area[0] - 4.0).abs() < 1e-12 && (r.area[1] - 4.0).abs() < 1e-12);
        // (cup - square) ∪ square through to_region: the area of cup ∪ square, the cup's
        // 9 + 9/2 (the cubic's bulge below y = 0) and the square's part outside the cup.
        let r = boolean(&cup_region, &s, BooleanOp::Difference).unwrap();
        let back = boolean(&r.to_region().unwrap(), &s, BooleanOp::Union).unwrap();
        let direct = boolean(&cup_region, &s, BooleanOp::Union).unwrap();
        assert!((back.area[0] - direct.area[0]).abs() < 1e-12);
        let outside = boolean(&s, &cup_region, BooleanOp::Difference).unwrap();
        let want = 13.5 + outside.area[0];
        assert!((direct.area[0] - want).abs() < 1e-12, "{:?}", direct.area);
        // The empty result is the empty region.
        let none = boolean(&a, &square_f64(5.0, 5.0, 1.0, 1.0), BooleanOp::Intersection).unwrap();
        assert!(none.to_region().unwrap().loops().is_empty());
        assert_eq!(none.svg().as_deref(), Some(""));
    }

    #[test]
    fn svg_reads_back_as_the_same_geometry() {
        let exact = |t: &str| parse_f64(t).map(exact_f64);
        let cases = [
            (cup(false, 0.0), square_f64(-1.0, -0.75, 6.0, 4.0)),
            (cup(true, 0.5), cup(false, 0.25)),
            (
                square_f64(0.0, 0.0, 4.0, 4.0),
                square_f64(1.0, 1.0, 1.0, 1.0),
            ),
        ];
        for (a, b) in &cases {
            for op in [
                BooleanOp::Intersection,
                BooleanOp::Union,
                BooleanOp::Difference,
            ] {
                let r = boolean(a, b, op).unwrap();
                let svg = r.svg().unwrap();
                let geometry = r.geometry();
                let read = parse_svg_path(&svg, exact).unwrap();
                assert_eq!(read.len(), geometry.len(), "{svg}");
                for (got, want) in read.iter().zip(&geometry) {
                    // Z adds nothing: the last piece ends where the first starts.
                    assert_eq!(got.len(), want.len(), "{svg}");
                    for (g, w) in got.iter().zip(want) {
                        let w: Vec<[Rational; 2]> =
                            w.points().iter().map(|p| p.map(exact_f64)).collect();
                        assert_eq!(g.points(), w.as_slice(), "{svg}");
                    }
                }
                let letters: String = svg.chars().filter(char::is_ascii_alphabetic).collect();
                let expected: String = geometry
                    .iter()
                    .map(|pieces| {
                        let body: String = pieces
                            .iter()
                            .map(|p| ['L', 'Q', 'C'][p.degree() - 1])
                            .collect();
                        format!("M{body}Z")
                    })
                    .collect();
                // `e` of an exponent would count as a letter: these numbers have none.
                assert_eq!(letters, expected);
            }
        }
        // Two squares meeting in the unit square [1, 2]^2, written in full.
        let r = boolean(
            &square_f64(0.0, 0.0, 2.0, 2.0),
            &square_f64(1.0, 1.0, 2.0, 2.0),
            BooleanOp::Intersection,
        )
        .unwrap();
        let svg = r.svg().unwrap();
        let corners = ["1,1", "2,1", "2,2", "1,2"];
        let start = corners
            .iter()
            .position(|c| svg.starts_with(&format!("M {c} ")))
            .unwrap();
        let turn: Vec<&str> = (0..5).map(|k| corners[(start + k) % 4]).collect();
        assert_eq!(
            svg,
            format!(
                "M {} L {} L {} L {} L {} Z",
                turn[0], turn[1], turn[2], turn[3], turn[4]
            )
        );
    }

    #[test]
    fn degree_over_three_has_no_path() {
        // A quartic bottom side.
        let quartic = region_f64(vec![loop_f64(&[
            &[[0.0, 0.0], [1.0, -1.0], [2.0, 1.0], [3.0, -1.0], [4.0, 0.0]],
            &[[4.0, 0.0], [4.0, 2.0]],
            &[[4.0, 2.0], [0.0, 2.0]],
            &[[0.0, 2.0], [0.0, 0.0]],
        ])]);
        let r = boolean(
            &quartic,
            &square_f64(1.0, -2.0, 2.0, 3.0),
            BooleanOp::Intersection,
        )
        .unwrap();
        assert!(r.geometry().iter().flatten().any(|p| p.degree() == 4));
        assert_eq!(r.svg(), None);
        let e = r.drawable().unwrap_err();
        assert_eq!(e.kind, crate::ErrorKind::Degree);
        assert!(e.field.starts_with("loops[0].edges["), "{}", e.field);
        // to_region keeps the degree.
        assert!(r.to_region().unwrap().loops()[0]
            .iter()
            .any(|c| c.degree() == 4));
    }

    #[test]
    fn numbers_are_written_short_and_read_back_exactly() {
        let cases = [
            (1.0, "1"),
            (-3.0, "-3"),
            (0.5, "0.5"),
            (0.1, "0.1"),
            (1e21, "1e21"),
            (1.5e-7, "1.5e-7"),
            (123456.0, "123456"),
            (1e300, "1e300"),
            (-2.5e-300, "-2.5e-300"),
        ];
        for (x, want) in cases {
            let mut s = String::new();
            write_number(&mut s, x);
            assert_eq!(s, want);
        }
        let mut rng = XorShift(0x5eed);
        for _ in 0..2000 {
            let x = f64::from_bits(rng.next());
            if !x.is_finite() {
                continue;
            }
            let mut s = String::new();
            write_number(&mut s, x);
            assert_eq!(parse_f64(&s).unwrap().to_bits(), x.to_bits(), "{s}");
            assert!(s.len() <= 24, "{s}");
        }
    }
}
