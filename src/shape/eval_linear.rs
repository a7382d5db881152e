//! Evaluation of a float64 Bézier curve at many parameters in O(n) operations per point: a
//! running convex combination of the control points whose weights follow the ratios of
//! consecutive Bernstein polynomials (the recurrence of P. Woźny and F. Chudy, "Linear-time
//! geometric algorithm for evaluating Bézier curves", Computer-Aided Design 118, 2020), run
//! on blocks of parameters at once so that every step vectorises.

use crate::error::Result;
use crate::shape::bezier::BezierCurve;
use crate::shape::eval_many::check_out;

/// Parameters evaluated together (one lane each) by [`BezierCurve::eval_many_linear`].
const LANES: usize = 8;

impl BezierCurve<f64> {
    /// The curve B(t) = sum_j C(n, j) (1 - t)^(n - j) t^j w_j at every parameter of `ts`,
    /// written point after point to `out` (`ts.len() * dim` numbers, as
    /// [`BezierCurve::eval_many`]), in O(n) operations per parameter in [0, 1] instead of de
    /// Casteljau's n (n + 1) / 2.
    ///
    /// # The method
    ///
    /// With b_j = C(n, j) t^j (1 - t)^(n - j) and S_k = b_0 + ... + b_k, the weighted means
    /// q_k = (b_0 w_0 + ... + b_k w_k) / S_k satisfy q_0 = w_0, q_n = B(t) (as S_n = 1) and
    ///
    /// ```text
    /// q_k = q_(k-1) + h_k (w_k - q_(k-1)),    h_k = b_k / S_k,
    /// h_k = (n - k + 1) t h_(k-1) / (k (1 - t) + (n - k + 1) t h_(k-1)),    h_0 = 1,
    /// ```
    ///
    /// the last from b_k / b_(k-1) = (n - k + 1) t / (k (1 - t)) and S_(k-1) = b_(k-1) / h_(k-1).
    /// For t in [0, 1] every h_k lies in [0, 1], so each step is a convex combination, the
    /// step `x + h (y - x)` of de Casteljau's algorithm ([`BezierCurve::eval_into`]): n steps
    /// per coordinate and one division per parameter and step. For t > 1/2 the recurrence
    /// runs from the other end (the nodes reversed, 1 - t for t, computed exactly), so the
    /// denominators k s + ... stay at least k / 2. Parameters outside [0, 1] (and NaN) are
    /// evaluated by de Casteljau's algorithm, bit for bit [`BezierCurve::eval_into`].
    ///
    /// # Centring
    ///
    /// Each coordinate is first translated by c, its node nearest to zero when all its nodes
    /// have one sign, else 0: B(t) = c + sum_j B_j(t) (w_j - c), as the B_j sum to 1. The
    /// steps then work on the differences w_j - c, which are never larger than the w_j, and
    /// for a curve far from the origin compared to its size are much smaller; t = 0 and t = 1
    /// give w_0 and w_n themselves.
    ///
    /// # Error bound
    ///
    /// Per coordinate, with u = 2^-53 the unit roundoff, γ_k = k u / (1 - k u),
    /// M_c = max_j |w_j - c| (at most max_j |w_j|) and D = max_j w_j - min_j w_j, for t in
    /// [0, 1]:
    ///
    /// ```text
    /// |computed - B(t)| <= u |B(t)| + (n + 1) u M_c + (12 n + 2) u D + O(u^2).
    /// ```
    ///
    /// *Proof.* Let d_j = fl(w_j - c) = (w_j - c)(1 + ε_j), |ε_j| <= u: replacing w_j - c by
    /// d_j moves the convex combination sum_j B_j(t) (w_j - c) by at most u M_c. The steps run
    /// on the d_j (|d_j| <= M_c (1 + u), spread D (1 + O(u))), and the last addition c + q_n
    /// adds at most u |B(t)| (1 + O(u)).
    /// (1) Rounding in the steps. The computed step fl(q + fl(h fl(w - q))) is
    /// (q + h (w - q)) (1 + δ_3) + h (w - q) θ_2 with |δ_3| <= u, |θ_2| <= γ_2: an error at step
    /// k of at most u |q_k| + γ_2 h_k |w_k - q_(k-1)| <= u M_c + γ_2 h_k D (q_k is a convex
    /// combination of the d_j). The later steps q -> (1 - h_i) q + h_i d_i carry it multiplied
    /// by (1 - h_(k+1)) ... (1 - h_n) <= 1, and sum_k h_k prod_(i>k) (1 - h_i) =
    /// 1 - prod_(i>=1) (1 - h_i) <= 1 (a telescoping sum), so these errors total at most
    /// n u M_c + γ_2 D.
    /// (2) Rounding in the weights. The computed h̃_k = fl(fl(fl(a_k t') h̃_(k-1)) /
    /// fl(fl(k s) + ...)) (a_k = n - k + 1 exact, t' and s the two parameters of the
    /// branch, s = fl(1 - t) rounded once for t <= 1/2) is the exact map
    /// F(h) = a_k t' h / (k s + a_k t' h) of h̃_(k-1) within a relative γ_6 (two roundings in
    /// the numerator, the quotient's, the sum's, and k s with the rounding of s in the
    /// denominator). F's relative condition is h F'(h) / F(h) = 1 - h_k <= 1, so
    /// |h̃_k - h_k| <= h_k γ_6 sum_(i<=k) P(i, k) with P(i, k) = prod_(m=i+1..k) (1 - h_m).
    /// A change of h_k by e moves q_k by e (d_k - q_(k-1)), at most |e| D, carried on by
    /// factors <= 1; and sum_(k>=i) h_k P(i, k) <= h_i + 1 - P(i, n) <= 2 (telescoping again),
    /// so these errors total at most D γ_6 sum_i 2 = 12 n u D. The sum of the parts is the
    /// bound.
    ///
    /// De Casteljau's algorithm with the same step satisfies, by the argument of (1) on each
    /// of its n levels (no weights to compute), n u M + 2 n t u D + O(u^2) with
    /// M = max_j |w_j|. The two bounds have the same order, n u (M + D); the leading term of
    /// this one is the smaller for curves far from the origin compared to their size
    /// (M_c <= D there), its difference term at most about 6 times de Casteljau's.
    /// Measured against the exact values (the doubles read as rationals), over degrees 1 to
    /// 20, parameters uniform in [0, 1] and nodes uniform in [-1, 1], [0, 1] and [10, 11], the
    /// largest error of this method per degree and node set was at most 1.48 times de
    /// Casteljau's in the test `linear_error_within_twice_de_casteljau` (which asserts 2 times
    /// and prints the table) and 1.63 times in `benches/python/evaluate_multi.py --errors-only`
    /// (more samples, through Python, with bezier's beside: up to 2.08 times), mostly below 1,
    /// and 0.2 to 0.3 times for nodes in [10, 11] (BENCHMARKS.md, "Python everyday paths").
    ///
    /// ```
    /// use blossom::BezierCurve;
    /// let c = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![2.0, 0.0]])?;
    /// let ts = [0.0, 0.25, 0.5, 1.0];
    /// let mut out = vec![0.0; ts.len() * 2];
    /// c.eval_many_linear(&ts, &mut out)?;
    /// assert_eq!(out, [0.0, 0.0, 0.5, 0.75, 1.0, 1.0, 2.0, 0.0]);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::Shape`](crate::ErrorKind::Shape) on `out` when it does not hold `ts.len() * dim` numbers (nothing
    /// is written then).
    pub fn eval_many_linear(&self, ts: &[f64], out: &mut [f64]) -> Result<()> {
        let dim = self.dim();
        check_out(ts.len(), dim, out.len())?;
        let w = self.coordinates();
        let n = self.degree();
        if n == 0 {
            for point in out.chunks_exact_mut(dim) {
                point.copy_from_slice(w);
            }
            return Ok(());
        }
        // Each coordinate's centre c (its node nearest to zero when all have one sign, else
        // 0) and the nodes less c, in order and reversed.
        let centre: Vec<f64> = (0..dim)
            .map(|x| {
                let column = w.iter().skip(x).step_by(dim);
                if column.clone().all(|&v| v > 0.0) {
                    column.fold(f64::INFINITY, |m, &v| m.min(v))
                } else if column.clone().all(|&v| v < 0.0) {
                    column.fold(f64::NEG_INFINITY, |m, &v| m.max(v))
                } else {
                    0.0
                }
            })
            .collect();
        let centred: Vec<f64> = w
            .chunks_exact(dim)
            .flat_map(|p| p.iter().zip(&centre).map(|(v, c)| v - c))
            .collect();
        let reversed: Vec<f64> = centred.rchunks_exact(dim).flatten().copied().collect();
        let nodes = Nodes {
            centre: &centre,
            forward: &centred,
            reversed: &reversed,
        };
        #[cfg(target_arch = "x86_64")]
        let avx = std::arch::is_x86_feature_detected!("avx");
        #[cfg(not(target_arch = "x86_64"))]
        let avx = false;
        if avx {
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the processor has just been seen to support AVX.
            #[allow(unsafe_code)]
            unsafe {
                blocks_avx(&nodes, ts, out)
            };
        } else {
            blocks_any(&nodes, ts, out);
        }
        self.fix_ends(ts, out);
        Ok(())
    }

