//! Typed errors of the kinematic calibration (thesis 3.5).

use biped_dynamics::jacobian::JacobianError;
use biped_dynamics::mechanism::MechanismError;
use biped_dynamics::urdf::UrdfError;
use thiserror::Error;

/// Why a calibration problem cannot be set up or solved.
#[derive(Debug, Error)]
pub enum CalibrationError {
    /// A named joint does not exist or has not exactly one coordinate.
    #[error("joint `{0}`: not a one-DoF joint of the model")]
    UnknownJoint(String),
    /// A named link/body does not exist in the model.
    #[error("frame `{0}`: no such link or body in the model")]
    UnknownFrame(String),
    /// A pose or constraint refers to something invalid (empty lists, bad weights, ...).
    #[error("{0}")]
    Invalid(String),
    /// A non-finite number in the input.
    #[error("non-finite value in {0}")]
    NonFinite(String),
    /// A joint is listed twice among the calibrated joints.
    #[error("joint `{0}` is listed twice among the calibrated joints")]
    DuplicateJoint(String),
    /// A solver result is infinite or NaN (finite inputs too large for `f64`).
    #[error("calibration result `{0}` is not finite (inputs too large?)")]
    NonFiniteResult(&'static str),
    /// The stacked Jacobian is rank deficient: these joints' offsets cannot be identified.
    #[error("unobservable offsets (rank {rank} of {unknowns}): {}", joints.join(", "))]
    Unobservable {
        /// Joints involved in the unobservable directions.
        joints: Vec<String>,
        /// Numerical rank of the stacked, column-scaled Jacobian.
        rank: usize,
        /// Number of unknown offsets.
        unknowns: usize,
    },
    /// Levenberg-Marquardt did not converge.
    #[error("calibration did not converge in {iterations} iterations (cost {cost:e})")]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// Final cost.
        cost: f64,
    },
    /// Kinematics failed.
    #[error(transparent)]
    Kinematics(#[from] JacobianError),
    /// A drive mechanism could not be evaluated.
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    /// The URDF could not be loaded.
    #[error(transparent)]
    Urdf(#[from] UrdfError),
    /// A calibration file is malformed: `file:line: field: message`.
    #[error("{file}:{line}: {field}: {message}")]
    File {
        /// File name.
        file: String,
        /// 1-based line (0 if unknown).
        line: usize,
        /// Field (JSON key or path) at fault.
        field: String,
        /// What is wrong.
        message: String,
    },
}
