//! The thesis-literal reference O(n) algorithm (`dynamics::reference`, Algorithms 2.1-2.4)
//! against the fast O(n) path, CRBA + Cholesky and sparse LTL: Dill(n), random trees with
//! every joint type, random trees with loop sub-systems (geared rotors, linear gears, four-bar
//! couplers), and the G1 URDF floating and fixed, with and without motor rotors. Also the body
//! accelerations of Algorithm 2.4 against the fast path's.

mod core_support;
mod reference_support;
// The random trees with loops; it loads `core_support` again for itself (its items are private).
#[allow(clippy::duplicate_mod)]
mod loop_support;

use biped_dynamics::dynamics::reference::kinds::{fast_member_kinds, MemberKind};
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{dill::dill, Force, JointModel, Model, RotorSpec, Wrench};
use core_support::{random_model, random_q, random_vec, rng, TreeOptions};
use nalgebra::{DVector, Vector3};
use proptest::prelude::*;
use rand::rngs::StdRng;
use reference_support::deviation;
use std::collections::BTreeSet;

/// Tolerance of every comparison (relative, max norm).
const TOL: f64 = 1e-9;

/// Random `(q, v, tau, fext)`.
fn state(
    model: &Model,
    rng: &mut StdRng,
) -> (DVector<f64>, DVector<f64>, DVector<f64>, Vec<Wrench>) {
    let q = random_q(model, rng);
    let v = random_vec(model.nv(), 2.0, rng);
    let tau = random_vec(model.nv(), 5.0, rng);
    let fext = (0..model.nbodies())
        .map(|_| {
            let (t, f) = (random_vec(3, 1.0, rng), random_vec(3, 1.0, rng));
            Force::new(
                Vector3::new(t[0], t[1], t[2]),
                Vector3::new(f[0], f[1], f[2]),
            )
        })
        .collect();
    (q, v, tau, fext)
}

/// [`deviation`] at `n` random states, with and without external wrenches.
fn check(model: &Model, seed: u64, n: usize) -> f64 {
    let mut rng = rng(seed);
    let mut worst: f64 = 0.0;
    for k in 0..n {
        let (q, v, tau, fext) = state(model, &mut rng);
        let fext = (k % 2 == 1).then_some(fext.as_slice());
        worst = worst.max(deviation(model, &q, &v, &tau, fext));
    }
    worst
}

/// The G1 URDF, floating or fixed, optionally with a motor rotor on every revolute joint.
fn g1(floating: bool, rotors: bool) -> Model {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
    let model = load_file(
        path,
        &UrdfOptions {
            floating,
            ..UrdfOptions::default()
        },
    )
    .expect("bundled URDF")
    .model;
    if !rotors {
        return model;
    }
    let revolute = |&i: &usize| matches!(model.bodies()[i].joint(), JointModel::Revolute { .. });
    let specs: Vec<RotorSpec> = (0..model.nbodies())
        .filter(revolute)
        .enumerate()
        .map(|(k, i)| RotorSpec::from_armature(&model, i, 10.0 + k as f64, 0.01).expect("rotor"))
        .collect();
    model.with_geared_rotors(&specs).expect("rotors")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn dill_matches_the_fast_paths(seed in any::<u64>(), n in 1u32..6) {
        let model = dill(n).expect("dill");
        let dev = check(&model, seed, 2);
        prop_assert!(dev < TOL, "Dill({n}) {dev:e}");
    }

    #[test]
    fn random_trees_match_the_fast_paths(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions::default());
        let dev = check(&model, seed ^ 1, 2);
        prop_assert!(dev < TOL, "tree {n} {dev:e}");
    }

    #[test]
    fn loop_subsystems_match_the_fast_paths(seed in any::<u64>(), n in 3usize..24) {
        let model = loop_support::random_loop_model(seed, n, seed % 2 == 0, loop_support::random_coupling);
        let dev = check(&model, seed ^ 2, 2);
        prop_assert!(dev < TOL, "loops {n}, {} sub-systems: {dev:e}", model.subsystems().len());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn g1_matches_the_fast_paths(seed in any::<u64>(), floating: bool, rotors: bool) {
        let model = g1(floating, rotors);
        let dev = check(&model, seed, 2);
        prop_assert!(dev < TOL, "G1 floating {floating} rotors {rotors}: {dev:e}");
    }
}

/// The member kinds of the fast path the models above exercise.
#[test]
fn member_kinds_covered() {
    let mut kinds = BTreeSet::new();
    for seed in 0..40 {
        let model = loop_support::random_loop_model(
            seed,
            4 + seed as usize % 20,
            seed % 2 == 0,
            loop_support::random_coupling,
        );
        kinds.extend(fast_member_kinds(&model).into_iter().map(|(_, k)| k));
    }
    kinds.extend(
        fast_member_kinds(&g1(true, true))
            .into_iter()
            .map(|(_, k)| k),
    );
    println!("member kinds: {kinds:?}");
    for k in [
        MemberKind::Rigid,
        MemberKind::General,
        MemberKind::AxialGeared,
        MemberKind::Link,
    ] {
        assert!(kinds.contains(&k), "{k:?} not exercised: {kinds:?}");
    }
}

/// Largest deviations per model family (printed with `--nocapture`).
#[test]
fn largest_deviations() {
    let mut dill_dev: f64 = 0.0;
    for n in 1..=6 {
        dill_dev = dill_dev.max(check(&dill(n).expect("dill"), n.into(), 4));
    }
    let mut tree_dev: f64 = 0.0;
    let mut loop_dev: f64 = 0.0;
    let mut subsystems = 0;
    for seed in 0..100 {
        let n = 2 + seed as usize % 30;
        tree_dev = tree_dev.max(check(
            &random_model(seed, n, TreeOptions::default()),
            seed,
            2,
        ));
        let model = loop_support::random_loop_model(
            seed,
            n + 2,
            seed % 2 == 0,
            loop_support::random_coupling,
        );
        subsystems += model.subsystems().len();
        loop_dev = loop_dev.max(check(&model, seed, 2));
    }
    let mut g1_dev: f64 = 0.0;
    for (floating, rotors) in [(false, false), (true, false), (false, true), (true, true)] {
        g1_dev = g1_dev.max(check(&g1(floating, rotors), 5, 10));
    }
    println!("Dill {dill_dev:e}, trees {tree_dev:e}, loops {loop_dev:e} ({subsystems} sub-systems), G1 {g1_dev:e}");
    for dev in [dill_dev, tree_dev, loop_dev, g1_dev] {
        assert!(dev < TOL, "{dev:e}");
    }
}
