//! The float filter of curve-curve intersection: the common transversal case of two 2-D
//! Bézier curves with `f64` control points, certified in floating point, no big numbers.
//!
//! The problem is F(s, t) = P(s) - Q(t) = 0 on [0, 1]^2. The filter answers only when it has
//! *proved* the complete answer; otherwise it says `None` and the exact path
//! ([`super::curves::intersect_curves_f64`]) answers. What it proves:
//!
//! **1. Every root lies in a surviving cell (rigorous Bézier clipping).** A cell is S x T,
//! S = [a, b] and T = [c, d] with double ends. The piece of P over S is computed from P's
//! control points as the blossom values P(a^(n-k), b^k), k = 0..n ([`Curve::restrict`]): each
//! after exactly n de Casteljau steps v' = fl(x + fl(τ fl(y - x))) at the double τ = a or b
//! in [0, 1]. From values |x|, |y| <= M one step is off the exact x + τ (y - x) by at most
//! u |τ (y - x)| (2 + u) + η/2 + u |x + fl(τ fl(y - x))| <= 5u M (1 + u) + η (u = 2^-53,
//! η = 2^-1074; sums have no underflow error), and an exact convex combination of perturbed
//! inputs moves by at most their error, so every computed control point coordinate lies
//! within E = n β, β = 5u M0 (1 + 2^-38) + η, of the exact one (M0 the largest input
//! coordinate; computed values stay within M0 (1 + 2^-40) for n <= 256, which β covers).
//! The exact interval of a piece is exactly [a, b]: no parameter is rounded. The cell is
//! dropped when the bounding boxes of the two pieces' control points, each enlarged by E
//! and rounded outwards, are disjoint (a piece lies in the convex hull of its exact control
//! points). Otherwise it is *clipped* ([`clip`]): with the double vector ν normal to the
//! chord of the Q piece, every exact control point q of that piece has ν·q within
//! [lo - m_q, hi + m_q], lo and hi the least and largest computed ν·q and
//! m_q = |ν|_1 (E_q + 3u M_q) + 4η (two products and a sum, rounded; the error of the
//! control points), so Q(T) lies in that band (the fat line). A common point P(s) = Q(t)
//! with s = a + u (b - a) has ν·P(s) = Σ δ_k B_k(u) in the band, the δ_k = ν·p_k of the
//! exact P piece, which lie within m_p of the computed D_k: so Σ D_k B_k(u) lies in the band
//! [L, H] widened by m_p, rounded outwards. The graph of Σ D_k B_k lies in the convex hull
//! of the points (k/n, D_k); the least and largest u of that hull inside the band are among
//! the points inside the band and the crossings of the band's edges by the segments between
//! two points (the hull meets the band in a convex polygon whose vertices are of these
//! kinds); they are computed in `f64` within 10u, and widened by 2^-48, then mapped to the
//! global parameter with a margin of 4u b + η and `next_down`/`next_up`, clamped to S. No
//! point of the hull in the band: the cell holds no root and is dropped. S is clipped so,
//! then T against the new P piece's fat line; cells that a round of clipping shrinks by less
//! than 20% on both sides are halved (the wider side), so every root in [0, 1]^2 stays in
//! some cell. Cells inside a box proved below (its one root known) are dropped.
//!
//! **2. Krawczyk's test proves one root in a box.** For a box X = m ± r (midpoint m and
//! radius r > 0 doubles, in (s, t)), with Y an approximate inverse of the Jacobian
//! J = [P'(s) | -Q'(t)] at m,
//! K(X) = m - Y F(m) + (I - Y J(X)) (X - m),
//! evaluated in interval arithmetic ([`BoundedF64`] as midpoint-radius intervals, see
//! [`super::interval`]; de Casteljau's steps in convex form, [`ConvexStep`], so that the
//! bounds do not grow geometrically with the degree): F(m) from de Casteljau at the double m
//! in double-double ([`Dd`], with a rigorous bound near n^2 u^2 M), J(X) from de Casteljau
//! of the hodographs n (p_(i+1) - p_i) (their rounding bounded by `BoundedF64`) at the
//! interval arguments m ± r, which encloses P'(S) and Q'(T) (interval evaluation is
//! inclusion isotone). By the mean value theorem row by row, every root of F in X lies in
//! K(X); K(X) ⊂ X gives a root (Brouwer), and K(X) in the interior of X gives exactly one,
//! with every matrix A of J(X) nonsingular: the radius of K is at least |I - Y A| r, so
//! |I - Y A| r < r for the positive vector r, hence the spectral radius of I - Y A is
//! below 1. The Jacobian at the root is then nonsingular, i.e. cross(P'(s), Q'(t)) != 0: the
//! crossing is transversal and `tangent` is false, exactly. A cell is tried
//! ([`Search::settle`]) when both sides are at most 2^-40 wide, or when clipping has stalled
//! on a cell at most 2^-20 wide: X is centred at z (the cell's centre when tiny, else a
//! Newton point near it, found in plain `f64`: a heuristic choice) with radii 1.25 times
//! |z - centre| + half width, rounded up, at least 2^-48, so that X contains the cell. A
//! proved X is an *exclusion box*: the cell's roots are its one root. A cell whose test
//! fails is halved, or left undecided below 2^-40.
//!
//! **3. A tight enclosure and correct rounding.** When X is wider than 8 times the Newton
//! correction |Y F(z)|, a second Krawczyk step on z ± max(8 |Y F(z)|, 2^-48) (inside X, so
//! its root is X's root) gives the enclosure; else X's own. It encloses the root as s* in
//! z_s + Δ_s, t* in z_t + Δ_t with a width near 1e-28. The correctly rounded s and t (ties
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
//! rigorous margins above): a transversal crossing is cut down quadratically to a cell of
//! about 1e-15, so that a random pair of cubics costs a few rounds of clipping and, per
//! crossing, one Krawczyk test and one double-double evaluation; the search state is kept
//! per thread and reused, so a call allocates nothing after the first (but its answer).

