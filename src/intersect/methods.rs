//! The certified operations as methods of the curve types a user holds:
//! [`BezierCurve<T>`] (any dimension, checked where an operation needs one) and
//! [`Bezier<T, D>`] (`D` in the type), for `T` = `f64` or [`Rational`] alike
//! ([`ExactInput`]: doubles are read exactly, nothing is rounded on the way in).
//!
//! Each method is thin: it names its arguments, reads the coordinates exactly and calls the
//! one implementation of its operation (`curves`, `rounded`, `zeros`, `extrema`), which the
//! free functions call too.

use super::curves::{intersect_named, pairs, self_intersections_named, Intersections};
use super::extrema::{box_of, nearest_of, NearestPoint, TightBox};
use super::rounded::{rounded_named, RoundedIntersections};
use super::zeros::{bezier_zeros, BezierZeros};
use crate::error::{Error, ErrorKind, Result};
use crate::num::exact::{exact_coordinates, exact_values, ExactInput};
use crate::num::ring::Rational;
use crate::shape::array::Bezier;
use crate::shape::bezier::BezierCurve;

/// `Ok` when a curve named `field` has points of `want` coordinates, else
/// [`ErrorKind::Dimension`] on `field[0]` (every point of a curve has the curve's dimension).
fn check_dimension(field: &str, found: usize, want: usize, what: &str) -> Result<()> {
    if found == want {
        return Ok(());
    }
    Err(Error::of(
        ErrorKind::Dimension,
        format!("{field}[0]"),
        format!("{what} needs points of {want} coordinates, found {found}"),
    ))
}

/// The control points of a planar curve read exactly.
fn planar<T: ExactInput>(field: &str, coordinates: &[T]) -> Result<Vec<[Rational; 2]>> {
    Ok(pairs(&exact_coordinates(field, coordinates, 2)?))
}

