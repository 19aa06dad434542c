//! Two-phase forward dynamics (`forward_dynamics_kinematics` then `forward_dynamics_solve`)
//! against the one-call `forward_dynamics`, on random trees with geared rotors and on
//! Lola-like chains whose links carry Harmonic Drive rotors (sub-systems, section 2.6-2.9).

mod loop_support;
mod rotor_support;

use biped_dynamics::{
    forward_dynamics, forward_dynamics_kinematics, forward_dynamics_solve, forward_kinematics,
    update_placements, Algorithm, Data, DynamicsError, Model, Wrench,
};
use loop_support::*;
use nalgebra::{DVector, Vector3};
use rand::rngs::StdRng;
use rand::Rng;

const ALGOS: [Algorithm; 3] = [Algorithm::On, Algorithm::Crba, Algorithm::Sparse];

/// Random finite wrenches, one per body.
fn random_wrenches(model: &Model, rng: &mut StdRng) -> Vec<Wrench> {
    let mut r = || Vector3::new(rng.random(), rng.random(), rng.random()) * 4.0;
    (0..model.nbodies())
        .map(|_| Wrench::new(r(), r()))
        .collect()
}

/// Both phases equal the one-call result exactly; a repeated solve with another `tau` equals a
/// fresh one-call evaluation; link world poses after phase one equal forward kinematics'.
fn check_model(model: &Model, seed: u64) {
    let mut rng = rng(seed);
    let (mut one, mut two) = (Data::new(model), Data::new(model));
    let q = random_q(model, &mut rng);
    let v = random_vec(model.nv(), 2.0, &mut rng);
    let (tau, tau2) = (
        random_vec(model.nv(), 5.0, &mut rng),
        random_vec(model.nv(), 5.0, &mut rng),
    );
    let fext = random_wrenches(model, &mut rng);
    for algo in ALGOS {
        let expect = forward_dynamics(model, &mut one, &q, &v, &tau, Some(&fext), algo)
            .unwrap()
            .clone();
        forward_dynamics_kinematics(model, &mut two, &q, &v).unwrap();
        let got = forward_dynamics_solve(model, &mut two, &tau, Some(&fext), algo).unwrap();
        assert_eq!(&expect, got, "seed {seed} {algo:?}");
        let again = forward_dynamics_solve(model, &mut two, &tau2, None, algo)
            .unwrap()
            .clone();
        let fresh = forward_dynamics(model, &mut one, &q, &v, &tau2, None, algo).unwrap();
        assert_eq!(
            rel_diff(fresh, &again),
            0.0,
            "seed {seed} {algo:?}: repeated solve"
        );
    }
    forward_dynamics_kinematics(model, &mut two, &q, &v).unwrap();
    let a = DVector::zeros(model.nv());
    forward_kinematics(model, &mut one, &q, &v, &a).unwrap();
    for i in rotor_support::link_bodies(model) {
        assert!(
            (one.world_rot[i] - two.world_rot[i]).amax() < 1e-12,
            "body {i}"
        );
        assert!(
            (one.world_pos[i] - two.world_pos[i]).amax() < 1e-12,
            "body {i}"
        );
        assert!((one.vel[i].to_vector() - two.vel[i].to_vector()).amax() < 1e-10);
    }
}

#[test]
fn two_phases_equal_one_call_on_random_rotor_trees() {
    for seed in 0..20 {
        let model = random_loop_model(seed, 4 + seed as usize % 12, seed % 2 == 0, rotor);
        check_model(&model, seed);
    }
}

#[test]
fn two_phases_equal_one_call_on_harmonic_drive_chains() {
    for seed in 0..12 {
        let model = rotor_support::harmonic_drive_chain(seed, 3 + seed as usize % 6);
        check_model(&model, 100 + seed);
    }
}

#[test]
fn solve_without_current_kinematics_is_an_error() {
    let model = rotor_support::harmonic_drive_chain(3, 4);
    let mut data = Data::new(&model);
    let mut rng = rng(7);
    let q = random_q(&model, &mut rng);
    let v = random_vec(model.nv(), 1.0, &mut rng);
    let tau = random_vec(model.nv(), 1.0, &mut rng);
    let stale = Err(DynamicsError::KinematicsNotCurrent);
    assert_eq!(
        forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).cloned(),
        stale
    );
    forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
    update_placements(&model, &mut data, &q).unwrap();
    assert_eq!(
        forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::Crba).cloned(),
        stale
    );
    // Bad inputs to either phase are typed errors, never panics.
    let short = DVector::zeros(model.nv() - 1);
    assert!(forward_dynamics_kinematics(&model, &mut data, &q, &short).is_err());
    forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
    assert!(forward_dynamics_solve(&model, &mut data, &short, None, Algorithm::On).is_err());
    let mut nan = tau.clone();
    nan[0] = f64::NAN;
    assert!(forward_dynamics_solve(&model, &mut data, &nan, None, Algorithm::On).is_err());
    let few = vec![Wrench::zero(); model.nbodies() - 1];
    assert!(forward_dynamics_solve(&model, &mut data, &tau, Some(&few), Algorithm::On).is_err());
}
