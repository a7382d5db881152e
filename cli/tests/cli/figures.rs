//! `blossom figures`: every SVG rendered to pixels (resvg), checked to be a picture, and each
//! control point looked up on the page.
//!
//! The expected control points do not come from the figures' own computation: the patches'
//! nets are the values printed in Tables 1 and 2 (compared as sets, since Table 2's labels
//! follow an index convention of their own), the arcs' polygons are the printed ones of seed
//! 004, the ln t cubic's polygon is the printed expression in ln 2, ln 3, ln 5 (the figure
//! computes it by the inverse formula (22); both sides evaluate ln p by the same series of
//! `verify`), and the knot images F(t_j) of the B-spline are evaluated here by the Cox-de Boor
//! recurrence of the basis functions (the figure uses the library's de Boor algorithm). The de
//! Boor points are the figure's input itself, so for them only the page position is tested.
//! The error curve of the ln t cubic is recomputed here from the printed polygon by Bernstein
//! sums. The marks of the intersection picture are placed by the library's exact intersection
//! (resultants); here they come from closed forms of the chosen inputs (the crossing pair and
//! the loop are symmetric, so their parameters solve 20 s^3 - 30 s^2 + 12 s - 1 = 0, i.e.
//! s = 1/2 and 1/2 -+ sqrt(15)/10; the touching arcs meet at s = t = 1/2; the overlapping
//! stretches share the base cubic over [1/3, 2/3]), evaluated by Bernstein sums here.
//!
//! Each expected point must be one of the figure's dots (to 1e-12), and the pixel at its page
//! position, computed through the chart the drawing uses ([`figures::pixels`]: this checks
//! that the rendered dot is where the chart puts the value; `the_page_positions_follow_the_chart`
//! checks the chart's orientation), must have the colour of the dot drawn last over it. Text is
//! not rendered (resvg without fonts), so labels cannot cover a dot.

use crate::binary::run_binary;
use blossom::{rational_to_f64, Rational};
use blossom_cli::figures::{self, palette, Figure, Point3, Rgb, SIZE};
use blossom_cli::verify::paper_data::{Labelled, TABLE_1_S1, TABLE_1_S2, TABLE_2_S3, TABLE_2_S4};
use blossom_cli::verify::seeds_002_004::circle::{UNIT_QUADRATIC, UNIT_QUARTIC};
use blossom_cli::verify::seeds_002_004::expr::parse;
use blossom_cli::verify::seeds_002_004::logarithm::{value, POLYGON};
use blossom_cli::verify::seeds_002_004::splines::{EXAMPLE_1_POINTS, THEOREM_2_2_KNOTS};
use blossom_cli::verify::seeds_002_004::{num, point};
use resvg::{tiny_skia, usvg};

/// A figure rendered at its page size.
fn render(figure: &Figure) -> tiny_skia::Pixmap {
    let text = figures::svg(figure).expect("the figure draws");
    let tree = usvg::Tree::from_str(&text, &usvg::Options::default()).expect("valid SVG");
    let size = tree.size().to_int_size();
    assert_eq!((size.width(), size.height()), SIZE, "{}", figure.file);
    let mut pixmap = tiny_skia::Pixmap::new(SIZE.0, SIZE.1).expect("a page");
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap
}

fn colour_at(pixmap: &tiny_skia::Pixmap, (x, y): (i32, i32)) -> Option<Rgb> {
    let c = pixmap.pixel(u32::try_from(x).ok()?, u32::try_from(y).ok()?)?;
    let c = c.demultiply();
    Some(Rgb(c.red(), c.green(), c.blue()))
}

/// Whether every channel of `a` is within `tolerance` of `b`'s.
fn within(a: Rgb, b: Rgb, tolerance: i32) -> bool {
    let d = |x: u8, y: u8| (i32::from(x) - i32::from(y)).abs();
    d(a.0, b.0) <= tolerance && d(a.1, b.1) <= tolerance && d(a.2, b.2) <= tolerance
}

/// The colour of a disc's centre: `b` up to rounding of the rendering.
fn close(a: Rgb, b: Rgb) -> bool {
    within(a, b, 8)
}

