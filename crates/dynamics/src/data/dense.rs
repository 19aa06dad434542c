//! The dense `nv x nv` workspaces of the O(n^3) methods (mass matrix, factorisation): sized
//! in [`Data::new`] for small models, else on first use, fallibly.

use super::Data;
use crate::DynamicsError;
use nalgebra::DMatrix;

/// Largest `nv` whose dense workspaces [`Data::new`] allocates up front (2 x 256^2 x 8 bytes
/// = 1 MiB); larger models get them on first use, so the O(n) algorithms need O(n) memory.
const EAGER_DENSE_MAX_NV: usize = 256;

/// An `n x n` zero matrix, or [`DynamicsError::Allocation`] if the memory is not available
/// (a fallible reservation: an oversized model is an error, not an abort).
fn dense_zeros(what: &'static str, n: usize) -> Result<DMatrix<f64>, DynamicsError> {
    let error = || DynamicsError::Allocation { what, rows: n };
    let len = n.checked_mul(n).ok_or_else(error)?;
    let mut entries = Vec::new();
    entries.try_reserve_exact(len).map_err(|_| error())?;
    entries.resize(len, 0.0);
    Ok(DMatrix::from_vec(n, n, entries))
}

impl Data {
    /// [`Data::new`]'s part: the dense workspaces of a model with `nv <= EAGER_DENSE_MAX_NV`.
    pub(super) fn dense_workspace_up_front(&mut self) {
        if self.nv <= EAGER_DENSE_MAX_NV {
            // At most 1 MiB: cannot fail in practice, and if it did the first dense call
            // would report it.
            let _ = self.dense_workspace(true);
        }
    }

    /// Sizes the dense `nv x nv` workspaces on first use: `mass`, and `factor` if
    /// `with_factor` (later calls find them sized and allocate nothing).
    pub(crate) fn dense_workspace(&mut self, with_factor: bool) -> Result<(), DynamicsError> {
        if self.mass.nrows() != self.nv {
            self.mass = dense_zeros("mass matrix", self.nv)?;
        }
        if with_factor && self.factor.nrows() != self.nv {
            self.factor = dense_zeros("factorisation workspace", self.nv)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dense matrix beyond the address space (or whose entry count overflows) is a typed
    /// error, not an abort.
    #[test]
    fn oversized_dense_matrix_is_an_error() {
        for n in [1usize << 28, 1 << 33] {
            match dense_zeros("mass matrix", n) {
                Err(e @ DynamicsError::Allocation { rows, .. }) => {
                    assert_eq!(rows, n);
                    let bytes = format!("({:.3e} bytes)", (n as f64).powi(2) * 8.0);
                    assert!(e.to_string().contains(&bytes), "{e}");
                }
                other => panic!("n = {n}: {other:?}"),
            }
        }
    }
}
