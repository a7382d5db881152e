//! The subdivision paper's tables re-derived exactly, and the `verify` report, snapshotted in
//! the top-level `snapshots/` directory.

use blossom::{
    restrict_power_curve, restrict_power_surface, restrict_power_surface_to_triangle, Method, Poly,
    Rational, Ring,
};
use blossom_cli::verify::subdivision::{example_1_surface, format_point};
use blossom_cli::verify::{build_report, Status};
use std::fmt::Write;
use std::str::FromStr;

macro_rules! snapshot {
    ($name:expr, $value:expr) => {
        insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
            insta::assert_snapshot!($name, $value);
        });
    };
}

fn q(text: &str) -> Rational {
    Rational::from_str(text).unwrap()
}

#[test]
fn report_explains_everything_and_finds_the_table_2_convention() {
    let report = build_report();
    assert!(report.all_explained(), "{}", report.to_text(true));
    let s3 = report
        .sections
        .iter()
        .find(|s| s.title == "Table 2, S_3")
        .unwrap();
    assert_eq!(s3.status, Status::Explained);
    assert!(s3
        .findings
        .iter()
        .any(|f| f.contains("q_kl = b(c^k, a^l, b^(5-k-l)): 21/21")));
    for title in ["Table 1, S_1", "Table 1, S_2"] {
        let s = report.sections.iter().find(|s| s.title == title).unwrap();
        assert_eq!(s.status, Status::Reproduced, "{title}");
        assert_eq!(s.entries.len(), 12);
    }
    // Wrong versions of (15), (16), (21) come with a counterexample.
    for title in [
        "Formula (15) as printed in 000",
        "Formula (16) as printed in 001",
        "Formula (21) as printed (000 and 001)",
    ] {
        let s = report.sections.iter().find(|s| s.title == title).unwrap();
        assert_eq!(s.status, Status::Explained, "{title}");
        assert!(
            s.findings.iter().any(|f| f.contains("counterexample")),
            "{title}"
        );
    }
    snapshot!("verify_report", report.to_text(true));
    // What `blossom verify` prints by default: the verdict first, one line per section.
    let short = report.to_text(false);
    assert!(
        short.starts_with("blossom verify: every printed value"),
        "{short}"
    );
    assert!(
        short.lines().count() <= 70,
        "{} lines:\n{short}",
        short.lines().count()
    );
    assert!(short.lines().all(|l| l.chars().count() <= 100), "{short}");
    snapshot!("verify_summary", short);
}

#[test]
fn a_wrong_printed_value_is_unexplained() {
    use blossom_cli::verify::paper_data::{
        TABLE_1_RECTANGLES, TABLE_1_S2, TABLE_2_S4, TABLE_2_TRIANGLES,
    };
    use blossom_cli::verify::subdivision::{tensor_section, triangle_section};
    // One printed coordinate off by a little: no reading of the labels explains it.
    let mut s4 = TABLE_2_S4;
    s4[7].1[2] = "2420/6400";
    let section = triangle_section("perturbed S_4", &s4, &TABLE_2_TRIANGLES[1]);
    assert_eq!(section.status, Status::Unexplained);
    assert_eq!(section.entries.iter().filter(|e| !e.matches).count(), 1);
    let mut s2 = TABLE_1_S2;
    s2[0].1[0] = "29/27";
    let section = tensor_section("perturbed S_2", &s2, &TABLE_1_RECTANGLES[1]);
    assert_eq!(section.status, Status::Unexplained);
    // Unperturbed, the same calls reproduce the tables.
    let section = tensor_section("S_2", &TABLE_1_S2, &TABLE_1_RECTANGLES[1]);
    assert_eq!(section.status, Status::Reproduced);
}

fn table(title: &str, points: Vec<(String, Vec<Rational>)>) -> String {
    let mut out = format!("{title}\n");
    for (label, p) in points {
        let _ = writeln!(out, "{label} = {}", format_point(&p));
    }
    out
}

#[test]
fn computed_tables_snapshot() {
    let surface = example_1_surface();
    for (name, rect) in [
        ("table_1_s1", ["0", "1", "0", "1"]),
        ("table_1_s2", ["1/3", "2/3", "1/4", "3/4"]),
    ] {
        let rect = rect.map(q);
        let net = restrict_power_surface(&surface, &rect, Method::Bulk);
        let mut rows = Vec::new();
        for (nu, row) in net.to_nested().iter().enumerate() {
            for (mu, p) in row.iter().enumerate() {
                rows.push((format!("p_{nu}{mu}"), p.clone()));
            }
        }
        snapshot!(
            name,
            table(
                &format!("{name}: p_(nu mu) = b(b^nu a^(3-nu); d^mu c^(2-mu)) on {rect:?}"),
                rows
            )
        );
    }
    for (name, tri) in [
        ("table_2_s3", [["0", "0"], ["1", "0"], ["0", "1"]]),
        ("table_2_s4", [["0", "1/2"], ["1/2", "0"], ["1/2", "1/2"]]),
    ] {
        let tri = tri.map(|p| p.map(q));
        let patch = restrict_power_surface_to_triangle(&surface, &tri, Method::Bulk);
        let rows = patch
            .entries()
            .map(|(nu, mu, la, p)| (format!("q[a^{nu} b^{mu} c^{la}]"), p.to_vec()))
            .collect();
        snapshot!(
            name,
            table(
                &format!("{name}: eq. (12) indexing, lexicographic in (nu, mu)"),
                rows
            )
        );
    }
}

#[test]
fn symbolic_control_points_snapshot() {
    let curve = blossom_cli::proofs::symbolic_curve(3);
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let bez = restrict_power_curve(&curve, &a, &b, Method::Bulk);
    let mut out = String::from("cubic C(u) = c0 + c1 u + c2 u^2 + c3 u^3 on [a, b]\n");
    for (v, w) in bez.control_points().iter().enumerate() {
        let _ = writeln!(out, "w_{v} = {}", w[0]);
    }
    // w_1 = b(b, a, a) by eq. (3), written out by hand.
    let third = Rational::new(1.into(), 3.into());
    let hand = Poly::var("c0")
        + Poly::var("c1") * (&b + &a + &a).scale(&third)
        + Poly::var("c2") * (&b * &a + &b * &a + &a * &a).scale(&third)
        + Poly::var("c3") * &b * &a * &a;
    assert_eq!(bez.control_points()[1][0], hand);
    snapshot!("symbolic_cubic_curve", out);

    let surface = blossom_cli::proofs::symbolic_surface(1, 1);
    let rect = ["a", "b", "c", "d"].map(Poly::var);
    let net = restrict_power_surface(&surface, &rect, Method::Bulk);
    let mut out =
        String::from("S(u, v) = sum c_i_j u^i v^j, (n, m) = (1, 1), on [a, b] x [c, d]\n");
    for (nu, row) in net.to_nested().iter().enumerate() {
        for (mu, p) in row.iter().enumerate() {
            let _ = writeln!(out, "p_{nu}{mu} = {}", p[0]);
        }
    }
    snapshot!("symbolic_tensor_1_1", out);
}
