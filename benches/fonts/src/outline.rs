//! Glyph outlines read from a TrueType font by ttf-parser, in one neutral form that both
//! libraries are fed from: contours of curves, each curve its control points as doubles (2 for
//! a line, 3 for a quadratic, 4 for a cubic), every contour closed exactly (its last curve ends
//! where its first begins).
//!
//! Composite glyphs come decomposed (ttf-parser applies the components' offsets and
//! matrices). As a font pen does, a zero-length line (a contour whose last point repeats its
//! first, say) is dropped, and so is a contour left without curves (the single-point contours
//! that mark anchors).

use std::fmt::Write as _;

/// The control points of one curve: 2 (line), 3 (quadratic) or 4 (cubic).
pub type Curve = Vec<[f64; 2]>;

/// Contours of curves, each closed.
pub type Outline = Vec<Vec<Curve>>;

/// One glyph with an outline.
pub struct Glyph {
    pub id: u16,
    /// The post table's name, else `gid<N>`.
    pub name: String,
    pub outline: Outline,
}

/// A font's glyphs with outlines, and what laying out text needs.
pub struct Font {
    /// The file name (without its directory).
    pub name: String,
    pub units_per_em: u16,
    pub glyphs: Vec<Glyph>,
    data: Vec<u8>,
}

/// Collects ttf-parser's drawing calls into an [`Outline`].
#[derive(Default)]
struct Collect {
    contours: Outline,
    current: Vec<Curve>,
    at: [f64; 2],
    start: [f64; 2],
}

impl Collect {
    fn push(&mut self, curve: Curve) {
        if curve.iter().all(|p| *p == curve[0]) {
            return;
        }
        self.at = *curve.last().expect("two points at least");
        self.current.push(curve);
    }
}

impl ttf_parser::OutlineBuilder for Collect {
    fn move_to(&mut self, x: f32, y: f32) {
        self.at = [x.into(), y.into()];
        self.start = self.at;
        self.current.clear();
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.push(vec![self.at, [x.into(), y.into()]]);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        self.push(vec![self.at, [x1.into(), y1.into()], [x.into(), y.into()]]);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        self.push(vec![
            self.at,
            [x1.into(), y1.into()],
            [x2.into(), y2.into()],
            [x.into(), y.into()],
        ]);
    }

    fn close(&mut self) {
        if self.current.is_empty() {
            return;
        }
        if self.at != self.start {
            // ttf-parser closes TrueType contours itself; CFF ones may end elsewhere.
            let (at, start) = (self.at, self.start);
            self.push(vec![at, start]);
        }
        self.contours.push(std::mem::take(&mut self.current));
    }
}

