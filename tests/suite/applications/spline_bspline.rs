//! B-splines cross-checked between independent algorithms: de Boor's algorithm (blossoms),
//! the recursive definition of the N_i^p (Definition 1.1 of seed 002), the power-basis pieces
//! a spline was built from (Curry-Schoenberg), the Bézier pieces against the engine's
//! restriction, and knot insertion against the original curve.

use crate::common::{q, Rng};
use blossom::curve_blossom;
use blossom::{bspline_from_pieces, bspline_from_pieces_with_knots, BSpline, Piece};
use blossom::{restrict_power_curve, Method, PowerCurve, Rational, Ring};

fn pad(c: &PowerCurve<Rational>, p: usize) -> PowerCurve<Rational> {
    let mut v = c.coefficients().to_vec();
    v.resize(p + 1, vec![q(0, 1); c.dim()]);
    PowerCurve::new(v).unwrap()
}

/// Random pieces of degree p on breakpoints 0 < e_1 < ... with a prescribed continuity r_i at
/// each breakpoint: the next piece copies the previous one's Taylor coefficients up to r_i
/// and draws the rest (so the exact continuity is at least r_i, and r_i for generic draws).
fn random_spline(
    rng: &mut Rng,
    p: usize,
    k: usize,
    dim: usize,
) -> (Vec<Piece<Rational>>, Vec<isize>) {
    let mut pieces = Vec::new();
    let mut conts = Vec::new();
    let mut e = q(0, 1);
    let mut prev: Option<PowerCurve<Rational>> = None;
    for _ in 0..k {
        let len = q((rng.next() % 3) as i64 + 1, (rng.next() % 2) as i64 + 1);
        let next_e = &e + &len;
        let curve = match &prev {
            None => rng.curve(p, dim),
            Some(c) => {
                let r = (rng.next() % (p as u64 + 2)) as isize - 1;
                conts.push(r);
                // Taylor coefficients at e: copy 0..=r, draw the others; shift back by -e.
                let mut t = c.coefficients().to_vec();
                blossom::engine::taylor_shift(&mut t, &e);
                for (i, ti) in t.iter_mut().enumerate() {
                    if i as isize > r {
                        *ti = rng.point(dim);
                    }
                }
                blossom::engine::taylor_shift(&mut t, &e.neg());
                PowerCurve::new(t).unwrap()
            }
        };
        pieces.push(Piece {
            interval: [e.clone(), next_e.clone()],
            curve: curve.clone(),
        });
        prev = Some(curve);
        e = next_e;
    }
    (pieces, conts)
}

/// The piece whose interval [e_0, e_1) holds `x` (a span may cover several pieces when they
/// are one polynomial: then its breakpoints are no knots).
fn piece_at<'a>(pieces: &'a [Piece<Rational>], x: &Rational) -> &'a Piece<Rational> {
    pieces
        .iter()
        .find(|s| s.interval[0] <= *x && *x < s.interval[1])
        .unwrap()
}

#[test]
fn curry_schoenberg_round_trips_through_every_algorithm() {
    let mut rng = Rng(40);
    for p in 0..=5 {
        for k in 1..=4 {
            let (pieces, conts) = random_spline(&mut rng, p, k, 2);
            let f = bspline_from_pieces(p, &pieces).unwrap();
            // Interior multiplicities are p - r, at most.
            for (i, r) in conts.iter().enumerate() {
                let e = &pieces[i + 1].interval[0];
                let mult = f.knot_vector().multiplicity(e) as isize;
                assert!(
                    mult <= p as isize - r,
                    "p={p} breakpoint {e}: multiplicity {mult} with continuity {r}"
                );
            }
            // Cox-de Boor pieces equal the input pieces on every span.
            for pc in f.power_pieces().unwrap() {
                let src = piece_at(&pieces, &pc.interval[0]);
                assert_eq!(
                    pc.curve,
                    pad(&src.curve, p),
                    "p={p} k={k} {:?}",
                    pc.interval
                );
            }
            // Bézier pieces equal the engine's restriction of the input pieces.
            for bp in f.bezier_pieces() {
                let src = piece_at(&pieces, &bp.interval[0]);
                let want = restrict_power_curve(
                    &pad(&src.curve, p),
                    &bp.interval[0],
                    &bp.interval[1],
                    Method::Bulk,
                );
                assert_eq!(bp.curve, want);
            }
            // De Boor's algorithm equals the pieces at random parameters and at the breakpoints.
            let (a, b) = (f.domain().0.clone(), f.domain().1.clone());
            for s in pieces.iter() {
                let mid = (&s.interval[0] + &s.interval[1]) / q(2, 1);
                for t in [s.interval[0].clone(), mid] {
                    assert_eq!(f.eval(&t).unwrap(), s.curve.eval(&t), "p={p} t={t}");
                }
            }
            assert_eq!(f.eval(&b).unwrap(), pieces.last().unwrap().curve.eval(&b));
            assert_eq!(f.eval(&a).unwrap(), pieces[0].curve.eval(&a));
        }
    }
}

#[test]
fn blossom_by_de_boor_is_the_blossom_of_the_piece() {
    let mut rng = Rng(41);
    for p in 1..=5 {
        let (pieces, _) = random_spline(&mut rng, p, 3, 3);
        let f = bspline_from_pieces(p, &pieces).unwrap();
        let t = f.knots().to_vec();
        for s in f.knot_vector().spans() {
            let src = piece_at(&pieces, &t[s]);
            let args: Vec<Rational> = (0..p).map(|_| rng.rational()).collect();
            assert_eq!(
                f.blossom(s, &args).unwrap(),
                curve_blossom(&pad(&src.curve, p), &args).unwrap()
            );
            // Symmetry: reversed arguments give the same point.
            let rev: Vec<Rational> = args.iter().rev().cloned().collect();
            assert_eq!(f.blossom(s, &rev).unwrap(), f.blossom(s, &args).unwrap());
        }
        assert_eq!(f.blossom(0, &vec![q(0, 1); p]).unwrap_err().field, "span");
    }
}

