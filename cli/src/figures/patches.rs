//! Figures 1 and 2 of the subdivision paper (seeds 000/001, section 4): the surface S of
//! Example 1, S(u, v) = sum c_ij u^i v^j with Table 1's coefficients (n = 3, m = 2), restricted
//! by the library
//!
//! * to the rectangles of Table 1, as tensor-product Bézier patches S_1 on [0, 1] x [0, 1] and
//!   S_2 on [1/3, 2/3] x [1/4, 3/4] (formula (9); p_{nu mu} = b(b^nu, a^(n-nu); d^mu, c^(m-mu)));
//! * to the triangles of Table 2, as triangular Bézier patches of total degree N = n + m = 5:
//!   S_3 on a = (0, 0), b = (1, 0), c = (0, 1) and S_4 on a = (0, 1/2), b = (1/2, 0),
//!   c = (1/2, 1/2) (formula (14); q_{nu mu lambda} = b(a^nu, b^mu, c^lambda), eq. (12)).
//!
//! Each patch is drawn as its iso-parameter lines, evaluated from the computed control points,
//! with its control net as lines and dots:
//! Figure 1 (a) S_1 with its net, (b) S_1 and S_2 with their nets; Figure 2 (a) S_3 with its
//! net, (b) S_1 and S_3 with the net of S_3, (c) S_4 with its net, (d) S_3 and S_4 with the net
//! of S_4.

use super::mesh::{
    tensor_f64, tensor_iso_lines, tensor_net_lines, tensor_points, triangle_f64,
    triangle_iso_lines, triangle_net_lines, triangle_points,
};
use super::palette::{DOTS, DOTS_2, MESH, MESH_2, NET, NET_2};
use super::scene::{Figure, Layer, Rgb, View};
use crate::verify::paper_data::{TABLE_1_RECTANGLES, TABLE_2_TRIANGLES};
use crate::verify::seeds_002_004::num;
use crate::verify::subdivision::example_1_surface;
use blossom::{restrict_power_surface, restrict_power_surface_to_triangle, Error, Method};
use blossom::{Rational, TensorPatch, TriangularPatch};

/// The method the pictures restrict with (the library's default).
pub const METHOD: Method = Method::Bulk;
/// The viewing angles of every surface picture (plotters' yaw and pitch, radians).
const YAW: f64 = 0.65;
const PITCH: f64 = 0.4;
/// The radius of a control point's dot.
const DOT_RADIUS: u32 = 4;

/// S_1 (`which = 0`) or S_2 (`which = 1`): S on the rectangle of Table 1.
pub fn tensor_restriction(which: usize) -> Result<TensorPatch<Rational>, Error> {
    let rect = TABLE_1_RECTANGLES
        .get(which)
        .ok_or_else(|| Error::new("figures", "Table 1 has two rectangles"))?;
    Ok(restrict_power_surface(
        &example_1_surface(),
        &rect.map(num),
        METHOD,
    ))
}

/// S_3 (`which = 0`) or S_4 (`which = 1`): S on the triangle of Table 2, at total degree 5.
pub fn triangle_restriction(which: usize) -> Result<TriangularPatch<Rational>, Error> {
    let tri = TABLE_2_TRIANGLES
        .get(which)
        .ok_or_else(|| Error::new("figures", "Table 2 has two triangles"))?;
    Ok(restrict_power_surface_to_triangle(
        &example_1_surface(),
        &tri.map(|corner| corner.map(num)),
        METHOD,
    ))
}

/// A patch's layers: its iso-parameter lines (mesh), and optionally its net as lines and dots.
struct Drawn {
    mesh: Layer,
    net: Option<(Layer, Layer)>,
}

fn tensor_drawn(patch: &TensorPatch<Rational>, colours: Colours) -> Result<Drawn, Error> {
    let net = tensor_points(patch);
    Ok(Drawn {
        mesh: Layer::lines(tensor_iso_lines(&tensor_f64(patch)?), colours.mesh, 1),
        net: colours.net.map(|(line, dot)| {
            (
                Layer::lines(tensor_net_lines(&net), line, 1),
                Layer::dots(net.concat(), dot, DOT_RADIUS),
            )
        }),
    })
}

