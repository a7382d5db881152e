//! Prints the measured relative error of every method in f64 against the exact answer, on
//! random inputs with coefficients in [-1, 1] and domains inside [-1, 1]:
//! `cargo run --release --example float_error`.

use blossom::{Method, PowerCurve, PowerSurface, Rational};
use blossom_accuracy::{curve_error, tensor_error, triangle_error};
use num_bigint::BigInt;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 11
    }
    /// A rational in [-1, 1] with denominator 1000.
    fn unit(&mut self) -> Rational {
        Rational::new(
            BigInt::from((self.next() % 2001) as i64 - 1000),
            BigInt::from(1000),
        )
    }
    fn point(&mut self) -> Vec<Rational> {
        (0..3).map(|_| self.unit()).collect()
    }
}

fn main() {
    let mut rng = Rng(7);
    let trials = 20;
    println!("max relative error over {trials} random inputs, f64 against exact");
    println!(
        "{:10} {:>6} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "shape", "degree", "bulk", "closed-form", "definition", "pyramid", "polarisation"
    );
    for n in [3usize, 8, 16, 24] {
        let mut worst = [0.0f64; 5];
        for _ in 0..trials {
            let c = PowerCurve::new((0..=n).map(|_| rng.point()).collect()).unwrap();
            let (a, b) = (rng.unit(), rng.unit());
            for (w, m) in worst.iter_mut().zip(Method::ALL) {
                *w = w.max(curve_error(&c, &a, &b, m));
            }
        }
        println!(
            "{:10} {:>6} {}",
            "curve",
            n,
            worst.map(|e| format!("{e:>12.2e}")).join(" ")
        );
    }
    for n in [2usize, 4, 6] {
        let mut worst = [0.0f64; 5];
        for _ in 0..trials {
            let s = PowerSurface::new(
                (0..=n)
                    .map(|_| (0..=n).map(|_| rng.point()).collect())
                    .collect(),
            )
            .unwrap();
            let rect = std::array::from_fn(|_| rng.unit());
            for (w, m) in worst.iter_mut().zip(Method::ALL) {
                *w = w.max(tensor_error(&s, &rect, m));
            }
        }
        println!(
            "{:10} {:>6} {}",
            "tensor",
            format!("({n},{n})"),
            worst.map(|e| format!("{e:>12.2e}")).join(" ")
        );
    }
    for big_n in [2usize, 6, 10] {
        let mut worst = [0.0f64; 5];
        for _ in 0..trials / 4 {
            let n = big_n / 2;
            let s = PowerSurface::new(
                (0..=n)
                    .map(|_| (0..=big_n - n).map(|_| rng.point()).collect())
                    .collect(),
            )
            .unwrap();
            let tri = std::array::from_fn(|_| [rng.unit(), rng.unit()]);
            for (w, m) in worst.iter_mut().zip(Method::ALL) {
                *w = w.max(triangle_error(&s, &tri, m));
            }
        }
        println!(
            "{:10} {:>6} {}",
            "triangle",
            big_n,
            worst.map(|e| format!("{e:>12.2e}")).join(" ")
        );
    }
}
