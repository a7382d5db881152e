//! The accuracy sweep of issue 12: every f64 restriction path against the exact answer and
//! against the stable reference ([`super::reference`]) on the same inputs.
//!
//! Error = max |got - exact| / max |exact| over all coordinates of all control points, the
//! maximum over the samples of one row. Inputs: 3-D control points (or power coefficients)
//! uniform in [-1, 1] on the grid of step 2^-24 (rounding happens from the first product on;
//! the grid only keeps the exact answers short); intervals of three kinds ([`Kind`]). The exact
//! answer is the engine run in exact arithmetic ([`Dyadic`] for Bézier input, [`Rational`] for
//! power input) on the exact values of the same doubles: exact, so any correct exact
//! algorithm gives it, and the symbolic proofs show the engine is one.

use super::dyadic::Dyadic;
use super::reference;
use blossom::engine::bernstein_to_power;
use blossom::{
    rational_to_f64, restrict_power_curve, Batch, Bezier, BezierTensor, BezierTriangle, Method,
    PowerCurve, PowerSurface, Rational, RestrictionMap,
};

/// The kind of interval (or of rectangle and triangle, built from such intervals).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// a < b uniform in [0, 1].
    Inside,
    /// b = a + 1e-3 inside [0, 1].
    Short,
    /// a, b uniform in [-3, 3].
    Extrapolating,
}

impl Kind {
    /// All three.
    pub const ALL: [Kind; 3] = [Kind::Inside, Kind::Short, Kind::Extrapolating];

    /// The name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Inside => "inside [0,1]",
            Kind::Short => "length 1e-3",
            Kind::Extrapolating => "in [-3,3]",
        }
    }
}

/// SplitMix64.
pub struct Rng(pub u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) on the grid of step 2^-24: doubles whose exact values stay short,
    /// so the exact answers at degree 64 cost milliseconds, not seconds.
    fn unit(&mut self) -> f64 {
        (self.next() >> 40) as f64 / (1u64 << 24) as f64
    }

    /// Uniform in [lo, hi) on the grid of step 2^-24 (lo, hi integers or 1 - 1e-3).
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        let x = lo + (hi - lo) * self.unit();
        (x * (1u64 << 24) as f64).round() / (1u64 << 24) as f64
    }

    fn point(&mut self) -> [f64; 3] {
        std::array::from_fn(|_| self.between(-1.0, 1.0))
    }

    /// An interval of `kind`.
    pub fn interval(&mut self, kind: Kind) -> (f64, f64) {
        match kind {
            Kind::Inside => {
                let (x, y) = (self.unit(), self.unit());
                (x.min(y), x.max(y))
            }
            Kind::Short => {
                let a = self.between(0.0, 1.0 - 1e-3);
                (a, a + 1e-3)
            }
            Kind::Extrapolating => (self.between(-3.0, 3.0), self.between(-3.0, 3.0)),
        }
    }
}