#[test]
fn knot_insertion_preserves_the_curve() {
    let mut rng = Rng(42);
    for p in 1..=4 {
        let (pieces, _) = random_spline(&mut rng, p, 3, 2);
        let mut f = bspline_from_pieces(p, &pieces).unwrap();
        let (a, b) = (f.domain().0.clone(), f.domain().1.clone());
        for step in 0..6 {
            // Insert at a random point of the domain, or at an existing knot.
            let x = if step % 2 == 0 {
                &a + (&b - &a) * q((rng.next() % 97) as i64, 97)
            } else {
                f.knots()[p + 1].clone()
            };
            match f.insert_knot(&x) {
                Ok(g) => {
                    assert_eq!(g.control_points().len(), f.control_points().len() + 1);
                    for pc in &pieces {
                        let mid = (&pc.interval[0] + &pc.interval[1]) / q(3, 1)
                            + &pc.interval[0] * q(1, 3);
                        for t in [pc.interval[0].clone(), mid, x.clone()] {
                            if t >= a && t <= b {
                                assert_eq!(
                                    g.eval(&t).unwrap(),
                                    f.eval(&t).unwrap(),
                                    "p={p} x={x} t={t}"
                                );
                            }
                        }
                    }
                    f = g;
                }
                Err(e) => assert!(f.knot_vector().multiplicity(&x) == p + 1, "{e}"),
            }
        }
        // Inserting every interior knot up to multiplicity p gives the Bézier pieces as the
        // de Boor points (Boehm's route to the Bézier form, against blossoms).
        let mut g = f.clone();
        let interior: Vec<Rational> = {
            let mut v: Vec<Rational> = g.knots()[p + 1..g.control_points().len()].to_vec();
            v.dedup();
            v
        };
        for x in interior {
            while g.knot_vector().multiplicity(&x) < p {
                g = g.insert_knot(&x).unwrap();
            }
        }
        // Theorem 2.2 with every interior knot of multiplicity >= p: the de Boor points of a
        // span are the Bézier points of its piece.
        let t = g.knots().to_vec();
        let spans = g.knot_vector().spans();
        for (s, bp) in spans.iter().zip(f.bezier_pieces()) {
            assert_eq!(bp.interval, [t[*s].clone(), t[s + 1].clone()]);
            assert_eq!(
                g.control_points().slice(s - p..s + 1),
                bp.curve.control_points(),
                "p={p} span {s}"
            );
        }
    }
}

#[test]
fn fewer_knots_than_the_continuity_needs_are_refused() {
    // C^0 pieces given a knot vector that claims C^1 at the breakpoint.
    let c = |v: &[i64]| PowerCurve::new(v.iter().map(|&x| vec![q(x, 1)]).collect()).unwrap();
    let pieces = vec![
        Piece {
            interval: [q(0, 1), q(1, 1)],
            curve: c(&[0, 1]),
        },
        Piece {
            interval: [q(1, 1), q(2, 1)],
            curve: c(&[2, -1]),
        },
    ];
    let ok = bspline_from_pieces(2, &pieces).unwrap();
    assert_eq!(ok.knot_vector().multiplicity(&q(1, 1)), 2);
    let e =
        bspline_from_pieces_with_knots(2, &pieces, [0, 0, 0, 1, 2, 2, 2].map(|k| q(k, 1)).to_vec())
            .unwrap_err();
    assert_eq!(e.field, "knots");
    assert!(e.message.contains("d_"), "{e}");
    // A knot vector whose domain is not the pieces' interval.
    let e = bspline_from_pieces_with_knots(
        2,
        &pieces,
        [0, 0, 0, 1, 1, 3, 3, 3].map(|k| q(k, 1)).to_vec(),
    )
    .unwrap_err();
    assert!(e.message.contains("domain"), "{e}");
    // More knots than needed are fine.
    let more = bspline_from_pieces_with_knots(
        2,
        &pieces,
        [0, 0, 0, 1, 1, 1, 2, 2, 2].map(|k| q(k, 1)).to_vec(),
    )
    .unwrap();
    assert_eq!(more.eval(&q(3, 2)).unwrap(), vec![q(1, 2)]);
}

#[test]
fn floats_follow_the_exact_answer() {
    let mut rng = Rng(43);
    let (pieces, _) = random_spline(&mut rng, 3, 3, 2);
    let f = bspline_from_pieces(3, &pieces).unwrap();
    let to_f = |x: &Rational| blossom::rational_to_f64(x);
    let ff = BSpline::new(
        3,
        f.knots().iter().map(to_f).collect(),
        f.control_points()
            .iter()
            .map(|p| p.iter().map(to_f).collect())
            .collect(),
    )
    .unwrap();
    for k in 0..=20 {
        let t = f.domain().0 + (f.domain().1 - f.domain().0) * q(k, 20);
        let exact = f.eval(&t).unwrap();
        let float = ff.eval(&to_f(&t)).unwrap();
        for (x, y) in exact.iter().zip(&float) {
            assert!((to_f(x) - y).abs() <= 1e-9 * (1.0 + y.abs()), "{x} vs {y}");
        }
    }
}