impl<T: ExactInput> BezierCurve<T> {
    /// Every intersection of this planar curve P with the planar curve `other` Q over
    /// [0, 1]: the isolated points P(s) = Q(t) with the exact parameters and an exact tangency
    /// flag, and the overlaps (maximal common stretches), all **certified**; see
    /// [`Intersections`] for the guarantee, the method and its limits. An overlap is a common
    /// piece of the two exact curves: a piece computed in `f64` at a parameter that is not
    /// dyadic has rounded control points and is another curve, with no overlap
    /// ([`Intersections`] shows the exact route that finds it). The same as
    /// [`Bezier::intersect`] and [`intersect_curves`](crate::intersect_curves).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let a = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// let b = BezierCurve::new(vec![vec![0.0, 0.5], vec![2.0, 0.5]])?;
    /// let x = a.intersect(&b)?;
    /// assert_eq!(x.points.len(), 2);
    /// // 4s(1 - s) = 1/2 at s = (2 ± sqrt 2) / 4: irrational, the roots of 8s^2 - 8s + 1.
    /// let s = &x.points[0].s;
    /// assert!(s.exact().is_none());
    /// assert_eq!(s.polynomial(), [1.into(), (-8).into(), 8.into()]);
    /// assert!((s.to_f64() - 0.1464466094067262).abs() < 1e-16);
    /// assert!(!x.points[0].tangent);
    /// // A curve of another dimension is refused, naming it.
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0, 1.0], vec![1.0, 1.0, 1.0]])?;
    /// assert_eq!(a.intersect(&c).unwrap_err().path(), "other.control_points[0]");
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `control_points[0]` or `other.control_points[0]` when a
    /// curve is not planar; [`ErrorKind::Empty`] on `control_points` or
    /// `other.control_points` for a curve of degree 0 (one control point);
    /// [`ErrorKind::NotFinite`] on `control_points[i][j]` or `other.control_points[i][j]`
    /// for a NaN or an infinity.
    pub fn intersect(&self, other: &Self) -> Result<Intersections> {
        check_dimension("control_points", self.dim(), 2, "curve-curve intersection")?;
        check_dimension(
            "other.control_points",
            other.dim(),
            2,
            "curve-curve intersection",
        )?;
        let p = planar("control_points", self.coordinates())?;
        let q = planar("other.control_points", other.coordinates())?;
        intersect_named(&p, &q, ["control_points", "other.control_points"])
    }

    /// [`BezierCurve::intersect`] as doubles: the parameters correctly rounded (ties to even),
    /// the tangency flag exact, the common points correctly rounded. When both curves' control
    /// points are doubles exactly, the float filter
    /// ([`certified_crossings_f64`](crate::certified_crossings_f64)) answers first if it can
    /// prove the complete answer (transversal crossings inside (0, 1)^2, no big numbers);
    /// otherwise the exact path answers, rounded. Both give the same doubles.
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let a = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 1.0]])?;
    /// let b = BezierCurve::new(vec![vec![0.0, 1.0], vec![1.0, 0.0]])?;
    /// let x = a.intersect_rounded(&b)?;
    /// assert!(x.by_filter);
    /// assert_eq!((x.points[0].s, x.points[0].t, x.points[0].point), (0.5, 0.5, [0.5, 0.5]));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`BezierCurve::intersect`].
    pub fn intersect_rounded(&self, other: &Self) -> Result<RoundedIntersections> {
        check_dimension("control_points", self.dim(), 2, "curve-curve intersection")?;
        check_dimension(
            "other.control_points",
            other.dim(),
            2,
            "curve-curve intersection",
        )?;
        rounded_named(
            self.coordinates(),
            other.coordinates(),
            ["control_points", "other.control_points"],
        )
    }

    /// Every pair s < t in [0, 1] with P(s) = P(t) of this planar curve, and the overlaps of
    /// a curve that retraces itself, **certified** (see [`Intersections`]). The same as
    /// [`Bezier::self_intersections`] and [`self_intersections`](crate::self_intersections).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// // A loop: the cubic (0, 0), (2, 2), (-1, 2), (1, 0) crosses itself once.
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![2.0, 2.0], vec![-1.0, 2.0], vec![1.0, 0.0]])?;
    /// let x = c.self_intersections()?;
    /// assert_eq!(x.points.len(), 1);
    /// let p = &x.points[0];
    /// assert!(p.s.compare(&p.t).is_lt());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `control_points[0]` when the curve is not planar;
    /// [`ErrorKind::Empty`] on `control_points` for degree 0; [`ErrorKind::NotFinite`] on
    /// `control_points[i][j]`.
    pub fn self_intersections(&self) -> Result<Intersections> {
        check_dimension("control_points", self.dim(), 2, "self-intersection")?;
        let p = planar("control_points", self.coordinates())?;
        self_intersections_named(&p, "control_points")
    }

    /// The tight bounding box of the curve over [0, 1], in any dimension: for each coordinate
    /// its exact minimum and maximum along the curve (not the control polygon's box) and where
    /// they are attained, **exact** ([`TightBox`]; [`TightBox::outward`] rounds it outwards
    /// to the smallest box of doubles that holds the curve).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// // The arch (0, 0), (1, 2), (2, 0) peaks at y = 1, below its control point's 2.
    /// let arch = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// let bounds = arch.bounding_box()?;
    /// assert_eq!(bounds.outward(), (vec![0.0, 0.0], vec![2.0, 1.0]));
    /// assert_eq!(bounds.max[1].at[0].to_f64(), 0.5);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `control_points[i][j]` (never for `Rational`).
    pub fn bounding_box(&self) -> Result<TightBox> {
        let exact = exact_coordinates("control_points", self.coordinates(), self.dim())?;
        Ok(box_of(&exact, self.dim()))
    }

    /// The points of the curve over [0, 1] nearest to `point`, in any dimension: the exact
    /// squared distance, every parameter attaining it and the nearest points, **exact**
    /// ([`NearestPoint`]).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let line = BezierCurve::new(vec![vec![0.0, 0.0], vec![4.0, 0.0]])?;
    /// let nearest = line.nearest_point(&[1.0, 3.0])?;
    /// assert_eq!(nearest.squared_distance.to_f64(), 9.0);
    /// assert_eq!(nearest.at[0].to_f64(), 0.25);
    /// // A point of another dimension is refused.
    /// assert_eq!(line.nearest_point(&[1.0]).unwrap_err().path(), "point");
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `point` when it has not the curve's dimension;
    /// [`ErrorKind::NotFinite`] on `control_points[i][j]` or `point[j]`.
    pub fn nearest_point(&self, point: &[T]) -> Result<NearestPoint> {
        let exact = exact_coordinates("control_points", self.coordinates(), self.dim())?;
        nearest_of(&exact, self.dim(), &exact_values("point", point)?, "point")
    }

    /// The zeros in [0, 1] of this 1-D curve read as a Bézier function
    /// f(t) = sum_i c_i B_i^n(t), with multiplicities, **exact** ([`BezierZeros`]). The same
    /// as [`Bezier::zeros`] and [`bezier_zeros`](crate::bezier_zeros).
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// // Coefficients 1, -1, 1: f(t) = (1 - t)^2 - 2t(1 - t) + t^2 = (1 - 2t)^2.
    /// let f = BezierCurve::new(vec![vec![1.0], vec![-1.0], vec![1.0]])?;
    /// let z = f.zeros()?;
    /// assert_eq!(z.zeros.len(), 1);
    /// assert_eq!((z.zeros[0].t.to_string(), z.zeros[0].multiplicity), ("1/2".to_string(), 2));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Dimension`] on `control_points[0]` when the curve is not 1-D;
    /// [`ErrorKind::NotFinite`] on `control_points[i][0]`.
    pub fn zeros(&self) -> Result<BezierZeros> {
        check_dimension("control_points", self.dim(), 1, "the zeros of a function")?;
        bezier_zeros(&exact_coordinates("control_points", self.coordinates(), 1)?)
    }
}

