//! The flat storage of the B-spline types against nested points: the two constructors agree,
//! the allocation-free evaluations equal a textbook de Boor written here on nested vectors
//! (independent of `de_boor.rs`), and bad buffers are named errors.

use super::{BSpline, BSplineSurface, KnotVector};
use crate::error::ErrorKind;
use crate::{Rational, RationalBSpline, RationalBSplineSurface};
use num_bigint::BigInt;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// Samples drawn from the shared test generator ([`crate::test_rng::XorShift`]).
struct Rng(crate::test_rng::XorShift);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0.next()
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// A rational in [-10, 10] with a denominator up to 7.
    fn rational(&mut self) -> Rational {
        q(self.below(141) as i64 - 70, self.below(7) as i64 + 1)
    }

    fn point(&mut self, dim: usize) -> Vec<Rational> {
        (0..dim).map(|_| self.rational()).collect()
    }

    /// A clamped knot vector of degree p with m de Boor points: p + 1 zeros, interior knots
    /// drawn from a few values (so some repeat, up to multiplicity p + 1), p + 1 end knots.
    fn knots(&mut self, p: usize, m: usize) -> Vec<Rational> {
        loop {
            let mut inner: Vec<Rational> = (0..m - p - 1)
                .map(|_| q(self.below(9) as i64 + 1, 2))
                .collect();
            inner.sort();
            let mut t = vec![q(0, 1); p + 1];
            t.extend(inner);
            t.extend(vec![q(5, 1); p + 1]);
            if KnotVector::new(p, t.clone()).is_ok() {
                return t;
            }
        }
    }
}

/// The span s of t in the textbook convention: the last s in p..m with t_s <= t and
/// t_s < t_(s+1) (so the right end of the domain belongs to the last non-empty span).
fn textbook_span(t: &[Rational], p: usize, m: usize, x: &Rational) -> usize {
    (p..m)
        .rev()
        .find(|&s| t[s] <= *x && t[s] < t[s + 1])
        .expect("x in the domain")
}

/// De Boor's algorithm as in the textbooks, on nested points: copy d_(s-p)..d_s, then for
/// r = 1..=p and j = p down to r, with i = s - p + j,
/// a = (x - t_i) / (t_(i+p+1-r) - t_i), d_j = (1 - a) d_(j-1) + a d_j.
fn textbook_de_boor(t: &[Rational], p: usize, d: &[Vec<Rational>], x: &Rational) -> Vec<Rational> {
    let s = textbook_span(t, p, d.len(), x);
    let mut w: Vec<Vec<Rational>> = d[s - p..=s].to_vec();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = s - p + j;
            let a = (x - &t[i]) / (&t[i + p + 1 - r] - &t[i]);
            let one_minus = q(1, 1) - &a;
            w[j] = w[j - 1]
                .iter()
                .zip(&w[j])
                .map(|(l, h)| &one_minus * l + &a * h)
                .collect();
        }
    }
    w.swap_remove(p)
}

/// Parameters to test at: every knot of the domain and random points between them.
fn parameters(rng: &mut Rng, t: &[Rational], p: usize, m: usize) -> Vec<Rational> {
    let (a, b) = (&t[p], &t[m]);
    let mut xs: Vec<Rational> = t[p..=m].to_vec();
    for _ in 0..6 {
        xs.push(a + (b - a) * q(rng.below(1001) as i64, 1000));
    }
    xs
}

#[test]
fn flat_and_nested_constructors_agree() {
    let mut rng = Rng(crate::test_rng::XorShift(0x5eed_0001));
    for p in 0..=4 {
        for dim in 1..=3 {
            let m = p + 1 + rng.below(4) as usize;
            let t = rng.knots(p, m);
            let nested: Vec<Vec<Rational>> = (0..m).map(|_| rng.point(dim)).collect();
            let f = BSpline::new(p, t.clone(), nested.clone()).unwrap();
            let g = BSpline::from_coordinates(p, t, dim, nested.concat()).unwrap();
            assert_eq!(f, g, "p = {p}, dim = {dim}");
            assert_eq!(f.control_points(), nested);
            assert_eq!(f.to_nested(), nested);
            assert_eq!(f.coordinates(), nested.concat().as_slice());
            for (i, d) in nested.iter().enumerate() {
                assert_eq!(f.control_point(i), d.as_slice());
            }
        }
    }
}

