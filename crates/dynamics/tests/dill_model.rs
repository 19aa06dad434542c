//! Dill(n) (thesis 2.10.1): size, inertias, and the mass-matrix sparsity of Table 2.1.

use biped_dynamics::dill::{
    dill, dill_nonzeros_formula, dill_parents, dill_test_state, link_inertia, tree_lower_nonzeros,
    DillError, MAX_DILL_LEVEL,
};
use biped_dynamics::{mass_matrix, Data};

/// Table 2.1, column n_nz, as printed in the thesis (n = 1..10).
const TABLE_2_1_NNZ: [u64; 10] = [3, 8, 20, 48, 112, 256, 576, 1280, 2816, 6144];

#[test]
fn formula_reproduces_table_2_1() {
    for (k, &nnz) in TABLE_2_1_NNZ.iter().enumerate() {
        assert_eq!(dill_nonzeros_formula(k as u32 + 1), nnz);
    }
}

#[test]
fn dill_has_two_to_the_n_revolute_bodies() {
    for n in 0..=10 {
        let m = dill(n).unwrap();
        assert_eq!((m.nbodies(), m.nq(), m.nv()), (1 << n, 1 << n, 1 << n));
        assert!(m.joints().iter().all(|j| j.nq == 1 && j.nv == 1));
        let parents: Vec<_> = m.bodies().iter().map(|b| b.parent()).collect();
        assert_eq!(parents, dill_parents(n).unwrap(), "n = {n}");
    }
}

#[test]
fn structural_nonzeros_match_table_2_1() {
    for n in 1..=10 {
        let parents = dill_parents(n).unwrap();
        assert_eq!(
            tree_lower_nonzeros(&parents),
            dill_nonzeros_formula(n),
            "n = {n}"
        );
    }
}

/// Lower-triangle sparsity pattern of the tree: (i, j) with j = i or j an ancestor of i.
fn structural_pattern(parents: &[Option<usize>]) -> Vec<Vec<bool>> {
    let n = parents.len();
    let mut pattern = vec![vec![false; n]; n];
    for (i, row) in pattern.iter_mut().enumerate() {
        let mut j = Some(i);
        while let Some(k) = j {
            row[k] = true;
            j = parents[k];
        }
    }
    pattern
}

#[test]
fn mass_matrix_nonzeros_at_test_state_match_table_2_1() {
    for n in 1..=8 {
        let model = dill(n).unwrap();
        let (q, _) = dill_test_state(&model);
        let mut data = Data::new(&model);
        let m = mass_matrix(&model, &mut data, &q).unwrap();
        let scale = m.amax();
        let pattern = structural_pattern(&dill_parents(n).unwrap());
        let mut nnz = 0;
        for i in 0..m.nrows() {
            for j in 0..=i {
                let nonzero = m[(i, j)].abs() > 1e-14 * scale;
                assert_eq!(
                    nonzero,
                    pattern[i][j],
                    "n = {n}, M[{i}][{j}] = {}",
                    m[(i, j)]
                );
                nnz += usize::from(nonzero);
                assert_eq!(m[(i, j)], m[(j, i)], "symmetric");
            }
        }
        assert_eq!(nnz as u64, dill_nonzeros_formula(n), "n = {n}");
    }
}

/// Total mass of Dill(n) by the recursive definition: scaled root link plus the sub-trees.
fn dill_mass(n: u32) -> f64 {
    let s = f64::from(n.max(1));
    0.1 * s.powi(3) + (1..=n).map(|i| dill_mass(i - 1)).sum::<f64>()
}

#[test]
fn total_mass_follows_the_recursive_definition() {
    for n in 0..=8 {
        let m = dill(n).unwrap();
        let total: f64 = m.bodies().iter().map(|b| b.inertia().mass()).sum();
        assert!((total - dill_mass(n)).abs() < 1e-12 * total, "n = {n}");
    }
}

#[test]
fn link_inertia_is_the_quoted_cylinder() {
    // Cylinder of length L = 0.1, radius r = 0.01 along x from the origin, mass 0.1, scaled by s.
    for s in [1.0, 2.0, 3.0] {
        let i = link_inertia(s).unwrap();
        let (m, l, r) = (0.1 * s * s * s, 0.1 * s, 0.01 * s);
        assert!((i.mass() - m).abs() < 1e-15);
        assert!((i.com() - nalgebra::Vector3::new(l / 2.0, 0.0, 0.0)).norm() < 1e-15);
        let about_com = i.inertia_about_com();
        let axial = m * r * r / 2.0;
        let transverse = m * (3.0 * r * r + l * l) / 12.0;
        let expected = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(
            axial, transverse, transverse,
        ));
        assert!(
            (about_com - expected).amax() < 1e-12 * transverse,
            "s = {s}"
        );
        // The quoted moments are about the joint origin: 1/200000 and 403/1200000 times s^5.
        let about_origin_yy = transverse + m * (l / 2.0) * (l / 2.0);
        assert!((about_origin_yy - 403.0 / 1_200_000.0 * s.powi(5)).abs() < 1e-15);
        assert!((axial - s.powi(5) / 200_000.0).abs() < 1e-18);
    }
}

#[test]
fn test_state_is_pi_over_six_and_unit_rates() {
    let m = dill(3).unwrap();
    let (q, v) = dill_test_state(&m);
    assert!(q
        .iter()
        .all(|&x| (x - std::f64::consts::PI / 6.0).abs() < 1e-15));
    assert!(v.iter().all(|&x| x == 1.0));
}

#[test]
fn too_large_levels_are_rejected() {
    assert!(matches!(
        dill(MAX_DILL_LEVEL + 1),
        Err(DillError::TooLarge { .. })
    ));
    assert!(dill_parents(MAX_DILL_LEVEL + 1).is_err());
}
