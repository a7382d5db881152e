//! Prints the accuracy table of every f64 restriction path, against the exact answer and
//! against a stable reference on the same inputs (`blossom_accuracy::sweep`):
//!
//! `cargo run --release -p blossom-accuracy --example accuracy` (add `--all` for every degree).
//!
//! Error = max |got - exact| / max |exact|, the worst of the samples of a row; "ratio" is the
//! worst path's error over the reference's (floored at 2^-52), for the paths of the engine.

use blossom_accuracy::sweep::{
    bezier_curves, bezier_tensors, bezier_triangles, markdown, power_curves, Row, BATCH, ENGINE,
    GENERATED,
};

fn print(title: &str, rows: &[Row], paths: &[&str]) {
    println!("## {title}\n");
    print!("{}", markdown(rows));
    let worst = rows
        .iter()
        .map(|r| r.worst_ratio(paths))
        .fold(0.0, f64::max);
    println!(
        "\nworst ratio to the reference ({}): {worst:.2}\n",
        paths.join(", ")
    );
}

fn main() {
    let all = std::env::args().any(|a| a == "--all");
    let curves: Vec<usize> = if all {
        (1..=64).collect()
    } else {
        vec![1, 2, 3, 4, 8, 12, 16, 24, 32, 48, 64]
    };
    let tensors: Vec<(usize, usize)> = if all {
        (0..=16)
            .map(|n| (n, n))
            .chain((0..=16).map(|n| (n, 16 - n)))
            .collect()
    } else {
        vec![
            (1, 1),
            (2, 2),
            (3, 3),
            (3, 1),
            (5, 5),
            (2, 5),
            (8, 8),
            (12, 12),
            (16, 16),
        ]
    };
    let triangles: Vec<usize> = if all {
        (1..=16).collect()
    } else {
        vec![1, 2, 3, 4, 6, 8, 12, 16]
    };
    let powers: Vec<usize> = if all {
        (1..=32).collect()
    } else {
        vec![1, 2, 3, 4, 8, 16, 24, 32]
    };
    let engine = [ENGINE, BATCH, GENERATED];
    print("Bézier curves", &bezier_curves(&curves, 4, 1), &engine);
    print(
        "Tensor-product patches",
        &bezier_tensors(&tensors, 3, 2),
        &engine,
    );
    print(
        "Triangular patches",
        &bezier_triangles(&triangles, 3, 3),
        &engine,
    );
    print(
        "Power-basis curves",
        &power_curves(&powers, 4, 4),
        &["bulk"],
    );
}
