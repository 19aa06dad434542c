//! A collision-model update allocates nothing after construction (counting allocator).

mod model_support;

use biped_ssv::format;
use model_support::data_path;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

struct Counting;

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

#[test]
fn update_does_not_allocate() {
    let mut loaded = format::load(data_path("humanoid.toml")).unwrap();
    let postures: Vec<_> = loaded.poses.values().cloned().collect();
    let before = allocations();
    for _ in 0..10 {
        for poses in &postures {
            loaded.model.update(poses).unwrap();
            std::hint::black_box(loaded.model.min_distance());
        }
    }
    assert_eq!(allocations() - before, 0);
    // The counter works: a Vec allocates.
    let v: Vec<u8> = Vec::with_capacity(8);
    std::hint::black_box(&v);
    assert!(allocations() > before);
}