fn f64_point(p: &[Rational]) -> Point3 {
    let mut out = [0.0; 3];
    for (o, x) in out.iter_mut().zip(p) {
        *o = rational_to_f64(x);
    }
    out
}

fn printed_net(table: &[Labelled]) -> Vec<Point3> {
    table
        .iter()
        .map(|(_, xyz)| f64_point(&xyz.map(num)))
        .collect()
}

/// N_{k,d}(t) on `knots` by the Cox-de Boor recurrence; the last non-empty span is closed on
/// the right so that F(t_max) is the end point.
fn basis(knots: &[f64], k: usize, d: usize, t: f64) -> f64 {
    if d == 0 {
        let (a, b) = (knots[k], knots[k + 1]);
        let last = knots[knots.len() - 1];
        let inside = (a <= t && t < b) || (t == last && a < b && b == last);
        return if inside { 1.0 } else { 0.0 };
    }
    let term = |num: f64, den: f64, n: f64| if den == 0.0 { 0.0 } else { num / den * n };
    term(
        t - knots[k],
        knots[k + d] - knots[k],
        basis(knots, k, d - 1, t),
    ) + term(
        knots[k + d + 1] - t,
        knots[k + d + 1] - knots[k + 1],
        basis(knots, k + 1, d - 1, t),
    )
}

fn knot_images() -> Vec<Point3> {
    let knots: Vec<f64> = THEOREM_2_2_KNOTS
        .split(',')
        .map(|t| t.trim().parse().expect("an integer knot"))
        .collect();
    let points: Vec<Point3> = EXAMPLE_1_POINTS
        .iter()
        .map(|p| f64_point(&point(p)))
        .collect();
    let mut distinct = knots.clone();
    distinct.dedup();
    distinct
        .iter()
        .map(|&t| {
            let mut f = [0.0; 3];
            for (k, d) in points.iter().enumerate() {
                let n = basis(&knots, k, 3, t);
                for j in 0..3 {
                    f[j] += n * d[j];
                }
            }
            f
        })
        .collect()
}

fn printed_polygon(polygon: &[&str]) -> Vec<Point3> {
    polygon.iter().map(|p| f64_point(&point(p))).collect()
}

fn ln_polygon() -> Vec<Point3> {
    POLYGON
        .iter()
        .map(|[x, y]| f64_point(&[value(&parse(x)), value(&parse(y))]))
        .collect()
}

/// sum_i b_i B_i^n(s) of integer control points moved by `offset`, by Bernstein sums.
fn bernstein(points: &[[i64; 2]], offset: [f64; 2], s: f64) -> Point3 {
    let n = points.len() - 1;
    let mut out = [0.0; 3];
    let mut binomial = 1.0;
    for (i, p) in points.iter().enumerate() {
        let w = binomial * s.powi(i as i32) * (1.0 - s).powi((n - i) as i32);
        out[0] += w * (p[0] as f64 + offset[0]);
        out[1] += w * (p[1] as f64 + offset[1]);
        binomial = binomial * (n - i) as f64 / (i + 1) as f64;
    }
    out
}

/// The parameters where the symmetric crossing pair and the loop meet themselves or each
/// other, besides 1/2: the roots of 10 s^2 - 10 s + 1.
fn outer_roots() -> [f64; 2] {
    let r = 15f64.sqrt() / 10.0;
    [0.5 - r, 0.5 + r]
}

/// The marks of the intersection picture: crossings, tangencies, self-intersections.
fn intersection_marks() -> Vec<(Rgb, Vec<Point3>)> {
    use figures::intersections::{CROSSING, LOOP, OFFSETS, TOUCHING};
    let [a, b] = outer_roots();
    let crossings = [a, 0.5, b]
        .iter()
        .map(|&s| bernstein(CROSSING[0], OFFSETS[0], s))
        .collect();
    let touching = vec![bernstein(TOUCHING[0], OFFSETS[1], 0.5)];
    let looped = vec![bernstein(LOOP, OFFSETS[3], a)];
    vec![
        (palette::DOTS, crossings),
        (palette::DOTS_4, touching),
        (palette::DOTS_3, looped),
    ]
}

