//! Many Bézier curves or patches restricted to one shared domain.
//!
//! # Layout
//!
//! A [`Batch`] stores its objects as a structure of arrays in blocks of [`BATCH_LANES`] objects
//! ("AoSoA"). Within a block, coordinate x of control point p of the objects in the block is
//! one contiguous run of `BATCH_LANES` numbers, at `block * block_len + (p * dim + x) * BATCH_LANES`.
//!
//! # Restriction
//!
//! Point p of a block, all its coordinates for all its objects, is one contiguous run of
//! `dim * BATCH_LANES` numbers. A block is therefore *one* Bézier object whose points have
//! `dim * BATCH_LANES` coordinates, and the restriction engine ([`crate::engine::curve_net`],
//! [`crate::engine::tensor_net`], [`crate::engine::triangle_net`]) runs on it unchanged: every de Casteljau
//! step is one straight loop over `dim * BATCH_LANES` numbers, which the compiler vectorises,
//! and every object gets exactly the answer (bit for bit) of the engine run on it alone: the
//! accuracy of de Casteljau, not that of a precomputed matrix. A block of a cubic 3-D curve
//! batch (48 KiB in, 48 KiB out, 36 KiB of scratch) stays in the L2 cache while it is worked on
//! (`BENCHMARKS.md` has the measured choice of the block size). Blocks are independent, so
//! with the `rayon` feature `Batch::par_restrict_into` spreads them over threads. The last
//! block is padded with zeros.

use crate::error::{Error, ErrorKind, Result};
use crate::num::limits::{check_entries, checked_product};
use crate::num::linalg::check_finite;
use crate::shape::bezier::BezierCurve;
use crate::shape::flat::curve_subsegment_fixed;
use crate::shape::halving::{
    checked_curve_scratch_len, checked_tensor_scratch_len, checked_triangle_scratch_len,
};
use crate::shape::halving::{
    curve_net, tensor_net, triangle_net, BernsteinPairStep, BernsteinStep,
};
use crate::shape::simplex::checked_triangle_len;

/// What the degree of a [`RestrictionMap`] counts, for its errors.
const POINTS: &str = "the number of control points";

/// Objects per block of a [`Batch`]: 512, chosen by measurement (`BENCHMARKS.md`) so that a
/// block of cubic 3-D curves (48 KiB in, 48 KiB out, 36 KiB of the engine's scratch) stays in
/// the L2 cache while it is restricted.
pub const BATCH_LANES: usize = 512;

/// Objects per tile of [`pack_block`] and [`unpack_block`]: 8 doubles are one cache line of
/// a row of the block.
const TILE: usize = 8;

/// Writes up to [`BATCH_LANES`] objects into one block of the [`Batch`] layout: coordinate `i`
/// (point `i / D`, axis `i % D`) of object `j` at `i * BATCH_LANES + j`; lanes past the last
/// object are set to zero. A tiled transpose: [`TILE`] objects at a time (a few cache lines,
/// read once), each of their coordinates written as one run of [`TILE`] numbers (a whole
/// cache line of a row), so that every line is read and written once.
fn pack_block<const K: usize, const D: usize>(objects: &[[[f64; D]; K]], block: &mut [f64]) {
    let (tiles, rest) = objects.as_chunks::<TILE>();
    for (t, tile) in tiles.iter().enumerate() {
        for (i, chunk) in block.chunks_exact_mut(BATCH_LANES).enumerate() {
            let run = &mut chunk[t * TILE..(t + 1) * TILE];
            for (x, object) in run.iter_mut().zip(tile) {
                *x = object.as_flattened()[i];
            }
        }
    }
    let done = tiles.len() * TILE;
    for row in block.chunks_exact_mut(BATCH_LANES) {
        row[done + rest.len()..].fill(0.0);
    }
    for (i, row) in block.chunks_exact_mut(BATCH_LANES).enumerate() {
        for (x, object) in row[done..].iter_mut().zip(rest) {
            *x = object.as_flattened()[i];
        }
    }
}

