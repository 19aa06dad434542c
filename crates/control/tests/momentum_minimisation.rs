//! Minimisation (7.13)-(7.15) on Lola Type 2: the in-place weight `delta E + J_Lz^T J_Lz`
//! inverts like the dense matrix and like the closed form (7.15); a RMRC step with it has no
//! larger `|L_z|` than with `W = E` (independent dense solve), and usually much smaller.

#[path = "momentum_util.rs"]
mod util;

use biped_control::momentum::{MomentumError, MomentumMinimisation, VerticalMomentum};
use biped_control::Weight;
use biped_dynamics::{JacobianFrame, Jacobians};
use nalgebra::{DMatrix, DVector, Vector3};
use proptest::prelude::*;
use util::Lola;

/// Task Jacobian after Table 4.2: both sole frames (6 + 6), CoM (3), torso orientation (3),
/// pelvis rotation/adduction and toe joints (4): 22 of 31 DoFs, the arms and head redundant.
fn task_jacobian(s: &mut Lola, q: &DVector<f64>) -> DMatrix<f64> {
    let model = s.lola.model.clone();
    let nv = model.nv();
    let mut jac = Jacobians::new(&model);
    jac.compute(&model, &mut s.data, q).unwrap();
    let mut out = DMatrix::zeros(22, nv);
    let mut frame = DMatrix::zeros(6, nv);
    for (k, body) in ["l_sole", "r_sole"].iter().enumerate() {
        let id = model.body_id(body).unwrap();
        let f = JacobianFrame::WorldAligned;
        jac.frame_jacobian(id, &Vector3::zeros(), f, &mut frame)
            .unwrap();
        out.rows_mut(6 * k, 6).copy_from(&frame);
    }
    let mut com = DMatrix::zeros(3, nv);
    s.centroidal
        .com_jacobian(&model, &mut s.data, q, &mut com)
        .unwrap();
    out.rows_mut(12, 3).copy_from(&com);
    let torso = model.body_id("torso").unwrap();
    let f = JacobianFrame::WorldAligned;
    jac.frame_jacobian(torso, &Vector3::zeros(), f, &mut frame)
        .unwrap();
    out.rows_mut(15, 3).copy_from(&frame.rows(0, 3));
    for (k, name) in ["pelvis_rotation", "torso", "l_toe", "r_toe"]
        .iter()
        .enumerate()
    {
        let j = model.joints().iter().find(|j| j.name == *name).unwrap();
        out[(18 + k, j.v_index)] = 1.0;
    }
    out
}

/// Dense RMRC `qdot = W^-1 J^T (J W^-1 J^T)^-1 xdot` (4.9) with a dense inverse of `W`.
fn dense_rmrc(w: &DMatrix<f64>, j: &DMatrix<f64>, xdot: &DVector<f64>) -> DVector<f64> {
    let winv = w.clone().try_inverse().unwrap();
    let b = j * &winv * j.transpose();
    &winv * j.transpose() * b.lu().solve(xdot).unwrap()
}

/// Same solve with `W^-1` applied column by column through `Weight::solve_into`.
fn weight_rmrc(w: &Weight, j: &DMatrix<f64>, xdot: &DVector<f64>) -> DVector<f64> {
    let n = j.ncols();
    let mut winv_jt = DMatrix::zeros(n, j.nrows());
    let mut out = DVector::zeros(n);
    for r in 0..j.nrows() {
        w.solve_into(&j.row(r).transpose(), &mut out).unwrap();
        winv_jt.set_column(r, &out);
    }
    let b = j * &winv_jt;
    &winv_jt * b.cholesky().unwrap().solve(xdot)
}

/// Closed-form prediction: with `W = delta E + a a^T` (`a = J_Lz^T`) the weighted solution is
/// `q_E + Z z` (`Z` an orthonormal null-space basis of `J`), minimising
/// `delta |z|^2 + (L_E + b^T z)^2` with `b = Z^T a`, so `L_z(W) = L_z(E) delta / (delta + |b|^2)`
/// and `|b|^2 = a^T N a` with the orthogonal projector `N = E - J^+ J`.
fn predicted_ratio(delta: f64, j: &DMatrix<f64>, a: &DVector<f64>) -> f64 {
    let n = j.ncols();
    let null = DMatrix::identity(n, n) - util::pinv(j) * j;
    delta / (delta + a.dot(&(null * a)))
}