impl<T: ExactInput> Bezier<T, 2> {
    /// Every intersection of this planar curve with `other`, **certified**: as
    /// [`BezierCurve::intersect`], which it is.
    ///
    /// ```
    /// use blossom::{Bezier, Rational};
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let a = Bezier::new(vec![[q(0), q(0)], [q(2), q(2)]])?;
    /// let b = Bezier::new(vec![[q(0), q(2)], [q(2), q(0)]])?;
    /// let x = a.intersect(&b)?;
    /// assert_eq!(x.points[0].s.exact(), Some(&Rational::new(1.into(), 2.into())));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Empty`] on `points` or `other.points` for a curve of degree 0;
    /// [`ErrorKind::NotFinite`] on `points[i][j]` or `other.points[i][j]`.
    pub fn intersect(&self, other: &Self) -> Result<Intersections> {
        let p = planar("points", self.points().as_flattened())?;
        let q = planar("other.points", other.points().as_flattened())?;
        intersect_named(&p, &q, ["points", "other.points"])
    }

    /// As [`BezierCurve::intersect_rounded`]: the doubles of the certified answer, the float
    /// filter first when it decides.
    ///
    /// ```
    /// use blossom::Bezier;
    /// let a = Bezier::new(vec![[0.0, 0.0], [1.0, 1.0]])?;
    /// let b = Bezier::new(vec![[1.0, 1.0], [2.0, 0.0]])?;
    /// // An end-point contact: decided exactly, not by the filter.
    /// let x = a.intersect_rounded(&b)?;
    /// assert!(!x.by_filter);
    /// assert_eq!((x.points[0].s, x.points[0].t), (1.0, 0.0));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Bezier::intersect`].
    pub fn intersect_rounded(&self, other: &Self) -> Result<RoundedIntersections> {
        rounded_named(
            self.points().as_flattened(),
            other.points().as_flattened(),
            ["points", "other.points"],
        )
    }

    /// Every self-intersection of this planar curve, **certified**: as
    /// [`BezierCurve::self_intersections`].
    ///
    /// ```
    /// use blossom::Bezier;
    /// let c = Bezier::new(vec![[0.0, 0.0], [2.0, 2.0], [-1.0, 2.0], [1.0, 0.0]])?;
    /// assert_eq!(c.self_intersections()?.points.len(), 1);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Empty`] on `points` for degree 0; [`ErrorKind::NotFinite`] on
    /// `points[i][j]`.
    pub fn self_intersections(&self) -> Result<Intersections> {
        let p = planar("points", self.points().as_flattened())?;
        self_intersections_named(&p, "points")
    }
}

