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
//! * The work of a `boolean`, `simplify` or `triangle-triangle` job is the library's
//!   estimate ([`blossom::region::boolean_work`]) in nanoseconds of a 2-core machine; a job
//!   whose estimate is over twice `--max-work` is refused up front
//!   ([`within_budget`](super::intersect::within_budget)) naming `regions` (`region`,
//!   `triangles`); what it lets through runs under the work meter
//!   ([`super::cost::metered`]), which stops it at `--max-work` naming the same field. The
//!   answer is written under the meter as well: the exact parameters of the crossings the
//!   float path proved are computed there.
//! * The work of a `winding` job is [`Region::winding_work`], refused over twice `--max-work`
//!   naming `points`, and metered the same way.

pub mod boolean;
pub mod simplify;
pub mod triangle_triangle;
pub mod winding;

use super::intersect::{over_degree, Curve2, Curves};
use super::read::{below, counted, Count, Name, Named, Reading};
use super::write::{write, Double, Param};
use blossom::region::MAX_REGION_DEGREE;
use blossom::region::{parse_svg_path, BooleanOp, Edge, FillRule, Region, RegionResult};
use blossom::Error;
use serde::de::{self, Deserializer};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::marker::PhantomData;

/// The curves of `blossom region`.
#[derive(Clone, Copy, Debug)]
pub struct RegionCurves;

impl Curves for RegionCurves {
    const MAX: usize = MAX_REGION_DEGREE;
    const SUBCOMMAND: &'static str = "blossom region";
    const PLANAR: &'static str = "coordinates (regions are 2-D)";
    const AT_LEAST_TWO: bool = false;
}

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
    loops: Option<Vec<Loop<T>>>,
    path: Option<String>,
    fill: Option<Name<FillRule>>,
}

/// A LOOP: its curves.
struct Loop<T>(Vec<Curve2<T, RegionCurves>>);

impl<'de, T: Reading> Deserialize<'de> for Loop<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        counted(d, Count::Any, "a loop (an array of curves)").map(Loop)
    }
}

impl<'de, T: Reading> Deserialize<'de> for RegionShape<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let fields = RegionFields::<T>::deserialize(d)?;
        let loops = match (fields.loops, fields.path) {
            (Some(loops), None) => loops
                .into_iter()
                .map(|l| l.0.into_iter().map(|c| blossom::Bezier::new(c.0)).collect())
                .collect::<Result<Vec<Vec<_>>, Error>>(),
            (None, Some(path)) => parse_svg_path(&path, |text| {
                T::read(&Value::String(text.to_string()))
                    .map(|x| x.exact())
                    .map_err(|message| Error::new("", message))
            })
            .map_err(|e| Error::of(e.kind, "path", e.message)),
            (None, None) => Err(Error::new(
                "loops",
                "missing field (a region is {\"loops\": [...]} or {\"path\": SVG path data})",
            )),
            (Some(_), Some(_)) => Err(Error::new(
                "path",
                "a region has \"loops\" or \"path\", not both",
            )),
        }
        .map_err(|e| below(&e))?;
        let fill = fields.fill.map_or(FillRule::NonZero, |f| f.0);
        Region::new(loops, fill)
            .map(|r| RegionShape(r, PhantomData))
            .map_err(|e| below(&e))
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
    nodes: Vec<super::intersect::Point2<T, RegionCurves>>,
}

/// The degree of a triangle: a JSON integer, at most [`MAX_REGION_DEGREE`].
struct TriangleDegree(usize);

impl<'de> Deserialize<'de> for TriangleDegree {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let value = Value::deserialize(d)?;
        let found = match &value {
            Value::Number(n) => n.to_string(),
            other => crate::number::json_type(other).to_string(),
        };
        let degree = value.as_u64().ok_or_else(|| {
            de::Error::custom(format!("expected an integer n >= 1, found {found}"))
        })?;
        match usize::try_from(degree) {
            Ok(n) if n <= MAX_REGION_DEGREE => Ok(TriangleDegree(n)),
            _ => Err(de::Error::custom(over_degree::<RegionCurves>(
                usize::try_from(degree).unwrap_or(usize::MAX),
            ))),
        }
    }
}

impl<'de, T: Reading> Deserialize<'de> for TriangleShape<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let fields = TriangleFields::<T>::deserialize(d)?;
        let nodes = fields.nodes.into_iter().map(|p| p.0).collect();
        Region::triangle(fields.degree.0, nodes)
            .map(|r| TriangleShape(r, PhantomData))
            .map_err(|e| below(&e))
    }
}

/// Exactly two shapes (`regions`, `triangles`).
#[derive(Clone, Debug)]
pub struct Two<S>(pub [S; 2]);

impl<'de, S: Deserialize<'de> + Plural> Deserialize<'de> for Two<S> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let items: Vec<S> = counted(
            d,
            Count::Exactly(2, S::PLURAL),
            format!("an array of two {}", S::PLURAL),
        )?;
        Ok(Two(items.try_into().unwrap_or_else(|_| unreachable!())))
    }
}

/// The name of several shapes, for messages.
pub trait Plural {
    /// `regions`, `triangles`.
    const PLURAL: &'static str;
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
    kind: &'static str,
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
    /// The answer of the job `kind` (`triangle_edges`: edges numbered as a
    /// `triangle-triangle` answer numbers them) as JSON.
    pub fn write(
        kind: &'static str,
        result: &RegionResult,
        triangle_edges: bool,
    ) -> Result<Value, Error> {
        let edge = |e: &Edge| -> Result<EdgeAnswer, Error> {
            let (from, to) = (Param::of(e.from.algebraic()?), Param::of(e.to.algebraic()?));
            Ok(if triangle_edges {
                EdgeAnswer {
                    region: None,
                    loop_index: None,
                    curve: e.triangle_edge(),
                    from,
                    to,
                }
            } else {
                EdgeAnswer {
                    region: Some(e.region),
                    loop_index: Some(e.loop_index),
                    curve: e.curve,
                    from,
                    to,
                }
            })
        };
        let loops = result
            .loops
            .iter()
            .map(|l| {
                Ok(LoopAnswer {
                    hole: l.hole,
                    edges: l.edges.iter().map(edge).collect::<Result<_, Error>>()?,
                })
            })
            .collect::<Result<_, Error>>()?;
        write(&RegionAnswer {
            kind,
            loops,
            area: [Double(result.area[0]), Double(result.area[1])],
            svg: result.svg(),
        })
    }
}

/// `error` re-addressed under `path` (the library names its own arguments).
pub fn at(path: &str, error: Error) -> Error {
    let field = super::read::joined(path, &error.field);
    Error::of(error.kind, field, error.message)
}

/// The points of a `winding` job.
pub type Points<T> = Vec<super::intersect::Point2<T, RegionCurves>>;
