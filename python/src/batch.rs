//! `restrict_curves`: many Bézier curves restricted to one interval at once, by the library's
//! batch call, with the GIL released.

use crate::errors::{bad, call_detached};
use crate::numbers::{first_not_finite, read_array, Coords};
use blossom::RestrictionMap;
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray3, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// Many Bézier curves restricted to one interval: `nodes` an `N x D x (n + 1)` float64 array
/// (curve k's nodes `nodes[k]`, as a `Curve`'s), answer the same shape, curve k over
/// [start, end] reparametrised to [0, 1], bit for bit `Curve.specialize`'s answer, in the
/// layout of `nodes` (or written into `out`, an array of that shape and layout). The library's
/// batch call (`RestrictionMap::restrict_arrays`) does the work where the numbers lie, with the
/// GIL released: on `[[f64; D]; n + 1]` curves when the array's memory holds each curve point
/// after point (strides (8 D (n + 1), 8, 8 D): the `(N, D, n + 1)` view of an `(N, n + 1, D)`
/// array, the layout of the Rust call), else on the N D coordinate rows as one-dimensional
/// curves (C order). Any other layout is first copied to C order.
#[pyfunction]
#[pyo3(signature = (nodes, start, end, *, out = None))]
pub fn restrict_curves<'py>(
    py: Python<'py>,
    nodes: &Bound<'py, PyAny>,
    start: &Bound<'py, PyAny>,
    end: &Bound<'py, PyAny>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let start = crate::numbers::f64_arg(start, "start")?;
    let end = crate::numbers::f64_arg(end, "end")?;
    let array = batch_array(py, nodes)?;
    let shape = array.shape().to_vec();
    let (n, d, k) = (shape[0], shape[1], shape[2]);
    if d == 0 || k == 0 {
        return Err(bad(
            "nodes",
            "Empty",
            format!(
                "expected at least one coordinate and one node per curve, found shape {shape:?}"
            ),
        ));
    }
    let point_major = is_point_major(&array);
    // The memory as it is when it holds the curves point after point or in C order; any other
    // layout is copied to C order first.
    let array = if point_major || array.is_c_contiguous() {
        array
    } else {
        py.import("numpy")?
            .call_method1("ascontiguousarray", (&array,))?
            .cast_into::<PyArray3<f64>>()?
    };
    let answer = match out {
        Some(o) => {
            let o = o.cast::<PyArray3<f64>>().map_err(|_| {
                bad(
                    "out",
                    "Invalid",
                    "expected a float64 array of three dimensions",
                )
            })?;
            let same_layout = if point_major {
                is_point_major(o)
            } else {
                o.is_c_contiguous()
            };
            if o.shape() != shape.as_slice() || !same_layout {
                return Err(bad(
                    "out",
                    "Shape",
                    format!(
                        "expected an array of shape {shape:?} laid out as nodes ({})",
                        if point_major {
                            "point after point"
                        } else {
                            "C order"
                        }
                    ),
                ));
            }
            o.clone()
        }
        // SAFETY (both arms): the new array is written whole by `restrict_batch` before it is
        // returned; on an error it is dropped unread.
        #[allow(unsafe_code)]
        None if point_major => {
            // Allocated (n, k, d) in C order, answered as its (n, d, k) view.
            let buffer = unsafe { PyArray3::<f64>::new(py, [n, k, d], false) };
            buffer
                .call_method1("transpose", ((0, 2, 1),))?
                .cast_into::<PyArray3<f64>>()?
        }
        #[allow(unsafe_code)]
        None => unsafe { PyArray3::<f64>::new(py, [n, d, k], false) },
    };
    let readonly = array.readonly();
    let input = readonly.as_array();
    let input = input.as_slice_memory_order().expect("contiguous");
    let mut writable = answer.try_readwrite().map_err(|_| {
        bad(
            "out",
            "Invalid",
            "expected a writable array not in use elsewhere",
        )
    })?;
    let mut output = writable.as_array_mut();
    let output = output.as_slice_memory_order_mut().expect("contiguous");
    let not_finite = call_detached(py, &[], || {
        restrict_batch(input, output, d, k, start, end, point_major)
    })?;
    if let Some(i) = not_finite {
        let logical = if point_major {
            (i / (d * k)) * d * k + (i % d) * k + (i % (d * k)) / d
        } else {
            i
        };
        return Err(bad(
            crate::numbers::index_path("nodes", &shape, logical),
            "NotFinite",
            format!("expected a finite number, found {}", input[i]),
        ));
    }
    drop(writable);
    Ok(answer.into_any())
}

/// Whether the array's memory holds each curve's points one after the other (strides
/// (8 D (n + 1), 8, 8 D) of an `N x D x (n + 1)` array).
fn is_point_major(a: &Bound<'_, PyArray3<f64>>) -> bool {
    let shape = a.shape();
    let item = std::mem::size_of::<f64>() as isize;
    let (d, k) = (shape[1] as isize, shape[2] as isize);
    let strides = a.strides();
    // A stride along an axis of length 1 is never used (numpy sets it freely).
    shape[0] > 0
        && shape[1] > 1
        && (shape[0] == 1 || strides[0] == item * d * k)
        && strides[1] == item
        && (shape[2] == 1 || strides[2] == item * d)
}

