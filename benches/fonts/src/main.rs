//! Certified booleans on real font outlines, blossom against linesweeper 0.5, in one process
//! (issue 45, part 8). For every glyph with an outline of each font, nonzero fill:
//!
//! * `remove`: overlap removal of the glyph (blossom `simplify`; linesweeper `binary_op` of
//!   the glyph with the empty path, `Union`);
//! * `union`: the glyph united with `--copies` (3) copies of itself moved by `--shift` (20)
//!   units along x, 2x, 3x: `boolean(glyph, copies, Union)` where the copies are one region
//!   (nonzero), the same two paths to linesweeper's `binary_op`;
//! * `text`: a word laid out with the font's advances times `--advance` (0.8, so that
//!   neighbouring letters overlap), the whole word's outline simplified as one region.
//!
//! Each side starts from the same outline (contours of control points as doubles), makes the
//! same kurbo paths of it, computes, and consumes its answer into a kurbo path (`peers.rs`);
//! that whole call is timed, and the freeing of everything it made, once per item, the two
//! libraries alternating item by item (20 items run untimed first). Outside the timing, each
//! blossom answer is checked (`check.rs`) and linesweeper's area compared with blossom's
//! certified enclosure (before blossom's answer is freed). The table goes to stdout and, with the slowest items and every
//! item's times (CSV), to `$CARGO_TARGET_DIR/fonts/` (else `benches/fonts/target/fonts/`).
//!
//! `cargo run --release -- --help` lists the options. To profile blossom alone on the glyphs
//! that cost it most: `cargo build --release`, then for instance
//! `valgrind --tool=callgrind target/release/blossom-fonts-bench --blossom-only --tasks union
//! --glyphs shade,uni2328`.

mod check;
#[path = "../../common/mod.rs"]
#[allow(dead_code)]
mod common;
mod outline;
mod peers;
mod report;

use outline::{box_size, curve_count, translated, Font, Outline};
use report::{Item, TaskStats};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::time::Instant;

const DEFAULT_FONTS: [&str; 4] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
];

/// The words of the `text` task unless `--words` or `--words-file` gives others: plain and
/// accented Latin (composite glyphs), letters that kern tight, Greek and Cyrillic.
const DEFAULT_WORDS: [&str; 40] = [
    "Hamburgefonstiv",
    "typography",
    "Wavy",
    "AVATAR",
    "Typewriter",
    "office",
    "affluent",
    "illumination",
    "minimum",
    "quixotic",
    "jackdaws",
    "sphinx",
    "Blossom",
    "certified",
    "boolean",
    "overlap",
    "LOREM",
    "ipsum",
    "WWW",
    "mmm",
    "Bézier",
    "façade",
    "naïve",
    "Ærøskøbing",
    "Łódź",
    "Straße",
    "Ångström",
    "Übermäßig",
    "crème",
    "brûlée",
    "Ðakovo",
    "Škoda",
    "Çağrı",
    "Ŋuŋ",
    "Ohơn",
    "Øresund",
    "ĦĦĦ",
    "Κύκλος",
    "Шрифт",
    "42%@&",
];

const USAGE: &str = "\
blossom against linesweeper 0.5 on every glyph of TrueType fonts (issue 45)

USAGE: cargo run --release -- [OPTIONS] [FONT.ttf ...]

With no font, the four DejaVu faces of Debian's fonts-dejavu-core:
  DejaVuSans.ttf DejaVuSerif.ttf DejaVuSansMono.ttf DejaVuSans-Bold.ttf
  (in /usr/share/fonts/truetype/dejavu/).

OPTIONS:
  --tasks LIST       comma-separated among remove, union, text (default: all three)
  --glyphs LIST      only the glyphs of these names (remove and union)
  --shift N          union: the copies' step along x in font units (default 20)
  --copies N         union: the copies beside the glyph (default 3)
  --advance F        text: each advance times F, the pen rounded to units (default 0.8)
  --words LIST       text: comma-separated words instead of the built-in 40
  --words-file PATH  text: one word per line instead of the built-in 40
  --slowest [N]      print blossom's N slowest items (default 20) with their times
  --changed          list the glyphs whose overlap removal changed the outline
  --blossom-only     blossom alone: no linesweeper, no checks (for profiling)
  --no-check         skip the checks of blossom's answers
  --dump DIR         write the outlines of --glyphs of the first font as JSON into DIR
                     (the form of tests/data/glyphs/) and stop
  -h, --help         this text
";

#[derive(Clone, Copy, PartialEq, Eq)]
enum Task {
    Remove,
    Union,
    Text,
}

