//! The input: a region as loops of exact 2-D Bézier curves and a fill rule, checked on entry.

use super::curve::is_double;
use crate::error::{Error, ErrorKind, Result};
use crate::intersect::algebraic::exact_f64;
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::array::Bezier;
use std::sync::{Arc, OnceLock};

/// The highest curve degree a region accepts: the exact intersection of two curves of degree
/// n costs about n^4 operations on growing numbers (see
/// [`intersection_work`](crate::budget::intersection_work)), 0.6-1.6 s at degree 20.
pub const MAX_REGION_DEGREE: usize = 20;

/// Which points the loops of a region enclose (SVG's fill rules).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// Points whose winding number around all loops together is not zero.
    #[default]
    NonZero,
    /// Points whose winding number around all loops together is odd.
    EvenOdd,
}

impl FillRule {
    /// Whether a point of winding number `w` (off the loops) is inside.
    ///
    /// ```
    /// use blossom::region::FillRule;
    /// assert!(FillRule::NonZero.inside(-2) && !FillRule::EvenOdd.inside(-2));
    /// ```
    pub fn inside(self, w: i64) -> bool {
        match self {
            FillRule::NonZero => w != 0,
            FillRule::EvenOdd => w % 2 != 0,
        }
    }
}

/// A region of the plane: closed loops of 2-D polynomial Bézier curves (any degree from 1 to
/// [`MAX_REGION_DEGREE`], exact rational control points) and a [`FillRule`]. The region is the
/// set of points off the loops that the fill rule puts inside, given the exact winding number
/// of the point around all loops together ([`Region::winding`]).
///
/// Loops may cross themselves and each other, touch, share pieces and run either way. A curve
/// whose control points are all one point is accepted and traces nothing.
///
/// ```
/// use blossom::region::{FillRule, Position, Region};
/// use blossom::{Bezier, Rational};
/// let p = |x: i64, y: i64| [Rational::from_integer(x.into()), Rational::from_integer(y.into())];
/// // The unit square, counter-clockwise, its top side a quadratic bulging upwards.
/// let square = Region::new(
///     vec![vec![
///         Bezier::new(vec![p(0, 0), p(1, 0)])?,
///         Bezier::new(vec![p(1, 0), p(1, 1)])?,
///         Bezier::new(vec![p(1, 1), p(1, 2), p(0, 1)])?,
///         Bezier::new(vec![p(0, 1), p(0, 0)])?,
///     ]],
///     FillRule::NonZero,
/// )?;
/// assert_eq!(square.contains(&p(1, 1)), Position::Boundary);
/// let inside = [Rational::new(1.into(), 2.into()), Rational::new(5.into(), 4.into())];
/// assert_eq!(square.contains(&inside), Position::Inside);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// A `Region` is a shared handle: cloning it is cheap (one reference count), and what is
/// proved about it once (its loops' simplicity, its exact curves) is kept for every clone.
#[derive(Clone, Debug)]
pub struct Region(Arc<RegionData>);

/// The data behind a [`Region`].
#[derive(Debug)]
struct RegionData {
    /// The exact curves: given, or made from `doubles` on first use.
    loops: OnceLock<Vec<Vec<Bezier<Rational, 2>>>>,
    fill: FillRule,
    /// The control points as doubles when every coordinate is one exactly (the float path
    /// of the booleans reads these).
    doubles: Option<Arc<Doubles>>,
    /// Whether the float path proved the loops simple and pairwise disjoint (computed by the
    /// first boolean that asks, then kept: a fact about the region alone).
    simple: OnceLock<bool>,
}

impl PartialEq for Region {
    /// The same loops of the same curves and the same fill rule.
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
            || (self.fill() == other.fill() && self.loops() == other.loops())
    }
}

/// The control points of a region's curves as doubles, `[loop][curve][point]`.
pub(crate) type Doubles = Vec<Vec<Vec<[f64; 2]>>>;