impl Font {
    /// Reads the font at `path`: every glyph with a non-empty outline, or only those named in
    /// `only` (so that a profile of a few glyphs is not a profile of reading the font).
    pub fn load(path: &std::path::Path, only: Option<&[String]>) -> Result<Font, String> {
        let data = std::fs::read(path).map_err(|e| {
            format!(
                "cannot read the font {}: {e} (pass font paths as arguments; the default \
                 faces come with Debian's fonts-dejavu-core)",
                path.display()
            )
        })?;
        let face = ttf_parser::Face::parse(&data, 0)
            .map_err(|e| format!("{} is not a font ttf-parser reads: {e}", path.display()))?;
        // A name is found by a walk of the post table: by name for a few glyphs.
        let ids: Vec<u16> = match only {
            Some(names) => names
                .iter()
                .filter_map(|n| face.glyph_index_by_name(n))
                .map(|g| g.0)
                .collect(),
            None => (0..face.number_of_glyphs()).collect(),
        };
        let glyphs = ids
            .into_iter()
            .filter_map(|id| {
                let name = face
                    .glyph_name(ttf_parser::GlyphId(id))
                    .map_or_else(|| format!("gid{id}"), str::to_owned);
                let outline = outline_of(&face, ttf_parser::GlyphId(id))?;
                Some(Glyph { id, name, outline })
            })
            .collect();
        let units_per_em = face.units_per_em();
        let name = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into(),
        );
        Ok(Font {
            name,
            units_per_em,
            glyphs,
            data,
        })
    }

    fn face(&self) -> ttf_parser::Face<'_> {
        ttf_parser::Face::parse(&self.data, 0).expect("parsed when loaded")
    }

    /// The outline of `word` laid out from x = 0 with each glyph's horizontal advance (hmtx)
    /// times `factor`, the pen rounded to whole font units so that coordinates stay integers;
    /// the characters the font lacks are named in the error.
    pub fn word(&self, word: &str, factor: f64) -> Result<Outline, String> {
        let face = self.face();
        let mut outline = Outline::new();
        let mut pen = 0.0f64;
        let mut missing = String::new();
        for c in word.chars() {
            let Some(id) = face.glyph_index(c) else {
                missing.push(c);
                continue;
            };
            if let Some(glyph) = outline_of(&face, id) {
                outline.extend(translated(&glyph, pen));
            }
            let advance = f64::from(face.glyph_hor_advance(id).unwrap_or(0));
            pen += (advance * factor).round();
        }
        if !missing.is_empty() {
            return Err(format!("{} has no glyph for {missing:?}", self.name));
        }
        if outline.is_empty() {
            return Err(format!("{word:?} has no outline in {}", self.name));
        }
        Ok(outline)
    }
}

fn outline_of(face: &ttf_parser::Face<'_>, id: ttf_parser::GlyphId) -> Option<Outline> {
    let mut collect = Collect::default();
    face.outline_glyph(id, &mut collect)?;
    (!collect.contours.is_empty()).then_some(collect.contours)
}

/// `outline` moved by `dx` along x.
pub fn translated(outline: &Outline, dx: f64) -> Outline {
    outline
        .iter()
        .map(|contour| {
            contour
                .iter()
                .map(|curve| curve.iter().map(|p| [p[0] + dx, p[1]]).collect())
                .collect()
        })
        .collect()
}

/// The number of curves of `outline`.
pub fn curve_count(outline: &Outline) -> usize {
    outline.iter().map(Vec::len).sum()
}

/// The area of the smallest axis-parallel box holding every control point, and its larger
/// side (0 for an empty outline).
pub fn box_size(outline: &Outline) -> (f64, f64) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in outline.iter().flatten().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if lo[0] > hi[0] {
        return (0.0, 0.0);
    }
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    (w * h, w.max(h))
}

/// `outline` as the JSON of `tests/data/glyphs/` (see its README): the contours, each a list of
/// curves, each curve its control points `[x, y]`.
pub fn to_json(font: &str, glyph: &Glyph) -> String {
    let number = |x: f64| {
        if x.fract() == 0.0 {
            format!("{x:.0}")
        } else {
            format!("{x}")
        }
    };
    let mut out = String::new();
    writeln!(out, "{{").unwrap();
    writeln!(out, "  \"font\": \"{font}\",").unwrap();
    writeln!(out, "  \"glyph\": \"{}\",", glyph.name).unwrap();
    writeln!(out, "  \"gid\": {},", glyph.id).unwrap();
    writeln!(out, "  \"fill\": \"nonzero\",").unwrap();
    writeln!(out, "  \"contours\": [").unwrap();
    for (c, contour) in glyph.outline.iter().enumerate() {
        writeln!(out, "    [").unwrap();
        for (k, curve) in contour.iter().enumerate() {
            let points: Vec<String> = curve
                .iter()
                .map(|p| format!("[{}, {}]", number(p[0]), number(p[1])))
                .collect();
            let comma = if k + 1 < contour.len() { "," } else { "" };
            writeln!(out, "      [{}]{comma}", points.join(", ")).unwrap();
        }
        let comma = if c + 1 < glyph.outline.len() { "," } else { "" };
        writeln!(out, "    ]{comma}").unwrap();
    }
    writeln!(out, "  ]").unwrap();
    write!(out, "}}").unwrap();
    out.push('\n');
    out
}
