//! The float filter of curve-curve intersection: the common transversal case of two 2-D
//! Bézier curves with `f64` control points, certified in floating point, no big numbers.
//!
//! The problem is F(s, t) = P(s) - Q(t) = 0 on [0, 1]^2. The filter answers only when it has
//! *proved* the complete answer; otherwise it says `None` and the exact path
//! ([`super::curves::intersect_curves_f64`]) answers. What it proves:
//!
//! **1. Every root lies in a surviving cell.** P over S and Q over T are halved by the
//! library's de Casteljau split ([`crate::shape::halving::curve_split`] at 1/2, in plain
//! `f64`). A cell S x T is dropped when the bounding boxes of the two pieces' control points,
//! each enlarged by a rigorous bound E on the split's rounding, are disjoint (a piece lies in
//! the convex hull of its exact control points), or when the fat lines (the bands orthogonal to
//! either piece's chord that hold its control points, with a rigorous rounding margin) are
//! disjoint. The bound E is a priori: one halving step
//! computes v' = fl(x + fl(0.5 fl(y - x))) from values |x|, |y| <= M, and
//! |v' - (x + y) / 2| <= u |y - x| / 2 + η / 2 + u |x + h| <= 2u M (1 + u) + 2η
//! (u = 2^-53; halving is exact but for underflow; sums have no underflow error), while the
//! exact average of perturbed inputs moves by at most the inputs' error. A control point of a
//! piece after d halvings has gone through at most d n such steps, so
//! E(d) = d n β with β = 2u M0 (1 + 2^-19) + 2η, M0 the largest input coordinate (computed
//! values stay within M0 (1 + 2^-20), which the margin covers; inputs with M0 outside
//! [2^-900, 2^900] are left to the exact path).
//!
//! **2. Krawczyk's test proves one root in a box.** For a box X = m ± r (midpoint m and
//! radius r > 0 doubles, in (s, t)), with Y an approximate inverse of the Jacobian
//! J = [P'(s) | -Q'(t)] at m,
//! K(X) = m - Y F(m) + (I - Y J(X)) (X - m),
//! evaluated in interval arithmetic ([`BoundedF64`] as midpoint-radius intervals, see
//! [`super::interval`]; de Casteljau's steps in convex form, [`ConvexStep`], so that the
//! bounds do not grow geometrically with the degree): F(m) from de Casteljau at the double m, J(X) from de Casteljau of the
//! hodographs n (p_(i+1) - p_i) (the library's [`crate::bezier_derivative`], its rounding
//! bounded by `BoundedF64`) restricted to S and T by the library's engine, whose control
//! points' hull encloses P'(S) and Q'(T). By the
//! mean value theorem row by row, every root of F in X lies in K(X); K(X) ⊂ X gives a root
//! (Brouwer), and K(X) in the interior of X gives exactly one, with every matrix A of J(X)
//! nonsingular: the radius of K is at least |I - Y A| r, so |I - Y A| r < r for the positive
//! vector r, hence the spectral radius of I - Y A is below 1. The Jacobian at the root is
//! then nonsingular, i.e. cross(P'(s), Q'(t)) != 0: the crossing is transversal and
//! `tangent` is false, exactly. A surviving cell is tried around a Newton point z: one found
//! before that lies in the cell, else Newton's method in `f64` from the chords' crossing
//! when they nearly cross (a new point; one that converges to a known point outside the cell
//! leaves the cell to be halved). When z is near the cell, the box B centred at z with radii
//! |z - centre| + half width (rounded up) contains the cell, and Krawczyk's test on B is
//! tried unless B is more than `REACH` times larger than z's *reach* 1 / (2 |J(z)^-1| D), D
//! bounding |P''| and |Q''| (a plain-`f64` estimate of where the test can succeed, used
//! only to skip tests bound to fail: the cell is then halved). Newton points, their F
//! enclosures and all storage are kept per thread and reused, so a call allocates nothing
//! after the first (but its answer). A proved B is an *exclusion box*: its one root is
//! the only one in B, so every later cell inside B is dropped. Boxes centred on the Newton
//! point keep the root away from the box's boundary, so roots on the cells' dyadic edges need
//! no special case. Around a new root a box `INFLATE` times as large is tried too, to settle
//! the neighbouring cells at once. Cells whose test fails are halved again (both curves).
//!
//! **3. A tight enclosure and correct rounding.** For a proved B, a second Krawczyk step on
//! the small box z ± r' (r' = max(8 |Y F(z)|, 2^-48), inside B) with F(z) evaluated in
//! double-double ([`Dd`], de Casteljau with a rigorous bound near n^2 u^2 M) encloses the root
//! as s* in z_s + Δ_s, t* in z_t + Δ_t with |Δ| ~ 1e-16 and a width near 1e-28. The correctly
//! rounded s and t (ties to even) are decided from these offsets against the half-ulp
//! boundaries ([`round_nearest`]); the common point from P(s*) in P(z_s) + Δ_s P'(S'), also
//! correctly rounded, so that the filter's answer equals the exact path's bit for bit.
//!
//! **4. The answer.** Distinct proved roots have disjoint tight enclosures; two whose
//! enclosures meet are one root when one enclosure lies in the other's exclusion box. A root
//! whose enclosure lies outside [0, 1]^2 is not reported; one inside (0, 1)^2 is. Once every
//! cell is dropped, the proved roots inside are all the intersections, sorted by s then t.
//!
//! **Undecided (`None`)**, for the exact path: a tight enclosure touching s or t in {0, 1}
//! (end-point contacts are decided exactly), enclosures that meet without being the same root,
//! a rounding not decided by the enclosure (a common point with a zero coordinate among them),
//! more than `MAX_CELLS` cells or a side below 2^-`MAX_LEVEL` (tangency, near-coincident
//! roots, overlapping or identical curves, where Krawczyk's test cannot succeed), a curve that
//! is a single point, non-finite or extreme input.

