//! The sections of `blossom verify` on Theorem 1 (18), the blossom axioms, the transcription
//! differences, Ejemplo 2 of seed 002 and the rational surfaces; each with a negative control
//! that the same check refuses.

use blossom::{curve_blossom, multilinear_polar_form, Poly, Ring};
use blossom_cli::verify::axioms::{check_form, check_restriction, curve_rows, Slot};
use blossom_cli::verify::transcriptions::{judge_eleven, triangle_reduces_to_curves, ELEVEN};
use blossom_cli::verify::{rational_surfaces, seeds_002_004, theorem_1, Report, Status};

#[test]
fn theorem_1_is_an_identity_and_becomes_19() {
    assert!(theorem_1::polynomial_identity(3, 2));
    assert!(theorem_1::becomes_19(4));
    assert_eq!(theorem_1::curve_cross_check(4), (true, true));
    assert!(theorem_1::triangle_cross_check(3));
    // Negative control: (18) needs a homogeneous q. Fed the affine curve C itself at the
    // arguments t_k (sums instead of averages), it is not the blossom.
    let c = blossom_cli::proofs::symbolic_curve(2);
    let ts: Vec<Vec<Poly>> = ["t1", "t2"].iter().map(|t| vec![Poly::var(t)]).collect();
    let wrong = multilinear_polar_form(2, &ts, 1, &|x| c.eval(&x[0])).unwrap();
    let flat: Vec<Poly> = ts.iter().map(|x| x[0].clone()).collect();
    assert_ne!(wrong, curve_blossom(&c, &flat).unwrap());
}

#[test]
fn every_algorithm_satisfies_the_axioms_and_wrong_forms_do_not() {
    for row in curve_rows(3) {
        assert!(row.axioms.all(), "{} {}", row.algorithm, row.degree);
    }
    let c = blossom_cli::proofs::symbolic_curve(2);
    let diagonal = |p: &[Vec<Poly>]| c.eval(&p[0][0]);
    // Not multi-affine, not symmetric: c0 + c1 x1 + c2 x1^2.
    let lopsided = |a: &[Vec<Poly>]| c.eval(&a[0][0]);
    let found = check_form(&[2], 1, &lopsided, &diagonal);
    assert!(!found.symmetric && !found.multiaffine && found.diagonal);
    // A restriction with its two end points exchanged: each point alone looks fine, but
    // the recovered forms disagree and the diagonal fails.
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    let mut w =
        blossom::restrict_power_curve(&c, &a, &b, blossom::Method::Bulk).into_control_points();
    w.swap(0, 2);
    let slots = |v: usize| vec![Slot::new(&["a"], 2 - v), Slot::new(&["b"], v)];
    let points: Vec<(Vec<Poly>, Vec<Slot>)> = w
        .into_iter()
        .enumerate()
        .map(|(v, p)| (p, slots(v)))
        .collect();
    let found = check_restriction(&[2], 1, &points, &diagonal);
    assert!(!found.all());
    assert!(!found.multiaffine);
    let _ = Poly::one();
}

#[test]
fn transcription_differences_are_decided() {
    assert_eq!(judge_eleven(&ELEVEN[0], 3), Ok(3));
    let refuted = judge_eleven(&ELEVEN[1], 3).unwrap_err();
    assert!(refuted.contains("(n, m) = (1, 0)"), "{refuted}");
    assert!(triangle_reduces_to_curves(3));
}

#[test]
fn ejemplo_2_and_the_rational_surfaces_are_reproduced() {
    let seeds = seeds_002_004::sections();
    let ejemplo = seeds
        .iter()
        .find(|s| s.title.starts_with("Ejemplo 2: the cubic B-spline"))
        .unwrap();
    assert_eq!(ejemplo.status, Status::Reproduced);
    assert_eq!(ejemplo.entries.len(), 11);
    let surfaces = rational_surfaces::sections();
    assert_eq!(surfaces.len(), 3);
    for s in &surfaces {
        assert_eq!(s.status, Status::Reproduced, "{}", s.title);
    }
    let mut report = Report::default();
    report.sections.push(ejemplo.clone());
    report.sections.push(theorem_1::section());
    report.sections.extend(surfaces);
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/../snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("verify_new_sections", report.to_text(true));
    });
}
