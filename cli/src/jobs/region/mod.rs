//! The jobs of `blossom region` (the contract's section "Regions and booleans"): the
//! intersection of two Bézier triangles ([`triangle_triangle`]), the booleans of two regions
//! ([`boolean`]), overlap removal ([`simplify`]) and exact winding numbers ([`winding`]),
//! every answer certified by the library's region layer ([`blossom::region`]).
//!
//! This module reads the shapes (REGION, TRIANGLE; their numbers read exactly as the
//! arithmetic says, every error naming its field by its full path) and writes the answers
//! ([`RegionAnswer`]). What makes a region a region (loops closed, curve degrees in
//! 1..=[`MAX_REGION_DEGREE`], a triangle's node count) is checked once, by the library's
//! [`Region::new`] and [`Region::triangle`], whose errors name the field relative to the
//! region and are put under the job's path (`regions[1].loops[0][2]: starts at (1, 0), the
//! previous curve ends at (1, 1/2)`).
//!
//! # Limits
//!
//! * Curve and triangle degrees 1..=[`MAX_REGION_DEGREE`] (the contract asks for 10); a
//!   longer curve is refused before its numbers are read.
//! * The work budget as for `blossom intersect` ([`certified`](super::intersect::certified)),
//!   from the library's estimate ([`blossom::region::boolean_work`], [`Region::winding_work`])
//!   and under the meter, naming `regions` (`region`, `triangles`, `points`). The answer is
//!   written under the meter as well: the exact parameters of the crossings the float path
//!   proved are computed there.

pub mod boolean;
pub mod simplify;
pub mod triangle_triangle;
pub mod winding;

use super::intersect::{Curve2, Curves};
pub use super::read::Two;
use super::read::{any, below, items, leaf, List, Name, Named, Plural, Reading};
use super::write::{write, Double, Param};
use blossom::region::MAX_REGION_DEGREE;
use blossom::region::{parse_svg_path, BooleanOp, Edge, FillRule, Region, RegionResult};
use blossom::{Error, ErrorKind, Rational};
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use std::marker::PhantomData;

/// The curves of `blossom region`.
pub const REGION: Curves = Curves {
    max: MAX_REGION_DEGREE,
    subcommand: "blossom region",
    planar: "coordinates (regions are 2-D)",
    at_least_two: false,
};

impl Named for FillRule {
    const WHAT: &'static str = "fill rule";
    const NAMES: &'static [(&'static str, Self)] = &[
        ("nonzero", FillRule::NonZero),
        ("evenodd", FillRule::EvenOdd),
    ];
}

impl Named for BooleanOp {
    const WHAT: &'static str = "op";
    const NAMES: &'static [(&'static str, Self)] = &[
        ("intersection", BooleanOp::Intersection),
        ("union", BooleanOp::Union),
        ("difference", BooleanOp::Difference),
        ("xor", BooleanOp::Xor),
    ];
}

/// A REGION: `{"loops": [LOOP, ...], "fill": "nonzero" | "evenodd"}` (no loops: the empty
/// region), or `{"path": D, "fill": ...}` with D SVG path data ([`parse_svg_path`]; its
/// numbers read as the arithmetic reads numbers, relative coordinates added exactly).
#[derive(Clone, Debug)]
pub struct RegionShape<T>(pub Region, PhantomData<T>);

/// The fields of a REGION.
#[derive(Deserialize)]
#[serde(
    bound = "T: Reading",
    expecting = "a region {\"loops\": [...], \"fill\": ...}"
)]
struct RegionFields<T> {
    loops: Option<List<Loop<T>>>,
    path: Option<String>,
    fill: Option<Name<FillRule>>,
}

/// A LOOP: its curves.
struct Loop<T>(Vec<Curve2>, PhantomData<T>);

impl<'de, T: Reading> Deserialize<'de> for Loop<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let curve = |c: &Value| REGION.curve::<T>(c);
        leaf(d, |v| items(v, "a loop (an array of curves)", any, curve))
            .map(|l| Loop(l, PhantomData))
    }
}

impl<'de, T: Reading> Deserialize<'de> for RegionShape<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let fields = RegionFields::<T>::deserialize(d)?;
        let fill = fields.fill.map_or(FillRule::NonZero, |f| f.0);
        let region = match (fields.loops, fields.path) {
            (Some(loops), None) => from_loops(loops.0.into_iter().map(|l| l.0).collect(), fill),
            (None, Some(path)) => parse_svg_path(&path, |text| {
                T::read(&Value::String(text.to_string()))
                    .map(|x| x.exact())
                    .map_err(|message| Error::new("", message))
            })
            .map_err(|e| Error::of(e.kind, "path", e.message))
            .and_then(|loops| Region::new(loops, fill)),
            (None, None) => Err(Error::new(
                "loops",
                "missing field (a region is {\"loops\": [...]} or {\"path\": SVG path data})",
            )),
            (Some(_), Some(_)) => Err(Error::new(
                "path",
                "a region has \"loops\" or \"path\", not both",
            )),
        };
        region
            .map(|r| RegionShape(r, PhantomData))
            .map_err(|e| below(&e))
    }
}

