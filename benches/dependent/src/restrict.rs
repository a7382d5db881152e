//! Restriction to [a, b] timed from a dependent crate: for each line, random curves (control
//! points uniform in [0, 1)^D) are restricted one after another to random sub-intervals of
//! [0, 1] and every answer is consumed (its coordinates summed). The forms of a line take
//! turns pass after pass, in an order that rotates from pass to pass, so that a change of load
//! meets all of them alike; the fastest of 21 passes (the least disturbed by other processes:
//! on a shared machine the median moves with the load) is reported in nanoseconds per curve,
//! with its ratio to the faster peer (planar lines) or to the textbook split (3-D lines).
//!
//! * `textbook`: de Casteljau at b keeps [0, b], then de Casteljau at a / b keeps the right
//!   part, in place on a fixed-size array `[[f64; D]; N]` (what a user writes by hand);
//! * `BezierCurve::subsegment`, `Bezier::subsegment`: the library's returning forms;
//! * `Bezier::subsegment_into`: into a reused buffer;
//! * lyon's `split_range` and kurbo's `ParamCurve::subsegment` (planar quadratics and cubics).
//!
//! The planar lines hold 10^5 curves; the 3-D lines 10^5 at degree 3 and fewer as the degree
//! grows (10^6 / (n + 1)^2, at least 250: a pass of a millisecond or two, short enough that
//! some passes of every form run undisturbed), every degree 3..=16 and 20, 24, ..., 64.

use crate::lyon;
use blossom::{Bezier, BezierCurve};
use blossom_dependent_bench::{textbook, Rng};
use std::hint::black_box;
use std::time::Instant;

const PASSES: usize = 21;

/// One timed pass of a form: its answers consumed into one number.
type Pass<'a> = Box<dyn FnMut() -> f64 + 'a>;

/// The fastest pass of each form, in nanoseconds per item, the forms taking turns pass after
/// pass (the first form of pass p is form p mod the number of forms).
fn interleaved(items: usize, forms: &mut [&mut dyn FnMut() -> f64]) -> Vec<f64> {
    let mut times = vec![Vec::with_capacity(PASSES); forms.len()];
    for pass in 0..PASSES {
        for k in 0..forms.len() {
            let i = (k + pass) % forms.len();
            let start = Instant::now();
            black_box((forms[i])());
            times[i].push(start.elapsed().as_nanos() as f64 / items as f64);
        }
    }
    times
        .into_iter()
        .map(|t| t.into_iter().fold(f64::INFINITY, f64::min))
        .collect()
}

fn sum_points<const D: usize>(points: &[[f64; D]]) -> f64 {
    points.iter().flatten().sum()
}

/// `count` random curves of degree N - 1 in dimension D, in each form, with their intervals.
struct Cases<const N: usize, const D: usize> {
    arrays: Vec<[[f64; D]; N]>,
    curves: Vec<BezierCurve<f64>>,
    beziers: Vec<Bezier<f64, D>>,
    ranges: Vec<(f64, f64)>,
}

