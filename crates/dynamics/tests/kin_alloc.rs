//! Jacobian, CoM and centroidal calls allocate nothing once their workspaces exist
//! (counting global allocator).

mod core_support;

use biped_dynamics::{center_of_mass, Centroidal, Data, JacobianFrame, Jacobians};
use core_support::*;
use nalgebra::{DMatrix, DVector, Vector3};
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
fn jacobian_and_centroidal_calls_do_not_allocate() {
    for seed in [1u64, 2, 3] {
        let opts = TreeOptions {
            rotors: true,
            ..TreeOptions::default()
        };
        let model = random_model(seed, 30, opts);
        let mut r = rng(seed);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let nv = model.nv();
        let mut data = Data::new(&model);
        let mut jac = Jacobians::new(&model);
        let mut cen = Centroidal::new(&model);
        let (mut j6, mut j3) = (DMatrix::zeros(6, nv), DMatrix::zeros(3, nv));
        let mut grad = DVector::zeros(nv);
        let point = Vector3::new(0.1, 0.2, 0.3);
        let before = ALLOCATIONS.load(Ordering::SeqCst);
        for _ in 0..3 {
            jac.compute_with_derivatives(&model, &mut data, &q, &v)
                .unwrap();
            for i in 0..model.nbodies() {
                for frame in [JacobianFrame::Body, JacobianFrame::WorldAligned] {
                    jac.body_jacobian(i, frame, &mut j6).unwrap();
                    jac.body_jacobian_derivative(i, frame, &mut j6).unwrap();
                }
                jac.frame_jacobian(i, &point, JacobianFrame::Body, &mut j6)
                    .unwrap();
                jac.frame_jacobian_derivative(i, &point, JacobianFrame::World, &mut j6)
                    .unwrap();
                jac.point_jacobian(i, &point, &mut j3).unwrap();
                jac.point_jacobian_derivative(i, &point, &mut j3).unwrap();
                jac.point_jacobian_tr_mul_add(i, &point, &point, &mut grad)
                    .unwrap();
            }
            center_of_mass(&model, &mut data, &q, Some(&v)).unwrap();
            cen.com_jacobian(&model, &mut data, &q, &mut j3).unwrap();
            cen.compute(&model, &mut data, &q, &v).unwrap();
            cen.angular_momentum_jacobian(&mut j3).unwrap();
            cen.ag_bias().unwrap();
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
