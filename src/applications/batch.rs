//! Many Bézier curves or patches restricted to one shared domain.
//!
//! For a fixed domain the restriction is one fixed linear map on control points. For a curve
//! on [a, b], q_j = sum_i M_ji b_i, where M_ji = B_i^n[a^(n-j), b^j] is the blossom of the
//! Bernstein polynomial B_i^n. Tensor and triangular patches work the same way, with the
//! blossoms of their own bases. The map is built once, *exactly*:
//!
//! 1. every finite f64 is a dyadic rational, so the domain is read exactly;
//! 2. the restriction of the identity net (control point i = the unit vector e_i) is computed
//!    in rational arithmetic by [`crate::subdivide`], and its coordinates are the entries of
//!    M;
//! 3. each entry is rounded once to the nearest f64.
//!
//! Applying M costs one multiply-add per entry, per coordinate and per object. That is all
//! the floating-point work, and it is memory-bound for cubics.
//!
//! # Layout
//!
//! A [`Batch`] stores its objects as a structure of arrays in blocks of [`BATCH_LANES`] objects
//! ("AoSoA"). Within a block, coordinate x of control point p of the objects in the block is
//! one contiguous run of `BATCH_LANES` numbers, at `block * block_len + (p * dim + x) * BATCH_LANES`.
//! Applying M to a block is a sequence of multiply-adds over contiguous runs, which the
//! compiler vectorises. A block of a cubic 3-D curve batch (12 runs in, 12 out, 48 KiB each)
//! stays in the L2 cache while it is worked on (`BENCHMARKS.md` has the measured choice of the
//! block size). Blocks are
//! independent, so with the `rayon` feature `Batch::par_restrict_into` spreads them over
//! threads. The last block is padded with zeros.

use crate::error::{Error, ErrorKind, Result};
use crate::shape::bezier::{BezierCurve, TensorPatch, TriangularPatch};
use crate::shape::simplex::triangle_len;
use crate::shape::subdivide::{
    restrict_bezier_curve, restrict_bezier_tensor, restrict_bezier_triangle_affine,
};
use crate::Rational;
use num_traits::{One, Zero};

/// Objects per block of a [`Batch`] (measured: see the module docs).
pub const BATCH_LANES: usize = 512;

/// The f64 value `x` as an exact rational, or an error naming `field` when it is not finite.
fn exact(x: f64, field: &str) -> Result<Rational> {
    Rational::from_float(x).ok_or_else(|| {
        Error::of(
            ErrorKind::NotFinite,
            field,
            format!("expected a finite number, found {x}"),
        )
    })
}

/// The unit vector e_i of dimension `len`, exactly.
fn unit(i: usize, len: usize) -> Vec<Rational> {
    (0..len)
        .map(|k| {
            if k == i {
                Rational::one()
            } else {
                Rational::zero()
            }
        })
        .collect()
}

/// The restriction of every object of a batch to one domain, as a matrix
/// `entries[out * inputs + in]` rounded once from the exact one.
#[derive(Clone, Debug, PartialEq)]
pub struct RestrictionMap {
    inputs: usize,
    outputs: usize,
    entries: Vec<f64>,
}

impl RestrictionMap {
    /// Rounds the exact restrictions of the unit nets: `points[j][i]` = M_ji.
    fn from_exact(points: &[Vec<Rational>]) -> Self {
        let outputs = points.len();
        let inputs = points[0].len();
        let entries = points
            .iter()
            .flat_map(|p| p.iter().map(crate::num::ring::rational_to_f64))
            .collect();
        RestrictionMap {
            inputs,
            outputs,
            entries,
        }
    }

    /// The map of Bézier curves of degree `degree` over [0, 1] restricted to [a, b].
    pub fn curve(degree: usize, a: f64, b: f64) -> Result<Self> {
        let (a, b) = (exact(a, "a")?, exact(b, "b")?);
        let len = degree + 1;
        let identity = BezierCurve::new((0..len).map(|i| unit(i, len)).collect())?;
        Ok(Self::from_exact(
            restrict_bezier_curve(&identity, &a, &b).control_points(),
        ))
    }

