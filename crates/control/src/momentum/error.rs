//! Typed errors of the angular momentum module.

use biped_dynamics::JacobianError;
use thiserror::Error;

/// Errors of the angular momentum compensation, reference and minimisation (ch. 7).
#[derive(Debug, Error)]
pub enum MomentumError {
    /// The centroidal computation failed (bad `q`, workspace mismatch, not computed).
    #[error(transparent)]
    Jacobian(#[from] JacobianError),
    /// A vector or matrix argument has the wrong length.
    #[error("`{argument}` has length {got}, expected {expected}")]
    Dimension {
        /// Which argument.
        argument: &'static str,
        /// Expected length.
        expected: usize,
        /// Actual length.
        got: usize,
    },
    /// An argument contains NaN or infinity.
    #[error("`{argument}` is not finite")]
    NonFinite {
        /// Which argument.
        argument: &'static str,
    },
    /// A scalar parameter is out of its valid range.
    #[error("parameter `{name}` = {value} is invalid: {reason}")]
    InvalidParameter {
        /// Parameter name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Valid range.
        reason: &'static str,
    },
    /// A joint name is not in the model.
    #[error("unknown joint `{0}`")]
    UnknownJoint(String),
    /// A reducing joint does not have exactly one velocity coordinate.
    #[error("joint `{name}` has {nv} velocity coordinates; reducing joints need exactly one")]
    NotOneDof {
        /// Joint name.
        name: String,
        /// Its velocity coordinates.
        nv: usize,
    },
    /// The set of reducing joints is empty or lists a joint twice.
    #[error("the reducing joint set must be non-empty and without duplicates")]
    BadReducingSet,
    /// The joint-space weight rejected the update.
    #[error(transparent)]
    Weight(#[from] crate::error::IkError),
}

/// `Ok` if `len == expected`.
pub(crate) fn check_len(
    argument: &'static str,
    len: usize,
    expected: usize,
) -> Result<(), MomentumError> {
    if len == expected {
        Ok(())
    } else {
        Err(MomentumError::Dimension {
            argument,
            expected,
            got: len,
        })
    }
}

/// `Ok` if every entry is finite.
pub(crate) fn check_finite<'a>(
    argument: &'static str,
    values: impl IntoIterator<Item = &'a f64>,
) -> Result<(), MomentumError> {
    if values.into_iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(MomentumError::NonFinite { argument })
    }
}

/// `Ok(value)` if `value` is finite and `> 0`.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, MomentumError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(MomentumError::InvalidParameter {
            name,
            value,
            reason: "must be finite and > 0",
        })
    }
}
