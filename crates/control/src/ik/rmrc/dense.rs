//! Dense in-place kernels of the Klein-Huang solve on contiguous column slices: Cholesky of
//! the leading block of a column-major buffer, its solves, axpy and dot (no allocation).

use crate::error::IkError;
use nalgebra::DMatrix;

/// In-place right-looking Cholesky `B = L L^T` on the lower triangle of the leading `m x m`
/// block of the column-major `mm x mm` buffer `b` (column `k` of `L` is contiguous). The
/// trailing updates are independent axpys, so only `m` steps are on the dependency chain;
/// `inv[k] = 1 / L_kk` is stored for the solves.
pub(super) fn cholesky_lower(
    b: &mut [f64],
    mm: usize,
    m: usize,
    inv: &mut [f64],
) -> Result<(), IkError> {
    for k in 0..m {
        let d = b[k * mm + k];
        if d.is_nan() || d <= 0.0 {
            return Err(IkError::NotPositiveDefinite);
        }
        let l = d.sqrt();
        b[k * mm + k] = l;
        inv[k] = 1.0 / l;
        for x in &mut b[k * mm + k + 1..k * mm + m] {
            *x *= inv[k];
        }
        for j in k + 1..m {
            let (left, right) = b.split_at_mut(j * mm);
            let ck = &left[k * mm + j..k * mm + m];
            let ljk = ck[0];
            for (x, y) in right[j..m].iter_mut().zip(ck) {
                *x -= ljk * y;
            }
        }
    }
    Ok(())
}

/// Solves `L L^T x = rhs` in place on `x[..m]` with the factor of [`cholesky_lower`].
pub(super) fn cholesky_lower_solve(b: &[f64], mm: usize, m: usize, inv: &[f64], x: &mut [f64]) {
    for k in 0..m {
        x[k] *= inv[k];
        let xk = x[k];
        for (xi, l) in x[k + 1..m].iter_mut().zip(&b[k * mm + k + 1..k * mm + m]) {
            *xi -= l * xk;
        }
    }
    for i in (0..m).rev() {
        let below = &b[i * mm + i + 1..i * mm + m];
        x[i] = (x[i] - dot(below, &x[i + 1..m])) * inv[i];
    }
}

/// The first `m` entries of each column of `j` (contiguous in nalgebra's column-major storage).
#[inline]
pub(super) fn columns(j: &DMatrix<f64>, m: usize) -> impl Iterator<Item = &[f64]> {
    j.as_slice()
        .chunks_exact(j.nrows().max(1))
        .map(move |c| &c[..m])
}

/// `y += a x` on equally long slices.
#[inline]
pub(super) fn axpy(a: f64, x: &[f64], y: &mut [f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += a * xi;
    }
}

/// Dot product of two equally long slices.
#[inline]
pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    // four independent accumulators: the single-chain sum is latency bound
    let (mut acc, n4) = ([0.0; 4], a.len().min(b.len()) / 4 * 4);
    for (x, y) in a[..n4].chunks_exact(4).zip(b[..n4].chunks_exact(4)) {
        for k in 0..4 {
            acc[k] += x[k] * y[k];
        }
    }
    let tail: f64 = a[n4..].iter().zip(&b[n4..]).map(|(x, y)| x * y).sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}
