//! What a picture shows, as plain data in f64: polylines, dots and text placed at points of
//! the plane or of space, in drawing order. Nothing here draws; [`super::render`] does.

/// A colour, red, green, blue.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb(pub u8, pub u8, pub u8);

/// A point of the picture's space, `[x, y, z]`; plane pictures have z = 0.
pub type Point3 = [f64; 3];

/// One thing drawn, in one colour.
#[derive(Clone, Debug, PartialEq)]
pub enum Layer {
    /// Polylines (a sampled curve, the iso-parameter lines of a patch, a control polygon or
    /// net) of `width` pixels.
    Lines {
        /// The polylines, each a list of points.
        lines: Vec<Vec<Point3>>,
        /// Their colour.
        colour: Rgb,
        /// The stroke width in pixels.
        width: u32,
    },
    /// Filled discs of `radius` pixels centred at the points: control points, and points
    /// marked on a curve.
    Dots {
        /// The centres.
        points: Vec<Point3>,
        /// The fill colour, used by nothing else in the picture.
        colour: Rgb,
        /// The radius in pixels.
        radius: u32,
    },
    /// Filled polygons (a sampled region's loops), drawn one after the other without
    /// outline: a hole is drawn as a polygon of the background colour after the loop around it.
    Fill {
        /// The polygons, each a closed list of points.
        polygons: Vec<Vec<Point3>>,
        /// The fill colour.
        colour: Rgb,
    },
    /// Text beside points (the weights of a rational curve, the knots of a spline).
    Labels {
        /// Each point with its text.
        items: Vec<(Point3, String)>,
        /// The colour of the text.
        colour: Rgb,
        /// Where the text starts relative to its point, in pixels (right, down).
        offset: (i32, i32),
    },
}

impl Layer {
    /// [`Layer::Lines`]: `lines` in `colour`, `width` pixels wide.
    pub fn lines(lines: Vec<Vec<Point3>>, colour: Rgb, width: u32) -> Layer {
        Layer::Lines {
            lines,
            colour,
            width,
        }
    }

    /// [`Layer::Dots`]: discs of `radius` pixels at `points`, filled with `colour`.
    pub fn dots(points: Vec<Point3>, colour: Rgb, radius: u32) -> Layer {
        Layer::Dots {
            points,
            colour,
            radius,
        }
    }
}

/// How the picture maps its points to the page.
#[derive(Clone, Debug, PartialEq)]
pub enum View {
    /// A 2-D chart of x against y.
    Plane {
        /// The x range shown.
        x: (f64, f64),
        /// The y range shown.
        y: (f64, f64),
        /// Whether one unit has the same length on both axes (the ranges are widened to fit).
        equal_aspect: bool,
    },
    /// A 3-D chart with z up, seen from the angles of plotters' projection (yaw about the
    /// vertical axis, then pitch), both in radians.
    Space {
        /// The x range shown.
        x: (f64, f64),
        /// The y range shown.
        y: (f64, f64),
        /// The z range shown (vertical).
        z: (f64, f64),
        /// The rotation about the vertical axis.
        yaw: f64,
        /// The tilt towards the viewer.
        pitch: f64,
    },
}

impl View {
    /// A plane view of every point of `layers`, with a margin of 6 % on each side.
    pub fn plane_around(layers: &[Layer], equal_aspect: bool) -> View {
        let [x, y, _] = bounds(layers);
        View::Plane { x, y, equal_aspect }
    }

    /// A space view of every point of `layers`, with a margin of 6 % on each side.
    pub fn space_around(layers: &[Layer], yaw: f64, pitch: f64) -> View {
        let [x, y, z] = bounds(layers);
        View::Space {
            x,
            y,
            z,
            yaw,
            pitch,
        }
    }
}

/// A legend entry: a swatch of the colour and what it stands for.
pub type LegendEntry = (Rgb, String);

/// One picture: its file name, a title, a legend, the view and the layers in drawing order.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// The file name, e.g. `figure1_s1_net.svg`.
    pub file: &'static str,
    /// The title printed above the chart.
    pub title: String,
    /// The legend printed under the title.
    pub legend: Vec<LegendEntry>,
    /// How points map to the page.
    pub view: View,
    /// What is drawn, first to last.
    pub layers: Vec<Layer>,
}

impl Figure {
    /// The dot layers (control points and marked points) in drawing order: their centres,
    /// colour and radius.
    pub fn dots(&self) -> Vec<(&[Point3], Rgb, u32)> {
        self.layers
            .iter()
            .filter_map(|layer| match layer {
                Layer::Dots {
                    points,
                    colour,
                    radius,
                } => Some((points.as_slice(), *colour, *radius)),
                _ => None,
            })
            .collect()
    }
}

/// The smallest box holding every point of `layers`, widened by 6 % on each side (and to a
/// width of at least 1e-9 where all points share a coordinate).
fn bounds(layers: &[Layer]) -> [(f64, f64); 3] {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut visit = |p: &Point3| {
        for k in 0..3 {
            if p[k].is_finite() {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    };
    for layer in layers {
        match layer {
            Layer::Lines { lines, .. } => lines.iter().flatten().for_each(&mut visit),
            Layer::Dots { points, .. } => points.iter().for_each(&mut visit),
            Layer::Fill { polygons, .. } => polygons.iter().flatten().for_each(&mut visit),
            Layer::Labels { items, .. } => items.iter().for_each(|(p, _)| visit(p)),
        }
    }
    let mut out = [(0.0, 1.0); 3];
    for k in 0..3 {
        if lo[k] <= hi[k] {
            let pad = ((hi[k] - lo[k]) * 0.06).max(1e-9);
            out[k] = (lo[k] - pad, hi[k] + pad);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_pad_every_axis() {
        let layers = vec![Layer::Dots {
            points: vec![[0.0, 0.0, 5.0], [1.0, 2.0, 5.0]],
            colour: Rgb(1, 2, 3),
            radius: 4,
        }];
        let [x, y, z] = bounds(&layers);
        assert!(x.0 < 0.0 && x.1 > 1.0 && y.0 < 0.0 && y.1 > 2.0);
        assert!(z.0 < 5.0 && z.1 > 5.0);
    }
}