/// The `nodes` argument of `restrict_curves` as a float64 array of three dimensions.
fn batch_array<'py>(
    py: Python<'py>,
    nodes: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    if let Ok(a) = nodes.cast::<PyArray3<f64>>() {
        return Ok(a.clone());
    }
    let read = read_array(nodes, "nodes", 3, "N x D x (n + 1)")?;
    let Coords::F64(c) = read.coords else {
        return Err(bad(
            "nodes",
            "Invalid",
            "the batch restriction is float64 only; give floats",
        ));
    };
    let shape = (read.shape[0], read.shape[1], read.shape[2]);
    Ok(Array3::from_shape_vec(shape, c)
        .expect("the shape read")
        .into_pyarray(py))
}

/// The first not-finite number of a batch (its index in memory), or the library's error.
type Checked = Result<Option<usize>, blossom::Error>;

/// Restricts every curve of `input` (point-major curves, or C order `N x D x K`) into `output`
/// in the same layout, by the library's `RestrictionMap::restrict_arrays` on `[[f64; D]; K]`
/// curves (D = 2, 3, K <= 9), in chunks that stay in the cache: point-major curves where they
/// lie ([`restrict_points`]), C-ordered ones through point-major copies of each chunk
/// ([`restrict_c_order`]). Each chunk's numbers are checked finite as they are read; the first
/// NaN or infinity stops the work (`Ok(Some(index in memory))`; the chunks before it are
/// written). Other sizes go through the engine row by row (after one check of the whole
/// input), as one-dimensional curves: de Casteljau's steps act on each coordinate alone, so
/// every answer is the same bit for bit.
fn restrict_batch(
    input: &[f64],
    output: &mut [f64],
    d: usize,
    k: usize,
    start: f64,
    end: f64,
    point_major: bool,
) -> Checked {
    macro_rules! fixed {
        ($(($dd:literal, $kk:literal)),*) => {
            match (d, k) {
                $(($dd, $kk) => {
                    return if point_major {
                        restrict_points::<$kk, $dd>(input, output, start, end)
                    } else {
                        restrict_c_order::<$kk, $dd>(input, output, start, end)
                    };
                })*
                _ => {}
            }
        };
    }
    fixed!(
        (2, 2),
        (2, 3),
        (2, 4),
        (2, 5),
        (2, 6),
        (2, 7),
        (2, 8),
        (2, 9),
        (3, 2),
        (3, 3),
        (3, 4),
        (3, 5),
        (3, 6),
        (3, 7),
        (3, 8),
        (3, 9)
    );
    if let Some(i) = first_not_finite(input) {
        return Ok(Some(i));
    }
    if !point_major {
        restrict_rows(input, output, k, start, end)?;
        return Ok(None);
    }
    let c_order = transpose_curves(input, k, d);
    let mut answer = vec![0.0; c_order.len()];
    restrict_rows(&c_order, &mut answer, k, start, end)?;
    output.copy_from_slice(&transpose_curves(&answer, d, k));
    Ok(None)
}

/// Curves restricted at a time by [`restrict_points`] and [`restrict_c_order`]: 64 planar
/// cubics are 4 KiB in and 4 KiB out, in the L1 cache between the check, the copies and the
/// restriction.
const CHUNK: usize = 64;

/// Curves of `K` points of dimension `D`, point after point, restricted by the library's
/// `restrict_arrays` where they lie, [`CHUNK`] at a time, each chunk checked finite first.
fn restrict_points<const K: usize, const D: usize>(
    input: &[f64],
    output: &mut [f64],
    start: f64,
    end: f64,
) -> Checked {
    let map = RestrictionMap::curve(K - 1, start, end)?;
    let (points_in, _) = input.as_chunks::<D>();
    let (curves_in, _) = points_in.as_chunks::<K>();
    let (points_out, _) = output.as_chunks_mut::<D>();
    let (curves_out, _) = points_out.as_chunks_mut::<K>();
    for (c, (chunk_in, chunk_out)) in curves_in
        .chunks(CHUNK)
        .zip(curves_out.chunks_mut(CHUNK))
        .enumerate()
    {
        if let Some(i) = first_not_finite(chunk_in.as_flattened().as_flattened()) {
            return Ok(Some(c * CHUNK * K * D + i));
        }
        map.restrict_arrays(chunk_in, chunk_out)?;
    }
    Ok(None)
}