/// The inverse of [`pack_block`]: the objects of one block, as many as `objects` holds, by
/// the same tiles.
fn unpack_block<const K: usize, const D: usize>(block: &[f64], objects: &mut [[[f64; D]; K]]) {
    let (tiles, rest) = objects.as_chunks_mut::<TILE>();
    for (t, tile) in tiles.iter_mut().enumerate() {
        for (i, chunk) in block.chunks_exact(BATCH_LANES).enumerate() {
            let run = &chunk[t * TILE..(t + 1) * TILE];
            for (&x, object) in run.iter().zip(tile.iter_mut()) {
                object.as_flattened_mut()[i] = x;
            }
        }
    }
    let done = tiles.len() * TILE;
    for (i, row) in block.chunks_exact(BATCH_LANES).enumerate() {
        for (&x, object) in row[done..].iter().zip(rest.iter_mut()) {
            object.as_flattened_mut()[i] = x;
        }
    }
}

/// The f64 value `x`, or an error naming `field` when it is not finite.
fn finite(x: f64, field: &str) -> Result<f64> {
    check_finite(&x, field).map(|()| x)
}

/// The domain of a [`RestrictionMap`].
#[derive(Clone, Debug, PartialEq)]
enum Domain {
    Curve([f64; 2]),
    Tensor {
        cols: usize,
        rect: [f64; 4],
    },
    Triangle {
        degree: usize,
        corners: [[f64; 2]; 3],
    },
}

/// The restriction of every object of a batch to one domain: a linear map on control points,
/// applied by the halving engine.
#[derive(Clone, Debug, PartialEq)]
pub struct RestrictionMap {
    inputs: usize,
    outputs: usize,
    domain: Domain,
}

