//! The float filter of curve-curve intersection: the common transversal case of two 2-D
//! Bézier curves with `f64` control points, certified in floating point, no big numbers.
//!
//! The problem is F(s, t) = P(s) - Q(t) = 0 on [0, 1]^2. The filter answers only when it has
//! *proved* the complete answer; otherwise it says `None` and the exact path
//! ([`super::curves::intersect_curves_f64`]) answers. What it proves:
//!
//! **1. Every root lies in a surviving cell (rigorous Bézier clipping).** A cell is S x T,
//! S = [a, b] and T = [c, d] with double ends. The piece of P over S is computed from P's
//! control points as the blossom values P(a^(n-k), b^k), k = 0..n ([`restrict`]; unrolled
//! for degrees 1 to 3): each after exactly n de Casteljau steps v' = fl(x + fl(τ fl(y - x)))
//! at the doubles τ = a or b in [0, 1] (from the pyramids at a and at b, blossoms being
//! symmetric). From values |x|, |y| <= M one step is off the exact x + τ (y - x) by at most
//! u |τ (y - x)| (2 + u) + η/2 + u |x + fl(τ fl(y - x))| <= 5u M (1 + u) + η (u = 2^-53,
//! η = 2^-1074; sums have no underflow error), and an exact convex combination of perturbed
//! inputs moves by at most their error, so every computed control point coordinate lies
//! within E = n β, β = 5u M0 (1 + 2^-38) + η, of the exact one (M0 the largest input
//! coordinate; computed values stay within M0 (1 + 2^-40) for n <= 256, which β covers).
//! The exact interval of a piece is exactly [a, b]: no parameter is rounded. The cell is
//! dropped when the bounding boxes of the two pieces' control points, each enlarged by its
//! E, are disjoint (a piece lies in the convex hull of its exact control points): when a
//! computed difference of box ends fl(x - y) exceeds a double e >= E_p + E_q
//! ([`boxes_meet`]; rounding is monotone, so the exact x - y exceeds e too). Otherwise it
//! is *clipped* ([`clip`]): with the double vector ν normal to the chord of the Q piece,
//! every exact control point q of that piece has ν·q within [lo - m_q, hi + m_q], lo and hi
//! the least and largest computed ν·q and m_q = |ν|_1 (E_q + 3u M_q) + 4η (two products and
//! a sum, rounded; the error of the control points), so Q(T) lies in that band (the fat
//! line). A common point P(s) = Q(t) with s = a + u (b - a) has ν·P(s) = Σ δ_k B_k(u) in the
//! band, the δ_k = ν·p_k of the exact P piece, which lie within m_p of the computed D_k: so
//! Σ D_k B_k(u) lies in the band [L, H] = [lo - m_q - m_p, hi + m_q + m_p]. Its edges are
//! computed as fl(lo - m) and fl(hi + m) with m = fl(fl(fl(|ν_0| + |ν_1|) K) + 16η), K the
//! sum of the two reaches E + 4u M times 1 + 64u, rounded upwards ([`margin_scale`]): three
//! roundings down (each at least 1 - u) leave m >= |ν|_1 (E_p + E_q + 4u (M_p + M_q))
//! (1 + 60u), and 15η more when the product is below 2^-1022 (where it is off by η/2 and the
//! sum is exact), else 44u times a normal number, over 20η. So m exceeds m_p + m_q by at
//! least u |ν|_1 M_q + 16u (m_p + m_q), more than the rounding of the edge, at most
//! u (|lo| + m) with |lo|, |hi| <= |ν|_1 M_q (1 + 2^-38) (a sum has no underflow error), so
//! the computed edges lie outside [L, H]. The graph of
//! Σ D_k B_k lies in the convex hull C of the points (k/n, D_k). Its least abscissa in the
//! band ([`Band`]): 0 when D_0 is in the band; else, say D_0 > H, it is the least abscissa of
//! C on the line y = H (were the least point x* of C in the band below that line, the
//! segment from (0, D_0) to x* would meet the band left of x*), which is the least crossing
//! of that line by a segment from a point (i/n, D_i) with D_i > H to a point (j/n, D_j) with
//! D_j <= H (C meets the line in the hull of these crossings), and a pair with j < i is
//! dominated by the pair (0, j), whose crossing lies left of j/n: so the least of the
//! crossings i + (j - i) ρ, ρ = (D_i - H) / (D_i - D_j), over i < j with D_i beyond the
//! edge and D_j not, in units of 1/n; no such pair: every point beyond the edge, the cell
//! holds no root and is dropped. The largest abscissa likewise from D_n. The decisions
//! "beyond" are exact (fl(x - y) has the sign of x - y). A crossing is computed within 9u:
//! ρ' = fl(fl(D_i - e) fl(1 / fl(D_i - D_j))) = ρ (1 + δ1)(1 + δ3)(1 + δ4) / (1 + δ2) with
//! |δ| <= u (and an absolute η/2 for underflow; for a cubic, by the reciprocal unless it
//! overflows, else, and for other degrees, by one division, a rounding fewer), so
//! |ρ' - ρ| <= 4.0001u + η as ρ <= 1; the product by the integer j - i and the sum with i
//! (values at most n) add 2un (1 + 4u), the product by fl(1 / n) (itself within u of 1 / n,
//! relatively) 2.0001u + η; in [0, 1]: at most 6.001u + 2.0001u + 3η < 9u. The two ends,
//! ordered (rounding may reverse them when C meets the
//! band in one abscissa), are widened by 2^-48 = 32u (the rounding of the subtraction adds
//! at most u), clamped to [0, 1], then mapped to the global parameter a + u (b - a) (three
//! roundings, within 3.01u b + η) moved outwards by fl(8u b + 2η) (which covers that and
//! its own rounding, 1.01u b + u η), clamped to S. A round clips S so, and T against the
//! fat line of the same cell's P piece, side by side (the two clips are independent, which
//! shortens the chain of dependent operations); cells that a round shrinks by less than
//! 20% on both sides are halved (the wider side), so every root in [0, 1]^2 stays in some
//! cell. Cells inside a box proved below (its one root known) are dropped.
//!
//! **2. Krawczyk's test proves one root in a box.** For a box X = m ± r (midpoint m and
//! radius r > 0 doubles, in (s, t)), with Y an approximate inverse of the Jacobian
//! J = [P'(s) | -Q'(t)] at m,
//! K(X) = m - Y F(m) + (I - Y J(X)) (X - m),
//! evaluated in interval arithmetic ([`BoundedF64`] as midpoint-radius intervals, see
//! [`super::interval`]; de Casteljau's steps in convex form, [`ConvexStep`], so that the
//! bounds do not grow geometrically with the degree): F(m) from de Casteljau at the double m
//! in double-double ([`Dd`], with a rigorous bound near n^2 u^2 M), J(X) as enclosures of
//! P'(S) and Q'(T) ([`Curve::tangent`]): when S lies in [0, 1], by the mean value theorem,
//! P'(s) within r G of P'(m_s), G = n (n - 1) max |p_(i+2) - 2 p_(i+1) + p_i| bounding |P''|
//! on [0, 1] (the second hodograph's control points, convex hull), rounded upwards, and
//! P'(m_s) = n (B1 - B0) from de Casteljau's pyramid at the double m_s in plain `f64` (B0,
//! B1 blossom values after n - 1 steps, each computed within (n - 1) β, part 1), so that the
//! computed v = fl(n fl(b1 - b0)) lies within 2 (n - 1) E + 2.0001u |v| + η of it; else
//! from de Casteljau of the hodographs n (p_(i+1) - p_i) (their rounding bounded by
//! `BoundedF64`) at the interval argument m_s ± r_s (interval evaluation is inclusion
//! isotone): values a and radii ρ, |A - a| <= ρ entrywise for A in J(X), and F(m) within
//! e_F of f. The product with the matrix Y (the computed inverse of a, any
//! doubles: Krawczyk's operator is sound for every Y) is done in plain `f64` ([`krawczyk`]):
//! K(X) - m lies in μ ± R, μ_i = fl(-(Y_i0 f_0 + Y_i1 f_1)) (off from -(Y f)_i by at most
//! (2u + u^2) T_i + 2η, T_i = |Y_i0| |f_0| + |Y_i1| |f_1|), and for each column j the entry
//! (I - Y A)_ij is at most |c_ij| + Σ_k |Y_ik| ρ_kj with c = I - Y a, whose computed
//! ĉ_ij = fl(δ_ij - fl(fl(Y_i0 a_0j) + fl(Y_i1 a_1j))) is off by at most u |ĉ_ij| +
//! 3u Σ_k |Y_ik| |a_kj| + 2η: so with ρ'_kj = ρ_kj + 3u |a_kj|,
//! R_i = (1 + u) (|Y_i0| e_F0 + |Y_i1| e_F1 + 3u T_i + Σ_j (|ĉ_ij| + Σ_k |Y_ik| ρ'_kj) r_j)
//! plus absolute terms. That expression is computed from nonnegative doubles by sums and
//! products, at most 16 roundings deep: each rounding is fl(w) >= (1 - u) w (sums have no
//! underflow error; a product's η / 2 joins the absolute terms), so the exact expression is
//! at most (1 - u)^-16 times the computed one R'. The absolute terms (the 2η above, the
//! products' η / 2, times |Y| <= 10^30 < 2^100 (a larger entry: the test fails) and radii
//! below 8) stay under 2^-960. The radius taken is fl(fl(R' (1 + 2^-45)) + 2^-900), at least
//! (1 - u)^2 (1 + 256u) R' + (1 - u)(2^-900 - η/2) >= (1 + u)(1 - u)^-16 R' + 2^-901: it
//! covers both. The test |μ_i| + R_i < r_i is decided by fl(|μ_i| + R_i) < r_i (rounding is
//! monotone and r_i a double). By the mean value theorem row by row, every root of F in X
//! lies in K(X); K(X) ⊂ X gives a root (Brouwer), and K(X) in the interior of X gives exactly one,
//! with every matrix A of J(X) nonsingular: the radius of K is at least |I - Y A| r, so
//! |I - Y A| r < r for the positive vector r, hence the spectral radius of I - Y A is
//! below 1. The Jacobian at the root is then nonsingular, i.e. cross(P'(s), Q'(t)) != 0: the
//! crossing is transversal and `tangent` is false, exactly. A cell is tried
//! ([`Search::settle`]) when both sides are at most 2^-40 wide, when clipping has stalled
//! on a cell at most 2^-20 wide, and once early, when a round that shrank it well leaves
//! both sides at most 2^-7 wide (a failure then only lets clipping go on): X is centred at
//! z (the cell's centre when tiny, else a Newton point near it, found in plain `f64`: a
//! heuristic choice) with radii 1.25 times |z - centre| + half width, rounded up, at least
//! 2^-48, so that X contains the cell. A proved X is an *exclusion box*: the cell's roots
//! are its one root. A cell whose test fails is halved, or left undecided below 2^-40.
//!
//! **3. A tight enclosure and correct rounding.** For a tiny cell, X's own enclosure K(X)
//! when it decides what follows (for a cell of 2^-40 it is some |Y| |J(X) - J(z)| r wide,
//! near 1e-27); else, when X is wider than 8 times the Newton correction |Y F(z)|, a second
//! Krawczyk step on X' = z ± max(8 |Y F(z)|, 2^-48), inside X, so that its root is X's
//! root, with the Jacobian enclosed over X'. It
//! encloses the root as s* in z_s + Δ_s, t* in z_t + Δ_t. The correctly rounded s and t (ties
//! to even) are decided from these offsets against the half-ulp boundaries
//! ([`round_nearest`]); the common point from P(s*) in P(z_s) + Δ_s P'(S'), also correctly
//! rounded, so that the filter's answer equals the exact path's bit for bit.
//!
//! **4. The answer.** Distinct proved roots have disjoint tight enclosures; two whose
//! enclosures meet are one root when one enclosure lies in the other's exclusion box. A root
//! whose enclosure lies outside [0, 1]^2 is not reported; one inside (0, 1)^2 is. Once every
//! cell is dropped or settled, the proved roots inside are all the intersections, sorted by
//! s then t.
//!
//! **Undecided (`None`)**, for the exact path: a tight enclosure touching s or t in {0, 1}
//! (end-point contacts are decided exactly), enclosures that meet without being the same
//! root, a rounding not decided by the enclosure (a common point with a zero coordinate
//! among them), more than `MAX_STEPS` rounds of clipping or a cell of side 2^-40 that
//! Krawczyk's test does not settle (tangency, near-coincident roots, overlapping or
//! identical curves, where the test cannot succeed), a curve that is a single point, a
//! degree above 256, non-finite or extreme input (largest coordinate outside
//! [1e-90, 1e90], so that no product of the filter overflows or loses its bound).
//!
//! The speed comes from clipping (Sederberg and Nishita's Bézier clipping, with the
//! rigorous margins above): a transversal crossing is cut down quadratically, and once a
//! cell is 2^-7 wide a few Newton steps in `f64` centre the Krawczyk boxes, so that a random
//! pair of cubics costs a few rounds of clipping and, per crossing, two Krawczyk tests and
//! one double-double evaluation of each curve. The two clips of a round are independent
//! (a short chain of dependent operations per round), and on x86-64 processors with AVX2 the
//! search and the settlement run builds of the same source compiled for AVX2 (the same
//! doubles). The search state is kept per thread and reused, so a call allocates nothing
//! after the first (but its answer).