impl<T: ExactInput> Bezier<T, 1> {
    /// The zeros in [0, 1] of the Bézier function with these coefficients, with
    /// multiplicities, **exact**: as [`BezierCurve::zeros`].
    ///
    /// ```
    /// use blossom::Bezier;
    /// // f(t) = 1 - 3t: coefficients 1, -2 over [0, 1].
    /// let f = Bezier::new(vec![[1.0], [-2.0]])?;
    /// assert_eq!(f.zeros()?.zeros[0].t.to_string(), "1/3");
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `points[i][0]`.
    pub fn zeros(&self) -> Result<BezierZeros> {
        bezier_zeros(&exact_coordinates(
            "points",
            self.points().as_flattened(),
            1,
        )?)
    }
}

impl<T: ExactInput, const D: usize> Bezier<T, D> {
    /// The tight bounding box of the curve, **exact**: as [`BezierCurve::bounding_box`].
    ///
    /// ```
    /// use blossom::Bezier;
    /// let arch = Bezier::new(vec![[0.0, 0.0, 0.0], [1.0, 2.0, 0.0], [2.0, 0.0, 0.0]])?;
    /// assert_eq!(arch.bounding_box()?.outward(), (vec![0.0; 3], vec![2.0, 1.0, 0.0]));
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `points[i][j]` (never for `Rational`).
    pub fn bounding_box(&self) -> Result<TightBox> {
        let exact = exact_coordinates("points", self.points().as_flattened(), D)?;
        Ok(box_of(&exact, D))
    }

