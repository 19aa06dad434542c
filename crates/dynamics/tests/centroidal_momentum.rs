//! `centroidal_momentum` (CoM and `h_G` from the forward-dynamics first pass, rotors from
//! their carriers) against the centroidal momentum matrix route `h_G = A_G v` of
//! `Centroidal::compute` (full kinematics, spun rotor poses) on Lola-like chains whose rotors
//! are mostly spin-invariant (fast path) and one in four generic (general path), and on
//! random trees with coupled drive-train parts; plus its error cases.

#[allow(unused_imports)]
mod loop_support;
mod rotor_support;

use biped_dynamics::{
    centroidal_momentum, centroidal_momentum_current, forward_kinematics, Centroidal, Data,
    DynamicsError, JacobianError, Model,
};
use loop_support::{random_q, random_vec, rng};
use proptest::prelude::*;

/// Both routes agree at a random state of `model`; returns the momentum's norm.
fn check(model: &Model, seed: u64) -> f64 {
    let mut r = rng(seed);
    let q = random_q(model, &mut r);
    let v = random_vec(model.nv(), 3.0, &mut r);
    let mut data = Data::new(model);
    let s = centroidal_momentum(model, &mut data, &q, &v).unwrap();
    let mut c = Centroidal::new(model);
    c.compute(model, &mut Data::new(model), &q, &v).unwrap();
    let h = c.momentum().unwrap();
    let scale = 1.0 + h.ang.norm() + h.lin.norm();
    assert!(
        (s.mass - c.mass()).abs() < 1e-12 * c.mass(),
        "seed {seed}: mass"
    );
    assert!(
        (s.com - c.com()).norm() < 1e-12,
        "seed {seed}: {} vs {}",
        s.com,
        c.com()
    );
    let (da, dl) = (
        (s.momentum.ang - h.ang).norm(),
        (s.momentum.lin - h.lin).norm(),
    );
    assert!(
        da < 1e-11 * scale,
        "seed {seed}: L_G {} vs {}",
        s.momentum.ang,
        h.ang
    );
    assert!(
        dl < 1e-11 * scale,
        "seed {seed}: p {} vs {}",
        s.momentum.lin,
        h.lin
    );
    h.ang.norm()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]
    /// Harmonic Drive chains (fast and general rotors mixed).
    #[test]
    fn rotor_chains_match_ag_v(seed in 0u64..100_000, n in 1usize..9) {
        let model = rotor_support::harmonic_drive_chain(seed, n);
        prop_assert!(check(&model, seed ^ 0xc0de) > 1e-6);
    }
}

#[test]
fn coupled_trees_match_ag_v() {
    for seed in 0..20 {
        let model =
            loop_support::random_loop_model(seed, 4 + seed as usize % 8, true, |rng, ins| {
                loop_support::rotor(rng, ins)
            });
        check(&model, seed);
    }
}

#[test]
fn needs_current_first_pass() {
    let model = rotor_support::harmonic_drive_chain(3, 4);
    let mut data = Data::new(&model);
    let mut r = rng(1);
    let q = random_q(&model, &mut r);
    let v = random_vec(model.nv(), 1.0, &mut r);
    let not_current = Err(JacobianError::Dynamics(DynamicsError::KinematicsNotCurrent));
    assert_eq!(centroidal_momentum_current(&model, &data), not_current);
    let a = centroidal_momentum(&model, &mut data, &q, &v).unwrap();
    assert_eq!(centroidal_momentum_current(&model, &data), Ok(a));
    let a0 = nalgebra::DVector::zeros(model.nv());
    forward_kinematics(&model, &mut data, &q, &v, &a0).unwrap();
    assert_eq!(centroidal_momentum_current(&model, &data), not_current);
    let mut bad = v.clone();
    bad[0] = f64::NAN;
    assert!(centroidal_momentum(&model, &mut data, &q, &bad).is_err());
    let short = Data::new(&rotor_support::harmonic_drive_chain(3, 2));
    assert!(centroidal_momentum_current(&model, &short).is_err());
}