impl RestrictionMap {
    /// Bézier curves of degree `degree` over [0, 1] restricted to [a, b] (any a, b: outside
    /// [0, 1] or a > b too).
    ///
    /// ```
    /// use blossom::{ErrorKind, RestrictionMap};
    /// let map = RestrictionMap::curve(3, 0.25, 0.75)?;
    /// assert_eq!((map.inputs(), map.outputs()), (4, 4));
    /// assert_eq!(RestrictionMap::curve(3, f64::NAN, 1.0).unwrap_err().kind(), ErrorKind::NotFinite);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `a` or `b` when not finite; [`ErrorKind::TooLarge`] on
    /// `degree` when a block of one-dimensional curves, or the engine's scratch for it, would
    /// exceed [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    pub fn curve(degree: usize, a: f64, b: f64) -> Result<Self> {
        let domain = Domain::Curve([finite(a, "a")?, finite(b, "b")?]);
        let len = check_entries(degree.checked_add(1), "degree", POINTS)?;
        RestrictionMap::sized(len, domain)
    }

    /// Tensor patches of bidegree `degree` over [0, 1]^2 restricted to `rect = [a, b, c, d]`;
    /// control points are numbered row by row, `p = nu * (m + 1) + mu`.
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `rect[k]` when not finite; [`ErrorKind::TooLarge`] on
    /// `degree` as for [`RestrictionMap::curve`].
    pub fn tensor(degree: (usize, usize), rect: [f64; 4]) -> Result<Self> {
        for (k, &x) in rect.iter().enumerate() {
            finite(x, &format!("rect[{k}]"))?;
        }
        let rows = check_entries(degree.0.checked_add(1), "degree", POINTS)?;
        let cols = check_entries(degree.1.checked_add(1), "degree", POINTS)?;
        let len = checked_product(&[rows, cols], "degree", POINTS)?;
        RestrictionMap::sized(len, Domain::Tensor { cols, rect })
    }

    /// Triangular patches of degree `degree` restricted to the sub-triangle whose corners have
    /// the first two barycentric coordinates `corners` (the third is 1 minus their sum);
    /// control points in the order of [`crate::TriangularPatch`].
    ///
    /// # Errors
    /// [`ErrorKind::NotFinite`] on `corners[k][l]` when not finite; [`ErrorKind::TooLarge`] on
    /// `degree` as for [`RestrictionMap::curve`].
    pub fn triangle(degree: usize, corners: [[f64; 2]; 3]) -> Result<Self> {
        for (k, corner) in corners.iter().enumerate() {
            for (l, &x) in corner.iter().enumerate() {
                finite(x, &format!("corners[{k}][{l}]"))?;
            }
        }
        let len = check_entries(checked_triangle_len(degree), "degree", POINTS)?;
        RestrictionMap::sized(len, Domain::Triangle { degree, corners })
    }

    /// The map of `len` points per object on `domain`, refused (about `degree`) when a block
    /// of one-dimensional objects or its scratch exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    fn sized(len: usize, domain: Domain) -> Result<Self> {
        let map = RestrictionMap {
            inputs: len,
            outputs: len,
            domain,
        };
        checked_product(&[len, BATCH_LANES], "degree", "a block of objects")?;
        map.check_scratch(1, "degree")?;
        Ok(map)
    }

    /// The scratch of the engine for one block of `dim`-dimensional objects, refused (about
    /// `field`) when it overflows or exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    fn check_scratch(&self, dim: usize, field: &str) -> Result<usize> {
        let lanes = dim.checked_mul(BATCH_LANES);
        let len = lanes.and_then(|lanes| match &self.domain {
            Domain::Curve(_) => checked_curve_scratch_len(self.inputs - 1, lanes),
            Domain::Tensor { cols, .. } => {
                checked_tensor_scratch_len(self.inputs / cols - 1, cols - 1, lanes)
            }
            Domain::Triangle { degree, .. } => checked_triangle_scratch_len(*degree, lanes),
        });
        check_entries(len, field, "the scratch of the restriction engine")
    }

    /// Restricts objects kept in the caller's own layout, plain arrays of `K` points of `D`
    /// coordinates (a curve's polygon, a tensor net row by row, a triangular net in its order),
    /// writing the answers to `output` in the same layout: no [`Batch`] to build or read back.
    ///
    /// Curves are restricted one at a time where they lie, by the engine with the dimension
    /// fixed (unrolled for degrees 1..=8 in dimensions 1..=4): for small objects the
    /// transposes into and out of a block cost more than the restriction (10^5 planar cubics:
    /// 1.7 ms through blocks, 1.1 ms in place, `benches/peers.rs`, group `cubics_end_to_end`).
    /// Patches are packed [`BATCH_LANES`] at a time into one block buffer (which stays in the
    /// cache), the engine runs on the block as in [`Batch::restrict_into`], and the answers are
    /// unpacked. Either way every object gets the answer of the engine run on it alone, bit for
    /// bit, and nothing is allocated per object.
    ///
    /// ```
    /// use blossom::{Bezier, RestrictionMap};
    /// let curves = vec![[[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]]; 1000];
    /// let mut halves = vec![[[0.0; 2]; 4]; 1000];
    /// RestrictionMap::curve(3, 0.0, 0.5)?.restrict_arrays(&curves, &mut halves)?;
    /// let alone = Bezier::new(curves[7].to_vec())?.subsegment(0.0..0.5);
    /// assert_eq!(&halves[7][..], alone.points());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `input` when its objects do not have the map's number of points (`K`), `output` when it
    /// holds another number of objects, `map` when the engine's scratch for a block of this
    /// dimension exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    pub fn restrict_arrays<const K: usize, const D: usize>(
        &self,
        input: &[[[f64; D]; K]],
        output: &mut [[[f64; D]; K]],
    ) -> Result<()> {
        if K != self.inputs || K != self.outputs {
            return Err(Error::of(
                ErrorKind::Shape,
                "input",
                format!(
                    "the map takes objects of {} control points, found {K}",
                    self.inputs
                ),
            ));
        }
        if output.len() != input.len() {
            return Err(Error::of(
                ErrorKind::Shape,
                "output",
                format!("expected {} objects, found {}", input.len(), output.len()),
            ));
        }
        self.check_scratch(D, "map")?;
        if input.is_empty() || D == 0 || K == 0 {
            return Ok(());
        }
        if let Domain::Curve([a, b]) = &self.domain {
            let mut scratch = Vec::new();
            for (object, answer) in input.iter().zip(output.iter_mut()) {
                curve_subsegment_fixed::<f64, D>(
                    object.as_flattened(),
                    a,
                    b,
                    answer.as_flattened_mut(),
                    &mut scratch,
                );
            }
            return Ok(());
        }
        let block = K * D * BATCH_LANES;
        let (mut packed, mut restricted) = (vec![0.0; block], vec![0.0; block]);
        let mut scratch = Vec::new();
        for (objects, answers) in input
            .chunks(BATCH_LANES)
            .zip(output.chunks_mut(BATCH_LANES))
        {
            pack_block(objects, &mut packed);
            self.apply_block(D, &packed, &mut restricted, &mut scratch);
            unpack_block(&restricted, answers);
        }
        Ok(())
    }

    /// Control points per object taken in.
    pub fn inputs(&self) -> usize {
        self.inputs
    }

    /// Control points per object given out.
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// Restricts one block: `input` and `output` are blocks of `dim`-dimensional objects in
    /// the layout of [`Batch`], i.e. one object with points of `dim * BATCH_LANES` numbers.
    fn apply_block(&self, dim: usize, input: &[f64], output: &mut [f64], scratch: &mut Vec<f64>) {
        let lanes = dim * BATCH_LANES;
        match &self.domain {
            Domain::Curve([a, b]) => curve_net(
                input,
                lanes,
                &BernsteinStep(a),
                &BernsteinStep(b),
                output,
                scratch,
            ),
            Domain::Tensor { cols, rect } => {
                let steps = rect.each_ref().map(BernsteinStep);
                tensor_net(input, *cols, lanes, steps.each_ref(), output, scratch)
            }
            Domain::Triangle { degree, corners } => {
                let steps = corners.each_ref().map(BernsteinPairStep);
                triangle_net(input, *degree, lanes, steps.each_ref(), output, scratch)
            }
        }
    }
}

