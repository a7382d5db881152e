//! Reads criterion's medians under `target/criterion/<group>/<method>/<size>/new/` and prints,
//! per group and method, the medians, the log-log slope of cost against degree (least squares,
//! over all degrees and over the three largest) and the ratio to the `bulk` method of the group
//! in the same run.
//!
//! Usage: `cargo bench --bench restrict && cargo run --release --example bench_slopes [group...]`

use std::fs;
use std::path::Path;

fn median_ns(path: &Path) -> Option<f64> {
    let text = fs::read_to_string(path.join("new/estimates.json")).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    v["median"]["point_estimate"].as_f64()
}

fn slope(points: &[(f64, f64)]) -> f64 {
    let k = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / k, sy / k);
    let num: f64 = points
        .iter()
        .map(|(x, y)| (x.ln() - mx) * (y.ln() - my))
        .sum();
    let den: f64 = points.iter().map(|(x, _)| (x.ln() - mx).powi(2)).sum();
    num / den
}

fn main() {
    let root = Path::new("target/criterion");
    let mut groups: Vec<String> = std::env::args().skip(1).collect();
    if groups.is_empty() {
        groups = vec!["curve".into(), "tensor".into(), "triangle".into()];
    }
    for group in groups {
        let Ok(methods) = fs::read_dir(root.join(&group)) else {
            eprintln!("no criterion data for group {group}: run cargo bench first");
            continue;
        };
        let mut methods: Vec<String> = methods
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|m| m != "report")
            .collect();
        methods.sort();
        println!("group {group}");
        let mut table: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
        for m in methods {
            let Ok(sizes) = fs::read_dir(root.join(&group).join(&m)) else {
                continue;
            };
            let mut pts: Vec<(f64, f64)> = sizes
                .filter_map(|e| e.ok())
                .filter_map(|e| {
                    let size: f64 = e.file_name().to_string_lossy().parse().ok()?;
                    Some((size, median_ns(&e.path())?))
                })
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            if pts.len() >= 2 {
                table.push((m, pts));
            }
        }
        for (m, pts) in &table {
            let medians: Vec<String> = pts
                .iter()
                .map(|(n, t)| format!("{n}: {:.3} us", t / 1e3))
                .collect();
            // The slope over the whole range, and over the three largest degrees, where the
            // leading term of the cost dominates the constant and lower-order work.
            let tail = &pts[pts.len().saturating_sub(3)..];
            println!(
                "  {m:12} slope {:.2} (largest three: {:.2})   {}",
                slope(pts),
                slope(tail),
                medians.join(", ")
            );
        }
        if let Some((base, base_pts)) = table.iter().find(|(m, _)| m == "bulk") {
            for (m, pts) in table.iter().filter(|(m, _)| m != base) {
                let ratios: Vec<String> = pts
                    .iter()
                    .filter_map(|(n, t)| {
                        let b = base_pts.iter().find(|(bn, _)| bn == n)?;
                        Some(format!("{n}: {:.1}x", t / b.1))
                    })
                    .collect();
                println!("  {m} / {base}: {}", ratios.join(", "));
            }
        }
    }
}
