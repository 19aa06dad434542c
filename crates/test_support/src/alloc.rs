//! The "no heap allocation per call" checks of the workspace: a global
//! allocator that counts the allocations (and reallocations) of the calling thread only, and
//! the bytes they request ([`allocated_bytes`], for memory-bound checks), so
//! the test harness's own threads (output capture, parallel tests, more so under load) do not
//! disturb a count. Install it in a test binary with
//! `#[global_allocator] static GLOBAL: Counting = Counting;` and compare [`allocations`]
//! before and after the code under test.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// System allocator that counts the calling thread's allocations.
pub struct Counting;

thread_local! {
    /// Allocations and reallocations made by this thread.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

thread_local! {
    /// Bytes requested by this thread's allocations and reallocations (new sizes).
    static BYTES: Cell<usize> = const { Cell::new(0) };
}

/// Counts one allocation of `size` bytes on this thread (no-op while the thread is torn down).
fn bump(size: usize) {
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
    let _ = BYTES.try_with(|c| c.set(c.get().saturating_add(size)));
}

/// Bytes the calling thread has requested so far (allocations plus the new sizes of
/// reallocations): an upper bound of the peak heap use it caused.
pub fn allocated_bytes() -> usize {
    BYTES.with(Cell::get)
}

/// Allocations and reallocations made by the calling thread so far (0 unless [`Counting`] is
/// the global allocator).
pub fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// Allocations the calling thread makes while running `f`.
pub fn count(f: impl FnOnce()) -> usize {
    let before = allocations();
    f();
    allocations() - before
}

// SAFETY: every call forwards to the system allocator unchanged; counting touches only a
// const-initialised thread-local cell (no allocation, no re-entry).
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        bump(layout.size());
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        bump(new_size);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}
