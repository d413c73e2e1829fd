//! The peaks-only observer allocates nothing per step: the bytes a run
//! allocates do not grow with its length (a counting global allocator,
//! private to this test binary, counting per thread so that tests running
//! side by side do not see each other's allocations).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use pounding::model::{Params, SET1};
use pounding::solver::{SolverOptions, simulate};

struct Counting;
thread_local! {
    /// Bytes allocated by this thread.
    static ALLOCATED: Cell<usize> = const { Cell::new(0) };
}

fn allocated() -> usize {
    ALLOCATED.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // `try_with`: a thread being torn down has no counter left, and needs none.
        let _ = ALLOCATED.try_with(|a| a.set(a.get() + layout.size()));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocated_by(p: &Params) -> usize {
    let before = allocated();
    let r = simulate(p, &SolverOptions::default(), &mut ());
    assert!(r.completed);
    allocated() - before
}

/// Without pounding, 1 and 200 cycles allocate the same bytes; with pounding,
/// only the impact list grows (≤ 2× its final size, Vec doubling).
#[test]
fn peaks_only_memory_does_not_grow_with_run_length() {
    let free = Params {
        gap: f64::INFINITY,
        ..SET1
    };
    let short = allocated_by(&Params {
        cycles: 1,
        ..free.clone()
    });
    let long = allocated_by(&Params {
        cycles: 200,
        ..free.clone()
    });
    assert_eq!(short, long);
    let p = Params {
        cycles: 200,
        ..SET1
    };
    let impacts = simulate(&p, &SolverOptions::default(), &mut ())
        .impacts
        .len();
    let bytes = allocated_by(&p);
    let per_impact = std::mem::size_of::<pounding::solver::Impact>();
    assert!(
        bytes <= 4 * impacts.max(32) * per_impact + short,
        "{bytes} bytes for {impacts} impacts"
    );
}
