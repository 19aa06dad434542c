//! The hot paths allocate nothing once `Data` exists (counting global allocator).

mod core_support;

use biped_dynamics::{
    forward_dynamics, forward_kinematics, inverse_dynamics, mass_matrix, on, Algorithm, Data, Force,
};
use core_support::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// System allocator that counts allocations.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn dynamics_calls_do_not_allocate() {
    for (seed, rotors) in [(1u64, false), (2, false), (3, true)] {
        let model = random_model(
            seed,
            30,
            TreeOptions {
                root: 0,
                rotors,
                ..TreeOptions::default()
            },
        );
        let mut r = rng(seed);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let tau = random_vec(model.nv(), 1.0, &mut r);
        let fext = vec![Force::zero(); model.nbodies()];
        let mut data = Data::new(&model);
        let before = ALLOCATIONS.load(Ordering::SeqCst);
        for _ in 0..3 {
            if !rotors {
                forward_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext), Algorithm::On)
                    .unwrap();
                on::forward_pass_1(&model, &mut data, &q, &v, None).unwrap();
                on::backward_pass(&model, &mut data, &tau).unwrap();
                on::forward_pass_2(&model, &mut data);
            }
            forward_dynamics(
                &model,
                &mut data,
                &q,
                &v,
                &tau,
                Some(&fext),
                Algorithm::Crba,
            )
            .unwrap();
            forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::Sparse).unwrap();
            inverse_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext)).unwrap();
            mass_matrix(&model, &mut data, &q).unwrap();
            forward_kinematics(&model, &mut data, &q, &v, &tau).unwrap();
        }
        let after = ALLOCATIONS.load(Ordering::SeqCst);
        assert_eq!(
            after - before,
            0,
            "seed {seed}: {} allocations",
            after - before
        );
    }
}
