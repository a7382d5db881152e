//! The data model of the `blossom verify` report and its text and JSON renderings.

use serde_json::{json, Value};
use std::fmt::Write;

/// How a printed value, table or formula stands against the computation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Reproduced exactly as printed.
    Reproduced,
    /// Not as printed, but the report says what holds instead and why (an index convention,
    /// a typo with its correction, a formula version shown wrong by a counterexample).
    Explained,
    /// Neither reproduced nor explained.
    Unexplained,
}

impl Status {
    /// The lowercase name used in both renderings.
    pub fn name(self) -> &'static str {
        match self {
            Status::Reproduced => "reproduced",
            Status::Explained => "explained",
            Status::Unexplained => "unexplained",
        }
    }
}

/// One printed value against its computed counterpart.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The paper's label, e.g. `p_21` or `q_05`.
    pub label: String,
    /// The value as printed (transcribed data).
    pub printed: String,
    /// The value as computed.
    pub computed: String,
    /// Whether they are identical.
    pub matches: bool,
}

/// A table, worked example or formula of a seed paper, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// A short title, e.g. `Table 1, S_2`.
    pub title: String,
    /// Where it is printed, e.g. `seed 000/001, Example 1, formula (9)`.
    pub source: String,
    /// The verdict.
    pub status: Status,
    /// Printed against computed values (may be empty for formula findings).
    pub entries: Vec<Entry>,
    /// What was found: conventions, counterexamples, corrections.
    pub findings: Vec<String>,
}

impl Section {
    /// A section whose status follows from its entries: reproduced when every entry matches,
    /// otherwise `otherwise` (explained when the findings account for the mismatches).
    pub fn from_entries(
        title: impl Into<String>,
        source: impl Into<String>,
        entries: Vec<Entry>,
        findings: Vec<String>,
        otherwise: Status,
    ) -> Self {
        let status = if entries.iter().all(|e| e.matches) {
            Status::Reproduced
        } else {
            otherwise
        };
        Section {
            title: title.into(),
            source: source.into(),
            status,
            entries,
            findings,
        }
    }
}

/// The whole report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// The sections in the order they are printed.
    pub sections: Vec<Section>,
}

impl Report {
    /// Whether every section is reproduced or explained (the exit status of `verify`).
    pub fn all_explained(&self) -> bool {
        self.sections
            .iter()
            .all(|s| s.status != Status::Unexplained)
    }

    /// The human-readable rendering.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        out.push_str("blossom verify: the seed papers' tables and examples, re-derived exactly\n");
        for s in &self.sections {
            let _ = writeln!(out, "\n== {} [{}]", s.title, s.status.name());
            let _ = writeln!(out, "   source: {}", s.source);
            for f in &s.findings {
                let _ = writeln!(out, "   - {f}");
            }
            if !s.entries.is_empty() {
                let matched = s.entries.iter().filter(|e| e.matches).count();
                let _ = writeln!(out, "   entries: {matched}/{} match", s.entries.len());
                for e in &s.entries {
                    let mark = if e.matches { "ok" } else { "MISMATCH" };
                    if e.matches {
                        let _ = writeln!(out, "   {mark:8} {:10} {}", e.label, e.printed);
                    } else {
                        let _ = writeln!(
                            out,
                            "   {mark:8} {:10} printed {}  computed {}",
                            e.label, e.printed, e.computed
                        );
                    }
                }
            }
        }
        let count = |st: Status| self.sections.iter().filter(|s| s.status == st).count();
        let _ = writeln!(
            out,
            "\nsummary: {} sections: {} reproduced, {} explained, {} unexplained",
            self.sections.len(),
            count(Status::Reproduced),
            count(Status::Explained),
            count(Status::Unexplained)
        );
        out
    }

    /// The JSON rendering.
    pub fn to_json(&self) -> Value {
        let sections: Vec<Value> = self
            .sections
            .iter()
            .map(|s| {
                json!({
                    "title": s.title,
                    "source": s.source,
                    "status": s.status.name(),
                    "findings": s.findings,
                    "entries": s.entries.iter().map(|e| json!({
                        "label": e.label,
                        "printed": e.printed,
                        "computed": e.computed,
                        "match": e.matches,
                    })).collect::<Vec<_>>(),
                })
            })
            .collect();
        json!({ "all_explained": self.all_explained(), "sections": sections })
    }
}
