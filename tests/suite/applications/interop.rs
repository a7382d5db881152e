//! The optional features `mint`, `kurbo`, `lyon` and `serde`: conversions both ways, their errors on a
//! wrong degree or dimension, kurbo's and lyon's evaluation and subdivision against the library's on random
//! curves, JSON round trips of every geometry type and the refusal of invalid documents.
//!
//! Each part compiles only with its feature: `cargo test -p blossom --features mint,kurbo,lyon,serde
//! --test suite interop`. `cargo test --workspace` runs them too (the application's
//! dev-dependency on `blossom` turns the features on; see cli/Cargo.toml).

#[cfg(feature = "mint")]
mod mint_points {
    use blossom::{BezierCurve, ErrorKind, ForeignPoint, Rational};

    #[test]
    fn mint_points_convert_both_ways() {
        let p = mint::Point2 { x: 1.5, y: -2.0 };
        assert_eq!(p.into_point(), vec![1.5, -2.0]);
        assert_eq!(mint::Point2::try_from_point(&[1.5, -2.0], "p").unwrap(), p);
        let v = mint::Vector3 {
            x: 1.0,
            y: 2.0,
            z: 3.0,
        };
        assert_eq!(v.into_point(), vec![1.0, 2.0, 3.0]);
        assert_eq!(
            mint::Vector3::try_from_point(&[1.0, 2.0, 3.0], "v").unwrap(),
            v
        );
        // Any Clone number type, exact ones included.
        let q = |n: i64| Rational::from_integer(n.into());
        let r = mint::Point3 {
            x: q(1),
            y: q(2),
            z: q(3),
        };
        assert_eq!(r.clone().into_point(), vec![q(1), q(2), q(3)]);
        assert_eq!(
            mint::Point3::try_from_point(&[q(1), q(2), q(3)], "r").unwrap(),
            r
        );
        assert_eq!(
            mint::Vector2::try_from_point(&[q(4), q(5)], "w").unwrap(),
            mint::Vector2 { x: q(4), y: q(5) }
        );
    }

    #[test]
    fn mint_dimension_mismatch_is_an_error() {
        let e = mint::Point2::<f64>::try_from_point(&[1.0, 2.0, 3.0], "corner").unwrap_err();
        assert_eq!((e.path(), e.kind()), ("corner", ErrorKind::Dimension));
        assert_eq!(
            e.to_string(),
            "corner: expected 2 coordinates (a mint::Point2), found 3"
        );
        let e = mint::Vector3::<f64>::try_from_point(&[1.0], "v").unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Dimension);

        let spatial = BezierCurve::new(vec![vec![0.0, 0.0, 1.0], vec![1.0, 0.0, 0.0]]).unwrap();
        let e = Vec::<mint::Point2<f64>>::try_from(&spatial).unwrap_err();
        assert_eq!(
            (e.path(), e.kind()),
            ("control_points[0]", ErrorKind::Dimension)
        );
        assert!(Vec::<mint::Point3<f64>>::try_from(&spatial).is_ok());
    }

    #[test]
    fn mint_polygons_are_bezier_curves() {
        let polygon = vec![
            mint::Point2 { x: 0.0, y: 0.0 },
            mint::Point2 { x: 1.0, y: 2.0 },
            mint::Point2 { x: 3.0, y: 3.0 },
            mint::Point2 { x: 4.0, y: 0.0 },
        ];
        let cubic = BezierCurve::try_from(polygon.clone()).unwrap();
        assert_eq!(cubic.degree(), 3);
        assert_eq!(Vec::<mint::Point2<f64>>::try_from(&cubic).unwrap(), polygon);
        // The left half by the library, back in mint's type: its end is the curve's middle.
        let left: Vec<mint::Point2<f64>> = (&cubic.subsegment(0.0..0.5)).try_into().unwrap();
        let middle = cubic.eval(&0.5);
        assert_eq!([left[3].x, left[3].y], [middle[0], middle[1]]);

        let e = BezierCurve::try_from(Vec::<mint::Vector2<f64>>::new()).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("control_points", ErrorKind::Empty));
    }
}