    /// The map of tensor patches of bidegree `degree` over [0, 1]^2 restricted to
    /// `rect = [a, b, c, d]`; control points are numbered row by row, `p = nu * (m + 1) + mu`.
    pub fn tensor(degree: (usize, usize), rect: [f64; 4]) -> Result<Self> {
        let rect = [
            exact(rect[0], "rect[0]")?,
            exact(rect[1], "rect[1]")?,
            exact(rect[2], "rect[2]")?,
            exact(rect[3], "rect[3]")?,
        ];
        let (rows, cols) = (degree.0 + 1, degree.1 + 1);
        let len = rows * cols;
        let identity = TensorPatch::new(
            (0..rows)
                .map(|r| (0..cols).map(|c| unit(r * cols + c, len)).collect())
                .collect(),
        )?;
        let net = restrict_bezier_tensor(&identity, &rect);
        let points: Vec<Vec<Rational>> = net.control_points().iter().flatten().cloned().collect();
        Ok(Self::from_exact(&points))
    }

    /// The map of triangular patches of degree `degree` restricted to the sub-triangle whose
    /// corners have the first two barycentric coordinates `corners` (the third is 1 minus
    /// their sum); control points in the order of [`TriangularPatch`].
    pub fn triangle(degree: usize, corners: [[f64; 2]; 3]) -> Result<Self> {
        let mut exact_corners: [[Rational; 2]; 3] = Default::default();
        for (k, corner) in corners.iter().enumerate() {
            for (l, &x) in corner.iter().enumerate() {
                exact_corners[k][l] = exact(x, &format!("corners[{k}][{l}]"))?;
            }
        }
        let len = triangle_len(degree);
        let identity = TriangularPatch::new(degree, (0..len).map(|i| unit(i, len)).collect())?;
        let net = restrict_bezier_triangle_affine(&identity, &exact_corners);
        Ok(Self::from_exact(net.control_points()))
    }

    /// Control points per object taken in.
    pub fn inputs(&self) -> usize {
        self.inputs
    }

    /// Control points per object given out.
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// The entry M_(out, in).
    pub fn entry(&self, out: usize, input: usize) -> f64 {
        self.entries[out * self.inputs + input]
    }

    /// Applies the map to one block: `output` and `input` are blocks of `dim`-dimensional
    /// objects in the layout of [`Batch`]. Each output run is written in one pass per group of
    /// up to four inputs (o = w0 i0 + w1 i1 + w2 i2 + w3 i3, then o += ... for the next
    /// group), so a cubic's output run is loaded and stored once.
    fn apply_block(&self, dim: usize, input: &[f64], output: &mut [f64]) {
        let run = |i: usize, x: usize| -> &[f64; BATCH_LANES] {
            input[(i * dim + x) * BATCH_LANES..][..BATCH_LANES]
                .try_into()
                .expect("a run of BATCH_LANES numbers")
        };
        for j in 0..self.outputs {
            let row = &self.entries[j * self.inputs..][..self.inputs];
            for x in 0..dim {
                let out: &mut [f64; BATCH_LANES] = (&mut output[(j * dim + x) * BATCH_LANES..]
                    [..BATCH_LANES])
                    .try_into()
                    .expect("a run of BATCH_LANES numbers");
                for (g, weights) in row.chunks(4).enumerate() {
                    let last = weights.len() - 1;
                    let runs: [&[f64; BATCH_LANES]; 4] =
                        std::array::from_fn(|k| run(4 * g + k.min(last), x));
                    let runs = &runs[..weights.len()];
                    if g == 0 {
                        combine::<false>(out, weights, runs);
                    } else {
                        combine::<true>(out, weights, runs);
                    }
                }
            }
        }
    }
}

