//! Dense Cholesky `M = L L^T` in place (O(n^3), no use of the sparsity): right-looking by
//! panels of four columns, so that the trailing update, where almost all of the `n^3 / 6`
//! multiply-adds are, reads four factor columns per pass over a target column (one load
//! and store of the target per four products) and has no serial chain of additions.

use super::{check_pivot, dot_last_first, scale, sub_scaled};
use crate::DynamicsError;
use nalgebra::{DMatrix, DVector};

/// Panel width of the blocked factorisation.
const PANEL: usize = 4;

/// Dense Cholesky `M = L L^T` in place: `L` in the lower triangle of `m` (each column of `L`
/// contiguous below its diagonal; the strict upper triangle keeps `M`), with `1 / L_kk` stored
/// on the diagonal so that the solves multiply instead of divide on their serial chains.
/// `original` is the unfactored matrix, for the relative pivot test.
pub(crate) fn cholesky_in_place(
    m: &mut DMatrix<f64>,
    original: &DMatrix<f64>,
) -> Result<(), DynamicsError> {
    let n = m.nrows();
    let a = m.as_mut_slice();
    for k in (0..n).step_by(PANEL) {
        let w = PANEL.min(n - k);
        factor_panel(a, n, k, w, original)?;
        if w == PANEL {
            update_trailing(a, n, k);
        }
    }
    Ok(())
}

/// Factors columns `k..k + w` (all earlier panels already applied): the left-looking steps
/// inside the panel, pivots checked against `original`.
fn factor_panel(
    a: &mut [f64],
    n: usize,
    k: usize,
    w: usize,
    original: &DMatrix<f64>,
) -> Result<(), DynamicsError> {
    for t in k..k + w {
        let (left, right) = a.split_at_mut(t * n);
        let col_t = &mut right[..n];
        for s in k..t {
            let col_s = &left[s * n..s * n + n];
            sub_scaled(&mut col_t[t..], col_s[t], &col_s[t..]);
        }
        let d = col_t[t];
        check_pivot(t, d, original[(t, t)])?;
        let inv = 1.0 / d.sqrt();
        col_t[t] = inv;
        scale(&mut col_t[t + 1..], inv);
    }
    Ok(())
}

/// Subtracts `L_j L_j^T` of the four panel columns `k..k + 4` from every later column `j`
/// (rows `j..n`, the lower triangle), two target columns per pass over the panel rows so that
/// each load of the panel serves eight products.
fn update_trailing(a: &mut [f64], n: usize, k: usize) {
    let (panel, rest) = a.split_at_mut((k + PANEL) * n);
    let c = |t: usize| &panel[(k + t) * n..(k + t + 1) * n];
    let p = [c(0), c(1), c(2), c(3)];
    let below = |r: usize| [&p[0][r..], &p[1][r..], &p[2][r..], &p[3][r..]];
    let at = |j: usize| [p[0][j], p[1][j], p[2][j], p[3][j]];
    let mut pairs = rest.chunks_exact_mut(2 * n);
    let mut j = k + PANEL;
    for pair in &mut pairs {
        let (col_a, col_b) = pair.split_at_mut(n);
        let (la, lb) = (at(j), at(j + 1));
        col_a[j] -= (la[0] * p[0][j] + la[1] * p[1][j]) + (la[2] * p[2][j] + la[3] * p[3][j]);
        rank4_pair(
            &mut col_a[j + 1..],
            &mut col_b[j + 1..],
            &la,
            &lb,
            below(j + 1),
        );
        j += 2;
    }
    let last = pairs.into_remainder();
    if !last.is_empty() {
        rank4(&mut last[j..], &at(j), below(j));
    }
}

/// [`rank4`] on two target slices with their own coefficients and the same sources.
#[inline]
fn rank4_pair(ya: &mut [f64], yb: &mut [f64], la: &[f64; 4], lb: &[f64; 4], x: [&[f64]; 4]) {
    let sub = |y: f64, l: &[f64; 4], x: [f64; 4]| {
        y - l[0] * x[0] - l[1] * x[1] - l[2] * x[2] - l[3] * x[3]
    };
    let mut blocks = ya.chunks_exact_mut(4).zip(yb.chunks_exact_mut(4));
    let mut i = 0;
    for (ba, bb) in &mut blocks {
        let (x0, x1, x2, x3) = (
            &x[0][i..i + 4],
            &x[1][i..i + 4],
            &x[2][i..i + 4],
            &x[3][i..i + 4],
        );
        for t in 0..4 {
            let xs = [x0[t], x1[t], x2[t], x3[t]];
            ba[t] = sub(ba[t], la, xs);
            bb[t] = sub(bb[t], lb, xs);
        }
        i += 4;
    }
    for r in i..ya.len().min(yb.len()) {
        let xs = [x[0][r], x[1][r], x[2][r], x[3][r]];
        ya[r] = sub(ya[r], la, xs);
        yb[r] = sub(yb[r], lb, xs);
    }
}