use super::interval::{lerp_pyramid_bound, lower, round_nearest, upper, ConvexStep, Dd};
use super::pyramid::{convex_point, dd_point, dd_point_bounded, dd_points_bounded};
use crate::num::bounded::{upward, BoundedF64, ETA, UNIT_ROUNDOFF};
use crate::num::ring::Ring;

/// One proved transversal crossing P(s) = Q(t) with s, t in (0, 1), **certified** (see
/// [`certified_crossings_f64`]). `Display` writes `s = .., t = .., point = (x, y)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CertifiedCrossing {
    /// The double nearest to the exact parameter on the first curve (ties to even).
    pub s: f64,
    /// The double nearest to the exact parameter on the second curve.
    pub t: f64,
    /// Doubles lo <= hi with the exact s in [lo, hi] (a few ulps wide).
    pub s_enclosure: [f64; 2],
    /// Doubles lo <= hi with the exact t in [lo, hi].
    pub t_enclosure: [f64; 2],
    /// The common point, each coordinate the double nearest to its exact value.
    pub point: [f64; 2],
}

/// At most this many clipping steps (each clips both curves once) per call.
const MAX_STEPS: usize = 4000;
/// No cell side is halved below this width; a cell this small that Krawczyk's test does not
/// settle is undecided.
const MIN_WIDTH: f64 = 1.0 / (1u64 << 40) as f64;
/// A cell whose sides are both at most this wide is tried by Krawczyk's test at once.
const TINY_WIDTH: f64 = MIN_WIDTH;
/// A cell that clipping no longer shrinks is tried by Krawczyk's test when its sides are at
/// most this wide (else halved).
const SETTLE_WIDTH: f64 = 1.0 / (1u64 << 20) as f64;
/// A cell that clipping shrinks well is tried once when its sides are at most this wide.
const EARLY_WIDTH: f64 = 1.0 / (1u64 << 7) as f64;
/// Clipping that leaves more than this fraction of both sides has stalled: the cell is halved.
const PROGRESS: f64 = 0.8;
/// The outward margin of a clipped range in the local parameter (module documentation, 1).
const CLIP_SLACK: f64 = 1.0 / (1u64 << 48) as f64;
/// The least radius of a Krawczyk box.
const TIGHT_RADIUS: f64 = 1.0 / (1u64 << 48) as f64;
/// The factor of a Krawczyk box's radii over the distances to the cell's corners (a margin
/// that keeps a root near the cell's edge away from the box's edge).
const COVER: f64 = 1.25;
/// Newton iterations from the centre of a cell that is not tiny.
const NEWTON_STEPS: usize = 12;
/// A Newton step at most this long ends the iteration.
const NEWTON_DONE: f64 = 1.0 / (1u64 << 30) as f64;
/// How far beyond the cell a Newton point may lie and still centre a Krawczyk box.
const NEWTON_REACH: f64 = 1.0 / (1u64 << 40) as f64;
/// The largest degree the filter takes (its a-priori bounds assume n <= 256).
const MAX_DEGREE: usize = 256;
/// The largest and least admissible size of the input coordinates (beyond: the exact path).
const MAX_SIZE: f64 = 1.0e90;
const MIN_SIZE: f64 = 1.0e-90;

/// One curve: its control points in the forms the filter needs, and scratch space.
struct Curve {
    /// Degree n.
    degree: usize,
    /// Control points.
    points: Vec<[f64; 2]>,
    /// The hodograph's control points with their rounding bounds.
    hodograph: Vec<[BoundedF64; 2]>,
    /// Whether `hodograph` is that of `points` ([`Curve::prepare`]).
    prepared: bool,
    /// G >= n (n - 1) max |p_(i+2) - 2 p_(i+1) + p_i| (every coordinate), a bound on |P''| over
    /// [0, 1], once `bend_known` ([`Curve::bend`]).
    bend: f64,
    bend_known: bool,
    /// 2 (n - 1) E: with 2u |v| + η, the bound on the error of the derivative v computed by
    /// [`Curve::eval_f64`] at an argument in [0, 1] ([`Curve::tangent`]).
    slope_error: f64,
    /// The largest |coordinate| M0.
    size: f64,
    /// E = n β of the module documentation: the bound on the distance of each computed control
    /// point coordinate of a restriction ([`Curve::restrict`]) to the exact one.
    error: f64,
    /// E + 4 u M: the per-unit-weight part of a distance coefficient's margin ([`clip`]),
    /// with u M for the rounding of the band's edges (module documentation, 1).
    reach: f64,
    /// The bound of [`Curve::eval_dd`] at arguments in [0, 1], known a priori
    /// ([`lerp_pyramid_bound`]).
    dd_bound: f64,
    /// Scratch.
    level: Vec<[f64; 2]>,
    level_dd: Vec<Dd>,
    level_bounded: Vec<BoundedF64>,
}

