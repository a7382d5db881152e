//! How often the everyday float calls allocate, counted by a global allocator that counts the
//! allocations of the calling thread: the forms that return a new shape allocate once (the
//! answer), the `_into` forms and the fixed-dimension evaluation not at all, at degrees on
//! both sides of the unrolled evaluators (degree 24), where the engine needs scratch space.

use blossom::engine::INLINE_COORDINATES;
use blossom::{
    restrict_power_curve, Bezier, BezierCurve, Method, PowerCurve, RationalBezierCurve,
    TensorPatch, TriangularPatch,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting the allocations (and reallocations) of each thread.
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: every call is forwarded to the system allocator unchanged; the count is a
// thread-local `Cell` with a constant initialiser, which never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The allocations `work` makes on this thread (its answer dropped after counting).
fn allocations<R>(work: impl FnOnce() -> R) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    let answer = std::hint::black_box(work());
    let count = ALLOCATIONS.with(Cell::get) - before;
    drop(answer);
    count
}

fn points(n: usize, dim: usize) -> Vec<Vec<f64>> {
    (0..=n)
        .map(|i| {
            (0..dim)
                .map(|k| ((i * 7 + k * 3) % 11) as f64 - 5.0)
                .collect()
        })
        .collect()
}

#[test]
fn returned_float_curves_allocate_only_their_answer() {
    for n in [1, 3, 12, 24, 25, 40, 64] {
        for dim in [2, 3, 5] {
            let curve = BezierCurve::new(points(n, dim)).unwrap();
            // The first call may grow this thread's scratch buffer; later ones reuse it.
            // (-0.5..0.75 reaches outside [0, 1], so it takes the engine, whose scratch this
            // grows, at every degree; 0.25..0.5 takes the two subdivisions at 9..=40.)
            let _ = curve.subsegment(0.25..0.5);
            let _ = curve.subsegment(-0.5..0.75);
            let _ = curve.eval(&0.3);
            let returned = allocations(|| curve.subsegment(-0.5..0.75));
            // Answers of at most INLINE_COORDINATES numbers are held inline: no allocation.
            let answer = usize::from((n + 1) * dim > INLINE_COORDINATES);
            assert_eq!(returned, answer, "degree {n}, dim {dim}");
            let evaluated = allocations(|| curve.eval(&0.3));
            assert_eq!(evaluated, 1, "eval, degree {n}, dim {dim}: the point only");
            let mut out = curve.clone();
            let mut scratch = Vec::new();
            // The same interval as below (outside [0, 1]: the engine) sizes the scratch.
            curve.subsegment_into(&0.2, &1.5, &mut out, &mut scratch);
            let into = allocations(|| curve.subsegment_into(&0.2, &1.5, &mut out, &mut scratch));
            assert_eq!(into, 0, "subsegment_into, degree {n}, dim {dim}");
        }
    }
}

#[test]
fn fixed_dimension_curves_allocate_only_their_answer() {
    for n in [1, 2, 3, 4, 8, 24, 40, 41, 64] {
        let ctrl: Vec<[f64; 3]> = points(n, 3).iter().map(|p| [p[0], p[1], p[2]]).collect();
        let curve = Bezier::new(ctrl).unwrap();
        let _ = (
            curve.subsegment(0.25..0.5),
            curve.eval(&0.5),
            curve.split(&0.5),
        );
        assert_eq!(allocations(|| curve.eval(&0.3)), 0, "eval, degree {n}");
        // A 3-D curve of at most INLINE_COORDINATES numbers (a cubic) is returned inline.
        let answer = usize::from((n + 1) * 3 > INLINE_COORDINATES);
        assert_eq!(
            allocations(|| curve.subsegment(0.1..0.3)),
            answer,
            "subsegment, degree {n}"
        );
        assert_eq!(
            allocations(|| curve.split(&0.3)),
            2 * answer,
            "split, degree {n}"
        );
    }
}

#[test]
fn returned_float_patches_allocate_only_their_answer() {
    for n in [2, 5, 9] {
        let net: Vec<Vec<Vec<f64>>> = (0..=n)
            .map(|i| {
                points(n, 3)
                    .into_iter()
                    .map(|p| p.into_iter().map(|x| x + i as f64).collect())
                    .collect()
            })
            .collect();
        let patch = TensorPatch::new(net).unwrap();
        let rect = [0.1, 0.6, -0.2, 0.9];
        let _ = patch.restrict(&rect);
        assert_eq!(
            allocations(|| patch.restrict(&rect)),
            1,
            "tensor, degree {n}"
        );
        let count = (n + 1) * (n + 2) / 2;
        let triangle = TriangularPatch::new(n, points(count - 1, 3)).unwrap();
        let corners = [[0.1, 0.1], [0.8, 0.1], [0.2, 0.7]];
        let _ = triangle.restrict(&corners);
        assert_eq!(
            allocations(|| triangle.restrict(&corners)),
            1,
            "triangle, degree {n}"
        );
    }
}