use super::interval::{inside_radius, lower, round_nearest, upper, ConvexStep, Dd};
use crate::num::bounded::{upward, BoundedF64, ETA, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::shape::flat::curve_pyramid_in_place;

/// One proved transversal crossing P(s) = Q(t) with s, t in (0, 1).
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
    /// The same, as double-doubles.
    dd: Vec<Dd>,
    /// The hodograph's control points with their rounding bounds.
    hodograph: Vec<BoundedF64>,
    /// Whether `dd` and `hodograph` are those of `points` ([`Curve::prepare`]).
    prepared: bool,
    /// E = n β of the module documentation: the bound on the distance of each computed control
    /// point coordinate of a restriction ([`Curve::restrict`]) to the exact one.
    error: f64,
    /// E + 3 u M: the per-unit-weight part of a distance coefficient's margin ([`clip`]).
    reach: f64,
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
            dd: Vec::new(),
            hodograph: Vec::new(),
            prepared: false,
            error: 0.0,
            reach: 0.0,
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
        let (mut m0, mut single) = (0.0f64, true);
        for c in p {
            if c[0].is_nan() || c[1].is_nan() {
                return None;
            }
            m0 = m0.max(c[0].abs()).max(c[1].abs());
            single &= c == &p[0];
        }
        if single || !(MIN_SIZE..=MAX_SIZE).contains(&m0) {
            return None;
        }
        self.degree = p.len() - 1;
        self.points.clear();
        self.points.extend_from_slice(p);
        self.prepared = false;
        // β = 5u M (1 + 2^-39) + η with M = M0 (1 + 2^-40) (module documentation, 1).
        let beta = upward(5.0 * UNIT_ROUNDOFF * m0 * (1.0 + 2f64.powi(-38)) + ETA);
        self.error = upward(self.degree as f64 * beta);
        let size = m0 * (1.0 + 2f64.powi(-39));
        self.reach = upward(self.error + 3.0 * UNIT_ROUNDOFF * size);
        Some(())
    }

    /// Makes the double-double control points and the hodograph, on first use after
    /// [`Curve::reset`] (most pairs never need them).
    fn prepare(&mut self) {
        if self.prepared {
            return;
        }
        self.prepared = true;
        let p = &self.points;
        self.dd.clear();
        self.dd.extend(p.iter().flatten().map(|&x| Dd::exact(x)));
        // The hodograph n (p_(i+1) - p_i), its rounding bounded.
        let n = BoundedF64::exact(self.degree as f64);
        self.hodograph.clear();
        self.hodograph.extend(
            p.iter()
                .flatten()
                .zip(p[1..].iter().flatten())
                .map(|(&a, &b)| BoundedF64::exact(b).sub(&BoundedF64::exact(a)).mul(&n)),
        );
    }

    /// P(s) and P'(s) in plain `f64` (for Newton's method only): n - 1 de Casteljau steps
    /// leave the segment b0 b1 with P(s) = b0 + s (b1 - b0) and P'(s) = n (b1 - b0).
    fn eval_f64(&mut self, s: f64) -> ([f64; 2], [f64; 2]) {
        let level = &mut self.level;
        level.clear();
        level.extend_from_slice(&self.points);
        for k in (3..=self.degree + 1).rev() {
            lerp_step(&mut level[..k], s);
        }
        let d = [level[1][0] - level[0][0], level[1][1] - level[0][1]];
        let n = self.degree as f64;
        (
            [level[0][0] + s * d[0], level[0][1] + s * d[1]],
            [n * d[0], n * d[1]],
        )
    }

    /// P at the double `s` in double-double with a bound (de Casteljau's pyramid by
    /// [`Dd::lerp`]).
    fn eval_dd(&mut self, s: f64) -> [Dd; 2] {
        let level = &mut self.level_dd;
        level.clear();
        level.extend_from_slice(&self.dd);
        for k in (4..=level.len()).rev().step_by(2) {
            for i in 0..k - 2 {
                level[i] = Dd::lerp(&level[i], &level[i + 2], s);
            }
        }
        [level[0], level[1]]
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius: de Casteljau's pyramid of
    /// the hodograph at the interval argument in convex form (inclusion isotone, its width
    /// growing only linearly with the degree).
    fn tangent_pyramid(&mut self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        let level = &mut self.level_bounded;
        level.clear();
        level.extend_from_slice(&self.hodograph);
        let step = ConvexStep::new(BoundedF64::with_bound(mid, radius));
        curve_pyramid_in_place(level, 2, &step);
        [level[0], level[1]]
    }
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

/// The control points of the curve `points` restricted to [a, b] (doubles in [0, 1],
/// a <= b), in `out`: the blossom values P(a^(n-k), b^k), each after exactly n de Casteljau
/// steps x + τ (y - x) at τ = a or b (fewer where a step is exact: at 0 it keeps the first
/// point, and the steps at 1 of [0, 1] keep the points), so within E of the exact ones
/// (module documentation, 1). `work` and `tmp` are scratch of the same length.
#[inline(always)]
fn restrict(
    points: &[[f64; 2]],
    [a, b]: [f64; 2],
    out: &mut [[f64; 2]],
    work: &mut [[f64; 2]],
    tmp: &mut [[f64; 2]],
) {
    // The lengths from `out` (a constant for the fixed-size pieces, so the loops unroll).
    let n = out.len() - 1;
    let (points, work, tmp) = (&points[..=n], &mut work[..=n], &mut tmp[..=n]);
    if a == 0.0 && b == 1.0 {
        out.copy_from_slice(points);
        return;
    }
    work.copy_from_slice(points);
    for j in 0..=n {
        // The points P(b^j, ...) of the j-th level at b: at b = 1, exactly the last n + 1 - j
        // control points.
        let len = n + 1 - j;
        let level = if b == 1.0 { &points[j..] } else { &work[..len] };
        if a == 0.0 {
            out[j] = level[0];
        } else {
            tmp[..len].copy_from_slice(level);
            for k in (2..=len).rev() {
                lerp_step(&mut tmp[..k], a);
            }
            out[j] = tmp[0];
        }
        if j < n && b != 1.0 {
            lerp_step(&mut work[..len], b);
        }
    }
}

/// Whether the bounding boxes of the control points of `a` and `b`, enlarged by their errors
/// `ea` and `eb` (rounded outwards), meet.
#[inline(always)]
fn boxes_meet(a: &[[f64; 2]], ea: f64, b: &[[f64; 2]], eb: f64) -> bool {
    let bounds = |pts: &[[f64; 2]], e: f64| {
        let mut r = [pts[0][0], pts[0][0], pts[0][1], pts[0][1]];
        for xy in &pts[1..] {
            r[0] = r[0].min(xy[0]);
            r[1] = r[1].max(xy[0]);
            r[2] = r[2].min(xy[1]);
            r[3] = r[3].max(xy[1]);
        }
        [
            (r[0] - e).next_down(),
            (r[1] + e).next_up(),
            (r[2] - e).next_down(),
            (r[3] + e).next_up(),
        ]
    };
    let (x, y) = (bounds(a, ea), bounds(b, eb));
    x[0] <= y[1] && y[0] <= x[1] && x[2] <= y[3] && y[2] <= x[3]
}

/// Fat-line clipping of the piece `a` (control points within `a_reach - 3uM` of the exact
/// ones, see [`Curve::reach`]) against the fat line of the piece `b` (module documentation,
/// 1): `None` when no point of `a` lies on the fat line (no common point), else a range
/// [u0, u1] of `a`'s local parameter in [0, 1] outside which `a` has no common point with
/// `b`. [0, 1] when nothing is clipped.
#[inline(always)]
fn clip(a: &[[f64; 2]], a_reach: f64, b: &[[f64; 2]], b_reach: f64) -> Option<[f64; 2]> {
    let (first, last) = (b[0], b[b.len() - 1]);
    let normal = [first[1] - last[1], last[0] - first[0]];
    if normal == [0.0, 0.0] {
        return Some([0.0, 1.0]);
    }
    let dot = |xy: &[f64; 2]| normal[0] * xy[0] + normal[1] * xy[1];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for xy in b {
        let d = dot(xy);
        lo = lo.min(d);
        hi = hi.max(d);
    }
    // The margins of both pieces' distance coefficients, added to the band.
    let weight = upward(normal[0].abs() + normal[1].abs());
    let margin = upward(weight * (a_reach + b_reach) + 8.0 * ETA);
    let (low, high) = ((lo - margin).next_down(), (hi + margin).next_up());
    let n = a.len() - 1;
    let step = 1.0 / n as f64;
    // The hull of the points (i / n, D_i) against the band [low, high]: the least and largest
    // abscissa over the points inside the band and the crossings of the band's edges by the
    // segments between two points.
    // (Branch-free: a candidate that does not apply is replaced by ±∞. The inputs' bound
    // 1e90 keeps every D_i finite, and D_i - D_j != 0 where the sides differ.)
    let (mut u0, mut u1) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, pi) in a.iter().enumerate() {
        let di = dot(pi);
        let ui = i as f64 * step;
        let inside = low <= di && di <= high;
        u0 = u0.min(if inside { ui } else { f64::INFINITY });
        u1 = u1.max(if inside { ui } else { f64::NEG_INFINITY });
        for (j, pj) in a.iter().enumerate().skip(i + 1) {
            let dj = dot(pj);
            let uj = j as f64 * step;
            for edge in [low, high] {
                let crossing = ui + (uj - ui) * ((di - edge) / (di - dj));
                let applies = (di > edge) != (dj > edge);
                u0 = u0.min(if applies { crossing } else { f64::INFINITY });
                u1 = u1.max(if applies { crossing } else { f64::NEG_INFINITY });
            }
        }
    }
    if u0 > u1 {
        // No point in the band and no crossing: every point on one side.
        return None;
    }
    Some([(u0 - CLIP_SLACK).max(0.0), (u1 + CLIP_SLACK).min(1.0)])
}

