//! Writing the answers of `blossom region` in the contract's form: a [`RegionResult`] as
//! `{"kind", "loops": [{"hole", "edges": [EDGE, ...]}, ...], "area": [lo, hi]}` with every
//! parameter a PARAM (the correctly rounded double, the exact rational when there is one, an
//! isolating interval and the square-free integer polynomial:
//! `intersect_jobs::param`), and the winding numbers of points.

use super::intersect_jobs::{double, param};
use blossom::region::{Edge, Position, Region, RegionResult, Winding};
use blossom::{Error, Rational};
use serde_json::{json, Value};

/// The answer of a `boolean` (`triangle_edges` false: edges name region, loop and curve) or
/// `triangle-triangle` job (`triangle_edges` true: edges name the curve 0..=5, the first
/// triangle's edges 0, 1, 2 and the second's 3, 4, 5).
pub fn region_result(
    kind: &str,
    result: &RegionResult,
    triangle_edges: bool,
) -> Result<Value, Error> {
    let loops = result
        .loops
        .iter()
        .map(|lp| {
            let edges = lp
                .edges
                .iter()
                .map(|e| edge(e, triangle_edges))
                .collect::<Result<Vec<Value>, Error>>()?;
            Ok(json!({"hole": lp.hole, "edges": edges}))
        })
        .collect::<Result<Vec<Value>, Error>>()?;
    Ok(json!({
        "kind": kind,
        "loops": loops,
        "area": [double(result.area[0])?, double(result.area[1])?],
    }))
}

/// One EDGE.
fn edge(e: &Edge, triangle_edges: bool) -> Result<Value, Error> {
    let (from, to) = (param(e.from.algebraic()?)?, param(e.to.algebraic()?)?);
    Ok(if triangle_edges {
        json!({"curve": e.triangle_edge(), "from": from, "to": to})
    } else {
        json!({
            "region": e.region,
            "loop": e.loop_index,
            "curve": e.curve,
            "from": from,
            "to": to,
        })
    })
}

/// The answer of a `winding` job: for each point its exact winding number around the
/// region's loops and where the fill rule puts it; a point on a loop is `"boundary"` with
/// `"winding": null`.
pub fn windings(region: &Region, points: &[[Rational; 2]]) -> Result<Value, Error> {
    let fill = region.fill();
    let entries: Vec<Value> = region
        .windings(points)
        .into_iter()
        .map(|w| match w {
            Winding::Boundary => json!({"position": position(Position::Boundary), "winding": null}),
            Winding::Number(k) => {
                let p = if fill.inside(k) {
                    Position::Inside
                } else {
                    Position::Outside
                };
                json!({"position": position(p), "winding": k})
            }
        })
        .collect();
    Ok(json!({"kind": "winding", "points": entries}))
}

/// The contract's name of a position.
fn position(p: Position) -> &'static str {
    match p {
        Position::Inside => "inside",
        Position::Outside => "outside",
        Position::Boundary => "boundary",
    }
}
