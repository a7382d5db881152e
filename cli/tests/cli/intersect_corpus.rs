//! `blossom intersect` against an independent exact truth: every case of
//! `tests/intersect_corpus/cases.json` (written by `tests/intersect_corpus/generate.py` with
//! sympy: resultants, exact factorisation and real-root isolation, see its README) is run
//! through the binary and compared field by field:
//! - the numbers of roots, points and overlaps, `identically_zero`, every multiplicity and
//!   tangent flag;
//! - every PARAM's `"value"` to the last bit and its `"exact"` string;
//! - every PARAM's `"polynomial"`: integer, square-free, divisible by the parameter's minimal
//!   polynomial (so it vanishes there), and its `"interval"`: it contains the parameter (decided
//!   exactly from the truth's isolating interval) and no other real root of the polynomial
//!   (Descartes' rule of signs on the interval, with bisection);
//! - every `"point"` coordinate within one ulp of the exact coordinate.
//!
//! Every mismatch is printed with its case's name; the test fails at the end with the count.
//! `INTERSECT_CORPUS_FILTER=text` runs only the cases whose name contains `text`.

use std::cmp::Ordering;
use std::path::PathBuf;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde_json::Value;

use crate::binary::run_binary;

/// The cases of the corpus.
fn corpus() -> Vec<Value> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/intersect_corpus/cases.json");
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("the corpus {} cannot be read: {e}", path.display()));
    let all: Value = serde_json::from_str(&text).expect("the corpus is JSON");
    let cases = all["cases"].as_array().expect("a list of cases").clone();
    assert!(!cases.is_empty(), "the corpus is empty");
    cases
}

/// The cases this version refuses instead of answering (issue 26 is open): each must be refused
/// with the library's "not decided exactly" error, never answered wrongly. A case that starts
/// to be answered must leave this list (the test then checks its answer like any other).
const REFUSED_FOR_NOW: [&str; 0] = [];

#[test]
fn intersect_corpus_every_case_exact() {
    let filter = std::env::var("INTERSECT_CORPUS_FILTER").unwrap_or_default();
    let cases: Vec<Value> = corpus()
        .into_iter()
        .filter(|c| {
            c["name"]
                .as_str()
                .is_some_and(|n| n.contains(filter.as_str()))
        })
        .collect();
    let mut mismatches = Vec::new();
    let mut failed = 0usize;
    for case in &cases {
        let name = case["name"].as_str().expect("a name");
        let mut found = Vec::new();
        if REFUSED_FOR_NOW.contains(&name) {
            check_refused(case, &mut found);
        } else {
            check_case(case, &mut found);
        }
        if !found.is_empty() {
            failed += 1;
        }
        mismatches.extend(found.into_iter().map(|m| format!("{name}: {m}")));
    }
    for m in &mismatches {
        eprintln!("{m}");
    }
    assert!(
        failed == 0,
        "{failed} of {} cases of tests/intersect_corpus/cases.json disagree with the exact truth ({} mismatches printed above)",
        cases.len(),
        mismatches.len()
    );
}

/// A case of [`REFUSED_FOR_NOW`]: exit 2 with an error that says the case is not decided.
fn check_refused(case: &Value, out: &mut Vec<String>) {
    let arithmetic = case["arithmetic"].as_str().expect("an arithmetic");
    let run = run_binary(
        &["intersect", "--arithmetic", arithmetic],
        case["job"].to_string().as_bytes(),
    );
    let undecided =
        run.stderr.contains("cannot decide exactly") || run.stderr.contains("not decided exactly");
    if run.code != 2 || !undecided {
        out.push(format!(
            "listed as refused for now, but exit {} ({}{}): take it off REFUSED_FOR_NOW",
            run.code,
            run.stderr.trim_end(),
            run.stdout.trim_end()
        ));
    }
}