impl Task {
    fn name(self) -> &'static str {
        match self {
            Task::Remove => "remove overlaps of one glyph",
            Task::Union => "union of a glyph and its shifted copies",
            Task::Text => "a word set with overlapping letters",
        }
    }

    fn short(self) -> &'static str {
        match self {
            Task::Remove => "remove",
            Task::Union => "union",
            Task::Text => "text",
        }
    }
}

struct Options {
    fonts: Vec<PathBuf>,
    tasks: Vec<Task>,
    glyphs: Option<Vec<String>>,
    shift: f64,
    copies: usize,
    advance: f64,
    words: Vec<String>,
    slowest: usize,
    changed: bool,
    linesweeper: bool,
    check: bool,
    dump: Option<PathBuf>,
}

fn list(s: &str) -> Vec<String> {
    s.split(',')
        .map(str::trim)
        .filter(|w| !w.is_empty())
        .map(str::to_owned)
        .collect()
}

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        fonts: Vec::new(),
        tasks: vec![Task::Remove, Task::Union, Task::Text],
        glyphs: None,
        shift: 20.0,
        copies: 3,
        advance: 0.8,
        words: DEFAULT_WORDS.iter().map(|w| (*w).to_owned()).collect(),
        slowest: 0,
        changed: false,
        linesweeper: true,
        check: true,
        dump: None,
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut k = 0;
    let value = |k: &mut usize, name: &str| -> Result<String, String> {
        *k += 1;
        args.get(*k)
            .cloned()
            .ok_or_else(|| format!("{name} needs a value (see --help)"))
    };
    let number = |s: String, name: &str| -> Result<f64, String> {
        s.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("{name}: expected a number, found {s:?}"))
    };
    while k < args.len() {
        let a = args[k].as_str();
        match a {
            "-h" | "--help" => {
                print!("{USAGE}");
                std::process::exit(0);
            }
            "--tasks" => {
                o.tasks = list(&value(&mut k, a)?)
                    .iter()
                    .map(|t| match t.as_str() {
                        "remove" => Ok(Task::Remove),
                        "union" => Ok(Task::Union),
                        "text" => Ok(Task::Text),
                        _ => Err(format!("--tasks: unknown task {t:?} (remove, union, text)")),
                    })
                    .collect::<Result<_, _>>()?;
            }
            "--glyphs" => o.glyphs = Some(list(&value(&mut k, a)?)),
            "--shift" => o.shift = number(value(&mut k, a)?, a)?,
            "--copies" => {
                let v = value(&mut k, a)?;
                o.copies = v.parse().ok().filter(|&n| n > 0).ok_or_else(|| {
                    format!("--copies: expected a count of 1 or more, found {v:?}")
                })?;
            }
            "--advance" => o.advance = number(value(&mut k, a)?, a)?,
            "--words" => o.words = list(&value(&mut k, a)?),
            "--words-file" => {
                let path = value(&mut k, a)?;
                let text = std::fs::read_to_string(&path)
                    .map_err(|e| format!("--words-file: cannot read {path}: {e}"))?;
                o.words = text
                    .lines()
                    .map(str::trim)
                    .filter(|w| !w.is_empty())
                    .map(str::to_owned)
                    .collect();
            }
            "--slowest" => {
                o.slowest = 20;
                if let Some(n) = args.get(k + 1).and_then(|s| s.parse().ok()) {
                    o.slowest = n;
                    k += 1;
                }
            }
            "--changed" => o.changed = true,
            "--blossom-only" => {
                o.linesweeper = false;
                o.check = false;
            }
            "--no-check" => o.check = false,
            "--dump" => o.dump = Some(value(&mut k, a)?.into()),
            _ if a.starts_with('-') => return Err(format!("unknown option {a} (see --help)")),
            _ => o.fonts.push(a.into()),
        }
        k += 1;
    }
    if o.fonts.is_empty() {
        o.fonts = DEFAULT_FONTS.iter().map(PathBuf::from).collect();
    }
    if o.words.is_empty() && o.tasks.contains(&Task::Text) {
        return Err("the text task has no word".into());
    }
    Ok(o)
}

/// One input of a task: one outline (simplified) or two (united).
struct Case {
    name: String,
    a: Outline,
    b: Option<Outline>,
}

