//! Reuse of the forward-dynamics kinematics: `forward_dynamics_kinematics` at a `(q, v)`
//! bitwise equal to the one `data` holds skips the pass, and every result is then
//! bit-identical to a fresh `Data`; any other `(q, v)` (one ulp apart) or an intervening
//! kinematics call recomputes. Whether the pass ran is observed by poisoning public kinematic
//! fields between the calls (a skipped pass leaves the poison, a run overwrites it).
//! Models: Lola-like Harmonic Drive chains (spin-invariant rotors, whose skipped kinematics
//! the CRBA/sparse solves complete from the stored `q, v`) and random trees with geared rotors.

mod loop_support;
mod rotor_support;

use biped_dynamics::dynamics::forward_dynamics_kinematics_current as current;
use biped_dynamics::{
    center_of_mass, centroidal_momentum, centroidal_momentum_current, forward_dynamics,
    forward_dynamics_kinematics, forward_dynamics_solve, forward_kinematics, inverse_dynamics,
    mass_matrix, nearby_state, update_placements, Algorithm, Data, DynamicsError, Model,
};
use loop_support::*;
use nalgebra::{DVector, Vector3};

const ALGOS: [Algorithm; 3] = [Algorithm::On, Algorithm::Crba, Algorithm::Sparse];
const POISON: f64 = 1234.5;

/// Test models: harmonic-drive chains and random geared-rotor trees.
fn models() -> Vec<(u64, Model)> {
    let mut out: Vec<(u64, Model)> = (0..4)
        .map(|s| (s, rotor_support::harmonic_drive_chain(s, 3 + s as usize)))
        .collect();
    out.extend((0..4).map(|s| {
        (
            50 + s,
            random_loop_model(50 + s, 6 + 2 * s as usize, true, rotor),
        )
    }));
    out
}

/// Random `(q, v, tau)` for `model`.
fn state(model: &Model, seed: u64) -> (DVector<f64>, DVector<f64>, DVector<f64>) {
    let mut rng = rng(seed);
    let q = random_q(model, &mut rng);
    let v = random_vec(model.nv(), 2.0, &mut rng);
    (q, v, random_vec(model.nv(), 5.0, &mut rng))
}

/// `qddot` by `algo` on a fresh workspace.
fn fresh(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    algo: Algorithm,
) -> DVector<f64> {
    let mut d = Data::new(model);
    forward_dynamics(model, &mut d, q, v, tau, None, algo)
        .unwrap()
        .clone()
}

/// Bitwise equality of two vectors.
fn same(a: &DVector<f64>, b: &DVector<f64>) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// Overwrites the world positions and velocities of every body with a marker.
fn poison(data: &mut Data) {
    data.world_pos
        .iter_mut()
        .for_each(|p| *p = Vector3::repeat(POISON));
    data.vel
        .iter_mut()
        .for_each(|m| m.lin = Vector3::repeat(POISON));
}

/// True if no link body carries the marker (the pass ran over all of them).
fn recomputed(model: &Model, data: &Data) -> bool {
    rotor_support::link_bodies(model)
        .into_iter()
        .all(|i| data.world_pos[i].x != POISON && data.vel[i].lin.x != POISON)
}

/// `q` or `v` with entry `k` moved by one ulp.
fn ulp(w: &DVector<f64>, k: usize) -> DVector<f64> {
    let mut w = w.clone();
    w[k] = f64::from_bits(w[k].to_bits() + 1);
    w
}

#[test]
fn reused_pass_gives_bit_identical_results() {
    for (seed, model) in models() {
        let (q, v, tau) = state(&model, seed);
        let mut data = Data::new(&model);
        forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
        forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).unwrap();
        let tau2 = tau.map(|x| 0.5 - x);
        // The CRBA/sparse solves complete the rotors' kinematics at the stored (q, v): the
        // pass stays reusable, also for a following O(n) solve.
        for algo in ALGOS.into_iter().chain([Algorithm::On]) {
            let kept = (data.world_pos.clone(), data.vel.clone());
            poison(&mut data);
            forward_dynamics_kinematics(&model, &mut data, &q.clone(), &v.clone()).unwrap();
            assert_eq!(data.world_pos[0].x, POISON, "seed {seed}: pass not skipped");
            // Restore the poisoned fields (the skipped pass relies on them).
            (data.world_pos, data.vel) = kept;
            let got = forward_dynamics_solve(&model, &mut data, &tau2, None, algo).unwrap();
            assert!(
                same(got, &fresh(&model, &q, &v, &tau2, algo)),
                "seed {seed} {algo:?}"
            );
            let h = centroidal_momentum_current(&model, &data).unwrap();
            let h0 = centroidal_momentum(&model, &mut Data::new(&model), &q, &v).unwrap();
            assert_eq!(h, h0, "seed {seed} {algo:?}: centroidal momentum");
        }
    }
}

