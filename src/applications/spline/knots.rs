//! Validated knot vectors (Definition 1.1 of seed 002).
//!
//! A B-spline of degree p with m de Boor points lives on a knot vector T = (t_1, ..., t_{m+p+1})
//! with t_i <= t_{i+1} and t_i < t_{i+p+1} (no knot of multiplicity above p + 1); its domain is
//! [t_{p+1}, t_{m+1}], which must be non-empty, and p + 1 <= m (Theorem 2.3, ii).
//!
//! The code indexes from 0: knot `knots[i]` is the paper's t_{i+1} and de Boor point `d[k]`
//! is d_{k+1}. Every formula of the paper keeps its shape under this shift (for instance
//! d_k = f_j(t_{k+1}, ..., t_{k+p}) for k = j - p..=j, Theorem 2.2).

use crate::error::{Error, ErrorKind, Result};
use crate::num::limits::check_entries;
use crate::num::linalg::{check_all_finite, check_finite, Field};

/// A knot vector checked for a given degree.
#[derive(Clone, Debug, PartialEq)]
pub struct KnotVector<T> {
    degree: usize,
    knots: Vec<T>,
}

impl<T: Field> KnotVector<T> {
    /// Checks `knots` for degree `degree`: at least 2p + 2 knots (so m >= p + 1),
    /// non-decreasing, every multiplicity at most p + 1, and a non-empty domain.
    ///
    /// # Errors
    /// [`ErrorKind::TooLarge`] on `degree` when 2p + 2 overflows or exceeds
    /// [`MAX_ENTRIES`](crate::MAX_ENTRIES); [`ErrorKind::Shape`] on `knots` when there are
    /// fewer than 2p + 2; [`ErrorKind::NotFinite`] on `knots[i]` for a NaN or an infinity (the
    /// order of the knots decides every span search); [`ErrorKind::Domain`] on `knots[i]` or
    /// `knots` when they decrease, repeat more than p + 1 times or leave an empty domain.
    ///
    /// ```
    /// use blossom::KnotVector;
    /// assert!(KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]).is_ok());
    /// let e = KnotVector::new(1, vec![0.0, 2.0, 1.0, 3.0]).unwrap_err();
    /// assert_eq!(e.to_string(), "knots[2]: knots must be non-decreasing, found 1 after 2");
    /// ```
    pub fn new(degree: usize, knots: Vec<T>) -> Result<Self> {
        let p = degree;
        let least = check_entries(
            p.checked_mul(2).and_then(|k| k.checked_add(2)),
            "degree",
            "the number of knots 2p + 2",
        )?;
        if knots.len() < least {
            return Err(Error::of(ErrorKind::Shape,
                "knots",
                format!(
                    "a B-spline of degree {p} needs at least {least} knots (p + 1 <= m de Boor points), found {}",
                    knots.len()
                ),
            ));
        }
        check_all_finite(&knots, "knots")?;
        for i in 1..knots.len() {
            if knots[i] < knots[i - 1] {
                return Err(Error::of(
                    ErrorKind::Domain,
                    format!("knots[{i}]"),
                    format!(
                        "knots must be non-decreasing, found {} after {}",
                        knots[i],
                        knots[i - 1]
                    ),
                ));
            }
        }
        for i in 0..knots.len() - p - 1 {
            if knots[i] == knots[i + p + 1] {
                return Err(Error::of(
                    ErrorKind::Domain,
                    format!("knots[{}]", i + p + 1),
                    format!(
                        "the knot {} has multiplicity above p + 1 = {} (t_i < t_(i+p+1) fails)",
                        knots[i],
                        p + 1
                    ),
                ));
            }
        }
        let m = knots.len() - p - 1;
        if knots[p] == knots[m] {
            return Err(Error::of(
                ErrorKind::Domain,
                "knots",
                format!(
                    "the domain [t_{}, t_{}] = [{}, {}] is empty",
                    p + 1,
                    m + 1,
                    knots[p],
                    knots[m]
                ),
            ));
        }
        Ok(KnotVector { degree, knots })
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots t_1..t_{m+p+1} (0-based).
    pub fn knots(&self) -> &[T] {
        &self.knots
    }

    /// The number m of de Boor points: len - p - 1.
    pub fn control_count(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The domain [t_{p+1}, t_{m+1}].
    pub fn domain(&self) -> (&T, &T) {
        (&self.knots[self.degree], &self.knots[self.control_count()])
    }

    /// The 0-based indices s of the non-empty spans `[knots[s], knots[s+1])` in the domain.
    pub fn spans(&self) -> Vec<usize> {
        (self.degree..self.control_count())
            .filter(|&s| self.knots[s] < self.knots[s + 1])
            .collect()
    }

    /// Whether `s` is a non-empty span of the domain.
    pub fn is_span(&self, s: usize) -> bool {
        s >= self.degree && s < self.control_count() && self.knots[s] < self.knots[s + 1]
    }

    /// The span s with `knots[s] <= t < knots[s+1]` (the last non-empty span at the right end of
    /// the domain).
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `t` for a NaN or an infinity, [`ErrorKind::Domain`] on `t`
    /// when t is outside the domain.
    pub fn span(&self, t: &T) -> Result<usize> {
        check_finite(t, "t")?;
        let (a, b) = self.domain();
        if t < a || t > b {
            return Err(Error::of(
                ErrorKind::Domain,
                "t",
                format!("the parameter {t} is outside the domain [{a}, {b}] of the knot vector"),
            ));
        }
        Ok(self
            .spans()
            .into_iter()
            .rev()
            .find(|&s| self.knots[s] <= *t)
            .expect("a parameter in the domain lies in a span"))
    }

    /// How many knots equal `x`.
    pub fn multiplicity(&self, x: &T) -> usize {
        self.knots.iter().filter(|k| *k == x).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_names_the_knot() {
        let e = KnotVector::new(3, vec![0.0; 7]).unwrap_err();
        assert_eq!(e.field, "knots");
        let e = KnotVector::new(1, vec![0.0, 0.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "knots[2]: the knot 0 has multiplicity above p + 1 = 2 (t_i < t_(i+p+1) fails)"
        );
        let e = KnotVector::new(1, vec![0.0, 1.0, 1.0, 2.0]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "knots: the domain [t_2, t_3] = [1, 1] is empty"
        );
    }

    #[test]
    fn spans_and_parameters() {
        let k = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 3.0, 3.0, 3.0]).unwrap();
        assert_eq!(k.spans(), vec![2, 4]);
        assert_eq!(k.span(&0.0).unwrap(), 2);
        assert_eq!(k.span(&1.0).unwrap(), 4);
        assert_eq!(k.span(&3.0).unwrap(), 4);
        assert_eq!(k.span(&3.5).unwrap_err().field, "t");
        assert_eq!(k.multiplicity(&1.0), 2);
    }
}
