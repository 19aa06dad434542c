//! Both Lola types: O(n) with sub-systems, CRBA and sparse agree; RNEA inverts them; DoF counts
//! and mass-matrix sparsity (Table 2.4) checked against the numeric mass matrix.

use biped_dynamics::{forward_dynamics, inverse_dynamics, mass_matrix, Algorithm, Data};
use biped_robots::lola::{self, mass_matrix_nonzeros, sparsity, LolaModel, LolaType};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};

fn rel_err(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    (a - b).amax() / (1.0 + b.amax())
}

fn both() -> Vec<LolaModel> {
    [LolaType::Type2, LolaType::Type3]
        .into_iter()
        .map(|t| lola::build(t).expect("shipped file builds"))
        .collect()
}

#[test]
fn dof_counts_and_subsystems() {
    let m = both();
    // 6 (free base) + 25 actuated; Type 3 adds one motor per elastic Harmonic Drive (16).
    assert_eq!(m[0].model.nv(), 31);
    assert_eq!(m[0].limits.len(), 25);
    assert_eq!(m[1].gears.len(), 16);
    assert_eq!(m[1].model.nv(), 31 + 16);
    // Type 2: 18 HD rotors + 2 knees + 2 ankles are loops -> at least 22 sub-systems;
    // Type 3 keeps only the 2 head HD rotors, the knees and the ankles.
    let n2 = m[0].model.subsystems().len();
    let n3 = m[1].model.subsystems().len();
    assert!(n2 > n3 && n3 >= 6, "sub-systems type2 {n2}, type3 {n3}");
}

#[test]
fn algorithms_agree_and_rnea_inverts() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for lm in both() {
        let m = &lm.model;
        let mut data = Data::new(m);
        for _ in 0..20 {
            let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
            let tau = DVector::from_fn(m.nv(), |_, _| rng.random_range(-20.0..20.0));
            let on = forward_dynamics(m, &mut data, &q, &v, &tau, None, Algorithm::On)
                .unwrap()
                .clone();
            let crba = forward_dynamics(m, &mut data, &q, &v, &tau, None, Algorithm::Crba)
                .unwrap()
                .clone();
            let sparse = forward_dynamics(m, &mut data, &q, &v, &tau, None, Algorithm::Sparse)
                .unwrap()
                .clone();
            assert!(
                rel_err(&on, &crba) < 1e-10,
                "{:?} on/crba {}",
                lm.variant,
                rel_err(&on, &crba)
            );
            assert!(
                rel_err(&sparse, &crba) < 1e-10,
                "{:?} sparse/crba",
                lm.variant
            );
            let back = inverse_dynamics(m, &mut data, &q, &v, &on, None)
                .unwrap()
                .clone();
            assert!(
                rel_err(&back, &tau) < 1e-10,
                "{:?} rnea {}",
                lm.variant,
                rel_err(&back, &tau)
            );
        }
    }
}

#[test]
fn sparsity_matches_numeric_mass_matrix() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    for lm in both() {
        let m = &lm.model;
        let s = sparsity(m);
        let mut data = Data::new(m);
        let lambda = m.dof_parents();
        let is_ancestor =
            |j: usize, i: usize| std::iter::successors(Some(i), |&k| lambda[k]).any(|k| k == j);
        let mut union = std::collections::BTreeSet::new();
        for _ in 0..5 {
            let (q, _) = lm.random_state(&mut |a, b| rng.random_range(a..b));
            let mass = mass_matrix(m, &mut data, &q).unwrap().clone();
            union.extend(mass_matrix_nonzeros(&mass, 1e-13));
        }
        // Every numeric non-zero lies in the branch-induced pattern; the pattern is only an
        // upper bound (e.g. the base's translational block is `m 1`, footnote 13 of 2.10.2).
        assert!(
            union.iter().all(|&(i, j)| is_ancestor(j, i)),
            "{:?}",
            lm.variant
        );
        println!("{:?}: {s:?}, numeric non-zeros {}", lm.variant, union.len());
        // Diagonal always non-zero; structural zeros from geometry (axes perpendicular for all
        // q, centred rotors against base translation) make the numeric count smaller.
        assert!((0..s.n).all(|i| union.contains(&(i, i))));
        assert!(union.len() <= s.nonzero && union.len() * 4 >= s.nonzero * 3);
        println!("{:?}: {s:?}, numeric non-zeros {}", lm.variant, union.len());
        assert_eq!(s.dense, s.n * (s.n + 1) / 2);
    }
}
