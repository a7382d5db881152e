//! One input curve prepared for exact geometry: its power form, an outward-rounded bounding
//! box, and (on first use) its breaks into pieces monotone in x or in y.
//!
//! **Bounding box.** The control points' box holds the curve (convex hull property); each
//! side is rounded outward to a double, so a comparison of a box with a point's outward
//! rounded coordinates that separates them proves the separation: the box only prunes.
//!
//! **Monotone pieces.** Along an axis a, the coordinate c_a(t) is strictly monotone between
//! consecutive roots in (0, 1) of its derivative (exact roots, [`AlgebraicReal`]s); the breaks
//! are 0, those roots and 1, with the coordinate's exact values there. A curve whose
//! coordinate is constant has no piece that changes it.

use crate::intersect::algebraic::{exact_f64, value_at, AlgebraicReal};
use crate::intersect::upoly;
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::array::Bezier;
use crate::shape::basis::bernstein_to_power;
use num_traits::{One, Zero};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The breaks of a curve into pieces strictly monotone along one axis.
#[derive(Clone, Debug)]
pub(crate) struct Monotone {
    /// 0, the roots of the derivative in (0, 1) in increasing order, 1.
    pub params: Vec<AlgebraicReal>,
    /// The coordinate at each parameter.
    pub values: Vec<AlgebraicReal>,
    /// Whether the coordinate is constant (then no piece changes it).
    pub constant: bool,
    /// For each piece: whether the coordinate increases along it.
    pub rising: Vec<bool>,
    /// Outward-rounded doubles around each value: `(down, up)`.
    pub bounds: Vec<(f64, f64)>,
}

/// An input curve with its exact power form and cached derived data.
#[derive(Debug)]
pub(crate) struct Curve {
    /// Control points.
    pub points: Vec<[Rational; 2]>,
    /// Power-form coefficients of x(t) and y(t), ascending.
    pub power: [Vec<Rational>; 2],
    /// Outward-rounded box: `[xmin, ymin, xmax, ymax]`.
    pub bbox: [f64; 4],
    monotone: [OnceCell<Monotone>; 2],
    x_dy: OnceCell<Vec<Rational>>,
}

/// The largest double not above `r`.
pub(crate) fn f64_down(r: &Rational) -> f64 {
    let x = rational_to_f64(r);
    if x.is_finite() && &exact_f64(x) > r {
        x.next_down()
    } else {
        x
    }
}

/// The smallest double not below `r`.
pub(crate) fn f64_up(r: &Rational) -> f64 {
    let x = rational_to_f64(r);
    if x.is_finite() && &exact_f64(x) < r {
        x.next_up()
    } else {
        x
    }
}

/// p(r) for a rational polynomial (ascending).
pub(crate) fn eval(p: &[Rational], r: &Rational) -> Rational {
    p.iter().rev().fold(Rational::zero(), |acc, c| acc * r + c)
}

/// The derivative of a rational polynomial (ascending).
pub(crate) fn derivative(p: &[Rational]) -> Vec<Rational> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * Rational::from_integer((i as i64).into()))
        .collect()
}

impl Curve {
    /// Prepares `curve`.
    pub fn new(curve: &Bezier<Rational, 2>) -> Curve {
        let points = curve.points().to_vec();
        let rows: Vec<Vec<Rational>> = points.iter().map(|p| p.to_vec()).collect();
        let c = bernstein_to_power(&rows);
        let power = [0, 1].map(|a| c.iter().map(|p| p[a].clone()).collect::<Vec<_>>());
        let mut bbox = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in &points {
            for a in 0..2 {
                bbox[a] = bbox[a].min(f64_down(&p[a]));
                bbox[a + 2] = bbox[a + 2].max(f64_up(&p[a]));
            }
        }
        Curve {
            points,
            power,
            bbox,
            monotone: [OnceCell::new(), OnceCell::new()],
            x_dy: OnceCell::new(),
        }
    }

    /// The point at the rational parameter t.
    pub fn at(&self, t: &Rational) -> [Rational; 2] {
        [eval(&self.power[0], t), eval(&self.power[1], t)]
    }

    /// The derivative vector at the rational parameter t.
    pub fn tangent(&self, t: &Rational) -> [Rational; 2] {
        [0, 1].map(|a| eval(&derivative(&self.power[a]), t))
    }

    /// Whether the boxes of the two curves share a point (false proves they are disjoint).
    pub fn boxes_meet(&self, other: &Curve) -> bool {
        self.bbox[0] <= other.bbox[2]
            && other.bbox[0] <= self.bbox[2]
            && self.bbox[1] <= other.bbox[3]
            && other.bbox[1] <= self.bbox[3]
    }

    /// The breaks into pieces monotone along `axis` (0: x, 1: y), computed once.
    pub fn monotone(&self, axis: usize) -> &Monotone {
        self.monotone[axis].get_or_init(|| monotone_breaks(&self.power[axis]))
    }

    /// The antiderivative of x(t) y'(t) vanishing at 0 (for areas), computed once.
    pub fn x_dy(&self) -> &[Rational] {
        self.x_dy.get_or_init(|| super::area::x_dy(&self.power))
    }

    /// The parameters in [0, 1] where the curve passes through the rational point `p`, in
    /// increasing order: the roots of gcd(x(t) - p_x, y(t) - p_y).
    pub fn parameters_at(&self, p: &[Rational; 2]) -> Vec<AlgebraicReal> {
        let minus = |a: usize| {
            let mut q = self.power[a].clone();
            q[0] -= &p[a];
            upoly::from_rationals(&q)
        };
        let (gx, gy) = (minus(0), minus(1));
        let g = match (upoly::is_zero(&gx), upoly::is_zero(&gy)) {
            (true, true) => return vec![zero(), one()],
            (true, false) => gy,
            (false, true) => gx,
            (false, false) => upoly::gcd(&gx, &gy),
        };
        if upoly::degree(&g).unwrap_or(0) == 0 {
            return Vec::new();
        }
        roots_with_multiplicity(&g, &Rational::zero(), &Rational::one())
            .into_iter()
            .map(|r| r.value)
            .collect()
    }
}

/// The algebraic number 0.
pub(crate) fn zero() -> AlgebraicReal {
    AlgebraicReal::from_rational(Rational::zero())
}

/// The algebraic number 1.
pub(crate) fn one() -> AlgebraicReal {
    AlgebraicReal::from_rational(Rational::one())
}

/// The monotone breaks of the coordinate polynomial `c` (ascending).
fn monotone_breaks(c: &[Rational]) -> Monotone {
    let d = upoly::from_rationals(&derivative(c));
    let constant = upoly::is_zero(&d);
    let mut params = vec![zero()];
    if !constant && upoly::degree(&d).unwrap_or(0) > 0 {
        for r in roots_with_multiplicity(&d, &Rational::zero(), &Rational::one()) {
            let inside = r.value.cmp_rational(&Rational::zero()) == Ordering::Greater
                && r.value.cmp_rational(&Rational::one()) == Ordering::Less;
            if inside {
                params.push(r.value);
            }
        }
    }
    params.push(one());
    let values: Vec<AlgebraicReal> = params.iter().map(|t| value_at(c, t)).collect();
    let rising = values
        .windows(2)
        .map(|v| v[0].compare(&v[1]) == Ordering::Less)
        .collect();
    let bounds = values
        .iter()
        .map(|v| (v.to_f64_down(), v.to_f64_up()))
        .collect();
    Monotone {
        params,
        values,
        constant,
        rising,
        bounds,
    }
}