/// The control points of `loops` as doubles, when every coordinate is one exactly.
fn as_doubles(loops: &[Vec<Bezier<Rational, 2>>]) -> Option<Doubles> {
    loops
        .iter()
        .map(|curves| {
            curves
                .iter()
                .map(|c| {
                    c.points()
                        .iter()
                        .map(|p| {
                            (is_double(&p[0]) && is_double(&p[1]))
                                .then(|| [rational_to_f64(&p[0]), rational_to_f64(&p[1])])
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// The checks of [`Region::new`] on the control points of every curve (`loops[l][c]`),
/// `show` writing a point for the messages.
fn validate<P: PartialEq>(loops: &[Vec<&[P]>], show: impl Fn(&P) -> String) -> Result<()> {
    for (l, curves) in loops.iter().enumerate() {
        if curves.is_empty() {
            return Err(Error::of(
                ErrorKind::Empty,
                format!("loops[{l}]"),
                "a loop needs at least one curve",
            ));
        }
        for (c, points) in curves.iter().enumerate() {
            let n = points.len().saturating_sub(1);
            if n == 0 || n > MAX_REGION_DEGREE {
                return Err(Error::of(
                    ErrorKind::Degree,
                    format!("loops[{l}][{c}]"),
                    format!(
                        "degree {n} is outside the accepted 1..={MAX_REGION_DEGREE} \
                         (a curve needs at least 2 control points)"
                    ),
                ));
            }
        }
        for c in 0..curves.len() {
            let previous = curves[(c + curves.len() - 1) % curves.len()];
            let end = previous.last().expect("degree >= 1");
            let start = &curves[c][0];
            if end != start {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("loops[{l}][{c}]"),
                    format!(
                        "starts at {}, the previous curve ends at {}",
                        show(start),
                        show(end)
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The three edges (control points) of the planar Bézier triangle of degree `degree` with
/// `nodes` in the spec's order (see [`Region::triangle`]).
fn triangle_edges<P: Clone>(degree: usize, nodes: &[P]) -> Result<[Vec<P>; 3]> {
    if degree == 0 || degree > MAX_REGION_DEGREE {
        return Err(Error::of(
            ErrorKind::Degree,
            "degree",
            format!("degree {degree} is outside the accepted 1..={MAX_REGION_DEGREE}"),
        ));
    }
    let n = degree;
    let expected = (n + 1) * (n + 2) / 2;
    if nodes.len() != expected {
        return Err(Error::of(
            ErrorKind::Shape,
            "nodes",
            format!(
                "a triangle of degree {n} has {expected} nodes, found {}",
                nodes.len()
            ),
        ));
    }
    // p_ijk with i = n - j - k sits at offset(k) + j, offset(k) = sum_(k' < k) (n + 1 - k').
    let at = |j: usize, k: usize| {
        let offset: usize = (0..k).map(|kk| n + 1 - kk).sum();
        nodes[offset + j].clone()
    };
    Ok([
        (0..=n).map(|j| at(j, 0)).collect(),
        (0..=n).map(|k| at(n - k, k)).collect(),
        (0..=n).map(|i| at(0, n - i)).collect(),
    ])
}

/// A point written as the spec writes it: `(1, 1/2)`.
pub(crate) fn show(p: &[Rational; 2]) -> String {
    format!("({}, {})", p[0], p[1])
}

impl Region {
    /// The region of `loops` (`loops[l][c]` is curve c of loop l) under `fill`.
    ///
    /// # Errors
    /// Each names the field relative to the region:
    /// * [`ErrorKind::Empty`] on `loops[l]` for a loop without curves;
    /// * [`ErrorKind::Degree`] on `loops[l][c]` for a curve of degree 0 or over
    ///   [`MAX_REGION_DEGREE`];
    /// * [`ErrorKind::Shape`] on `loops[l][c]` when curve c does not start exactly where curve
    ///   c - 1 ends (`starts at (1, 0), the previous curve ends at (1, 1/2)`); a last curve
    ///   that does not end where the first starts names curve 0.
    pub fn new(loops: Vec<Vec<Bezier<Rational, 2>>>, fill: FillRule) -> Result<Region> {
        let points: Vec<Vec<&[[Rational; 2]]>> = loops
            .iter()
            .map(|curves| curves.iter().map(|c| c.points()).collect())
            .collect();
        validate(&points, show)?;
        let doubles = as_doubles(&loops).map(Arc::new);
        Ok(Region(Arc::new(RegionData {
            loops: OnceLock::from(loops),
            fill,
            doubles,
            simple: OnceLock::new(),
        })))
    }

    /// [`Region::new`] of control points given as doubles, each read exactly.
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `loops[l][c][i]` for a NaN or an infinity, else as
    /// [`Region::new`].
    pub fn from_f64(loops: Vec<Vec<Bezier<f64, 2>>>, fill: FillRule) -> Result<Region> {
        let doubles: Doubles = loops
            .iter()
            .map(|curves| curves.iter().map(|c| c.points().to_vec()).collect())
            .collect();
        Region::of_doubles(doubles, fill)
    }

    /// The region of loops of curves of doubles (`doubles[l][c]`: the control points of
    /// curve c of loop l), each number read exactly; the exact curves are made on first use.
    fn of_doubles(doubles: Doubles, fill: FillRule) -> Result<Region> {
        for (l, curves) in doubles.iter().enumerate() {
            for (c, points) in curves.iter().enumerate() {
                for (i, xy) in points.iter().enumerate() {
                    if let Some(x) = xy.iter().find(|x| !x.is_finite()) {
                        return Err(Error::of(
                            ErrorKind::NotFinite,
                            format!("loops[{l}][{c}][{i}]"),
                            format!("expected a finite number, found {x}"),
                        ));
                    }
                }
            }
        }
        let points: Vec<Vec<&[[f64; 2]]>> = doubles
            .iter()
            .map(|curves| curves.iter().map(Vec::as_slice).collect())
            .collect();
        validate(&points, |p| show(&[exact_f64(p[0]), exact_f64(p[1])]))?;
        Ok(Region(Arc::new(RegionData {
            loops: OnceLock::new(),
            fill,
            doubles: Some(Arc::new(doubles)),
            simple: OnceLock::new(),
        })))
    }

    /// The region of the planar Bézier triangle of degree `degree` with `nodes` in the spec's
    /// order (p_n00, p_(n-1)10, ..., p_0n0, p_(n-1)01, ..., p_00n: by increasing k, within it
    /// increasing j): one loop of its three edges, edge 0 = B(s, 0), edge 1 = B(1 - t, t),
    /// edge 2 = B(0, 1 - u), each of degree `degree` (curves 0, 1, 2 of loop 0), fill nonzero.
    ///
    /// ```
    /// use blossom::region::{Position, Region};
    /// use blossom::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let t = Region::triangle(1, vec![[q(0), q(0)], [q(1), q(0)], [q(0), q(1)]])?;
    /// let centre = [Rational::new(1.into(), 4.into()), Rational::new(1.into(), 4.into())];
    /// assert_eq!(t.contains(&centre), Position::Inside);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Degree`] on `degree` for 0 or over [`MAX_REGION_DEGREE`];
    /// [`ErrorKind::Shape`] on `nodes` when there are not (n + 1)(n + 2)/2 of them.
    pub fn triangle(degree: usize, nodes: Vec<[Rational; 2]>) -> Result<Region> {
        let curves = triangle_edges(degree, &nodes)?
            .into_iter()
            .map(Bezier::new)
            .collect::<Result<Vec<_>>>()?;
        Region::new(vec![curves], FillRule::NonZero)
    }

    /// [`Region::triangle`] of nodes given as doubles, each read exactly (the exact curves are
    /// made only if an exact computation needs them).
    ///
    /// ```
    /// use blossom::region::{triangle_intersection, Region};
    /// let t1 = Region::triangle_f64(1, vec![[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])?;
    /// let t2 = Region::triangle_f64(1, vec![[1.0, 0.0], [3.0, 0.0], [1.0, 2.0]])?;
    /// let r = triangle_intersection(&t1, &t2)?;
    /// // The overlap is the triangle (1, 0), (2, 0), (1, 1): area 1/2.
    /// assert!(r.area[0] <= 0.5 && 0.5 <= r.area[1]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Region::triangle`], and [`ErrorKind::NotFinite`] on `nodes[k]` for a node with a
    /// NaN or an infinity.
    pub fn triangle_f64(degree: usize, nodes: Vec<[f64; 2]>) -> Result<Region> {
        if let Some(k) = nodes
            .iter()
            .position(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(Error::of(
                ErrorKind::NotFinite,
                format!("nodes[{k}]"),
                format!("expected finite numbers, found {:?}", nodes[k]),
            ));
        }
        let edges = triangle_edges(degree, &nodes)?;
        Region::of_doubles(vec![Vec::from(edges)], FillRule::NonZero)
    }

    /// The empty region (no loops) under `fill`.
    ///
    /// ```
    /// use blossom::region::{FillRule, Region};
    /// assert!(Region::empty(FillRule::NonZero).loops().is_empty());
    /// ```
    pub fn empty(fill: FillRule) -> Region {
        Region(Arc::new(RegionData {
            loops: OnceLock::from(Vec::new()),
            fill,
            doubles: Some(Arc::new(Vec::new())),
            simple: OnceLock::new(),
        }))
    }

    /// The loops: `loops()[l][c]` is curve c of loop l.
    pub fn loops(&self) -> &[Vec<Bezier<Rational, 2>>] {
        self.0.loops.get_or_init(|| {
            let doubles = self
                .0
                .doubles
                .as_ref()
                .expect("a region without its exact curves was made from doubles");
            doubles
                .iter()
                .map(|curves| {
                    curves
                        .iter()
                        .map(|points| {
                            let exact = points
                                .iter()
                                .map(|p| [exact_f64(p[0]), exact_f64(p[1])])
                                .collect();
                            Bezier::new(exact).expect("validated when the region was made")
                        })
                        .collect()
                })
                .collect()
        })
    }

    /// The fill rule.
    pub fn fill(&self) -> FillRule {
        self.0.fill
    }

    /// The control points as doubles, loop by loop and curve by curve, when every input
    /// coordinate is a double exactly.
    pub(crate) fn doubles(&self) -> Option<&Arc<Doubles>> {
        self.0.doubles.as_ref()
    }

    /// Whether the float path proved the region's loops simple and pairwise disjoint, by
    /// `prove` on the first call.
    pub(crate) fn proved_simple(&self, prove: impl FnOnce() -> bool) -> bool {
        *self.0.simple.get_or_init(prove)
    }
}

/// Whether every control point of the curve is the same point (the curve traces one point).
pub(crate) fn is_single_point(curve: &Bezier<Rational, 2>) -> bool {
    let p = curve.points();
    p.iter().all(|q| q == &p[0])
}