/// The control points of the two regions of the region picture, in its input panel: the
/// figure's input itself, so only their page positions are tested.
fn region_control_points() -> Vec<(Rgb, Vec<Point3>)> {
    use figures::regions::{A, B, OFFSETS};
    let points = |curves: figures::regions::Loop| {
        let mut out: Vec<Point3> = Vec::new();
        for p in curves.iter().flat_map(|c| c.iter()) {
            let p = [
                (p[0] + OFFSETS[0][0]) as f64,
                (p[1] + OFFSETS[0][1]) as f64,
                0.0,
            ];
            if !out.contains(&p) {
                out.push(p);
            }
        }
        out
    };
    vec![(palette::DOTS, points(A)), (palette::DOTS_2, points(B))]
}

/// The expected dots of each figure, by file name: (dot colour, points).
fn expected(file: &str) -> Vec<(Rgb, Vec<Point3>)> {
    let (first, second, marks) = (palette::DOTS, palette::DOTS_2, palette::DOTS_3);
    match file {
        "figure1a_s1_net.svg" => vec![(first, printed_net(&TABLE_1_S1))],
        "figure1b_s1_s2.svg" => vec![
            (first, printed_net(&TABLE_1_S1)),
            (second, printed_net(&TABLE_1_S2)),
        ],
        "figure2a_s3_net.svg" => vec![(first, printed_net(&TABLE_2_S3))],
        "figure2b_s1_s3.svg" => vec![(second, printed_net(&TABLE_2_S3))],
        "figure2c_s4_net.svg" => vec![(first, printed_net(&TABLE_2_S4))],
        "figure2d_s3_s4.svg" => vec![(second, printed_net(&TABLE_2_S4))],
        "bspline_de_boor.svg" => vec![
            (first, printed_polygon(&EXAMPLE_1_POINTS)),
            (marks, knot_images()),
        ],
        "circle_quadratic.svg" => vec![(first, printed_polygon(&UNIT_QUADRATIC.0))],
        "circle_quartic.svg" => vec![(first, printed_polygon(&UNIT_QUARTIC.0))],
        "ln_cubic.svg" => vec![(first, ln_polygon())],
        "ln_cubic_error.svg" => vec![],
        "intersections.svg" => intersection_marks(),
        "regions.svg" => region_control_points(),
        other => panic!("a figure this test does not know: {other}"),
    }
}

fn near(a: &Point3, b: &Point3) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + y.abs()))
}

/// The colour of the dot drawn last whose disc holds the pixel `at` of `figure`.
fn topmost_dot(figure: &Figure, at: (i32, i32)) -> Option<Rgb> {
    let mut top = None;
    for (points, colour, radius) in figure.dots() {
        let placed = figures::pixels(figure, points).expect("page positions");
        let r = f64::from(radius) - 1.0;
        if placed
            .iter()
            .any(|&(x, y)| f64::from(x - at.0).hypot(f64::from(y - at.1)) <= r)
        {
            top = Some(colour);
        }
    }
    top
}

/// The figure written to `file`.
fn figure_named(file: &str) -> Figure {
    figures::figures()
        .expect("the figures compute")
        .into_iter()
        .find(|f| f.file == file)
        .expect("a figure of that name")
}