/// `len` objects (curves or patches) of `points` control points of dimension `dim`, in a
/// blocked structure-of-arrays layout ("AoSoA"): blocks of [`BATCH_LANES`] objects, and within
/// a block coordinate x of control point p of every object is one contiguous run of
/// `BATCH_LANES` numbers, at `block * block_len + (p * dim + x) * BATCH_LANES`; the last block
/// is padded with zeros. A block is one object with points of `dim * BATCH_LANES` numbers, on
/// which [`RestrictionMap`] runs the restriction engine.
///
/// Guarantee: every object gets exactly the answer (bit for bit) of the engine run on it
/// alone. Limits: the storage, whole blocks, at most [`MAX_ENTRIES`](crate::MAX_ENTRIES)
/// numbers ([`ErrorKind::TooLarge`] otherwise).
///
/// # Which call for which data
///
/// * Curves held as plain arrays (`[[[f64; D]; K]]`), each restricted once, answers wanted as
///   arrays: [`RestrictionMap::restrict_arrays`]. It restricts each curve where it lies, with
///   nothing to pack; a `Batch` round trip (pack, restrict, unpack) costs more for curves.
/// * Objects restricted to several domains, or kept in this layout between steps: pack once
///   ([`Batch::from_arrays`], or [`Batch::copy_from_arrays`] into a batch that is reused),
///   then [`Batch::restrict_into`] per map (and `par_restrict_into` with the `rayon`
///   feature), reading answers back with [`Batch::copy_to_arrays`] into a reused buffer.
///   Building new batches and vectors for every call pays the page faults of fresh
///   multi-megabyte buffers, which cost more than the restriction.
/// * [`Batch::get`], [`Batch::set`], [`Batch::net`] (a vector per call), [`Batch::from_nets`]
///   and [`Batch::from_curves`] are for a few objects, not for bulk data.
///
/// Measured on 10^5 planar cubics (`cargo bench -p blossom --bench restrict -- batch`, one
/// run on a busy 2-core machine, 2026-12-07): `restrict_arrays` 1.45 ms; the batch's own
/// restriction 1.52 ms, packing into a reused batch 1.25 ms and unpacking into a reused
/// vector 1.10 ms, the whole round trip with reused buffers 6.3 ms; the same round trip
/// building a new batch, answer batch and vector every call 32 ms, of which 24 ms are the
/// allocator's: with glibc's return of memory to the system turned off
/// (`MALLOC_TRIM_THRESHOLD_` and `MALLOC_MMAP_THRESHOLD_` at 4e9) it takes 8.4 ms.
///
/// ```
/// use blossom::{Batch, RestrictionMap};
/// let curves = vec![[[0.0, 0.0], [2.0, 2.0], [4.0, 2.0], [6.0, 0.0]]; 1000];
/// let batch = Batch::from_arrays(&curves)?;
/// // One packing, two restrictions.
/// let (left, right) = (RestrictionMap::curve(3, 0.0, 0.5)?, RestrictionMap::curve(3, 0.5, 1.0)?);
/// let mut halves = [Batch::zeros(4, 2, 1000)?, Batch::zeros(4, 2, 1000)?];
/// batch.restrict_into(&left, &mut halves[0])?;
/// batch.restrict_into(&right, &mut halves[1])?;
/// assert_eq!(halves[0].get(7, 3, 0), halves[1].get(7, 0, 0)); // both halves meet at t = 1/2
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Batch {
    points: usize,
    dim: usize,
    len: usize,
    data: Vec<f64>,
}