/// `out = sum_k weights[k] runs[k]` (or `out +=` when `ACCUMULATE`), for 1 to 4 runs, lane
/// by lane in straight loops that the compiler vectorises.
fn combine<const ACCUMULATE: bool>(
    out: &mut [f64; BATCH_LANES],
    weights: &[f64],
    runs: &[&[f64; BATCH_LANES]],
) {
    let put = |o: &mut f64, v: f64| *o = if ACCUMULATE { *o + v } else { v };
    match (weights, runs) {
        (&[w0, w1, w2, w3], &[r0, r1, r2, r3]) => {
            for ((((o, a), b), c), d) in out.iter_mut().zip(r0).zip(r1).zip(r2).zip(r3) {
                put(o, w0 * a + w1 * b + (w2 * c + w3 * d));
            }
        }
        (&[w0, w1, w2], &[r0, r1, r2]) => {
            for (((o, a), b), c) in out.iter_mut().zip(r0).zip(r1).zip(r2) {
                put(o, w0 * a + w1 * b + w2 * c);
            }
        }
        (&[w0, w1], &[r0, r1]) => {
            for ((o, a), b) in out.iter_mut().zip(r0).zip(r1) {
                put(o, w0 * a + w1 * b);
            }
        }
        (&[w0], &[r0]) => {
            for (o, a) in out.iter_mut().zip(r0) {
                put(o, w0 * a);
            }
        }
        _ => unreachable!("one run per weight, 1 to 4 of them"),
    }
}

/// `len` objects (curves or patches) of `points` control points of dimension `dim`, in a
/// blocked structure-of-arrays layout ("AoSoA"): blocks of [`BATCH_LANES`] objects, and within
/// a block coordinate x of control point p of every object is one contiguous run of
/// `BATCH_LANES` numbers, at `block * block_len + (p * dim + x) * BATCH_LANES`; the last block
/// is padded with zeros. Applying a [`RestrictionMap`] is then a sequence of multiply-adds over
/// contiguous runs, which the compiler vectorises.
#[derive(Clone, Debug, PartialEq)]
pub struct Batch {
    points: usize,
    dim: usize,
    len: usize,
    data: Vec<f64>,
}

impl Batch {
    /// `len` objects with every coordinate zero.
    pub fn zeros(points: usize, dim: usize, len: usize) -> Self {
        let blocks = len.div_ceil(BATCH_LANES);
        Batch {
            points,
            dim,
            len,
            data: vec![0.0; blocks * points * dim * BATCH_LANES],
        }
    }

