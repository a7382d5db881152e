//! `Display` for the certified answers: every number as its correctly rounded double, and
//! exactly where that is short.
//!
//! An [`AlgebraicReal`] prints as its exact value when it is rational (`1/2`, `-3`, `0`), and
//! otherwise as its correctly rounded double followed by what defines it exactly: the
//! square-free integer polynomial it is a root of and the isolating interval
//! (`0.17267316464601143 (root of 7x^2 - 7x + 1 in [0, 1/2])`). The alternate form `{:#}`,
//! or a precision (`{:.3}`), prints the double alone, formatted as `f64` formats it. The
//! records (points, overlaps, zeros, extremes) print their numbers the same way, passing the
//! flags on.

use super::algebraic::AlgebraicReal;
use super::curves::{IntersectionPoint, Intersections, Overlap};
use super::extrema::{Extreme, NearestPoint, TightBox};
use super::filter::CertifiedCrossing;
use super::rounded::{RoundedIntersections, RoundedOverlap, RoundedPoint};
use super::zeros::{BezierZeros, PolynomialZero};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::fmt::{self, Display, Formatter};

/// Whether the formatter asks for doubles only (`{:#}` or a precision).
fn doubles_only(f: &Formatter<'_>) -> bool {
    f.alternate() || f.precision().is_some()
}

/// A double with the formatter's precision, if any.
fn double(f: &mut Formatter<'_>, x: f64) -> fmt::Result {
    match f.precision() {
        Some(p) => write!(f, "{x:.p$}"),
        None => write!(f, "{x}"),
    }
}

/// An algebraic number with the formatter's flags passed on.
fn number(f: &mut Formatter<'_>, x: &AlgebraicReal) -> fmt::Result {
    match (f.alternate(), f.precision()) {
        (_, Some(p)) => write!(f, "{x:.p$}"),
        (true, None) => write!(f, "{x:#}"),
        (false, None) => write!(f, "{x}"),
    }
}

/// An integer polynomial, ascending coefficients, written in x with descending powers and
/// a positive leading coefficient (a root's polynomial is defined up to sign):
/// `7x^2 - 7x + 1`.
fn polynomial(f: &mut Formatter<'_>, p: &[BigInt]) -> fmt::Result {
    let negate = p
        .iter()
        .rev()
        .find(|c| !c.is_zero())
        .is_some_and(Signed::is_negative);
    let mut first = true;
    for (k, c) in p.iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let c = if negate { -c } else { c.clone() };
        let sign = if c.is_negative() { "-" } else { "+" };
        match (first, sign) {
            (true, "-") => f.write_str("-")?,
            (true, _) => {}
            (false, s) => write!(f, " {s} ")?,
        }
        first = false;
        let magnitude = c.abs();
        if k == 0 || !magnitude.is_one() {
            write!(f, "{magnitude}")?;
        }
        match k {
            0 => {}
            1 => f.write_str("x")?,
            _ => write!(f, "x^{k}")?,
        }
    }
    if first {
        f.write_str("0")?;
    }
    Ok(())
}

/// `1/2` for a rational number; `0.17267316464601143 (root of 7x^2 - 7x + 1 in [0, 1/2])`
/// for an irrational one; the double alone with `{:#}` or a precision (a precision formats
/// that double).
///
/// ```
/// use blossom::{bezier_zeros, AlgebraicReal, Rational};
/// let half = AlgebraicReal::from_rational(Rational::new(1.into(), 2.into()));
/// assert_eq!(half.to_string(), "1/2");
/// assert_eq!(format!("{half:#}"), "0.5");
/// // 7t^2 - 7t + 1 has the Bernstein coefficients 1, -5/2, 1 over [0, 1].
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let roots = bezier_zeros(&[q(1, 1), q(-5, 2), q(1, 1)])?;
/// let text = roots.zeros[0].t.to_string();
/// assert!(text.starts_with("0.17267316464601143 (root of 7x^2 - 7x + 1 in ["), "{text}");
/// assert_eq!(format!("{:.3}", roots.zeros[0].t), "0.173");
/// # Ok::<(), blossom::Error>(())
/// ```
impl Display for AlgebraicReal {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        if doubles_only(f) {
            return double(f, self.to_f64());
        }
        if let Some(r) = self.exact() {
            return write!(f, "{r}");
        }
        write!(f, "{} (root of ", self.to_f64())?;
        polynomial(f, self.polynomial())?;
        let (lo, hi) = self.interval();
        write!(f, " in [{lo}, {hi}])")
    }
}

/// `s = 1/2, t = 1/2, point = (0.5, 0.5)`, then `, tangent` for a tangency; the flags pass
/// to the parameters.
impl Display for IntersectionPoint {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str("s = ")?;
        number(f, &self.s)?;
        f.write_str(", t = ")?;
        number(f, &self.t)?;
        write!(f, ", point = ({}, {})", self.point[0], self.point[1])?;
        if self.tangent {
            f.write_str(", tangent")?;
        }
        Ok(())
    }
}

