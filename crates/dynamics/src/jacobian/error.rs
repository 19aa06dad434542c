//! Typed errors of the Jacobian and centroidal computations.

use crate::DynamicsError;
use thiserror::Error;

/// Invalid input to a Jacobian, centre-of-mass or momentum computation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum JacobianError {
    /// Invalid `q`, `v` or `Data` (wrong length, non-finite entry, zero quaternion).
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// The workspace was built for a different model.
    #[error("workspace built for {workspace_bodies} bodies / {workspace_nv} DoFs, model has {model_bodies} / {model_nv}")]
    WorkspaceMismatch {
        /// Bodies of the workspace.
        workspace_bodies: usize,
        /// DoFs of the workspace.
        workspace_nv: usize,
        /// Bodies of the model.
        model_bodies: usize,
        /// DoFs of the model.
        model_nv: usize,
    },
    /// A body index out of range.
    #[error("body index {body} out of range ({nbodies} bodies)")]
    UnknownBody {
        /// The index given.
        body: usize,
        /// Number of bodies.
        nbodies: usize,
    },
    /// An output matrix has the wrong shape.
    #[error("output `{argument}` is {got_rows}x{got_cols}, expected {rows}x{cols}")]
    OutputShape {
        /// Which output.
        argument: &'static str,
        /// Expected rows.
        rows: usize,
        /// Expected columns.
        cols: usize,
        /// Actual rows.
        got_rows: usize,
        /// Actual columns.
        got_cols: usize,
    },
    /// A point argument contains NaN or infinity.
    #[error("point argument has a non-finite coordinate")]
    NonFinitePoint,
    /// Jacobians were requested before `compute`, or derivatives before `compute_with_derivatives`.
    #[error("{0} not computed for the current state")]
    NotComputed(&'static str),
    /// The model's total mass is zero, so the centre of mass is undefined.
    #[error("total mass is zero: centre of mass undefined")]
    ZeroMass,
}

/// Checks the shape of an output matrix.
pub(crate) fn shape(
    argument: &'static str,
    out: &nalgebra::DMatrix<f64>,
    rows: usize,
    cols: usize,
) -> Result<(), JacobianError> {
    if out.nrows() == rows && out.ncols() == cols {
        Ok(())
    } else {
        Err(JacobianError::OutputShape {
            argument,
            rows,
            cols,
            got_rows: out.nrows(),
            got_cols: out.ncols(),
        })
    }
}
