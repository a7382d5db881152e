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
//! the convex hull of its exact control points). The bound is a priori: one halving step
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
//! `tangent` is false, exactly. A surviving cell is tried once both its sides are at most
//! 2^-`PROOF_LEVEL`: Newton's method in `f64` from its centre; when it converges to z near the
//! cell, the box B centred at z with radii |z - centre| + half width (rounded up) contains the
//! cell, and Krawczyk's test on B is tried. A proved B is an *exclusion box*: its one root is
//! the only one in B, so every later cell inside B is dropped. Boxes centred on the Newton
//! point keep the root away from the box's boundary, so roots on the cells' dyadic edges need
//! no special case. Cells whose test fails are halved again (both curves).
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

use super::interval::{
    from_bounds, inside_radius, lower, outside_radius, round_nearest, upper, ConvexStep, Dd,
};
use crate::num::bounded::{upward, BoundedF64, ETA, UNIT_ROUNDOFF};
use crate::num::ring::Ring;
use crate::shape::bezier::BezierCurve;
use crate::shape::flat::{curve_eval_into, curve_pyramid_in_place};
use crate::shape::halving::curve_net;
use crate::shape::halving::curve_split;

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

/// Cells are tried by Newton and Krawczyk once both sides are at most 2^-PROOF_LEVEL.
const PROOF_LEVEL: u32 = 1;
/// No side is halved below 2^-MAX_LEVEL.
const MAX_LEVEL: u32 = 40;
/// At most this many cells are examined.
const MAX_CELLS: usize = 4000;
/// Newton iterations from a cell's centre.
const NEWTON_STEPS: usize = 16;
/// The least radius of the final Krawczyk box.
const TIGHT_RADIUS: f64 = 1.0 / (1u64 << 48) as f64;

/// One curve: its control points in the forms the filter needs, and its subdivision tree.
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
    /// The hodograph's control points as plain doubles (the values of `hodograph`).
    hodograph_f64: Vec<f64>,
    /// β of the module documentation: the error bound of one halving step.
    step_error: f64,
    /// Control points of the pieces, `2 (n + 1)` doubles each.
    pieces: Vec<f64>,
    /// Per piece: start of its parameter interval, its level (width 2^-level), its enlarged
    /// bounding box [x_lo, x_hi, y_lo, y_hi], and its halves once split.
    nodes: Vec<Node>,
    /// Scratch for evaluation and splitting.
    level: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

#[derive(Clone, Copy)]
struct Node {
    start: f64,
    level: u32,
    bbox: [f64; 4],
    children: Option<[usize; 2]>,
}

