//! Typed errors of the simulation layers (plant, drives, contact, controller loop, scenarios).

use biped_dynamics::mechanism::MechanismError;
use biped_dynamics::{DynamicsError, JacobianError};
use thiserror::Error;

/// Everything that can go wrong while building or running a simulation.
#[derive(Debug, Error)]
pub enum SimError {
    /// A parameter is out of its valid range (`what` names it, `reason` says why).
    #[error("invalid parameter `{what}`: {reason}")]
    InvalidParameter {
        /// Parameter name.
        what: String,
        /// Why it is invalid.
        reason: String,
    },
    /// A named body, link or joint does not exist in the model.
    #[error("unknown {kind} `{name}`")]
    Unknown {
        /// What was looked up ("body", "joint", "foot", ...).
        kind: &'static str,
        /// The name.
        name: String,
    },
    /// A vector has the wrong length.
    #[error("`{what}` has length {got}, expected {expected}")]
    Length {
        /// Vector name.
        what: &'static str,
        /// Actual length.
        got: usize,
        /// Expected length.
        expected: usize,
    },
    /// A state, input or result is NaN or infinite.
    #[error("non-finite value in `{what}` (index {index})")]
    NonFinite {
        /// Where.
        what: &'static str,
        /// First offending index.
        index: usize,
    },
    /// Commands of a different kind than the plant's drive mode.
    #[error("commands are {got:?} but the plant's drive mode is {expected:?}")]
    CommandKind {
        /// The commands' kind.
        got: crate::drive::DriveMode,
        /// The plant's drive mode.
        expected: crate::drive::DriveMode,
    },
    /// The model has a joint the simulation does not support where it is needed.
    #[error("unsupported: {0}")]
    Unsupported(String),
    /// Forward dynamics failed.
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// A Jacobian / centroidal computation failed.
    #[error(transparent)]
    Jacobian(#[from] JacobianError),
    /// A drive mechanism could not be evaluated.
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    /// The integrator failed (settings, interval, step count).
    #[error("integrator: {0}")]
    Integrator(String),
    /// The integration diverged: a non-finite state or derivative, or a step-size underflow.
    #[error("integrator: {0}")]
    Divergence(String),
    /// Writing outputs failed.
    #[error("output: {0}")]
    Output(String),
    /// A controller (e.g. a user's hook) failed; the text says why.
    #[error("controller: {0}")]
    Controller(String),
    /// The observer ended the run early (e.g. on SIGINT); the text says why.
    #[error("stopped: {0}")]
    Stopped(String),
}

impl SimError {
    /// Whether this error of a running simulation says that its state blew up (numerical or
    /// physical divergence: non-finite values, a mass matrix no longer positive definite, a
    /// free-joint quaternion far off the unit sphere, a mechanism loop that cannot close, an
    /// integrator step underflow), as opposed to a setup error (parameters, lengths, names,
    /// unsupported models) or an observer's stop.
    pub fn is_divergence(&self) -> bool {
        match self {
            SimError::NonFinite { .. } | SimError::Divergence(_) | SimError::Mechanism(_) => true,
            SimError::Dynamics(e) | SimError::Jacobian(JacobianError::Dynamics(e)) => {
                dynamics_diverged(e)
            }
            _ => false,
        }
    }
}

/// The dynamics errors a diverging state produces (see [`SimError::is_divergence`]).
fn dynamics_diverged(e: &DynamicsError) -> bool {
    matches!(
        e,
        DynamicsError::NonFinite { .. }
            | DynamicsError::ZeroQuaternion { .. }
            | DynamicsError::QuaternionNorm { .. }
            | DynamicsError::NotPositiveDefinite { .. }
            | DynamicsError::Mechanism { .. }
            | DynamicsError::NonFiniteResult { .. }
    )
}

/// Checks that `x` is finite and `> 0` (or `>= 0` with `allow_zero`).
pub(crate) fn positive(what: &str, x: f64, allow_zero: bool) -> Result<(), SimError> {
    let ok = x.is_finite() && (x > 0.0 || (allow_zero && x == 0.0));
    if ok {
        Ok(())
    } else {
        let bound = if allow_zero { ">= 0" } else { "> 0" };
        Err(SimError::InvalidParameter {
            what: what.to_string(),
            reason: format!("must be finite and {bound}, got {x}"),
        })
    }
}

/// Index of the first non-finite entry of `x`, as an error.
pub(crate) fn finite(what: &'static str, x: &[f64]) -> Result<(), SimError> {
    if crate::ode::all_finite(x) {
        return Ok(());
    }
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(SimError::NonFinite { what, index }),
        None => Ok(()),
    }
}