    /// Rewrites the points of [`BezierCurve::eval_many_linear`] at parameters not in (0, 1):
    /// the end nodes at 0 and 1, de Casteljau's algorithm elsewhere (and at NaN).
    fn fix_ends(&self, ts: &[f64], out: &mut [f64]) {
        let (w, dim) = (self.coordinates(), self.dim());
        let mut level = Vec::new();
        for (t, point) in ts.iter().zip(out.chunks_exact_mut(dim)) {
            if !(*t > 0.0 && *t < 1.0) {
                if *t == 0.0 {
                    point.copy_from_slice(&w[..dim]);
                } else if *t == 1.0 {
                    point.copy_from_slice(&w[w.len() - dim..]);
                } else {
                    self.eval_into(t, point, &mut level);
                }
            }
        }
    }
}

/// The translated control points of [`BezierCurve::eval_many_linear`]: each coordinate's
/// centre, and the nodes less their centres in order and reversed (point after point).
struct Nodes<'a> {
    centre: &'a [f64],
    forward: &'a [f64],
    reversed: &'a [f64],
}

/// [`blocks_any`] compiled for AVX (4 lanes an instruction, the same operations, so the same
/// doubles); callers make sure that the processor has it.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn blocks_avx(nodes: &Nodes<'_>, ts: &[f64], out: &mut [f64]) {
    blocks_any(nodes, ts, out);
}

