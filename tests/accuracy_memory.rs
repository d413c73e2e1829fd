//! The peaks-only observer allocates nothing per step: the bytes a run
//! allocates do not grow with its length (a counting global allocator,
//! private to this test binary).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use pounding::model::{Params, SET1};
use pounding::solver::{SolverOptions, simulate};

struct Counting;
static ALLOCATED: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATED.fetch_add(layout.size(), Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocated_by(p: &Params) -> usize {
    let before = ALLOCATED.load(Ordering::Relaxed);
    let r = simulate(p, &SolverOptions::default(), &mut ());
    assert!(r.completed);
    ALLOCATED.load(Ordering::Relaxed) - before
}

/// Without pounding, 1 and 200 cycles allocate the same bytes; with pounding,
/// only the impact list grows (≤ 2× its final size, Vec doubling).
#[test]
fn peaks_only_memory_does_not_grow_with_run_length() {
    let free = Params {
        gap: f64::INFINITY,
        ..SET1
    };
    let short = allocated_by(&Params { cycles: 1, ..free });
    let long = allocated_by(&Params {
        cycles: 200,
        ..free
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
