//! Stage 3 of the float path: the faces of the arrangement and the winding numbers of both
//! regions on each.
//!
//! **Faces.** Walking along half-edge h with the face on its left, at its end vertex w the
//! face continues by the half-edge leaving w just clockwise of h's twin (the order of stage
//! 2). The cycles of that successor are the faces' boundaries, one cycle per face and
//! connected component of the arrangement (a face of several components is several cycles,
//! each seeded on its own below).
//!
//! **Across a half-edge.** For half-edge h of group g (its representative's way for h = 2g),
//! the winding number of region r on h's left exceeds the one on its right by the signed
//! number of g's pieces of r (+1 for a piece running h's way): crossing a closed loop from its
//! right to its left adds one. So within a component every face's winding numbers follow
//! from one face's, by a walk across half-edges; two routes to one face must agree (they do
//! for a correct arrangement; a disagreement sends the boolean to the exact stages).
//!
//! **One seed per component.** A component is a union of whole input loops (consecutive curves
//! of a loop meet at their join). Let v be a join of the component on a side of the box of
//! its control points, say the least x. Every curve of the component lies in x >= v_x (hulls),
//! so the points just left of v lie outside every one of them: the component's loops wind 0
//! times around them, and every half-edge leaving v points into x >= v_x (its class differs
//! from -x's). The sector at v that holds the direction -x is therefore a face of the
//! component whose winding numbers are those of the *other* loops at v, which do not pass
//! through v: an exact ray count on boxes (`side`). That sector lies just counter-clockwise
//! of the last half-edge at v whose class precedes -x's. Sides y_lo, x_hi, y_hi likewise.
//! When no join lies on a side of the box (the extreme is inside a curve), the component's
//! *outer* face is found by area: the cycles of a connected plane arrangement bound its
//! faces, each bounded face's cycle counter-clockwise (positive signed area) and the outer
//! face's clockwise (negative: minus the area the component encloses), so the one cycle of
//! the component whose signed area is proved negative (rigorous enclosure, `measure`) is the
//! outer face; the component winds 0 times around its points near the component, and the
//! other loops wind around them as around any join of the component (a ray count on boxes).
//! When that does not decide either (a component of zero area, every ray undecided), the
//! exact stages' own computation seeds the component: exact winding numbers beside one of its
//! pieces by a ray from a rational point of it (`classify::sides_of_piece`).

use super::bounds::sign;
use super::graph::Graph;
use super::measure::Areas;
use super::order::{ccw_order, classes_at, Around};
use super::side::windings_at;
use crate::error::Result;
use crate::num::bounded::BoundedF64;
use crate::num::ring::Ring;
use crate::region::arrangement::Joins;
use crate::region::classify::sides_of_piece;

/// Each half-edge's face and each face's winding numbers `[A, B]`.
pub(super) struct Faces {
    pub face: Vec<usize>,
    pub winding: Vec<[i64; 2]>,
    /// Components seeded by the sign of a face's area.
    pub area_seeds: usize,
    /// Components seeded by the exact stages' ray (nothing cheaper decided).
    pub exact_seeds: usize,
}

/// The cycles of the half-edge successor, one after another.
struct Cycles {
    edges: Vec<usize>,
    /// Cycle f is `edges[start[f]..start[f + 1]]`.
    start: Vec<usize>,
}

impl Cycles {
    fn len(&self) -> usize {
        self.start.len() - 1
    }

    fn get(&self, f: usize) -> &[usize] {
        &self.edges[self.start[f]..self.start[f + 1]]
    }
}

/// How many joins of a component are tried for a ray count on boxes.
const JOINS_TRIED: usize = 8;

/// The outer face of component `comp` (the cycle of negative signed area) with its winding
/// numbers, or `None` when no cycle's sign or no ray decides (module docs).
fn seed_by_area(
    graph: &Graph<'_>,
    cycles: &Cycles,
    comp_of_curve: &[usize],
    comp: usize,
    areas: &mut Areas<'_, '_>,
) -> Option<(usize, [i64; 2])> {
    let w = (0..graph.curves.len())
        .filter(|&c| comp_of_curve[c] == comp)
        .take(JOINS_TRIED)
        .find_map(|c| {
            windings_at(graph, graph.curves[c].points[0], |d| {
                comp_of_curve[d] == comp
            })
        })?;
    for f in 0..cycles.len() {
        let cycle = cycles.get(f);
        let (c, _, _) = graph.branch(cycle[0]);
        if comp_of_curve[c] != comp {
            continue;
        }
        let mut sum = BoundedF64::exact(0.0);
        for &h in cycle {
            let (c, at, toward) = graph.branch(h);
            sum = sum.add(&areas.piece(c, at, toward));
        }
        if sign(&sum) == Some(-1) {
            return Some((f, w));
        }
    }
    None
}

/// The half-edge after h along the face on h's left.
fn successor(graph: &Graph<'_>, around: &Around, h: usize) -> usize {
    around.clockwise(h ^ 1, graph.dest(h))
}

/// The signed number of pieces of each region in h's group running h's way.
fn across(graph: &Graph<'_>, h: usize) -> [i64; 2] {
    let m = graph.multiplicity(h / 2);
    if h.is_multiple_of(2) {
        m
    } else {
        [-m[0], -m[1]]
    }
}