/// `y -= sum_t l_t x_t` over equally long slices, in blocks of four rows (one vector each)
/// and a remainder of at most three.
#[inline]
fn rank4(y: &mut [f64], l: &[f64; 4], x: [&[f64]; 4]) {
    // One chain of four fused multiply-subtracts per row: the rows are independent, so the
    // chain costs no throughput and saves the two additions of a pairwise sum.
    let sub = |y: f64, x0: f64, x1: f64, x2: f64, x3: f64| {
        y - l[0] * x0 - l[1] * x1 - l[2] * x2 - l[3] * x3
    };
    let mut blocks = y.chunks_exact_mut(4);
    let mut i = 0;
    for b in &mut blocks {
        let (x0, x1, x2, x3) = (
            &x[0][i..i + 4],
            &x[1][i..i + 4],
            &x[2][i..i + 4],
            &x[3][i..i + 4],
        );
        for t in 0..4 {
            b[t] = sub(b[t], x0[t], x1[t], x2[t], x3[t]);
        }
        i += 4;
    }
    for (yr, r) in blocks.into_remainder().iter_mut().zip(i..) {
        *yr = sub(*yr, x[0][r], x[1][r], x[2][r], x[3][r]);
    }
}

/// Solves `L L^T x = b` in place with the factor of [`cholesky_in_place`]: forward
/// substitution by columns (`axpy`), back substitution by column dot products summed from
/// the far end, so that the unknown just solved enters last and the serial chain from one
/// unknown to the next is a few operations, not a whole dot product.
pub(crate) fn cholesky_solve_in_place(l: &DMatrix<f64>, b: &mut DVector<f64>) {
    let n = l.nrows();
    let a = l.as_slice();
    let x = b.as_mut_slice();
    if n == 0 {
        return; // no coordinates (only fixed joints): `chunks_exact` needs a non-zero size
    }
    for (k, col) in a.chunks_exact(n).enumerate() {
        x[k] *= col[k];
        let xk = x[k];
        sub_scaled(&mut x[k + 1..], xk, &col[k + 1..]);
    }
    for (i, col) in a.chunks_exact(n).enumerate().rev() {
        let s = dot_last_first(&col[i + 1..], &x[i + 1..]);
        x[i] = (x[i] - s) * col[i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against nalgebra's Cholesky on random SPD matrices of every size up to 13 (all panel
    /// remainders), and the solve against `M x = b`.
    #[test]
    fn factor_and_solve_match_nalgebra() {
        for n in 1..14 {
            let g = DMatrix::from_fn(n, n, |i, j| ((i * 7 + j * 3) as f64 * 0.37).sin());
            let m = &g * g.transpose() + DMatrix::identity(n, n) * 0.5;
            let mut f = m.clone();
            cholesky_in_place(&mut f, &m).expect("SPD");
            let reference = m.clone().cholesky().expect("SPD").l();
            let mut lower = f.lower_triangle();
            lower.set_diagonal(&lower.diagonal().map(|d| 1.0 / d));
            assert!((lower - &reference).amax() < 1e-12, "n = {n}");
            let b = DVector::from_fn(n, |i, _| (i as f64).cos());
            let mut x = b.clone();
            cholesky_solve_in_place(&f, &mut x);
            assert!((&m * x - b).amax() < 1e-11, "n = {n}");
        }
    }

    /// A singular matrix reports the first failing pivot.
    #[test]
    fn singular_matrix_is_an_error() {
        let mut m = DMatrix::identity(6, 6);
        m[(4, 4)] = 0.0;
        let original = m.clone();
        let e = cholesky_in_place(&mut m, &original).unwrap_err();
        assert!(matches!(
            e,
            DynamicsError::NotPositiveDefinite { index: 4, .. }
        ));
    }
}