#[cfg(feature = "kurbo")]
mod kurbo_curves {
    use crate::common::Rng;
    use blossom::{Bezier, BezierCurve, ErrorKind, ForeignPoint};
    use kurbo::{CubicBez, Line, ParamCurve, PathSeg, Point, QuadBez, Vec2};

    fn pt(rng: &mut Rng) -> Point {
        Point::new(rng.unit(), rng.unit())
    }

    #[test]
    fn kurbo_points_convert_both_ways() {
        assert_eq!(Point::new(1.0, 2.0).into_point(), vec![1.0, 2.0]);
        assert_eq!(
            Vec2::try_from_point(&[3.0, 4.0], "v").unwrap(),
            Vec2::new(3.0, 4.0)
        );
        let e = Point::try_from_point(&[1.0], "p").unwrap_err();
        assert_eq!(
            e.to_string(),
            "p: expected 2 coordinates (a kurbo::Point), found 1"
        );
    }

    #[test]
    fn kurbo_segments_round_trip() {
        let mut rng = Rng(15);
        let line = Line::new(pt(&mut rng), pt(&mut rng));
        let quad = QuadBez::new(pt(&mut rng), pt(&mut rng), pt(&mut rng));
        let cubic = CubicBez::new(pt(&mut rng), pt(&mut rng), pt(&mut rng), pt(&mut rng));

        let b = BezierCurve::from(cubic);
        assert_eq!(b.degree(), 3);
        assert_eq!(b.control_points()[1], vec![cubic.p1.x, cubic.p1.y]);
        assert_eq!(CubicBez::try_from(&b).unwrap(), cubic);
        assert_eq!(QuadBez::try_from(BezierCurve::from(quad)).unwrap(), quad);
        assert_eq!(Line::try_from(&BezierCurve::from(line)).unwrap(), line);

        let fixed = Bezier::<f64, 2>::from(cubic);
        assert_eq!(fixed.points()[3], [cubic.p3.x, cubic.p3.y]);
        assert_eq!(CubicBez::try_from(&fixed).unwrap(), cubic);
        assert_eq!(QuadBez::try_from(&Bezier::from(quad)).unwrap(), quad);
        assert_eq!(Line::try_from(&Bezier::from(line)).unwrap(), line);

        for seg in [
            PathSeg::Line(line),
            PathSeg::Quad(quad),
            PathSeg::Cubic(cubic),
        ] {
            assert_eq!(PathSeg::try_from(&BezierCurve::from(seg)).unwrap(), seg);
            assert_eq!(PathSeg::try_from(BezierCurve::from(seg)).unwrap(), seg);
            assert_eq!(PathSeg::try_from(&Bezier::from(seg)).unwrap(), seg);
        }
    }