impl<const N: usize, const D: usize> Cases<N, D> {
    fn new(rng: &mut Rng, count: usize) -> Self {
        let arrays: Vec<[[f64; D]; N]> = (0..count)
            .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| rng.next())))
            .collect();
        let ranges = (0..count)
            .map(|_| {
                let a = 0.05 + 0.4 * rng.next();
                (a, a + 0.1 + 0.4 * rng.next())
            })
            .collect();
        let beziers: Vec<Bezier<f64, D>> = arrays
            .iter()
            .map(|c| Bezier::new(c.to_vec()).expect("a curve"))
            .collect();
        let curves = beziers.iter().map(BezierCurve::from).collect();
        let cases = Cases {
            arrays,
            curves,
            beziers,
            ranges,
        };
        // The library's forms agree with the textbook before they are timed.
        for k in 0..100.min(count) {
            let (a, b) = cases.ranges[k];
            let want = textbook(&cases.arrays[k], a, b);
            let got = cases.curves[k].subsegment(a..b);
            let fixed = cases.beziers[k].subsegment(a..b);
            for ((w, g), f) in want
                .iter()
                .flatten()
                .zip(got.coordinates())
                .zip(fixed.points().iter().flatten())
            {
                let tolerance = 1e-9 * (1.0 + w.abs());
                assert!(
                    (w - g).abs() <= tolerance && (w - f).abs() <= tolerance,
                    "degree {}",
                    N - 1
                );
            }
        }
        cases
    }

    /// The times of the textbook split and the three library forms, taking turns.
    fn time_library(&self, peers: &mut [&mut dyn FnMut() -> f64]) -> Vec<f64> {
        let mut out = vec![[0.0; D]; N];
        let mut scratch = Vec::new();
        let mut textbook_pass = || {
            let mut acc = 0.0;
            for (c, &(a, b)) in self.arrays.iter().zip(&self.ranges) {
                acc += sum_points(&textbook(c, a, b));
            }
            acc
        };
        let mut curve_pass = || {
            let mut acc = 0.0;
            for (c, &(a, b)) in self.curves.iter().zip(&self.ranges) {
                acc += c.subsegment(a..b).coordinates().iter().sum::<f64>();
            }
            acc
        };
        let mut bezier_pass = || {
            let mut acc = 0.0;
            for (c, &(a, b)) in self.beziers.iter().zip(&self.ranges) {
                acc += sum_points(c.subsegment(a..b).points());
            }
            acc
        };
        let mut into_pass = || {
            let mut acc = 0.0;
            for (c, &(a, b)) in self.beziers.iter().zip(&self.ranges) {
                c.subsegment_into(&a, &b, &mut out, &mut scratch)
                    .expect("sized");
                acc += sum_points(&out);
            }
            acc
        };
        let mut forms: Vec<&mut dyn FnMut() -> f64> = Vec::new();
        for peer in peers.iter_mut() {
            forms.push(&mut **peer);
        }
        forms.push(&mut textbook_pass);
        forms.push(&mut curve_pass);
        forms.push(&mut bezier_pass);
        forms.push(&mut into_pass);
        interleaved(self.ranges.len(), &mut forms)
    }
}

/// The planar quadratic (N = 3) or cubic (N = 4) against lyon and kurbo; returns the ratios of
/// `BezierCurve::subsegment`, `Bezier::subsegment` and `subsegment_into` to the faster peer.
fn planar_line<const N: usize>(rng: &mut Rng) -> [f64; 3] {
    use kurbo::ParamCurve;
    let cs = Cases::<N, 2>::new(rng, 100_000);
    let p = |c: &[[f64; 2]; N], i: usize| (c[i][0], c[i][1]);
    let ranges = &cs.ranges;
    let (lyon_pass, kurbo_pass): (Pass, Pass) = match N {
        3 => {
            let lyons: Vec<_> = cs
                .arrays
                .iter()
                .map(|c| lyon_geom::QuadraticBezierSegment {
                    from: p(c, 0).into(),
                    ctrl: p(c, 1).into(),
                    to: p(c, 2).into(),
                })
                .collect();
            let kurbos: Vec<_> = cs
                .arrays
                .iter()
                .map(|c| kurbo::QuadBez::new(p(c, 0), p(c, 1), p(c, 2)))
                .collect();
            (
                Box::new(move || {
                    let mut acc = 0.0;
                    for (c, &(a, b)) in lyons.iter().zip(ranges) {
                        let s = c.split_range(a..b);
                        acc += s.from.x + s.from.y + s.ctrl.x + s.ctrl.y + s.to.x + s.to.y;
                    }
                    acc
                }),
                Box::new(move || {
                    let mut acc = 0.0;
                    for (c, &(a, b)) in kurbos.iter().zip(ranges) {
                        let s = c.subsegment(a..b);
                        acc += s.p0.x + s.p0.y + s.p1.x + s.p1.y + s.p2.x + s.p2.y;
                    }
                    acc
                }),
            )
        }
        _ => {
            let lyons: Vec<_> = cs
                .arrays
                .iter()
                .map(|c| lyon::lyon_cubic(&std::array::from_fn(|i| c[i])))
                .collect();
            let kurbos: Vec<_> = cs
                .arrays
                .iter()
                .map(|c| kurbo::CubicBez::new(p(c, 0), p(c, 1), p(c, 2), p(c, 3)))
                .collect();
            (
                Box::new(move || {
                    let mut acc = 0.0;
                    for (c, &(a, b)) in lyons.iter().zip(ranges) {
                        let s = c.split_range(a..b);
                        acc += s.from.x
                            + s.from.y
                            + s.ctrl1.x
                            + s.ctrl1.y
                            + s.ctrl2.x
                            + s.ctrl2.y
                            + s.to.x
                            + s.to.y;
                    }
                    acc
                }),
                Box::new(move || {
                    let mut acc = 0.0;
                    for (c, &(a, b)) in kurbos.iter().zip(ranges) {
                        let s = c.subsegment(a..b);
                        acc +=
                            s.p0.x + s.p0.y + s.p1.x + s.p1.y + s.p2.x + s.p2.y + s.p3.x + s.p3.y;
                    }
                    acc
                }),
            )
        }
    };
    let (mut lyon_pass, mut kurbo_pass) = (lyon_pass, kurbo_pass);
    let t = cs.time_library(&mut [&mut *lyon_pass, &mut *kurbo_pass]);
    let fastest = t[0].min(t[1]);
    let r = |x: f64| x / fastest;
    println!(
        "| planar degree {} | {:.2} | {:.2} | {:.2} ({:.2}) | {:.2} (**{:.2}**) | {:.2} (**{:.2}**) | {:.2} ({:.2}) |",
        N - 1,
        t[0],
        t[1],
        t[2],
        r(t[2]),
        t[3],
        r(t[3]),
        t[4],
        r(t[4]),
        t[5],
        r(t[5]),
    );
    [r(t[3]), r(t[4]), r(t[5])]
}

