//! The hot paths allocate nothing once `Data` and the Jacobian/centroidal workspaces exist
//! (counting global allocator).

mod core_support;

use biped_dynamics::{
    center_of_mass, forward_dynamics, forward_kinematics, inverse_dynamics, mass_matrix, on,
    Algorithm, Centroidal, Data, Force, JacobianFrame, Jacobians,
};
use biped_test_support::alloc::{allocations, Counting};
use core_support::*;
use nalgebra::{DMatrix, DVector, Vector3};

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
        let before = allocations();
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
        let after = allocations();
        assert_eq!(
            after - before,
            0,
            "seed {seed}: {} allocations",
            after - before
        );
    }
}

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
        let before = allocations();
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
        let after = allocations();
        assert_eq!(
            after - before,
            0,
            "seed {seed}: {} allocations",
            after - before
        );
    }
}
