//! Errors of the walking integration.

use crate::avoidance::AvoidanceError;
use crate::error::IkError;
use crate::momentum::MomentumError;
use crate::pattern::PatternError;
use thiserror::Error;

/// Error of [`super::WalkController`] and [`super::run_walk`].
#[derive(Debug, Error)]
pub enum WalkError {
    /// Inverse kinematics failed (solve, task evaluation, retract).
    #[error("inverse kinematics: {0}")]
    Ik(#[from] IkError),
    /// Angular momentum terms failed.
    #[error("angular momentum: {0}")]
    Momentum(#[from] MomentumError),
    /// Collision avoidance failed.
    #[error("collision avoidance: {0}")]
    Avoidance(#[from] AvoidanceError),
    /// Walking pattern generation failed.
    #[error("walking pattern: {0}")]
    Pattern(#[from] PatternError),
    /// Model, kinematics or dynamics failure.
    #[error("model: {0}")]
    Model(String),
    /// A robot description cannot be walked (names the file and what is missing).
    #[error("{0}")]
    Description(String),
    /// A parameter is out of range.
    #[error("invalid parameter `{name}`: {reason}")]
    InvalidParameter {
        /// Parameter name.
        name: &'static str,
        /// What is wrong.
        reason: String,
    },
}

/// Maps any displayable error into [`WalkError::Model`].
pub(crate) fn model_err(e: impl std::fmt::Display) -> WalkError {
    WalkError::Model(e.to_string())
}
