//! Exact winding numbers by signed crossings of an axis-parallel ray.
//!
//! For a point p off the curves, the winding number of closed loops around p is the signed
//! count of their crossings with the ray from p along +x: each piece of a curve strictly
//! monotone in y that spans the height p_y contributes +1 going up and -1 going down when it
//! crosses the line y = p_y to the right of p. Heights are counted half-open: a piece from
//! height lo to height hi (lo < hi) spans p_y when lo <= p_y < hi. That is the count of the
//! ray lifted to y = p_y + ε for an infinitesimal ε > 0, which crosses every piece
//! transversally and misses every curve end and every turning point, so the count is exact
//! and the ends of consecutive curves of a loop are neither missed nor counted twice.
//! A piece that is horizontal (a curve whose y is constant) never spans a height.
//!
//! Every test is exact: the breaks of monotony are roots of y'(t) ([`Curve::monotone`]), the
//! comparisons of their heights with p_y are signs of algebraic numbers, the crossing is the
//! one root of y(t) - p_y on the piece, and the side is the exact sign of x(t) - p_x there.
//! The outward-rounded boxes only skip curves whose box misses the line or lies wholly left
//! of p (no crossing to count) and skip the side test for boxes wholly right of p; the side
//! test is first tried by the certified float filter of `crossing` (a proved sign only),
//! and the crossing is isolated exactly only when the filter does not decide.
//!
//! The same count along +y (axis 1) uses the pieces monotone in x; a crossing there
//! contributes -1 going right (+x) and +1 going left, so that both rays give the winding
//! number (the count along +y is the count along +x of the mirror image in the line y = x,
//! whose orientation is reversed).

use super::crossing::crossing_side;
use super::curve::{f64_down, f64_up, Curve};
use super::input::{FillRule, Region};
use crate::intersect::algebraic::{shifted_poly, AlgebraicReal};
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::ring::Rational;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// The winding number of a point around a region's loops.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Winding {
    /// The point lies on a curve of a loop.
    Boundary,
    /// The point lies off every loop, with this winding number.
    Number(i64),
}

/// Where a point lies with respect to a region.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Position {
    /// Off the loops, and the fill rule puts it inside.
    Inside,
    /// Off the loops, and the fill rule puts it outside.
    Outside,
    /// On a curve of a loop.
    Boundary,
}

/// What a crossing exactly at the ray's start means to the caller.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum AtStart {
    /// It cannot happen (the caller proved the point off the curves).
    Impossible,
    /// Skip it: the caller counts for the point moved by an infinitesimal δ along the ray,
    /// with δ larger than ε, so a curve through the start is left behind.
    Skip,
}