    /// The points of the curve nearest to `point`, **exact**: as
    /// [`BezierCurve::nearest_point`].
    ///
    /// ```
    /// use blossom::Bezier;
    /// let line = Bezier::new(vec![[0.0, 0.0], [4.0, 0.0]])?;
    /// assert_eq!(line.nearest_point(&[1.0, 3.0])?.at[0].to_f64(), 0.25);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `points[i][j]` or `point[j]`.
    pub fn nearest_point(&self, point: &[T; D]) -> Result<NearestPoint> {
        let exact = exact_coordinates("points", self.points().as_flattened(), D)?;
        nearest_of(&exact, D, &exact_values("point", point)?, "point")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::ring::rational_to_f64;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    fn curve(points: &[[f64; 2]]) -> BezierCurve<f64> {
        BezierCurve::new(points.iter().map(|p| p.to_vec()).collect()).unwrap()
    }

    fn exact(c: &BezierCurve<f64>) -> BezierCurve<Rational> {
        let coords = c
            .coordinates()
            .iter()
            .map(|&x| Rational::from_float(x).unwrap())
            .collect();
        BezierCurve::from_coordinates(c.dim(), coords).unwrap()
    }

    /// The answer as text with every number exact (the records' own `Display`, rational or
    /// polynomial with interval, compared by the rounded doubles and the exact flags).
    fn summary(x: &Intersections) -> Vec<(f64, f64, bool, [f64; 2])> {
        x.points
            .iter()
            .map(|p| (p.s.to_f64(), p.t.to_f64(), p.tangent, p.point))
            .chain(x.overlaps.iter().map(|o| {
                (
                    o.s[0].to_f64(),
                    o.t[0].to_f64(),
                    true,
                    [o.s[1].to_f64(), o.t[1].to_f64()],
                )
            }))
            .collect()
    }

    #[test]
    fn dimension_errors_name_the_curve() {
        let planar = curve(&[[0.0, 0.0], [1.0, 1.0]]);
        let space = BezierCurve::new(vec![vec![0.0, 0.0, 0.0], vec![1.0, 1.0, 1.0]]).unwrap();
        let line = BezierCurve::new(vec![vec![0.0], vec![1.0]]).unwrap();
        let path = |e: Error| (e.kind, e.path().to_string());
        let dim = ErrorKind::Dimension;
        assert_eq!(
            path(space.intersect(&planar).unwrap_err()),
            (dim, "control_points[0]".into())
        );
        assert_eq!(
            path(planar.intersect(&space).unwrap_err()),
            (dim, "other.control_points[0]".into())
        );
        assert_eq!(
            path(planar.intersect_rounded(&line).unwrap_err()),
            (dim, "other.control_points[0]".into())
        );
        assert_eq!(
            path(line.self_intersections().unwrap_err()),
            (dim, "control_points[0]".into())
        );
        assert_eq!(
            path(planar.zeros().unwrap_err()),
            (dim, "control_points[0]".into())
        );
        assert_eq!(
            path(planar.nearest_point(&[0.0]).unwrap_err()),
            (dim, "point".into())
        );
        // The box and the nearest point take any dimension.
        assert_eq!(space.bounding_box().unwrap().min.len(), 3);
        assert!(space.nearest_point(&[2.0, 2.0, 2.0]).unwrap().at[0].exact() == Some(&q(1, 1)));
    }

    #[test]
    fn degree_zero_and_non_finite_input_name_the_field() {
        let point = BezierCurve::new(vec![vec![1.0, 1.0]]).unwrap();
        let planar = curve(&[[0.0, 0.0], [1.0, 1.0]]);
        let e = planar.intersect(&point).unwrap_err();
        assert_eq!(
            (e.kind, e.path()),
            (ErrorKind::Empty, "other.control_points")
        );
        let e = point.self_intersections().unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::Empty, "control_points"));
        let nan = curve(&[[0.0, 0.0], [1.0, f64::NAN]]);
        for e in [
            planar.intersect(&nan).unwrap_err(),
            planar.intersect_rounded(&nan).unwrap_err(),
        ] {
            assert_eq!(
                (e.kind, e.path()),
                (ErrorKind::NotFinite, "other.control_points[1][1]")
            );
        }
        assert_eq!(
            nan.bounding_box().unwrap_err().path(),
            "control_points[1][1]"
        );
        assert_eq!(
            planar
                .nearest_point(&[0.0, f64::INFINITY])
                .unwrap_err()
                .path(),
            "point[1]"
        );
        let a = Bezier::new(vec![[0.0, 0.0], [f64::NAN, 1.0]]).unwrap();
        let e = a.self_intersections().unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::NotFinite, "points[1][0]"));
        let e = Bezier::new(vec![[0.0, 0.0]])
            .unwrap()
            .intersect(&Bezier::new(vec![[0.0, 0.0], [1.0, 1.0]]).unwrap())
            .unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::Empty, "points"));
        let f = Bezier::new(vec![[1.0], [f64::INFINITY]]).unwrap();
        assert_eq!(f.zeros().unwrap_err().path(), "points[1][0]");
    }

    #[test]
    fn doubles_are_read_exactly_not_rounded() {
        // 0.1 is not 1/10: the line from (0, 0.1) to (1, 0.1) meets y = x at s = t = the
        // double 0.1 read exactly (its own rational), which to_f64 gives back bit for bit.
        let flat = curve(&[[0.0, 0.1], [1.0, 0.1]]);
        let diagonal = curve(&[[0.0, 0.0], [1.0, 1.0]]);
        let x = flat.intersect(&diagonal).unwrap();
        assert_eq!(x.points[0].s.exact(), Rational::from_float(0.1).as_ref());
        assert_ne!(x.points[0].s.exact(), Some(&q(1, 10)));
        // The exact curve through 1/10 meets it at 1/10: a different curve, a different answer.
        let tenth =
            BezierCurve::new(vec![vec![q(0, 1), q(1, 10)], vec![q(1, 1), q(1, 10)]]).unwrap();
        let x = tenth.intersect(&exact(&diagonal)).unwrap();
        assert_eq!(x.points[0].s.exact(), Some(&q(1, 10)));
        // The zeros of a function of doubles likewise: a (1 - t) + b t with the doubles
        // a = 0.1, b = 0.1 - 1.0 has its zero at A / (A - B) for their exact values A, B.
        let (a, b) = (0.1, 0.1 - 1.0);
        let f = BezierCurve::new(vec![vec![a], vec![b]]).unwrap();
        let (ea, eb) = (
            Rational::from_float(a).unwrap(),
            Rational::from_float(b).unwrap(),
        );
        let z = f.zeros().unwrap();
        assert_eq!(z.zeros[0].t.exact(), Some(&(&ea / (&ea - &eb))));
        let g = Bezier::new(vec![[a], [b]]).unwrap();
        assert_eq!(
            g.zeros().unwrap().zeros[0].t.exact(),
            Some(&(&ea / (&ea - &eb)))
        );
    }

    #[test]
    fn f64_and_exact_input_agree_on_dyadic_curves() {
        // Dyadic control points: the f64 curve is the exact one, so every answer is equal.
        type Pair<'a> = (&'a [[f64; 2]], &'a [[f64; 2]]);
        let cases: [Pair; 3] = [
            (
                &[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]],
                &[[0.0, 0.5], [2.0, 0.5]],
            ),
            (
                &[[0.0, 0.0], [2.0, 2.0], [-1.0, 2.0], [1.0, 0.0]],
                &[[0.0, 1.0], [0.25, -1.0], [1.0, 1.5]],
            ),
            // A tangency and an overlap: decided by the exact path in both.
            (
                &[[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]],
                &[[0.0, 0.5], [1.0, 0.5]],
            ),
        ];
        for (a, b) in cases {
            let (fa, fb) = (curve(a), curve(b));
            let (ea, eb) = (exact(&fa), exact(&fb));
            let by_f64 = fa.intersect(&fb).unwrap();
            let by_exact = ea.intersect(&eb).unwrap();
            assert_eq!(summary(&by_f64), summary(&by_exact));
            assert_eq!(by_f64.to_string(), by_exact.to_string());
            assert_eq!(
                fa.intersect_rounded(&fb).unwrap().points,
                ea.intersect_rounded(&eb).unwrap().points
            );
            assert_eq!(
                fa.self_intersections().unwrap().to_string(),
                ea.self_intersections().unwrap().to_string()
            );
            assert_eq!(
                fa.bounding_box().unwrap().to_string(),
                ea.bounding_box().unwrap().to_string()
            );
            let p = [0.25, 0.75];
            let ep = [q(1, 4), q(3, 4)];
            assert_eq!(
                fa.nearest_point(&p).unwrap().to_string(),
                ea.nearest_point(&ep).unwrap().to_string()
            );
            // The fixed-dimension curve gives the same as the runtime one.
            let ba = Bezier::<f64, 2>::try_from(&fa).unwrap();
            let bb = Bezier::<f64, 2>::try_from(&fb).unwrap();
            assert_eq!(ba.intersect(&bb).unwrap().to_string(), by_f64.to_string());
            assert_eq!(
                ba.bounding_box().unwrap().to_string(),
                fa.bounding_box().unwrap().to_string()
            );
            assert_eq!(
                ba.nearest_point(&p).unwrap().to_string(),
                fa.nearest_point(&p).unwrap().to_string()
            );
        }
    }

    #[test]
    fn rounded_answers_are_the_exact_ones_rounded() {
        // A rational curve that is not doubles: the filter cannot run, the exact path answers.
        let a = BezierCurve::new(vec![vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(1, 3)]]).unwrap();
        let b = BezierCurve::new(vec![vec![q(0, 1), q(1, 3)], vec![q(1, 1), q(0, 1)]]).unwrap();
        let r = a.intersect_rounded(&b).unwrap();
        assert!(!r.by_filter);
        let x = a.intersect(&b).unwrap();
        assert_eq!(r.points[0].s, x.points[0].s.to_f64());
        assert_eq!(r.points[0].point, [0.5, rational_to_f64(&q(1, 6))]);
        // Rationals that are doubles exactly take the filter, as doubles do.
        let c = BezierCurve::new(vec![vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(1, 1)]]).unwrap();
        let d = BezierCurve::new(vec![vec![q(0, 1), q(1, 1)], vec![q(1, 1), q(0, 1)]]).unwrap();
        assert!(c.intersect_rounded(&d).unwrap().by_filter);
    }
}