impl Batch {
    /// `len` objects with every coordinate zero.
    ///
    /// # Errors
    /// [`ErrorKind::TooLarge`] on `points * dim * len` when the storage (whole blocks of
    /// [`BATCH_LANES`] objects) overflows or exceeds [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    pub fn zeros(points: usize, dim: usize, len: usize) -> Result<Self> {
        let size = Self::storage(points, dim, len, "points * dim * len")?;
        Ok(Batch {
            points,
            dim,
            len,
            data: vec![0.0; size],
        })
    }

    /// The numbers stored for `len` objects of `points` points of dimension `dim` (whole
    /// blocks), refused (about `field`) beyond [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    fn storage(points: usize, dim: usize, len: usize, field: &str) -> Result<usize> {
        checked_product(
            &[len.div_ceil(BATCH_LANES), points, dim, BATCH_LANES],
            field,
            "the storage of the batch",
        )
    }

    /// The batch of `nets`, each a list of `points` control points of dimension `dim`
    /// (a curve's polygon, a tensor net row by row, a triangular net in its order).
    ///
    /// # Errors
    /// `nets[k]` when net k has another number of points, `nets[k][p]` when a point has
    /// another dimension; as [`Batch::zeros`] when the storage is too large.
    pub fn from_nets(points: usize, dim: usize, nets: &[&[Vec<f64>]]) -> Result<Self> {
        let mut batch = Batch::zeros(points, dim, nets.len())?;
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
        let (points, dim) = (first.degree() + 1, first.dim());
        let mut batch = Batch::zeros(points, dim, curves.len())?;
        for (k, curve) in curves.iter().enumerate() {
            if (curve.degree() + 1, curve.dim()) != (points, dim) {
                return Err(Error::of(
                    ErrorKind::Shape,
                    format!("curves[{k}]"),
                    format!(
                        "expected {points} control points of {dim} coordinates (as curves[0]), \
                         found {} of {}",
                        curve.degree() + 1,
                        curve.dim()
                    ),
                ));
            }
            batch.set_curve(k, curve.coordinates());
        }
        Ok(batch)
    }

    /// Writes the flat coordinates `coords` (point after point) of object `k`.
    fn set_curve(&mut self, k: usize, coords: &[f64]) {
        for (p, point) in coords.chunks_exact(self.dim).enumerate() {
            for (x, &value) in point.iter().enumerate() {
                let i = self.index(k, p, x);
                self.data[i] = value;
            }
        }
    }

    fn index(&self, k: usize, p: usize, x: usize) -> usize {
        let block = self.points * self.dim * BATCH_LANES;
        (k / BATCH_LANES) * block + (p * self.dim + x) * BATCH_LANES + k % BATCH_LANES
    }

    /// The batch of objects given as plain arrays of `K` points of `D` coordinates (a curve's
    /// polygon, a tensor net row by row, a triangular net in its order): a new buffer, then
    /// [`Batch::copy_from_arrays`]. To restrict arrays once and read arrays back,
    /// [`RestrictionMap::restrict_arrays`] is the faster call (see [`Batch`]).
    ///
    /// ```
    /// use blossom::Batch;
    /// let batch = Batch::from_arrays(&[[[1.0, 2.0], [3.0, 4.0]]; 3])?;
    /// assert_eq!((batch.len(), batch.points(), batch.dim()), (3, 2, 2));
    /// assert_eq!(batch.get(2, 1, 0), 3.0);
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Batch::zeros`] when the storage is too large.
    pub fn from_arrays<const K: usize, const D: usize>(objects: &[[[f64; D]; K]]) -> Result<Self> {
        let mut batch = Batch::zeros(K, D, objects.len())?;
        batch.pack(objects);
        Ok(batch)
    }

    /// Makes this batch hold `objects`, plain arrays of `K` points of `D` coordinates, in
    /// place: its buffer is reused (grown only when too small), so that a batch filled again
    /// and again allocates nothing (a fresh buffer of many megabytes costs its page faults,
    /// more than the packing itself). The packing is a tiled transpose, one pass over the
    /// objects; the last block is padded with zeros.
    ///
    /// ```
    /// use blossom::{Batch, RestrictionMap};
    /// let map = RestrictionMap::curve(3, 0.0, 0.5)?;
    /// // Three buffers, allocated once and reused for every round.
    /// let (mut batch, mut halves) = (Batch::zeros(4, 2, 0)?, Batch::zeros(4, 2, 100)?);
    /// let mut out = vec![[[0.0; 2]; 4]; 100];
    /// for round in 0..3 {
    ///     let curves = vec![[[0.0, 0.0], [2.0, 2.0], [4.0, 2.0], [6.0, round as f64]]; 100];
    ///     batch.copy_from_arrays(&curves)?;
    ///     batch.restrict_into(&map, &mut halves)?;
    ///     halves.copy_to_arrays(&mut out)?;
    ///     assert_eq!(out[99][1], [1.0, 1.0]);
    /// }
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`ErrorKind::TooLarge`] on `objects` when the storage (whole blocks of
    /// [`BATCH_LANES`] objects) would exceed [`MAX_ENTRIES`](crate::MAX_ENTRIES); the batch is
    /// then left as it was.
    pub fn copy_from_arrays<const K: usize, const D: usize>(
        &mut self,
        objects: &[[[f64; D]; K]],
    ) -> Result<()> {
        let size = Self::storage(K, D, objects.len(), "objects")?;
        if self.data.capacity() < size {
            self.data = vec![0.0; size];
        } else {
            self.data.resize(size, 0.0);
        }
        (self.points, self.dim, self.len) = (K, D, objects.len());
        self.pack(objects);
        Ok(())
    }

    /// Packs `objects` into the buffer, which has their shape.
    fn pack<const K: usize, const D: usize>(&mut self, objects: &[[[f64; D]; K]]) {
        if K * D > 0 {
            let blocks = self.data.chunks_exact_mut(K * D * BATCH_LANES);
            for (group, block) in objects.chunks(BATCH_LANES).zip(blocks) {
                pack_block(group, block);
            }
        }
    }

    /// The objects as plain arrays of `K` points of `D` coordinates, in a new vector (see
    /// [`Batch::copy_to_arrays`] to write into one of the caller's).
    ///
    /// # Errors
    /// `K` or `D` when they are not the batch's points per object or dimension.
    pub fn to_arrays<const K: usize, const D: usize>(&self) -> Result<Vec<[[f64; D]; K]>> {
        self.check_arrays::<K, D>()?;
        let mut objects = vec![[[0.0; D]; K]; self.len];
        self.unpack(&mut objects);
        Ok(objects)
    }

    /// Writes the objects into `out`, plain arrays of `K` points of `D` coordinates, one per
    /// object: the inverse of [`Batch::copy_from_arrays`], allocating nothing.
    ///
    /// ```
    /// use blossom::Batch;
    /// let batch = Batch::from_arrays(&[[[1.0], [2.0]], [[3.0], [4.0]]])?;
    /// let mut out = [[[0.0]; 2]; 2];
    /// batch.copy_to_arrays(&mut out)?;
    /// assert_eq!(out, [[[1.0], [2.0]], [[3.0], [4.0]]]);
    /// assert!(batch.copy_to_arrays(&mut [[[0.0]; 2]; 3]).is_err());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `K` or `D` when they are not the batch's points per object or dimension, `out` when it
    /// does not hold one array per object.
    pub fn copy_to_arrays<const K: usize, const D: usize>(
        &self,
        out: &mut [[[f64; D]; K]],
    ) -> Result<()> {
        self.check_arrays::<K, D>()?;
        if out.len() != self.len {
            return Err(Error::of(
                ErrorKind::Shape,
                "out",
                format!("expected {} objects, found {}", self.len, out.len()),
            ));
        }
        self.unpack(out);
        Ok(())
    }

    /// `Ok` when the batch's objects are `K` points of `D` coordinates.
    fn check_arrays<const K: usize, const D: usize>(&self) -> Result<()> {
        if K != self.points {
            return Err(Error::of(
                ErrorKind::Shape,
                "K",
                format!("the batch has {} points per object, not {K}", self.points),
            ));
        }
        if D != self.dim {
            return Err(Error::of(
                ErrorKind::Dimension,
                "D",
                format!("the batch has dimension {}, not {D}", self.dim),
            ));
        }
        Ok(())
    }

    /// Unpacks the buffer into `objects`, which have its shape.
    fn unpack<const K: usize, const D: usize>(&self, objects: &mut [[[f64; D]; K]]) {
        if K * D > 0 {
            let blocks = self.data.chunks_exact(K * D * BATCH_LANES);
            for (block, group) in blocks.zip(objects.chunks_mut(BATCH_LANES)) {
                unpack_block(block, group);
            }
        }
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
        map.check_scratch(self.dim, "map")?;
        Ok(())
    }

    fn block_lens(&self, out: &Batch) -> (usize, usize) {
        (
            self.points * self.dim * BATCH_LANES,
            out.points * out.dim * BATCH_LANES,
        )
    }

    /// Writes the restriction of every object by `map` into `out`, which must hold as many
    /// objects of `map.outputs()` points of the same dimension (see [`Batch::zeros`]). One
    /// allocation per call (the engine's scratch, shared by all blocks). Each object's answer
    /// is bit for bit that of the engine on the object alone.
    ///
    /// ```
    /// use blossom::{Batch, BezierCurve, RestrictionMap};
    /// let curve = BezierCurve::new(vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 3.0]])?;
    /// let batch = Batch::from_curves(&vec![curve.clone(); 10])?;
    /// let mut out = Batch::zeros(3, 2, 10)?;
    /// batch.restrict_into(&RestrictionMap::curve(2, 0.25, 0.75)?, &mut out)?;
    /// let alone = curve.subsegment(0.25..0.75);
    /// assert_eq!(out.net(9), alone.into_control_points());
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `map` or `out` when their shapes do not fit this batch; [`ErrorKind::TooLarge`] on `map`
    /// when the engine's scratch for a block of this dimension exceeds
    /// [`MAX_ENTRIES`](crate::MAX_ENTRIES).
    pub fn restrict_into(&self, map: &RestrictionMap, out: &mut Batch) -> Result<()> {
        self.check(map, out)?;
        let (bin, bout) = self.block_lens(out);
        if bin == 0 || bout == 0 {
            return Ok(());
        }
        let mut scratch = Vec::new();
        for (input, output) in self.data.chunks(bin).zip(out.data.chunks_mut(bout)) {
            map.apply_block(self.dim, input, output, &mut scratch);
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
            .for_each_init(Vec::new, |scratch, (input, output)| {
                map.apply_block(self.dim, input, output, scratch)
            });
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Objects whose every coordinate is distinct: object k, point p, axis x.
    fn objects<const K: usize, const D: usize>(count: usize, salt: f64) -> Vec<[[f64; D]; K]> {
        (0..count)
            .map(|k| {
                std::array::from_fn(|p| {
                    std::array::from_fn(|x| salt + (k * 1000 + p * 10 + x) as f64)
                })
            })
            .collect()
    }

    #[test]
    fn packing_puts_every_coordinate_where_the_layout_says() {
        // Counts around the tile and the block: partial tiles, partial blocks.
        for count in [0, 1, 7, 8, 9, 511, 512, 513, 1030] {
            let objs = objects::<4, 2>(count, 0.5);
            let batch = Batch::from_arrays(&objs).unwrap();
            let data = batch.as_slice();
            assert_eq!(data.len(), count.div_ceil(BATCH_LANES) * 8 * BATCH_LANES);
            for (k, object) in objs.iter().enumerate() {
                for (p, point) in object.iter().enumerate() {
                    for (x, &value) in point.iter().enumerate() {
                        // The layout of the type's docs, written out here.
                        let at = (k / BATCH_LANES) * 8 * BATCH_LANES
                            + (p * 2 + x) * BATCH_LANES
                            + k % BATCH_LANES;
                        assert_eq!(data[at], value, "{count}: object {k}, point {p}, axis {x}");
                    }
                }
            }
            // Padding lanes are zero.
            let lanes_used = count % BATCH_LANES;
            if lanes_used > 0 {
                let last = data.len() - 8 * BATCH_LANES;
                for row in data[last..].chunks_exact(BATCH_LANES) {
                    assert!(row[lanes_used..].iter().all(|&v| v == 0.0));
                }
            }
            assert_eq!(batch.to_arrays::<4, 2>().unwrap(), objs);
        }
    }

    #[test]
    fn reused_batches_equal_fresh_ones() {
        let mut batch = Batch::zeros(4, 2, 0).unwrap();
        let mut out = Vec::new();
        // Larger, then smaller (stale numbers must not survive in the padding), then another
        // shape.
        for count in [1030, 9, 600] {
            let objs = objects::<4, 2>(count, count as f64);
            batch.copy_from_arrays(&objs).unwrap();
            assert_eq!(batch, Batch::from_arrays(&objs).unwrap());
            out.resize(count, [[0.0; 2]; 4]);
            batch.copy_to_arrays(&mut out).unwrap();
            assert_eq!(out, objs);
        }
        let triples = objects::<3, 3>(20, 1.0);
        batch.copy_from_arrays(&triples).unwrap();
        assert_eq!((batch.points(), batch.dim(), batch.len()), (3, 3, 20));
        assert_eq!(batch, Batch::from_arrays(&triples).unwrap());
    }

    #[test]
    fn copies_that_do_not_fit_are_errors() {
        let batch = Batch::from_arrays(&objects::<4, 2>(5, 0.0)).unwrap();
        let e = batch.copy_to_arrays(&mut [[[0.0; 2]; 4]; 4]).unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::Shape, "out"));
        let e = batch.copy_to_arrays(&mut [[[0.0; 2]; 3]; 5]).unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::Shape, "K"));
        let e = batch.copy_to_arrays(&mut [[[0.0; 3]; 4]; 5]).unwrap_err();
        assert_eq!((e.kind, e.path()), (ErrorKind::Dimension, "D"));
    }
}
