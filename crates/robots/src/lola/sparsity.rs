//! Mass-matrix sparsity of a tree-structured model (thesis Table 2.4, Fig. 2.20).

use biped_dynamics::Model;
use nalgebra::DMatrix;

/// Branch-induced sparsity of the lower triangle of `M` (Table 2.4 / Table 2.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sparsity {
    /// Number of DoFs `n`.
    pub n: usize,
    /// Triangle elements of a dense matrix, `n (n + 1) / 2`.
    pub dense: usize,
    /// Structurally non-zero triangle elements: pairs of a DoF and one of its ancestors.
    pub nonzero: usize,
    /// Triangle sparsity `alpha = nonzero / dense`.
    pub alpha: f64,
    /// Possible factorisation speed-up `1 / alpha^2` (Table 2.4).
    pub speedup: f64,
}

use serde::Serialize;

/// Structural sparsity from the DoF parent array `lambda`: `M_ij` can be non-zero only if
/// `j` is `i` or an ancestor of `i` (2.10.1).
pub fn sparsity(model: &Model) -> Sparsity {
    let lambda = model.dof_parents();
    let nonzero: usize = (0..lambda.len())
        .map(|i| std::iter::successors(Some(i), |&k| lambda[k]).count())
        .sum();
    let n = lambda.len();
    let dense = n * (n + 1) / 2;
    let alpha = if dense == 0 {
        0.0
    } else {
        nonzero as f64 / dense as f64
    };
    Sparsity {
        n,
        dense,
        nonzero,
        alpha,
        speedup: if alpha > 0.0 {
            1.0 / (alpha * alpha)
        } else {
            0.0
        },
    }
}

/// Lower-triangle entries of a numeric mass matrix with `|M_ij| > tol` (for cross-checks).
pub fn mass_matrix_nonzeros(mass: &DMatrix<f64>, tol: f64) -> Vec<(usize, usize)> {
    let n = mass.nrows().min(mass.ncols());
    (0..n)
        .flat_map(|i| (0..=i).map(move |j| (i, j)))
        .filter(|&(i, j)| mass[(i, j)].abs() > tol)
        .collect()
}
