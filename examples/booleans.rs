//! Certified booleans of regions bounded by Bézier curves, read from SVG path data: union,
//! intersection and difference, overlap removal (`simplify`) of an outline whose contours
//! overlap, exact winding numbers, results as SVG path data and chained into further booleans
//! (`to_region`), and the report of how each boolean was decided.
//!
//! `cargo run -p blossom --example booleans`.
//!
//! Every area is checked against the exact value worked out by hand in the comments: the
//! answer's `area` is an enclosure `[lo, hi]` of doubles, and lo <= exact <= hi is tested in
//! exact rational arithmetic.

use blossom::region::{
    boolean, simplify, BooleanOp, FillRule, Position, Region, RegionResult, Winding,
};
use blossom::Rational;

/// Whether the enclosure `[lo, hi]` holds the exact number `want` (compared exactly).
fn encloses(area: [f64; 2], want: &Rational) -> bool {
    let exact = |x: f64| Rational::from_float(x).expect("a finite area");
    &exact(area[0]) <= want && want <= &exact(area[1])
}

/// A one-line summary of a result: its loops, holes and area enclosure.
fn summary(r: &RegionResult) -> String {
    let holes = r.loops.iter().filter(|l| l.hole).count();
    format!(
        "{} loop(s), {holes} hole(s), area in [{}, {}]",
        r.loops.len(),
        r.area[0],
        r.area[1]
    )
}

