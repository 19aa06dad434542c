//! In-place factorisations of the mass matrix: dense Cholesky `M = U^T U` (O(n^3)) and
//! Featherstone's reverse sparse `M = L^T L` on the DoF parent array `lambda` (thesis 2.10.1).

use crate::model::DofAncestors;
use crate::DynamicsError;
use nalgebra::{DMatrix, DVector};

/// Relative pivot tolerance: a pivot below `PIVOT_TOLERANCE` times the original diagonal entry
/// means the matrix is numerically singular (e.g. Euler ZXZ at `sin(theta) = 0`).
pub(crate) const PIVOT_TOLERANCE: f64 = 1e-12;

/// Checks one pivot against the original diagonal entry.
#[inline]
pub(crate) fn check_pivot(index: usize, pivot: f64, original: f64) -> Result<(), DynamicsError> {
    if pivot > PIVOT_TOLERANCE * original.abs() && pivot.is_finite() {
        Ok(())
    } else {
        Err(DynamicsError::NotPositiveDefinite { index, pivot })
    }
}

/// Dense Cholesky `M = U^T U` in place, `U` upper triangular in the upper triangle of `m`
/// (column-major friendly: every inner product runs down two contiguous columns).
pub(crate) fn cholesky_in_place(m: &mut DMatrix<f64>) -> Result<(), DynamicsError> {
    let n = m.nrows();
    let a = m.as_mut_slice();
    for j in 0..n {
        let (left, right) = a.split_at_mut(j * n);
        let col_j = &mut right[..n];
        for i in 0..j {
            let col_i = &left[i * n..i * n + n];
            let s = col_j[i] - dot(&col_i[..i], &col_j[..i]);
            col_j[i] = s / col_i[i];
        }
        let d = col_j[j] - dot(&col_j[..j], &col_j[..j]);
        check_pivot(j, d, col_j[j])?;
        col_j[j] = d.sqrt();
    }
    Ok(())
}

/// Solves `U^T U x = b` in place with the factor of [`cholesky_in_place`].
pub(crate) fn cholesky_solve_in_place(u: &DMatrix<f64>, b: &mut DVector<f64>) {
    let n = u.nrows();
    let a = u.as_slice();
    let x = b.as_mut_slice();
    for i in 0..n {
        let col = &a[i * n..i * n + n];
        x[i] = (x[i] - dot(&col[..i], &x[..i])) / col[i];
    }
    for i in (0..n).rev() {
        let col = &a[i * n..i * n + n];
        x[i] /= col[i];
        let xi = x[i];
        for (xk, uk) in x[..i].iter_mut().zip(&col[..i]) {
            *xk -= uk * xi;
        }
    }
}

/// Dot product of two equally long slices.
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Reverse sparse factorisation `M = L^T L` in place, touching only the entries `(k, j)` with
/// `j` an ancestor of `k` (`ancestors`, the pattern of the DoF parent array `lambda`);
/// fill-in free for tree patterns. `L(k, j)` (`j <= k`) is stored transposed, at `(j, k)` in the
/// upper triangle, so that each row of `L` is one contiguous column. `original` is the
/// unfactored matrix, used for the relative pivot test.
pub(crate) fn ltl_in_place(
    m: &mut DMatrix<f64>,
    ancestors: &DofAncestors,
    original: &DMatrix<f64>,
) -> Result<(), DynamicsError> {
    let n = m.nrows();
    let a = m.as_mut_slice();
    for k in (0..n).rev() {
        let (left, right) = a.split_at_mut(k * n);
        let row_k = &mut right[..n];
        let d = row_k[k];
        check_pivot(k, d, original[(k, k)])?;
        let root = d.sqrt();
        row_k[k] = root;
        let anc = ancestors.of(k);
        for &i in anc {
            row_k[i] /= root;
        }
        for (m_i, &i) in anc.iter().enumerate() {
            let lki = row_k[i];
            let row_i = &mut left[i * n..i * n + n];
            row_i[i] -= lki * lki;
            for &j in &anc[m_i + 1..] {
                row_i[j] -= lki * row_k[j];
            }
        }
    }
    Ok(())
}

/// Solves `L^T L x = b` in place with the factor of [`ltl_in_place`].
pub(crate) fn ltl_solve_in_place(l: &DMatrix<f64>, ancestors: &DofAncestors, b: &mut DVector<f64>) {
    let n = l.nrows();
    let (a, x) = (l.as_slice(), b.as_mut_slice());
    for i in (0..n).rev() {
        let row = &a[i * n..i * n + n];
        x[i] /= row[i];
        let xi = x[i];
        for &j in ancestors.of(i) {
            x[j] -= row[j] * xi;
        }
    }
    for i in 0..n {
        let row = &a[i * n..i * n + n];
        let s: f64 = ancestors.of(i).iter().map(|&j| row[j] * x[j]).sum();
        x[i] = (x[i] - s) / row[i];
    }
}
