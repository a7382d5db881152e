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

    /// How many sections have status `status`.
    fn count(&self, status: Status) -> usize {
        self.sections.iter().filter(|s| s.status == status).count()
    }

    /// The verdict: whether everything is reproduced or explained.
    pub fn verdict(&self) -> &'static str {
        if self.all_explained() {
            "every printed value reproduced or explained"
        } else {
            "NOT everything reproduced or explained"
        }
    }

    /// `N sections: R reproduced, E explained, U unexplained`.
    fn counts(&self) -> String {
        format!(
            "{} sections: {} reproduced, {} explained, {} unexplained",
            self.sections.len(),
            self.count(Status::Reproduced),
            self.count(Status::Explained),
            self.count(Status::Unexplained)
        )
    }

    /// The human-readable rendering: the verdict and one line per section, or with `verbose`
    /// the full report (every section's findings and entries, the summary last).
    pub fn to_text(&self, verbose: bool) -> String {
        if verbose {
            self.to_full_text()
        } else {
            self.to_short_text()
        }
    }

    /// The verdict, what the statuses mean, then one line per section: status, entries
    /// matched, the whole title and its source in the papers (named as the README names
    /// them). Consecutive sections on formulae as printed (titles `Formula ...`) share one
    /// line, the worst of their statuses. `--verbose` has every entry and finding.
    fn to_short_text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "blossom verify: {}", self.verdict());
        let _ = writeln!(
            out,
            "{}; `--verbose` shows every entry and finding",
            self.counts()
        );
        let _ = writeln!(out, "{LEGEND}");
        let _ = writeln!(
            out,
            "\n{:11}  {:>7}  section (where in the papers)",
            "status", "entries"
        );
        for row in self.rows() {
            let entries = match row.entries {
                None => String::from("-"),
                Some((matched, total)) => format!("{matched}/{total}"),
            };
            let _ = writeln!(
                out,
                "{:11}  {entries:>7}  {} ({})",
                row.status.name(),
                row.title,
                row.source
            );
        }
        let unexplained: Vec<&str> = self
            .sections
            .iter()
            .filter(|s| s.status == Status::Unexplained)
            .map(|s| s.title.as_str())
            .collect();
        if !unexplained.is_empty() {
            let _ = writeln!(out, "\nunexplained: {}", unexplained.join("; "));
        }
        out
    }

    /// The rows of the short table: one per section, except that a run of consecutive
    /// `Formula ...` sections is one row.
    fn rows(&self) -> Vec<Row> {
        let mut rows: Vec<Row> = Vec::new();
        let mut formulae: Vec<&Section> = Vec::new();
        let flush = |formulae: &mut Vec<&Section>, rows: &mut Vec<Row>| {
            match formulae.as_slice() {
                [] => {}
                [one] => rows.push(Row::of(one)),
                many => rows.push(Row::of_formulae(many)),
            }
            formulae.clear();
        };
        for s in &self.sections {
            if s.title.starts_with("Formula") {
                formulae.push(s);
            } else {
                flush(&mut formulae, &mut rows);
                rows.push(Row::of(s));
            }
        }
        flush(&mut formulae, &mut rows);
        rows
    }

    /// Today's full report: every section with its findings and entries, the summary last.
    fn to_full_text(&self) -> String {
        let mut out = String::new();
        out.push_str("blossom verify: the papers' tables and examples, re-derived exactly\n");
        let _ = writeln!(out, "{LEGEND}");
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
        let _ = writeln!(out, "\nsummary: {}", self.counts());
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

/// One row of the short table.
struct Row {
    title: String,
    source: String,
    /// Entries matched and in all, if any section of the row has entries.
    entries: Option<(usize, usize)>,
    status: Status,
}

impl Row {
    fn of(s: &Section) -> Row {
        Row::of_formulae(std::slice::from_ref(&s)).titled(&s.title, &s.source)
    }

    /// One row for the sections `group`: entries added up, the worst status.
    fn of_formulae(group: &[&Section]) -> Row {
        let with_entries: Vec<&&Section> = group.iter().filter(|s| !s.entries.is_empty()).collect();
        let entries = (!with_entries.is_empty()).then(|| {
            with_entries.iter().fold((0, 0), |(m, t), s| {
                (
                    m + s.entries.iter().filter(|e| e.matches).count(),
                    t + s.entries.len(),
                )
            })
        });
        let status = group
            .iter()
            .map(|s| s.status)
            .max_by_key(|st| match st {
                Status::Reproduced => 0,
                Status::Explained => 1,
                Status::Unexplained => 2,
            })
            .unwrap_or(Status::Reproduced);
        Row {
            title: format!("{} formulae as printed", group.len()),
            source: String::from("subdivision paper, Theorems 2, 3, proofs"),
            entries,
            status,
        }
    }

    fn titled(mut self, title: &str, source: &str) -> Row {
        self.title = title.to_string();
        self.source = source.to_string();
        self
    }
}

/// What the statuses mean, printed under the counts.
const LEGEND: &str = "reproduced: every value printed in the paper computed again and equal; \
explained: some printed values differ, and the report shows why (a misprint, a transcription \
error, a different convention), with the corrected value computed";

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(label: &str, matches: bool) -> Entry {
        Entry {
            label: label.into(),
            printed: "1".into(),
            computed: if matches { "1" } else { "2" }.into(),
            matches,
        }
    }

    fn report() -> Report {
        Report {
            sections: vec![
                Section::from_entries(
                    "Table 1, S_1",
                    "subdivision paper (transcription 000), Table 1",
                    vec![entry("p_00", true), entry("p_01", true)],
                    vec![],
                    Status::Unexplained,
                ),
                Section::from_entries(
                    "A title far longer than the column it is printed in, by a lot",
                    "inverse relations paper",
                    vec![entry("w_1", false)],
                    vec!["an index convention".into()],
                    Status::Explained,
                ),
            ],
        }
    }

    #[test]
    fn the_short_report_opens_with_its_verdict_and_lists_each_section_once() {
        let text = report().to_text(false);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "blossom verify: every printed value reproduced or explained"
        );
        assert!(lines[1].starts_with("2 sections: 1 reproduced, 1 explained, 0 unexplained"));
        assert!(lines[2].starts_with("reproduced: ") && lines[2].contains("explained: "));
        let rows: Vec<&&str> = lines
            .iter()
            .filter(|l| l.ends_with(" paper)") || l.ends_with("Table 1)"))
            .collect();
        assert_eq!(rows.len(), 2, "{text}");
        assert!(
            rows[0].starts_with("reproduced ") && rows[0].contains("2/2"),
            "{text}"
        );
        assert!(
            rows[1].starts_with("explained ") && rows[1].contains("0/1"),
            "{text}"
        );
        // Titles are printed whole, with the paper named as the README names it.
        assert!(
            rows[1].contains("A title far longer than the column it is printed in, by a lot")
                && rows[1].ends_with("(inverse relations paper)")
                && !text.contains('~'),
            "{text}"
        );
        assert!(!text.contains("MISMATCH") && !text.contains("an index convention"));
    }

    #[test]
    fn consecutive_formula_sections_share_a_row_with_the_worst_status() {
        let mut r = report();
        let formula = |title: &str, status| Section {
            title: title.into(),
            source: "subdivision paper (transcription 000)".into(),
            status,
            entries: vec![entry("x", status == Status::Reproduced)],
            findings: vec![],
        };
        r.sections.push(formula("Formula (1)", Status::Reproduced));
        r.sections.push(formula("Formula (2)", Status::Unexplained));
        r.sections.push(formula("Formula (3)", Status::Explained));
        let text = r.to_text(false);
        let row: Vec<&str> = text.lines().filter(|l| l.contains("formulae")).collect();
        assert_eq!(row.len(), 1, "{text}");
        assert!(row[0].contains("3 formulae as printed"), "{text}");
        assert!(
            row[0].contains("1/3") && row[0].starts_with("unexplained "),
            "{text}"
        );
        assert!(text.contains("unexplained: Formula (2)"), "{text}");
    }

    #[test]
    fn the_verbose_report_has_entries_and_findings() {
        let text = report().to_text(true);
        assert!(text.contains("MISMATCH") && text.contains("an index convention"));
        assert!(text
            .trim_end()
            .ends_with("1 reproduced, 1 explained, 0 unexplained"));
    }

    #[test]
    fn an_unexplained_section_changes_the_verdict_and_is_named() {
        let mut r = report();
        r.sections[1].status = Status::Unexplained;
        let text = r.to_text(false);
        assert!(text.starts_with("blossom verify: NOT everything"), "{text}");
        assert!(text.contains("\nunexplained: A title far longer"), "{text}");
    }
}
