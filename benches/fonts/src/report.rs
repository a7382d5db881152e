//! Timings and failures of one task, and the tables printed and written.

use std::fmt::Write as _;

/// One timed item (a glyph or a word) of one task on one font.
pub struct Item {
    pub font: String,
    pub name: String,
    pub curves: usize,
    /// Seconds.
    pub blossom: f64,
    pub linesweeper: Option<f64>,
}

/// Everything one task gathered, over one or more fonts.
#[derive(Default)]
pub struct TaskStats {
    pub items: Vec<Item>,
    /// (font, item, message) of every `Err` or panic of blossom.
    pub errors: Vec<(String, String, String)>,
    /// (font, item, message) of every blossom answer failing a check.
    pub malformed: Vec<(String, String, String)>,
    /// (font, item, message) of every `Err` of linesweeper.
    pub linesweeper_errors: Vec<(String, String, String)>,
    /// (font, item, message): linesweeper's area off blossom's enclosure by more than 1e-6 of
    /// the input's box.
    pub area_off: Vec<(String, String, String)>,
    /// (font, item) of the answers that differ from their input (`simplify` tasks).
    pub changed: Vec<(String, String)>,
    /// Whether the answers were checked (not under `--blossom-only` or `--no-check`).
    pub checked: bool,
}

impl TaskStats {
    pub fn absorb(&mut self, other: TaskStats) {
        self.items.extend(other.items);
        self.errors.extend(other.errors);
        self.malformed.extend(other.malformed);
        self.linesweeper_errors.extend(other.linesweeper_errors);
        self.area_off.extend(other.area_off);
        self.changed.extend(other.changed);
        self.checked = other.checked;
    }
}

/// `x` seconds as us, ms or s.
pub fn show(x: f64) -> String {
    if x < 1e-3 {
        format!("{:.1} us", x * 1e6)
    } else if x < 1.0 {
        format!("{:.2} ms", x * 1e3)
    } else {
        format!("{x:.2} s")
    }
}

/// The value at quantile `q` of sorted `xs` (nearest rank).
fn quantile(xs: &[f64], q: f64) -> f64 {
    let k = ((q * xs.len() as f64).ceil() as usize).clamp(1, xs.len());
    xs[k - 1]
}

struct Summary {
    median: f64,
    total: f64,
    p99: f64,
    max: f64,
}

fn summary(mut xs: Vec<f64>) -> Option<Summary> {
    if xs.is_empty() {
        return None;
    }
    xs.sort_by(f64::total_cmp);
    Some(Summary {
        median: quantile(&xs, 0.5),
        total: xs.iter().sum(),
        p99: quantile(&xs, 0.99),
        max: xs[xs.len() - 1],
    })
}

/// The header of the table.
pub fn header() -> String {
    "| task | items | linesweeper 0.5 median / total | blossom median / total | blossom p99 / max | \
     blossom / linesweeper (median, total) | blossom errors | malformed | linesweeper errors | \
     linesweeper area off |\n|---|---|---|---|---|---|---|---|---|---|\n"
        .to_owned()
}

/// One row of the table.
pub fn row(task: &str, s: &TaskStats) -> String {
    let b = summary(s.items.iter().map(|i| i.blossom).collect());
    let l = summary(s.items.iter().filter_map(|i| i.linesweeper).collect());
    let (bm, bt) = b.as_ref().map_or(("-".into(), "-".into()), |b| {
        (show(b.median), show(b.total))
    });
    let tail = b
        .as_ref()
        .map_or("-".into(), |b| format!("{} / {}", show(b.p99), show(b.max)));
    let (lm, ratio) = match (&l, &b) {
        (Some(l), Some(b)) => (
            format!("{} / {}", show(l.median), show(l.total)),
            format!("{:.2}x, {:.2}x", b.median / l.median, b.total / l.total),
        ),
        _ => ("-".into(), "-".into()),
    };
    let count = |list: &Vec<(String, String, String)>, known: bool| {
        if known {
            list.len().to_string()
        } else {
            "-".into()
        }
    };
    format!(
        "| {task} | {} | {lm} | {bm} / {bt} | {tail} | {ratio} | {} | {} | {} | {} |\n",
        s.items.len(),
        s.errors.len(),
        count(&s.malformed, s.checked),
        count(&s.linesweeper_errors, l.is_some()),
        count(&s.area_off, s.checked && l.is_some()),
    )
}

/// The failures of a task, one per line (at most `limit` of each kind).
pub fn failures(task: &str, s: &TaskStats, limit: usize) -> String {
    let mut out = String::new();
    for (what, list) in [
        ("blossom error", &s.errors),
        ("malformed blossom answer", &s.malformed),
        ("linesweeper error", &s.linesweeper_errors),
        ("linesweeper area off", &s.area_off),
    ] {
        for (font, item, message) in list.iter().take(limit) {
            writeln!(out, "{task}: {what}: {font} {item}: {message}").unwrap();
        }
        if list.len() > limit {
            writeln!(out, "{task}: {what}: ... and {} more", list.len() - limit).unwrap();
        }
    }
    out
}

/// The `n` slowest items of blossom over `tasks`, slowest first.
pub fn slowest(tasks: &[(&str, &TaskStats)], n: usize) -> String {
    let mut all: Vec<(&str, &Item)> = tasks
        .iter()
        .flat_map(|(t, s)| s.items.iter().map(move |i| (*t, i)))
        .collect();
    all.sort_by(|a, b| b.1.blossom.total_cmp(&a.1.blossom));
    let mut out = String::new();
    writeln!(
        out,
        "| blossom | linesweeper | task | font | item | curves |\n|---|---|---|---|---|---|"
    )
    .unwrap();
    for (task, i) in all.iter().take(n) {
        let l = i.linesweeper.map_or("-".into(), show);
        writeln!(
            out,
            "| {} | {l} | {task} | {} | {} | {} |",
            show(i.blossom),
            i.font,
            i.name,
            i.curves
        )
        .unwrap();
    }
    out
}

/// Every item's times as CSV.
pub fn csv(tasks: &[(&str, &TaskStats)]) -> String {
    let mut out = String::from("task,font,item,curves,blossom_ns,linesweeper_ns\n");
    for (task, s) in tasks {
        for i in &s.items {
            let l = i
                .linesweeper
                .map_or(String::new(), |x| format!("{:.0}", x * 1e9));
            let name = i.name.replace(',', ";");
            writeln!(
                out,
                "{task},{},{name},{},{:.0},{l}",
                i.font,
                i.curves,
                i.blossom * 1e9
            )
            .unwrap();
        }
    }
    out
}
