//! A [`Figure`] drawn as SVG with plotters, and the page positions of its points through the
//! very chart the drawing uses (the same layout, ranges and projection), so that a test can put
//! an independently computed control point on the page and look at the pixel there.
//!
//! The page is [`SIZE`] pixels: a header band with the title and the legend, the chart below.
//! A plane chart is plotters' 2-D Cartesian chart; a space chart is its 3-D chart
//! (`build_cartesian_3d`, `with_projection`), whose vertical axis is plotters' y: a point
//! (x, y, z) of a figure is passed to it as (y, z, x), so that z is up and the frame right-handed.

use super::palette::{DOT_COLOURS, TEXT};
use super::scene::{Figure, Layer, Point3, Rgb, View};
use blossom::Error;
use plotters::coord::cartesian::Cartesian2d;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::ranged3d::Cartesian3d;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::{CoordTranslate, Shift};
use plotters::prelude::*;

/// The size of every page in pixels, width and height.
pub const SIZE: (u32, u32) = (800, 640);
/// The height of the header band (title and legend), in pixels from the top of the page.
pub const HEADER: u32 = 84;
/// Legend entries per row of the header.
const LEGEND_COLUMNS: usize = 3;

type Svg<'a> = SVGBackend<'a>;
type Area<'a> = DrawingArea<Svg<'a>, Shift>;
type Failure<'a> = DrawingAreaErrorKind<<Svg<'a> as DrawingBackend>::ErrorType>;
type PlaneChart<'a, 'b> = ChartContext<'a, Svg<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;
type SpaceChart<'a, 'b> =
    ChartContext<'a, Svg<'b>, Cartesian3d<RangedCoordf64, RangedCoordf64, RangedCoordf64>>;

/// The figure as an SVG document.
pub fn svg(figure: &Figure) -> Result<String, Error> {
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, SIZE).into_drawing_area();
        draw(&root, figure)
            .and_then(|()| root.present())
            .map_err(|e| failed(figure, &e))?;
    }
    Ok(text)
}

/// The page positions (pixels from the top left corner) of `points` in `figure`, through the
/// chart its drawing builds.
pub fn pixels(figure: &Figure, points: &[Point3]) -> Result<Vec<(i32, i32)>, Error> {
    let mut sink = String::new();
    let root = SVGBackend::with_string(&mut sink, SIZE).into_drawing_area();
    let (_, plot) = root.split_vertically(HEADER);
    let placed = match &figure.view {
        View::Plane { x, y, equal_aspect } => {
            plane_chart(&plot, *x, *y, *equal_aspect).map(|chart| {
                let spec = chart.as_coord_spec();
                points
                    .iter()
                    .map(|p| spec.translate(&(p[0], p[1])))
                    .collect()
            })
        }
        View::Space { .. } => space_chart(&plot, &figure.view).map(|chart| {
            let spec = chart.as_coord_spec();
            points.iter().map(|p| spec.translate(&up(p))).collect()
        }),
    };
    placed.map_err(|e| failed(figure, &e))
}

fn failed(figure: &Figure, e: &dyn std::fmt::Display) -> Error {
    Error::new("figures", format!("cannot draw {}: {e}", figure.file))
}

fn colour(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

/// An axis label as plotters writes an f64, without the sign of a value that prints as zero
/// (`-0.0`).
fn tick(v: &f64) -> String {
    let text = <RangedCoordf64 as ValueFormatter<f64>>::format(v);
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => text,
    }
}

/// A figure's point in plotters' 3-D coordinates (X, Y, Z) = (y, z, x): plotters' vertical
/// axis is its second, and its frame shows (X, Y, Z) left-handed, so x and y trade places for
/// the picture to show (x, y, z) right-handed.
fn up(p: &Point3) -> (f64, f64, f64) {
    (p[1], p[2], p[0])
}

fn draw<'a>(root: &Area<'a>, figure: &Figure) -> Result<(), Failure<'a>> {
    root.fill(&colour(super::palette::BACKGROUND))?;
    let (header, plot) = root.split_vertically(HEADER);
    draw_header(&header, figure)?;
    match &figure.view {
        View::Plane { x, y, equal_aspect } => {
            let mut chart = plane_chart(&plot, *x, *y, *equal_aspect)?;
            chart
                .configure_mesh()
                .light_line_style(RGBColor(245, 245, 245))
                .label_style(("sans-serif", 13).into_font().color(&colour(TEXT)))
                .x_label_formatter(&tick)
                .y_label_formatter(&tick)
                .draw()?;
            for layer in &figure.layers {
                draw_layer(&mut chart, layer, |p| (p[0], p[1]))?;
            }
        }
        View::Space { .. } => {
            let mut chart = space_chart(&plot, &figure.view)?;
            chart
                .configure_axes()
                .x_labels(6)
                .y_labels(6)
                .z_labels(6)
                .label_style(("sans-serif", 12).into_font().color(&colour(TEXT)))
                .x_formatter(&tick)
                .y_formatter(&tick)
                .z_formatter(&tick)
                .draw()?;
            for layer in &figure.layers {
                draw_layer(&mut chart, layer, up)?;
            }
        }
    }
    Ok(())
}