#[test]
fn rmrc_with_momentum_weight_reduces_lz_as_predicted() {
    let mut s = Lola::new(21);
    let model = s.lola.model.clone();
    let nv = model.nv();
    let mut vm = VerticalMomentum::new(&model);
    let mut ratios = Vec::new();
    for _ in 0..20 {
        let (q, _) = s.state();
        let j = task_jacobian(&mut s, &q);
        let xdot = s.vector(j.nrows());
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
            .unwrap();
        let jlz = vm.jacobian_z();
        let plain = dense_rmrc(&DMatrix::identity(nv, nv), &j, &xdot);
        let lz_plain = jlz.dot(&plain);
        let mut previous = f64::INFINITY;
        for delta in [10.0, 0.5, 0.05, 1e-3] {
            let minimise = MomentumMinimisation::new(delta).unwrap();
            let mut w = minimise.weight(nv).unwrap();
            minimise.update(jlz, &mut w).unwrap();
            let dense_w = DMatrix::identity(nv, nv) * delta + jlz * jlz.transpose();
            let weighted = dense_rmrc(&dense_w, &j, &xdot);
            let fast = weight_rmrc(&w, &j, &xdot);
            assert!((&fast - &weighted).norm() < 1e-8 * weighted.norm().max(1.0));
            assert!(
                (&j * &weighted - &xdot).norm() < 1e-8,
                "tasks still tracked"
            );
            let lz_w = jlz.dot(&weighted);
            let expected = lz_plain * predicted_ratio(delta, &j, jlz);
            assert!(
                (lz_w - expected).abs() < 1e-8 * lz_plain.abs().max(1.0),
                "{lz_w} vs {expected}"
            );
            assert!(lz_w.abs() <= previous + 1e-12 && lz_w.abs() <= lz_plain.abs() + 1e-12);
            previous = lz_w.abs();
            if delta == 0.5 {
                ratios.push(lz_w.abs() / lz_plain.abs());
            }
        }
    }
    ratios.sort_by(|a, b| a.total_cmp(b));
    let median = ratios[ratios.len() / 2];
    println!("delta = 0.5: median |L_z(W)| / |L_z(E)| = {median:.3}");
}

#[test]
fn base_weight_variant_against_its_own_diagonal_reference() {
    let mut s = Lola::new(22);
    let model = s.lola.model.clone();
    let nv = model.nv();
    let d = DVector::from_fn(nv, |i, _| 1.0 + (i % 3) as f64);
    let minimise = MomentumMinimisation::with_base(0.5, d.clone()).unwrap();
    let mut w = minimise.weight(nv).unwrap();
    let mut vm = VerticalMomentum::new(&model);
    for _ in 0..10 {
        let (q, _) = s.state();
        let j = task_jacobian(&mut s, &q);
        let xdot = s.vector(j.nrows());
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
            .unwrap();
        minimise.update(vm.jacobian_z(), &mut w).unwrap();
        let jlz = vm.jacobian_z();
        let base = DMatrix::from_diagonal(&(&d * 0.5));
        let plain = dense_rmrc(&base, &j, &xdot);
        let weighted = weight_rmrc(&w, &j, &xdot);
        assert!(jlz.dot(&weighted).abs() <= jlz.dot(&plain).abs() + 1e-10);
    }
}

#[test]
fn update_is_in_place() {
    let mut s = Lola::new(23);
    let model = s.lola.model.clone();
    let minimise = MomentumMinimisation::new(0.5).unwrap();
    let mut w = minimise.weight(model.nv()).unwrap();
    let ptrs = |w: &Weight| match w {
        Weight::DiagonalRankOne { diag, u } => (diag.as_ptr(), u.as_ptr()),
        _ => unreachable!(),
    };
    let before = ptrs(&w);
    let mut vm = VerticalMomentum::new(&model);
    let (q, _) = s.state();
    vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
        .unwrap();
    minimise.update(vm.jacobian_z(), &mut w).unwrap();
    assert_eq!(before, ptrs(&w));
    let expected = DMatrix::identity(model.nv(), model.nv()) * 0.5
        + vm.jacobian_z() * vm.jacobian_z().transpose();
    assert!((w.to_dense(model.nv()) - expected).norm() < 1e-14);
}

#[test]
fn bad_parameters_are_typed_errors() {
    assert!(matches!(
        MomentumMinimisation::new(0.0),
        Err(MomentumError::InvalidParameter { .. })
    ));
    assert!(MomentumMinimisation::new(f64::NAN).is_err());
    assert!(MomentumMinimisation::with_base(0.5, DVector::from_element(3, -1.0)).is_err());
    let m = MomentumMinimisation::new(0.5).unwrap();
    let mut identity = Weight::Identity;
    assert!(m.update(&DVector::zeros(4), &mut identity).is_err());
    let mut w = m.weight(4).unwrap();
    assert!(matches!(
        m.update(&DVector::zeros(5), &mut w),
        Err(MomentumError::Dimension { .. })
    ));
    assert!(m
        .update(&DVector::from_element(4, f64::NAN), &mut w)
        .is_err());
    let based = MomentumMinimisation::with_base(0.5, DVector::from_element(3, 1.0)).unwrap();
    assert!(based.weight(4).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, failure_persistence: None, ..ProptestConfig::default() })]

    /// `W^-1 x` of the updated weight equals the dense inverse and the closed form (7.15).
    #[test]
    fn weight_inverse_matches_dense_and_closed_form(seed in 0u64..1000, delta in 0.01f64..10.0) {
        let mut s = Lola::new(seed);
        let model = s.lola.model.clone();
        let n = model.nv();
        let (q, _) = s.state();
        let x = s.vector(n);
        let mut vm = VerticalMomentum::new(&model);
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q).unwrap();
        let minimise = MomentumMinimisation::new(delta).unwrap();
        let mut w = minimise.weight(n).unwrap();
        minimise.update(vm.jacobian_z(), &mut w).unwrap();
        let mut fast = DVector::zeros(n);
        w.solve_into(&x, &mut fast).unwrap();
        let j = vm.jacobian_z();
        let dense = (DMatrix::identity(n, n) * delta + j * j.transpose()).try_inverse().unwrap();
        let closed = (DMatrix::identity(n, n) - j * j.transpose() / (delta + j.dot(j))) / delta;
        let scale = x.norm() / delta;
        prop_assert!((&fast - &dense * &x).norm() < 1e-10 * scale);
        prop_assert!((&fast - &closed * &x).norm() < 1e-10 * scale);
    }
}