impl Curve {
    /// The curve with control points `p`, or `None` when the filter does not take it (fewer
    /// than two points, a non-finite or extreme coordinate, a single point).
    fn new(p: &[[f64; 2]]) -> Option<Self> {
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
        let points: Vec<f64> = p.iter().flatten().copied().collect();
        let exact: Vec<BoundedF64> = points.iter().map(|&x| BoundedF64::exact(x)).collect();
        let dd = points.iter().map(|&x| Dd::exact(x)).collect();
        let hodograph = BezierCurve::from_raw(2, exact.clone())
            .deriv()
            .coordinates()
            .to_vec();
        let hodograph_f64 = hodograph.iter().map(BoundedF64::value).collect();
        let step_error = upward(2.0 * UNIT_ROUNDOFF * m0 * (1.0 + 2f64.powi(-19)) + 2.0 * ETA);
        let mut curve = Curve {
            degree: p.len() - 1,
            points: points.clone(),
            exact,
            dd,
            hodograph,
            hodograph_f64,
            step_error,
            pieces: Vec::new(),
            nodes: Vec::new(),
            level: Vec::new(),
            left: vec![0.0; points.len()],
            right: vec![0.0; points.len()],
        };
        curve.push_piece(&points, 0.0, 0);
        Some(curve)
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
            children: None,
        });
        self.nodes.len() - 1
    }

    /// The halves of piece `i`, split on first use.
    fn children(&mut self, i: usize) -> [usize; 2] {
        if let Some(c) = self.nodes[i].children {
            return c;
        }
        let stride = self.points.len();
        let Node { start, level, .. } = self.nodes[i];
        curve_split(
            &self.pieces[i * stride..(i + 1) * stride],
            2,
            &0.5,
            &mut self.left,
            &mut self.right,
        );
        let half = width(level + 1);
        let (left, right) = (
            std::mem::take(&mut self.left),
            std::mem::take(&mut self.right),
        );
        let a = self.push_piece(&left, start, level + 1);
        let b = self.push_piece(&right, start + half, level + 1);
        (self.left, self.right) = (left, right);
        self.nodes[i].children = Some([a, b]);
        [a, b]
    }

    /// P(s) and P'(s) in plain `f64`.
    fn eval_f64(&mut self, s: f64) -> ([f64; 2], [f64; 2]) {
        let mut point = [0.0; 2];
        let mut tangent = [0.0; 2];
        curve_eval_into(&self.points, 2, &s, &mut point, &mut self.level);
        curve_eval_into(&self.hodograph_f64, 2, &s, &mut tangent, &mut self.level);
        (point, tangent)
    }

    /// An enclosure of P at the double `s` (the pyramid in convex form, [`ConvexStep`]).
    fn eval_bounded(&self, s: f64) -> [BoundedF64; 2] {
        let mut level = self.exact.clone();
        curve_pyramid_in_place(&mut level, 2, &ConvexStep::new(BoundedF64::exact(s)));
        [level[0], level[1]]
    }

    /// P at the double `s` in double-double with a bound.
    fn eval_dd(&self, s: f64) -> [Dd; 2] {
        let mut level = self.dd.clone();
        curve_pyramid_in_place(&mut level, 2, &ConvexStep::new(Dd::exact(s)));
        [level[0], level[1]]
    }

    /// An enclosure of P'(s) for every s with |s - mid| <= radius: the hull of the
    /// hodograph's control points over [a, b] ⊇ [mid - radius, mid + radius] (the engine's
    /// restriction net at the exact double ends a, b in convex form, its rounding bounded by
    /// `BoundedF64`), which
    /// holds the hodograph over [a, b] by the convex hull property. (De Casteljau's pyramid at
    /// an interval argument would also enclose it, but its width grows like (1 + 2|s|)^n.)
    fn tangent_over(&self, mid: f64, radius: f64) -> [BoundedF64; 2] {
        let a = BoundedF64::exact((mid - radius).next_down());
        let b = BoundedF64::exact((mid + radius).next_up());
        let mut net = vec![BoundedF64::zero(); self.hodograph.len()];
        let (a, b) = (ConvexStep::new(a), ConvexStep::new(b));
        curve_net(&self.hodograph, 2, &a, &b, &mut net, &mut Vec::new());
        [0, 1].map(|c| {
            let (lo, hi) = net
                .iter()
                .skip(c)
                .step_by(2)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                    (lo.min(lower(x)), hi.max(upper(x)))
                });
            from_bounds(lo, hi)
        })
    }
}

/// 2^-level.
fn width(level: u32) -> f64 {
    2f64.powi(-(level as i32))
}

/// A box in (s, t): midpoint and radii, standing for m ± r exactly.
#[derive(Clone, Copy, Debug)]
struct Box2 {
    mid: [f64; 2],
    radius: [f64; 2],
}

impl Box2 {
    /// Whether [a0, a1] x [b0, b1] lies inside the box (decided conservatively).
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
    /// P'(S) over the box's S.
    tangent_p: [BoundedF64; 2],
    /// K(X) lies in the interior of X: exactly one root in X, a nonsingular Jacobian.
    proved: bool,
    /// K(X) misses X: no root in X.
    empty: bool,
}

