//! The spin-invariant Harmonic Drive rotor fast path of the O(n) algorithm (rotor dynamics in
//! the parent frame, no rotor kinematics) against CRBA and sparse LTL (which evaluate the spun
//! rotor poses) and RNEA as inverse, with external wrenches also on the rotors.

mod loop_support;
mod rotor_support;

use biped_dynamics::{inverse_dynamics, Data, Model, Wrench};
use loop_support::*;
use nalgebra::{DVector, Vector3};
use proptest::prelude::*;
use rand::Rng;

/// O(n), CRBA and sparse agree and RNEA inverts them at a random state of `model`.
fn check_state(model: &Model, seed: u64, with_fext: bool) {
    let mut rng = rng(seed);
    let mut data = Data::new(model);
    let q = random_q(model, &mut rng);
    let v = random_vec(model.nv(), 3.0, &mut rng);
    let tau = random_vec(model.nv(), 5.0, &mut rng);
    let mut r =
        || Vector3::new(rng.random(), rng.random(), rng.random()) * 2.0 - Vector3::repeat(1.0);
    let fext: Vec<Wrench> = (0..model.nbodies())
        .map(|_| Wrench::new(r(), r()))
        .collect();
    let fext = with_fext.then_some(fext.as_slice());
    let on = check_methods(seed, model, &mut data, &q, &v, &tau, fext);
    let back: DVector<f64> = inverse_dynamics(model, &mut data, &q, &v, &on, fext)
        .unwrap()
        .clone();
    assert!(
        rel_diff(&back, &tau) < 1e-9,
        "seed {seed}: RNEA(O(n)) {}",
        rel_diff(&back, &tau)
    );
}

#[test]
fn harmonic_drive_chains_all_methods_agree() {
    for seed in 0..30 {
        let model = rotor_support::harmonic_drive_chain(seed, 2 + seed as usize % 9);
        check_state(&model, seed, seed % 3 != 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Random chains and states, with and without external wrenches.
    #[test]
    fn fast_rotors_match_crba(seed in 0u64..100_000, n in 1usize..8, fext in any::<bool>()) {
        let model = rotor_support::harmonic_drive_chain(seed, n);
        check_state(&model, seed ^ 0x5eed, fext);
    }
}