    #[test]
    fn kurbo_wrong_degree_or_dimension_is_an_error() {
        let quadratic =
            BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 1.0], vec![2.0, 0.0]]).unwrap();
        let e = CubicBez::try_from(&quadratic).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("control_points", ErrorKind::Degree));
        assert_eq!(
            e.to_string(),
            "control_points: a kurbo::CubicBez has degree 3 (4 control points), found degree 2"
        );
        assert_eq!(
            Line::try_from(&quadratic).unwrap_err().kind(),
            ErrorKind::Degree
        );

        let spatial = BezierCurve::new(vec![vec![0.0, 0.0, 0.0], vec![1.0, 1.0, 1.0]]).unwrap();
        let e = Line::try_from(&spatial).unwrap_err();
        assert_eq!(
            (e.path(), e.kind()),
            ("control_points[0]", ErrorKind::Dimension)
        );

        let quartic = BezierCurve::new(vec![vec![0.0, 0.0]; 5]).unwrap();
        let e = PathSeg::try_from(&quartic).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("control_points", ErrorKind::Degree));
        let point = BezierCurve::new(vec![vec![0.0, 0.0]]).unwrap();
        assert_eq!(
            PathSeg::try_from(&point).unwrap_err().kind(),
            ErrorKind::Degree
        );

        let fixed = Bezier::new(vec![[0.0, 0.0]; 4]).unwrap();
        let e = QuadBez::try_from(&fixed).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("points", ErrorKind::Degree));
        let e = PathSeg::try_from(&Bezier::new(vec![[0.0, 0.0]; 6]).unwrap()).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("points", ErrorKind::Degree));
    }

    /// The largest distance between two lists of 2-D points.
    fn distance(a: &[Vec<f64>], b: &[Point]) -> f64 {
        a.iter()
            .zip(b)
            .map(|(p, q)| (p[0] - q.x).abs().max((p[1] - q.y).abs()))
            .fold(0.0, f64::max)
    }

    #[test]
    fn kurbo_and_blossom_agree_on_random_curves() {
        let mut rng = Rng(2024);
        for _ in 0..200 {
            let cubic = CubicBez::new(pt(&mut rng), pt(&mut rng), pt(&mut rng), pt(&mut rng));
            let quad = QuadBez::new(pt(&mut rng), pt(&mut rng), pt(&mut rng));
            for seg in [PathSeg::Cubic(cubic), PathSeg::Quad(quad)] {
                let ours = BezierCurve::from(seg);
                // Control points in [-1, 1]: 1e-14 is about 50 units in the last place.
                for k in 0..=16 {
                    let t = k as f64 / 16.0;
                    let d = distance(&[ours.eval(&t)], &[seg.eval(t)]);
                    assert!(d <= 1e-14, "eval at {t}: {d:e}");
                }
                let (a, b) = (rng.unit().abs() * 0.5, 0.5 + rng.unit().abs() * 0.5);
                let theirs = seg.subsegment(a..b);
                let mine = ours.subsegment(a..b);
                let points: Vec<Point> = match theirs {
                    PathSeg::Cubic(c) => vec![c.p0, c.p1, c.p2, c.p3],
                    PathSeg::Quad(q) => vec![q.p0, q.p1, q.p2],
                    PathSeg::Line(l) => vec![l.p0, l.p1],
                };
                let d = distance(&mine.control_points().to_vec(), &points);
                assert!(d <= 1e-12, "subsegment {a}..{b}: {d:e}");
                // And the library's answer converts back to the kurbo segment of that degree.
                assert!(PathSeg::try_from(&mine).is_ok());
            }
        }
    }
}

#[cfg(feature = "lyon")]
mod lyon_curves {
    use crate::common::Rng;
    use blossom::{Bezier, BezierCurve, ErrorKind, ForeignPoint};
    use lyon_geom::{
        point, vector, CubicBezierSegment, LineSegment, Point, QuadraticBezierSegment, Vector,
    };

    fn pt(rng: &mut Rng) -> Point<f64> {
        point(rng.unit(), rng.unit())
    }

    #[test]
    fn lyon_points_convert_both_ways() {
        assert_eq!(point(1.0, 2.0).into_point(), vec![1.0, 2.0]);
        assert_eq!(
            Vector::<f64>::try_from_point(&[3.0, 4.0], "v").unwrap(),
            vector(3.0, 4.0)
        );
        let e = Point::<f64>::try_from_point(&[1.0, 2.0, 3.0], "p").unwrap_err();
        assert_eq!(
            e.to_string(),
            "p: expected 2 coordinates (a lyon_geom::Point), found 3"
        );
    }

    #[test]
    fn lyon_segments_round_trip() {
        let mut rng = Rng(16);
        let line = LineSegment {
            from: pt(&mut rng),
            to: pt(&mut rng),
        };
        let quad = QuadraticBezierSegment {
            from: pt(&mut rng),
            ctrl: pt(&mut rng),
            to: pt(&mut rng),
        };
        let cubic = CubicBezierSegment {
            from: pt(&mut rng),
            ctrl1: pt(&mut rng),
            ctrl2: pt(&mut rng),
            to: pt(&mut rng),
        };
        let b = BezierCurve::from(cubic);
        assert_eq!(b.degree(), 3);
        assert_eq!(b.control_points()[2], vec![cubic.ctrl2.x, cubic.ctrl2.y]);
        assert_eq!(CubicBezierSegment::try_from(&b).unwrap(), cubic);
        assert_eq!(
            QuadraticBezierSegment::try_from(BezierCurve::from(quad)).unwrap(),
            quad
        );
        assert_eq!(
            LineSegment::try_from(&BezierCurve::from(line)).unwrap(),
            line
        );
        let fixed = Bezier::<f64, 2>::from(cubic);
        assert_eq!(fixed.points()[3], [cubic.to.x, cubic.to.y]);
        assert_eq!(CubicBezierSegment::try_from(&fixed).unwrap(), cubic);
        assert_eq!(
            QuadraticBezierSegment::try_from(Bezier::from(quad)).unwrap(),
            quad
        );
        assert_eq!(LineSegment::try_from(&Bezier::from(line)).unwrap(), line);
    }