/// The signed count of the crossings of the ray from `p` along +`axis` with `curves`, as the
/// module docs define it. With [`AtStart::Skip`] a crossing exactly at p is not counted (the
/// count is then that of p + δ e_axis for an infinitesimal δ > ε > 0). `through` may name a
/// curve known to pass through p at the rational parameter m, strictly inside one of its
/// monotone pieces along the other axis: that piece's crossing is then p itself, skipped
/// without isolating it.
pub(crate) fn ray_count<'a>(
    curves: impl IntoIterator<Item = &'a Curve>,
    p: &[Rational; 2],
    axis: usize,
    at_start: AtStart,
    through: Option<(&Curve, &Rational)>,
) -> i64 {
    let (a, b) = (axis, 1 - axis);
    let (pa_lo, pb_lo, pb_hi) = (f64_down(&p[a]), f64_down(&p[b]), f64_up(&p[b]));
    let pa_hi = f64_up(&p[a]);
    let orientation = if axis == 0 { 1 } else { -1 };
    let mut total = 0;
    for curve in curves {
        let bb = &curve.bbox;
        if bb[b + 2] < pb_lo || bb[b] > pb_hi || bb[a + 2] < pa_lo {
            continue;
        }
        let wholly_beyond = bb[a] > pa_hi;
        let mono = curve.monotone(b);
        if mono.constant {
            continue;
        }
        let mut roots: Option<Vec<AlgebraicReal>> = None;
        for k in 0..mono.params.len() - 1 {
            let rising = mono.rising[k];
            let (lo_k, hi_k) = if rising { (k, k + 1) } else { (k + 1, k) };
            let (lo_b, hi_b) = (mono.bounds[lo_k], mono.bounds[hi_k]);
            // The doubles decide lo <= p_b < hi when they separate; else the exact test.
            if pb_hi < lo_b.0 || pb_lo > hi_b.1 {
                continue;
            }
            let surely_between = lo_b.1 < pb_lo && pb_hi < hi_b.0;
            let lo_param = &mono.params[lo_k];
            let at_lo = if surely_between {
                false
            } else {
                let c = mono.cmp_value(lo_k, &p[b]);
                if c == Ordering::Greater || mono.cmp_value(hi_k, &p[b]) != Ordering::Greater {
                    continue;
                }
                c == Ordering::Equal
            };
            let sign = if rising { orientation } else { -orientation };
            if let Some((known, m)) = through {
                // The piece crosses the height once; when it holds m, that crossing is p.
                let (t0, t1) = (&mono.params[k], &mono.params[k + 1]);
                if std::ptr::eq(known, curve)
                    && t0.cmp_rational(m) == Ordering::Less
                    && t1.cmp_rational(m) == Ordering::Greater
                {
                    debug_assert_eq!(at_start, AtStart::Skip);
                    continue;
                }
            }
            if wholly_beyond {
                total += sign;
                continue;
            }
            if !at_lo {
                let piece = (&mono.params[k], &mono.params[k + 1]);
                match crossing_side(curve, a, piece, p) {
                    Some(Ordering::Greater) => {
                        total += sign;
                        continue;
                    }
                    Some(_) => continue,
                    None => {}
                }
            }
            let crossing = if at_lo {
                lo_param.clone()
            } else {
                let all = roots.get_or_insert_with(|| {
                    let f = shifted_poly(&curve.power[b], &p[b]);
                    roots_with_multiplicity(&f, &Rational::zero(), &Rational::one())
                        .into_iter()
                        .map(|r| r.value)
                        .collect()
                });
                let (t0, t1) = (&mono.params[k], &mono.params[k + 1]);
                all.iter()
                    .find(|t| t.compare(t0) == Ordering::Greater && t.compare(t1) == Ordering::Less)
                    .expect("a strictly monotone piece spanning the height crosses it inside")
                    .clone()
            };
            let mut crossing = crossing;
            match crossing.sign_of(&shifted_poly(&curve.power[a], &p[a])) {
                Ordering::Greater => total += sign,
                Ordering::Less => {}
                Ordering::Equal => match at_start {
                    AtStart::Skip => {}
                    AtStart::Impossible => {
                        panic!("a crossing at a point proved off the curves")
                    }
                },
            }
        }
    }
    total
}

/// Whether some curve passes exactly through `p` (boxes prune; the test is the gcd of
/// x(t) - p_x and y(t) - p_y having a root in [0, 1]).
pub(crate) fn on_curves<'a>(
    curves: impl IntoIterator<Item = &'a Curve>,
    p: &[Rational; 2],
) -> bool {
    let lo = [f64_down(&p[0]), f64_down(&p[1])];
    let hi = [f64_up(&p[0]), f64_up(&p[1])];
    curves.into_iter().any(|c| {
        let bb = &c.bbox;
        bb[0] <= hi[0]
            && lo[0] <= bb[2]
            && bb[1] <= hi[1]
            && lo[1] <= bb[3]
            && !c.parameters_at(p).is_empty()
    })
}

/// The winding number of `p` around prepared curves.
pub(crate) fn winding_of(curves: &[Curve], p: &[Rational; 2]) -> Winding {
    if on_curves(curves, p) {
        Winding::Boundary
    } else {
        Winding::Number(ray_count(curves, p, 0, AtStart::Impossible, None))
    }
}

/// The prepared curves of a region (a curve that is a single point is kept: a point there is
/// on the loop, and it crosses no ray).
pub(crate) fn prepared(region: &Region) -> Vec<Curve> {
    region.loops().iter().flatten().map(Curve::new).collect()
}