/// A face of component `comp` with its winding numbers, from a join on a side of the
/// component's box (module docs), or `None` when none decides.
fn seed_at_join(
    graph: &Graph<'_>,
    around: &Around,
    face: &[usize],
    comp_of_curve: &[usize],
    comp: usize,
) -> Result<Option<(usize, [i64; 2])>> {
    let curves: Vec<usize> = (0..graph.curves.len())
        .filter(|&c| comp_of_curve[c] == comp)
        .collect();
    let b = curves.iter().fold(graph.curves[curves[0]].bbox, |b, &c| {
        let e = graph.curves[c].bbox;
        [
            b[0].min(e[0]),
            b[1].min(e[1]),
            b[2].max(e[2]),
            b[3].max(e[3]),
        ]
    });
    for &c in &curves {
        let v = graph.curves[c].points[0];
        // (side of the box, the class of the direction out of it)
        for (on_side, outward) in [
            (v[0] == b[0], 4u8),
            (v[1] == b[1], 6),
            (v[0] == b[2], 0),
            (v[1] == b[3], 2),
        ] {
            if !on_side {
                continue;
            }
            let Some(w) = windings_at(graph, v, |d| comp_of_curve[d] == comp) else {
                break;
            };
            let vertex = graph.vertex[c][0];
            let classes = classes_at(graph, around, vertex)?;
            if classes.contains(&outward) {
                continue;
            }
            // The half-edge just clockwise of `outward`: the latest counter-clockwise of
            // those whose class precedes it, else of all.
            let list = around.at(vertex);
            let before = |i: &usize| classes[*i] < outward;
            let any_before = (0..list.len()).any(|i| before(&i));
            let mut best: Option<usize> = None;
            for i in (0..list.len()).filter(|i| !any_before || before(i)) {
                best = Some(match best {
                    None => i,
                    Some(j) if classes[i] != classes[j] => {
                        if classes[i] > classes[j] {
                            i
                        } else {
                            j
                        }
                    }
                    Some(j) => match ccw_order(graph, list[i], list[j])? {
                        std::cmp::Ordering::Greater => i,
                        _ => j,
                    },
                });
            }
            let i = best.expect("a vertex has half-edges");
            return Ok(Some((face[list[i]], w)));
        }
    }
    Ok(None)
}

/// A face of component `comp` with its winding numbers by the exact stages' ray beside a
/// piece of it.
fn seed_exact(
    graph: &Graph<'_>,
    face: &[usize],
    comp_of_curve: &[usize],
    comp: usize,
) -> Result<(usize, [i64; 2])> {
    let g = (0..graph.groups.len())
        .find(|&g| comp_of_curve[graph.pieces[graph.groups[g].rep].curve] == comp)
        .expect("a component has a group");
    let (c, at, toward) = graph.branch(2 * g);
    let (a, b) = (
        graph.params[c][at].algebraic()?,
        graph.params[c][toward].algebraic()?,
    );
    let of_region = |r: usize| -> Vec<&crate::region::curve::Curve> {
        graph
            .curves
            .iter()
            .filter(|x| x.id.region == r)
            .map(|x| x.exact())
            .collect()
    };
    let sides = sides_of_piece(
        graph.curves[c].exact(),
        a,
        b,
        graph.multiplicity(g),
        [of_region(0), of_region(1)],
    );
    Ok((face[2 * g], sides[0]))
}

/// The faces and their winding numbers, or `None` when two routes to a face disagree.
pub(super) fn faces(
    graph: &Graph<'_>,
    around: &Around,
    areas: &mut Areas<'_, '_>,
) -> Result<Option<Faces>> {
    let n = graph.half_edges();
    let mut face = vec![usize::MAX; n];
    // The cycles one after another: cycle f is edges[start[f]..start[f + 1]].
    let mut cycles = Cycles {
        edges: Vec::with_capacity(n),
        start: vec![0],
    };
    for h in 0..n {
        if face[h] != usize::MAX {
            continue;
        }
        let id = cycles.start.len() - 1;
        let mut e = h;
        while face[e] == usize::MAX {
            face[e] = id;
            cycles.edges.push(e);
            e = successor(graph, around, e);
        }
        if e != h {
            return Ok(None);
        }
        cycles.start.push(cycles.edges.len());
    }
    // Components: vertices joined by the groups.
    let mut joins = Joins::new(graph.vertices);
    for g in 0..graph.groups.len() {
        joins.join(graph.origin(2 * g), graph.dest(2 * g), false);
    }
    let comp_of_curve: Vec<usize> = (0..graph.curves.len())
        .map(|c| joins.find(graph.vertex[c][0]).0)
        .collect();
    let mut winding: Vec<Option<[i64; 2]>> = vec![None; cycles.len()];
    let (mut area_seeds, mut exact_seeds) = (0, 0);
    let mut queue = Vec::new();
    let mut seeded = vec![false; graph.vertices];
    for &comp in &comp_of_curve {
        if std::mem::replace(&mut seeded[comp], true) {
            continue;
        }
        let (f, w) = match seed_at_join(graph, around, &face, &comp_of_curve, comp)? {
            Some(seed) => seed,
            None => match seed_by_area(graph, &cycles, &comp_of_curve, comp, areas) {
                Some(seed) => {
                    area_seeds += 1;
                    seed
                }
                None => {
                    exact_seeds += 1;
                    seed_exact(graph, &face, &comp_of_curve, comp)?
                }
            },
        };
        winding[f] = Some(w);
        queue.push(f);
        while let Some(f) = queue.pop() {
            let wf = winding[f].expect("queued faces have winding numbers");
            for &h in cycles.get(f) {
                let d = across(graph, h);
                let wt = [wf[0] - d[0], wf[1] - d[1]];
                let t = face[h ^ 1];
                match winding[t] {
                    None => {
                        winding[t] = Some(wt);
                        queue.push(t);
                    }
                    Some(x) if x != wt => return Ok(None),
                    Some(_) => {}
                }
            }
        }
    }
    let winding = winding.into_iter().collect::<Option<Vec<_>>>();
    Ok(winding.map(|winding| Faces {
        face,
        winding,
        area_seeds,
        exact_seeds,
    }))
}