/// `s = [0, 1/2], t = [1, 1/2]`: the matching ends on both curves.
impl Display for Overlap {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str("s = [")?;
        number(f, &self.s[0])?;
        f.write_str(", ")?;
        number(f, &self.s[1])?;
        f.write_str("], t = [")?;
        number(f, &self.t[0])?;
        f.write_str(", ")?;
        number(f, &self.t[1])?;
        f.write_str("]")
    }
}

/// One line per point, then one per overlap (`overlap: ...`); `no intersection` when empty.
impl Display for Intersections {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        if self.points.is_empty() && self.overlaps.is_empty() {
            return f.write_str("no intersection");
        }
        let mut first = true;
        for p in &self.points {
            if !first {
                f.write_str("\n")?;
            }
            first = false;
            p.fmt(f)?;
        }
        for o in &self.overlaps {
            if !first {
                f.write_str("\n")?;
            }
            first = false;
            f.write_str("overlap: ")?;
            o.fmt(f)?;
        }
        Ok(())
    }
}

/// `s = 0.5, t = 0.5, point = (0.5, 0.5)`, then `, tangent` for a tangency.
impl Display for RoundedPoint {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "s = {}, t = {}, point = ({}, {})",
            self.s, self.t, self.point[0], self.point[1]
        )?;
        if self.tangent {
            f.write_str(", tangent")?;
        }
        Ok(())
    }
}

/// `s = [0, 0.5], t = [1, 0.5]`.
impl Display for RoundedOverlap {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "s = [{}, {}], t = [{}, {}]",
            self.s[0], self.s[1], self.t[0], self.t[1]
        )
    }
}

/// One line per point, then one per overlap (`overlap: ...`); `no intersection` when empty.
impl Display for RoundedIntersections {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let lines: Vec<String> = self
            .points
            .iter()
            .map(ToString::to_string)
            .chain(self.overlaps.iter().map(|o| format!("overlap: {o}")))
            .collect();
        if lines.is_empty() {
            return f.write_str("no intersection");
        }
        f.write_str(&lines.join("\n"))
    }
}

/// `s = 0.5, t = 0.5, point = (0.5, 0.5)` (the correctly rounded parameters).
impl Display for CertifiedCrossing {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "s = {}, t = {}, point = ({}, {})",
            self.s, self.t, self.point[0], self.point[1]
        )
    }
}

/// `t = 1/2, multiplicity 2`.
impl Display for PolynomialZero {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str("t = ")?;
        number(f, &self.t)?;
        write!(f, ", multiplicity {}", self.multiplicity)
    }
}

/// One line per zero; `identically zero` or `no zero in [0, 1]`.
impl Display for BezierZeros {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        if self.identically_zero {
            return f.write_str("identically zero");
        }
        if self.zeros.is_empty() {
            return f.write_str("no zero in [0, 1]");
        }
        for (k, z) in self.zeros.iter().enumerate() {
            if k > 0 {
                f.write_str("\n")?;
            }
            z.fmt(f)?;
        }
        Ok(())
    }
}

/// `1 at t = 1/2` (every parameter attaining the value), or `1 everywhere`.
impl Display for Extreme {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        number(f, &self.value)?;
        if self.everywhere {
            return f.write_str(" everywhere");
        }
        f.write_str(" at t = ")?;
        for (k, t) in self.at.iter().enumerate() {
            if k > 0 {
                f.write_str(", ")?;
            }
            number(f, t)?;
        }
        Ok(())
    }
}

/// One line per coordinate: `x0: min 0 at t = 0, max 2 at t = 1`.
impl Display for TightBox {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        for (j, (lo, hi)) in self.min.iter().zip(&self.max).enumerate() {
            if j > 0 {
                f.write_str("\n")?;
            }
            write!(f, "x{j}: min ")?;
            lo.fmt(f)?;
            f.write_str(", max ")?;
            hi.fmt(f)?;
        }
        Ok(())
    }
}

/// `squared distance 9 at t = 1/4, point (1, 0)`, one point per nearest parameter.
impl Display for NearestPoint {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str("squared distance ")?;
        number(f, &self.squared_distance)?;
        if self.everywhere {
            return f.write_str(" everywhere");
        }
        for (k, (t, p)) in self.at.iter().zip(&self.points).enumerate() {
            f.write_str(if k == 0 { " at t = " } else { "; t = " })?;
            number(f, t)?;
            f.write_str(", point (")?;
            for (j, x) in p.iter().enumerate() {
                if j > 0 {
                    f.write_str(", ")?;
                }
                // Each coordinate as its correctly rounded double (exact when rational).
                match x.exact() {
                    Some(r) if !doubles_only(f) => write!(f, "{r}")?,
                    _ => double(f, x.to_f64())?,
                }
            }
            f.write_str(")")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::ring::Rational;
    use crate::{bezier_zeros, intersect_curves, Bezier};

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    /// The polynomial text for ascending integer coefficients.
    fn poly_text(p: &[i64]) -> String {
        struct P(Vec<BigInt>);
        impl Display for P {
            fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
                polynomial(f, &self.0)
            }
        }
        P(p.iter().map(|&c| c.into()).collect()).to_string()
    }