/// Curves in C order (`N x D x K`: coordinate x of curve c is the row
/// `input[(c D + x) K..][..K]`), restricted by the library's `restrict_arrays` on point-major
/// copies of [`CHUNK`] curves at a time: each chunk checked finite, each curve's D rows read
/// into its `[[f64; D]; K]` array, the chunk restricted, each answer written back to its D rows
/// in the output. Every number is read and written once in memory; the copies stay in the
/// cache. The answer is bit for bit that of each curve restricted alone.
fn restrict_c_order<const K: usize, const D: usize>(
    input: &[f64],
    output: &mut [f64],
    start: f64,
    end: f64,
) -> Checked {
    let map = RestrictionMap::curve(K - 1, start, end)?;
    let mut points = [[[0.0; D]; K]; CHUNK];
    let mut answers = [[[0.0; D]; K]; CHUNK];
    let (rows_in, _) = input.as_chunks::<K>();
    let (curves_in, _) = rows_in.as_chunks::<D>();
    let (rows_out, _) = output.as_chunks_mut::<K>();
    let (curves_out, _) = rows_out.as_chunks_mut::<D>();
    for (c, (chunk_in, chunk_out)) in curves_in
        .chunks(CHUNK)
        .zip(curves_out.chunks_mut(CHUNK))
        .enumerate()
    {
        if let Some(i) = first_not_finite(chunk_in.as_flattened().as_flattened()) {
            return Ok(Some(c * CHUNK * K * D + i));
        }
        let m = chunk_in.len();
        for (curve, rows) in points.iter_mut().zip(chunk_in) {
            for (x, row) in rows.iter().enumerate() {
                for (p, &v) in curve.iter_mut().zip(row) {
                    p[x] = v;
                }
            }
        }
        map.restrict_arrays(&points[..m], &mut answers[..m])?;
        for (curve, rows) in answers.iter().zip(chunk_out.iter_mut()) {
            to_rows(curve, rows);
        }
    }
    Ok(None)
}

/// A curve's points `[[f64; D]; K]` written as its D coordinate rows `[[f64; K]; D]`. For
/// planar curves on x86-64, two points at a time by SSE2 shuffles (the x pair and the y pair
/// of points j, j + 1): the compiler's code stored one number at a time, and the stores were
/// the cost of the C-order batch.
#[inline(always)]
fn to_rows<const K: usize, const D: usize>(curve: &[[f64; D]; K], rows: &mut [[f64; K]; D]) {
    #[cfg(target_arch = "x86_64")]
    if D == 2 {
        use std::arch::x86_64::{_mm_loadu_pd, _mm_storeu_pd, _mm_unpackhi_pd, _mm_unpacklo_pd};
        let [xs, ys] = rows.first_chunk_mut::<2>().expect("D == 2");
        for (j, pair) in curve.chunks_exact(2).enumerate() {
            // SAFETY: SSE2 is part of x86-64; each load reads the two numbers of one point
            // (D == 2) and each store writes two numbers of a row at 2 j < K - 1.
            #[allow(unsafe_code)]
            unsafe {
                let a = _mm_loadu_pd(pair[0].as_ptr());
                let b = _mm_loadu_pd(pair[1].as_ptr());
                _mm_storeu_pd(xs.as_mut_ptr().add(2 * j), _mm_unpacklo_pd(a, b));
                _mm_storeu_pd(ys.as_mut_ptr().add(2 * j), _mm_unpackhi_pd(a, b));
            }
        }
        if K % 2 == 1 {
            xs[K - 1] = curve[K - 1][0];
            ys[K - 1] = curve[K - 1][1];
        }
        return;
    }
    for (x, row) in rows.iter_mut().enumerate() {
        for (v, p) in row.iter_mut().zip(curve) {
            *v = p[x];
        }
    }
}

/// Restricts every run of `k` numbers of `input` as a one-dimensional curve.
fn restrict_rows(
    input: &[f64],
    output: &mut [f64],
    k: usize,
    start: f64,
    end: f64,
) -> Result<(), blossom::Error> {
    macro_rules! fixed {
        ($($kk:literal),*) => {
            match k {
                $($kk => {
                    let map = RestrictionMap::curve($kk - 1, start, end)?;
                    let (points_in, _) = input.as_chunks::<1>();
                    let (curves_in, _) = points_in.as_chunks::<$kk>();
                    let (points_out, _) = output.as_chunks_mut::<1>();
                    let (curves_out, _) = points_out.as_chunks_mut::<$kk>();
                    return map.restrict_arrays(curves_in, curves_out);
                })*
                _ => {}
            }
        };
    }
    fixed!(2, 3, 4, 5, 6, 7, 8, 9);
    let (rows_in, _) = input.as_chunks::<1>();
    let (rows_out, _) = output.as_chunks_mut::<1>();
    let mut scratch = Vec::new();
    for (row, answer) in rows_in.chunks_exact(k).zip(rows_out.chunks_exact_mut(k)) {
        blossom::engine::subsegment_into::<f64, 1>(row, &start, &end, answer, &mut scratch)?;
    }
    Ok(())
}

/// Each curve's `a x b` block of `v` transposed to `b x a`.
fn transpose_curves(v: &[f64], a: usize, b: usize) -> Vec<f64> {
    let mut out = vec![0.0; v.len()];
    for (curve, t) in v.chunks_exact(a * b).zip(out.chunks_exact_mut(a * b)) {
        for i in 0..a {
            for j in 0..b {
                t[j * a + i] = curve[i * b + j];
            }
        }
    }
    out
}
