//! `J_L`, `J_Lz`, `L_z`, its rate and `I_zz^CoG` on Lola Type 2 against independent
//! references: (7.1) summed over bodies from finite differences of body poses, central
//! differences of `L_z` along a trajectory, and the momentum of a rigid rotation.

#[path = "momentum_util.rs"]
mod util;

use biped_control::momentum::{
    vertical_inertia, vertical_momentum_rate, LzRate, MomentumError, VerticalMomentum,
};
use biped_dynamics::{integrate, update_placements, Data, Model};
use nalgebra::{DVector, Matrix3, Rotation3, Vector3};
use util::{rel, Lola};

/// Body CoM positions and rotations at `q`.
fn poses(model: &Model, data: &mut Data, q: &DVector<f64>) -> Vec<(Vector3<f64>, Matrix3<f64>)> {
    update_placements(model, data, q).unwrap();
    model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let r = data.world_rot[i];
            (data.world_pos[i] + r * b.inertia().com(), r)
        })
        .collect()
}

/// Angular momentum about the CoM by (7.1): body velocities from central differences of the
/// poses along `q (+) v t`, no Jacobian involved.
fn momentum_by_poses(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Vector3<f64> {
    // 1e-5: the coupled drive bodies are solved to a tolerance, so smaller steps lose digits.
    let h = 1e-5;
    let p0 = poses(model, data, q);
    let pp = poses(model, data, &integrate(model, q, v, h).unwrap());
    let pm = poses(model, data, &integrate(model, q, v, -h).unwrap());
    let masses: Vec<f64> = model.bodies().iter().map(|b| b.inertia().mass()).collect();
    let m: f64 = masses.iter().sum();
    let com = p0
        .iter()
        .zip(&masses)
        .map(|(p, mi)| p.0 * *mi)
        .sum::<Vector3<f64>>()
        / m;
    let vel: Vec<Vector3<f64>> = pp
        .iter()
        .zip(&pm)
        .map(|(a, b)| (a.0 - b.0) / (2.0 * h))
        .collect();
    let com_vel = vel
        .iter()
        .zip(&masses)
        .map(|(v, mi)| v * *mi)
        .sum::<Vector3<f64>>()
        / m;
    let mut l = Vector3::zeros();
    for (i, body) in model.bodies().iter().enumerate() {
        let rot = Rotation3::from_matrix_unchecked(pp[i].1 * pm[i].1.transpose());
        let omega = rot.scaled_axis() / (2.0 * h);
        let r = p0[i].1;
        let inertia = r * body.inertia().inertia_about_com() * r.transpose();
        l += inertia * omega + (p0[i].0 - com).cross(&(vel[i] - com_vel)) * masses[i];
    }
    l
}

#[test]
fn jacobian_matches_momentum_from_pose_differences() {
    let mut s = Lola::new(1);
    let mut vm = VerticalMomentum::new(s.model());
    for _ in 0..10 {
        let (q, v) = s.state();
        let model = s.lola.model.clone();
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
            .unwrap();
        let reference = momentum_by_poses(&model, &mut s.data, &q, &v);
        let l: Vector3<f64> = (vm.jacobian() * &v).fixed_rows::<3>(0).into();
        assert!(
            (l - reference).norm() < 1e-5 * reference.norm().max(1.0),
            "{l} vs {reference}"
        );
        let lz = vm.lz(&v).unwrap();
        assert!(rel(lz, reference.z) < 1e-5, "{lz} vs {}", reference.z);
        assert_eq!(vm.jacobian_z().len(), model.nv());
    }
}

#[test]
fn lz_equals_centroidal_momentum() {
    let mut s = Lola::new(2);
    let mut vm = VerticalMomentum::new(s.model());
    let model = s.lola.model.clone();
    let (q, v) = s.state();
    s.centroidal.compute(&model, &mut s.data, &q, &v).unwrap();
    vm.update(&s.centroidal).unwrap();
    let h = s.centroidal.momentum().unwrap();
    assert!(rel(vm.lz(&v).unwrap(), h.ang.z) < 1e-12);
}

#[test]
fn analytic_rate_matches_central_differences_and_cycle_difference() {
    let mut s = Lola::new(3);
    let model = s.lola.model.clone();
    let mut vm = VerticalMomentum::new(&model);
    for _ in 0..5 {
        let (q, v) = s.state();
        let qdd = s.vector(model.nv());
        s.centroidal.compute(&model, &mut s.data, &q, &v).unwrap();
        vm.update(&s.centroidal).unwrap();
        let analytic = vertical_momentum_rate(&s.centroidal, vm.jacobian_z(), &qdd).unwrap();
        // L_z(t) along q(t) = q (+) v t (constant v), plus J_Lz qdd for the acceleration part.
        let mut lz_at = |t: f64| {
            let qt = integrate(&model, &q, &v, t).unwrap();
            vm.compute(&model, &mut s.data, &mut s.centroidal, &qt)
                .unwrap();
            vm.lz(&(&v + &qdd * t)).unwrap()
        };
        let h = 1e-5;
        let central = (lz_at(h) - lz_at(-h)) / (2.0 * h);
        assert!(rel(analytic, central) < 1e-5, "{analytic} vs {central}");
        // The cycle difference at 1 kHz is first order: within O(dt) of the analytic rate.
        let dt = 1e-3;
        let mut rate = LzRate::new(dt).unwrap();
        assert_eq!(rate.update(lz_at(0.0)).unwrap(), 0.0);
        let fd = rate.update(lz_at(dt)).unwrap();
        let second = (lz_at(2.0 * dt) - 2.0 * lz_at(dt) + lz_at(0.0)) / (dt * dt);
        assert!((fd - analytic).abs() <= 0.5 * dt * second.abs() * 1.5 + 1e-6);
    }
}

#[test]
fn vertical_inertia_equals_momentum_of_rigid_rotation() {
    let mut s = Lola::new(4);
    let model = s.lola.model.clone();
    for _ in 0..5 {
        let (q, _) = s.state();
        let izz = vertical_inertia(&model, &mut s.data, &q).unwrap();
        // Base twist (body coordinates, [lin; ang]) = rotation about world z, joints locked.
        let rot = s.data.world_rot[0];
        let mut v = DVector::zeros(model.nv());
        let w = rot.transpose() * Vector3::z();
        v.fixed_rows_mut::<3>(3).copy_from(&w);
        s.centroidal.compute(&model, &mut s.data, &q, &v).unwrap();
        let lz = s.centroidal.momentum().unwrap().ang.z;
        assert!(izz > 0.0 && rel(izz, lz) < 1e-10, "{izz} vs {lz}");
    }
}

#[test]
fn bad_inputs_are_typed_errors() {
    let mut s = Lola::new(5);
    let model = s.lola.model.clone();
    let mut vm = VerticalMomentum::new(&model);
    let fresh = biped_dynamics::Centroidal::new(&model);
    assert!(matches!(vm.update(&fresh), Err(MomentumError::Jacobian(_))));
    let (q, _) = s.state();
    vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
        .unwrap();
    assert!(matches!(
        vm.lz(&DVector::zeros(3)),
        Err(MomentumError::Dimension { .. })
    ));
    let mut nan = DVector::zeros(model.nv());
    nan[4] = f64::NAN;
    assert!(matches!(vm.lz(&nan), Err(MomentumError::NonFinite { .. })));
    let bad_q = DVector::zeros(model.nq());
    assert!(vm
        .compute(&model, &mut s.data, &mut s.centroidal, &bad_q)
        .is_err());
    assert!(vertical_inertia(&model, &mut s.data, &DVector::zeros(2)).is_err());
    assert!(matches!(
        LzRate::new(0.0),
        Err(MomentumError::InvalidParameter { .. })
    ));
    let mut rate = LzRate::new(1e-3).unwrap();
    assert!(rate.update(f64::INFINITY).is_err());
    let jz = vm.jacobian_z().clone();
    assert!(vertical_momentum_rate(&s.centroidal, &jz, &DVector::zeros(model.nv())).is_err());
}
