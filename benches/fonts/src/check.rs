//! The checks of a blossom answer, outside the timed calls: its form (what the answer
//! promises) and its consumed geometry against its own area enclosure.

use crate::peers::{piece, segment, BlossomAnswer, Curves};
use blossom::region::{Edge, Parameter};
use kurbo::ParamCurveArea;

/// Where the edge starts (`end = false`) or ends (`end = true`) when that is a curve's own
/// end: the control point, exactly.
fn control_end(curves: &[Curves; 2], e: &Edge, end: bool) -> Option<[f64; 2]> {
    let p = if end { &e.to } else { &e.from };
    let one = p.curve_end()?;
    let points = curves[e.region][e.loop_index][e.curve].points();
    Some(if one {
        *points.last().expect("degree >= 1")
    } else {
        points[0]
    })
}

fn same_parameter(p: &Parameter, q: &Parameter) -> bool {
    p.to_f64() == q.to_f64() && p.enclosure() == q.enclosure()
}

/// Whether `e` ends where `f` begins: exactly when both are curve ends (control points) or
/// both are on one curve (the same parameter), else to within `tol` (a crossing of two
/// curves, whose exact point is algebraic).
fn joined(curves: &[Curves; 2], e: &Edge, f: &Edge, tol: f64) -> Result<(), String> {
    let ids = |x: &Edge| (x.region, x.loop_index, x.curve);
    if let (Some(p), Some(q)) = (control_end(curves, e, true), control_end(curves, f, false)) {
        return if p == q {
            Ok(())
        } else {
            Err(format!(
                "{:?} ends at {p:?}, {:?} begins at {q:?}",
                ids(e),
                ids(f)
            ))
        };
    }
    if ids(e) == ids(f) {
        return if same_parameter(&e.to, &f.from) {
            Ok(())
        } else {
            Err(format!(
                "{:?} ends at parameter {}, the next edge on it begins at {}",
                ids(e),
                e.to,
                f.from
            ))
        };
    }
    let p = *piece(curves, e).points().last().expect("degree >= 1");
    let q = piece(curves, f).points()[0];
    let d = (p[0] - q[0]).hypot(p[1] - q[1]);
    if d <= tol {
        Ok(())
    } else {
        Err(format!(
            "{:?} ends at {p:?}, {:?} begins at {q:?} ({d:e} apart)",
            ids(e),
            ids(f)
        ))
    }
}

/// The checks of one answer whose inputs have the curves `curves` (`[region][loop][curve]`).
/// `box_area` and `extent` are the input's box area and larger side.
pub fn well_formed(
    answer: &BlossomAnswer,
    curves: &[Curves; 2],
    box_area: f64,
    extent: f64,
) -> Result<(), String> {
    let r = &answer.result;
    let [lo, hi] = r.area;
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return Err(format!("area enclosure [{lo}, {hi}] is not an interval"));
    }
    if hi < 0.0 {
        return Err(format!("negative area enclosure [{lo}, {hi}]"));
    }
    let tol = 1e-9 * extent.max(1.0);
    let mut total = 0.0;
    for (l, lp) in r.loops.iter().enumerate() {
        if lp.edges.is_empty() {
            return Err(format!("loop {l} has no edge"));
        }
        for e in &lp.edges {
            let named = curves
                .get(e.region)
                .and_then(|c| c.get(e.loop_index))
                .and_then(|c| c.get(e.curve));
            if named.is_none() {
                return Err(format!(
                    "loop {l} names curve ({}, {}, {}), which the inputs lack",
                    e.region, e.loop_index, e.curve
                ));
            }
        }
        for (k, e) in lp.edges.iter().enumerate() {
            let f = &lp.edges[(k + 1) % lp.edges.len()];
            joined(curves, e, f, tol).map_err(|m| format!("loop {l}, edge {k}: {m}"))?;
        }
        let area: f64 = lp
            .edges
            .iter()
            .map(|e| segment(&piece(curves, e)).signed_area())
            .sum();
        if area.abs() > tol * extent && (area < 0.0) != lp.hole {
            return Err(format!(
                "loop {l} (hole: {}) has signed area {area}",
                lp.hole
            ));
        }
        total += area;
    }
    let geometry = r.geometry();
    for (l, pieces) in geometry.iter().enumerate() {
        for (k, p) in pieces.iter().enumerate() {
            let next = &pieces[(k + 1) % pieces.len()];
            let (end, start) = (p.points()[p.degree()], next.points()[0]);
            if end != start {
                return Err(format!(
                    "geometry: loop {l}, piece {k} ends at {end:?}, the next begins at {start:?}"
                ));
            }
        }
    }
    let slack = 1e-9 * box_area.max(1.0);
    if total < lo - slack || total > hi + slack {
        return Err(format!(
            "the pieces enclose {total}, outside the enclosure [{lo}, {hi}]"
        ));
    }
    if (answer.path_area - total).abs() > slack {
        return Err(format!(
            "the consumed path's area {} differs from the pieces' {total}",
            answer.path_area
        ));
    }
    Ok(())
}

/// Whether the answer is the input itself: every edge a whole input curve, as many edges as
/// curves (what `simplify` answers on a glyph without overlaps).
pub fn unchanged(answer: &BlossomAnswer, curves: usize) -> bool {
    let whole = |e: &Edge| {
        matches!(
            (e.from.curve_end(), e.to.curve_end()),
            (Some(a), Some(b)) if a != b
        )
    };
    let edges: usize = answer.result.loops.iter().map(|l| l.edges.len()).sum();
    edges == curves && answer.result.loops.iter().flat_map(|l| &l.edges).all(whole)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::outline::Outline;

    /// Two overlapping squares in one outline, clockwise as TrueType draws them.
    fn squares() -> Outline {
        let square = |x: f64, y: f64| -> Vec<Vec<[f64; 2]>> {
            let c = [[x, y], [x, y + 2.0], [x + 2.0, y + 2.0], [x + 2.0, y]];
            (0..4).map(|i| vec![c[i], c[(i + 1) % 4]]).collect()
        };
        vec![square(0.0, 0.0), square(1.0, 1.0)]
    }

    fn curves() -> [Curves; 2] {
        [crate::peers::curves_of(&squares()), Vec::new()]
    }

    #[test]
    fn a_right_answer_passes() {
        let a = crate::peers::blossom(&squares(), None).unwrap();
        assert_eq!(a.result.loops.len(), 1);
        assert!((a.path_area - 7.0).abs() < 1e-12);
        well_formed(&a, &curves(), 9.0, 3.0).unwrap();
        assert!(!unchanged(&a, 8));
    }

    #[test]
    fn broken_answers_fail() {
        let mut a = crate::peers::blossom(&squares(), None).unwrap();
        a.result.loops[0].edges.swap(0, 2);
        assert!(well_formed(&a, &curves(), 9.0, 3.0)
            .unwrap_err()
            .contains("begins"));
        let mut a = crate::peers::blossom(&squares(), None).unwrap();
        a.result.loops[0].hole = true;
        assert!(well_formed(&a, &curves(), 9.0, 3.0)
            .unwrap_err()
            .contains("signed area"));
        let mut a = crate::peers::blossom(&squares(), None).unwrap();
        a.result.area = [6.0, 6.5];
        assert!(well_formed(&a, &curves(), 9.0, 3.0)
            .unwrap_err()
            .contains("enclosure"));
        a.result.area = [7.5, 7.0];
        assert!(well_formed(&a, &curves(), 9.0, 3.0)
            .unwrap_err()
            .contains("interval"));
    }
}
