//! In-place factorisations of the mass matrix: dense Cholesky `M = U^T U` (O(n^3)) and
//! Featherstone's reverse sparse `M = L^T L` on the DoF parent array `lambda` (thesis 2.10.1).

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

/// Reverse sparse factorisation `M = L^T L` in place (lower triangle), touching only the
/// entries `(k, j)` with `j` an ancestor of `k` in `lambda`; fill-in free for tree patterns.
/// `original` is the unfactored matrix, used for the relative pivot test.
pub(crate) fn ltl_in_place(
    m: &mut DMatrix<f64>,
    lambda: &[Option<usize>],
    original: &DMatrix<f64>,
) -> Result<(), DynamicsError> {
    for k in (0..m.nrows()).rev() {
        let d = m[(k, k)];
        check_pivot(k, d, original[(k, k)])?;
        let a = d.sqrt();
        m[(k, k)] = a;
        let mut i = lambda[k];
        while let Some(ii) = i {
            m[(k, ii)] /= a;
            i = lambda[ii];
        }
        let mut i = lambda[k];
        while let Some(ii) = i {
            let lki = m[(k, ii)];
            let mut j = Some(ii);
            while let Some(jj) = j {
                m[(ii, jj)] -= lki * m[(k, jj)];
                j = lambda[jj];
            }
            i = lambda[ii];
        }
    }
    Ok(())
}

/// Solves `L^T L x = b` in place with the factor of [`ltl_in_place`].
pub(crate) fn ltl_solve_in_place(l: &DMatrix<f64>, lambda: &[Option<usize>], b: &mut DVector<f64>) {
    let n = l.nrows();
    for i in (0..n).rev() {
        b[i] /= l[(i, i)];
        let mut j = lambda[i];
        while let Some(jj) = j {
            b[jj] -= l[(i, jj)] * b[i];
            j = lambda[jj];
        }
    }
    for i in 0..n {
        let mut j = lambda[i];
        while let Some(jj) = j {
            b[i] -= l[(i, jj)] * b[jj];
            j = lambda[jj];
        }
        b[i] /= l[(i, i)];
    }
}