/// One row: the errors of every path on the same inputs, and of the reference.
#[derive(Clone, Debug)]
pub struct Row {
    /// `bezier-curve`, `bezier-tensor`, `bezier-triangle` or `power-curve`.
    pub shape: &'static str,
    /// The degree (m = 0 for curves and triangles).
    pub degree: (usize, usize),
    /// The kind of domain.
    pub kind: Kind,
    /// The reference's name and error: the textbook pyramid for Bézier input, the closed form
    /// for power input.
    pub reference: (&'static str, f64),
    /// Each path's name and error.
    pub errors: Vec<(&'static str, f64)>,
}

impl Row {
    /// The largest ratio error / reference error among the paths named in `paths` (with the
    /// reference's error floored at one ulp, 2^-52).
    pub fn worst_ratio(&self, paths: &[&str]) -> f64 {
        let floor = self.reference.1.max(f64::EPSILON);
        self.errors
            .iter()
            .filter(|(name, _)| paths.contains(name))
            .map(|(_, e)| e / floor)
            .fold(0.0, f64::max)
    }
}

/// Running maximum of |got - exact| and of |exact| for one path.
#[derive(Clone, Copy, Default)]
struct Accumulator {
    diff: f64,
    size: f64,
}

impl Accumulator {
    fn add(&mut self, exact: &[[f64; 3]], got: &[[f64; 3]]) {
        for (e, g) in exact.iter().zip(got) {
            for (&e, g) in e.iter().zip(g) {
                self.diff = self.diff.max((g - e).abs());
                self.size = self.size.max(e.abs());
            }
        }
    }

    fn error(self) -> f64 {
        if self.size > 0.0 {
            self.diff / self.size
        } else {
            self.diff
        }
    }
}

/// Exact numbers of the sweep: converted from doubles, and back to the nearest double.
trait Exact: blossom::Ring {
    fn of(x: f64) -> Self;
    fn nearest(&self) -> f64;
}

impl Exact for Dyadic {
    fn of(x: f64) -> Self {
        Dyadic::from_f64(x).expect("finite inputs")
    }
    fn nearest(&self) -> f64 {
        rational_to_f64(&self.to_rational())
    }
}

impl Exact for Rational {
    fn of(x: f64) -> Self {
        Rational::from_float(x).expect("finite inputs")
    }
    fn nearest(&self) -> f64 {
        rational_to_f64(self)
    }
}

fn exact_points<T: Exact>(points: &[[f64; 3]]) -> Vec<[T; 3]> {
    points.iter().map(|p| p.map(T::of)).collect()
}

/// The exact answer rounded once to doubles.
fn nearest<T: Exact>(points: &[[T; 3]]) -> Vec<[f64; 3]> {
    points
        .iter()
        .map(|p| std::array::from_fn(|x| p[x].nearest()))
        .collect()
}

fn exact(x: f64) -> Dyadic {
    Dyadic::of(x)
}

/// Per path, the accumulators of one row, in a fixed order of names.
struct Paths {
    names: Vec<&'static str>,
    acc: Vec<Accumulator>,
}

impl Paths {
    fn new(names: &[&'static str]) -> Self {
        Paths {
            names: names.to_vec(),
            acc: vec![Accumulator::default(); names.len()],
        }
    }

    fn add(&mut self, name: &str, exact: &[[f64; 3]], got: &[[f64; 3]]) {
        let k = self
            .names
            .iter()
            .position(|n| *n == name)
            .expect("a declared path");
        self.acc[k].add(exact, got);
    }

    fn into_row(
        self,
        shape: &'static str,
        degree: (usize, usize),
        kind: Kind,
        reference: &'static str,
    ) -> Row {
        let mut errors: Vec<(&'static str, f64)> = self
            .names
            .iter()
            .zip(&self.acc)
            .map(|(n, a)| (*n, a.error()))
            .collect();
        let k = errors
            .iter()
            .position(|(n, _)| *n == reference)
            .expect("the reference is a path");
        let reference = errors.remove(k);
        Row {
            shape,
            degree,
            kind,
            reference,
            errors,
        }
    }
}

/// The textbook pyramid, one per control point.
pub const PYRAMID: &str = "textbook pyramid";
/// The engine through the generic API ([`Bezier::subsegment`] and siblings).
pub const ENGINE: &str = "engine";
/// The engine on a [`Batch`].
pub const BATCH: &str = "batch";
/// The evaluator `blossom::restriction!` generated for that degree.
pub const GENERATED: &str = "generated";
/// The previous default: to the power basis by forward differences, then the Taylor shift.
pub const BEFORE: &str = "before (power basis)";

/// The generated evaluator of a Bézier curve of degree `n`, if the binary carries it.
fn generated_curve(ctrl: &[[f64; 3]], a: f64, b: f64) -> Option<Vec<[f64; 3]>> {
    #[cfg(feature = "carried-grid")]
    {
        let curve =
            blossom::BezierCurve::new(ctrl.iter().map(|p| p.to_vec()).collect()).expect("points");
        let got = blossom_grid::restrict_bezier_curve_specialised(&curve, &a, &b)?;
        Some(
            got.control_points()
                .iter()
                .map(|p| std::array::from_fn(|x| p[x]))
                .collect(),
        )
    }
    #[cfg(not(feature = "carried-grid"))]
    {
        let _ = (ctrl, a, b);
        None
    }
}

/// Bézier curves of each degree in `degrees`: `samples` intervals of each kind, two curves per
/// interval (the batch restricts both at once).
pub fn bezier_curves(degrees: &[usize], samples: usize, seed: u64) -> Vec<Row> {
    let mut rng = Rng(seed);
    let mut rows = Vec::new();
    for &n in degrees {
        for kind in Kind::ALL {
            let mut paths = Paths::new(&[PYRAMID, ENGINE, BATCH, GENERATED, BEFORE]);
            let mut generated = true;
            for _ in 0..samples {
                let (a, b) = rng.interval(kind);
                let curves: Vec<Vec<[f64; 3]>> = (0..2)
                    .map(|_| (0..=n).map(|_| rng.point()).collect())
                    .collect();
                let batch = Batch::from_nets(
                    n + 1,
                    3,
                    &curves
                        .iter()
                        .map(|c| c.iter().map(|p| p.to_vec()).collect::<Vec<_>>())
                        .collect::<Vec<_>>()
                        .iter()
                        .map(Vec::as_slice)
                        .collect::<Vec<_>>(),
                )
                .expect("two curves of one shape");
                let map = RestrictionMap::curve(n, a, b).expect("finite");
                let mut out = Batch::zeros(n + 1, 3, 2).expect("a small batch");
                batch.restrict_into(&map, &mut out).expect("fitting shapes");
                for (k, ctrl) in curves.iter().enumerate() {
                    let want = Bezier::new(exact_points::<Dyadic>(ctrl))
                        .expect("points")
                        .subsegment(exact(a)..exact(b));
                    let want = nearest(want.points());
                    paths.add(PYRAMID, &want, &reference::curve(ctrl, a, b));
                    let engine = Bezier::new(ctrl.clone()).expect("points").subsegment(a..b);
                    paths.add(ENGINE, &want, engine.points());
                    let lanes: Vec<[f64; 3]> = (0..=n)
                        .map(|p| std::array::from_fn(|x| out.get(k, p, x)))
                        .collect();
                    paths.add(BATCH, &want, &lanes);
                    match generated_curve(ctrl, a, b) {
                        Some(g) => paths.add(GENERATED, &want, &g),
                        None => generated = false,
                    }
                    let power = PowerCurve::new(bernstein_to_power(
                        &ctrl.iter().map(|p| p.to_vec()).collect::<Vec<_>>(),
                    ))
                    .expect("points");
                    let before: Vec<[f64; 3]> =
                        restrict_power_curve(&power, &a, &b, Method::TaylorShift)
                            .control_points()
                            .iter()
                            .map(|p| std::array::from_fn(|x| p[x]))
                            .collect();
                    paths.add(BEFORE, &want, &before);
                }
            }
            let mut row = paths.into_row("bezier-curve", (n, 0), kind, PYRAMID);
            if !generated {
                row.errors.retain(|(name, _)| *name != GENERATED);
            }
            rows.push(row);
        }
    }
    rows
}

macro_rules! generated_tensors {
    ($($n:literal, $m:literal => $name:ident;)*) => {
        $(blossom::restriction!(name = $name, shape = bezier_tensor, degree = ($n, $m));)*
        /// The generated evaluator of a tensor patch of bidegree `degree`, among those this
        /// sweep instantiates.
        fn generated_tensor(
            net: &[[f64; 3]],
            degree: (usize, usize),
            rect: [f64; 4],
        ) -> Option<Vec<[f64; 3]>> {
            match degree {
                $(($n, $m) => {
                    let grid: [[[f64; 3]; $m + 1]; $n + 1] = std::array::from_fn(|i| {
                        std::array::from_fn(|j| net[i * ($m + 1) + j])
                    });
                    Some($name(&grid, &rect).concat())
                })*
                _ => None,
            }
        }
    };
}

generated_tensors! {
    1, 1 => bezier_tensor_1_1;
    2, 2 => bezier_tensor_2_2;
    3, 3 => bezier_tensor_3_3;
    3, 1 => bezier_tensor_3_1;
    4, 4 => bezier_tensor_4_4;
    5, 5 => bezier_tensor_5_5;
    2, 5 => bezier_tensor_2_5;
}

/// Tensor patches of each bidegree in `degrees`, rectangles from two intervals of one kind.
pub fn bezier_tensors(degrees: &[(usize, usize)], samples: usize, seed: u64) -> Vec<Row> {
    let mut rng = Rng(seed);
    let mut rows = Vec::new();
    for &(n, m) in degrees {
        for kind in Kind::ALL {
            let mut paths = Paths::new(&[PYRAMID, ENGINE, BATCH, GENERATED, BEFORE]);
            let mut generated = true;
            for _ in 0..samples {
                let ((a, b), (c, d)) = (rng.interval(kind), rng.interval(kind));
                let rect = [a, b, c, d];
                let net: Vec<[f64; 3]> = (0..(n + 1) * (m + 1)).map(|_| rng.point()).collect();
                let exact_net =
                    BezierTensor::new((n, m), exact_points::<Dyadic>(&net)).expect("net");
                let want = nearest(exact_net.restrict(&rect.map(exact)).points());
                paths.add(PYRAMID, &want, &reference::tensor(&net, m + 1, rect));
                let patch = BezierTensor::new((n, m), net.clone()).expect("net");
                paths.add(ENGINE, &want, patch.restrict(&rect).points());
                let batch = Batch::from_nets(
                    net.len(),
                    3,
                    &[&net.iter().map(|p| p.to_vec()).collect::<Vec<_>>()],
                )
                .expect("one net");
                let map = RestrictionMap::tensor((n, m), rect).expect("finite");
                let mut out = Batch::zeros(net.len(), 3, 1).expect("a small batch");
                batch.restrict_into(&map, &mut out).expect("fitting shapes");
                let lanes: Vec<[f64; 3]> = (0..net.len())
                    .map(|p| std::array::from_fn(|x| out.get(0, p, x)))
                    .collect();
                paths.add(BATCH, &want, &lanes);
                match generated_tensor(&net, (n, m), rect) {
                    Some(g) => paths.add(GENERATED, &want, &g),
                    None => generated = false,
                }
                // Before: rows along v to the power basis, then columns along u, then the
                // Taylor shift of the power surface.
                let rows: Vec<Vec<Vec<f64>>> = net
                    .chunks(m + 1)
                    .map(|r| bernstein_to_power(&r.iter().map(|p| p.to_vec()).collect::<Vec<_>>()))
                    .collect();
                let long: Vec<Vec<f64>> = rows.iter().map(|r| r.concat()).collect();
                let coefficients: Vec<Vec<Vec<f64>>> = bernstein_to_power(&long)
                    .into_iter()
                    .map(|r| r.chunks(3).map(<[f64]>::to_vec).collect())
                    .collect();
                let power = PowerSurface::new(coefficients).expect("grid");
                let before: Vec<[f64; 3]> =
                    blossom::restrict_power_surface(&power, &rect, Method::TaylorShift)
                        .to_nested()
                        .iter()
                        .flatten()
                        .map(|p| std::array::from_fn(|x| p[x]))
                        .collect();
                paths.add(BEFORE, &want, &before);
            }
            let mut row = paths.into_row("bezier-tensor", (n, m), kind, PYRAMID);
            if !generated {
                row.errors.retain(|(name, _)| *name != GENERATED);
            }
            rows.push(row);
        }
    }
    rows
}

macro_rules! generated_triangles {
    ($($n:literal => $name:ident;)*) => {
        $(blossom::restriction!(name = $name, shape = bezier_triangle, degree = $n);)*
        /// The generated evaluator of a triangular patch of degree `n`, among those this sweep
        /// instantiates.
        fn generated_triangle(
            net: &[[f64; 3]],
            n: usize,
            corners: [[f64; 2]; 3],
        ) -> Option<Vec<[f64; 3]>> {
            match n {
                $($n => {
                    let ctrl: [[f64; 3]; ($n + 1) * ($n + 2) / 2] = std::array::from_fn(|i| net[i]);
                    Some($name(&ctrl, &corners).to_vec())
                })*
                _ => None,
            }
        }
    };
}

generated_triangles! {
    1 => bezier_triangle_1;
    2 => bezier_triangle_2;
    3 => bezier_triangle_3;
    4 => bezier_triangle_4;
    5 => bezier_triangle_5;
    6 => bezier_triangle_6;
}

/// A triangle of `kind`: each corner's (s, t) from intervals of that kind.
fn corners(rng: &mut Rng, kind: Kind) -> [[f64; 2]; 3] {
    std::array::from_fn(|_| {
        let (s, t) = rng.interval(kind);
        [s, t]
    })
}

/// Triangular patches of each degree in `degrees`.
pub fn bezier_triangles(degrees: &[usize], samples: usize, seed: u64) -> Vec<Row> {
    let mut rng = Rng(seed);
    let mut rows = Vec::new();
    for &n in degrees {
        for kind in Kind::ALL {
            let mut paths = Paths::new(&[PYRAMID, ENGINE, BATCH, GENERATED]);
            let mut generated = true;
            for _ in 0..samples {
                let tri = corners(&mut rng, kind);
                let len = (n + 1) * (n + 2) / 2;
                let net: Vec<[f64; 3]> = (0..len).map(|_| rng.point()).collect();
                let exact_patch =
                    BezierTriangle::new(n, exact_points::<Dyadic>(&net)).expect("net");
                let want = nearest(exact_patch.restrict(&tri.map(|c| c.map(exact))).points());
                paths.add(PYRAMID, &want, &reference::triangle(&net, n, tri));
                let patch = BezierTriangle::new(n, net.clone()).expect("net");
                paths.add(ENGINE, &want, patch.restrict(&tri).points());
                let batch = Batch::from_nets(
                    len,
                    3,
                    &[&net.iter().map(|p| p.to_vec()).collect::<Vec<_>>()],
                )
                .expect("one net");
                let map = RestrictionMap::triangle(n, tri).expect("finite");
                let mut out = Batch::zeros(len, 3, 1).expect("a small batch");
                batch.restrict_into(&map, &mut out).expect("fitting shapes");
                let lanes: Vec<[f64; 3]> = (0..len)
                    .map(|p| std::array::from_fn(|x| out.get(0, p, x)))
                    .collect();
                paths.add(BATCH, &want, &lanes);
                match generated_triangle(&net, n, tri) {
                    Some(g) => paths.add(GENERATED, &want, &g),
                    None => generated = false,
                }
            }
            let mut row = paths.into_row("bezier-triangle", (n, 0), kind, PYRAMID);
            if !generated {
                row.errors.retain(|(name, _)| *name != GENERATED);
            }
            rows.push(row);
        }
    }
    rows
}

/// Power-basis curves of each degree: [`Method::Bulk`] (the engine), the Taylor shift and the
/// pyramid against the closed form, the reference for power input.
pub fn power_curves(degrees: &[usize], samples: usize, seed: u64) -> Vec<Row> {
    let mut rng = Rng(seed);
    let methods = [
        Method::ClosedForm,
        Method::Bulk,
        Method::TaylorShift,
        Method::Pyramid,
    ];
    let mut rows = Vec::new();
    for &n in degrees {
        for kind in Kind::ALL {
            let mut paths = Paths::new(&methods.map(Method::name));
            for _ in 0..samples {
                let (a, b) = rng.interval(kind);
                let coefficients: Vec<[f64; 3]> = (0..=n).map(|_| rng.point()).collect();
                let exact_curve = PowerCurve::new(
                    exact_points::<Rational>(&coefficients)
                        .into_iter()
                        .map(|p| p.to_vec())
                        .collect(),
                )
                .expect("points");
                let (ea, eb) = (Rational::of(a), Rational::of(b));
                let want: Vec<[f64; 3]> =
                    restrict_power_curve(&exact_curve, &ea, &eb, Method::Bulk)
                        .control_points()
                        .iter()
                        .map(|p| std::array::from_fn(|x| p[x].nearest()))
                        .collect();
                let curve = PowerCurve::new(coefficients.iter().map(|p| p.to_vec()).collect())
                    .expect("points");
                for method in methods {
                    let got: Vec<[f64; 3]> = restrict_power_curve(&curve, &a, &b, method)
                        .control_points()
                        .iter()
                        .map(|p| std::array::from_fn(|x| p[x]))
                        .collect();
                    paths.add(method.name(), &want, &got);
                }
            }
            rows.push(paths.into_row("power-curve", (n, 0), kind, "closed-form"));
        }
    }
    rows
}

/// The rows as a Markdown table, one column per path.
pub fn markdown(rows: &[Row]) -> String {
    let Some(first) = rows.first() else {
        return String::new();
    };
    let mut out = format!(
        "| {} | degree | domain | {} |",
        first.shape, first.reference.0
    );
    let mut rule = String::from("|---|---|---|---|");
    let names: Vec<&str> = rows
        .iter()
        .flat_map(|r| r.errors.iter().map(|(n, _)| *n))
        .fold(Vec::new(), |mut v, n| {
            if !v.contains(&n) {
                v.push(n);
            }
            v
        });
    for n in &names {
        out.push_str(&format!(" {n} |"));
        rule.push_str("---|");
    }
    out.push('\n');
    out.push_str(&rule);
    out.push('\n');
    for r in rows {
        let degree = if r.shape == "bezier-tensor" {
            format!("({}, {})", r.degree.0, r.degree.1)
        } else {
            r.degree.0.to_string()
        };
        out.push_str(&format!(
            "| | {degree} | {} | {:.1e} |",
            r.kind.name(),
            r.reference.1
        ));
        for n in &names {
            match r.errors.iter().find(|(m, _)| m == n) {
                Some((_, e)) => out.push_str(&format!(" {e:.1e} |")),
                None => out.push_str(" - |"),
            }
        }
        out.push('\n');
    }
    out
}