impl Region {
    /// The exact winding number of `point` around all the region's loops together, or
    /// [`Winding::Boundary`] when the point lies on a curve of a loop (see the module docs of
    /// `region::winding` in the source for the method: signed crossings of a ray, exact root
    /// isolation, exact signs at algebraic parameters, half-open heights).
    ///
    /// ```
    /// use blossom::region::{FillRule, Region, Winding};
    /// use blossom::{Bezier, Rational};
    /// let p = |x: i64, y: i64| [Rational::from_integer(x.into()), Rational::from_integer(y.into())];
    /// let line = |a, b| Bezier::new(vec![a, b]);
    /// // A triangle traced twice counter-clockwise: winding number 2 inside.
    /// let lp = vec![line(p(0, 0), p(4, 0))?, line(p(4, 0), p(0, 4))?, line(p(0, 4), p(0, 0))?];
    /// let twice = Region::new(vec![lp.clone(), lp], FillRule::EvenOdd)?;
    /// assert_eq!(twice.winding(&p(1, 1)), Winding::Number(2));
    /// assert_eq!(twice.winding(&p(2, 2)), Winding::Boundary);
    /// assert_eq!(twice.winding(&p(5, 5)), Winding::Number(0));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn winding(&self, point: &[Rational; 2]) -> Winding {
        winding_of(&prepared(self), point)
    }

    /// Where `point` lies: [`Position::Boundary`] on a loop, else inside or outside by the
    /// fill rule applied to the exact winding number.
    pub fn contains(&self, point: &[Rational; 2]) -> Position {
        position(self.fill(), self.winding(point))
    }

    /// The winding numbers of many points, the curves prepared once.
    pub fn windings(&self, points: &[[Rational; 2]]) -> Vec<Winding> {
        let curves = prepared(self);
        points.iter().map(|p| winding_of(&curves, p)).collect()
    }

    /// The estimated work of [`Region::windings`] on `points` points, in nanoseconds as
    /// [`intersection_work`](crate::budget::intersection_work): each curve's breaks into monotone
    /// pieces once (exact roots of a derivative and values there, about 50 µs for a cubic of
    /// small coordinates), and for each point a box test against every curve (about 100 ns)
    /// and the exact tests (a gcd, a root isolation, a sign at an algebraic number, about
    /// 30 µs for a cubic) on the curves whose boxes meet the point's line, counted as
    /// 2 + √(curves) per point. Costs grow as (n + 1)^2 in the degree n and with the
    /// coordinates' length in 64-bit words.
    ///
    /// ```
    /// use blossom::region::Region;
    /// use blossom::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let t = Region::triangle(1, vec![[q(0), q(0)], [q(2), q(0)], [q(0), q(2)]])?;
    /// assert!(t.winding_work(100) < t.winding_work(1000));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    pub fn winding_work(&self, points: usize) -> u128 {
        let curves: Vec<&crate::Bezier<Rational, 2>> = self.loops().iter().flatten().collect();
        let count = curves.len() as u128;
        let scale = |c: &crate::Bezier<Rational, 2>| {
            let n = c.degree() as u128 + 1;
            let bits = c
                .points()
                .iter()
                .flatten()
                .map(|v| v.numer().bits() + v.denom().bits())
                .max()
                .unwrap_or(1) as u128;
            n * n * (bits / 64 + 1) / 16 + 1
        };
        let worst = curves.iter().map(|c| scale(c)).max().unwrap_or(0);
        let breaks: u128 = curves.iter().map(|c| 50_000 * scale(c)).sum();
        let exact_per_point = (2 + count.isqrt()).min(count) * 30_000 * worst;
        breaks + points as u128 * (100 * count + exact_per_point)
    }
}

/// The position of a point of winding `w` under `fill`.
pub(crate) fn position(fill: FillRule, w: Winding) -> Position {
    match w {
        Winding::Boundary => Position::Boundary,
        Winding::Number(n) if fill.inside(n) => Position::Inside,
        Winding::Number(_) => Position::Outside,
    }
}
