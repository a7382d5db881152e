//! The sections of `blossom verify` on seeds 002 and 004 (the inverse-relations paper and the
//! de Boor points), and Example 2 of seed 004 (degree reduction), with snapshots.

use crate::common::q;
use blossom_cli::verify::seeds_002_004::{self, reduction};
use blossom_cli::verify::Status;
use serde_json::json;

#[test]
fn seed_002_and_004_sections_are_all_explained() {
    let sections = seeds_002_004::sections();
    assert!(sections.len() >= 14);
    for s in &sections {
        assert_ne!(s.status, Status::Unexplained, "{}", s.title);
        assert!(!s.entries.is_empty(), "{}", s.title);
        if s.status == Status::Explained {
            assert!(!s.findings.is_empty(), "{}", s.title);
        }
    }
    let text: Vec<String> = sections
        .iter()
        .map(|s| {
            let bad: Vec<String> = s
                .entries
                .iter()
                .filter(|e| !e.matches)
                .map(|e| {
                    format!(
                        "  {}: printed {} / computed {}",
                        e.label, e.printed, e.computed
                    )
                })
                .collect();
            format!("{} [{}]\n{}", s.title, s.status.name(), bad.join("\n"))
        })
        .collect();
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("verify_seeds_002_004_summary", text.join("\n"));
    });
}

#[test]
fn example_2_of_seed_004() {
    let b = reduction::curve();
    assert_eq!(b.control_points()[5], vec![q(-575, 252), q(13, 42)]);
    let all = reduction::reductions();
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_json_snapshot!(
            "degree_example_2_reductions",
            all.iter()
                .map(|(m, r, e)| json!({
                    "method": m.name(),
                    "control_points": r.control_points().iter().map(|p| p.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>(),
                    "l2_error": e.to_string(),
                    "l2_error_approx": format!("{:.6e}", blossom::rational_to_f64(e)),
                }))
                .collect::<Vec<_>>()
        );
    });
}
