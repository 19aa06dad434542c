//! Dense Cholesky factorisation and solve of the small sub-system mass matrices `M_S` (2.76),
//! kept in fixed `S x S` arrays of which the leading `n x n` block is used. The factor's
//! diagonal is stored inverted (`1 / L_cc`): one division per column, products elsewhere.

use crate::DynamicsError;

/// In-place Cholesky `M_S = L L^T` of the leading `n x n` block (lower triangle used; the
/// diagonal holds `1 / L_cc`).
#[inline(always)]
pub(crate) fn cholesky<const N: usize>(
    m: &mut [[f64; N]; N],
    n: usize,
    v_set: &[usize],
) -> Result<(), DynamicsError> {
    for c in 0..n {
        let scale = m[c][c].abs();
        let d = m[c][c] - m[c][..c].iter().map(|x| x * x).sum::<f64>();
        if d <= 1e-14 * scale.max(f64::MIN_POSITIVE) || !d.is_finite() {
            return Err(DynamicsError::NotPositiveDefinite {
                index: v_set[c],
                pivot: d,
            });
        }
        let inv = 1.0 / d.sqrt();
        m[c][c] = inv;
        for r in c + 1..n {
            let dot: f64 = m[r][..c].iter().zip(&m[c][..c]).map(|(a, b)| a * b).sum();
            m[r][c] = (m[r][c] - dot) * inv;
        }
    }
    Ok(())
}

/// Solves `L L^T x = b` in place for the leading `n x n` block of a factor of [`cholesky`]
/// (stored in an `S x S` array; `b` holds at least `n` entries).
#[inline(always)]
pub(crate) fn solve<const S: usize>(l: &[[f64; S]; S], n: usize, b: &mut [f64]) {
    for c in 0..n {
        for k in 0..c {
            b[c] -= l[c][k] * b[k];
        }
        b[c] *= l[c][c];
    }
    for c in (0..n).rev() {
        for k in c + 1..n {
            b[c] -= l[k][c] * b[k];
        }
        b[c] *= l[c][c];
    }
}
