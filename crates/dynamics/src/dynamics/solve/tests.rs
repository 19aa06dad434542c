//! Property tests of the factorisations on random tree patterns: both solves against
//! nalgebra's Cholesky, and the `L^T L` factor against the pattern it may touch.

use super::{cholesky_in_place, cholesky_solve_in_place, ltl_in_place, ltl_solve_in_place};
use crate::model::DofAncestors;
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;

/// A parent array (`lambda[k] < k`, `None` for roots) from raw draws, and an SPD matrix
/// `L^T L` whose lower-triangular `L` has the tree pattern (`L_kj != 0` only for `j` an
/// ancestor of `k` or `j = k`), so that `M` has it too.
fn tree_matrix(parents: &[u32], values: &[f64]) -> (Vec<Option<usize>>, DMatrix<f64>) {
    let n = parents.len();
    let lambda: Vec<Option<usize>> = (parents.iter().enumerate())
        .map(|(k, &p)| (k > 0 && p % 5 != 0).then(|| p as usize % k))
        .collect();
    let ancestors = DofAncestors::new(&lambda);
    let mut l = DMatrix::zeros(n, n);
    let mut next = values.iter().cycle();
    for k in 0..n {
        l[(k, k)] = 0.5 + next.next().copied().unwrap_or(0.0).abs();
        for &j in ancestors.of(k) {
            l[(k, j)] = next.next().copied().unwrap_or(0.0);
        }
    }
    (lambda, l.transpose() * l)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Dense and sparse solves agree with nalgebra's Cholesky solve to 1e-9 relative, on
    /// every size up to 40 (all panel remainders) and tree shapes (chains, bushes, forests).
    #[test]
    fn solves_match_nalgebra(
        parents in prop::collection::vec(any::<u32>(), 1..40),
        values in prop::collection::vec(-1.0f64..1.0, 1..64),
    ) {
        let (lambda, m) = tree_matrix(&parents, &values);
        let n = m.nrows();
        let b = DVector::from_fn(n, |i, _| (i as f64 * 0.7).sin() + 0.3);
        let reference = m.clone().cholesky().expect("SPD").solve(&b);
        let scale = reference.amax().max(1.0);

        let mut dense = m.clone();
        cholesky_in_place(&mut dense, &m).expect("SPD");
        let mut x = b.clone();
        cholesky_solve_in_place(&dense, &mut x);
        prop_assert!((&x - &reference).amax() <= 1e-9 * scale, "dense {}", (&x - &reference).amax());

        let ancestors = DofAncestors::new(&lambda);
        let mut sparse = m.clone();
        ltl_in_place(&mut sparse, &ancestors, &m).expect("SPD");
        let mut x = b.clone();
        ltl_solve_in_place(&sparse, &ancestors, &mut x);
        prop_assert!((&x - &reference).amax() <= 1e-9 * scale, "sparse {}", (&x - &reference).amax());
        // Entries outside the pattern (upper triangle, (j, k) with j not an ancestor of k)
        // are left as they were.
        for k in 0..n {
            for j in 0..k {
                if !ancestors.of(k).contains(&j) {
                    prop_assert_eq!(sparse[(j, k)], m[(j, k)]);
                }
            }
        }
    }
}