/// Runs one case and appends every mismatch to `out`.
fn check_case(case: &Value, out: &mut Vec<String>) {
    let arithmetic = case["arithmetic"].as_str().expect("an arithmetic");
    let job = &case["job"];
    let expected = &case["expected"];
    let run = run_binary(
        &["intersect", "--arithmetic", arithmetic],
        job.to_string().as_bytes(),
    );
    if run.code != 0 {
        out.push(format!("exit {} ({})", run.code, run.stderr.trim_end()));
        return;
    }
    let got: Value = match serde_json::from_str(&run.stdout) {
        Ok(v) => v,
        Err(e) => {
            out.push(format!("the answer is not JSON ({e}): {}", run.stdout));
            return;
        }
    };
    let kind = job["kind"].as_str().expect("a kind");
    if got["kind"].as_str() != Some(kind) {
        out.push(format!("kind {}, expected {kind}", got["kind"]));
    }
    if kind == "roots" {
        check_roots(&got, expected, out);
    } else {
        check_points(&got, expected, out);
        check_overlaps(&got, expected, out);
    }
}

fn check_roots(got: &Value, exp: &Value, out: &mut Vec<String>) {
    if got["identically_zero"] != exp["identically_zero"] {
        out.push(format!(
            "identically_zero {}, expected {}",
            got["identically_zero"], exp["identically_zero"]
        ));
    }
    let Some(roots) = list(got, "roots", out) else {
        return;
    };
    let want = exp["roots"].as_array().expect("expected roots");
    if roots.len() != want.len() {
        out.push(format!(
            "{} roots {}, expected {} at {}",
            roots.len(),
            values(roots, &["t"]),
            want.len(),
            values(want, &["t"])
        ));
        return;
    }
    for (i, (g, w)) in roots.iter().zip(want).enumerate() {
        if g["multiplicity"].as_u64() != w["multiplicity"].as_u64() {
            out.push(format!(
                "roots[{i}].multiplicity {}, expected {}",
                g["multiplicity"], w["multiplicity"]
            ));
        }
        check_param(&g["t"], &w["t"], &format!("roots[{i}].t"), out);
    }
}

fn check_points(got: &Value, exp: &Value, out: &mut Vec<String>) {
    let Some(points) = list(got, "points", out) else {
        return;
    };
    let want = exp["points"].as_array().expect("expected points");
    if points.len() != want.len() {
        out.push(format!(
            "{} points {}, expected {} at {}",
            points.len(),
            values(points, &["s", "t"]),
            want.len(),
            values(want, &["s", "t"])
        ));
        return;
    }
    for (i, (g, w)) in points.iter().zip(want).enumerate() {
        check_param(&g["s"], &w["s"], &format!("points[{i}].s"), out);
        check_param(&g["t"], &w["t"], &format!("points[{i}].t"), out);
        if g["tangent"].as_bool() != w["tangent"].as_bool() {
            out.push(format!(
                "points[{i}].tangent {}, expected {}",
                g["tangent"], w["tangent"]
            ));
        }
        match g["point"].as_array() {
            Some(xy) if xy.len() == 2 => {
                for (k, (c, e)) in xy
                    .iter()
                    .zip(w["point"].as_array().expect("a point"))
                    .enumerate()
                {
                    check_coordinate(c, e, &format!("points[{i}].point[{k}]"), out);
                }
            }
            _ => out.push(format!(
                "points[{i}].point is not a 2-D point: {}",
                g["point"]
            )),
        }
    }
}