impl Curve {
    /// A curve with no control points and empty storage, to be [`Curve::reset`].
    fn empty() -> Self {
        Curve {
            degree: 0,
            points: Vec::new(),
            hodograph: Vec::new(),
            prepared: false,
            bend: 0.0,
            bend_known: false,
            slope_error: 0.0,
            size: 0.0,
            error: 0.0,
            reach: 0.0,
            dd_bound: 0.0,
            level: Vec::new(),
            level_dd: Vec::new(),
            level_bounded: Vec::new(),
        }
    }

    /// Makes this the curve with control points `p`, reusing the storage, or `None` when the
    /// filter does not take it (fewer than two or more than `MAX_DEGREE + 1` points, a
    /// non-finite or extreme coordinate, a single point).
    fn reset(&mut self, p: &[[f64; 2]]) -> Option<()> {
        if p.len() < 2 || p.len() > MAX_DEGREE + 1 {
            return None;
        }
        // The largest |coordinate| (∞ for an infinite one), and whether all points are equal.
        // (Branch-free: `largest` ignores a NaN, which `nan` records.)
        let (mut m0, mut single, mut nan) = (0.0f64, true, false);
        for c in p {
            nan |= c[0].is_nan() | c[1].is_nan();
            m0 = largest(largest(m0, c[0].abs()), c[1].abs());
            single &= (c[0] == p[0][0]) & (c[1] == p[0][1]);
        }
        if nan || single || !(MIN_SIZE..=MAX_SIZE).contains(&m0) {
            return None;
        }
        self.degree = p.len() - 1;
        self.points.clear();
        self.points.extend_from_slice(p);
        self.prepared = false;
        self.bend_known = false;
        self.size = m0;
        // β = 5u M (1 + 2^-39) + η with M = M0 (1 + 2^-40) (module documentation, 1).
        let beta = upward(5.0 * UNIT_ROUNDOFF * m0 * (1.0 + 2f64.powi(-38)) + ETA);
        self.error = upward(self.degree as f64 * beta);
        let size = m0 * (1.0 + 2f64.powi(-39));
        self.reach = upward(self.error + 4.0 * UNIT_ROUNDOFF * size);
        self.slope_error = upward(2.0 * (self.degree - 1) as f64 * self.error);
        self.dd_bound = lerp_pyramid_bound(self.degree, m0);
        Some(())
    }

