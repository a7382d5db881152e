//! One input curve prepared for exact geometry: its power form, an outward-rounded bounding
//! box, and (on first use) its breaks into pieces monotone in x or in y.
//!
//! **Bounding box.** The control points' box holds the curve (convex hull property); each
//! side is rounded outward to a double, so a comparison of a box with a point's outward
//! rounded coordinates that separates them proves the separation: the box only prunes.
//!
//! **Monotone pieces.** Along an axis a, the coordinate c_a(t) is strictly monotone between
//! consecutive roots in (0, 1) of its derivative (exact roots, [`AlgebraicReal`]s); the breaks
//! are 0, those roots and 1. Whether the coordinate rises along a piece is the sign of the
//! derivative at a rational point inside it; the coordinate's value at a break is compared
//! with a rational exactly as the sign of c(t) - r at the break, and enclosed in doubles
//! (interval Horner over the break's isolating interval, rounded outward) for the filter. A
//! curve whose coordinate is constant has no piece that changes it. When the control
//! coordinates already move one way (differences all >= 0 or all <= 0, not all 0) the
//! derivative's Bernstein form proves it has no root inside, and no root is isolated.

use crate::intersect::algebraic::{
    enclose, exact_f64, over_common_denominator, shifted_poly, simplest_between, AlgebraicReal,
};
use crate::intersect::upoly;
use crate::intersect::zeros::roots_with_multiplicity;
use crate::num::bounded::BoundedF64;
use crate::num::ring::{rational_to_f64, Rational};
use crate::shape::array::Bezier;
#[cfg(test)]
use crate::shape::basis::bernstein_to_power;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The breaks of a curve into pieces strictly monotone along one axis.
#[derive(Clone, Debug)]
pub(crate) struct Monotone {
    /// 0, the roots of the derivative in (0, 1) in increasing order, 1.
    pub params: Vec<AlgebraicReal>,
    /// The coordinate polynomial (ascending).
    pub coordinate: Vec<Rational>,
    /// Whether the coordinate is constant (then no piece changes it).
    pub constant: bool,
    /// For each piece: whether the coordinate increases along it.
    pub rising: Vec<bool>,
    /// Outward-rounded doubles around the coordinate's value at each break: `(down, up)`.
    pub bounds: Vec<(f64, f64)>,
}

impl Monotone {
    /// The exact comparison of the coordinate at break `k` with `r`.
    pub fn cmp_value(&self, k: usize, r: &Rational) -> Ordering {
        let t = &self.params[k];
        match t.exact() {
            Some(t0) => eval(&self.coordinate, t0).cmp(r),
            None => t.clone().sign_of(&shifted_poly(&self.coordinate, r)),
        }
    }
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
    power_bounded: OnceCell<[Vec<BoundedF64>; 2]>,
}

/// Whether the rational is exactly a normal double (or zero): a power-of-two denominator of at
/// most 2^1000 and a numerator of at most 53 bits, so `rational_to_f64` is exact.
pub(crate) fn is_double(r: &Rational) -> bool {
    let d = r.denom();
    let bits = d.bits();
    r.numer().bits() <= 53 && bits <= 1000 && d.trailing_zeros() == Some(bits - 1)
}

/// The largest double not above `r`.
pub(crate) fn f64_down(r: &Rational) -> f64 {
    if is_double(r) {
        return rational_to_f64(r);
    }
    let x = rational_to_f64(r);
    if x.is_finite() && &exact_f64(x) > r {
        x.next_down()
    } else {
        x
    }
}

/// The smallest double not below `r`.
pub(crate) fn f64_up(r: &Rational) -> f64 {
    if is_double(r) {
        return rational_to_f64(r);
    }
    let x = rational_to_f64(r);
    if x.is_finite() && &exact_f64(x) < r {
        x.next_up()
    } else {
        x
    }
}

