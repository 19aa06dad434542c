//! Featherstone's reverse sparse factorisation `M = L^T L` on the DoF parent array `lambda`
//! (thesis 2.10.1), in place: only the entries `(k, j)` with `j` an ancestor of `k` are
//! touched, fill-in free for tree patterns. The ancestors of a coordinate are walked as runs of
//! consecutive indices (a chain of the tree is a run), so every update is a contiguous `axpy`.

use super::{check_pivot, dot, scale, sub_scaled};
use crate::model::DofAncestors;
use crate::DynamicsError;
use nalgebra::{DMatrix, DVector};

/// Copies the entries [`ltl_in_place`] reads, the diagonal and the upper triangle on the
/// pattern (`(j, k)`, `j` an ancestor of `k`), from `m` into `out` (same size): the
/// factorisation's input without a copy of all `n^2` entries.
pub(crate) fn copy_pattern(m: &DMatrix<f64>, ancestors: &DofAncestors, out: &mut DMatrix<f64>) {
    let n = m.nrows();
    if n == 0 {
        return; // no coordinates: `chunks_exact` needs a non-zero size
    }
    let columns = (m.as_slice().chunks_exact(n)).zip(out.as_mut_slice().chunks_exact_mut(n));
    for (k, (from, to)) in columns.enumerate() {
        to[k] = from[k];
        for r in ancestors.runs_of(k) {
            to[r.clone()].copy_from_slice(&from[r.clone()]);
        }
    }
}

/// Reverse sparse factorisation `M = L^T L` in place. `L(k, j)` (`j <= k`) is stored
/// transposed, at `(j, k)` in the upper triangle, so that each row of `L` is one contiguous
/// column; the diagonal holds `1 / L_kk`, so that the solve multiplies on its serial chains.
/// `original` is the unfactored matrix, used for the relative pivot test.
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
        let inv = 1.0 / d.sqrt();
        row_k[k] = inv;
        let runs = ancestors.runs_of(k);
        for r in runs {
            scale(&mut row_k[r.clone()], inv);
        }
        // Ancestor pairs (i, j), j < i: within i's run and all runs after it (lower indices).
        for (t, r) in runs.iter().enumerate() {
            for i in r.clone() {
                let lki = row_k[i];
                let row_i = &mut left[i * n..i * n + n];
                row_i[i] -= lki * lki;
                sub_scaled(&mut row_i[r.start..i], lki, &row_k[r.start..i]);
                for lower in &runs[t + 1..] {
                    sub_scaled(&mut row_i[lower.clone()], lki, &row_k[lower.clone()]);
                }
            }
        }
    }
    Ok(())
}

/// Solves `L^T L x = b` in place with the factor of [`ltl_in_place`].
pub(crate) fn ltl_solve_in_place(l: &DMatrix<f64>, ancestors: &DofAncestors, b: &mut DVector<f64>) {
    let n = l.nrows();
    let (a, x) = (l.as_slice(), b.as_mut_slice());
    if n == 0 {
        return; // no coordinates (only fixed joints): `chunks_exact` needs a non-zero size
    }
    for (i, row) in a.chunks_exact(n).enumerate().rev() {
        x[i] *= row[i];
        let xi = x[i];
        for r in ancestors.runs_of(i) {
            sub_scaled(&mut x[r.clone()], xi, &row[r.clone()]);
        }
    }
    for (i, row) in a.chunks_exact(n).enumerate() {
        // Farthest run first: the nearest ancestors, solved last, enter the sum last.
        let s: f64 = (ancestors.runs_of(i).iter().rev())
            .map(|r| dot(&row[r.clone()], &x[r.clone()]))
            .sum();
        x[i] = (x[i] - s) * row[i];
    }
}
