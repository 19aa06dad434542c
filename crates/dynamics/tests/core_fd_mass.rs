//! The mass matrix the O(n^3) forward-dynamics paths leave in `Data::mass`: the CRBA path
//! clears all of it, the sparse path only the tree pattern (the entries it fills). On random
//! trees with and without geared rotors, alternating the paths and states, both equal
//! `mass_matrix` (to rounding; off-pattern entries stay exact zeros; the agreement of the methods'
//! accelerations is `core_dynamics`'s, with its conditioning bound).

mod core_support;

use biped_dynamics::{forward_dynamics, mass_matrix, Algorithm, Data};
use core_support::*;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn fd_paths_leave_the_mass_matrix(seed in any::<u64>(), n in 1usize..40, rotors in any::<bool>()) {
        let opts = TreeOptions { rotors, ..TreeOptions::default() };
        let model = random_model(seed, n, opts);
        let mut r = rng(seed ^ 0xfd);
        let mut data = Data::new(&model);
        for step in 0..4 {
            let q = random_q(&model, &mut r);
            let v = random_vec(model.nv(), 1.0, &mut r);
            let tau = random_vec(model.nv(), 3.0, &mut r);
            let algo = if step % 2 == 0 { Algorithm::Sparse } else { Algorithm::Crba };
            forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo).unwrap();
            let left = data.mass.clone();
            // O(n) in between: it must not disturb what the next dense call relies on.
            forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On).unwrap();
            let m = mass_matrix(&model, &mut data, &q).unwrap();
            let scale = m.amax().max(1.0);
            prop_assert!((&left - m).amax() <= 1e-12 * scale, "{algo:?}: {}", (&left - m).amax());
            // Structural zeros stay exact zeros.
            for (l, x) in left.iter().zip(m.iter()) {
                prop_assert!(*x != 0.0 || *l == 0.0, "{algo:?}: {l} off the pattern");
            }
        }
    }
}

/// Dill(8) (256 DoF) is sparse enough for the pattern-only clear: after a dense call filled
/// all of `M` and a sparse call at another state rewrote its pattern, `M` is the mass matrix
/// of the second state, and both solves agree with O(n).
#[test]
fn pattern_clear_on_dill() {
    use biped_dynamics::dill::{dill, dill_test_state};
    let model = dill(8).unwrap();
    let (q, v) = dill_test_state(&model);
    let tau = nalgebra::DVector::zeros(model.nv());
    let q2 = q.map(|x| x * 0.7 + 0.1);
    let mut data = Data::new(&model);
    let on = forward_dynamics(&model, &mut data, &q2, &v, &tau, None, Algorithm::On)
        .unwrap()
        .clone();
    forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::Crba).unwrap();
    let sparse = forward_dynamics(&model, &mut data, &q2, &v, &tau, None, Algorithm::Sparse)
        .unwrap()
        .clone();
    assert!(rel_diff(&sparse, &on) < 1e-9, "{}", rel_diff(&sparse, &on));
    let left = data.mass.clone();
    let m = mass_matrix(&model, &mut data, &q2).unwrap();
    assert!((&left - m).amax() <= 1e-12 * m.amax());
    let zeros = m.iter().filter(|x| **x == 0.0).count();
    assert!(
        zeros > model.nv() * model.nv() / 2,
        "{zeros} structural zeros"
    );
    assert!(left
        .iter()
        .zip(m.iter())
        .all(|(l, x)| *x != 0.0 || *l == 0.0));
}
