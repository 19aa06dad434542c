//! The thesis-literal reference O(n) algorithm (`biped_dynamics::dynamics::reference`,
//! Algorithms 2.1-2.4, general kinematics for every sub-system member) against the fast O(n)
//! path, CRBA + Cholesky and sparse LTL on both Lola types with their loop sub-systems (Harmonic
//! Drive rotors, knee roller screws, ankle slider-cranks), and the fast-path member kinds these
//! models exercise.

use biped_dynamics::dynamics::reference::{self, kinds::fast_member_kinds, kinds::MemberKind};
use biped_dynamics::{forward_dynamics, Algorithm, Data, Force, Wrench};
use biped_robots::lola::{self, LolaModel, LolaType};
use nalgebra::{DVector, Vector3};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use std::collections::BTreeSet;

/// Tolerance of every comparison (relative, max norm).
const TOL: f64 = 1e-9;

/// `|a - b| / max(1, |a|, |b|)` in the max norm.
fn rel_diff(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    (a - b).amax() / a.amax().max(b.amax()).max(1.0)
}

/// Largest relative deviation of the reference from the three fast methods at one random
/// state (external wrenches on every body if `wrenches`).
fn deviation(lm: &LolaModel, seed: u64, wrenches: bool) -> f64 {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let m = &lm.model;
    let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
    let tau = DVector::from_fn(m.nv(), |_, _| rng.random_range(-20.0..20.0));
    let mut r3 = || Vector3::from_fn(|_, _| rng.random_range(-5.0..5.0));
    let fext: Vec<Wrench> = (0..m.nbodies()).map(|_| Force::new(r3(), r3())).collect();
    let fext = wrenches.then_some(fext.as_slice());
    let qdd = reference::forward_dynamics(m, &q, &v, &tau, fext).expect("reference");
    let mut data = Data::new(m);
    let mut worst: f64 = 0.0;
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let fast = forward_dynamics(m, &mut data, &q, &v, &tau, fext, algo).expect("fast");
        worst = worst.max(rel_diff(&qdd, fast));
    }
    worst
}

/// Both Lola types, built once.
fn models() -> &'static [LolaModel; 2] {
    static MODELS: std::sync::OnceLock<[LolaModel; 2]> = std::sync::OnceLock::new();
    MODELS.get_or_init(|| {
        [LolaType::Type2, LolaType::Type3].map(|t| lola::build(t).expect("shipped file builds"))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn reference_matches_the_fast_paths(seed in any::<u64>(), type3: bool, wrenches: bool) {
        let lm = &models()[usize::from(type3)];
        let dev = deviation(lm, seed, wrenches);
        prop_assert!(dev < TOL, "{:?}: {dev:e}", lm.variant);
    }
}

/// The fast-path member kinds of each type (all but the plain rigid member, which the dynamics
/// crate's random loop trees cover) and the largest deviation, printed with `--nocapture`.
#[test]
fn member_kinds_and_largest_deviation() {
    for lm in models() {
        let kinds: BTreeSet<MemberKind> = fast_member_kinds(&lm.model)
            .into_iter()
            .map(|(_, k)| k)
            .collect();
        let dev = (0..20)
            .map(|s| deviation(lm, s, s % 2 == 1))
            .fold(0.0, f64::max);
        println!(
            "{:?}: {} sub-systems, member kinds {kinds:?}, largest deviation {dev:e}",
            lm.variant,
            lm.model.subsystems().len()
        );
        assert!(dev < TOL, "{:?}: {dev:e}", lm.variant);
        use MemberKind::*;
        for k in [
            Axisymmetric,
            General,
            AxialGeared,
            AxialScrew,
            AxialSlider,
            Carrier,
            Rider,
            Link,
        ] {
            assert!(kinds.contains(&k), "{:?}: {k:?} not exercised", lm.variant);
        }
    }
}
