//! Evaluation of a Bézier curve at many parameters: de Casteljau's algorithm run on blocks
//! of [`EVAL_LANES`] parameters at once, so that every affine step x + t (y - x) is one
//! straight loop over the lanes, which the compiler vectorises for the hardware floats.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::BezierCurve;
use crate::Ring;

/// That `out` holds one point of dimension `dim` per parameter (`count` of them): the shape
/// check of every evaluation at many parameters.
pub(crate) fn check_out(count: usize, dim: usize, out: usize) -> Result<()> {
    if count.checked_mul(dim) == Some(out) {
        return Ok(());
    }
    Err(Error::of(
        ErrorKind::Shape,
        "out",
        format!(
            "expected {} numbers ({count} parameters of dimension {dim}), found {out}",
            count.saturating_mul(dim),
        ),
    ))
}

/// Parameters evaluated together by [`BezierCurve::eval_many`].
pub(crate) const EVAL_LANES: usize = 8;

impl<T: Ring> BezierCurve<T> {
    /// The curve B(t) = sum_j C(n, j) (1 - t)^(n - j) t^j w_j at every parameter of `ts`,
    /// written point after point to `out` (`ts.len() * dim` numbers: B(`ts[m]`) is
    /// `out[m * dim..(m + 1) * dim]`).
    ///
    /// The method is de Casteljau's: n levels of the affine step x + t (y - x), the step of
    /// [`BezierCurve::eval_into`] in the same order, run on 8 parameters at a
    /// time (one working copy of the control points per lane, so each step is a loop over the
    /// lanes that vectorises for `f64` and `f32`). Every answer is therefore **bit for bit**
    /// that of [`BezierCurve::eval_into`] at the same parameter (exact for `Rational`); only
    /// the speed differs. Work: n (n + 1) / 2 steps per parameter and coordinate; memory:
    /// 8 copies of the control points.
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// let ts = [0.0, 0.25, 0.5, 1.0];
    /// let mut out = vec![0.0; ts.len() * 2];
    /// c.eval_many(&ts, &mut out)?;
    /// assert_eq!(&out[4..6], &[1.0, 1.0]);
    /// assert_eq!(&out[2..4], c.eval(&0.25).as_slice());
    /// // `out` must hold one point per parameter.
    /// assert_eq!(c.eval_many(&ts, &mut [0.0; 3]).unwrap_err().path(), "out");
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Shape`] on `out` when it does not hold `ts.len() * dim` numbers (nothing
    /// is written then).
    pub fn eval_many(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        let dim = self.dim();
        check_out(ts.len(), dim, out.len())?;
        let points = self.coordinates();
        let count = points.len() / dim;
        let mut level: Vec<[T; EVAL_LANES]> = points
            .iter()
            .map(|v| std::array::from_fn(|_| v.clone()))
            .collect();
        for (t_block, out_block) in ts.chunks(EVAL_LANES).zip(out.chunks_mut(EVAL_LANES * dim)) {
            // A short last block repeats its first parameter in the unused lanes.
            let t: [T; EVAL_LANES] =
                std::array::from_fn(|l| t_block.get(l).unwrap_or(&t_block[0]).clone());
            for (lane, v) in level.iter_mut().zip(points) {
                *lane = std::array::from_fn(|_| v.clone());
            }
            for r in 1..count {
                for j in 0..(count - r) * dim {
                    let (left, right) = level.split_at_mut(j + dim);
                    let (x, y) = (&mut left[j], &right[0]);
                    for l in 0..EVAL_LANES {
                        x[l] = x[l].add(&t[l].mul(&y[l].sub(&x[l])));
                    }
                }
            }
            for (m, point) in out_block.chunks_exact_mut(dim).enumerate() {
                for (x, value) in point.iter_mut().enumerate() {
                    *value = level[x][m].clone();
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::{BezierCurve, Rational};

    /// B(t) in the Bernstein form, summed term by term in exact rationals: independent of
    /// de Casteljau's steps.
    fn bernstein(points: &[Vec<Rational>], t: &Rational) -> Vec<Rational> {
        let n = points.len() - 1;
        let mut out = vec![Rational::from_integer(0.into()); points[0].len()];
        let one = Rational::from_integer(1.into());
        for (j, w) in points.iter().enumerate() {
            let mut c = Rational::from_integer(1.into());
            for k in 0..j {
                c = c * Rational::from_integer(((n - k) as i64).into())
                    / Rational::from_integer(((k + 1) as i64).into());
            }
            let basis = c
                * num_traits::Pow::pow(t, j as u32)
                * num_traits::Pow::pow(&(one.clone() - t), (n - j) as u32);
            for (o, x) in out.iter_mut().zip(w) {
                *o = o.clone() + basis.clone() * x;
            }
        }
        out
    }

    #[test]
    fn f64_is_bitwise_eval_into_and_rational_is_exact() {
        // Degree 5 in 3-D, 19 parameters: two full blocks and a short one.
        let pts: Vec<Vec<f64>> = (0..6)
            .map(|j| {
                vec![
                    j as f64 * 0.3 - 1.0,
                    (j * j) as f64 / 7.0,
                    1.0 / (j as f64 + 1.5),
                ]
            })
            .collect();
        let c = BezierCurve::new(pts.clone()).unwrap();
        let ts: Vec<f64> = (0..19).map(|m| m as f64 / 17.0 - 0.05).collect();
        let mut out = vec![0.0; ts.len() * 3];
        c.eval_many(&ts, &mut out).unwrap();
        let mut one = vec![0.0; 3];
        let mut level = Vec::new();
        for (m, t) in ts.iter().enumerate() {
            c.eval_into(t, &mut one, &mut level);
            for x in 0..3 {
                assert_eq!(
                    out[m * 3 + x].to_bits(),
                    one[x].to_bits(),
                    "t = {t}, x = {x}"
                );
            }
        }
        let exact: Vec<Vec<Rational>> = pts
            .iter()
            .map(|p| {
                p.iter()
                    .map(|&x| Rational::from_float(x).unwrap())
                    .collect()
            })
            .collect();
        let ce = BezierCurve::new(exact.clone()).unwrap();
        let tq: Vec<Rational> = (0..11)
            .map(|m| Rational::new((m as i64 - 1).into(), 9.into()))
            .collect();
        let mut outq = vec![Rational::from_integer(0.into()); tq.len() * 3];
        ce.eval_many(&tq, &mut outq).unwrap();
        for (m, t) in tq.iter().enumerate() {
            assert_eq!(&outq[m * 3..m * 3 + 3], bernstein(&exact, t).as_slice());
        }
    }

    #[test]
    fn empty_parameters_and_wrong_out() {
        let c = BezierCurve::new(vec![vec![1.0], vec![2.0]]).unwrap();
        c.eval_many(&[], &mut []).unwrap();
        let e = c.eval_many(&[0.5], &mut [0.0, 0.0]).unwrap_err();
        assert_eq!(e.path(), "out");
    }
}