    #[test]
    fn lyon_wrong_degree_or_dimension_is_an_error() {
        let quadratic =
            BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 1.0], vec![2.0, 0.0]]).unwrap();
        let e = CubicBezierSegment::<f64>::try_from(&quadratic).unwrap_err();
        assert_eq!((e.path(), e.kind()), ("control_points", ErrorKind::Degree));
        assert_eq!(
            e.to_string(),
            "control_points: a lyon_geom::CubicBezierSegment has degree 3 (4 control points), found degree 2"
        );
        let spatial = BezierCurve::new(vec![vec![0.0, 0.0, 0.0], vec![1.0, 1.0, 1.0]]).unwrap();
        let e = LineSegment::<f64>::try_from(&spatial).unwrap_err();
        assert_eq!(
            (e.path(), e.kind()),
            ("control_points[0]", ErrorKind::Dimension)
        );
        let e = QuadraticBezierSegment::<f64>::try_from(&Bezier::new(vec![[0.0, 0.0]; 4]).unwrap())
            .unwrap_err();
        assert_eq!((e.path(), e.kind()), ("points", ErrorKind::Degree));
    }

    /// lyon's own evaluation and `split_range` against the library's on random cubics: the
    /// conversion keeps the curve, not only the numbers.
    #[test]
    fn lyon_and_blossom_agree_on_random_curves() {
        let mut rng = Rng(2025);
        for _ in 0..200 {
            let cubic = CubicBezierSegment {
                from: pt(&mut rng),
                ctrl1: pt(&mut rng),
                ctrl2: pt(&mut rng),
                to: pt(&mut rng),
            };
            let ours = BezierCurve::from(cubic);
            for k in 0..=16 {
                let t = k as f64 / 16.0;
                let (mine, theirs) = (ours.eval(&t), cubic.sample(t));
                let d = (mine[0] - theirs.x).abs().max((mine[1] - theirs.y).abs());
                assert!(d <= 1e-14, "eval at {t}: {d:e}");
            }
            let (a, b) = (rng.unit().abs() * 0.5, 0.5 + rng.unit().abs() * 0.5);
            let theirs = cubic.split_range(a..b);
            let mine = CubicBezierSegment::try_from(&ours.subsegment(a..b)).unwrap();
            for (p, q) in [
                (mine.from, theirs.from),
                (mine.ctrl1, theirs.ctrl1),
                (mine.ctrl2, theirs.ctrl2),
                (mine.to, theirs.to),
            ] {
                assert!((p - q).length() <= 1e-12, "subsegment {a}..{b}");
            }
        }
    }
}

#[cfg(feature = "serde")]
mod serde_documents {
    use crate::common::q;
    use blossom::{
        bspline_from_pieces, BSpline, BSplineSurface, Bezier, BezierCurve, BezierTensor,
        BezierTriangle, KnotVector, Piece, PowerCurve, PowerSurface, PowerTriangle, Rational,
        RationalBSpline, RationalBSplineSurface, RationalBezierCurve, RationalCurve,
        RationalPowerTriangle, RationalSurface, RationalTensorPatch, RationalTriangularPatch,
        TensorPatch, TriangularPatch,
    };
    use serde::de::DeserializeOwned;
    use serde::Serialize;
    use std::fmt::Debug;

    /// `value` written to JSON and read back is `value` again; the JSON text is returned.
    fn round_trip<V: Serialize + DeserializeOwned + PartialEq + Debug>(value: &V) -> String {
        let json = serde_json::to_string(value).unwrap();
        let back: V = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{json}: {e}"));
        assert_eq!(&back, value, "{json}");
        json
    }