fn cases(font: &Font, task: Task, o: &Options) -> Vec<Case> {
    let wanted = |name: &str| {
        o.glyphs
            .as_ref()
            .is_none_or(|g| g.iter().any(|n| n == name))
    };
    let copies = |g: &outline::Glyph| -> Outline {
        (1..=o.copies)
            .flat_map(|k| translated(&g.outline, o.shift * k as f64))
            .collect()
    };
    match task {
        Task::Remove | Task::Union => {
            if let Some(names) = &o.glyphs {
                for n in names
                    .iter()
                    .filter(|n| !font.glyphs.iter().any(|g| &g.name == *n))
                {
                    eprintln!("{}: no outlined glyph {n:?}", font.name);
                }
            }
            font.glyphs
                .iter()
                .filter(|g| wanted(&g.name))
                .map(|g| Case {
                    name: g.name.clone(),
                    a: g.outline.clone(),
                    b: (task == Task::Union).then(|| copies(g)),
                })
                .collect()
        }
        Task::Text => o
            .words
            .iter()
            .filter_map(|w| match font.word(w, o.advance) {
                Ok(a) => Some(Case {
                    name: w.clone(),
                    a,
                    b: None,
                }),
                Err(m) => {
                    eprintln!("text: skipping {w:?}: {m}");
                    None
                }
            })
            .collect(),
    }
}

fn panic_message(p: Box<dyn std::any::Any + Send>) -> String {
    p.downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic".into())
}

/// Times both libraries on every case of `task` on `font`, then checks the answers.
fn run_task(font: &Font, task: Task, o: &Options) -> TaskStats {
    let cases = cases(font, task, o);
    let mut s = TaskStats {
        checked: o.check,
        ..TaskStats::default()
    };
    // A few untimed calls first, so that the first timed item does not pay for cold caches.
    for c in cases.iter().take(20) {
        let _ = catch_unwind(AssertUnwindSafe(|| peers::blossom(&c.a, c.b.as_ref())));
        if o.linesweeper {
            let _ = peers::linesweeper(&c.a, c.b.as_ref());
        }
    }
    let note = |list: &mut Vec<(String, String, String)>, c: &Case, m: String| {
        list.push((font.name.clone(), c.name.clone(), m));
    };
    for c in &cases {
        let ls = o.linesweeper.then(|| {
            let start = Instant::now();
            let answer = peers::linesweeper(&c.a, c.b.as_ref());
            (start.elapsed().as_secs_f64(), answer)
        });
        let start = Instant::now();
        let answer = catch_unwind(AssertUnwindSafe(|| peers::blossom(&c.a, c.b.as_ref())));
        let mut time = start.elapsed().as_secs_f64();
        let curves = curve_count(&c.a) + c.b.as_ref().map_or(0, curve_count);
        let mut all = c.a.clone();
        all.extend(c.b.iter().flatten().cloned());
        let (box_area, extent) = box_size(&all);
        if let Some((_, Err(e))) = &ls {
            note(&mut s.linesweeper_errors, c, e.to_string());
        }
        let answer = match answer {
            Ok(Ok(a)) => Some(a),
            Ok(Err(e)) => {
                note(&mut s.errors, c, e.to_string());
                None
            }
            Err(p) => {
                note(&mut s.errors, c, format!("panic: {}", panic_message(p)));
                None
            }
        };
        if let Some(answer) = &answer {
            if o.check {
                let curves = [
                    peers::curves_of(&c.a),
                    c.b.as_ref().map_or_else(Vec::new, peers::curves_of),
                ];
                if let Err(m) = check::well_formed(answer, &curves, box_area, extent) {
                    note(&mut s.malformed, c, m);
                }
                if let Some((_, Ok(l))) = &ls {
                    let [lo, hi] = answer.result.area;
                    let off = (lo - l.area).max(l.area - hi).max(0.0);
                    if off > 1e-6 * box_area {
                        let m = format!(
                            "area {} against [{lo}, {hi}] (off by {:.2e} of the box)",
                            l.area,
                            off / box_area
                        );
                        note(&mut s.area_off, c, m);
                    }
                }
            }
            if task == Task::Remove && !check::unchanged(answer, curves) {
                s.changed.push((font.name.clone(), c.name.clone()));
            }
        }
        // The answer (and the regions it holds) is freed here, after the checks, and timed
        // with the call: linesweeper's is freed inside its timed call.
        let start = Instant::now();
        drop(answer);
        time += start.elapsed().as_secs_f64();
        s.items.push(Item {
            font: font.name.clone(),
            name: c.name.clone(),
            curves,
            blossom: time,
            linesweeper: ls.as_ref().map(|l| l.0),
        });
    }
    s
}