#[test]
fn one_ulp_in_q_or_v_recomputes() {
    for (seed, model) in models() {
        let (q, v, tau) = state(&model, seed + 7);
        let mut data = Data::new(&model);
        assert!(
            !current(&data, q.as_slice(), v.as_slice()),
            "fresh data holds no pass"
        );
        let last_q = model.nq() - 1;
        let cases = [
            (ulp(&q, 0), v.clone()),
            (ulp(&q, last_q), v.clone()),
            (q.clone(), ulp(&v, 0)),
            (q.clone(), ulp(&v, model.nv() - 1)),
        ];
        for (q1, v1) in cases {
            forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
            assert!(current(&data, q.as_slice(), v.as_slice()));
            assert!(!current(&data, q1.as_slice(), v1.as_slice()));
            poison(&mut data);
            forward_dynamics_kinematics(&model, &mut data, &q1, &v1).unwrap();
            assert!(recomputed(&model, &data), "seed {seed}: stale pass reused");
            let got = forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).unwrap();
            assert!(
                same(got, &fresh(&model, &q1, &v1, &tau, Algorithm::On)),
                "seed {seed}"
            );
        }
    }
}

#[test]
fn intervening_kinematics_calls_force_a_new_pass() {
    for (seed, model) in models() {
        let (q, v, tau) = state(&model, seed + 11);
        let (q2, v2, a2) = state(&model, seed + 12);
        let expect = fresh(&model, &q, &v, &tau, Algorithm::On);
        let others: [&dyn Fn(&mut Data); 5] = [
            &|d| forward_kinematics(&model, d, &q2, &v2, &a2).unwrap(),
            &|d| update_placements(&model, d, &q2).unwrap(),
            &|d| {
                mass_matrix(&model, d, &q2).unwrap();
            },
            &|d| {
                inverse_dynamics(&model, d, &q2, &v2, &a2, None).unwrap();
            },
            &|d| {
                center_of_mass(&model, d, &q2, Some(&v2)).unwrap();
            },
        ];
        for (k, other) in others.iter().enumerate() {
            let mut data = Data::new(&model);
            forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
            other(&mut data);
            assert!(!current(&data, q.as_slice(), v.as_slice()));
            assert_eq!(
                forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).cloned(),
                Err(DynamicsError::KinematicsNotCurrent)
            );
            forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
            let got = forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).unwrap();
            assert!(
                same(got, &expect),
                "seed {seed}: call {k} left a stale pass"
            );
        }
    }
}

#[test]
fn bad_inputs_are_still_rejected_and_keep_the_pass() {
    let model = rotor_support::harmonic_drive_chain(9, 5);
    let (q, v, tau) = state(&model, 9);
    let mut data = Data::new(&model);
    forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
    let (mut qn, mut vn) = (q.clone(), v.clone());
    qn[7] = f64::NAN;
    vn[2] = f64::NAN;
    assert!(forward_dynamics_kinematics(&model, &mut data, &qn, &v).is_err());
    assert!(forward_dynamics_kinematics(&model, &mut data, &q, &vn).is_err());
    let short = DVector::zeros(model.nv() - 1);
    assert!(forward_dynamics_kinematics(&model, &mut data, &q, &short).is_err());
    // Rejected calls touch nothing: the pass for (q, v) is still current and reused.
    poison(&mut data);
    forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
    assert_eq!(data.world_pos[0].x, POISON);
    forward_dynamics_kinematics(&model, &mut data, &q, &ulp(&v, 0)).unwrap();
    forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
    let got = forward_dynamics_solve(&model, &mut data, &tau, None, Algorithm::On).unwrap();
    assert!(same(got, &fresh(&model, &q, &v, &tau, Algorithm::On)));
}

#[test]
fn nearby_state_forces_a_new_pass_even_at_rest() {
    for (seed, model) in models() {
        let (q, v, _) = state(&model, seed);
        for v in [v.clone(), DVector::zeros(model.nv())] {
            let (q2, v2) = nearby_state(&model, &q, &v).unwrap();
            let mut data = Data::new(&model);
            forward_dynamics_kinematics(&model, &mut data, &q, &v).unwrap();
            assert!(!current(&data, q2.as_slice(), v2.as_slice()));
            poison(&mut data);
            forward_dynamics_kinematics(&model, &mut data, &q2, &v2).unwrap();
            assert!(
                recomputed(&model, &data),
                "seed {seed}: the nearby state reused the pass"
            );
        }
    }
}