#[test]
fn eval_into_equals_a_textbook_de_boor_on_random_rational_splines() {
    let mut rng = Rng(crate::test_rng::XorShift(0x5eed_0002));
    let mut scratch = Vec::new();
    for round in 0..40 {
        let p = round % 5;
        let dim = 1 + round % 3;
        let m = p + 1 + rng.below(5) as usize;
        let t = rng.knots(p, m);
        let d: Vec<Vec<Rational>> = (0..m).map(|_| rng.point(dim)).collect();
        let f = BSpline::from_coordinates(p, t.clone(), dim, d.concat()).unwrap();
        let mut out = vec![q(0, 1); dim];
        for x in parameters(&mut rng, &t, p, m) {
            let want = textbook_de_boor(&t, p, &d, &x);
            f.eval_into(&x, &mut out, &mut scratch).unwrap();
            assert_eq!(out, want, "p = {p}, knots {t:?}, x = {x}");
            assert_eq!(f.eval(&x).unwrap(), want);
            // After a knot insertion and on the Bézier piece of the span, the same point.
            if let Ok(g) = f.insert_knot(&x) {
                g.eval_into(&x, &mut out, &mut scratch).unwrap();
                assert_eq!(out, want, "after inserting {x}");
            }
        }
        for piece in f.bezier_pieces() {
            let [a, b] = &piece.interval;
            let x = (a + b) / q(2, 1);
            assert_eq!(piece.curve.eval(&q(1, 2)), textbook_de_boor(&t, p, &d, &x));
        }
    }
}

#[test]
fn surface_eval_into_equals_textbook_de_boor_along_v_then_u() {
    let mut rng = Rng(crate::test_rng::XorShift(0x5eed_0003));
    let mut scratch = Vec::new();
    for round in 0..12 {
        let (p, qd) = (round % 3, (round / 3) % 3);
        let dim = 1 + round % 2;
        let (m, n) = (
            p + 1 + rng.below(3) as usize,
            qd + 1 + rng.below(3) as usize,
        );
        let (tu, tv) = (rng.knots(p, m), rng.knots(qd, n));
        let grid: Vec<Vec<Vec<Rational>>> = (0..m)
            .map(|_| (0..n).map(|_| rng.point(dim)).collect())
            .collect();
        let f = BSplineSurface::new((p, qd), tu.clone(), tv.clone(), grid.clone()).unwrap();
        let flat: Vec<Rational> = grid.iter().flatten().flatten().cloned().collect();
        let g =
            BSplineSurface::from_coordinates((p, qd), tu.clone(), tv.clone(), dim, flat).unwrap();
        assert_eq!(f, g);
        assert_eq!(f.to_nested(), grid);
        assert_eq!(f.grid_size(), (m, n));
        assert_eq!(f.control_point(m - 1, n - 1), grid[m - 1][n - 1].as_slice());
        let mut out = vec![q(0, 1); dim];
        for u in parameters(&mut rng, &tu, p, m) {
            for v in parameters(&mut rng, &tv, qd, n).into_iter().step_by(3) {
                // Every row is a curve in v; the curve in u of their values is F(u, v).
                let column: Vec<Vec<Rational>> = grid
                    .iter()
                    .map(|row| textbook_de_boor(&tv, qd, row, &v))
                    .collect();
                let want = textbook_de_boor(&tu, p, &column, &u);
                f.eval_into(&u, &v, &mut out, &mut scratch).unwrap();
                assert_eq!(out, want, "({u}, {v})");
            }
        }
    }
}