fn dump(font: &Font, o: &Options, dir: &std::path::Path) -> Result<(), String> {
    let names = o
        .glyphs
        .as_ref()
        .ok_or("--dump writes the glyphs that --glyphs names")?;
    std::fs::create_dir_all(dir).map_err(|e| format!("--dump: {}: {e}", dir.display()))?;
    for name in names {
        let g = font
            .glyphs
            .iter()
            .find(|g| &g.name == name)
            .ok_or_else(|| format!("{} has no outlined glyph {name:?}", font.name))?;
        let path = dir.join(format!("{name}.json"));
        std::fs::write(&path, outline::to_json(&font.name, g))
            .map_err(|e| format!("--dump: {}: {e}", path.display()))?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// The load averages and the CPU model, read from /proc where there is one.
fn machine() -> String {
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let load: Vec<&str> = load.split_whitespace().take(3).collect();
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|c| {
            c.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown".into());
    format!("load average {}; CPU {cpu}", load.join(" "))
}

fn main() {
    if let Err(m) = run() {
        eprintln!("error: {m}");
        std::process::exit(2);
    }
}

fn run() -> Result<(), String> {
    let o = parse_args()?;
    let before = machine();
    // Fonts are read (and a missing one reported) before anything is timed.
    let fonts: Vec<Font> = o
        .fonts
        .iter()
        .map(|p| Font::load(p, o.glyphs.as_deref()))
        .collect::<Result<_, _>>()?;
    if let Some(dir) = &o.dump {
        return dump(&fonts[0], &o, dir);
    }
    let mut out = String::new();
    let mut totals: Vec<(Task, TaskStats)> =
        o.tasks.iter().map(|t| (*t, TaskStats::default())).collect();
    for font in &fonts {
        let mut table = format!(
            "\n{} ({} outlined glyphs read, {} units per em; shift {}, {} copies, advance x{}, {} words):\n\n{}",
            font.name,
            font.glyphs.len(),
            font.units_per_em,
            o.shift,
            o.copies,
            o.advance,
            o.words.len(),
            report::header()
        );
        let mut failures = String::new();
        for (task, total) in &mut totals {
            let start = Instant::now();
            let s = run_task(font, *task, &o);
            eprintln!(
                "{}: {} done in {:.1} s",
                font.name,
                task.short(),
                start.elapsed().as_secs_f64()
            );
            table += &report::row(task.name(), &s);
            failures += &report::failures(task.short(), &s, 20);
            total.absorb(s);
        }
        print!("{table}{failures}");
        out += &table;
        out += &failures;
    }
    if fonts.len() > 1 {
        let mut table = format!("\nall {} fonts:\n\n{}", fonts.len(), report::header());
        for (task, total) in &totals {
            table += &report::row(task.name(), total);
        }
        print!("{table}");
        out += &table;
    }
    let named: Vec<(&str, &TaskStats)> = totals.iter().map(|(t, s)| (t.short(), s)).collect();
    for (task, s) in &named {
        let n = if o.slowest > 0 { o.slowest } else { 20 };
        let list = format!(
            "\nblossom's {n} slowest items, {task}:\n\n{}",
            report::slowest(&[(task, s)], n)
        );
        if o.slowest > 0 {
            print!("{list}");
        }
        out += &list;
    }
    for (task, s) in &totals {
        let mut errors: Vec<String> = s
            .errors
            .iter()
            .map(|(f, i, _)| format!("{f} {i}"))
            .collect();
        errors.dedup();
        if !errors.is_empty() {
            let line = format!(
                "\n{}: blossom errors on {}\n",
                task.short(),
                errors.join(", ")
            );
            print!("{line}");
            out += &line;
        }
    }
    if o.changed {
        for (task, s) in &totals {
            if s.changed.is_empty() {
                continue;
            }
            let names: Vec<String> = s.changed.iter().map(|(f, i)| format!("{f} {i}")).collect();
            let line = format!(
                "\n{}: {} answers differ from their input: {}\n",
                task.short(),
                names.len(),
                names.join(", ")
            );
            print!("{line}");
            out += &line;
        }
    }
    let dir = common::out_dir("fonts");
    let command: Vec<String> = std::env::args().skip(1).collect();
    let head = format!(
        "# blossom against linesweeper 0.5 on font outlines\n\narguments: {}\n\nbefore: {before}\n\nafter: {}\n",
        command.join(" "),
        machine()
    );
    std::fs::write(dir.join("summary.md"), head + &out)
        .and_then(|()| std::fs::write(dir.join("times.csv"), report::csv(&named)))
        .map_err(|e| format!("cannot write into {}: {e}", dir.display()))?;
    eprintln!(
        "wrote {} and {}",
        dir.join("summary.md").display(),
        dir.join("times.csv").display()
    );
    Ok(())
}