#[test]
fn rational_curves_evaluate_with_one_allocation() {
    for n in [3, 24, 40] {
        let weights: Vec<f64> = (0..=n).map(|i| 1.0 + (i % 3) as f64).collect();
        let rational = RationalBezierCurve::new(points(n, 3), weights).unwrap();
        let _ = rational.eval(&0.5);
        assert_eq!(
            allocations(|| rational.eval(&0.3)),
            1,
            "rational eval, degree {n}"
        );
    }
}

#[test]
fn power_form_restriction_allocates_no_point_by_point() {
    for n in [3, 24, 40] {
        let power = PowerCurve::new(points(n, 3)).unwrap();
        let _ = restrict_power_curve(&power, &0.25, &0.5, Method::Bulk);
        // The scaled coefficients and the answer's one buffer; none per control point.
        let count = allocations(|| restrict_power_curve(&power, &0.1, &0.3, Method::Bulk));
        assert_eq!(count, 2, "degree {n}");
    }
}

/// The float filter of curve intersection ([`blossom::certified_crossings_f64`]) keeps its
/// search state per thread and reuses it, so that a call allocates nothing after the first
/// but its answer (the same counting allocator as the restriction calls above).
mod filter_search {
    use super::ALLOCATIONS;
    use blossom::certified_crossings_f64;
    use std::cell::Cell;

    /// The allocations `work` makes on this thread, and its answer.
    fn counted<R>(work: impl FnOnce() -> R) -> (usize, R) {
        let before = ALLOCATIONS.with(Cell::get);
        let answer = std::hint::black_box(work());
        (ALLOCATIONS.with(Cell::get) - before, answer)
    }

    /// A curve's control points.
    type Curve = Vec<[f64; 2]>;

    /// A curve of degree `n` with pseudo-random control points in [0, 1]^2 (xorshift).
    fn curve(n: usize, state: &mut u64) -> Curve {
        let mut unit = || {
            *state ^= *state << 13;
            *state ^= *state >> 7;
            *state ^= *state << 17;
            (*state >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..=n).map(|_| [unit(), unit()]).collect()
    }

    #[test]
    fn the_filter_allocates_nothing_after_the_first_call_but_its_answer() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        // Pairs of every size the search state has to hold: cubics (the unrolled pieces),
        // degrees 5 and 8, and 20 (pieces in vectors).
        let pairs: Vec<(Curve, Curve)> = [3, 3, 5, 8, 20, 3, 8, 20, 5, 3]
            .iter()
            .map(|&n| (curve(n, &mut state), curve(n, &mut state)))
            .collect();
        // The first calls allocate the search state (and grow it to the largest pair).
        let (first, _) = counted(|| certified_crossings_f64(&pairs[4].0, &pairs[4].1));
        assert!(first > 0, "the counter counts");
        for (p, q) in &pairs {
            certified_crossings_f64(p, q);
        }
        // From then on, a call allocates exactly what its answer's vector does: nothing for no
        // crossing (or no answer), else the allocations of collecting that many crossings.
        let (mut with_crossings, mut without) = (0, 0);
        for (p, q) in &pairs {
            let (count, answer) = counted(|| certified_crossings_f64(p, q));
            let crossings = answer.as_deref().unwrap_or(&[]);
            // The same vector grown push by push, as the filter collects its crossings.
            let (rebuilt, _) = counted(|| {
                let mut v = Vec::new();
                for c in crossings {
                    v.push(*c);
                }
                v
            });
            assert_eq!(
                count,
                rebuilt,
                "{} crossings of degrees {}, {}",
                crossings.len(),
                p.len() - 1,
                q.len() - 1
            );
            if crossings.is_empty() {
                assert_eq!(count, 0);
                without += 1;
            } else {
                with_crossings += 1;
            }
        }
        assert!(
            with_crossings >= 3 && without >= 1,
            "{with_crossings} with crossings, {without} without"
        );
    }
}