/// The region of `loops` under `fill` ([`Region::new`]); a curve that does not start where the
/// previous one ends is named with both points as written (`starts at (1, 0.1)`, not the exact
/// value of the double nearest to 0.1).
fn from_loops(loops: Vec<Vec<Curve2>>, fill: FillRule) -> Result<Region, Error> {
    type Ends = Vec<[String; 2]>;
    let (points, ends): (Vec<Vec<_>>, Vec<Ends>) = loops
        .into_iter()
        .map(|curves| curves.into_iter().map(|c| (c.points, c.ends)).unzip())
        .unzip();
    let bezier = |curves: Vec<_>| curves.into_iter().map(blossom::Bezier::new).collect();
    let exact = points
        .into_iter()
        .map(bezier)
        .collect::<Result<_, Error>>()?;
    Region::new(exact, fill).map_err(|e| {
        let open = |(l, curves): (usize, &Ends)| {
            let c = (0..curves.len()).find(|c| e.field == format!("loops[{l}][{c}]"))?;
            let previous = &curves[(c + curves.len() - 1) % curves.len()];
            let (start, end) = (&curves[c][0], &previous[1]);
            let message = format!("starts at {start}, the previous curve ends at {end}");
            Some(Error::of(e.kind, e.field.clone(), message))
        };
        match e.kind {
            ErrorKind::Shape => ends.iter().enumerate().find_map(open).unwrap_or(e),
            _ => e,
        }
    })
}

/// A point `[x, y]` of `blossom region` (of a triangle, or where a winding number is asked).
#[derive(Clone, Debug)]
pub struct Point2<T>(pub [Rational; 2], PhantomData<T>);

impl<'de, T: Reading> Deserialize<'de> for Point2<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| REGION.point::<T>(v)).map(|p| Point2(p, PhantomData))
    }
}

/// A TRIANGLE: `{"degree": n, "nodes": [...]}`, the region of its loop of three edges
/// ([`Region::triangle`]: curves 0, 1, 2 of loop 0 are edges 0, 1, 2).
#[derive(Clone, Debug)]
pub struct TriangleShape<T>(pub Region, PhantomData<T>);

/// The fields of a TRIANGLE.
#[derive(Deserialize)]
#[serde(
    bound = "T: Reading",
    expecting = "a triangle {\"degree\": n, \"nodes\": [...]}"
)]
struct TriangleFields<T> {
    degree: TriangleDegree,
    nodes: List<Point2<T>>,
}

/// The degree of a triangle: a JSON integer, at most [`MAX_REGION_DEGREE`].
struct TriangleDegree(usize);

impl<'de> Deserialize<'de> for TriangleDegree {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |value| {
            let found = match value {
                Value::Number(n) => n.to_string(),
                other => crate::number::json_type(other).to_string(),
            };
            let degree = value.as_u64().ok_or_else(|| {
                Error::new("", format!("expected an integer n >= 1, found {found}"))
            })?;
            match usize::try_from(degree) {
                Ok(n) if n <= MAX_REGION_DEGREE => Ok(TriangleDegree(n)),
                _ => Err(Error::new(
                    "",
                    REGION.over_degree(degree.try_into().unwrap_or(usize::MAX)),
                )),
            }
        })
    }
}

impl<'de, T: Reading> Deserialize<'de> for TriangleShape<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let fields = TriangleFields::<T>::deserialize(d)?;
        let nodes = fields.nodes.0.into_iter().map(|p| p.0).collect();
        Region::triangle(fields.degree.0, nodes)
            .map(|r| TriangleShape(r, PhantomData))
            .map_err(|e| below(&e))
    }
}

impl<T> Plural for RegionShape<T> {
    const PLURAL: &'static str = "regions";
}

impl<T> Plural for TriangleShape<T> {
    const PLURAL: &'static str = "triangles";
}

/// The answer of a `boolean`, `simplify` or `triangle-triangle` job: the regularized result as
/// oriented simple loops of edges, an enclosure of its area and its SVG path data.
#[derive(Serialize)]
pub struct RegionAnswer {
    loops: Vec<LoopAnswer>,
    area: [Double; 2],
    /// The result as SVG path data (`null` when an edge has degree over 3).
    svg: Option<String>,
}

#[derive(Serialize)]
struct LoopAnswer {
    hole: bool,
    edges: Vec<EdgeAnswer>,
}

/// An EDGE: a piece of one input curve between two PARAMs (`triangle-triangle`: the curve is
/// the edge number 0..=5, without region and loop).
#[derive(Serialize)]
struct EdgeAnswer {
    #[serde(skip_serializing_if = "Option::is_none")]
    region: Option<usize>,
    #[serde(rename = "loop", skip_serializing_if = "Option::is_none")]
    loop_index: Option<usize>,
    curve: usize,
    from: Param,
    to: Param,
}

impl RegionAnswer {
    /// The answer of `result` (`triangle_edges`: edges numbered as a `triangle-triangle`
    /// answer numbers them) as JSON.
    pub fn write(result: &RegionResult, triangle_edges: bool) -> Result<Value, Error> {
        let edge = |e: &Edge| -> Result<EdgeAnswer, Error> {
            Ok(EdgeAnswer {
                region: (!triangle_edges).then_some(e.region),
                loop_index: (!triangle_edges).then_some(e.loop_index),
                curve: if triangle_edges {
                    e.triangle_edge()
                } else {
                    e.curve
                },
                from: Param::of(e.from.algebraic()?),
                to: Param::of(e.to.algebraic()?),
            })
        };
        let loops = result.loops.iter().map(|l| {
            let edges = l.edges.iter().map(edge).collect::<Result<_, Error>>()?;
            Ok(LoopAnswer {
                hole: l.hole,
                edges,
            })
        });
        write(&RegionAnswer {
            loops: loops.collect::<Result<_, Error>>()?,
            area: [Double(result.area[0]), Double(result.area[1])],
            svg: result.svg(),
        })
    }
}