/// Overlaps are compared as a set (the spec does not order them): both lists sorted by
/// their ends' values.
fn check_overlaps(got: &Value, exp: &Value, out: &mut Vec<String>) {
    let Some(overlaps) = list(got, "overlaps", out) else {
        return;
    };
    let want = exp["overlaps"].as_array().expect("expected overlaps");
    if overlaps.len() != want.len() {
        out.push(format!(
            "{} overlaps, expected {}: {}",
            overlaps.len(),
            want.len(),
            ends(want)
        ));
        return;
    }
    let key = |o: &Value| -> Vec<f64> {
        ["s", "t"]
            .iter()
            .flat_map(|k| (0..2).map(move |j| (k, j)))
            .map(|(k, j)| o[*k][j]["value"].as_f64().unwrap_or(f64::NAN))
            .collect()
    };
    let mut sorted: Vec<&Value> = overlaps.iter().collect();
    sorted.sort_by(|a, b| key(a).partial_cmp(&key(b)).unwrap_or(Ordering::Equal));
    for (i, (g, w)) in sorted.into_iter().zip(want).enumerate() {
        for k in ["s", "t"] {
            for j in 0..2 {
                check_param(&g[k][j], &w[k][j], &format!("overlaps[{i}].{k}[{j}]"), out);
            }
        }
    }
}

/// The array under `field`, or a mismatch.
fn list<'a>(got: &'a Value, field: &str, out: &mut Vec<String>) -> Option<&'a Vec<Value>> {
    let found = got[field].as_array();
    if found.is_none() {
        out.push(format!("no list \"{field}\" in the answer {got}"));
    }
    found
}

/// The parameters' values of a list of points or roots, for a readable mismatch.
fn values(items: &[Value], keys: &[&str]) -> String {
    let shown: Vec<String> = items
        .iter()
        .map(|it| {
            let vs: Vec<String> = keys
                .iter()
                .map(|k| format!("{}", it[*k]["value"]))
                .collect();
            format!("({})", vs.join(", "))
        })
        .collect();
    format!("[{}]", shown.join(", "))
}

fn ends(overlaps: &[Value]) -> String {
    let shown: Vec<String> = overlaps
        .iter()
        .map(|o| {
            format!(
                "s [{}, {}] t [{}, {}]",
                o["s"][0]["value"], o["s"][1]["value"], o["t"][0]["value"], o["t"][1]["value"]
            )
        })
        .collect();
    shown.join("; ")
}

// ---------------------------------------------------------------------------------------------
// One PARAM against the truth.

/// The truth's parameter: its correctly rounded double, exact string, minimal polynomial m
/// (primitive, irreducible) and an interval [a, b] holding exactly one real root of m (a == b
/// for a rational parameter).
struct Truth {
    bits: u64,
    exact: Value,
    minpoly: Vec<BigInt>,
    a: BigRational,
    b: BigRational,
}

impl Truth {
    fn of(w: &Value) -> Truth {
        let ints = |v: &Value| -> Vec<BigInt> {
            v.as_array()
                .expect("a list")
                .iter()
                .map(|c| c.as_str().expect("a string").parse().expect("an integer"))
                .collect()
        };
        let enc = w["enclosure"].as_array().expect("an enclosure");
        Truth {
            bits: u64::from_str_radix(w["bits"].as_str().expect("bits"), 16).expect("hex bits"),
            exact: w["exact"].clone(),
            minpoly: ints(&w["minpoly"]),
            a: parse_exact(enc[0].as_str().expect("a string")).expect("an exact number"),
            b: parse_exact(enc[1].as_str().expect("a string")).expect("an exact number"),
        }
    }

    /// Whether the parameter x is >= lo (`upper == false`) or <= hi (`upper == true`),
    /// decided exactly: outside [a, b] by comparison, inside by the sign of m (the only root of
    /// m in [a, b] is x, and m changes sign there).
    fn on_side(&self, bound: &BigRational, upper: bool) -> bool {
        if self.a == self.b {
            return if upper {
                self.a <= *bound
            } else {
                self.a >= *bound
            };
        }
        if upper {
            if *bound >= self.b {
                return true;
            }
            if *bound <= self.a {
                return false;
            }
            // a < bound < b: x <= bound iff the root lies in (a, bound]
            let s = sign_at(&self.minpoly, bound);
            s == 0 || s != sign_at(&self.minpoly, &self.a)
        } else {
            if *bound <= self.a {
                return true;
            }
            if *bound >= self.b {
                return false;
            }
            let s = sign_at(&self.minpoly, bound);
            s == 0 || s != sign_at(&self.minpoly, &self.b)
        }
    }
}

