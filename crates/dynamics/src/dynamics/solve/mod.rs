//! In-place factorisations of the mass matrix: dense Cholesky `M = L L^T` (O(n^3), `dense`)
//! and Featherstone's reverse sparse `M = L^T L` on the DoF parent array `lambda` (thesis
//! 2.10.1, `ltl`), with the vector kernels they share.

mod dense;
mod ltl;

pub(crate) use dense::{cholesky_in_place, cholesky_solve_in_place};
pub(crate) use ltl::{copy_pattern, ltl_in_place, ltl_solve_in_place};

use crate::DynamicsError;

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

/// Dot product of two equally long slices, in four interleaved partial sums so that it
/// vectorises (a single running sum is one serial chain of additions).
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = [0.0; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let tail: f64 = (ca.remainder().iter().zip(cb.remainder()))
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in ca.zip(cb) {
        for t in 0..4 {
            acc[t] += x[t] * y[t];
        }
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3]) + tail
}

/// [`dot`] with the blocks of four taken from the end and the remainder, the first entries,
/// added last.
#[inline]
fn dot_last_first(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = [0.0; 4];
    let (ca, cb) = (a.rchunks_exact(4), b.rchunks_exact(4));
    let (ha, hb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for t in 0..4 {
            acc[t] += x[t] * y[t];
        }
    }
    let head: f64 = ha.iter().zip(hb).rev().map(|(x, y)| x * y).sum();
    ((acc[0] + acc[2]) + (acc[1] + acc[3])) + head
}

/// `y -= s x` over two equally long slices.
#[inline]
fn sub_scaled(y: &mut [f64], s: f64, x: &[f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi -= s * xi;
    }
}

/// `y *= s`.
#[inline]
fn scale(y: &mut [f64], s: f64) {
    for yi in y {
        *yi *= s;
    }
}

#[cfg(test)]
mod tests;
