//! `blossom verify`: re-derives every table and worked example of the seed papers exactly and
//! reports, per printed value, whether it is reproduced, and if not, what holds instead.
//!
//! Each submodule contributes the sections of one part of the papers.

pub mod formula_versions;
#[cfg(feature = "carried-grid")]
pub mod macro_proofs;
pub mod paper_data;
pub mod proof_summary;
pub mod report;
pub mod seeds_002_004;
pub mod subdivision;

pub use report::{Entry, Report, Section, Status};

/// Builds the whole report.
pub fn build_report() -> Report {
    let mut report = Report::default();
    report.sections.extend(subdivision::sections());
    report.sections.push(proof_summary::section());
    #[cfg(feature = "carried-grid")]
    report.sections.push(macro_proofs::section());
    report.sections.extend(seeds_002_004::sections());
    report
}

/// Runs the whole report; returns the text (or JSON when `json`) and whether every printed
/// value was reproduced or explained.
pub fn run_report(json: bool) -> (String, bool) {
    let report = build_report();
    let text = if json {
        serde_json::to_string_pretty(&report.to_json()).expect("JSON values serialise") + "\n"
    } else {
        report.to_text()
    };
    (text, report.all_explained())
}
