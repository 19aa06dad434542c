//! Criterion benchmarks of the Jacobian and centroidal computations on the bundled Unitree G1
//! (`data/g1_29dof_rev_1_0.urdf`) with a floating base: world columns (with and without
//! derivatives), a foot body Jacobian and its derivative, the CoM Jacobian, `A_G` / `J_L`
//! (position only, and with momentum and bias `Adot_G v`).

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{center_of_mass, Centroidal, Data, JacobianFrame, Jacobians, Model};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{DMatrix, DVector};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// The floating G1 with a fixed pseudo-random state and its foot body.
fn g1() -> (Model, DVector<f64>, DVector<f64>, usize) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
    let options = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let model = load_file(&path, &options).expect("URDF loads").model;
    let wave = |k: usize, f: f64| (f * (k as f64 + 1.0)).sin();
    let mut q = DVector::from_fn(model.nq(), |k, _| wave(k, 0.7));
    q.fixed_rows_mut::<4>(3).normalize_mut();
    let v = DVector::from_fn(model.nv(), |k, _| wave(k, 1.3));
    let foot = model
        .body_id("left_ankle_roll_link")
        .unwrap_or(model.nbodies() - 1);
    (model, q, v, foot)
}

/// All benchmarks of this file.
fn kinematics(c: &mut Criterion) {
    let (model, q, v, foot) = g1();
    let nv = model.nv();
    let mut data = Data::new(&model);
    let mut jac = Jacobians::new(&model);
    let mut cen = Centroidal::new(&model);
    let (mut j6, mut j3) = (DMatrix::zeros(6, nv), DMatrix::zeros(3, nv));
    let mut group = c.benchmark_group("kinematics_g1_floating");
    group
        .sample_size(50)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    group.bench_function("columns", |b| {
        b.iter(|| jac.compute(&model, &mut data, black_box(&q)).unwrap())
    });
    group.bench_function("columns_with_derivatives", |b| {
        b.iter(|| {
            jac.compute_with_derivatives(&model, &mut data, black_box(&q), black_box(&v))
                .unwrap()
        })
    });
    group.bench_function("body_jacobian_foot", |b| {
        b.iter(|| {
            jac.compute(&model, &mut data, black_box(&q)).unwrap();
            jac.body_jacobian(foot, JacobianFrame::WorldAligned, &mut j6)
                .unwrap();
            black_box(&j6);
        })
    });
    jac.compute(&model, &mut data, &q).unwrap();
    group.bench_function("body_jacobian_foot_extract_only", |b| {
        b.iter(|| {
            jac.body_jacobian(black_box(foot), JacobianFrame::Body, &mut j6)
                .unwrap();
            black_box(&j6);
        })
    });
    jac.compute_with_derivatives(&model, &mut data, &q, &v)
        .unwrap();
    group.bench_function("body_jacobian_derivative_foot_extract_only", |b| {
        b.iter(|| {
            jac.body_jacobian_derivative(black_box(foot), JacobianFrame::WorldAligned, &mut j6)
                .unwrap();
            black_box(&j6);
        })
    });
    group.bench_function("center_of_mass", |b| {
        b.iter(|| black_box(center_of_mass(&model, &mut data, black_box(&q), None).unwrap()))
    });
    group.bench_function("com_jacobian", |b| {
        b.iter(|| {
            cen.com_jacobian(&model, &mut data, black_box(&q), &mut j3)
                .unwrap();
            black_box(&j3);
        })
    });
    group.bench_function("centroidal_ag_jl", |b| {
        b.iter(|| {
            cen.compute_matrix(&model, &mut data, black_box(&q))
                .unwrap();
            cen.angular_momentum_jacobian(&mut j3).unwrap();
            black_box(&j3);
        })
    });
    group.bench_function("centroidal_ag_jl_bias", |b| {
        b.iter(|| {
            cen.compute(&model, &mut data, black_box(&q), black_box(&v))
                .unwrap();
            cen.angular_momentum_jacobian(&mut j3).unwrap();
            black_box((&j3, cen.ag_bias().unwrap()));
        })
    });
    group.finish();
}

criterion_group!(benches, kinematics);
criterion_main!(benches);