use super::interval::{from_bounds, inside_radius, lower, round_nearest, upper, ConvexStep, Dd};
use crate::num::bounded::{upward, BoundedF64, ETA, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::shape::flat::curve_pyramid_in_place;
use crate::shape::halving::curve_split;
use crate::shape::halving::{curve_net, step_left, BernsteinStep};

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

/// No side is halved below 2^-MAX_LEVEL.
const MAX_LEVEL: u32 = 40;
/// At most this many cells are examined.
const MAX_CELLS: usize = 4000;
/// Newton iterations from a cell's start point.
const NEWTON_STEPS: usize = 12;
/// The factor of the larger exclusion box tried around a new root.
const INFLATE: f64 = 4.0;
/// The least radius of the final Krawczyk box.
const TIGHT_RADIUS: f64 = 1.0 / (1u64 << 48) as f64;

/// One curve: its control points in the forms the filter needs, its subdivision tree, and
/// scratch space.
struct Curve {
    /// Degree n.
    degree: usize,
    /// Control points, flat (x0, y0, x1, y1, ...).
    points: Vec<f64>,
    /// The same, as exact intervals.
    exact: Vec<BoundedF64>,
    /// The same, as double-doubles.
    dd: Vec<Dd>,
    /// The hodograph's control points with their rounding bounds.
    hodograph: Vec<BoundedF64>,
    /// n (n - 1) max |Δ² p_i| over both coordinates: a bound on |P''| (plain `f64`, for the
    /// heuristic reach of a Newton point only).
    second_bound: f64,
    /// β of the module documentation: the error bound of one halving step.
    step_error: f64,
    /// Control points of the pieces, `2 (n + 1)` doubles each.
    pieces: Vec<f64>,
    /// The pieces' parameter intervals, bounding boxes and halves.
    nodes: Vec<Node>,
    /// Scratch.
    level: Vec<f64>,
    level_dd: Vec<Dd>,
    level_bounded: Vec<BoundedF64>,
    net_scratch: Vec<BoundedF64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

/// A piece of a curve: over [start, start + 2^-level], its control points' bounding box
/// [x_lo, x_hi, y_lo, y_hi] enlarged by the split's error bound, its halves once split.
#[derive(Clone, Copy)]
struct Node {
    start: f64,
    level: u32,
    bbox: [f64; 4],
    /// E(level): the bound on the distance of each computed control point coordinate to the
    /// exact one.
    error: f64,
    children: Option<[usize; 2]>,
}

impl Curve {
    /// A curve with no control points and empty storage, to be [`Curve::reset`].
    fn empty() -> Self {
        Curve {
            degree: 0,
            points: Vec::new(),
            exact: Vec::new(),
            dd: Vec::new(),
            hodograph: Vec::new(),
            step_error: 0.0,
            second_bound: 0.0,
            pieces: Vec::new(),
            nodes: Vec::new(),
            level: Vec::new(),
            level_dd: Vec::new(),
            level_bounded: Vec::new(),
            net_scratch: Vec::new(),
            left: Vec::new(),
            right: Vec::new(),
        }
    }

    /// Makes this the curve with control points `p`, reusing the storage, or `None` when the
    /// filter does not take it (fewer than two points, a non-finite or extreme coordinate, a
    /// single point).
    fn reset(&mut self, p: &[[f64; 2]]) -> Option<()> {
        if p.len() < 2 || p.iter().flatten().any(|c| !c.is_finite()) {
            return None;
        }
        if p.iter().all(|c| c == &p[0]) {
            return None;
        }
        let m0 = p.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
        if !(m0 >= 2f64.powi(-900) && m0 <= 2f64.powi(900)) {
            return None;
        }
        self.degree = p.len() - 1;
        self.points.clear();
        self.points.extend(p.iter().flatten());
        self.exact.clear();
        self.exact
            .extend(self.points.iter().map(|&x| BoundedF64::exact(x)));
        self.dd.clear();
        self.dd.extend(self.points.iter().map(|&x| Dd::exact(x)));
        // The hodograph n (p_(i+1) - p_i), its rounding bounded.
        let n = BoundedF64::exact(self.degree as f64);
        self.hodograph.clear();
        self.hodograph.extend(
            self.exact
                .iter()
                .zip(&self.exact[2..])
                .map(|(a, b)| b.sub(a).mul(&n)),
        );
        let n = self.degree as f64;
        self.second_bound = n
            * (n - 1.0)
            * p.windows(3)
                .flat_map(|w| (0..2).map(move |c| (w[2][c] - 2.0 * w[1][c] + w[0][c]).abs()))
                .fold(0.0, f64::max);
        self.step_error = upward(2.0 * UNIT_ROUNDOFF * m0 * (1.0 + 2f64.powi(-19)) + 2.0 * ETA);
        self.pieces.clear();
        self.nodes.clear();
        let len = self.points.len();
        self.left.resize(len, 0.0);
        self.right.resize(len, 0.0);
        let whole = std::mem::take(&mut self.left);
        let mut whole = whole;
        whole.copy_from_slice(&self.points);
        self.push_piece(&whole, 0.0, 0);
        self.left = whole;
        Some(())
    }

    /// Appends a piece with control points `coords` over [start, start + 2^-level].
    fn push_piece(&mut self, coords: &[f64], start: f64, level: u32) -> usize {
        let mut b = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for xy in coords.chunks_exact(2) {
            b[0] = b[0].min(xy[0]);
            b[1] = b[1].max(xy[0]);
            b[2] = b[2].min(xy[1]);
            b[3] = b[3].max(xy[1]);
        }
        let e = upward(f64::from(level) * self.degree as f64 * self.step_error);
        let bbox = [
            (b[0] - e).next_down(),
            (b[1] + e).next_up(),
            (b[2] - e).next_down(),
            (b[3] + e).next_up(),
        ];
        self.pieces.extend_from_slice(coords);
        self.nodes.push(Node {
            start,
            level,
            bbox,
            error: e,
            children: None,
        });
        self.nodes.len() - 1
    }

    /// The control points of piece `i`.
    fn piece(&self, i: usize) -> &[f64] {
        let stride = self.points.len();
        &self.pieces[i * stride..(i + 1) * stride]
    }

    /// The halves of piece `i` (the library's de Casteljau split at 1/2), split on first use.
    fn children(&mut self, i: usize) -> [usize; 2] {
        if let Some(c) = self.nodes[i].children {
            return c;
        }
        let Node { start, level, .. } = self.nodes[i];
        let (mut left, mut right) = (
            std::mem::take(&mut self.left),
            std::mem::take(&mut self.right),
        );
        curve_split(self.piece(i), 2, &0.5, &mut left, &mut right);
        let a = self.push_piece(&left, start, level + 1);
        let b = self.push_piece(&right, start + width(level + 1), level + 1);
        (self.left, self.right) = (left, right);
        self.nodes[i].children = Some([a, b]);
        [a, b]
    }

    /// P(s) and P'(s) in plain `f64` (for Newton's method only): n - 1 de Casteljau steps
    /// leave the segment b0 b1 with P(s) = b0 + s (b1 - b0) and P'(s) = n (b1 - b0).
    fn eval_f64(&mut self, s: f64) -> ([f64; 2], [f64; 2]) {
        let level = &mut self.level;
        level.clear();
        level.extend_from_slice(&self.points);
        let (len, step) = (level.len(), BernsteinStep(&s));
        for r in 0..self.degree - 1 {
            step_left(&mut level[..len - 2 * r], 2, &step);
        }
        let d = [level[2] - level[0], level[3] - level[1]];
        let n = self.degree as f64;
        (
            [level[0] + s * d[0], level[1] + s * d[1]],
            [n * d[0], n * d[1]],
        )
    }

    /// An enclosure of P at the double `s` (the pyramid in convex form, [`ConvexStep`]).
    fn eval_bounded(&mut self, s: f64) -> [BoundedF64; 2] {
        let level = &mut self.level_bounded;
        level.clear();
        level.extend_from_slice(&self.exact);
        curve_pyramid_in_place(level, 2, &ConvexStep::new(BoundedF64::exact(s)));
        [level[0], level[1]]
    }

    /// P at the double `s` in double-double with a bound (the pyramid in convex form,
    /// [`ConvexStep`]).
    fn eval_dd(&mut self, s: f64) -> [Dd; 2] {
        self.level_dd.clear();
        self.level_dd.extend_from_slice(&self.dd);
        curve_pyramid_in_place(&mut self.level_dd, 2, &ConvexStep::new(Dd::exact(s)));
        [self.level_dd[0], self.level_dd[1]]
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius: the hull of the
    /// hodograph's control points over [a, b] ⊇ [mid - radius, mid + radius] (the engine's
    /// restriction net at the exact double ends a, b in convex form, its rounding bounded by
    /// `BoundedF64`), which holds the hodograph over [a, b] by the convex hull property.
    fn tangent_hull(&mut self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        let a = ConvexStep::new(BoundedF64::exact((mid - radius).next_down()));
        let b = ConvexStep::new(BoundedF64::exact((mid + radius).next_up()));
        let net = &mut self.level_bounded;
        net.clear();
        net.resize(self.hodograph.len(), BoundedF64::zero());
        curve_net(&self.hodograph, 2, &a, &b, net, &mut self.net_scratch);
        // The least and largest fl(v -+ e) per coordinate, pushed outwards once: next_down and
        // next_up are monotone, so this is the hull of the intervals [lower, upper].
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for xy in net.chunks_exact(2) {
            for c in 0..2 {
                let (v, e) = (xy[c].value(), xy[c].error_bound());
                lo[c] = lo[c].min(v - e);
                hi[c] = hi[c].max(v + e);
            }
        }
        [0, 1].map(|c| from_bounds(lo[c].next_down(), hi[c].next_up()))
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius: de Casteljau's pyramid at
    /// the interval argument in convex form, whose width grows only linearly with the degree
    /// (each level adds about 2 radius max |x|); cheaper than [`Curve::tangent_hull`] and as
    /// good for the tiny boxes of the final step.
    fn tangent_pyramid(&mut self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        let level = &mut self.level_bounded;
        level.clear();
        level.extend_from_slice(&self.hodograph);
        let step = ConvexStep::new(BoundedF64::with_bound(mid, radius));
        curve_pyramid_in_place(level, 2, &step);
        [level[0], level[1]]
    }
}

/// 2^-level.
fn width(level: u32) -> f64 {
    // The exponent field of 2^-level (level <= MAX_LEVEL, a normal double).
    f64::from_bits(u64::from(1023 - level) << 52)
}

/// Whether the fat line of piece `a` (the band, orthogonal to the chord of `a`, that holds
/// its exact control points) misses every exact control point of piece `b`; coordinates of
/// the pieces within `ea` and `eb` of the exact ones. With any double vector n (the chord's
/// normal, computed), the exact n·x of an exact control point x lies within
/// (|n_x| + |n_y|) E + 3u (|n_x| |c_x| + |n_y| |c_y|) + 4η of the computed n·c (two
/// products and a sum, rounded); a curve lies in the hull of its control points, so disjoint
/// bands of the two pieces mean no common point.
fn fat_line_separates(a: &[f64], ea: f64, b: &[f64], eb: f64) -> bool {
    let k = a.len() - 2;
    let n = [a[1] - a[k + 1], a[k] - a[0]];
    if n == [0.0, 0.0] {
        return false;
    }
    let weight = [n[0].abs(), n[1].abs()];
    // |n_x| |c_x| + |n_y| |c_y| <= |n_x| max |c_x| + |n_y| max |c_y| =: size.
    let band = |pts: &[f64], e: f64| {
        let (mut lo, mut hi, mut cx, mut cy) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, 0.0f64);
        for c in pts.chunks_exact(2) {
            let d = n[0] * c[0] + n[1] * c[1];
            lo = lo.min(d);
            hi = hi.max(d);
            cx = cx.max(c[0].abs());
            cy = cy.max(c[1].abs());
        }
        let size = weight[0] * cx + weight[1] * cy;
        let margin = upward((weight[0] + weight[1]) * e + 3.0 * UNIT_ROUNDOFF * size + 4.0 * ETA);
        ((lo - margin).next_down(), (hi + margin).next_up())
    };
    let (a_lo, a_hi) = band(a, ea);
    let (b_lo, b_hi) = band(b, eb);
    a_hi < b_lo || b_hi < a_lo
}

/// A box in (s, t): midpoint and radii, standing for m ± r exactly.
#[derive(Clone, Copy, Debug)]
struct Box2 {
    mid: [f64; 2],
    radius: [f64; 2],
}

impl Box2 {
    /// Whether [s0, s1] x [t0, t1] lies inside the box (decided conservatively).
    fn contains(&self, s: [f64; 2], t: [f64; 2]) -> bool {
        let inside =
            |m: f64, r: f64, lo: f64, hi: f64| (m - r).next_up() <= lo && hi <= (m + r).next_down();
        inside(self.mid[0], self.radius[0], s[0], s[1])
            && inside(self.mid[1], self.radius[1], t[0], t[1])
    }
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

/// Newton's method in `f64` from `start`: the point it converges to, if it does, and the
/// last Jacobian [[P'_x, -Q'_x], [P'_y, -Q'_y]] as (P', Q').
fn newton(p: &mut Curve, q: &mut Curve, start: [f64; 2]) -> Option<([f64; 2], [[f64; 2]; 2])> {
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
            return Some(([s, t], [dps, dqt]));
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

/// Where the chords of the pieces `a` (over `s`) and `b` (over `t`) cross, as parameters, when
/// they nearly do: the start of Newton's method (a heuristic; nothing is proved from it).
fn chord_start(a: &[f64], b: &[f64], s: [f64; 2], t: [f64; 2]) -> Option<[f64; 2]> {
    let (n, m) = (a.len() - 2, b.len() - 2);
    let da = [a[n] - a[0], a[n + 1] - a[1]];
    let db = [b[m] - b[0], b[m + 1] - b[1]];
    let r = [b[0] - a[0], b[1] - a[1]];
    // a0 + u da = b0 + v db.
    let det = da[0] * (-db[1]) + db[0] * da[1];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let u = (r[0] * (-db[1]) + db[0] * r[1]) / det;
    let v = (da[0] * r[1] - da[1] * r[0]) / det;
    let near = |x: f64| (-0.5..=1.5).contains(&x);
    (near(u) && near(v)).then(|| [s[0] + u * (s[1] - s[0]), t[0] + v * (t[1] - t[0])])
}

/// A proved root: its tight enclosure, and the reported crossing when it lies inside the
/// domain.
struct Root {
    tight: [[f64; 2]; 2],
    crossing: Option<CertifiedCrossing>,
}

/// The tight certification of the root proved in `b` (module documentation, 3), from F and P
/// at its centre in double-double: `None` when undecided, else the root (with its crossing
/// when inside (0, 1)^2).
fn certify(p: &mut Curve, q: &mut Curve, b: &Box2) -> Option<Root> {
    let z = b.mid;
    let (fdd, pz) = residual_dd(p, q, z);
    let f = fdd.map(|c| c.to_bounded());
    let mut radius = [TIGHT_RADIUS; 2];
    let mut k;
    let mut dp;
    let mut tries = 0;
    loop {
        dp = p.tangent_pyramid(z[0], radius[0]);
        let dq = q.tangent_pyramid(z[1], radius[1]);
        k = krawczyk(&Box2 { mid: z, radius }, f, dp, dq)?;
        // The Newton correction sets the radius: 8 times it, at least TIGHT_RADIUS.
        let wanted = [0, 1].map(|i| (8.0 * k.offset[i].value().abs()).max(TIGHT_RADIUS));
        tries += 1;
        if k.proved || tries == 2 || wanted == radius {
            break;
        }
        radius = wanted;
    }
    if !k.proved || radius[0] > b.radius[0] || radius[1] > b.radius[1] {
        return None;
    }
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

/// A point where Newton's method converged, with an enclosure of F there: the centre of the
/// Krawczyk boxes tried for the cells that contain it (a heuristic choice of centre; nothing is
/// proved from it).
#[derive(Clone, Copy)]
struct Guess {
    z: [f64; 2],
    f: [BoundedF64; 2],
    /// The radius below which Krawczyk's test is expected to succeed around z (an estimate
    /// from the second derivatives, [`REACH`]).
    reach: f64,
}

/// The search state: both curves, the proved roots and their exclusion boxes, the Newton
/// points found so far, the stack of cells. Kept per thread and reused ([`with_search`]), so
/// that a call allocates only on its first use (or for larger curves than before).
struct Search {
    p: Curve,
    q: Curve,
    roots: Vec<Root>,
    /// Proved boxes, each with the index of its one root.
    exclusions: Vec<(Box2, usize)>,
    guesses: Vec<Guess>,
    stack: Vec<(usize, usize)>,
}

/// Krawczyk's test is tried on boxes up to this many times a Newton point's reach (a
/// heuristic that saves tests bound to fail; a skipped cell is halved).
const REACH: f64 = 4.0;

/// Two Newton points closer than this (in s and t) are taken as the same point (a heuristic:
/// it only decides whether a Krawczyk box is tried or the cell is halved).
const SAME_POINT: f64 = 1e-12;

impl Search {
    fn empty() -> Self {
        Search {
            p: Curve::empty(),
            q: Curve::empty(),
            roots: Vec::new(),
            exclusions: Vec::new(),
            guesses: Vec::new(),
            stack: Vec::new(),
        }
    }

    /// The centre of the Krawczyk box for the cell `s` x `t`: a known Newton point inside the
    /// cell, else Newton's method from `start` (the chords' crossing) when it converges to a
    /// new point, or to a known one inside the cell's neighbourhood (a known point outside the
    /// cell is left to the cell that holds it: `None`, the cell is halved).
    fn guess(&mut self, s: [f64; 2], t: [f64; 2], start: Option<[f64; 2]>) -> Option<Guess> {
        let inside = |z: [f64; 2]| s[0] <= z[0] && z[0] <= s[1] && t[0] <= z[1] && z[1] <= t[1];
        if let Some(g) = self.guesses.iter().find(|g| inside(g.z)) {
            return Some(*g);
        }
        let (z, [dp, dq]) = newton(&mut self.p, &mut self.q, start?)?;
        let same = |g: &Guess| (0..2).all(|i| (g.z[i] - z[i]).abs() <= SAME_POINT);
        if self.guesses.iter().any(same) {
            return None;
        }
        let (pz, qz) = (self.p.eval_bounded(z[0]), self.q.eval_bounded(z[1]));
        // Krawczyk's contraction on a box of radius r is about 2 |J^-1| D r, D bounding the
        // second derivatives: the reach r = 1 / (2 |J^-1| D).
        let det = (-dp[0] * dq[1] + dq[0] * dp[1]).abs();
        let inverse = (dq[1].abs() + dq[0].abs()).max(dp[1].abs() + dp[0].abs()) / det;
        let curvature = self.p.second_bound.max(self.q.second_bound);
        let g = Guess {
            z,
            f: [pz[0].sub(&qz[0]), pz[1].sub(&qz[1])],
            reach: 1.0 / (2.0 * inverse * curvature),
        };
        self.guesses.push(g);
        Some(g)
    }

    /// Krawczyk's test on the box around a Newton point that contains the cell `s` x `t`
    /// (module documentation, 2): whether the cell is settled, `None` when a proved root is
    /// undecided.
    fn try_cell(&mut self, s: [f64; 2], t: [f64; 2], start: Option<[f64; 2]>) -> Option<bool> {
        let centre = [0.5 * (s[0] + s[1]), 0.5 * (t[0] + t[1])];
        let half = [0.5 * (s[1] - s[0]), 0.5 * (t[1] - t[0])];
        let Some(Guess { z, f, reach }) = self.guess(s, t, start) else {
            return Some(false);
        };
        let far = |i: usize| (z[i] - centre[i]).abs() > 2.0 * half[i];
        if far(0) || far(1) {
            return Some(false);
        }
        let (p, q) = (&mut self.p, &mut self.q);
        let radius = [0, 1].map(|i| ((z[i] - centre[i]).abs().next_up() + half[i]).next_up());
        if radius[0].max(radius[1]) > REACH * reach {
            return Some(false);
        }
        let b = Box2 { mid: z, radius };
        let dp = p.tangent_hull(z[0], radius[0]);
        let dq = q.tangent_hull(z[1], radius[1]);
        if !krawczyk(&b, f, dp, dq).is_some_and(|k| k.proved) {
            return Some(false);
        }
        // A known root inside the box is its one root.
        let known = self
            .roots
            .iter()
            .position(|r| b.contains(r.tight[0], r.tight[1]));
        let index = match known {
            Some(index) => index,
            None => {
                let root = certify(p, q, &b)?;
                let index = self.add_root(root)?;
                let (p, q) = (&mut self.p, &mut self.q);
                // A new root: try a box INFLATE times as large, whose one root is then this
                // one too (it contains b), so that the neighbouring cells of the root are
                // settled without another Newton run.
                let big = Box2 {
                    mid: z,
                    radius: radius.map(|r| INFLATE * r),
                };
                let dp = p.tangent_hull(z[0], big.radius[0]);
                let dq = q.tangent_hull(z[1], big.radius[1]);
                if krawczyk(&big, f, dp, dq).is_some_and(|k| k.proved) {
                    self.exclusions.push((big, index));
                }
                index
            }
        };
        self.exclusions.push((b, index));
        Some(b.contains(s, t))
    }

    /// Adds a newly certified root, or finds it among the known ones: its index, `None` when
    /// its enclosure meets another's without being the same root.
    fn add_root(&mut self, root: Root) -> Option<usize> {
        let meets = |a: &[[f64; 2]; 2], b: &[[f64; 2]; 2]| {
            (0..2).all(|k| a[k][0] <= b[k][1] && b[k][0] <= a[k][1])
        };
        for (index, known) in self.roots.iter().enumerate() {
            if meets(&known.tight, &root.tight) {
                // The same root when the new enclosure lies in a box proved for the known one.
                let same = self
                    .exclusions
                    .iter()
                    .any(|(e, k)| *k == index && e.contains(root.tight[0], root.tight[1]));
                return same.then_some(index);
            }
        }
        self.roots.push(root);
        Some(self.roots.len() - 1)
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

impl Search {
    /// [`certified_crossings_f64`] on this search state, which it resets first.
    fn run(&mut self, p: &[[f64; 2]], q: &[[f64; 2]]) -> Option<Vec<CertifiedCrossing>> {
        self.p.reset(p)?;
        self.q.reset(q)?;
        self.roots.clear();
        self.exclusions.clear();
        self.guesses.clear();
        self.stack.clear();
        self.stack.push((0, 0));
        let mut examined = 0usize;
        while let Some((i, j)) = self.stack.pop() {
            examined += 1;
            if examined > MAX_CELLS {
                return None;
            }
            let (a, b) = (self.p.nodes[i], self.q.nodes[j]);
            if a.bbox[1] < b.bbox[0]
                || b.bbox[1] < a.bbox[0]
                || a.bbox[3] < b.bbox[2]
                || b.bbox[3] < a.bbox[2]
            {
                continue;
            }
            let (pa, qb) = (self.p.piece(i), self.q.piece(j));
            if fat_line_separates(pa, a.error, qb, b.error)
                || fat_line_separates(qb, b.error, pa, a.error)
            {
                continue;
            }
            let s = [a.start, a.start + width(a.level)];
            let t = [b.start, b.start + width(b.level)];
            if self.exclusions.iter().any(|(e, _)| e.contains(s, t)) {
                continue;
            }
            let start = chord_start(pa, qb, s, t);
            if self.try_cell(s, t, start)? {
                continue;
            }
            if a.level >= MAX_LEVEL || b.level >= MAX_LEVEL {
                return None;
            }
            let [p0, p1] = self.p.children(i);
            let [q0, q1] = self.q.children(j);
            self.stack.extend([(p1, q1), (p1, q0), (p0, q1), (p0, q0)]);
        }
        let mut out: Vec<CertifiedCrossing> =
            self.roots.iter().filter_map(|r| r.crossing).collect();
        out.sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
        Some(out)
    }
}
