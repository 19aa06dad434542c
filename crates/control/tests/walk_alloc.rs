//! One walking IK cycle allocates nothing (counting global allocator), for every method.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{walk_pattern_params, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaType};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// System allocator that counts the allocations of the calling thread (the test harness
/// allocates on its own threads, more so under load).
struct Counting;

thread_local! {
    /// Allocations and reallocations made by this thread.
    static ALLOCS: Cell<usize> = const { Cell::new(0) };
}

/// Counts one allocation on this thread (no-op while the thread is torn down).
fn bump() {
    let _ = ALLOCS.try_with(|c| c.set(c.get() + 1));
}

/// Allocations made by this thread so far.
fn allocations() -> usize {
    ALLOCS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        bump();
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        unsafe { System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, n: usize) -> *mut u8 {
        bump();
        unsafe { System.realloc(p, l, n) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn cycle_does_not_allocate() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pattern =
        WalkingPattern::generate(&walk_pattern_params(&lola, 2, 0.4, 0.8).unwrap()).unwrap();
    for method in Method::ALL {
        let mut ctrl = WalkController::new(&lola, method, WalkParams::default(), &pattern).unwrap();
        let samples = pattern.samples();
        for s in &samples[..1500] {
            ctrl.cycle(s, 1e-3).unwrap();
        }
        let before = allocations();
        for s in &samples[1500..1600] {
            ctrl.cycle(s, 1e-3).unwrap();
        }
        let n = allocations() - before;
        assert_eq!(n, 0, "{method}: {n} allocations in 100 cycles");
    }
}