    /// G of [`Curve::bend`]'s field, computed on first use after [`Curve::reset`]: from the
    /// computed second differences x = fl(fl(c - b) - fl(b - a)) of the coordinates, whose
    /// exact values are at most |x| (1 + u) + 4u M0 (each first difference, at most 2 M0, is
    /// off by at most u times that, the outer difference by u |x|; a difference has no
    /// underflow error), times n (n - 1), rounded upwards. Zero for a line.
    fn bend(&mut self) -> f64 {
        if !self.bend_known {
            let mut largest_difference = 0.0f64;
            for w in self.points.windows(3) {
                let (a, b, c) = (w[0], w[1], w[2]);
                for (x, (y, z)) in a.iter().zip(b.iter().zip(&c)) {
                    let second = (z - y) - (y - x);
                    largest_difference = largest(largest_difference, second.abs());
                }
            }
            let n = self.degree as f64;
            let difference =
                largest_difference * (1.0 + UNIT_ROUNDOFF) + 4.0 * UNIT_ROUNDOFF * self.size;
            self.bend = upward(n * (n - 1.0) * difference);
            self.bend_known = true;
        }
        self.bend
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius. When [mid - radius,
    /// mid + radius] lies in [0, 1] (decided exactly: radius <= mid, fl(mid + radius) < 1),
    /// by the mean value theorem: P'(s) lies within radius G ([`Curve::bend`]) of P'(mid),
    /// and the v = fl(n fl(b1 - b0)) of [`Curve::eval_f64`] within 2 (n - 1) E + 2.0001u |v|
    /// plus η of P'(mid) = n (B1 - B0) (b0, b1 are blossom values after n - 1 de Casteljau steps
    /// at mid, each within (n - 1) β of the exact B0, B1 (module documentation, 1); the
    /// difference and the product add u |b1 - b0| and u |v| + η/2); the sum rounded upwards.
    /// Else from de Casteljau's pyramid of the hodograph at the interval argument
    /// ([`Curve::tangent_pyramid`]).
    #[inline]
    fn tangent(&mut self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        if radius <= mid && mid + radius < 1.0 {
            let spread = radius * self.bend();
            let (_, d) = self.eval_f64(mid);
            let error = self.slope_error;
            let bound = |v: f64| upward(error + 2.0 * UNIT_ROUNDOFF * v.abs() + ETA + spread);
            [
                BoundedF64::with_bound(d[0], bound(d[0])),
                BoundedF64::with_bound(d[1], bound(d[1])),
            ]
        } else {
            self.prepare();
            self.tangent_pyramid(mid, radius)
        }
    }

    /// Makes the hodograph, on first use after [`Curve::reset`] (most pairs never need it).
    fn prepare(&mut self) {
        if self.prepared {
            return;
        }
        self.prepared = true;
        // The hodograph n (p_(i+1) - p_i), its rounding bounded.
        let n = BoundedF64::exact(self.degree as f64);
        let difference = |a: f64, b: f64| BoundedF64::exact(b).sub(&BoundedF64::exact(a)).mul(&n);
        self.hodograph.clear();
        for w in self.points.windows(2) {
            let (a, b) = (w[0], w[1]);
            self.hodograph
                .push([difference(a[0], b[0]), difference(a[1], b[1])]);
        }
    }

    /// P(s) and P'(s) in plain `f64` (for Newton's method, and the derivative for
    /// [`Curve::tangent`]): n - 1 de Casteljau steps leave the segment b0 b1 with
    /// P(s) = b0 + s (b1 - b0) and P'(s) = n (b1 - b0). Unrolled for degrees 1 to 3.
    #[inline]
    fn eval_f64(&mut self, s: f64) -> ([f64; 2], [f64; 2]) {
        match *self.points {
            [p0, p1] => eval_fixed([p0, p1], s),
            [p0, p1, p2] => eval_fixed([p0, p1, p2], s),
            [p0, p1, p2, p3] => eval_fixed([p0, p1, p2, p3], s),
            _ => {
                let level = &mut self.level;
                level.clear();
                level.extend_from_slice(&self.points);
                for k in (3..=self.degree + 1).rev() {
                    lerp_step(&mut level[..k], s);
                }
                segment_point(level[0], level[1], s, self.degree)
            }
        }
    }

    /// P at the double `s` in double-double with a bound (de Casteljau's pyramid by
    /// [`Dd::lerp`], unrolled for degrees 1 to 3: [`dd_point`]; for s in [0, 1], the common
    /// case, with the bound known a priori: [`dd_point_bounded`]).
    #[inline]
    fn eval_dd(&mut self, s: f64) -> [Dd; 2] {
        if (0.0..=1.0).contains(&s) {
            dd_point_bounded(&self.points, s, self.dd_bound, &mut self.level_dd)
        } else {
            dd_point(&self.points, s, &mut self.level_dd)
        }
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius: de Casteljau's pyramid of
    /// the hodograph at the interval argument in convex form (inclusion isotone, its width
    /// growing only linearly with the degree; unrolled for degrees 1 to 3: [`convex_point`]).
    #[inline]
    fn tangent_pyramid(&mut self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        let step = ConvexStep::new(BoundedF64::with_bound(mid, radius));
        convex_point(&self.hodograph, &step, &mut self.level_bounded)
    }
}

/// [`Curve::eval_f64`] on N points held in an array.
#[inline(always)]
fn eval_fixed<const N: usize>(mut level: [[f64; 2]; N], s: f64) -> ([f64; 2], [f64; 2]) {
    for k in (3..=N).rev() {
        for i in 0..k - 1 {
            level[i] = lerp(level[i], level[i + 1], s);
        }
    }
    segment_point(level[0], level[1], s, N - 1)
}

/// The point b0 + s (b1 - b0) and the derivative n (b1 - b0) from the last level of de
/// Casteljau's pyramid of a curve of degree n.
#[inline(always)]
fn segment_point(b0: [f64; 2], b1: [f64; 2], s: f64, n: usize) -> ([f64; 2], [f64; 2]) {
    let d = [b1[0] - b0[0], b1[1] - b0[1]];
    let n = n as f64;
    ([b0[0] + s * d[0], b0[1] + s * d[1]], [n * d[0], n * d[1]])
}

/// One de Casteljau step at `t` on the points of `level` (k points make k - 1, in place):
/// x + t (y - x) coordinate by coordinate.
#[inline(always)]
fn lerp_step(level: &mut [[f64; 2]], t: f64) {
    for i in 0..level.len() - 1 {
        let (x, y) = (level[i], level[i + 1]);
        level[i] = [x[0] + t * (y[0] - x[0]), x[1] + t * (y[1] - x[1])];
    }
}

/// One curve's piece over a side of the current cell: its control points, recomputed from the
/// curve's by [`restrict`]. Fixed-size arrays for small equal degrees (the loops unroll and
/// the scratch stays in registers), vectors otherwise.
trait Piece {
    /// The control points.
    fn points(&self) -> &[[f64; 2]];
    /// Makes this the restriction of the curve with control points `curve` to `range`.
    fn restrict(&mut self, curve: &[[f64; 2]], range: [f64; 2]);
}

/// A piece of N control points in arrays.
struct Fixed<const N: usize>([[f64; 2]; N]);

impl<const N: usize> Piece for Fixed<N> {
    #[inline(always)]
    fn points(&self) -> &[[f64; 2]] {
        &self.0
    }
    #[inline(always)]
    fn restrict(&mut self, curve: &[[f64; 2]], range: [f64; 2]) {
        let out: &mut [[f64; 2]] = &mut self.0;
        // N is a constant: one branch remains.
        match (out, curve) {
            (out @ [_, _], &[p0, p1]) => out.copy_from_slice(&restrict_line([p0, p1], range)),
            (out @ [_, _, _], &[p0, p1, p2]) => {
                out.copy_from_slice(&restrict_quadratic([p0, p1, p2], range))
            }
            (out @ [_, _, _, _], &[p0, p1, p2, p3]) => {
                out.copy_from_slice(&restrict_cubic([p0, p1, p2, p3], range))
            }
            (out, curve) => {
                let (mut a, mut b, mut tmp) = ([[0.0; 2]; N], [[0.0; 2]; N], [[0.0; 2]; N]);
                restrict(curve, range, out, [&mut a, &mut b, &mut tmp]);
            }
        }
    }
}

/// x + t (y - x), coordinate by coordinate: one de Casteljau step.
#[inline(always)]
fn lerp(x: [f64; 2], y: [f64; 2], t: f64) -> [f64; 2] {
    [x[0] + t * (y[0] - x[0]), x[1] + t * (y[1] - x[1])]
}

/// [`restrict`] for a line, unrolled: P(a), P(b).
#[inline(always)]
fn restrict_line([p0, p1]: [[f64; 2]; 2], [a, b]: [f64; 2]) -> [[f64; 2]; 2] {
    [lerp(p0, p1, a), lerp(p0, p1, b)]
}

/// [`restrict`] for a quadratic, unrolled (the same steps): P(a, a), P(a, b), P(b, b).
#[inline(always)]
fn restrict_quadratic([p0, p1, p2]: [[f64; 2]; 3], [a, b]: [f64; 2]) -> [[f64; 2]; 3] {
    let (a0, a1) = (lerp(p0, p1, a), lerp(p1, p2, a));
    let (b0, b1) = (lerp(p0, p1, b), lerp(p1, p2, b));
    [lerp(a0, a1, a), lerp(a0, a1, b), lerp(b0, b1, b)]
}

/// [`restrict`] for a cubic, unrolled (the same 14 steps): P(a, a, a), P(a, a, b) from the
/// second level at a, P(a, b, b) from the second level at b, P(b, b, b).
#[inline(always)]
fn restrict_cubic([p0, p1, p2, p3]: [[f64; 2]; 4], [a, b]: [f64; 2]) -> [[f64; 2]; 4] {
    let (a0, a1, a2) = (lerp(p0, p1, a), lerp(p1, p2, a), lerp(p2, p3, a));
    let (aa0, aa1) = (lerp(a0, a1, a), lerp(a1, a2, a));
    let (b0, b1, b2) = (lerp(p0, p1, b), lerp(p1, p2, b), lerp(p2, p3, b));
    let (bb0, bb1) = (lerp(b0, b1, b), lerp(b1, b2, b));
    [
        lerp(aa0, aa1, a),
        lerp(aa0, aa1, b),
        lerp(bb0, bb1, a),
        lerp(bb0, bb1, b),
    ]
}

/// A piece of any length in vectors, with the scratch of [`restrict`].
#[derive(Default)]
struct Dynamic {
    points: Vec<[f64; 2]>,
    scratch: [Vec<[f64; 2]>; 3],
}

impl Dynamic {
    /// Sizes the storage for `len` control points.
    fn resize(&mut self, len: usize) {
        for v in [&mut self.points]
            .into_iter()
            .chain(self.scratch.iter_mut())
        {
            v.clear();
            v.resize(len, [0.0; 2]);
        }
    }
}

impl Piece for Dynamic {
    fn points(&self) -> &[[f64; 2]] {
        &self.points
    }
    fn restrict(&mut self, curve: &[[f64; 2]], range: [f64; 2]) {
        let [a, b, tmp] = &mut self.scratch;
        restrict(curve, range, &mut self.points, [a, b, tmp]);
    }
}

/// The control points of the curve `points` restricted to [a, b] (doubles in [0, 1],
/// a <= b), in `out`: the blossom values P(a^(n-k), b^k), each after exactly n de Casteljau
/// steps x + τ (y - x) at τ = a or b, so within E of the exact ones (module documentation,
/// 1). The two pyramids at a and at b are built level by level; P(a^(n-k), b^k) is taken from
/// level n - k of the pyramid at a by k steps at b when 2k <= n, else from level k of the
/// pyramid at b by n - k steps at a (blossoms are symmetric): n (n + 1) + about n^3 / 24
/// steps, 14 for a cubic. `scratch` holds three buffers of the same length as `out`.
#[inline(always)]
fn restrict(
    points: &[[f64; 2]],
    [a, b]: [f64; 2],
    out: &mut [[f64; 2]],
    scratch: [&mut [[f64; 2]]; 3],
) {
    // The lengths from `out` (a constant for the fixed-size pieces, so the loops unroll).
    let n = out.len() - 1;
    let [at_a, at_b, tmp] = scratch;
    let (at_a, at_b, tmp) = (&mut at_a[..=n], &mut at_b[..=n], &mut tmp[..=n]);
    if a == 0.0 && b == 1.0 {
        out.copy_from_slice(&points[..=n]);
        return;
    }
    at_a.copy_from_slice(&points[..=n]);
    at_b.copy_from_slice(&points[..=n]);
    for level in 0..=n {
        // at_a[..n + 1 - level] is level `level` at a: P(a^level, ...); likewise at_b.
        let k = n - level;
        if 2 * k <= n {
            // P(a^(n-k), b^k): k steps at b on the k + 1 points of this level.
            tmp[..=k].copy_from_slice(&at_a[..=k]);
            for len in (2..=k + 1).rev() {
                lerp_step(&mut tmp[..len], b);
            }
            out[k] = tmp[0];
        }
        if 2 * level > n {
            // P(a^(n-level), b^level): n - level steps at a on this level at b.
            let m = n - level;
            tmp[..=m].copy_from_slice(&at_b[..=m]);
            for len in (2..=m + 1).rev() {
                lerp_step(&mut tmp[..len], a);
            }
            out[level] = tmp[0];
        }
        if level < n {
            lerp_step(&mut at_a[..=k], a);
            lerp_step(&mut at_b[..=k], b);
        }
    }
}

/// Whether the bounding boxes of the control points of `a` and `b`, each enlarged by its
/// error, meet, given a double `e` at least the sum of the errors. A box's side is dropped
/// only when a computed difference of ends fl(x - y) exceeds e: rounding is monotone and e
/// a double, so then the exact x - y exceeds e too, and the exact enlarged boxes are
/// disjoint.
#[inline(always)]
fn boxes_meet(a: &[[f64; 2]], b: &[[f64; 2]], e: f64) -> bool {
    let bounds = |pts: &[[f64; 2]]| match pts {
        // In a tree for a cubic (a shorter chain of dependent operations).
        [p0, p1, p2, p3] => {
            let (l, h) = (
                |c: usize| least(least(p0[c], p1[c]), least(p2[c], p3[c])),
                |c: usize| largest(largest(p0[c], p1[c]), largest(p2[c], p3[c])),
            );
            [l(0), h(0), l(1), h(1)]
        }
        _ => {
            let mut r = [pts[0][0], pts[0][0], pts[0][1], pts[0][1]];
            for xy in &pts[1..] {
                r[0] = least(r[0], xy[0]);
                r[1] = largest(r[1], xy[0]);
                r[2] = least(r[2], xy[1]);
                r[3] = largest(r[3], xy[1]);
            }
            r
        }
    };
    let (x, y) = (bounds(a), bounds(b));
    x[0] - y[1] <= e && y[0] - x[1] <= e && x[2] - y[3] <= e && y[2] - x[3] <= e
}

/// The margin of a fat line per unit of |ν|_1 for pieces of two curves with the reaches
/// `a_reach` and `b_reach` ([`Curve::reach`]): their sum times 1 + 64u, rounded upwards
/// (module documentation, 1; [`clip`]).
fn margin_scale(a_reach: f64, b_reach: f64) -> f64 {
    upward(upward(a_reach + b_reach) * (1.0 + 64.0 * UNIT_ROUNDOFF))
}

/// Fat-line clipping of the piece `a` against the fat line of the piece `b` (control points
/// within `reach - 4uM` of the exact ones, see [`Curve::reach`]; `scale` from
/// [`margin_scale`] of both curves' reaches) (module documentation, 1): `None` when no point
/// of `a` lies on the fat line (no common point), else a range [u0, u1] of `a`'s local
/// parameter in [0, 1] outside which `a` has no common point with `b`. [0, 1] when nothing
/// is clipped.
#[inline(always)]
fn clip(a: &[[f64; 2]], b: &[[f64; 2]], scale: f64) -> Option<[f64; 2]> {
    let (first, last) = (b[0], b[b.len() - 1]);
    let normal = [first[1] - last[1], last[0] - first[0]];
    if normal == [0.0, 0.0] {
        return Some([0.0, 1.0]);
    }
    let dot = |xy: &[f64; 2]| normal[0] * xy[0] + normal[1] * xy[1];
    let (lo, hi) = match b {
        // In a tree for a cubic (a shorter chain of dependent operations).
        [b0, b1, b2, b3] => {
            let d = [dot(b0), dot(b1), dot(b2), dot(b3)];
            (
                least(least(d[0], d[1]), least(d[2], d[3])),
                largest(largest(d[0], d[1]), largest(d[2], d[3])),
            )
        }
        _ => b
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), xy| {
                let d = dot(xy);
                (least(lo, d), largest(hi, d))
            }),
    };
    // The margins of both pieces' distance coefficients, added to the band, and the rounding
    // of the edges (module documentation, 1).
    let margin = (normal[0].abs() + normal[1].abs()) * scale + 16.0 * ETA;
    let (low, high) = (lo - margin, hi + margin);
    let band = Band::new(low, high, dot(&a[0]), dot(&a[a.len() - 1]));
    let coefficient = |xy: &[f64; 2]| band.coefficient(dot(xy));
    // The hull's range in the band, unrolled for a cubic.
    let range = match a {
        [p0, p1, p2, p3] => {
            let d = [
                coefficient(p0),
                coefficient(p1),
                coefficient(p2),
                coefficient(p3),
            ];
            // By reciprocals (one division per pair), unless one of them is not finite (a
            // subnormal difference where a candidate applies): then by divisions.
            match band.cubic_hull(&d, true) {
                (range, true) => range,
                _ => band.cubic_hull(&d, false).0,
            }
        }
        _ => band.hull(a.iter().map(coefficient), a.len() - 1),
    };
    band.finish(range, a.len() - 1)
}

/// The band [low, high] of a fat line against the distance coefficients D_k of a piece of
/// degree n, for the range of the abscissae of the hull of the points (k/n, D_k) inside it.
/// The least is 0 when D_0 is in the band, else the least crossing of the edge e0 beyond
/// which D_0 lies by a segment from a point i beyond it to a later point j not beyond it;
/// the largest likewise from D_n and its edge e1 (module documentation, 1). Abscissae are
/// kept as multiples of 1/n, i + (j - i) r, and divided by n at the end.
struct Band {
    /// The edges e0, e1 (either when D_0, D_n is inside).
    edge: [f64; 2],
    /// The sides of D_0, D_n: 1 above the band, -1 below, 0 inside.
    side: [f64; 2],
}

/// One distance coefficient D_k against the band: D_k - e0 and D_k - e1, and whether D_k lies
/// beyond e0 on D_0's side and beyond e1 on D_n's side. (fl(x - y) has the sign of x - y, so
/// that side (D_k - e) > 0 decides "beyond" exactly; never for an end inside, side 0.)
#[derive(Clone, Copy)]
struct Coefficient {
    value: f64,
    offset: [f64; 2],
    beyond: [bool; 2],
}

impl Band {
    #[inline(always)]
    fn new(low: f64, high: f64, d0: f64, dn: f64) -> Self {
        let edge = |d: f64| if d > high { high } else { low };
        let side = |d: f64| {
            if d > high {
                1.0
            } else if d < low {
                -1.0
            } else {
                0.0
            }
        };
        Band {
            edge: [edge(d0), edge(dn)],
            side: [side(d0), side(dn)],
        }
    }

