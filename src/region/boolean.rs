//! The public front of the booleans: the operations on regions and their work estimates.

#[cfg(doc)]
use super::answer::Edge;
use super::answer::{BooleanOp, Outline, RegionResult};
use super::input::Region;
use crate::error::Result;

/// The boolean `op` of the regions `a` and `b`, certified: every decision in it (which pieces
/// coincide, which are on the boundary, how loops continue at a vertex) is exact for the
/// input numbers. See the module docs of [`crate::region`] for the algorithm and the form of
/// the answer.
///
/// ```
/// use blossom::region::{boolean, BooleanOp, FillRule, Region};
/// use blossom::{Bezier, Rational};
/// let p = |x: i64, y: i64| [Rational::from_integer(x.into()), Rational::from_integer(y.into())];
/// let square = |x: i64, y: i64, s: i64| -> Result<Region, blossom::Error> {
///     let c = [p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)];
///     let sides = (0..4).map(|i| Bezier::new(vec![c[i].clone(), c[(i + 1) % 4].clone()]));
///     Region::new(vec![sides.collect::<Result<_, _>>()?], FillRule::NonZero)
/// };
/// // Two 2 x 2 squares overlapping in a 1 x 1 square.
/// let (a, b) = (square(0, 0, 2)?, square(1, 1, 2)?);
/// let both = boolean(&a, &b, BooleanOp::Intersection)?;
/// assert_eq!(both.loops.len(), 1);
/// assert!(both.area[0] <= 1.0 && 1.0 <= both.area[1]);
/// let union = boolean(&a, &b, BooleanOp::Union)?;
/// assert!(union.area[0] <= 7.0 && 7.0 <= union.area[1]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// None for valid regions today; the `Result` leaves room for limits.
pub fn boolean(a: &Region, b: &Region, op: BooleanOp) -> Result<RegionResult> {
    let Outline {
        loops,
        area,
        report,
    } = super::pipeline::run(&[a, b], op)?;
    Ok(RegionResult {
        loops,
        area,
        inputs: [a.clone(), b.clone()],
        report,
    })
}

/// The region `a` itself under its own fill rule as regularized simple oriented loops
/// (overlap removal): overlapping and self-crossing loops merged, the parts whose winding
/// number the fill rule leaves out removed, parts of zero area dropped. It is the union of
/// `a` with the empty region, so every edge names `region` 0 and the answer has the form and
/// the guarantees of [`boolean`].
///
/// ```
/// use blossom::region::{simplify, FillRule, Region};
/// use blossom::Bezier;
/// let square = |x: f64, y: f64| -> Vec<Bezier<f64, 2>> {
///     let c = [[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]];
///     (0..4).map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]).unwrap()).collect()
/// };
/// // Two overlapping squares in one region: one loop of area 7 after overlap removal.
/// let a = Region::from_f64(vec![square(0.0, 0.0), square(1.0, 1.0)], FillRule::NonZero)?;
/// let r = simplify(&a)?;
/// assert_eq!(r.loops.len(), 1);
/// assert!(r.area[0] <= 7.0 && 7.0 <= r.area[1]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// As [`boolean`].
pub fn simplify(a: &Region) -> Result<RegionResult> {
    boolean(a, &Region::empty(a.fill()), BooleanOp::Union)
}

/// The estimated work of [`simplify`], as [`boolean_work`].
pub fn simplify_work(a: &Region) -> u128 {
    boolean_work(a, &Region::empty(a.fill()))
}

/// The intersection of the regions of two planar Bézier triangles (build them with
/// [`Region::triangle`]): [`boolean`] with [`BooleanOp::Intersection`]; an [`Edge`] names the
/// triangle as `region` and its edge (0, 1, 2) as `curve`.
///
/// ```
/// use blossom::region::{triangle_intersection, Region};
/// use blossom::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let t1 = Region::triangle(1, vec![[q(0), q(0)], [q(2), q(0)], [q(0), q(2)]])?;
/// let t2 = Region::triangle(1, vec![[q(2), q(2)], [q(0), q(2)], [q(2), q(0)]])?;
/// // They share the diagonal only: the regularized intersection is empty.
/// let r = triangle_intersection(&t1, &t2)?;
/// assert!(r.loops.is_empty() && r.area == [0.0, 0.0]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// As [`boolean`].
pub fn triangle_intersection(t1: &Region, t2: &Region) -> Result<RegionResult> {
    boolean(t1, t2, BooleanOp::Intersection)
}

/// The estimated work of [`boolean`] on `a` and `b`, in nanoseconds of a 2-core x86-64
/// machine as [`intersection_work`](crate::budget::intersection_work). When both regions
/// are of doubles (the float path of [`boolean`]), a few microseconds per pair of curves
/// whose boxes meet and per curve, and a ray on boxes per loop against every curve; the
/// exact intersections of the pairs the float filter will not decide are not counted, and a
/// caller bounds them with its work meter (the CLI does). Otherwise the exact stages'
/// estimate: the intersections of every
/// pair of curves whose boxes meet ([`curve_pair_work`](crate::budget::curve_pair_work), which runs
/// the float filter), the self-intersections of every curve
/// ([`self_intersection_work`](crate::budget::self_intersection_work)), and the classification of the
/// pieces (one ray per piece against the curves). It does not depend on `op`. Curves that
/// follow each other in a loop and are proved to meet only at their join, and curves proved
/// one-to-one, count a few microseconds instead of the exact solver's estimate.
///
/// ```
/// use blossom::region::{boolean_work, Region};
/// use blossom::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let t1 = Region::triangle(1, vec![[q(0), q(0)], [q(2), q(0)], [q(0), q(2)]])?;
/// let t2 = Region::triangle(1, vec![[q(1), q(0)], [q(3), q(0)], [q(1), q(2)]])?;
/// // Six lines: well under a millisecond.
/// assert!(boolean_work(&t1, &t2) < 1_000_000_000);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn boolean_work(a: &Region, b: &Region) -> u128 {
    super::pipeline::work(&[a, b])
}