pub fn main() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let nonzero = FillRule::NonZero;

    // A: the square [0, 4]^2, area 16.
    // B: the square [2, 6]^2 whose left side is a quadratic from (2, 6) through the control
    // point (0, 4) to (2, 2). On it y = 6 - 4t and x = 2 - 4t(1 - t), so at height y the
    // bulge reaches w(y) = (6 - y)(y - 2)/4 left of x = 2: its area is the integral of w over
    // [2, 6], 8/3, and B's area is 16 + 8/3 = 56/3.
    // A ∩ B: heights 2..4, x from 2 - w(y) to 4: 2 * 2 + (integral of w over [2, 4] = 4/3)
    // = 16/3. Then A ∪ B = 16 + 56/3 - 16/3 = 88/3, A - B = 16 - 16/3 = 32/3,
    // B - A = 56/3 - 16/3 = 40/3.
    let a = Region::from_svg_path("M 0 0 H 4 V 4 H 0 Z", nonzero).unwrap();
    let b = Region::from_svg_path("M 2 2 H 6 V 6 H 2 Q 0 4 2 2 Z", nonzero).unwrap();

    let cases = [
        ("A ∩ B", BooleanOp::Intersection, q(16, 3)),
        ("A ∪ B", BooleanOp::Union, q(88, 3)),
        ("A - B", BooleanOp::Difference, q(32, 3)),
        ("A xor B", BooleanOp::Xor, q(32, 3) + q(40, 3)),
    ];
    for (name, op, want) in &cases {
        let r = boolean(&a, &b, *op).unwrap();
        println!("{name}: {} (exact {want})", summary(&r));
        println!("  svg: {}", r.svg().unwrap());
        assert!(
            encloses(r.area, want),
            "{name}: {:?} against {want}",
            r.area
        );
        assert!(r.loops.iter().all(|l| !l.hole));
    }

    // The edges of A ∩ B: pieces of input curves between exact parameters. Going round
    // counter-clockwise from (4, 2): A's right side from s = 1/2 to 1, A's top from 0 to 3/4
    // (it runs from (4, 4) to (0, 4) and meets the quadratic's leftmost point (1, 4)), the
    // quadratic from t = 1/2 to 1, B's bottom from 0 to 1/2.
    let both = boolean(&a, &b, BooleanOp::Intersection).unwrap();
    assert_eq!(both.loops.len(), 1);
    let mut found = Vec::new();
    for e in &both.loops[0].edges {
        let exact_from = e.from.algebraic().unwrap().exact().unwrap().clone();
        let exact_to = e.to.algebraic().unwrap().exact().unwrap().clone();
        println!(
            "  region {} curve {}: from {} (enclosure {:?}) to {}",
            e.region,
            e.curve,
            exact_from,
            e.from.enclosure(),
            exact_to
        );
        // The correctly rounded double is known without exact work, and here it is the
        // exact number.
        assert_eq!(Rational::from_float(e.to.to_f64()).unwrap(), exact_to);
        found.push((e.region, e.curve, exact_from, exact_to));
    }
    found.sort();
    assert_eq!(
        found,
        vec![
            (0, 1, q(1, 2), q(1, 1)),
            (0, 2, q(0, 1), q(3, 4)),
            (1, 0, q(0, 1), q(1, 2)),
            (1, 3, q(1, 2), q(1, 1)),
        ]
    );

    // As geometry and SVG: the quadratic's piece over [1/2, 1] is the quadratic (1, 4),
    // (1, 3), (2, 2) (de Casteljau at 1/2: every number exact), written as `Q 1,3 2,2`.
    let svg = both.svg().unwrap();
    assert!(svg.contains("Q 1,3 2,2"), "{svg}");
    assert_eq!(svg.matches('L').count(), 3);
    let pieces = both.geometry();
    assert_eq!(pieces[0].iter().map(|p| p.degree()).sum::<usize>(), 5);
    // Read back, the SVG is the same region: simplified, its area is 16/3 again.
    let back = Region::from_svg_path(&svg, nonzero).unwrap();
    assert!(encloses(simplify(&back).unwrap().area, &q(16, 3)));

    // Chaining: (A ∪ B) - C, C the square [1, 3]^2 inside A. `to_region` turns the union into
    // a region (its pieces cut at the parameters 1/2 and 3/4: exact), and C's boundary lies
    // inside the union, so the answer is the union with a square hole: 88/3 - 4 = 76/3.
    let union = boolean(&a, &b, BooleanOp::Union).unwrap();
    let c = Region::from_svg_path("M 1 1 H 3 V 3 H 1 Z", nonzero).unwrap();
    let holed = boolean(&union.to_region().unwrap(), &c, BooleanOp::Difference).unwrap();
    println!("(A ∪ B) - C: {} (exact 76/3)", summary(&holed));
    println!("  svg: {}", holed.svg().unwrap());
    assert!(encloses(holed.area, &q(76, 3)));
    assert_eq!(holed.loops.len(), 2);
    assert_eq!(holed.loops.iter().filter(|l| l.hole).count(), 1);

    // Overlap removal. A plus sign drawn as a font draws it: two bars as two overlapping
    // counter-clockwise contours of one outline, each end capped by a quadratic bulging 1/2
    // out (control point 1 out: the cap is 2/3 of the triangle of its chord and control
    // point, 2/3 * 1 = 2/3). Each bar is 2 x 6 + 2 caps = 40/3; they overlap in [2, 4]^2.
    let plus = "M 0 2 H 6 Q 7 3 6 4 H 0 Q -1 3 0 2 Z \
                M 4 0 V 6 Q 3 7 2 6 V 0 Q 3 -1 4 0 Z";
    let outline = Region::from_svg_path(plus, nonzero).unwrap();
    // Winding numbers, exact: 2 in the middle, 1 on an arm, 0 outside; the tip of the right
    // cap (6.5, 3) lies on the outline.
    let at = |x: Rational, y: Rational| [x, y];
    assert_eq!(outline.winding(&at(q(3, 1), q(3, 1))), Winding::Number(2));
    assert_eq!(outline.winding(&at(q(1, 1), q(3, 1))), Winding::Number(1));
    assert_eq!(outline.winding(&at(q(7, 1), q(7, 1))), Winding::Number(0));
    assert_eq!(outline.winding(&at(q(13, 2), q(3, 1))), Winding::Boundary);
    // Nonzero: the union of the bars, 2 * 40/3 - 4 = 68/3, one loop of 12 edges.
    let merged = simplify(&outline).unwrap();
    println!("plus, nonzero, simplified: {}", summary(&merged));
    println!("  svg: {}", merged.svg().unwrap());
    assert!(encloses(merged.area, &q(68, 3)));
    assert_eq!(merged.loops.len(), 1);
    assert_eq!(merged.loops[0].edges.len(), 12);
    // Even-odd: the middle (winding 2) is out, 68/3 - 4 = 56/3: four arms that touch at the
    // corners of the middle square, so four loops (a result's loops are simple: they are
    // split where the boundary touches itself).
    let odd = Region::from_svg_path(plus, FillRule::EvenOdd).unwrap();
    assert_eq!(
        odd.contains(&at(q(3, 1), q(3, 1))),
        Position::Outside,
        "winding 2 is even"
    );
    let arms = simplify(&odd).unwrap();
    println!("plus, even-odd, simplified: {}", summary(&arms));
    assert!(encloses(arms.area, &q(56, 3)));
    assert_eq!(arms.loops.len(), 4);

    // How each boolean was decided. Every decision is exact either way; the report says
    // where the time went.
    // A and B: each loop simple, the two outlines crossing transversally at (4, 2) and
    // (1, 4): the generic shortcut of the float path.
    let report = *both.report();
    println!("A ∩ B: {report:?}");
    assert!(report.float_path && report.generic && report.exact_pairs == 0);
    // The plus: its contours cross each other, so the general float path (faces and
    // winding numbers of the arrangement) answers; its contacts are transversal crossings
    // the float filter proves, so nothing takes exact arithmetic.
    let report = *merged.report();
    println!("plus: {report:?}");
    assert!(report.float_path && !report.generic);
    assert_eq!(
        report.exact_pairs + report.exact_orders + report.exact_seeds,
        0
    );
    // A and the square [4, 8] x [0, 4], which shares A's right side: the float path still
    // answers; the coincident sides, and the sides that meet at the shared corners, are
    // intersected exactly, pair by pair, in fixed-width integers (the corners are small
    // integers), with no big rational. Union: 32, one loop.
    let beside = Region::from_svg_path("M 4 0 H 8 V 4 H 4 Z", nonzero).unwrap();
    let wide = boolean(&a, &beside, BooleanOp::Union).unwrap();
    println!(
        "A ∪ (A moved by 4): {}, {:?}",
        summary(&wide),
        wide.report()
    );
    assert!(encloses(wide.area, &q(32, 1)));
    assert_eq!(wide.loops.len(), 1);
    assert!(wide.report().float_path && wide.report().fixed_width >= 1);
    assert_eq!(wide.report().exact_pairs, 0);
    // A number that is not a double (0.1 is read exactly as 1/10) sends the boolean to the
    // exact stages, which say why. A - [0, 1/10]^2 = 16 - 1/100.
    let tenth = Region::from_svg_path("M 0 0 H 0.1 V 0.1 H 0 Z", nonzero).unwrap();
    let nicked = boolean(&a, &tenth, BooleanOp::Difference).unwrap();
    println!(
        "A - [0, 0.1]^2: {}, {:?}",
        summary(&nicked),
        nicked.report()
    );
    assert!(encloses(nicked.area, &(q(16, 1) - q(1, 100))));
    assert!(!nicked.report().float_path);
    assert_eq!(
        nicked.report().reason,
        Some("an input number is not a double")
    );
}