/// The sorted file names in `dir`.
fn file_names(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("a readable directory")
        .map(|e| {
            e.expect("an entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    names.sort();
    names
}

#[test]
fn every_figure_is_a_picture_with_its_control_points_in_place() {
    let all = figures::figures().expect("the figures compute");
    assert_eq!(all.len(), 13);
    for figure in &all {
        let pixmap = render(figure);
        let background = palette::BACKGROUND;
        let inked = (0..SIZE.1)
            .flat_map(|y| (0..SIZE.0).map(move |x| (x as i32, y as i32)))
            .filter(|&p| colour_at(&pixmap, p).is_some_and(|c| !close(c, background)))
            .count();
        let share = inked as f64 / f64::from(SIZE.0 * SIZE.1);
        assert!(
            share > 0.01,
            "{}: only {inked} pixels are drawn",
            figure.file
        );
        let wanted = expected(figure.file);
        let drawn = figure.dots();
        assert_eq!(drawn.len(), wanted.len(), "{}: dot layers", figure.file);
        for ((colour, points), (dots, dot_colour, _)) in wanted.iter().zip(&drawn) {
            assert_eq!(colour, dot_colour, "{}", figure.file);
            assert_eq!(points.len(), dots.len(), "{}: control points", figure.file);
            for p in points {
                assert!(
                    dots.iter().any(|d| near(d, p)),
                    "{}: the printed point {p:?} is not among the drawn ones {dots:?}",
                    figure.file
                );
            }
            let placed = figures::pixels(figure, points).expect("page positions");
            for (p, &at) in points.iter().zip(&placed) {
                let top = topmost_dot(figure, at).expect("a dot is drawn there");
                let seen = colour_at(&pixmap, at);
                assert!(
                    seen.is_some_and(|c| close(c, top)),
                    "{}: at pixel {at:?} of {p:?} the colour is {seen:?}, not the dot's {top:?}",
                    figure.file
                );
            }
        }
    }
}

/// The cubic sum_i b_i B_i^3(s) of the printed polygon of seed 004, Example 3.
fn printed_cubic(s: f64) -> [f64; 2] {
    let b = ln_polygon();
    let w = [
        (1.0 - s).powi(3),
        3.0 * s * (1.0 - s).powi(2),
        3.0 * s * s * (1.0 - s),
        s.powi(3),
    ];
    let mut out = [0.0; 2];
    for (p, wi) in b.iter().zip(w) {
        out[0] += wi * p[0];
        out[1] += wi * p[1];
    }
    out
}

#[test]
fn the_ln_error_curve_is_the_printed_cubic_minus_ln() {
    let figure = &figure_named("ln_cubic_error.svg");
    let curve = figure
        .layers
        .iter()
        .find_map(|layer| match layer {
            figures::Layer::Lines { lines, colour, .. } if *colour == palette::CURVE => {
                lines.first()
            }
            _ => None,
        })
        .expect("the error curve");
    assert!(curve.len() >= 100, "{} samples", curve.len());
    let mut largest: f64 = 0.0;
    for p in curve {
        // x(s) = 1/2 + s/2 exactly (the printed x's are 1/2, 2/3, 5/6, 1), so s = 2x - 1.
        let [x, y] = printed_cubic(2.0 * p[0] - 1.0);
        assert!((x - p[0]).abs() <= 1e-14, "{p:?}");
        let error = y - x.ln();
        assert!(
            (error - p[1]).abs() <= 1e-12,
            "at x = {}: {} not {error}",
            p[0],
            p[1]
        );
        largest = largest.max(error.abs());
    }
    // The cubic interpolates ln at both ends and is close in between (seed 004's squared L2
    // error is about 2e-7): a picture of zero or of a wild curve fails here.
    assert!(largest > 1e-5 && largest < 1e-2, "largest error {largest}");
    let pixmap = render(figure);
    let placed = figures::pixels(figure, &curve[40..60]).expect("page positions");
    for at in placed {
        let near_line = (-1..=1).any(|dx| {
            (-1..=1).any(|dy| {
                // A 2-pixel line is anti-aliased: near its colour, not exactly it.
                colour_at(&pixmap, (at.0 + dx, at.1 + dy))
                    .is_some_and(|c| within(c, palette::CURVE, 40))
            })
        });
        assert!(near_line, "no curve colour near pixel {at:?}");
    }
}

#[test]
fn the_page_positions_follow_the_chart() {
    // A dot's page position moves with the point: in a plane figure, a larger x is further
    // right and a larger y higher up (smaller row), so the test above cannot pass by looking
    // at one spot.
    let circle = &figure_named("circle_quadratic.svg");
    let placed = figures::pixels(circle, &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
        .expect("page positions");
    assert!(placed[1].0 > placed[0].0 + 100, "{placed:?}");
    assert_eq!(placed[1].1, placed[0].1);
    assert!(placed[2].1 < placed[0].1 - 100, "{placed:?}");
    let pixmap = render(circle);
    assert!(colour_at(&pixmap, placed[0]).is_some_and(|c| !close(c, palette::DOTS)));
}

#[test]
fn figures_writes_every_svg_and_refuses_a_file_as_directory() {
    let dir = std::env::temp_dir().join(format!("blossom-figures-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = dir.join("new").join("pictures");
    let arg = out.to_str().expect("a UTF-8 temporary path");
    let run = run_binary(&["figures", "--out", arg], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    let files = file_names(&out);
    assert_eq!(files.len(), 13, "{files:?}");
    assert!(files.iter().all(|f| f.ends_with(".svg")));
    assert_eq!(run.stdout.lines().count(), 13, "{}", run.stdout);

    let file = dir.join("a_file");
    std::fs::write(&file, "not a directory").expect("a scratch file");
    let run = run_binary(&["figures", "--out", file.to_str().expect("UTF-8")], b"");
    assert_eq!(run.code, 2);
    assert!(run.stdout.is_empty(), "{}", run.stdout);
    assert!(run.stderr.starts_with("error: --out: "), "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1);
    assert_eq!(
        std::fs::read_to_string(&file).expect("still there"),
        "not a directory"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_pictures_in_docs_are_what_the_binary_draws() {
    // docs/figures holds every picture (the README shows two); they must not drift from the
    // code.
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures");
    let all = figures::figures().expect("the figures compute");
    let kept = file_names(&docs);
    let mut drawn: Vec<String> = all.iter().map(|f| f.file.to_string()).collect();
    drawn.sort();
    assert_eq!(
        kept, drawn,
        "docs/figures holds exactly the pictures the binary draws"
    );
    for figure in all {
        let kept = std::fs::read_to_string(docs.join(figure.file)).expect("a kept picture");
        assert!(
            kept == figures::svg(&figure).expect("the figure draws"),
            "docs/figures/{} is stale: run `cargo run --release -- figures --out docs/figures`",
            figure.file
        );
    }
}

#[test]
fn the_intersection_marks_and_the_overlap_are_where_the_exact_answers_say() {
    use figures::intersections::{OFFSETS, OVERLAP_BASE};
    let figure = &figure_named("intersections.svg");
    let pixmap = render(figure);
    let marks = intersection_marks();
    // The closed forms are right: the crossing pair, the touching arcs and the loop really
    // meet there (the other curve or the mirror parameter gives the same point).
    {
        use figures::intersections::{CROSSING, LOOP, TOUCHING};
        let [a, b] = outer_roots();
        for s in [a, 0.5, b] {
            let (p, q) = (
                bernstein(CROSSING[0], OFFSETS[0], s),
                bernstein(CROSSING[1], OFFSETS[0], s),
            );
            assert!(near(&p, &q), "{p:?} {q:?}");
        }
        let t = bernstein(TOUCHING[1], OFFSETS[1], 0.5);
        assert!(near(&bernstein(TOUCHING[0], OFFSETS[1], 0.5), &t));
        assert!(near(
            &bernstein(LOOP, OFFSETS[3], a),
            &bernstein(LOOP, OFFSETS[3], b)
        ));
    }
    // The overlap: the base cubic over [1/3, 2/3] (both stretches trace it) is highlighted,
    // the rest of both stretches is not.
    let on_base = |u: f64| bernstein(OVERLAP_BASE, OFFSETS[2], u);
    let inside: Vec<Point3> = (1..40)
        .map(|k| on_base(1.0 / 3.0 + f64::from(k) / 40.0 / 3.0))
        .collect();
    let outside: Vec<Point3> = (0..=20)
        .flat_map(|k| {
            let u = 0.03 + f64::from(k) / 20.0 * 0.27;
            [on_base(u), on_base(1.0 - u)]
        })
        .collect();
    let highlighted = |c: Option<Rgb>| c.is_some_and(|c| within(c, palette::HIGHLIGHT, 24));
    for at in figures::pixels(figure, &inside).expect("page positions") {
        assert!(
            highlighted(colour_at(&pixmap, at)),
            "no highlight at pixel {at:?} of the overlap"
        );
    }
    for at in figures::pixels(figure, &outside).expect("page positions") {
        assert!(
            !highlighted(colour_at(&pixmap, at)),
            "highlight at pixel {at:?}, off the overlap"
        );
    }
    // Nowhere else: a pixel of the chart in a mark colour is within a mark's radius of an
    // expected mark of that colour, and a highlighted pixel is within the stroke of the
    // overlap.
    let dense: Vec<Point3> = (0..=400)
        .map(|k| on_base(1.0 / 3.0 + f64::from(k) / 400.0 / 3.0))
        .collect();
    let stretch = figures::pixels(figure, &dense).expect("page positions");
    let placed: Vec<(Rgb, Vec<(i32, i32)>)> = marks
        .iter()
        .map(|(c, points)| (*c, figures::pixels(figure, points).expect("page positions")))
        .collect();
    let distance = |a: (i32, i32), b: (i32, i32)| f64::from(a.0 - b.0).hypot(f64::from(a.1 - b.1));
    let mut marked = 0;
    for y in figures::HEADER as i32..SIZE.1 as i32 {
        for x in 0..SIZE.0 as i32 {
            let Some(c) = colour_at(&pixmap, (x, y)) else {
                continue;
            };
            for (colour, centres) in &placed {
                if close(c, *colour) {
                    marked += 1;
                    assert!(
                        centres.iter().any(|&m| distance(m, (x, y)) <= 7.0),
                        "pixel {:?} has the mark colour {colour:?} away from every mark",
                        (x, y)
                    );
                }
            }
            if highlighted(Some(c)) {
                assert!(
                    stretch.iter().any(|&m| distance(m, (x, y)) <= 5.0),
                    "pixel {:?} is highlighted away from the overlap",
                    (x, y)
                );
            }
        }
    }
    // Five discs of radius 6 (about 113 pixels each, less where one covers a curve).
    assert!(marked > 5 * 80, "only {marked} mark pixels");
}

#[test]
fn the_region_results_are_filled_where_the_operations_put_them() {
    use figures::regions::OFFSETS;
    let figure = &figure_named("regions.svg");
    let pixmap = render(figure);
    // Points of the panel's own coordinates, each at least 0.3 from every boundary, with their
    // membership in A (the dome under 12 s (1 - s) over x = 4 (1 - s)^2 (1 + 2 s)) and B
    // (right of the line x = 2 - y / 3, under y = 3, left of the cubic side) worked out by
    // hand: at y = 0.53 the dome spans x in [0.02, 3.97], at y = 2.03 [0.47, 3.52], at
    // y = 2.47 [0.82, 3.19]; B's left side is at x = 1.82, 1.32, 1.18 there.
    let points: [([f64; 2], bool, bool); 6] = [
        ([1.07, 0.53], true, false),
        ([3.07, 0.53], true, true),
        ([5.07, 0.53], false, true),
        ([5.07, 3.57], false, false),
        ([3.57, 2.47], false, true),
        ([2.07, 2.03], true, true),
    ];
    let ops: [fn(bool, bool) -> bool; 3] = [|a, b| a || b, |a, b| a && b, |a, b| a && !b];
    for (panel, keeps) in ops.iter().enumerate() {
        let offset = OFFSETS[panel + 1];
        for (p, in_a, in_b) in points {
            let at = [p[0] + offset[0] as f64, p[1] + offset[1] as f64, 0.0];
            let pixel = figures::pixels(figure, &[at]).expect("a page position")[0];
            let seen = colour_at(&pixmap, pixel).expect("on the page");
            // Filled: the result's colour, drawn over the grid. Not filled: the page, or the
            // chart's grid under it (light neutral greys), never the fill's colour.
            let filled = keeps(in_a, in_b);
            let page = seen.0 == seen.1 && seen.1 == seen.2 && seen.0 >= 200;
            assert!(
                if filled {
                    close(seen, palette::FILL_2)
                } else {
                    page
                },
                "panel {}: {p:?} (in A: {in_a}, in B: {in_b}) is {seen:?}, filled: {filled}",
                panel + 1
            );
        }
    }
}
