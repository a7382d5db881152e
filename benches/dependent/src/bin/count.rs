//! One form at one degree, for instruction counts under callgrind (repeatable on a loaded
//! machine, unlike wall time): `count FORM DEGREE PASSES`, FORM one of textbook, curve,
//! bezier, into; 1,000 random 3-D curves per pass. Run it with PASSES 0 and 10 and take the
//! difference over 10,000 curves.

use blossom::{Bezier, BezierCurve};
use blossom_dependent_bench::{textbook, Rng};
use std::hint::black_box;

fn run<const N: usize>(form: &str, passes: usize) -> f64 {
    let mut rng = Rng(7);
    let arrays: Vec<[[f64; 3]; N]> = (0..1000)
        .map(|_| std::array::from_fn(|_| std::array::from_fn(|_| rng.next())))
        .collect();
    let beziers: Vec<Bezier<f64, 3>> = arrays
        .iter()
        .map(|c| Bezier::new(c.to_vec()).unwrap())
        .collect();
    let curves: Vec<BezierCurve<f64>> = beziers.iter().map(BezierCurve::from).collect();
    let (a, b) = (0.2, 0.7);
    let mut acc = 0.0;
    let mut out = vec![[0.0; 3]; N];
    let mut scratch = Vec::new();
    for _ in 0..passes {
        match form {
            "textbook" => arrays
                .iter()
                .for_each(|c| acc += textbook(black_box(c), a, b).iter().flatten().sum::<f64>()),
            "curve" => curves.iter().for_each(|c| {
                acc += black_box(c)
                    .subsegment(a..b)
                    .coordinates()
                    .iter()
                    .sum::<f64>()
            }),
            "bezier" => beziers.iter().for_each(|c| {
                acc += black_box(c)
                    .subsegment(a..b)
                    .points()
                    .iter()
                    .flatten()
                    .sum::<f64>()
            }),
            "into" => beziers.iter().for_each(|c| {
                black_box(c)
                    .subsegment_into(&a, &b, &mut out, &mut scratch)
                    .unwrap();
                acc += out.iter().flatten().sum::<f64>()
            }),
            _ => panic!("form"),
        }
    }
    acc
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (form, degree, passes) = (
        &args[1],
        args[2].parse::<usize>().unwrap(),
        args[3].parse::<usize>().unwrap(),
    );
    let acc = match degree {
        3 => run::<4>(form, passes),
        5 => run::<6>(form, passes),
        8 => run::<9>(form, passes),
        12 => run::<13>(form, passes),
        16 => run::<17>(form, passes),
        24 => run::<25>(form, passes),
        32 => run::<33>(form, passes),
        48 => run::<49>(form, passes),
        64 => run::<65>(form, passes),
        _ => panic!("degree"),
    };
    println!("{acc}");
}