/// The title, then the legend in rows of [`LEGEND_COLUMNS`]: a disc for a dot colour, a
/// short line for any other.
fn draw_header<'a>(header: &Area<'a>, figure: &Figure) -> Result<(), Failure<'a>> {
    let text = colour(TEXT);
    header.draw(&Text::new(
        figure.title.clone(),
        (16, 10),
        ("sans-serif", 19).into_font().color(&text),
    ))?;
    let width = SIZE.0 as i32 / LEGEND_COLUMNS as i32;
    for (k, (c, label)) in figure.legend.iter().enumerate() {
        let x = 24 + (k % LEGEND_COLUMNS) as i32 * width;
        let y = 46 + (k / LEGEND_COLUMNS) as i32 * 20;
        if DOT_COLOURS.contains(c) {
            header.draw(&Circle::new((x, y), 5, colour(*c).filled()))?;
        } else {
            header.draw(&PathElement::new(
                vec![(x - 9, y), (x + 9, y)],
                colour(*c).stroke_width(3),
            ))?;
        }
        header.draw(&Text::new(
            label.clone(),
            (x + 16, y - 7),
            ("sans-serif", 14).into_font().color(&text),
        ))?;
    }
    Ok(())
}

/// One layer on a chart whose coordinates are `C`, a figure's point mapped by `at`.
fn draw_layer<'a, 'b, CT, C>(
    chart: &mut ChartContext<'a, Svg<'b>, CT>,
    layer: &Layer,
    at: impl Fn(&Point3) -> C,
) -> Result<(), Failure<'b>>
where
    CT: CoordTranslate<From = C>,
    C: Clone + 'static,
{
    match layer {
        Layer::Lines {
            lines,
            colour: c,
            width,
        } => {
            let style = colour(*c).stroke_width(*width);
            chart.draw_series(
                lines
                    .iter()
                    .map(|line| PathElement::new(line.iter().map(&at).collect::<Vec<C>>(), style)),
            )?;
        }
        Layer::Dots {
            points,
            colour: c,
            radius,
        } => {
            let style = colour(*c).filled();
            chart.draw_series(
                points
                    .iter()
                    .map(|p| Circle::new(at(p), *radius as i32, style)),
            )?;
        }
        Layer::Fill {
            polygons,
            colour: c,
        } => {
            let style = colour(*c).filled();
            chart.draw_series(
                polygons.iter().map(|polygon| {
                    Polygon::new(polygon.iter().map(&at).collect::<Vec<C>>(), style)
                }),
            )?;
        }
        Layer::Labels {
            items,
            colour: c,
            offset,
        } => {
            let style = ("sans-serif", 14).into_font().color(&colour(*c));
            chart.draw_series(items.iter().map(|(p, label)| {
                EmptyElement::at(at(p)) + Text::new(label.clone(), *offset, style.clone())
            }))?;
        }
    }
    Ok(())
}

/// The 2-D chart of the ranges `x`, `y` on `area`; with `equal_aspect`, the range of the axis
/// with fewer units per pixel is widened about its middle until both have as many.
fn plane_chart<'a, 'b>(
    area: &'a Area<'b>,
    x: (f64, f64),
    y: (f64, f64),
    equal_aspect: bool,
) -> Result<PlaneChart<'a, 'b>, Failure<'b>> {
    let build = |x: (f64, f64), y: (f64, f64)| {
        ChartBuilder::on(area)
            .margin(14)
            .x_label_area_size(30)
            .y_label_area_size(52)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
    };
    let chart = build(x, y)?;
    if !equal_aspect {
        return Ok(chart);
    }
    let (px, py) = chart.plotting_area().get_pixel_range();
    let (w, h) = (
        f64::from((px.end - px.start).max(1)),
        f64::from((py.end - py.start).max(1)),
    );
    let per_pixel = ((x.1 - x.0) / w).max((y.1 - y.0) / h);
    build(widen(x, per_pixel * w), widen(y, per_pixel * h))
}

/// The range of length `length` with the middle of `r`.
fn widen(r: (f64, f64), length: f64) -> (f64, f64) {
    let mid = (r.0 + r.1) / 2.0;
    (mid - length / 2.0, mid + length / 2.0)
}

/// The 3-D chart of a space view on `area`, seen from its yaw and pitch.
fn space_chart<'a, 'b>(area: &'a Area<'b>, view: &View) -> Result<SpaceChart<'a, 'b>, Failure<'b>> {
    let (x, y, z, yaw, pitch) = match view {
        View::Space {
            x,
            y,
            z,
            yaw,
            pitch,
        } => (*x, *y, *z, *yaw, *pitch),
        View::Plane { x, y, .. } => (*x, *y, (0.0, 1.0), 0.0, 0.0),
    };
    let mut chart =
        ChartBuilder::on(area)
            .margin(24)
            .build_cartesian_3d(y.0..y.1, z.0..z.1, x.0..x.1)?;
    chart.with_projection(|mut p| {
        p.yaw = yaw;
        p.pitch = pitch;
        p.scale = 0.85;
        p.into_matrix()
    });
    Ok(chart)
}