    /// The error of reading `json` as a `V`.
    fn refused<V: DeserializeOwned + Debug>(json: &str) -> String {
        serde_json::from_str::<V>(json).unwrap_err().to_string()
    }

    fn r(v: &[(i64, i64)]) -> Vec<Vec<Rational>> {
        v.iter().map(|&(x, y)| vec![q(x, 1), q(y, 3)]).collect()
    }

    #[test]
    fn rationals_are_written_as_num_rational_writes_them() {
        assert_eq!(
            serde_json::to_string(&q(1, 3)).unwrap(),
            "[[1,[1]],[1,[3]]]"
        );
        assert_eq!(
            serde_json::to_string(&q(-2, 1)).unwrap(),
            "[[-1,[2]],[1,[1]]]"
        );
        let c = BezierCurve::new(vec![vec![q(1, 3)], vec![q(0, 1)]]).unwrap();
        assert_eq!(
            round_trip(&c),
            r#"{"control_points":[[[[1,[1]],[1,[3]]]],[[[0,[]],[1,[1]]]]]}"#
        );
        // A zero denominator is num-rational's error.
        assert!(
            refused::<BezierCurve<Rational>>(r#"{"control_points":[[[[1,[1]],[0,[]]]]]}"#)
                .contains("non-zero denominator")
        );
    }

    #[test]
    fn power_and_bezier_forms_round_trip() {
        let c = PowerCurve::new(vec![vec![1.0, 2.0], vec![0.5, -3.25]]).unwrap();
        assert_eq!(
            round_trip(&c),
            r#"{"coefficients":[[1.0,2.0],[0.5,-3.25]]}"#
        );
        round_trip(&PowerCurve::new(r(&[(1, 2), (3, -4), (0, 5)])).unwrap());
        round_trip(&PowerSurface::new(vec![r(&[(1, 1), (2, 2)]), r(&[(3, 3), (4, 4)])]).unwrap());
        let tri = PowerTriangle::new(vec![r(&[(1, 1), (2, 2)]), r(&[(3, 3)])]).unwrap();
        round_trip(&tri);

        round_trip(&BezierCurve::new(vec![vec![0.1, 0.2, 0.3]; 3]).unwrap());
        round_trip(&TensorPatch::new(vec![r(&[(1, 1), (2, 2), (5, 5)]); 2]).unwrap());
        let patch = TriangularPatch::new(1, r(&[(1, 1), (2, 2), (3, 3)])).unwrap();
        assert!(round_trip(&patch).starts_with(r#"{"degree":1,"control_points":"#));

        let fixed = Bezier::new(vec![[0.0, 1.0], [2.0, 3.0]]).unwrap();
        assert_eq!(round_trip(&fixed), r#"{"points":[[0.0,1.0],[2.0,3.0]]}"#);
        let t = BezierTensor::new((1, 2), vec![[1.0, 2.0, 3.0]; 6]).unwrap();
        assert!(round_trip(&t).starts_with(r#"{"degree":[1,2],"points":"#));
        round_trip(&BezierTriangle::new(2, vec![[q(1, 2)]; 6]).unwrap());
    }

    #[test]
    fn a_grid_power_triangle_is_written_as_its_triangular_array() {
        // u + v as a grid (n, m) = (1, 1): total degree 2, rows of 2, 2 points.
        let grid = PowerSurface::new(vec![vec![vec![0.0], vec![1.0]], vec![vec![1.0], vec![0.0]]])
            .unwrap();
        let tri = PowerTriangle::from_surface(&grid);
        let json = serde_json::to_string(&tri).unwrap();
        assert_eq!(
            json,
            r#"{"coefficients":[[[0.0],[1.0],[0.0]],[[1.0],[0.0]],[[0.0]]]}"#
        );
        let back: PowerTriangle<f64> = serde_json::from_str(&json).unwrap();
        assert_eq!(back.degree(), tri.degree());
        for (u, v) in [(0.5, 2.0), (-1.0, 3.0)] {
            assert_eq!(back.eval(&u, &v), tri.eval(&u, &v));
        }
        // At a lower degree (rows cut short) the same holds.
        let low = tri.at_degree(1).unwrap();
        assert_eq!(
            round_trip(&low),
            r#"{"coefficients":[[[0.0],[1.0]],[[1.0]]]}"#
        );
    }

    #[test]
    fn splines_and_rational_forms_round_trip() {
        let knots = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
        round_trip(&KnotVector::new(2, knots.clone()).unwrap());
        let points = vec![
            vec![1.0, 1.0],
            vec![2.0, 3.0],
            vec![4.0, 3.0],
            vec![3.0, 1.0],
        ];
        let f = BSpline::new(2, knots.clone(), points.clone()).unwrap();
        assert_eq!(
            round_trip(&f),
            r#"{"degree":2,"knots":[0.0,0.0,0.0,1.0,2.0,2.0,2.0],"control_points":[[1.0,1.0],[2.0,3.0],[4.0,3.0],[3.0,1.0]]}"#
        );
        let s = BSplineSurface::new(
            (1, 1),
            vec![0.0, 0.0, 1.0, 2.0, 2.0],
            vec![0.0, 0.0, 1.0, 1.0],
            vec![
                vec![vec![0.0], vec![0.0]],
                vec![vec![1.0], vec![2.0]],
                vec![vec![0.0], vec![4.0]],
            ],
        )
        .unwrap();
        round_trip(&s);

        let arc = RationalCurve::new(&r(&[(1, 0), (0, 6), (-1, 0)]), &[q(1, 1), q(0, 1), q(1, 1)])
            .unwrap();
        assert!(round_trip(&arc).starts_with(r#"{"numerator":"#));
        // A shorter denominator is padded with zeros, which read back the same.
        let short = RationalCurve::new(&[vec![1.0], vec![2.0]], &[1.0]).unwrap();
        assert_eq!(
            round_trip(&short),
            r#"{"numerator":[[1.0],[2.0]],"denominator":[1.0,0.0]}"#
        );
        let rs = RationalSurface::new(
            &[r(&[(1, 1)]), r(&[(2, 2)])],
            &[vec![q(1, 1)], vec![q(2, 1)]],
        )
        .unwrap();
        round_trip(&rs);
        let tri = RationalPowerTriangle::new(
            &[r(&[(1, 1), (0, 2)]), r(&[(2, 2)])],
            &[vec![q(1, 1), q(0, 1)], vec![q(2, 1)]],
        )
        .unwrap();
        round_trip(&tri);
        // A grid comes back as the same quotient in triangular form.
        let grid = RationalPowerTriangle::from_surface(&rs);
        let back: RationalPowerTriangle<Rational> =
            serde_json::from_str(&serde_json::to_string(&grid).unwrap()).unwrap();
        assert_eq!(back.degree(), grid.degree());
        assert_eq!(back.eval(&q(1, 2), &q(3, 1)), grid.eval(&q(1, 2), &q(3, 1)));
        round_trip(
            &RationalBezierCurve::new(r(&[(1, 1), (2, 2)]), vec![q(1, 2), q(3, 1)]).unwrap(),
        );
        // The rational patches: rows [nu][mu] of points and of weights; lexicographic lists.
        let patch = RationalTensorPatch::from_coordinates(
            (1, 0),
            2,
            vec![1.0, 2.0, 3.0, 4.0],
            vec![0.5, 2.0],
        )
        .unwrap();
        assert_eq!(
            round_trip(&patch),
            r#"{"points":[[[1.0,2.0]],[[3.0,4.0]]],"weights":[[0.5],[2.0]]}"#
        );
        let tri = RationalTriangularPatch::from_coordinates(
            1,
            1,
            vec![1.0, 2.0, 3.0],
            vec![1.0, 2.0, 4.0],
        )
        .unwrap();
        assert_eq!(
            round_trip(&tri),
            r#"{"degree":1,"points":[[1.0],[2.0],[3.0]],"weights":[1.0,2.0,4.0]}"#
        );
        round_trip(
            &rs.tensor(&[q(0, 1), q(1, 1), q(0, 1), q(1, 1)], None)
                .unwrap(),
        );

        // NURBS: exact numbers come back exactly; weights that are powers of two, exactly in
        // floating point too.
        let exact = |v: &[f64]| {
            v.iter()
                .map(|&x| Rational::from_float(x).unwrap())
                .collect()
        };
        let nurbs = RationalBSpline::new(
            2,
            exact(&knots),
            r(&[(1, 1), (2, 3), (4, 3), (3, 1)]),
            vec![q(1, 1), q(1, 3), q(5, 7), q(2, 1)],
        )
        .unwrap();
        round_trip(&nurbs);
        let float = RationalBSpline::new(2, knots, points, vec![1.0, 0.5, 2.0, 4.0]).unwrap();
        round_trip(&float);
        let surface = RationalBSplineSurface::new(
            (1, 1),
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
            vec![vec![vec![0.0], vec![1.0]], vec![vec![2.0], vec![3.0]]],
            vec![vec![1.0, 1.0], vec![1.0, 2.0]],
        )
        .unwrap();
        round_trip(&surface);
    }

    #[test]
    fn pieces_and_results_are_written() {
        let pieces = vec![
            Piece {
                interval: [q(0, 1), q(1, 1)],
                curve: PowerCurve::new(vec![vec![q(0, 1)], vec![q(0, 1)], vec![q(1, 1)]]).unwrap(),
            },
            Piece {
                interval: [q(1, 1), q(2, 1)],
                curve: PowerCurve::new(vec![vec![q(-1, 1)], vec![q(2, 1)]]).unwrap(),
            },
        ];
        round_trip(&pieces);
        let f = bspline_from_pieces(2, &pieces).unwrap();
        round_trip(&f.bezier_pieces());
        round_trip(&f.power_pieces().unwrap());

        let arc = RationalCurve::new(&r(&[(1, 0), (0, 6), (-1, 0)]), &[q(1, 1), q(0, 1), q(1, 1)])
            .unwrap();
        let rs = RationalSurface::new(
            &[r(&[(1, 1)]), r(&[(2, 2)])],
            &[vec![q(1, 1)], vec![q(2, 1)]],
        )
        .unwrap();
        let tensor = rs
            .tensor(&[q(0, 1), q(1, 1), q(0, 1), q(1, 1)], None)
            .unwrap();
        let json = serde_json::to_value(&tensor).unwrap();
        assert_eq!(json["weights"].as_array().unwrap().len(), 2);
        let corners = [[q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], [q(0, 1), q(0, 1)]];
        let triangle = rs.triangle(&corners, None).unwrap();
        assert_eq!(serde_json::to_value(&triangle).unwrap()["degree"], 1);
        assert!(serde_json::to_string(&arc.bezier(&q(0, 1), &q(1, 1), None).unwrap()).is_ok());
    }

    #[test]
    fn invalid_documents_are_refused_with_the_field() {
        let e = refused::<BezierCurve<f64>>(r#"{"control_points":[[0.0,0.0],[1.0]]}"#);
        assert!(
            e.starts_with("control_points[1]: expected 2 coordinates, found 1"),
            "{e}"
        );
        let e = refused::<BezierCurve<f64>>(r#"{"control_points":[]}"#);
        assert!(
            e.starts_with("control_points: expected at least one point"),
            "{e}"
        );
        let e = refused::<PowerSurface<f64>>(r#"{"coefficients":[[[1.0],[2.0]],[[3.0]]]}"#);
        assert!(e.starts_with("coefficients[1]: expected 2 points"), "{e}");
        let e = refused::<TriangularPatch<f64>>(r#"{"degree":2,"control_points":[[0.0],[1.0]]}"#);
        assert!(
            e.starts_with("control_points: a triangular patch of degree 2 has 6 points"),
            "{e}"
        );
        let e = refused::<KnotVector<f64>>(r#"{"degree":1,"knots":[0.0,2.0,1.0,3.0]}"#);
        assert!(
            e.starts_with("knots[2]: knots must be non-decreasing"),
            "{e}"
        );
        let e = refused::<BSpline<f64>>(
            r#"{"degree":2,"knots":[0.0,0.0,0.0,1.0,1.0,1.0],"control_points":[[0.0],[1.0]]}"#,
        );
        assert!(
            e.starts_with("control_points: a B-spline of degree 2 needs at least"),
            "{e}"
        );
        let e = refused::<RationalBezierCurve<f64>>(r#"{"points":[[0.0],[1.0]],"weights":[1.0]}"#);
        assert!(e.starts_with("weights: expected 2 weights, found 1"), "{e}");
        let e = refused::<RationalBezierCurve<f64>>(
            r#"{"points":[[0.0],[1.0, 2.0]],"weights":[1.0,1.0]}"#,
        );
        assert!(e.starts_with("points[1]: expected 1 coordinates"), "{e}");
        let e = refused::<RationalTensorPatch<f64>>(
            r#"{"points":[[[0.0]],[[1.0]]],"weights":[[1.0],[1.0,2.0]]}"#,
        );
        assert!(
            e.starts_with("weights[1]: expected 1 weights, found 2"),
            "{e}"
        );
        let e = refused::<RationalTriangularPatch<f64>>(
            r#"{"degree":1,"points":[[0.0],[1.0]],"weights":[1.0,1.0,1.0]}"#,
        );
        assert!(
            e.starts_with("points: a triangular patch of degree 1 has 3 points"),
            "{e}"
        );
        let e = refused::<RationalBSpline<f64>>(
            r#"{"degree":1,"knots":[0.0,0.0,1.0,1.0],"points":[[0.0],[1.0]],"weights":[1.0,0.0]}"#,
        );
        assert!(
            e.starts_with("weights[1]: a weight must be non-zero"),
            "{e}"
        );
        let e = refused::<RationalCurve<f64>>(r#"{"numerator":[[1.0]],"denominator":[0.0]}"#);
        assert!(
            e.starts_with("denominator: the denominator is the zero polynomial"),
            "{e}"
        );
        let e = refused::<PowerTriangle<f64>>(r#"{"coefficients":[[[1.0],[2.0]],[[3.0],[4.0]]]}"#);
        assert!(e.starts_with("coefficients[1]: expected 1 points"), "{e}");

        // Fixed dimension: the points must have D coordinates.
        let e = refused::<Bezier<f64, 2>>(r#"{"points":[[0.0,1.0],[2.0]]}"#);
        assert!(
            e.starts_with("points[1]: expected 2 coordinates, found 1"),
            "{e}"
        );
        let e = refused::<BezierTensor<f64, 1>>(r#"{"degree":[1,1],"points":[[0.0],[1.0]]}"#);
        assert!(e.starts_with("points: expected 4 points, found 2"), "{e}");

        // Unknown or missing fields.
        let e = refused::<BezierCurve<f64>>(r#"{"control_points":[[0.0]],"weights":[1.0]}"#);
        assert!(e.starts_with("unknown field `weights`"), "{e}");
        let e = refused::<TriangularPatch<f64>>(r#"{"control_points":[[0.0]]}"#);
        assert!(e.starts_with("missing field `degree`"), "{e}");
    }

    #[test]
    fn huge_degrees_in_a_document_are_errors_not_panics() {
        let max = usize::MAX;
        for json in [
            format!(r#"{{"degree":[{max},0],"points":[]}}"#),
            format!(r#"{{"degree":[0,{max}],"points":[[1.0]]}}"#),
            format!(
                r#"{{"degree":[{},{}],"points":[]}}"#,
                1u64 << 32,
                1u64 << 32
            ),
        ] {
            let e = refused::<BezierTensor<f64, 1>>(&json);
            assert!(e.starts_with("degree: "), "{json}: {e}");
        }
        let e = refused::<BezierTriangle<f64, 1>>(&format!(r#"{{"degree":{max},"points":[]}}"#));
        assert!(e.starts_with("degree: "), "{e}");
        let e =
            refused::<TriangularPatch<f64>>(&format!(r#"{{"degree":{max},"control_points":[]}}"#));
        assert!(e.starts_with("degree: "), "{e}");
        let e = refused::<KnotVector<f64>>(&format!(r#"{{"degree":{max},"knots":[]}}"#));
        assert!(e.starts_with("degree: "), "{e}");
    }
}
