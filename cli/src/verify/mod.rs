//! `blossom verify`: re-derives every table and worked example of the seed papers exactly and
//! reports, per printed value, whether it is reproduced, and if not, what holds instead.
//!
//! Each submodule contributes the sections of one part of the papers.

pub mod axioms;
pub mod formula_versions;
#[cfg(feature = "carried-grid")]
pub mod macro_proofs;
pub mod paper_data;
pub mod proof_summary;
pub mod rational_surfaces;
pub mod report;
pub mod seeds_002_004;
pub mod subdivision;
pub mod theorem_1;
pub mod transcriptions;

pub use report::{Entry, Report, Section, Status};

/// Builds the whole report. The symbolic proofs (the engine's, the carried grid's, the
/// axioms') are independent of each other and of the paper sections and take most of the time,
/// so they run on threads of their own; the sections keep their order.
pub fn build_report() -> Report {
    let mut report = Report::default();
    std::thread::scope(|scope| {
        let engine = scope.spawn(proof_summary::section);
        #[cfg(feature = "carried-grid")]
        let grid = scope.spawn(macro_proofs::section);
        let axioms = scope.spawn(axioms::section);
        report.sections.extend(subdivision::sections());
        let judged = transcriptions::sections(&report.sections);
        report.sections.extend(judged);
        let papers = seeds_002_004::sections();
        let surfaces = rational_surfaces::sections();
        let theorem_1 = theorem_1::section();
        report
            .sections
            .push(engine.join().expect("the engine proofs do not panic"));
        #[cfg(feature = "carried-grid")]
        report
            .sections
            .push(grid.join().expect("the grid proofs do not panic"));
        report
            .sections
            .push(axioms.join().expect("the axiom proofs do not panic"));
        report.sections.extend(papers);
        report.sections.push(theorem_1);
        report.sections.extend(surfaces);
    });
    report
}

/// Runs the whole report; returns the text (or JSON when `json`) and whether every printed
/// value was reproduced or explained.
pub fn run_report(json: bool, verbose: bool) -> (String, bool) {
    let report = build_report();
    let text = if json {
        serde_json::to_string_pretty(&report.to_json()).expect("JSON values serialise") + "\n"
    } else {
        report.to_text(verbose)
    };
    (text, report.all_explained())
}