    /// The batch of `nets`, each a list of `points` control points of dimension `dim`
    /// (a curve's polygon, a tensor net row by row, a triangular net in its order).
    ///
    /// # Errors
    /// `nets[k]` when net k has another number of points, `nets[k][p]` when a point has
    /// another dimension.
    pub fn from_nets(points: usize, dim: usize, nets: &[&[Vec<f64>]]) -> Result<Self> {
        let mut batch = Batch::zeros(points, dim, nets.len());
        for (k, net) in nets.iter().enumerate() {
            if net.len() != points {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("nets[{k}]"),
                    format!("expected {points} control points, found {}", net.len()),
                ));
            }
            for (p, point) in net.iter().enumerate() {
                if point.len() != dim {
                    return Err(Error::of(
                        ErrorKind::Dimension,
                        format!("nets[{k}][{p}]"),
                        format!("expected {dim} coordinates, found {}", point.len()),
                    ));
                }
                for (x, &value) in point.iter().enumerate() {
                    batch.set(k, p, x, value);
                }
            }
        }
        Ok(batch)
    }

    /// The batch of Bézier curves `curves`, all of one degree and dimension.
    ///
    /// # Errors
    /// `curves` when it is empty; `curves[k]` when curve k differs from the first.
    pub fn from_curves(curves: &[BezierCurve<f64>]) -> Result<Self> {
        let first = curves
            .first()
            .ok_or_else(|| Error::of(ErrorKind::Empty, "curves", "expected at least one curve"))?;
        let nets: Vec<&[Vec<f64>]> = curves.iter().map(|c| c.control_points()).collect();
        Batch::from_nets(first.degree() + 1, first.control_points()[0].len(), &nets)
            .map_err(|e| Error::of(e.kind, e.field.replacen("nets", "curves", 1), e.message))
    }

    fn index(&self, k: usize, p: usize, x: usize) -> usize {
        let block = self.points * self.dim * BATCH_LANES;
        (k / BATCH_LANES) * block + (p * self.dim + x) * BATCH_LANES + k % BATCH_LANES
    }

    /// Coordinate `x` of control point `p` of object `k`.
    ///
    /// # Panics
    /// When an index is out of range, as slice indexing does.
    pub fn get(&self, k: usize, p: usize, x: usize) -> f64 {
        assert!(
            k < self.len && p < self.points && x < self.dim,
            "index out of range"
        );
        self.data[self.index(k, p, x)]
    }

    /// Sets coordinate `x` of control point `p` of object `k`.
    ///
    /// # Panics
    /// When an index is out of range, as slice indexing does.
    pub fn set(&mut self, k: usize, p: usize, x: usize, value: f64) {
        assert!(
            k < self.len && p < self.points && x < self.dim,
            "index out of range"
        );
        let i = self.index(k, p, x);
        self.data[i] = value;
    }

    /// The control points of object `k`.
    pub fn net(&self, k: usize) -> Vec<Vec<f64>> {
        (0..self.points)
            .map(|p| (0..self.dim).map(|x| self.get(k, p, x)).collect())
            .collect()
    }

    /// Number of objects.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the batch holds no object.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Control points per object.
    pub fn points(&self) -> usize {
        self.points
    }

    /// Coordinates per point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The storage, blocks of [`BATCH_LANES`] objects (for copying or I/O).
    pub fn as_slice(&self) -> &[f64] {
        &self.data
    }

    /// The storage, mutable.
    pub fn as_mut_slice(&mut self) -> &mut [f64] {
        &mut self.data
    }

    fn check(&self, map: &RestrictionMap, out: &Batch) -> Result<()> {
        if map.inputs != self.points {
            return Err(Error::of(
                ErrorKind::Shape,
                "map",
                format!(
                    "takes objects of {} control points, the batch has {}",
                    map.inputs, self.points
                ),
            ));
        }
        if out.points != map.outputs || out.dim != self.dim || out.len != self.len {
            return Err(Error::of(ErrorKind::Dimension,
                "out",
                format!(
                    "expected {} objects of {} points of dimension {}, found {} of {} of dimension {}",
                    self.len, map.outputs, self.dim, out.len, out.points, out.dim
                ),
            ));
        }
        Ok(())
    }

    fn block_lens(&self, out: &Batch) -> (usize, usize) {
        (
            self.points * self.dim * BATCH_LANES,
            out.points * out.dim * BATCH_LANES,
        )
    }

    /// Writes the restriction of every object by `map` into `out`, which must hold as many
    /// objects of `map.outputs()` points of the same dimension (see [`Batch::zeros`]). No
    /// allocation.
    ///
    /// # Errors
    /// `map` or `out` when their shapes do not fit this batch.
    pub fn restrict_into(&self, map: &RestrictionMap, out: &mut Batch) -> Result<()> {
        self.check(map, out)?;
        let (bin, bout) = self.block_lens(out);
        if bin == 0 || bout == 0 {
            return Ok(());
        }
        for (input, output) in self.data.chunks(bin).zip(out.data.chunks_mut(bout)) {
            map.apply_block(self.dim, input, output);
        }
        Ok(())
    }

    /// [`Batch::restrict_into`] with the blocks spread over the threads of the current rayon
    /// pool. The answer is bit for bit that of the serial version.
    ///
    /// # Errors
    /// As [`Batch::restrict_into`].
    #[cfg(feature = "rayon")]
    pub fn par_restrict_into(&self, map: &RestrictionMap, out: &mut Batch) -> Result<()> {
        use rayon::prelude::*;
        self.check(map, out)?;
        let (bin, bout) = self.block_lens(out);
        if bin == 0 || bout == 0 {
            return Ok(());
        }
        self.data
            .par_chunks(bin)
            .zip(out.data.par_chunks_mut(bout))
            .for_each(|(input, output)| map.apply_block(self.dim, input, output));
        Ok(())
    }
}