/// [`blocks`] with the dimension fixed at compile time for 1, 2 and 3.
#[inline(always)]
fn blocks_any(nodes: &Nodes<'_>, ts: &[f64], out: &mut [f64]) {
    match nodes.centre.len() {
        1 => blocks::<1>(nodes, ts, out),
        2 => blocks::<2>(nodes, ts, out),
        3 => blocks::<3>(nodes, ts, out),
        _ => blocks::<0>(nodes, ts, out),
    }
}

/// The recurrence at every parameter of `ts`, [`LANES`] consecutive parameters at a time
/// (a short last block padded with 1/2), written point after point to `out`; each lane runs
/// from the end nearer to its parameter (the nodes in order and t' = t for t <= 1/2, reversed
/// and t' = 1 - t above), the choice made per lane by masks, without branches. Parameters
/// not in (0, 1) get numbers that [`BezierCurve::fix_ends`] then replaces. `D` is the
/// dimension when it is known at compile time, else 0.
#[inline(always)]
fn blocks<const D: usize>(nodes: &Nodes<'_>, ts: &[f64], out: &mut [f64]) {
    let dim = if D == 0 { nodes.centre.len() } else { D };
    let n = nodes.forward.len() / dim - 1;
    let mut q = vec![[0.0; LANES]; dim];
    let mut last = vec![0.0; LANES * dim];
    for (t_block, out_block) in ts.chunks(LANES).zip(out.chunks_mut(LANES * dim)) {
        let t: [f64; LANES] = std::array::from_fn(|l| t_block.get(l).copied().unwrap_or(0.5));
        // Each lane's direction as a mask of bits, t' and s = 1 - t'.
        let mut reverse = [0u64; LANES];
        let (mut tp, mut s) = ([0.0; LANES], [0.0; LANES]);
        for l in 0..LANES {
            let high = t[l] > 0.5;
            reverse[l] = if high { u64::MAX } else { 0 };
            (tp[l], s[l]) = if high {
                (1.0 - t[l], t[l])
            } else {
                (t[l], 1.0 - t[l])
            };
        }
        let pick = |f: f64, r: f64, mask: u64| {
            f64::from_bits((f.to_bits() & !mask) | (r.to_bits() & mask))
        };
        for (x, qx) in q.iter_mut().enumerate() {
            let (f, r) = (nodes.forward[x], nodes.reversed[x]);
            for l in 0..LANES {
                qx[l] = pick(f, r, reverse[l]);
            }
        }
        let mut h = [1.0f64; LANES];
        for k in 1..=n {
            let a = (n - k + 1) as f64;
            let b = k as f64;
            for l in 0..LANES {
                let num = a * tp[l] * h[l];
                h[l] = num / (b * s[l] + num);
            }
            let forward = &nodes.forward[k * dim..(k + 1) * dim];
            let reversed = &nodes.reversed[k * dim..(k + 1) * dim];
            for ((qx, &f), &r) in q.iter_mut().zip(forward).zip(reversed) {
                for l in 0..LANES {
                    let y = pick(f, r, reverse[l]);
                    qx[l] += h[l] * (y - qx[l]);
                }
            }
        }
        let whole = out_block.len() == LANES * dim;
        let target = if whole {
            &mut *out_block
        } else {
            &mut last[..]
        };
        for (x, (qx, &c)) in q.iter().zip(nodes.centre).enumerate() {
            for (l, &v) in qx.iter().enumerate() {
                target[l * dim + x] = c + v;
            }
        }
        if !whole {
            let len = out_block.len();
            out_block.copy_from_slice(&last[..len]);
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::test_rng::XorShift;
    use crate::{rational_to_f64, BezierCurve, Rational};
    use num_bigint::BigInt;
    use num_traits::{Signed, Zero};

    fn uniform(rng: &mut XorShift, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((rng.next() >> 11) as f64 / (1u64 << 53) as f64)
    }

    /// B(t) exactly, for one coordinate: sum_j C(n, j) t^j (1 - t)^(n - j) w_j in integers
    /// (t = p / 2^e, every w_j = m_j 2^f with one f), then one division.
    fn exact(w: &[f64], t: f64) -> Rational {
        let n = w.len() - 1;
        let t = Rational::from_float(t).expect("finite");
        let (p, q) = (t.numer().clone(), t.denom().clone());
        let r = q.clone() - &p;
        let ws: Vec<Rational> = w
            .iter()
            .map(|&x| Rational::from_float(x).unwrap())
            .collect();
        let den = ws.iter().fold(BigInt::from(1), |d, x| {
            num_integer::Integer::lcm(&d, x.denom())
        });
        let mut sum = BigInt::zero();
        let mut binom = BigInt::from(1);
        for (j, x) in ws.iter().enumerate() {
            let m = x.numer() * (&den / x.denom());
            sum += &binom * num_traits::pow(p.clone(), j) * num_traits::pow(r.clone(), n - j) * m;
            binom = binom * BigInt::from(n - j) / BigInt::from(j + 1);
        }
        Rational::new(sum, den * num_traits::pow(q, n))
    }

    fn error(x: f64, e: &Rational) -> f64 {
        rational_to_f64(&(Rational::from_float(x).unwrap() - e).abs())
    }

    /// The issue-47 criterion: over degrees 1..=20, node sets uniform in [-1, 1], [0, 1] and
    /// [10, 11], parameters uniform in [0, 1] (and 0, 1/2, 1), the largest absolute error of
    /// `eval_many_linear` is at most twice that of de Casteljau's `eval_many`, per degree and
    /// set. Prints the table (`cargo test --lib eval_linear -- --nocapture`).
    #[test]
    fn linear_error_within_twice_de_casteljau() {
        let mut rng = XorShift(0x5EED_0047);
        let mut worst_ratio: f64 = 0.0;
        for (lo, hi) in [(-1.0, 1.0), (0.0, 1.0), (10.0, 11.0)] {
            eprintln!("nodes in [{lo}, {hi}]: degree, de Casteljau, linear, ratio");
            for n in 1..=20 {
                let (mut dc, mut lin) = (0.0f64, 0.0f64);
                for _ in 0..12 {
                    let w: Vec<f64> = (0..=n).map(|_| uniform(&mut rng, lo, hi)).collect();
                    let c = BezierCurve::new(w.iter().map(|&x| vec![x]).collect()).unwrap();
                    let mut ts: Vec<f64> = (0..60).map(|_| uniform(&mut rng, 0.0, 1.0)).collect();
                    ts.extend([0.0, 0.5, 1.0]);
                    let (mut a, mut b) = (vec![0.0; ts.len()], vec![0.0; ts.len()]);
                    c.eval_many(&ts, &mut a).unwrap();
                    c.eval_many_linear(&ts, &mut b).unwrap();
                    for ((t, x), y) in ts.iter().zip(&a).zip(&b) {
                        let e = exact(&w, *t);
                        dc = dc.max(error(*x, &e));
                        lin = lin.max(error(*y, &e));
                    }
                }
                eprintln!("{n:3} {dc:10.3e} {lin:10.3e} {:6.2}", lin / dc);
                worst_ratio = worst_ratio.max(lin / dc);
                assert!(
                    lin <= 2.0 * dc,
                    "degree {n}, nodes in [{lo}, {hi}]: {lin:e} against de Casteljau's {dc:e}"
                );
            }
        }
        eprintln!("largest ratio {worst_ratio:.2}");
    }

    #[test]
    fn ends_outside_and_shapes() {
        let pts: Vec<Vec<f64>> = (0..7)
            .map(|j| {
                vec![
                    j as f64 * 0.3 - 1.0,
                    1.0 / (j as f64 + 1.5),
                    3.0e-20 * j as f64,
                ]
            })
            .collect();
        let c = BezierCurve::new(pts.clone()).unwrap();
        // Ends exact; outside [0, 1] and NaN by de Casteljau bit for bit; 19 parameters
        // (a short block in each branch).
        let mut ts = vec![0.0, 1.0, -0.5, 1.5, f64::NAN, 0.5];
        ts.extend((0..13).map(|m| m as f64 / 12.0));
        let mut out = vec![0.0; ts.len() * 3];
        c.eval_many_linear(&ts, &mut out).unwrap();
        assert_eq!(&out[0..3], pts[0].as_slice());
        assert_eq!(&out[3..6], pts[6].as_slice());
        let mut one = vec![0.0; 3];
        let mut level = Vec::new();
        for m in 2..5 {
            c.eval_into(&ts[m], &mut one, &mut level);
            for x in 0..3 {
                assert_eq!(out[m * 3 + x].to_bits(), one[x].to_bits());
            }
        }
        for (m, t) in ts.iter().enumerate().skip(5) {
            c.eval_into(t, &mut one, &mut level);
            for x in 0..3 {
                assert!((out[m * 3 + x] - one[x]).abs() <= 1e-15, "t = {t}");
            }
        }
        // A point and a constant curve.
        let p = BezierCurve::new(vec![vec![2.5, -1.0]]).unwrap();
        let mut o = vec![0.0; 4];
        p.eval_many_linear(&[0.3, 7.0], &mut o).unwrap();
        assert_eq!(o, [2.5, -1.0, 2.5, -1.0]);
        let k = BezierCurve::new(vec![vec![0.1]; 9]).unwrap();
        let ts: Vec<f64> = (0..=20).map(|m| m as f64 / 20.0).collect();
        let mut o = vec![0.0; ts.len()];
        k.eval_many_linear(&ts, &mut o).unwrap();
        assert!(o.iter().all(|&x| x == 0.1));
        assert_eq!(
            c.eval_many_linear(&[0.5], &mut [0.0; 2])
                .unwrap_err()
                .path(),
            "out"
        );
        c.eval_many_linear(&[], &mut []).unwrap();
    }
}