fn check_param(g: &Value, w: &Value, at: &str, out: &mut Vec<String>) {
    let truth = Truth::of(w);
    if !g.is_object() {
        out.push(format!("{at} is not a PARAM object: {g}"));
        return;
    }
    match g["value"].as_f64() {
        Some(v) if v.to_bits() == truth.bits => {}
        _ => out.push(format!(
            "{at}.value {} (bits {}), expected {} (bits {:016x})",
            g["value"],
            g["value"]
                .as_f64()
                .map_or("none".into(), |v| format!("{:016x}", v.to_bits())),
            w["value"],
            truth.bits
        )),
    }
    if g["exact"] != truth.exact {
        out.push(format!(
            "{at}.exact {}, expected {}",
            g["exact"], truth.exact
        ));
    }
    let poly: Option<Vec<BigInt>> = g["polynomial"].as_array().and_then(|cs| {
        cs.iter()
            .map(|c| c.as_str().and_then(|s| s.parse::<BigInt>().ok()))
            .collect()
    });
    let Some(poly) = poly.map(trim) else {
        out.push(format!(
            "{at}.polynomial is not a list of integer strings: {}",
            g["polynomial"]
        ));
        return;
    };
    if poly.len() < 2 {
        out.push(format!("{at}.polynomial {:?} is constant", g["polynomial"]));
        return;
    }
    if !divides(&truth.minpoly, &poly) {
        out.push(format!(
            "{at}.polynomial does not vanish at the parameter: {}",
            g["polynomial"]
        ));
    }
    if !square_free(&poly) {
        out.push(format!(
            "{at}.polynomial is not square-free: {}",
            g["polynomial"]
        ));
    }
    let interval: Option<Vec<BigRational>> = g["interval"].as_array().and_then(|e| {
        if e.len() != 2 {
            return None;
        }
        e.iter().map(|c| c.as_str().and_then(parse_exact)).collect()
    });
    let Some(iv) = interval else {
        out.push(format!(
            "{at}.interval is not two exact number strings: {}",
            g["interval"]
        ));
        return;
    };
    let (lo, hi) = (&iv[0], &iv[1]);
    if lo > hi {
        out.push(format!("{at}.interval [{lo}, {hi}] has lo > hi"));
        return;
    }
    if lo == hi && truth.a != truth.b {
        out.push(format!(
            "{at}.interval [{lo}, {hi}] is a point but the parameter is irrational"
        ));
    }
    if !(truth.on_side(lo, false) && truth.on_side(hi, true)) {
        out.push(format!(
            "{at}.interval [{lo}, {hi}] does not contain the parameter"
        ));
    }
    match roots_in(&poly, lo, hi) {
        Some(1) => {}
        Some(k) => out.push(format!(
            "{at}.interval [{lo}, {hi}] holds {k} real roots of the polynomial, not one"
        )),
        None => out.push(format!("{at}.interval [{lo}, {hi}]: roots not separated")),
    }
}

/// A coordinate of a point: a JSON number within one ulp of the exact value (its correctly
/// rounded double or a neighbour), or an exact string equal to it.
fn check_coordinate(g: &Value, w: &Value, at: &str, out: &mut Vec<String>) {
    let bits = u64::from_str_radix(w["bits"].as_str().expect("bits"), 16).expect("hex");
    let want = f64::from_bits(bits);
    if let Some(s) = g.as_str() {
        let Some(x) = parse_exact(s) else {
            out.push(format!("{at} {g} is not an exact number"));
            return;
        };
        let ok = match w["exact"].as_str() {
            Some(e) => parse_exact(e) == Some(x.clone()),
            None => {
                let lo = BigRational::from_float(next_down(want)).expect("finite");
                let hi = BigRational::from_float(next_up(want)).expect("finite");
                lo < x && x < hi
            }
        };
        if !ok {
            out.push(format!("{at} {s}, expected {}", w["value"]));
        }
        return;
    }
    match g.as_f64() {
        Some(v) if v == want || v == next_up(want) || v == next_down(want) => {}
        _ => out.push(format!("{at} {g}, expected {} within one ulp", w["value"])),
    }
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1);
    }
    if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// An exact number string of the spec's output form: `"p/q"` in lowest terms with q > 1, or
