//! `"kind": "rational-tensor"`: x(u, v) = (sum p_ij u^i v^j) / (sum w_ij u^i v^j) on
//! [a, b] x [c, d] as a rational tensor patch: the blossoms of the denominator (the weights)
//! and of the numerator divided by them, computed exactly and rounded once; a zero weight is
//! an error.

use super::{check_rounded_weights, exact, exact_points, rounded, Number};
use crate::jobs::cost::tensor_operations;
use crate::jobs::kind::prelude::*;
use crate::jobs::read::degree;
use blossom::RationalSurface;

/// The job.
#[derive(Debug, Deserialize)]
#[serde(bound = "T: Reading")]
pub struct RationalTensor<T> {
    /// `numerator[i][j]` = p_ij.
    numerator: Rows<T>,
    /// `denominator[i][j]` = w_ij.
    denominator: NumberRows<T>,
    /// [a, b, c, d].
    rectangle: Numbers<T, 4>,
    /// [n, m], by default the grids' sizes.
    degree: Option<DegreePair>,
}

/// `"degree": [n, m]`.
#[derive(Debug)]
struct DegreePair(usize, usize);

impl<'de> Deserialize<'de> for DegreePair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let pair = leaf(d, |v| {
            items(v, "an array of 2 degrees", exactly(2, "degrees"), degree)
        })?;
        Ok(DegreePair(pair[0], pair[1]))
    }
}

/// The answer.
#[derive(Serialize)]
#[serde(bound = "T: Write")]
struct Answer<T: Write> {
    degree: [usize; 2],
    control_points: Out<Vec<Vec<Point<T>>>>,
    weights: Out<Vec<Vec<T>>>,
}

/// The exact grids of a rational surface: the numerator's points and the denominator's numbers.
pub type Grids = (Vec<Vec<Point<Rational>>>, Vec<Vec<Rational>>);

/// The numerator's and denominator's grids of a rational surface, exactly, padded with zeros
/// to one shape (the larger size in each variable), after checking their shapes.
pub fn grids<T: Reading>(
    numerator: &[Vec<Point<T>>],
    denominator: &[Vec<T>],
) -> Result<Grids, Error> {
    rectangular(numerator, "numerator", "point")?;
    rectangular(denominator, "denominator", "number")?;
    let rows = numerator.len().max(denominator.len());
    let cols = numerator[0].len().max(denominator[0].len());
    if rows > MAX_DEGREE + 1 || cols > MAX_DEGREE + 1 {
        return Err(Error::new(
            "numerator",
            format!(
                "expected a degree of at most {MAX_DEGREE} in each variable (at most {} rows and \
                 columns)",
                MAX_DEGREE + 1
            ),
        ));
    }
    /// `grid` with `zero`s appended to `rows` rows of `cols` entries.
    fn padded<X: Clone>(grid: Vec<Vec<X>>, (rows, cols): (usize, usize), zero: X) -> Vec<Vec<X>> {
        let mut grid: Vec<Vec<X>> = grid;
        grid.iter_mut()
            .for_each(|row| row.resize(cols, zero.clone()));
        grid.resize(rows, vec![zero; cols]);
        grid
    }
    let zero = vec![Rational::default(); numerator[0][0].len()];
    let p = padded(
        numerator.iter().map(|r| exact_points(r)).collect(),
        (rows, cols),
        zero,
    );
    let w = padded(
        denominator.iter().map(|r| exact(r)).collect(),
        (rows, cols),
        Rational::default(),
    );
    Ok((p, w))
}

/// The estimate of a rational surface of degree `degree` in `ops` operations, exact under both
/// arithmetics, on the domain in the field `domain`.
pub fn estimate(
    env: &Env,
    domain: &str,
    degree: f64,
    ops: f64,
    factor: [f64; 2],
) -> Option<(f64, &'static str)> {
    let env = env.deciding_exactly();
    let [nu, de, dom] = ["numerator", "denominator", domain].map(|f| env.numbers(f));
    let bits = grown_bits(nu.max_bits.max(de.max_bits), dom.max_bits, degree);
    let work = ops * operation(true, bits) * env.factor(factor);
    Some((work + nu.and(de).and(dom).reading, "numerator"))
}

/// The grids' sizes: the rows, the columns, and the dimension of the homogeneous points.
pub fn sizes<T>(numerator: &Rows<T>, denominator: &NumberRows<T>) -> (f64, f64, f64) {
    let (rows, columns, d) = numerator.sizes();
    let w = &denominator.0;
    let w_columns = w.first().map_or(0, Vec::len) as f64;
    (rows.max(w.len() as f64), columns.max(w_columns), d + 1.0)
}

impl<T: Reading> Estimate for RationalTensor<T> {
    fn estimate(&self, env: &Env) -> Option<(f64, &'static str)> {
        let (rows, columns, d) = sizes(&self.numerator, &self.denominator);
        let (n, m) = self
            .degree
            .as_ref()
            .map_or((0.0, 0.0), |p| (p.0 as f64, p.1 as f64));
        let (n, m) = (n.max(rows - 1.0).max(0.0), m.max(columns - 1.0).max(0.0));
        let ops = tensor_operations(MethodChoice::Library(Method::Polarisation), n, m, d);
        estimate(env, "rectangle", n + m, ops, [5.8, 5.6])
    }
}

impl<T: Number> Kind for RationalTensor<Written<T>> {
    fn solve(self, _: &Context) -> Result<Value, Error> {
        let (p, w) = grids(&self.numerator.0, &self.denominator.0)?;
        let rect = self.rectangle.0.map(|x| x.0);
        let surface = RationalSurface::new(&p, &w)?;
        let degree = self.degree.map_or(surface.degree(), |d| (d.0, d.1));
        let patch = surface.tensor(&rect, Some(degree))?;
        let weights: Vec<Vec<T>> = patch.weight_rows().map(|row| rounded(row)).collect();
        check_rounded_weights(weights.iter().enumerate().flat_map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(move |(j, w)| (format!("weights[{i}][{j}]"), w))
        }))?;
        write(&Answer {
            degree: [degree.0, degree.1],
            control_points: Out(patch
                .rows()
                .map(|row| row.iter().map(|p| rounded(p)).collect())
                .collect()),
            weights: Out(weights),
        })
    }
}