/// One 3-D line at degree N - 1; returns the ratios of the three library forms to the
/// textbook split.
fn spatial_line<const N: usize>(rng: &mut Rng) -> [f64; 3] {
    let count = (1_000_000 / (N * N)).clamp(250, 100_000);
    let t = Cases::<N, 3>::new(rng, count).time_library(&mut []);
    let r = [t[1] / t[0], t[2] / t[0], t[3] / t[0]];
    println!(
        "| 3-D degree {:>2} | {:8.1} | {:8.1} ({:.2}) | {:8.1} ({:.2}) | {:8.1} ({:.2}) |",
        N - 1,
        t[0],
        t[1],
        r[0],
        t[2],
        r[1],
        t[3],
        r[2]
    );
    r
}

/// Every line, then the largest ratio of each form over the 3-D degrees.
pub fn restriction_lines() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    println!("planar, ns per curve (ratio to the faster of lyon and kurbo):");
    println!(
        "| curve | lyon | kurbo | textbook | BezierCurve::subsegment | Bezier::subsegment | Bezier::subsegment_into |"
    );
    println!("|---|---|---|---|---|---|---|");
    planar_line::<3>(&mut rng);
    planar_line::<4>(&mut rng);
    println!();
    println!("3-D, ns per curve (ratio to the textbook split on fixed arrays):");
    println!("| curve | textbook | BezierCurve::subsegment | Bezier::subsegment | Bezier::subsegment_into |");
    println!("|---|---|---|---|---|");
    let mut worst = [(0.0, 0); 3];
    macro_rules! lines {
        ($($n:literal)*) => {$(
            let r = spatial_line::<{ $n + 1 }>(&mut rng);
            for (w, x) in worst.iter_mut().zip(r) {
                if x > w.0 {
                    *w = (x, $n);
                }
            }
        )*};
    }
    lines!(3 4 5 6 7 8 9 10 11 12 13 14 15 16 20 24 28 32 36 40 44 48 52 56 60 64);
    println!(
        "largest ratio to the textbook over those degrees: BezierCurve::subsegment {:.2} (degree {}), Bezier::subsegment {:.2} (degree {}), subsegment_into {:.2} (degree {})",
        worst[0].0, worst[0].1, worst[1].0, worst[1].1, worst[2].0, worst[2].1
    );
}
