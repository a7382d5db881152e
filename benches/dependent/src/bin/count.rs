//! One form at one degree, for instruction counts under callgrind (repeatable on a loaded
//! machine, unlike wall time): `count FORM DEGREE PASSES [DIM]`, FORM one of textbook, curve,
//! bezier, into, and in 2-D at degrees 2 and 3 also lyon and kurbo; DIM 3 (degrees 1..=64) or
//! 2 (degrees 1..=8). 1,000 random curves per pass, each restricted to its own random
//! sub-interval of [0, 1] and the answer consumed (its coordinates summed). Run it with PASSES
//! 0 and 10 and take the difference over 10,000 curves (`count.sh`).

#[path = "../../../common/lyon.rs"]
mod lyon;

use blossom::{Bezier, BezierCurve};
use blossom_dependent_bench::{textbook, Rng};
use std::hint::black_box;

/// One pass of a peer over the planar curves `arrays` (degree 2 or 3).
fn peer<const N: usize>(form: &str, arrays: &[[[f64; 2]; N]], ranges: &[(f64, f64)]) -> f64 {
    use kurbo::ParamCurve;
    let mut acc = 0.0;
    let sum = |ps: &[(f64, f64)]| ps.iter().map(|p| p.0 + p.1).sum::<f64>();
    for (c, &(a, b)) in arrays.iter().zip(ranges) {
        let c = black_box(c);
        let p = |i: usize| (c[i][0], c[i][1]);
        acc += match (form, N) {
            ("lyon", 4) => {
                let s = lyon::lyon_cubic(&std::array::from_fn(|i| c[i])).split_range(a..b);
                sum(&[s.from, s.ctrl1, s.ctrl2, s.to].map(|q| (q.x, q.y)))
            }
            ("lyon", 3) => {
                let q = |i: usize| lyon_geom::point(c[i][0], c[i][1]);
                let s = lyon_geom::QuadraticBezierSegment {
                    from: q(0),
                    ctrl: q(1),
                    to: q(2),
                }
                .split_range(a..b);
                sum(&[s.from, s.ctrl, s.to].map(|q| (q.x, q.y)))
            }
            ("kurbo", 4) => {
                let s = kurbo::CubicBez::new(p(0), p(1), p(2), p(3)).subsegment(a..b);
                sum(&[s.p0, s.p1, s.p2, s.p3].map(|q| (q.x, q.y)))
            }
            ("kurbo", 3) => {
                let s = kurbo::QuadBez::new(p(0), p(1), p(2)).subsegment(a..b);
                sum(&[s.p0, s.p1, s.p2].map(|q| (q.x, q.y)))
            }
            _ => panic!("no peer {form} at degree {}", N - 1),
        };
    }
    acc
}

fn run<const N: usize, const D: usize>(form: &str, passes: usize) -> f64 {
    let mut rng = Rng(7);
    let arrays: Vec<[[f64; D]; N]> = (0..1000)
        .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| rng.next())))
        .collect();
    let ranges: Vec<(f64, f64)> = (0..1000)
        .map(|_| {
            let a = 0.05 + 0.4 * rng.next();
            (a, a + 0.1 + 0.4 * rng.next())
        })
        .collect();
    let beziers: Vec<Bezier<f64, D>> = arrays
        .iter()
        .map(|c| Bezier::new(c.to_vec()).unwrap())
        .collect();
    let curves: Vec<BezierCurve<f64>> = beziers.iter().map(BezierCurve::from).collect();
    let planar: Vec<[[f64; 2]; N]> = arrays
        .iter()
        .map(|c| std::array::from_fn(|i| [c[i][0], c[i][D - 1]]))
        .collect();
    let mut acc = 0.0;
    let mut out = vec![[0.0; D]; N];
    let mut scratch = Vec::new();
    let pairs = || ranges.iter().copied();
    for _ in 0..passes {
        match form {
            "textbook" => arrays.iter().zip(pairs()).for_each(|(c, (a, b))| {
                acc += textbook(black_box(c), a, b).iter().flatten().sum::<f64>()
            }),
            "curve" => curves.iter().zip(pairs()).for_each(|(c, (a, b))| {
                acc += black_box(c)
                    .subsegment(a..b)
                    .coordinates()
                    .iter()
                    .sum::<f64>()
            }),
            "bezier" => beziers.iter().zip(pairs()).for_each(|(c, (a, b))| {
                acc += black_box(c)
                    .subsegment(a..b)
                    .points()
                    .iter()
                    .flatten()
                    .sum::<f64>()
            }),
            "into" => beziers.iter().zip(pairs()).for_each(|(c, (a, b))| {
                black_box(c)
                    .subsegment_into(&a, &b, &mut out, &mut scratch)
                    .unwrap();
                acc += out.iter().flatten().sum::<f64>()
            }),
            _ => acc += peer(form, &planar, &ranges),
        }
    }
    acc
}

/// `run::<degree + 1, D>` for every listed degree.
macro_rules! by_degree {
    ($form:expr, $passes:expr, $degree:expr, $dim:literal; $($n:literal)*) => {
        match $degree {
            $($n => run::<{ $n + 1 }, $dim>($form, $passes),)*
            d => panic!("degree {d} in {}-D", $dim),
        }
    };
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (form, degree, passes) = (
        &args[1],
        args[2].parse::<usize>().unwrap(),
        args[3].parse::<usize>().unwrap(),
    );
    let acc = match args.get(4).map_or("3", String::as_str) {
        "2" => by_degree!(form, passes, degree, 2; 1 2 3 4 5 6 7 8),
        "3" => by_degree!(form, passes, degree, 3;
            1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32
            33 34 35 36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56 57 58 59 60 61
            62 63 64),
        d => panic!("dimension {d}"),
    };
    println!("{acc}");
}