/// Krawczyk's operator on the box `x` with F(m) enclosed by `f` (module documentation, 2).
fn krawczyk(p: &Curve, q: &Curve, x: &Box2, f: [BoundedF64; 2]) -> Option<Krawczyk> {
    let dp = p.tangent_over(x.mid[0], x.radius[0]);
    let dq = q.tangent_over(x.mid[1], x.radius[1]);
    // J = [[P'_x, -Q'_x], [P'_y, -Q'_y]] over the box; Y the inverse of its midpoint.
    let j = [[dp[0], dq[0].neg()], [dp[1], dq[1].neg()]];
    let a = [
        [j[0][0].value(), j[0][1].value()],
        [j[1][0].value(), j[1][1].value()],
    ];
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let y = [
        [a[1][1] / det, -a[0][1] / det],
        [-a[1][0] / det, a[0][0] / det],
    ];
    let yb = y.map(|row| row.map(BoundedF64::exact));
    let radius = x.radius.map(|r| BoundedF64::with_bound(0.0, r));
    let mut offset = [BoundedF64::zero(); 2];
    for i in 0..2 {
        // -Y F(m) + sum_j (δ_ij - (Y J)_ij) (X - m)_j.
        let yf = yb[i][0].mul(&f[0]).add(&yb[i][1].mul(&f[1]));
        let mut k = yf.neg();
        for col in 0..2 {
            let yj = yb[i][0].mul(&j[0][col]).add(&yb[i][1].mul(&j[1][col]));
            let identity = BoundedF64::exact(if i == col { 1.0 } else { 0.0 });
            k = k.add(&identity.sub(&yj).mul(&radius[col]));
        }
        offset[i] = k;
    }
    let proved = (0..2).all(|i| inside_radius(&offset[i], x.radius[i]));
    let empty = (0..2).any(|i| outside_radius(&offset[i], x.radius[i]));
    Some(Krawczyk {
        offset,
        tangent_p: dp,
        proved,
        empty,
    })
}

/// F(m) = P(m_s) - Q(m_t), enclosed in `f64` intervals.
fn residual(p: &Curve, q: &Curve, m: [f64; 2]) -> [BoundedF64; 2] {
    let (a, b) = (p.eval_bounded(m[0]), q.eval_bounded(m[1]));
    [a[0].sub(&b[0]), a[1].sub(&b[1])]
}

/// Newton's method in `f64` from `start`: the point it converges to, if it does.
fn newton(p: &mut Curve, q: &mut Curve, start: [f64; 2]) -> Option<[f64; 2]> {
    let [mut s, mut t] = start;
    for _ in 0..NEWTON_STEPS {
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
        if !(s.abs() < 4.0 && t.abs() < 4.0) {
            return None;
        }
        if ds.abs() <= 1e-15 && dt.abs() <= 1e-15 {
            return Some([s, t]);
        }
    }
    None
}

/// A proved root: its exclusion box, its tight enclosure, and the reported crossing when it
/// lies inside the domain.
struct Root {
    tight: [[f64; 2]; 2],
    crossing: Option<CertifiedCrossing>,
}