fn triangle_drawn(patch: &TriangularPatch<Rational>, colours: Colours) -> Result<Drawn, Error> {
    Ok(Drawn {
        mesh: Layer::lines(triangle_iso_lines(&triangle_f64(patch)?), colours.mesh, 1),
        net: colours.net.map(|(line, dot)| {
            (
                Layer::lines(triangle_net_lines(patch), line, 1),
                Layer::dots(triangle_points(patch), dot, DOT_RADIUS),
            )
        }),
    })
}

/// The mesh colour, and the net's line and dot colours when the net is drawn.
#[derive(Clone, Copy)]
struct Colours {
    mesh: Rgb,
    net: Option<(Rgb, Rgb)>,
}

const FIRST: Colours = Colours {
    mesh: MESH,
    net: Some((NET, DOTS)),
};
const FIRST_BARE: Colours = Colours {
    mesh: MESH,
    net: None,
};
const SECOND: Colours = Colours {
    mesh: MESH_2,
    net: Some((NET_2, DOTS_2)),
};

/// The layers of several patches: all meshes, then all net lines, then all dots, so that no
/// line covers a control point.
fn scene(file: &'static str, title: String, drawn: Vec<(Drawn, &str)>) -> Figure {
    let mut legend = Vec::new();
    let mut meshes = Vec::new();
    let mut nets = Vec::new();
    let mut points = Vec::new();
    for (d, name) in drawn {
        if let Layer::Lines { colour, .. } = &d.mesh {
            legend.push((*colour, format!("{name}: iso-parameter lines")));
        }
        meshes.push(d.mesh);
        if let Some((net, dot)) = d.net {
            if let Layer::Dots { colour, .. } = &dot {
                legend.push((*colour, format!("{name}: control points")));
            }
            nets.push(net);
            points.push(dot);
        }
    }
    let mut layers = meshes;
    layers.extend(nets);
    layers.extend(points);
    let view = View::space_around(&layers, YAW, PITCH);
    Figure {
        file,
        title,
        legend,
        view,
        layers,
    }
}

/// Figures 1 (a), 1 (b), 2 (a), 2 (b), 2 (c), 2 (d).
pub fn figures() -> Result<Vec<Figure>, Error> {
    let s1 = tensor_restriction(0)?;
    let s2 = tensor_restriction(1)?;
    let s3 = triangle_restriction(0)?;
    let s4 = triangle_restriction(1)?;
    Ok(vec![
        scene(
            "figure1a_s1_net.svg",
            "Figure 1 (a): S_1 on [0, 1] x [0, 1], bidegree (3, 2), with its control net".into(),
            vec![(tensor_drawn(&s1, FIRST)?, "S_1")],
        ),
        scene(
            "figure1b_s1_s2.svg",
            "Figure 1 (b): S_1 and S_2 on [1/3, 2/3] x [1/4, 3/4], with their nets".into(),
            vec![
                (tensor_drawn(&s1, FIRST)?, "S_1"),
                (tensor_drawn(&s2, SECOND)?, "S_2"),
            ],
        ),
        scene(
            "figure2a_s3_net.svg",
            "Figure 2 (a): S_3 on (0, 0), (1, 0), (0, 1), degree 5, with its net".into(),
            vec![(triangle_drawn(&s3, FIRST)?, "S_3")],
        ),
        scene(
            "figure2b_s1_s3.svg",
            "Figure 2 (b): S_1 and S_3 with the net of S_3".into(),
            vec![
                (tensor_drawn(&s1, FIRST_BARE)?, "S_1"),
                (triangle_drawn(&s3, SECOND)?, "S_3"),
            ],
        ),
        scene(
            "figure2c_s4_net.svg",
            "Figure 2 (c): S_4 on (0, 1/2), (1/2, 0), (1/2, 1/2), degree 5, with its net".into(),
            vec![(triangle_drawn(&s4, FIRST)?, "S_4")],
        ),
        scene(
            "figure2d_s3_s4.svg",
            "Figure 2 (d): S_3 and S_4 with the net of S_4".into(),
            vec![
                (triangle_drawn(&s3, FIRST_BARE)?, "S_3"),
                (triangle_drawn(&s4, SECOND)?, "S_4"),
            ],
        ),
    ])
}