/// `"p"`; anything else is `None`.
fn parse_exact(s: &str) -> Option<BigRational> {
    let (n, d) = match s.split_once('/') {
        Some((n, d)) => (n.parse::<BigInt>().ok()?, d.parse::<BigInt>().ok()?),
        None => (s.parse::<BigInt>().ok()?, BigInt::one()),
    };
    if !d.is_positive() {
        return None;
    }
    let x = BigRational::new(n, d);
    let canonical = if x.denom().is_one() {
        x.numer().to_string()
    } else {
        format!("{}/{}", x.numer(), x.denom())
    };
    (canonical == s).then_some(x)
}

// ---------------------------------------------------------------------------------------------
// Integer polynomials (ascending coefficients, no trailing zeros).

fn trim(mut p: Vec<BigInt>) -> Vec<BigInt> {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
    p
}

fn primitive(p: Vec<BigInt>) -> Vec<BigInt> {
    let g = p.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
    if g.is_zero() || g.is_one() {
        return p;
    }
    p.into_iter().map(|c| c / &g).collect()
}

/// The sign of p at x = n/d (d > 0): the sign of sum p_i n^i d^(deg - i).
fn sign_at(p: &[BigInt], x: &BigRational) -> i32 {
    let (n, d) = (x.numer(), x.denom());
    let mut acc = p.last().cloned().unwrap_or_default();
    let mut dp = d.clone();
    for c in p.iter().rev().skip(1) {
        acc = acc * n + c * &dp;
        dp *= d;
    }
    match acc.sign() {
        num_bigint::Sign::Minus => -1,
        num_bigint::Sign::NoSign => 0,
        num_bigint::Sign::Plus => 1,
    }
}

/// The pseudo-remainder of a by b (b nonzero), made primitive: lc(b)^k a = q b + r.
fn prem(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let lc = b.last().expect("a nonzero divisor");
    let mut r = a.to_vec();
    while r.len() >= b.len() {
        let c = r.last().expect("nonempty").clone();
        let shift = r.len() - b.len();
        for x in r.iter_mut() {
            *x *= lc;
        }
        for (i, bi) in b.iter().enumerate() {
            r[i + shift] -= &c * bi;
        }
        r = primitive(trim(r));
    }
    r
}

/// Whether m divides p over Q.
fn divides(m: &[BigInt], p: &[BigInt]) -> bool {
    prem(p, m).is_empty()
}

fn derivative(p: &[BigInt]) -> Vec<BigInt> {
    trim(
        p.iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * BigInt::from(i))
            .collect(),
    )
}

/// Whether p has no repeated factor: gcd(p, p') constant, proven modulo a prime not dividing
/// the leading coefficient (a repeated factor of p over Q stays one modulo such a prime), and
/// over Q by a primitive remainder sequence when every prime tried leaves a common factor.
fn square_free(p: &[BigInt]) -> bool {
    let dp = derivative(p);
    for q in [2_147_483_647u64, 1_000_000_007, 998_244_353] {
        let red = |v: &[BigInt]| -> Vec<u64> {
            let qb = BigInt::from(q);
            v.iter()
                .map(|c| c.mod_floor(&qb).to_u64().expect("below q"))
                .collect()
        };
        let (a, b) = (red(p), red(&dp));
        if a.last() == Some(&0) {
            continue;
        }
        if gcd_degree_mod(a, b, q) == 0 {
            return true;
        }
    }
    let (mut a, mut b) = (primitive(p.to_vec()), primitive(dp));
    while !b.is_empty() {
        let r = prem(&a, &b);
        a = b;
        b = r;
    }
    a.len() == 1
}