    #[inline(always)]
    fn coefficient(&self, d: f64) -> Coefficient {
        let offset = [d - self.edge[0], d - self.edge[1]];
        Coefficient {
            value: d,
            offset,
            beyond: [
                self.side[0] * offset[0] > 0.0,
                self.side[1] * offset[1] > 0.0,
            ],
        }
    }

    /// The empty range, or the ends that are inside, for degree n: [0 or ∞, n or -∞].
    #[inline(always)]
    fn start(&self, n: usize) -> [f64; 2] {
        [
            if self.side[0] == 0.0 {
                0.0
            } else {
                f64::INFINITY
            },
            if self.side[1] == 0.0 {
                n as f64
            } else {
                f64::NEG_INFINITY
            },
        ]
    }

    /// The crossings of the segment from point i to the later point j, of the edge e0 as a
    /// candidate for the least abscissa and of e1 for the largest, each replaced by +∞ or -∞
    /// where it does not apply (the inputs' bound 1e90 keeps every D_k finite, and
    /// D_i - D_j != 0 where the sides differ, so an applicable candidate is finite). With
    /// `reciprocal`, the ratios are taken as products by fl(1 / (D_i - D_j)), and the flag
    /// returned is false when that reciprocal overflows (a subnormal difference) where a
    /// candidate applies; else by divisions.
    #[inline(always)]
    fn candidates(
        i: usize,
        j: usize,
        di: &Coefficient,
        dj: &Coefficient,
        reciprocal: bool,
    ) -> ([f64; 2], bool) {
        let gap = di.value - dj.value;
        let w = (j - i) as f64;
        let first = di.beyond[0] & !dj.beyond[0];
        let last = dj.beyond[1] & !di.beyond[1];
        let (r0, r1, finite) = if reciprocal {
            let inverse = 1.0 / gap;
            let finite = !(first | last) | (inverse.abs() <= f64::MAX);
            (di.offset[0] * inverse, di.offset[1] * inverse, finite)
        } else {
            (di.offset[0] / gap, di.offset[1] / gap, true)
        };
        let c0 = i as f64 + w * r0;
        let c1 = i as f64 + w * r1;
        let lower = if first { c0 } else { f64::INFINITY };
        let upper = if last { c1 } else { f64::NEG_INFINITY };
        ([lower, upper], finite)
    }

    /// The range of the hull of a cubic's coefficients `d` in the band, unfinished (in
    /// units of 1/3), and whether every reciprocal taken was finite ([`Band::candidates`]).
    #[inline(always)]
    fn cubic_hull(&self, d: &[Coefficient; 4], reciprocal: bool) -> ([f64; 2], bool) {
        let c = |i: usize, j: usize| Band::candidates(i, j, &d[i], &d[j], reciprocal);
        let ([l01, u01], f01) = c(0, 1);
        let ([l02, u02], f02) = c(0, 2);
        let ([l03, u03], f03) = c(0, 3);
        let ([l12, u12], f12) = c(1, 2);
        let ([l13, u13], f13) = c(1, 3);
        let ([l23, u23], f23) = c(2, 3);
        // In a tree, for a short chain of dependent operations (no candidate is NaN).
        let start = self.start(3);
        let lower = least(
            least(least(start[0], l01), least(l02, l03)),
            least(least(l12, l13), l23),
        );
        let upper = largest(
            largest(largest(start[1], u01), largest(u02, u03)),
            largest(largest(u12, u13), u23),
        );
        ([lower, upper], f01 & f02 & f03 & f12 & f13 & f23)
    }

    /// The range of the hull of any piece's coefficients `d` in the band, unfinished (in
    /// units of 1/n), by divisions.
    #[inline(always)]
    fn hull(&self, d: impl Iterator<Item = Coefficient> + Clone, n: usize) -> [f64; 2] {
        let mut range = self.start(n);
        for (i, di) in d.clone().enumerate() {
            for (j, dj) in d.clone().enumerate().skip(i + 1) {
                let ([l, u], _) = Band::candidates(i, j, &di, &dj, false);
                range = [least(range[0], l), largest(range[1], u)];
            }
        }
        range
    }

