//! The float filter of curve intersection ([`blossom::certified_crossings_f64`]) keeps its
//! search state per thread and reuses it, so that a call allocates nothing after the first
//! but its answer: counted here by a global allocator that counts the allocations of the
//! calling thread (as `tests/allocations.rs` does for the restriction calls; a test binary of
//! its own, because a process has one global allocator).

use blossom::certified_crossings_f64;
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
