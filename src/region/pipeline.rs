//! The stages of a boolean run in order (see the module docs of [`crate::region`]), and the
//! work estimate that goes with them.

use super::answer::{BooleanOp, Edge, Outline, Report, ResultLoop};
use super::area::{loop_terms, refine_sum};
use super::arrangement::{candidate_pairs, one_to_one, proved_join, Arrangement, CurveId};
use super::chain::chain;
use super::classify::boundary_groups;
use super::curve::{f64_down, f64_up, is_double, Curve};
use super::input::{is_single_point, Region};
use super::parameter::Parameter;
use crate::error::Result;
use crate::intersect::budget::{curve_pair_work, self_intersection_work};
use crate::intersect::filter::crossing_parameters_f64;
use crate::num::ring::{rational_to_f64, Rational};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The curves of both regions that trace more than a point, in (region, loop, curve) order,
/// with their ids and each one's successor in its loop.
pub(crate) fn collect(regions: &[&Region; 2]) -> (Vec<Curve>, Vec<CurveId>, Vec<usize>) {
    let (mut curves, mut ids, mut next) = (Vec::new(), Vec::new(), Vec::new());
    for (r, region) in regions.iter().enumerate() {
        for (l, lp) in region.loops().iter().enumerate() {
            let first = curves.len();
            for (c, curve) in lp.iter().enumerate() {
                if is_single_point(curve) {
                    continue;
                }
                curves.push(Curve::new(curve));
                ids.push(CurveId {
                    region: r,
                    loop_index: l,
                    curve: c,
                });
                next.push(curves.len());
            }
            if curves.len() > first {
                *next.last_mut().expect("the loop has a curve") = first;
            }
        }
    }
    (curves, ids, next)
}

/// B: the area of the smallest axis-parallel box holding every input control point.
fn box_area(regions: &[&Region; 2]) -> Rational {
    let mut points = regions
        .iter()
        .flat_map(|r| r.loops().iter().flatten())
        .flat_map(|c| c.points().iter());
    let Some(p0) = points.next() else {
        return Rational::zero();
    };
    let (mut lo, mut hi) = (p0.clone(), p0.clone());
    for p in points {
        for a in 0..2 {
            if p[a] < lo[a] {
                lo[a] = p[a].clone();
            }
            if p[a] > hi[a] {
                hi[a] = p[a].clone();
            }
        }
    }
    (&hi[0] - &lo[0]) * (&hi[1] - &lo[1])
}

/// The boolean `op` of the two regions: the float path ([`super::filtered`]) when every
/// input number is a double (any arrangement), else the exact stages, which also answer
/// should a check of the float path not pass (the report keeps the reason).
pub(crate) fn run(regions: &[&Region; 2], op: BooleanOp) -> Result<Outline> {
    match super::filtered::run(regions, op) {
        Ok(answer) => Ok(answer),
        Err(reason) => {
            let mut answer = run_exact(regions, op)?;
            answer.report.reason = Some(reason);
            Ok(answer)
        }
    }
}

/// The boolean `op` of the two regions by the exact stages.
pub(crate) fn run_exact(regions: &[&Region; 2], op: BooleanOp) -> Result<Outline> {
    let (curves, ids, next) = collect(regions);
    let arr = Arrangement::build(curves, ids, &next)?;
    let verdicts = boundary_groups(&arr, [regions[0].fill(), regions[1].fill()], op);
    let loops = chain(&arr, &verdicts);
    if loops.is_empty() {
        return Ok(Outline {
            loops: Vec::new(),
            area: [0.0, 0.0],
            report: Report::default(),
        });
    }
    let zero = Rational::zero();
    let mut out = Vec::with_capacity(loops.len());
    let mut all_terms = Vec::new();
    for runs in &loops {
        // A simple loop bounds a positive area: refinement decides its sign.
        let mut terms = loop_terms(&arr, runs);
        let (_, hi) = refine_sum(&mut terms, |lo, hi| lo > &zero || hi < &zero);
        all_terms.extend(terms);
        let edges = runs
            .iter()
            .map(|r| {
                let id = arr.ids[r.curve];
                Edge {
                    region: id.region,
                    loop_index: id.loop_index,
                    curve: id.curve,
                    from: Parameter::known(arr.params[r.curve][r.from].clone()),
                    to: Parameter::known(arr.params[r.curve][r.to].clone()),
                }
            })
            .collect();
        out.push(ResultLoop {
            hole: hi < zero,
            edges,
        });
    }
    // hi - lo <= B / 2^42 before rounding; each outward rounding adds at most an ulp of a
    // number not above B in magnitude (the result lies in the box), 2^-52 B.
    let target = box_area(regions) / Rational::from_integer(BigInt::one() << 42);
    let (lo, hi) = refine_sum(&mut all_terms, |lo, hi| hi - lo <= target);
    Ok(Outline {
        loops: out,
        area: [f64_down(&lo), f64_up(&hi)],
        report: Report::default(),
    })
}

/// The intersection points a pair of curves is expected to add: the float filter's count of
/// proved crossings when it decides ([`crossing_parameters_f64`], on curves of doubles),
/// else 2.
fn expected_points(p: &Curve, q: &Curve) -> u128 {
    let doubles = |c: &Curve| -> Option<Vec<[f64; 2]>> {
        c.points
            .iter()
            .map(|xy| {
                (is_double(&xy[0]) && is_double(&xy[1]))
                    .then(|| [rational_to_f64(&xy[0]), rational_to_f64(&xy[1])])
            })
            .collect()
    };
    doubles(p)
        .zip(doubles(q))
        .and_then(|(pf, qf)| crossing_parameters_f64(&pf, &qf))
        .map_or(2, |c| c.len() as u128)
}

/// The cost of one intersection point beyond the pair's own work, in nanoseconds: the
/// refinement of its two algebraic parameters, the two extra pieces it makes and their
/// classification and chaining. Measured on the dense stars of the scale test (about 1,600
/// crossing points in 4 s on a loaded 2-core machine, 2026-12-07).
const PER_POINT: u128 = 1_000_000;

/// The work estimate of [`run`], in nanoseconds as
/// [`intersection_work`](crate::budget::intersection_work): [`super::filtered::work`] when
/// the float path applies to the two regions, else that of the exact stages: the pairs (proved joins a few
/// microseconds, others [`curve_pair_work`] plus [`PER_POINT`] per expected point), the
/// self-intersections, and the classification of about one group per curve and two per
/// point, each a ray tested against every curve's box (~20 ns) with a few exact tests, and
/// its share of the splitting, chaining and area (~50 µs in all, measured on the wavy
/// outlines of the scale test).
pub(crate) fn work(regions: &[&Region; 2]) -> u128 {
    if let Some(w) = super::filtered::work(regions) {
        return w;
    }
    let (curves, _, next) = collect(regions);
    let pairs = candidate_pairs(&curves);
    // A proof by a separating line or a monotone direction: a few microseconds.
    let proof = 5_000;
    let mut total: u128 = 0;
    let mut points: u128 = 0;
    for &(i, j) in &pairs {
        total += proof;
        if proved_join(&curves, &next, i, j).is_none() {
            total += curve_pair_work(&curves[i].points, &curves[j].points);
            points += expected_points(&curves[i], &curves[j]);
        }
    }
    for c in &curves {
        total += proof;
        if !one_to_one(&c.points) {
            total += self_intersection_work(&c.points);
            points += 1;
        }
    }
    let n = curves.len() as u128;
    let groups = n + 2 * points;
    total + points * PER_POINT + groups * (20 * n + 50_000)
}