    #[test]
    fn polynomials_read_as_written_by_hand() {
        assert_eq!(poly_text(&[1, -7, 7]), "7x^2 - 7x + 1");
        assert_eq!(poly_text(&[-1, 7, -7]), "7x^2 - 7x + 1");
        assert_eq!(poly_text(&[-2, 0, 1]), "x^2 - 2");
        assert_eq!(poly_text(&[0, -1, 0, 3]), "3x^3 - x");
        assert_eq!(poly_text(&[5]), "5");
        assert_eq!(poly_text(&[]), "0");
    }

    #[test]
    fn rationals_print_exactly_and_irrationals_with_their_definition() {
        let third = AlgebraicReal::from_rational(q(-1, 3));
        assert_eq!(third.to_string(), "-1/3");
        assert_eq!(format!("{third:#}"), (-1.0f64 / 3.0).to_string());
        assert_eq!(format!("{third:.2}"), "-0.33");
        assert_eq!(AlgebraicReal::from_rational(q(4, 2)).to_string(), "2");
        // sqrt(2) / 2, the zero of 2t^2 - 1: Bernstein coefficients -1, -1, 1.
        let z = bezier_zeros(&[q(-1, 1), q(-1, 1), q(1, 1)]).unwrap();
        let root = &z.zeros[0].t;
        let text = root.to_string();
        let (lo, hi) = root.interval();
        assert_eq!(
            text,
            format!("{} (root of 2x^2 - 1 in [{lo}, {hi}])", 0.5f64.sqrt())
        );
        // The printed double is the correctly rounded one, however the interval is.
        assert_eq!(text.split(' ').next().unwrap(), root.to_f64().to_string());
        assert_eq!(z.to_string(), format!("t = {text}, multiplicity 1"));
        assert_eq!(
            format!("{:#}", z.zeros[0]),
            format!("t = {}, multiplicity 1", 0.5f64.sqrt())
        );
    }

    #[test]
    fn records_print_one_line_each() {
        let p = [[q(0, 1), q(0, 1)], [q(1, 1), q(1, 1)]];
        let r = [[q(0, 1), q(1, 1)], [q(1, 1), q(0, 1)]];
        let x = intersect_curves(&p, &r).unwrap();
        assert_eq!(x.to_string(), "s = 1/2, t = 1/2, point = (0.5, 0.5)");
        // Two copies of one line overlap: one overlap, no point.
        let x = intersect_curves(&p, &p).unwrap();
        assert_eq!(x.to_string(), "overlap: s = [0, 1], t = [0, 1]");
        let disjoint = [[q(5, 1), q(5, 1)], [q(6, 1), q(5, 1)]];
        assert_eq!(
            intersect_curves(&p, &disjoint).unwrap().to_string(),
            "no intersection"
        );
        let a = Bezier::new(vec![[0.0, 0.0], [1.0, 1.0]]).unwrap();
        let b = Bezier::new(vec![[1.0, 1.0], [2.0, 0.0]]).unwrap();
        assert_eq!(
            a.intersect_rounded(&b).unwrap().to_string(),
            "s = 1, t = 0, point = (1, 1)"
        );
        // A tangency is flagged: y = x^2-like arch touching y = 1/2 at its top.
        let arch = Bezier::new(vec![[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]]).unwrap();
        let top = Bezier::new(vec![[0.0, 0.5], [1.0, 0.5]]).unwrap();
        assert_eq!(
            arch.intersect(&top).unwrap().to_string(),
            "s = 1/2, t = 1/2, point = (0.5, 0.5), tangent"
        );
        let constant = bezier_zeros(&[q(0, 1), q(0, 1)]).unwrap();
        assert_eq!(constant.to_string(), "identically zero");
        assert_eq!(
            bezier_zeros(&[q(1, 1)]).unwrap().to_string(),
            "no zero in [0, 1]"
        );
    }

    #[test]
    fn boxes_and_nearest_points() {
        let arch = Bezier::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]).unwrap();
        assert_eq!(
            arch.bounding_box().unwrap().to_string(),
            "x0: min 0 at t = 0, max 2 at t = 1\nx1: min 0 at t = 0, 1, max 1 at t = 1/2"
        );
        let line = Bezier::new(vec![[0.0, 0.0], [4.0, 0.0]]).unwrap();
        assert_eq!(
            line.nearest_point(&[1.0, 3.0]).unwrap().to_string(),
            "squared distance 9 at t = 1/4, point (1, 0)"
        );
    }
}