/// The global range of the local range `u` of the piece over `range` ([a, b] doubles in
/// [0, 1]): outward rounded, inside `range`.
fn to_global(range: [f64; 2], u: [f64; 2]) -> [f64; 2] {
    let [a, b] = range;
    let w = b - a;
    // Each end a + u w is computed with an error below 3u b + η (three roundings of numbers
    // at most b), covered by the slack.
    let slack = 4.0 * UNIT_ROUNDOFF * b + ETA;
    let lo = if u[0] == 0.0 {
        a
    } else {
        ((a + u[0] * w) - slack).next_down().max(a)
    };
    let hi = if u[1] == 1.0 {
        b
    } else {
        ((a + u[1] * w) + slack).next_up().min(b)
    };
    [lo, hi.max(lo)]
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

/// Krawczyk's operator on the box `x`, with F(m) enclosed by `f`, P'(S) by `dp` and Q'(T) by
/// `dq` (module documentation, 2). `None` when the midpoint Jacobian is singular.
fn krawczyk(
    x: &Box2,
    f: [BoundedF64; 2],
    dp: [BoundedF64; 2],
    dq: [BoundedF64; 2],
) -> Option<Krawczyk> {
    // J = [[P'_x, -Q'_x], [P'_y, -Q'_y]] over the box; Y the inverse of its midpoint.
    let j = [[dp[0], dq[0].neg()], [dp[1], dq[1].neg()]];
    let a = j.map(|row| row.map(|e| e.value()));
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let y = [
        [a[1][1] / det, -a[0][1] / det],
        [-a[1][0] / det, a[0][0] / det],
    ]
    .map(|row| row.map(BoundedF64::exact));
    let radius = x.radius.map(|r| BoundedF64::with_bound(0.0, r));
    let offset = [0, 1].map(|i| {
        // -Y F(m) + sum_j (δ_ij - (Y J)_ij) (X - m)_j.
        let yf = y[i][0].mul(&f[0]).add(&y[i][1].mul(&f[1]));
        (0..2).fold(yf.neg(), |k, col| {
            let yj = y[i][0].mul(&j[0][col]).add(&y[i][1].mul(&j[1][col]));
            let identity = BoundedF64::exact(if i == col { 1.0 } else { 0.0 });
            k.add(&identity.sub(&yj).mul(&radius[col]))
        })
    });
    let proved = (0..2).all(|i| inside_radius(&offset[i], x.radius[i]));
    Some(Krawczyk { offset, proved })
}

/// F(m) = P(m_s) - Q(m_t) in double-double with a bound, per coordinate, with P(m_s).
fn residual_dd(p: &mut Curve, q: &mut Curve, m: [f64; 2]) -> ([Dd; 2], [Dd; 2]) {
    let (a, b) = (p.eval_dd(m[0]), q.eval_dd(m[1]));
    ([a[0].sub(&b[0]), a[1].sub(&b[1])], a)
}

/// Newton's method in `f64` from `start`: the point it converges to, if it does.
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
        let ds = (-dqt[1] * f[0] + dqt[0] * f[1]) / det;
        let dt = (-dps[1] * f[0] + dps[0] * f[1]) / det;
        s -= ds;
        t -= dt;
        if !((-1.0..=2.0).contains(&s) && (-1.0..=2.0).contains(&t)) {
            return None;
        }
        let step = ds.abs().max(dt.abs());
        if step <= 1e-15 {
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
/// else the root with its crossing when inside (0, 1)^2.
fn root_of(z: [f64; 2], pz: [Dd; 2], k: &Krawczyk, dp: [BoundedF64; 2]) -> Option<Root> {
    let s = BoundedF64::exact(z[0]).add(&k.offset[0]);
    let t = BoundedF64::exact(z[1]).add(&k.offset[1]);
    let tight = [[lower(&s), upper(&s)], [lower(&t), upper(&t)]];
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
    // P(s*) in P(z_s) + (s* - z_s) P'(S), coordinate by coordinate (mean value theorem).
    let point = [0, 1].map(|c| {
        let offset = pz[c].rest().add(&k.offset[0].mul(&dp[c]));
        round_nearest(pz[c].hi(), &offset)
    });
    Some(Root {
        tight,
        crossing: Some(CertifiedCrossing {
            s: round_nearest(z[0], &k.offset[0])?,
            t: round_nearest(z[1], &k.offset[1])?,
            s_enclosure: tight[0],
            t_enclosure: tight[1],
            point: [point[0]?, point[1]?],
        }),
    })
}

/// The search state: both curves, the pieces of the current cell, the proved roots and their
/// exclusion boxes, the stack of cells. Kept per thread and reused ([`with_search`]), so that
/// a call allocates only on its first use (or for larger curves than before).
struct Search {
    p: Curve,
    q: Curve,
    /// The pieces and scratch of curves beyond the fixed sizes ([`Pieces`]).
    pieces: Pieces<Vec<[f64; 2]>>,
    roots: Vec<Root>,
    /// Proved boxes (their inner ranges, [`Box2::inner`]), each with the index of its one
    /// root.
    exclusions: Vec<([[f64; 2]; 2], usize)>,
    /// Cells S x T still to examine.
    stack: Vec<([f64; 2], [f64; 2])>,
}

impl Search {
    fn empty() -> Self {
        Search {
            p: Curve::empty(),
            q: Curve::empty(),
            pieces: Pieces {
                p: Vec::new(),
                q: Vec::new(),
                work_p: Vec::new(),
                tmp_p: Vec::new(),
                work_q: Vec::new(),
                tmp_q: Vec::new(),
            },
            roots: Vec::new(),
            exclusions: Vec::new(),
            stack: Vec::new(),
        }
    }

    /// Krawczyk's test on a box containing the cell `s` x `t` (module documentation, 2 and
    /// 3): `Some(true)` when the cell is settled (its roots are the one root of a proved box,
    /// recorded), `Some(false)` when the test fails, `None` when a proved root is undecided.
    fn settle(&mut self, s: [f64; 2], t: [f64; 2]) -> Option<bool> {
        let centre = [0.5 * (s[0] + s[1]), 0.5 * (t[0] + t[1])];
        let half = [0.5 * (s[1] - s[0]), 0.5 * (t[1] - t[0])];
        let (p, q) = (&mut self.p, &mut self.q);
        p.prepare();
        q.prepare();
        // The box's centre: the cell's centre when the cell is tiny, else a Newton point near
        // it (a heuristic choice; the box contains the cell either way).
        let z = if half[0].max(half[1]) <= TINY_WIDTH {
            centre
        } else {
            newton(p, q, centre)
                .filter(|z| (0..2).all(|i| (z[i] - centre[i]).abs() <= 2.0 * half[i]))
                .unwrap_or(centre)
        };
        let cover = [0, 1].map(|i| {
            upward(COVER * ((z[i] - centre[i]).abs().next_up() + half[i])).max(TIGHT_RADIUS)
        });
        let (fdd, pz) = residual_dd(p, q, z);
        let f = fdd.map(|c| c.to_bounded());
        let outer = Box2 {
            mid: z,
            radius: cover,
        };
        let mut dp = p.tangent_pyramid(z[0], cover[0]);
        let dq = q.tangent_pyramid(z[1], cover[1]);
        let Some(mut k) = krawczyk(&outer, f, dp, dq).filter(|k| k.proved) else {
            return Some(false);
        };
        // A tighter box around z when the cover is large: 8 times the Newton correction.
        let wanted = [0, 1].map(|i| (8.0 * k.offset[i].value().abs()).max(TIGHT_RADIUS));
        if (0..2).any(|i| wanted[i] < cover[i]) {
            let radius = [0, 1].map(|i| wanted[i].min(cover[i]));
            let dp_inner = p.tangent_pyramid(z[0], radius[0]);
            let dq_inner = q.tangent_pyramid(z[1], radius[1]);
            let inner = Box2 { mid: z, radius };
            if let Some(k_inner) = krawczyk(&inner, f, dp_inner, dq_inner).filter(|k| k.proved) {
                // Its one root is the one root of the outer box, which contains it.
                (k, dp) = (k_inner, dp_inner);
            }
        }
        let root = root_of(z, pz, &k, dp)?;
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

/// Every crossing of the curves with control points `p` and `q` when the float filter proves
/// the complete answer: all intersections are transversal and inside (0, 1)^2 (see the module
/// documentation for what is proved and when the answer is `None`). Sorted by s then t.
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
    with_search(|search| search.run(p, q))
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

/// The control points of P over the current cell's s side and of Q over its t side, with
/// the scratch of [`restrict`].
#[derive(Default)]
struct Pieces<B> {
    p: B,
    q: B,
    work_p: B,
    tmp_p: B,
    work_q: B,
    tmp_q: B,
}

impl Search {
    /// [`certified_crossings_f64`] on this search state, which it resets first.
    fn run(&mut self, p: &[[f64; 2]], q: &[[f64; 2]]) -> Option<Vec<CertifiedCrossing>> {
        self.p.reset(p)?;
        self.q.reset(q)?;
        self.roots.clear();
        self.exclusions.clear();
        self.stack.clear();
        self.stack.push(([0.0, 1.0], [0.0, 1.0]));
        // The pieces in arrays for equal small degrees (unrolled), else in vectors.
        match (self.p.degree, self.q.degree) {
            (1, 1) => self.cells(&mut Pieces::<[[f64; 2]; 2]>::default())?,
            (2, 2) => self.cells(&mut Pieces::<[[f64; 2]; 3]>::default())?,
            (3, 3) => self.cells(&mut Pieces::<[[f64; 2]; 4]>::default())?,
            (n, m) => {
                let mut pieces = std::mem::take(&mut self.pieces);
                for (v, len) in [
                    (&mut pieces.p, n + 1),
                    (&mut pieces.work_p, n + 1),
                    (&mut pieces.tmp_p, n + 1),
                    (&mut pieces.q, m + 1),
                    (&mut pieces.work_q, m + 1),
                    (&mut pieces.tmp_q, m + 1),
                ] {
                    v.clear();
                    v.resize(len, [0.0; 2]);
                }
                let done = self.cells(&mut pieces);
                self.pieces = pieces;
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
    /// when undecided.
    #[inline(always)]
    fn cells<B: AsRef<[[f64; 2]]> + AsMut<[[f64; 2]]>>(
        &mut self,
        pieces: &mut Pieces<B>,
    ) -> Option<()> {
        let Pieces {
            p: piece_p,
            q: piece_q,
            work_p,
            tmp_p,
            work_q,
            tmp_q,
        } = pieces;
        let (piece_p, piece_q) = (piece_p.as_mut(), piece_q.as_mut());
        let (work_p, tmp_p, work_q, tmp_q) = (
            work_p.as_mut(),
            tmp_p.as_mut(),
            work_q.as_mut(),
            tmp_q.as_mut(),
        );
        let (pe, qe, pr, qr) = (self.p.error, self.q.error, self.p.reach, self.q.reach);
        let mut steps = 0usize;
        while let Some((mut s, mut t)) = self.stack.pop() {
            restrict(&self.p.points, s, piece_p, work_p, tmp_p);
            restrict(&self.q.points, t, piece_q, work_q, tmp_q);
            loop {
                steps += 1;
                if steps > MAX_STEPS {
                    return None;
                }
                if self.excluded(s, t) || !boxes_meet(piece_p, pe, piece_q, qe) {
                    break;
                }
                let (ws, wt) = (s[1] - s[0], t[1] - t[0]);
                let Some(u) = clip(piece_p, pr, piece_q, qr) else {
                    break;
                };
                if u != [0.0, 1.0] {
                    s = to_global(s, u);
                    restrict(&self.p.points, s, piece_p, work_p, tmp_p);
                }
                let Some(v) = clip(piece_q, qr, piece_p, pr) else {
                    break;
                };
                if v != [0.0, 1.0] {
                    t = to_global(t, v);
                    restrict(&self.q.points, t, piece_q, work_q, tmp_q);
                }
                let (ws2, wt2) = (s[1] - s[0], t[1] - t[0]);
                let stalled = ws2 > PROGRESS * ws && wt2 > PROGRESS * wt;
                let size = ws2.max(wt2);
                if size <= TINY_WIDTH || (stalled && size <= SETTLE_WIDTH) {
                    if self.settle(s, t)? {
                        break;
                    }
                } else if !stalled {
                    continue;
                }
                // Stalled (or not settled): halve the wider side.
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