/// The tight certification of the root proved in `b` (module documentation, 3): `None` when
/// undecided, else the root (with its crossing when inside (0, 1)^2).
fn certify(p: &Curve, q: &Curve, b: &Box2) -> Option<Root> {
    let z = b.mid;
    let pz = p.eval_dd(z[0]);
    let qz = q.eval_dd(z[1]);
    let f = [
        pz[0].sub(&qz[0]).to_bounded(),
        pz[1].sub(&qz[1]).to_bounded(),
    ];
    // The size of the Newton correction sets the radius.
    let first = krawczyk(
        p,
        q,
        &Box2 {
            mid: z,
            radius: [TIGHT_RADIUS; 2],
        },
        f,
    )?;
    let radius = [0, 1].map(|i| {
        let d = first.offset[i].value().abs();
        (8.0 * d).max(TIGHT_RADIUS)
    });
    let k = if radius == [TIGHT_RADIUS; 2] {
        first
    } else {
        krawczyk(p, q, &Box2 { mid: z, radius }, f)?
    };
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
    let point = [0, 1].map(|c| {
        let offset = pz[c].rest().add(&k.offset[0].mul(&k.tangent_p[c]));
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

/// What became of a cell.
enum Tried {
    /// Its roots are those of this exclusion box, whose root is proved.
    Proved(Box2, Root),
    /// No root in the cell.
    Empty,
    /// Nothing decided: halve it.
    Open,
}

/// Newton from the cell's centre, then Krawczyk on the box around the Newton point that
/// contains the cell (module documentation, 2). `None` when a proved root is undecided.
fn try_cell(p: &mut Curve, q: &mut Curve, s: [f64; 2], t: [f64; 2]) -> Option<Tried> {
    let centre = [0.5 * (s[0] + s[1]), 0.5 * (t[0] + t[1])];
    let half = [0.5 * (s[1] - s[0]), 0.5 * (t[1] - t[0])];
    let Some(z) = newton(p, q, centre) else {
        let cell = Box2 {
            mid: centre,
            radius: half,
        };
        let k = krawczyk(p, q, &cell, residual(p, q, centre));
        return Some(match k {
            Some(k) if k.empty => Tried::Empty,
            _ => Tried::Open,
        });
    };
    let far = |i: usize| (z[i] - centre[i]).abs() > 2.0 * half[i];
    if far(0) || far(1) {
        return Some(Tried::Open);
    }
    let radius = [0, 1].map(|i| ((z[i] - centre[i]).abs().next_up() + half[i]).next_up());
    let b = Box2 { mid: z, radius };
    match krawczyk(p, q, &b, residual(p, q, z)) {
        Some(k) if k.proved => Some(Tried::Proved(b, certify(p, q, &b)?)),
        _ => Some(Tried::Open),
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
    let mut pc = Curve::new(p)?;
    let mut qc = Curve::new(q)?;
    let mut exclusions: Vec<(Box2, usize)> = Vec::new();
    let mut roots: Vec<Root> = Vec::new();
    let mut stack = vec![(0usize, 0usize)];
    let mut examined = 0usize;
    while let Some((i, j)) = stack.pop() {
        examined += 1;
        if examined > MAX_CELLS {
            return None;
        }
        let (a, b) = (pc.nodes[i], qc.nodes[j]);
        if a.bbox[1] < b.bbox[0]
            || b.bbox[1] < a.bbox[0]
            || a.bbox[3] < b.bbox[2]
            || b.bbox[3] < a.bbox[2]
        {
            continue;
        }
        let s = [a.start, a.start + width(a.level)];
        let t = [b.start, b.start + width(b.level)];
        if exclusions.iter().any(|(e, _)| e.contains(s, t)) {
            continue;
        }
        if a.level >= PROOF_LEVEL && b.level >= PROOF_LEVEL {
            match try_cell(&mut pc, &mut qc, s, t)? {
                Tried::Proved(bx, root) => {
                    let index = same_root(&roots, &exclusions, &bx, &root)?;
                    let index = index.unwrap_or_else(|| {
                        roots.push(root);
                        roots.len() - 1
                    });
                    exclusions.push((bx, index));
                    if bx.contains(s, t) {
                        continue;
                    }
                }
                Tried::Empty => continue,
                Tried::Open => {}
            }
        }
        if a.level >= MAX_LEVEL || b.level >= MAX_LEVEL {
            return None;
        }
        let [p0, p1] = pc.children(i);
        let [q0, q1] = qc.children(j);
        stack.extend([(p1, q1), (p1, q0), (p0, q1), (p0, q0)]);
    }
    let mut out: Vec<CertifiedCrossing> = roots.iter().filter_map(|r| r.crossing).collect();
    out.sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
    Some(out)
}

/// Whether the new `root` proved in `bx` is one already known: `Some(Some(index))` when it is,
/// `Some(None)` when it is new (its enclosure meets no other), `None` when undecided.
fn same_root(
    roots: &[Root],
    exclusions: &[(Box2, usize)],
    bx: &Box2,
    root: &Root,
) -> Option<Option<usize>> {
    let meets = |a: &[[f64; 2]; 2], b: &[[f64; 2]; 2]| {
        (0..2).all(|k| a[k][0] <= b[k][1] && b[k][0] <= a[k][1])
    };
    for (index, known) in roots.iter().enumerate() {
        if !meets(&known.tight, &root.tight) {
            continue;
        }
        let known_in_new = bx.contains(known.tight[0], known.tight[1]);
        let new_in_known = exclusions
            .iter()
            .any(|(e, k)| *k == index && e.contains(root.tight[0], root.tight[1]));
        if known_in_new || new_in_known {
            return Some(Some(index));
        }
        return None;
    }
    Some(None)
}