    /// The local range, widened by the slack, or `None` when every point lies beyond one edge.
    #[inline(always)]
    fn finish(&self, [u0, u1]: [f64; 2], n: usize) -> Option<[f64; 2]> {
        if u0 == f64::INFINITY || u1 == f64::NEG_INFINITY {
            return None;
        }
        // Times fl(1 / n) rather than divided by n: a shorter chain of operations.
        let scale = 1.0 / n as f64;
        // The two ends come from different candidates: rounding may order them wrongly when
        // the hull meets the band in one abscissa.
        let (lo, hi) = (least(u0, u1) * scale, largest(u0, u1) * scale);
        Some([largest(lo - CLIP_SLACK, 0.0), least(hi + CLIP_SLACK, 1.0)])
    }
}

/// The lesser of two numbers that are not NaN (one comparison, unlike `f64::min`).
#[inline(always)]
fn least(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

/// The larger of two numbers that are not NaN.
#[inline(always)]
fn largest(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// The global range of the local range `u` of the piece over `range` ([a, b] doubles in
/// [0, 1]): outward rounded, inside `range`.
fn to_global(range: [f64; 2], u: [f64; 2]) -> [f64; 2] {
    let [a, b] = range;
    let w = b - a;
    // Each end a + u w is computed within 3.01u b + η of the exact one (three roundings of
    // numbers at most b (1 + 3u)); the slack, at least 8u b (1 - u) + η, moves it outwards
    // past that error and the rounding of the slack's own sum or difference (at most
    // 1.01u b + u η).
    let slack = 8.0 * UNIT_ROUNDOFF * b + 2.0 * ETA;
    let lo = if u[0] == 0.0 {
        a
    } else {
        largest((a + u[0] * w) - slack, a)
    };
    let hi = if u[1] == 1.0 {
        b
    } else {
        least((a + u[1] * w) + slack, b)
    };
    [lo, largest(hi, lo)]
}

/// A box in (s, t): midpoint and radii, standing for m ± r exactly.
#[derive(Clone, Copy, Debug)]
struct Box2 {
    mid: [f64; 2],
    radius: [f64; 2],
}

impl Box2 {
    /// Double ranges [lo, hi] in s and in t whose product lies inside the box (rounded
    /// inwards).
    fn inner(&self) -> [[f64; 2]; 2] {
        [0, 1].map(|i| {
            let (m, r) = (self.mid[i], self.radius[i]);
            [(m - r).next_up(), (m + r).next_down()]
        })
    }
}

/// Whether [s0, s1] x [t0, t1] lies inside the ranges `inner` ([`Box2::inner`]).
#[inline]
fn within(inner: &[[f64; 2]; 2], s: [f64; 2], t: [f64; 2]) -> bool {
    inner[0][0] <= s[0] && s[1] <= inner[0][1] && inner[1][0] <= t[0] && t[1] <= inner[1][1]
}

/// What Krawczyk's operator gives on a box.
struct Krawczyk {
    /// K(X) - m, per coordinate.
    offset: [BoundedF64; 2],
    /// K(X) lies in the interior of X: exactly one root in X, a nonsingular Jacobian.
    proved: bool,
}

/// The largest |entry| of Y the settlement takes (a nearly singular midpoint Jacobian fails
/// the test anyway): it keeps every absolute rounding term of [`krawczyk`] below 2^-960.
const MAX_INVERSE: f64 = 1.0e30;
/// The absolute term of [`krawczyk`]'s radii, above every underflow term (module
/// documentation, 2).
const KRAWCZYK_FLOOR: f64 = f64::from_bits((1023 - 900) << 52);
/// The factor of [`krawczyk`]'s radii, 1 + 2^-45, over the rounding of its nonnegative sums
/// and products (module documentation, 2).
const KRAWCZYK_SCALE: f64 = 1.0 + 256.0 * UNIT_ROUNDOFF;

/// Krawczyk's operator on the box `x`, with F(m) enclosed by `f`, P'(S) by `dp` and Q'(T) by
/// `dq` (module documentation, 2), in plain `f64` with the radius bound derived there.
/// `None` when the midpoint Jacobian is singular or nearly so.
#[inline(always)]
fn krawczyk(
    x: &Box2,
    f: [BoundedF64; 2],
    dp: [BoundedF64; 2],
    dq: [BoundedF64; 2],
) -> Option<Krawczyk> {
    // J = [[P'_x, -Q'_x], [P'_y, -Q'_y]] over the box: midpoints a, radii ρ; Y the inverse
    // of a, computed (any doubles: Y is exact as the matrix it is).
    let a = [
        [dp[0].value(), -dq[0].value()],
        [dp[1].value(), -dq[1].value()],
    ];
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let inverse = 1.0 / det;
    let y = [
        [a[1][1] * inverse, -a[0][1] * inverse],
        [-a[1][0] * inverse, a[0][0] * inverse],
    ];
    // (Also false for NaN: a zero, non-finite or nearly singular determinant.)
    let small = |e: f64| e.abs() <= MAX_INVERSE;
    if !(small(y[0][0]) && small(y[0][1]) && small(y[1][0]) && small(y[1][1])) {
        return None;
    }
    let u = UNIT_ROUNDOFF;
    // ρ' = ρ + 3u |a|: the radius of J(X) with the rounding of Y a.
    let rho = [
        [
            dp[0].error_bound() + 3.0 * u * a[0][0].abs(),
            dq[0].error_bound() + 3.0 * u * a[0][1].abs(),
        ],
        [
            dp[1].error_bound() + 3.0 * u * a[1][0].abs(),
            dq[1].error_bound() + 3.0 * u * a[1][1].abs(),
        ],
    ];
    let (fv, fe) = (
        [f[0].value(), f[1].value()],
        [f[0].error_bound(), f[1].error_bound()],
    );
    let r = x.radius;
    // One row i of K(X) - m: μ_i and R_i.
    let row = |i: usize| {
        let (y0, y1) = (y[i][0], y[i][1]);
        let mid = -(y0 * fv[0] + y1 * fv[1]);
        // |Y_i| e_F + 3u |Y_i| |F| + Σ_j (|ĉ_ij| + |Y_i| ρ'_j) r_j, ĉ = fl(I - Y a).
        let (ay0, ay1) = (y0.abs(), y1.abs());
        let mut rad = ay0 * fe[0] + ay1 * fe[1] + 3.0 * u * (ay0 * fv[0].abs() + ay1 * fv[1].abs());
        let identity = [(i == 0) as u8 as f64, (i == 1) as u8 as f64];
        for j in 0..2 {
            let c = identity[j] - (y0 * a[0][j] + y1 * a[1][j]);
            rad += (c.abs() + ay0 * rho[0][j] + ay1 * rho[1][j]) * r[j];
        }
        BoundedF64::with_bound(mid, rad * KRAWCZYK_SCALE + KRAWCZYK_FLOOR)
    };
    let offset = [row(0), row(1)];
    // fl(|m| + R) < r implies |m| + R < r (rounding is monotone, r a double).
    let inside = |i: usize| offset[i].value().abs() + offset[i].error_bound() < r[i];
    let proved = inside(0) && inside(1);
    Some(Krawczyk { offset, proved })
}

/// [`krawczyk`]'s offsets K(X) - m on the box m ± r, for tests of its bound against exact
/// rationals: `None` when the midpoint Jacobian is (nearly) singular.
#[cfg(test)]
pub(super) fn krawczyk_offsets(
    mid: [f64; 2],
    radius: [f64; 2],
    f: [BoundedF64; 2],
    dp: [BoundedF64; 2],
    dq: [BoundedF64; 2],
) -> Option<([BoundedF64; 2], bool)> {
    let k = krawczyk(&Box2 { mid, radius }, f, dp, dq)?;
    Some((k.offset, k.proved))
}

/// [`Curve::tangent`] of the curve with control points `points` (the filter takes it: see
/// [`Curve::reset`]), for tests of its enclosure against exact rationals.
#[cfg(test)]
pub(super) fn tangent_enclosure(
    points: &[[f64; 2]],
    mid: f64,
    radius: f64,
) -> Option<[BoundedF64; 2]> {
    let mut curve = Curve::empty();
    curve.reset(points)?;
    Some(curve.tangent(mid, radius))
}

/// F(m) = P(m_s) - Q(m_t) in double-double with a bound, per coordinate, with P(m_s): the
/// two points at once when both arguments lie in [0, 1] (the common case), else one by one
/// ([`Curve::eval_dd`]).
fn residual_dd(p: &mut Curve, q: &mut Curve, m: [f64; 2]) -> ([Dd; 2], [Dd; 2]) {
    let unit = |x: f64| (0.0..=1.0).contains(&x);
    let [a, b] = if unit(m[0]) && unit(m[1]) {
        dd_points_bounded(
            (&p.points, m[0], p.dd_bound),
            (&q.points, m[1], q.dd_bound),
            &mut p.level_dd,
        )
    } else {
        [p.eval_dd(m[0]), q.eval_dd(m[1])]
    };
    ([a[0].sub(&b[0]), a[1].sub(&b[1])], a)
}

/// Newton's method in `f64` from `start`: the point it converges to, if it does.
#[inline(always)]
fn newton(p: &mut Curve, q: &mut Curve, start: [f64; 2]) -> Option<[f64; 2]> {
    let [mut s, mut t] = start;
    let mut previous = f64::INFINITY;
    for k in 0..NEWTON_STEPS {
        let (ps, dps) = p.eval_f64(s);
        let (qt, dqt) = q.eval_f64(t);
        let f = [ps[0] - qt[0], ps[1] - qt[1]];
        // J = [[dp_x, -dq_x], [dp_y, -dq_y]]; step = J^-1 f.
        let det = -dps[0] * dqt[1] + dqt[0] * dps[1];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inverse = 1.0 / det;
        let ds = (-dqt[1] * f[0] + dqt[0] * f[1]) * inverse;
        let dt = (-dps[1] * f[0] + dps[0] * f[1]) * inverse;
        s -= ds;
        t -= dt;
        if !((-1.0..=2.0).contains(&s) && (-1.0..=2.0).contains(&t)) {
            return None;
        }
        let step = ds.abs().max(dt.abs());
        // Near a regular root the next step would be some multiple of step^2: too small to
        // matter for the Krawczyk box centred here.
        if step <= NEWTON_DONE {
            return Some([s, t]);
        }
        // Past the first steps the iteration must contract (it converges quadratically near a
        // regular root); one that does not is abandoned.
        if k >= 2 && step > 0.5 * previous {
            return None;
        }
        previous = step;
    }
    None
}

/// A proved root: its tight enclosure, and the reported crossing when it lies inside the
/// domain.
struct Root {
    tight: [[f64; 2]; 2],
    crossing: Option<CertifiedCrossing>,
}

/// The root proved by Krawczyk's operator `k` on a box centred at `z`, with P(z_s) in `pz`
/// and P'(S) over the box's s side in `dp` (module documentation, 3): `None` when undecided,
/// else the root with its crossing when inside (0, 1)^2 (its common point NaN unless
/// `want_point`).
#[inline(always)]
fn root_of(
    z: [f64; 2],
    pz: [Dd; 2],
    k: &Krawczyk,
    dp: [BoundedF64; 2],
    want_point: bool,
) -> Option<Root> {
    let enclose = |m: f64, d: &BoundedF64| {
        let x = BoundedF64::exact(m).add(d);
        [lower(&x), upper(&x)]
    };
    let tight = [enclose(z[0], &k.offset[0]), enclose(z[1], &k.offset[1])];
    let outside = |e: [f64; 2]| e[1] < 0.0 || e[0] > 1.0;
    let inside = |e: [f64; 2]| e[0] > 0.0 && e[1] < 1.0;
    if outside(tight[0]) || outside(tight[1]) {
        return Some(Root {
            tight,
            crossing: None,
        });
    }
    if !(inside(tight[0]) && inside(tight[1])) {
        return None;
    }
    let s = round_nearest(z[0], &k.offset[0])?;
    let t = round_nearest(z[1], &k.offset[1])?;
    // P(s*) in P(z_s) + (s* - z_s) P'(S), coordinate by coordinate (mean value theorem).
    let coordinate = |c: usize| {
        let offset = pz[c].rest().add(&k.offset[0].mul(&dp[c]));
        round_nearest(pz[c].hi(), &offset)
    };
    let point = if want_point {
        [coordinate(0)?, coordinate(1)?]
    } else {
        [f64::NAN; 2]
    };
    Some(Root {
        tight,
        crossing: Some(CertifiedCrossing {
            s,
            t,
            s_enclosure: tight[0],
            t_enclosure: tight[1],
            point,
        }),
    })
}

/// The search state: both curves, the pieces of the current cell, the proved roots and their
/// exclusion boxes, the stack of cells. Kept per thread and reused ([`with_search`]), so that
/// a call allocates only on its first use (or for larger curves than before).
struct Search {
    p: Curve,
    q: Curve,
    /// The pieces of P and Q with their scratch, for curves beyond the fixed sizes.
    pieces: [Dynamic; 2],
    roots: Vec<Root>,
    /// Proved boxes (their inner ranges, [`Box2::inner`]), each with the index of its one
    /// root.
    exclusions: Vec<([[f64; 2]; 2], usize)>,
    /// Cells S x T still to examine.
    stack: Vec<([f64; 2], [f64; 2])>,
    /// Whether the common points are rounded (else NaN: [`crossing_parameters_f64`]).
    want_point: bool,
    /// Tests only: run the plain builds even where AVX2 is present.
    #[cfg(test)]
    plain: bool,
}

impl Search {
    fn empty() -> Self {
        Search {
            p: Curve::empty(),
            q: Curve::empty(),
            pieces: Default::default(),
            roots: Vec::new(),
            exclusions: Vec::new(),
            stack: Vec::new(),
            want_point: true,
            #[cfg(test)]
            plain: false,
        }
    }

    /// Whether the builds compiled for AVX2 may run: the processor has it (and, in tests,
    /// they are not switched off).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn wide(&self) -> bool {
        #[cfg(test)]
        if self.plain {
            return false;
        }
        std::arch::is_x86_feature_detected!("avx2")
    }

    /// Krawczyk's test on a box containing the cell `s` x `t` (module documentation, 2 and
    /// 3): `Some(true)` when the cell is settled (its roots are the one root of a proved box,
    /// recorded), `Some(false)` when the test fails, `None` when a proved root is undecided.
    fn settle(&mut self, s: [f64; 2], t: [f64; 2], early: bool) -> Option<bool> {
        #[cfg(target_arch = "x86_64")]
        if self.wide() {
            // SAFETY: the processor has just been seen to support AVX2.
            #[allow(unsafe_code)]
            return unsafe { self.settle_avx2(s, t, early) };
        }
        self.settle_body(s, t, early)
    }

    /// [`Search::settle`] compiled for AVX2 (as [`Search::cells_avx2`]: the same doubles);
    /// callers make sure that the processor has it.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn settle_avx2(&mut self, s: [f64; 2], t: [f64; 2], early: bool) -> Option<bool> {
        self.settle_body(s, t, early)
    }

    /// The body of [`Search::settle`], shared by its two builds.
    #[inline(always)]
    fn settle_body(&mut self, s: [f64; 2], t: [f64; 2], early: bool) -> Option<bool> {
        let centre = [0.5 * (s[0] + s[1]), 0.5 * (t[0] + t[1])];
        let half = [0.5 * (s[1] - s[0]), 0.5 * (t[1] - t[0])];
        let (p, q) = (&mut self.p, &mut self.q);
        let tiny = half[0].max(half[1]) <= TINY_WIDTH;
        // What a failure means: an early try only says "not yet" (clipping goes on).
        let fail = if early { Some(false) } else { None };
        // The box's centre: the cell's centre when the cell is tiny, else a Newton point near
        // it (a heuristic choice; the box contains the cell either way).
        let z = if tiny {
            centre
        } else {
            let near = |z: &[f64; 2]| {
                (0..2).all(|i| (z[i] - centre[i]).abs() <= 2.0 * half[i] + NEWTON_REACH)
            };
            match newton(p, q, centre).filter(near) {
                Some(z) => z,
                None if early => return Some(false),
                None => centre,
            }
        };
        let reach = |i: usize| {
            upward(COVER * ((z[i] - centre[i]).abs().next_up() + half[i])).max(TIGHT_RADIUS)
        };
        let cover = [reach(0), reach(1)];
        let (fdd, pz) = residual_dd(p, q, z);
        let f = [fdd[0].to_bounded(), fdd[1].to_bounded()];
        let outer = Box2 {
            mid: z,
            radius: cover,
        };
        let dp = p.tangent(z[0], cover[0]);
        let dq = q.tangent(z[1], cover[1]);
        let Some(k) = krawczyk(&outer, f, dp, dq).filter(|k| k.proved) else {
            return Some(false);
        };
        // The outer box's enclosure decides the common case of a tiny cell (its enclosure is
        // some |Y| |J(X) - J(z)| r wide, far below an ulp); else a tighter box around z, 8
        // times the Newton correction, with the Jacobian enclosed over it.
        let root = match tiny
            .then(|| root_of(z, pz, &k, dp, self.want_point))
            .flatten()
        {
            Some(root) => root,
            None => {
                let wanted = |i: usize| (8.0 * k.offset[i].value().abs()).max(TIGHT_RADIUS);
                let wanted = [wanted(0), wanted(1)];
                if wanted[0] >= cover[0] && wanted[1] >= cover[1] {
                    return fail;
                }
                let radius = [wanted[0].min(cover[0]), wanted[1].min(cover[1])];
                let inner = Box2 { mid: z, radius };
                // Its one root is the one root of the outer box, which contains it.
                let (dp_inner, dq_inner) = (p.tangent(z[0], radius[0]), q.tangent(z[1], radius[1]));
                let found = krawczyk(&inner, f, dp_inner, dq_inner)
                    .filter(|k| k.proved)
                    .and_then(|k| root_of(z, pz, &k, dp_inner, self.want_point));
                match found {
                    Some(root) => root,
                    None => return fail,
                }
            }
        };
        let index = self.add_root(root, &outer)?;
        self.exclusions.push((outer.inner(), index));
        Some(true)
    }

    /// Adds a newly certified root, proved to be the one root of `outer`, or finds it among
    /// the known ones: its index, `None` when its enclosure meets another's without being the
    /// same root.
    fn add_root(&mut self, root: Root, outer: &Box2) -> Option<usize> {
        let meets = |a: &[[f64; 2]; 2], b: &[[f64; 2]; 2]| {
            (0..2).all(|k| a[k][0] <= b[k][1] && b[k][0] <= a[k][1])
        };
        for (index, known) in self.roots.iter().enumerate() {
            if meets(&known.tight, &root.tight) {
                // The same root when one enclosure lies in a box proved for the other.
                let same = within(&outer.inner(), known.tight[0], known.tight[1])
                    || self
                        .exclusions
                        .iter()
                        .any(|(e, k)| *k == index && within(e, root.tight[0], root.tight[1]));
                return same.then_some(index);
            }
        }
        self.roots.push(root);
        Some(self.roots.len() - 1)
    }

    /// Whether the cell `s` x `t` lies in a proved box (whose one root is known).
    #[inline]
    fn excluded(&self, s: [f64; 2], t: [f64; 2]) -> bool {
        self.exclusions.iter().any(|(e, _)| within(e, s, t))
    }
}

/// Every crossing of the planar curves with `f64` control points `p` and `q` when the float
/// filter proves the complete answer, in floating point without big numbers: `Some` only
/// when every intersection is a transversal crossing inside (0, 1)^2. Sorted by s then t.
///
/// Guarantee (**certified**): when the answer is `Some`, it lists every intersection of the
/// curves with exactly these control points, once each, and each is transversal (tangent is
/// false, exactly); `s` and `t` are the correctly rounded parameters (ties to even) with
/// enclosures of the exact ones, `point` the correctly rounded common point: the same doubles
/// as the exact path ([`crate::BezierCurve::intersect_rounded`]) gives. The proof: rigorous
/// Bézier clipping (every root stays in a surviving cell), Krawczyk's test in interval
/// arithmetic (exactly one root, and a nonsingular Jacobian, in a box), double-double
/// residuals for the tight enclosures; it is written out in the source
/// (`src/intersect/filter.rs`).
///
/// `None` (undecided, for the exact path): an end-point contact (a parameter at 0 or 1),
/// a tangency or near-tangency, near-coincident roots, overlapping or identical curves, a
/// curve that is a single point or has one control point, a rounding the enclosure does not
/// decide, non-finite input, a largest coordinate outside [1e-90, 1e90], a degree above 256,
/// or a search that does not settle within its step limit. `None` says nothing about the
/// answer.
///
/// Cost: microseconds for a random pair of cubics (clipping converges quadratically); the
/// search state is kept per thread and reused, so a call allocates nothing but its answer
/// after the first.
///
/// ```
/// use blossom::certified_crossings_f64;
/// // The arc P(s) = (2s, 4s(1 - s)) and the line Q(t) = (2t, 1/2) cross where
/// // 4s(1 - s) = 1/2, s = t = (1 ± sqrt(1/2)) / 2.
/// let p = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
/// let q = [[0.0, 0.5], [2.0, 0.5]];
/// let x = certified_crossings_f64(&p, &q).expect("transversal: decided");
/// assert_eq!(x.len(), 2);
/// let root = (1.0 - 0.5f64.sqrt()) / 2.0;
/// assert!((x[0].s - root).abs() < 1e-15);
/// assert_eq!(x[0].s, x[0].t);
/// assert!(x[0].s_enclosure[0] <= x[0].s && x[0].s <= x[0].s_enclosure[1]);
/// assert_eq!(x[0].point[1], 0.5);
/// ```
pub fn certified_crossings_f64(p: &[[f64; 2]], q: &[[f64; 2]]) -> Option<Vec<CertifiedCrossing>> {
    with_search(|search| search.run(p, q, true))
}

/// [`certified_crossings_f64`] for callers that need the parameters alone: the same proof and
/// the same `s`, `t` and enclosures, but the common point is not rounded (`point` is NaN), so
/// that a crossing whose point the enclosure cannot round (a coordinate exactly zero, as
/// where a curve crosses a segment on an axis) is decided too.
pub(crate) fn crossing_parameters_f64(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
) -> Option<Vec<CertifiedCrossing>> {
    with_search(|search| search.run(p, q, false))
}

thread_local! {
    /// The search state of [`certified_crossings_f64`] on this thread, reused across calls.
    static SEARCH: std::cell::RefCell<Option<Search>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f` on this thread's reused [`Search`] (a fresh one when it is in use already).
fn with_search<R>(f: impl FnOnce(&mut Search) -> R) -> R {
    SEARCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut slot) => f(slot.get_or_insert_with(Search::empty)),
        Err(_) => f(&mut Search::empty()),
    })
}

impl Search {
    /// [`certified_crossings_f64`] on this search state, which it resets first.
    fn run(
        &mut self,
        p: &[[f64; 2]],
        q: &[[f64; 2]],
        want_point: bool,
    ) -> Option<Vec<CertifiedCrossing>> {
        self.want_point = want_point;
        self.p.reset(p)?;
        self.q.reset(q)?;
        self.roots.clear();
        self.exclusions.clear();
        self.stack.clear();
        self.stack.push(([0.0, 1.0], [0.0, 1.0]));
        // The pieces in arrays for equal small degrees (unrolled), else in vectors.
        match (self.p.degree, self.q.degree) {
            (1, 1) => self.cells(&mut Fixed([[0.0; 2]; 2]), &mut Fixed([[0.0; 2]; 2]))?,
            (2, 2) => self.cells(&mut Fixed([[0.0; 2]; 3]), &mut Fixed([[0.0; 2]; 3]))?,
            (3, 3) => self.cells(&mut Fixed([[0.0; 2]; 4]), &mut Fixed([[0.0; 2]; 4]))?,
            (n, m) => {
                let [mut piece_p, mut piece_q] = std::mem::take(&mut self.pieces);
                piece_p.resize(n + 1);
                piece_q.resize(m + 1);
                let done = self.cells(&mut piece_p, &mut piece_q);
                self.pieces = [piece_p, piece_q];
                done?
            }
        }
        let mut out: Vec<CertifiedCrossing> =
            self.roots.iter().filter_map(|r| r.crossing).collect();
        out.sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
        Some(out)
    }
}

impl Search {
    /// Examines the cells of the stack until none is left (module documentation, 1): `None`
    /// when undecided. On x86-64 processors with AVX2 (detected at run time) this runs a
    /// build of the same source compiled for AVX2 ([`Search::cells_avx2`]): the same
    /// floating-point operations in the same order, so the same doubles bit for bit (Rust
    /// never fuses a multiplication and an addition by itself), in fewer instructions.
    #[inline(always)]
    fn cells(&mut self, piece_p: &mut impl Piece, piece_q: &mut impl Piece) -> Option<()> {
        #[cfg(target_arch = "x86_64")]
        if self.wide() {
            // SAFETY: the processor has just been seen to support AVX2.
            #[allow(unsafe_code)]
            return unsafe { self.cells_avx2(piece_p, piece_q) };
        }
        self.cells_body(piece_p, piece_q)
    }

    /// [`Search::cells`] compiled for AVX2; callers make sure that the processor has it.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn cells_avx2(&mut self, piece_p: &mut impl Piece, piece_q: &mut impl Piece) -> Option<()> {
        self.cells_body(piece_p, piece_q)
    }

    /// The body of [`Search::cells`], shared by its two builds.
    #[inline(always)]
    fn cells_body(&mut self, piece_p: &mut impl Piece, piece_q: &mut impl Piece) -> Option<()> {
        let scale = margin_scale(self.p.reach, self.q.reach);
        let errors = upward(self.p.error + self.q.error);
        let mut steps = 0usize;
        while let Some((mut s, mut t)) = self.stack.pop() {
            piece_p.restrict(&self.p.points, s);
            piece_q.restrict(&self.q.points, t);
            let mut tried = false;
            loop {
                steps += 1;
                if steps > MAX_STEPS {
                    return None;
                }
                let (pp, qq) = (piece_p.points(), piece_q.points());
                if self.excluded(s, t) || !boxes_meet(pp, qq, errors) {
                    break;
                }
                let (ws, wt) = (s[1] - s[0], t[1] - t[0]);
                // Both pieces clipped against the other's fat line of this cell, side by side.
                let (Some(u), Some(v)) = (clip(pp, qq, scale), clip(qq, pp, scale)) else {
                    break;
                };
                if u != [0.0, 1.0] {
                    s = to_global(s, u);
                    piece_p.restrict(&self.p.points, s);
                }
                if v != [0.0, 1.0] {
                    t = to_global(t, v);
                    piece_q.restrict(&self.q.points, t);
                }
                let (ws2, wt2) = (s[1] - s[0], t[1] - t[0]);
                let stalled = ws2 > PROGRESS * ws && wt2 > PROGRESS * wt;
                let size = ws2.max(wt2);
                let early = !stalled && !tried && size <= EARLY_WIDTH;
                if size <= TINY_WIDTH || (stalled && size <= SETTLE_WIDTH) || early {
                    if self.settle(s, t, early && size > TINY_WIDTH)? {
                        break;
                    }
                    if early && size > TINY_WIDTH {
                        tried = true;
                        continue;
                    }
                } else if !stalled {
                    continue;
                }
                if size <= MIN_WIDTH {
                    return None;
                }
                if ws2 >= wt2 {
                    let m = 0.5 * (s[0] + s[1]);
                    self.stack.extend([([m, s[1]], t), ([s[0], m], t)]);
                } else {
                    let m = 0.5 * (t[0] + t[1]);
                    self.stack.extend([(s, [m, t[1]]), (s, [t[0], m])]);
                }
                break;
            }
        }
        Some(())
    }
}

/// [`certified_crossings_f64`] by the plain builds only (never the AVX2 ones), for tests
/// that the two give the same answers bit for bit.
#[cfg(test)]
pub(super) fn certified_crossings_plain(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
) -> Option<Vec<CertifiedCrossing>> {
    let mut search = Search::empty();
    search.plain = true;
    search.run(p, q, true)
}

/// The clipping of P's piece over `s` against the fat line of Q's piece over `t`, as one
/// round does it (for tests of the margins): `None` when the cell is dropped.
#[cfg(test)]
pub(super) fn clip_cell(
    p: &[[f64; 2]],
    q: &[[f64; 2]],
    s: [f64; 2],
    t: [f64; 2],
) -> Option<[f64; 2]> {
    let (mut cp, mut cq) = (Curve::empty(), Curve::empty());
    cp.reset(p)?;
    cq.reset(q)?;
    let (mut pp, mut pq) = (Dynamic::default(), Dynamic::default());
    pp.resize(p.len());
    pq.resize(q.len());
    pp.restrict(p, s);
    pq.restrict(q, t);
    clip(pp.points(), pq.points(), margin_scale(cp.reach, cq.reach))
}