/// p(r) for a rational polynomial (ascending), exactly: Horner on the integers (the
/// enclosure of p over [r, r], whose ends are both p(r)), with two reductions in all instead
/// of one per operation.
pub(crate) fn eval(p: &[Rational], r: &Rational) -> Rational {
    if p.is_empty() {
        return Rational::zero();
    }
    enclose(p, r, r).0
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
        let power = [0, 1].map(|a| power_form(&points, a));
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
            power_bounded: OnceCell::new(),
        }
    }

    /// The power-form coefficients of x(t) and y(t) enclosed in doubles
    /// ([`BoundedF64::rounded`]), for the float filters (computed on first use).
    pub fn power_bounded(&self) -> &[Vec<BoundedF64>; 2] {
        self.power_bounded
            .get_or_init(|| [0, 1].map(|a| self.power[a].iter().map(BoundedF64::rounded).collect()))
    }

    /// The point at the rational parameter t.
    pub fn at(&self, t: &Rational) -> [Rational; 2] {
        [eval(&self.power[0], t), eval(&self.power[1], t)]
    }

    /// The derivative vector at the rational parameter t.
    pub fn tangent(&self, t: &Rational) -> [Rational; 2] {
        [0, 1].map(|a| eval(&derivative(&self.power[a]), t))
    }

    /// The breaks into pieces monotone along `axis` (0: x, 1: y), computed once.
    pub fn monotone(&self, axis: usize) -> &Monotone {
        self.monotone[axis].get_or_init(|| {
            let column: Vec<&Rational> = self.points.iter().map(|p| &p[axis]).collect();
            match one_direction(&column) {
                Some(rising) => {
                    let ends = [column[0], column[column.len() - 1]];
                    Monotone {
                        params: vec![zero(), one()],
                        coordinate: self.power[axis].clone(),
                        constant: false,
                        rising: vec![rising],
                        bounds: ends.iter().map(|v| (f64_down(v), f64_up(v))).collect(),
                    }
                }
                None => monotone_breaks(&self.power[axis]),
            }
        })
    }

    /// The antiderivative of x(t) y'(t) vanishing at 0 (for areas), computed once.
    pub fn x_dy(&self) -> &[Rational] {
        self.x_dy.get_or_init(|| x_dy(&self.power))
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

/// The power-form coefficients of coordinate `a` of a Bézier curve, a_k = C(n, k) times the
/// k-th forward difference of the control points, computed on integers: the coordinates
/// over their common denominator D, the differences and binomials exact in integers, one
/// division by D per coefficient at the end.
fn power_form(points: &[[Rational; 2]], a: usize) -> Vec<Rational> {
    let column: Vec<Rational> = points.iter().map(|p| p[a].clone()).collect();
    let (mut diff, d) = over_common_denominator(&column);
    let n = diff.len() - 1;
    let mut out = Vec::with_capacity(n + 1);
    let mut binomial = BigInt::one();
    for k in 0..=n {
        out.push(Rational::new(&diff[0] * &binomial, d.clone()));
        // The next forward differences, and C(n, k + 1) = C(n, k) (n - k) / (k + 1).
        for i in 0..diff.len() - 1 {
            diff[i] = &diff[i + 1] - &diff[i];
        }
        diff.pop();
        binomial = binomial * BigInt::from(n - k) / BigInt::from(k + 1);
    }
    out
}

/// The algebraic number 0.
pub(crate) fn zero() -> AlgebraicReal {
    AlgebraicReal::from_rational(Rational::zero())
}

/// The algebraic number 1.
pub(crate) fn one() -> AlgebraicReal {
    AlgebraicReal::from_rational(Rational::one())
}

/// `Some(rising)` when the control coordinates `column` prove the coordinate strictly
/// monotone on [0, 1] without a break inside: the derivative's Bernstein coefficients
/// n (c_{i+1} - c_i) are all >= 0 (or all <= 0) and not all 0, and a Bernstein polynomial
/// with such coefficients is > 0 (< 0) on (0, 1), so it has no root there (exact
/// comparisons). `None` when the differences change sign or all vanish.
fn one_direction(column: &[&Rational]) -> Option<bool> {
    let (mut up, mut down) = (false, false);
    for w in column.windows(2) {
        match w[1].cmp(w[0]) {
            Ordering::Greater => up = true,
            Ordering::Less => down = true,
            Ordering::Equal => {}
        }
    }
    (up != down).then_some(up)
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
    let dc = derivative(c);
    // Strictly monotone between consecutive breaks: the derivative's sign at any rational
    // point inside tells the direction (it is not zero there, the breaks being its roots).
    let rising: Vec<bool> = params
        .windows(2)
        .map(|w| eval(&dc, &rational_between(&w[0], &w[1])) > Rational::zero())
        .collect();
    // Near a break c' vanishes, so an interval of width w encloses c within about w^2 |c"|:
    // 2^-32 is ample for the filters, which only prune or prove a sign. The breaks keep the
    // refined intervals (the same numbers, isolated more tightly).
    let fine = Rational::new(1.into(), BigInt::one() << 32);
    let bounds = params
        .iter_mut()
        .map(|t| match t.exact() {
            Some(t0) => {
                let v = eval(c, t0);
                (f64_down(&v), f64_up(&v))
            }
            None => {
                t.refine_to(&fine);
                let (lo, hi) = t.interval();
                let (vl, vh) = enclose(c, lo, hi);
                (f64_down(&vl), f64_up(&vh))
            }
        })
        .collect();
    Monotone {
        params,
        coordinate: c.to_vec(),
        constant,
        rising,
        bounds,
    }
}

/// The antiderivative of x(t) y'(t), vanishing at 0, for the curve's power form.
fn x_dy(power: &[Vec<Rational>; 2]) -> Vec<Rational> {
    let dy = derivative(&power[1]);
    let mut product = vec![Rational::zero(); power[0].len() + dy.len()];
    for (i, a) in power[0].iter().enumerate() {
        for (j, b) in dy.iter().enumerate() {
            product[i + j] += a * b;
        }
    }
    let mut out = vec![Rational::zero()];
    for (i, c) in product.into_iter().enumerate() {
        out.push(c / Rational::from_integer(((i + 1) as i64).into()));
    }
    out
}

/// A rational strictly between the distinct algebraic numbers `a` and `b`.
pub(crate) fn rational_between(a: &AlgebraicReal, b: &AlgebraicReal) -> Rational {
    let (mut lo, mut hi) = if a.compare(b) == Ordering::Less {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    loop {
        let (l, h) = (lo.interval().1.clone(), hi.interval().0.clone());
        if l < h {
            let four = Rational::from_integer(4.into());
            let three = Rational::from_integer(3.into());
            let x = (&three * &l + &h) / &four;
            let y = (&l + &three * &h) / &four;
            return simplest_between(&x, &y);
        }
        lo.refine();
        hi.refine();
    }
}

#[cfg(test)]
mod tests {
    use super::{bernstein_to_power, power_form, Rational};

    /// The integer power form against the library's change of basis, on curves of degree 1
    /// to 7 with mixed denominators.
    #[test]
    fn power_form_matches_the_change_of_basis() {
        let mut state = 0x1234_5678_9abc_def1u64;
        let mut next = |m: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % m) as i64
        };
        for n in 1..8 {
            let points: Vec<[Rational; 2]> = (0..=n)
                .map(|_| {
                    [
                        Rational::new((next(41) - 20).into(), (next(9) + 1).into()),
                        Rational::new((next(41) - 20).into(), (next(9) + 1).into()),
                    ]
                })
                .collect();
            let rows: Vec<Vec<Rational>> = points.iter().map(|p| p.to_vec()).collect();
            let expected = bernstein_to_power(&rows);
            for a in 0..2 {
                let column: Vec<Rational> = expected.iter().map(|p| p[a].clone()).collect();
                assert_eq!(power_form(&points, a), column, "degree {n}");
            }
        }
    }
}