#[test]
fn rational_eval_into_projects_the_homogeneous_de_boor() {
    let mut rng = Rng(crate::test_rng::XorShift(0x5eed_0004));
    let mut scratch = Vec::new();
    for p in 1..=3 {
        let m = p + 2;
        let t = rng.knots(p, m);
        let d: Vec<Vec<Rational>> = (0..m).map(|_| rng.point(2)).collect();
        let w: Vec<Rational> = (0..m).map(|_| q(rng.below(5) as i64 + 1, 3)).collect();
        let f = RationalBSpline::new(p, t.clone(), d.clone(), w.clone()).unwrap();
        let g = RationalBSpline::from_coordinates(p, t.clone(), 2, d.concat(), w.clone()).unwrap();
        assert_eq!(f, g);
        let h: Vec<Vec<Rational>> = d
            .iter()
            .zip(&w)
            .map(|(b, wi)| vec![&b[0] * wi, &b[1] * wi, wi.clone()])
            .collect();
        let mut out = vec![q(0, 1); 2];
        for x in parameters(&mut rng, &t, p, m) {
            let hx = textbook_de_boor(&t, p, &h, &x);
            let want = vec![&hx[0] / &hx[2], &hx[1] / &hx[2]];
            f.eval_into(&x, &mut out, &mut scratch).unwrap();
            assert_eq!(out, want, "p = {p}, x = {x}");
        }
    }
}

#[test]
fn bad_buffers_are_named_errors() {
    let t = vec![0.0, 0.0, 1.0, 1.0];
    let kind = |e: crate::Error| (e.kind, e.field);
    let e = BSpline::from_coordinates(1, t.clone(), 0, vec![0.0, 1.0]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "dim".into()));
    let e = BSpline::from_coordinates(1, t.clone(), 2, vec![0.0, 1.0, 2.0]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Shape, "coordinates".into()));
    let e = BSpline::<f64>::from_coordinates(1, t.clone(), 1, vec![]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Empty, "coordinates".into()));
    // One point is too few for degree 1; three points need five knots.
    let e = BSpline::from_coordinates(1, t.clone(), 1, vec![0.0]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Shape, "coordinates".into()));
    let e = BSpline::from_coordinates(1, t.clone(), 1, vec![0.0, 1.0, 2.0]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Shape, "knots".into()));
    let f = BSpline::from_coordinates(1, t.clone(), 2, vec![0.0, 1.0, 2.0, 3.0]).unwrap();
    let mut scratch = Vec::new();
    let e = f.eval_into(&0.5, &mut [0.0; 3], &mut scratch).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "out".into()));
    let e = f.eval_into(&2.0, &mut [0.0; 2], &mut scratch).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Domain, "t".into()));

    let e =
        RationalBSpline::from_coordinates(1, t.clone(), 1, vec![0.0, 1.0], vec![1.0]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Shape, "weights".into()));
    let e = RationalBSpline::from_coordinates(1, t.clone(), 1, vec![0.0, 1.0], vec![1.0, 0.0])
        .unwrap_err();
    assert_eq!(kind(e), (ErrorKind::ZeroWeight, "weights[1]".into()));
    let r =
        RationalBSpline::from_coordinates(1, t.clone(), 1, vec![0.0, 1.0], vec![1.0, 1.0]).unwrap();
    let e = r.eval_into(&0.5, &mut [], &mut scratch).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "out".into()));

    // A 2 x 2 grid needs 4 points; 3 are refused, and so are a zero dimension and bad knots.
    let s =
        |dim, c: Vec<f64>| BSplineSurface::from_coordinates((1, 1), t.clone(), t.clone(), dim, c);
    let e = s(1, vec![0.0; 3]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Shape, "coordinates".into()));
    let e = s(0, vec![0.0; 4]).unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "dim".into()));
    let e = BSplineSurface::from_coordinates(
        (1, 1),
        t.clone(),
        vec![0.0, 1.0, 0.5, 2.0],
        1,
        vec![0.0; 4],
    )
    .unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Domain, "v_knots[2]".into()));
    let f = s(2, vec![0.0; 8]).unwrap();
    let e = f
        .eval_into(&0.5, &0.5, &mut [0.0], &mut scratch)
        .unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "out".into()));
    let nurbs = RationalBSplineSurface::new(
        (1, 1),
        t.clone(),
        t.clone(),
        vec![vec![vec![0.0], vec![1.0]], vec![vec![2.0], vec![3.0]]],
        vec![vec![1.0, 1.0], vec![1.0, 3.0]],
    )
    .unwrap();
    let mut x = [0.0];
    nurbs.eval_into(&0.5, &0.5, &mut x, &mut scratch).unwrap();
    assert_eq!(x, [2.0]);
    let e = nurbs
        .eval_into(&0.5, &0.5, &mut [0.0; 2], &mut scratch)
        .unwrap_err();
    assert_eq!(kind(e), (ErrorKind::Dimension, "out".into()));
}
