//! Small in-place dense kernels for the m x m systems of Algorithm 4.3 (no allocation).
//!
//! Only the leading `m x m` block of a preallocated matrix is used, so one buffer serves
//! every task-space dimension up to its capacity.

use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// In-place Cholesky `B = L L^T` of the leading `m x m` block (lower triangle read/written).
pub fn cholesky_in_place(b: &mut DMatrix<f64>, m: usize) -> Result<(), IkError> {
    for j in 0..m {
        let mut d = b[(j, j)];
        for k in 0..j {
            d -= b[(j, k)] * b[(j, k)];
        }
        if d.is_nan() || d <= 0.0 {
            return Err(IkError::NotPositiveDefinite);
        }
        let ljj = d.sqrt();
        b[(j, j)] = ljj;
        for i in (j + 1)..m {
            let mut s = b[(i, j)];
            for k in 0..j {
                s -= b[(i, k)] * b[(j, k)];
            }
            b[(i, j)] = s / ljj;
        }
    }
    Ok(())
}

/// Solves `L L^T x = rhs` in place on the first `m` entries of `rhs` (factor from
/// [`cholesky_in_place`]).
pub fn cholesky_solve_in_place(l: &DMatrix<f64>, m: usize, rhs: &mut DVector<f64>) {
    for i in 0..m {
        let mut s = rhs[i];
        for k in 0..i {
            s -= l[(i, k)] * rhs[k];
        }
        rhs[i] = s / l[(i, i)];
    }
    for i in (0..m).rev() {
        let mut s = rhs[i];
        for k in (i + 1)..m {
            s -= l[(k, i)] * rhs[k];
        }
        rhs[i] = s / l[(i, i)];
    }
}

/// Errors unless every entry of `v` is finite.
pub fn check_finite(what: &'static str, v: &[f64]) -> Result<(), IkError> {
    // an entry is not finite iff its exponent bits are all set; the OR reduction has no early
    // exit, so it vectorises
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    let bad = v
        .iter()
        .fold(false, |a, x| a | (x.to_bits() & EXPONENT == EXPONENT));
    if !bad {
        Ok(())
    } else {
        Err(IkError::NonFinite(what))
    }
}

/// Errors unless `got == expected`.
pub fn check_dim(what: &'static str, expected: usize, got: usize) -> Result<(), IkError> {
    if got == expected {
        Ok(())
    } else {
        Err(IkError::Dimension {
            what,
            expected,
            got,
        })
    }
}
