//! The stages of a boolean run in order (see the module docs of [`crate::region`]), and the
//! work estimate that goes with them.

use super::area::enclose_loops;
use super::arrangement::{candidate_pairs, one_to_one, proved_join, Arrangement, CurveId};
use super::boolean::{BooleanOp, Edge, RegionResult, ResultLoop};
use super::chain::chain;
use super::classify::boundary_groups;
use super::curve::{f64_down, f64_up, Curve};
use super::input::{is_single_point, Region};
use crate::error::Result;
use crate::intersect::curves::{curve_pair_work, self_intersection_work};
use crate::num::ring::Rational;
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

/// The boolean `op` of the two regions.
pub(crate) fn run(regions: &[&Region; 2], op: BooleanOp) -> Result<RegionResult> {
    let (curves, ids, next) = collect(regions);
    let arr = Arrangement::build(curves, ids, &next)?;
    let verdicts = boundary_groups(&arr, [regions[0].fill(), regions[1].fill()], op);
    let loops = chain(&arr, &verdicts);
    if loops.is_empty() {
        return Ok(RegionResult {
            loops: Vec::new(),
            area: [0.0, 0.0],
        });
    }
    let zero = Rational::zero();
    let mut out = Vec::with_capacity(loops.len());
    for runs in &loops {
        let (_, hi) = enclose_loops(&arr, &[runs.as_slice()], |lo, hi| lo > &zero || hi < &zero);
        let edges = runs
            .iter()
            .map(|r| {
                let id = arr.ids[r.curve];
                Edge {
                    region: id.region,
                    loop_index: id.loop_index,
                    curve: id.curve,
                    from: arr.params[r.curve][r.from].clone(),
                    to: arr.params[r.curve][r.to].clone(),
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
    let all: Vec<&[_]> = loops.iter().map(Vec::as_slice).collect();
    let (lo, hi) = enclose_loops(&arr, &all, |lo, hi| hi - lo <= target);
    Ok(RegionResult {
        loops: out,
        area: [f64_down(&lo), f64_up(&hi)],
    })
}

/// The work estimate of [`run`], in nanoseconds as
/// [`intersection_work`](crate::intersection_work).
pub(crate) fn work(regions: &[&Region; 2]) -> u128 {
    let (curves, _, next) = collect(regions);
    let pairs = candidate_pairs(&curves);
    // A proof by a separating line or a monotone direction: a few microseconds.
    let proof = 5_000;
    let mut total: u128 = 0;
    for &(i, j) in &pairs {
        total += match proved_join(&curves, &next, i, j) {
            Some(_) => proof,
            None => proof + curve_pair_work(&curves[i].points, &curves[j].points),
        };
    }
    for c in &curves {
        total += proof;
        if !one_to_one(&c.points) {
            total += self_intersection_work(&c.points);
        }
    }
    // Classification: about one group per curve and two per intersecting pair, each a ray
    // tested against every curve's box (~20 ns) with a few exact crossings (~20 µs).
    let n = curves.len() as u128;
    let groups = n + 2 * pairs.len() as u128;
    total + groups * (20 * n + 20_000)
}
