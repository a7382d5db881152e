//! Restriction, intersection and the certified booleans timed from a dependent crate, as a
//! user meets them: with the argument `restrict`, only the restrictions of [`restrict`]; with
//! `intersect`, only the curve-curve intersections of [`intersect`]; with `region`, only the
//! certified booleans of [`region`]; with none, all three.

#[path = "../../common/mod.rs"]
mod common;
mod intersect;
#[path = "../../common/lyon.rs"]
mod lyon;
mod region;
mod restrict;

fn main() {
    let only = std::env::args().nth(1);
    let runs = |part: &str| only.is_none() || only.as_deref() == Some(part);
    if runs("intersect") {
        intersect::intersection_peers();
        println!();
    }
    if runs("region") {
        region::region_booleans();
        println!();
    }
    if runs("restrict") {
        restrict::restriction_lines();
    }
}
