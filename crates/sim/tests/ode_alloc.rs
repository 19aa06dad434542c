//! `advance` performs no heap allocation: a counting global allocator observes every call.

mod ode_support;

use biped_sim::ode::{Integrator, Method, Settings};
use ode_support::Kepler;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// System allocator that counts allocations.
struct Counting;

static ALLOCS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        unsafe { System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, n: usize) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(p, l, n) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn advance_does_not_allocate() {
    // Single test in this binary, so no other thread allocates meanwhile.
    for method in Method::ALL {
        let mut integ = Integrator::new(method, 4, Settings::fixed(1e-3)).expect("settings");
        let mut z = Kepler::initial(0.5);
        let outputs = [0.25, 0.3, 0.35];
        let mut sum = 0.0;
        let before = ALLOCS.load(Ordering::SeqCst);
        for k in 0..20 {
            let (t0, t1) = (0.01 * k as f64, 0.01 * (k + 1) as f64);
            integ
                .advance_split(&mut Kepler, t0, t1, &mut z)
                .expect("integrates");
        }
        integ
            .advance_split_dense(&mut Kepler, 0.2, 0.4, &mut z, &outputs, |_, y| sum += y[0])
            .expect("integrates");
        let after = ALLOCS.load(Ordering::SeqCst);
        assert_eq!(after - before, 0, "{method} allocated");
        assert!(sum.is_finite() && sum != 0.0);
    }
}
