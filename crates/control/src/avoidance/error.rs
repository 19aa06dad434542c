//! Errors of the collision-avoidance layer.

use super::law::RepulsiveLaw;
use biped_dynamics::JacobianError;

/// What can go wrong when building or evaluating the collision avoidance.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AvoidanceError {
    /// Law parameters out of range (see [`RepulsiveLaw::validate`]).
    #[error("bad repulsive law parameters {0:?}")]
    BadLaw(RepulsiveLaw),
    /// The activation distance must be finite and > 0 for a repulsive law.
    #[error("activation distance must be finite and > 0, got {0}")]
    BadActivationDistance(f64),
    /// A collision-model body that the multibody model does not have.
    #[error("collision body `{0}` is not a body of the multibody model")]
    UnknownBody(String),
    /// The multibody model, data or gradient vector does not match the one used at `new`.
    #[error("size mismatch: {what} is {got}, expected {expected}")]
    SizeMismatch {
        /// What was mismatched.
        what: &'static str,
        /// Expected size.
        expected: usize,
        /// Actual size.
        got: usize,
    },
    /// The segment model rejected the body poses (e.g. non-finite).
    #[error(transparent)]
    Model(#[from] biped_ssv::ModelError),
    /// A point Jacobian product failed (e.g. Jacobians not computed).
    #[error(transparent)]
    Jacobian(#[from] JacobianError),
}