/// The degree of gcd(a, b) over the integers modulo the prime q.
fn gcd_degree_mod(mut a: Vec<u64>, mut b: Vec<u64>, q: u64) -> usize {
    let strip = |v: &mut Vec<u64>| {
        while v.last() == Some(&0) {
            v.pop();
        }
    };
    let pow = |mut x: u64, mut e: u64| {
        let mut r = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                r = (r as u128 * x as u128 % q as u128) as u64;
            }
            x = (x as u128 * x as u128 % q as u128) as u64;
            e >>= 1;
        }
        r
    };
    strip(&mut a);
    strip(&mut b);
    while !b.is_empty() {
        let inv = pow(*b.last().expect("nonempty"), q - 2);
        while a.len() >= b.len() {
            let f = (*a.last().expect("nonempty") as u128 * inv as u128 % q as u128) as u64;
            let shift = a.len() - b.len();
            for (i, bi) in b.iter().enumerate() {
                let sub = (f as u128 * *bi as u128 % q as u128) as u64;
                a[i + shift] = (a[i + shift] + q - sub) % q;
            }
            strip(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// The number of distinct real roots of the square-free p in [lo, hi], or `None` when
/// bisection does not separate them within its depth.
fn roots_in(p: &[BigInt], lo: &BigRational, hi: &BigRational) -> Option<usize> {
    let at_lo = usize::from(sign_at(p, lo) == 0);
    if lo == hi {
        return Some(at_lo);
    }
    let at_hi = usize::from(sign_at(p, hi) == 0);
    Some(at_lo + at_hi + roots_open(p, lo, hi, 200)?)
}

/// The number of real roots of the square-free p in the open interval (a, b): Descartes' rule
/// of signs on (1 + y)^deg p((a + b y) / (1 + y)) (0 or 1 variations decide), else bisection.
fn roots_open(p: &[BigInt], a: &BigRational, b: &BigRational, depth: u32) -> Option<usize> {
    match variations(p, a, b) {
        0 => return Some(0),
        1 => return Some(1),
        _ if depth == 0 => return None,
        _ => {}
    }
    let mid = (a + b) / BigInt::from(2);
    let at_mid = usize::from(sign_at(p, &mid) == 0);
    Some(at_mid + roots_open(p, a, &mid, depth - 1)? + roots_open(p, &mid, b, depth - 1)?)
}

/// Sign variations of the coefficients of D^deg (1 + y)^deg p((a + b y) / (1 + y)), with a = A/D,
/// b = B/D: the homogeneous Horner scheme sum p_i N^i M^(deg - i), N = A + B y, M = D (1 + y).
fn variations(p: &[BigInt], a: &BigRational, b: &BigRational) -> usize {
    let d = a.denom().lcm(b.denom());
    let big_a = a.numer() * (&d / a.denom());
    let big_b = b.numer() * (&d / b.denom());
    let mul_linear = |q: &[BigInt], c0: &BigInt, c1: &BigInt| -> Vec<BigInt> {
        let mut r = vec![BigInt::zero(); q.len() + 1];
        for (i, x) in q.iter().enumerate() {
            r[i] += x * c0;
            r[i + 1] += x * c1;
        }
        r
    };
    let mut acc = vec![p.last().expect("nonzero").clone()];
    let mut m_pow = vec![BigInt::one()];
    for c in p.iter().rev().skip(1) {
        m_pow = mul_linear(&m_pow, &d, &d);
        acc = mul_linear(&acc, &big_a, &big_b);
        for (x, m) in acc.iter_mut().zip(&m_pow) {
            *x += c * m;
        }
    }
    let signs: Vec<bool> = acc
        .iter()
        .filter(|c| !c.is_zero())
        .map(Signed::is_positive)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}
