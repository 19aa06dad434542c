//! Typed errors of the inverse-kinematics and task modules (thesis 4.2-4.5).

use thiserror::Error;

/// Errors of the IK solvers, the weight matrix and the task description.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IkError {
    /// A vector or matrix has the wrong size.
    #[error("dimension mismatch in {what}: expected {expected}, got {got}")]
    Dimension {
        /// Which argument was wrong.
        what: &'static str,
        /// Expected size.
        expected: usize,
        /// Actual size.
        got: usize,
    },
    /// A diagonal weight entry is not strictly positive and finite.
    #[error("weight diagonal entry {index} = {value} is not > 0 and finite")]
    NonPositiveWeight {
        /// Index of the offending entry.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A matrix that must be symmetric positive definite is not (e.g. J W^-1 J^T singular).
    #[error("matrix is not positive definite (singular configuration?)")]
    NotPositiveDefinite,
    /// An input contains NaN or infinity.
    #[error("non-finite input in {0}")]
    NonFinite(&'static str),
    /// A parameter is outside its valid range.
    #[error("invalid parameter {name}: {reason}")]
    InvalidParameter {
        /// Parameter name.
        name: &'static str,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// Forward kinematics / Jacobian evaluation failed.
    #[error("kinematics: {0}")]
    Kinematics(String),
    /// A named body or joint does not exist in the model.
    #[error("unknown body or joint '{0}'")]
    UnknownName(String),
    /// Position IK stopped without reaching the target (Table 4.1 criterion other than sigma_2).
    #[error("target not reached: stopped by {stop:?} with |dx| = {error_norm}")]
    Unreachable {
        /// Criterion that stopped the iteration.
        stop: StopReason,
        /// Remaining task error norm.
        error_norm: f64,
    },
}

/// Which stopping criterion of Table 4.1 ended the iteration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// sigma_2: `|f(q_k) - x| < eps_c` (target reached).
    Converged,
    /// sigma_1: `k >= k_max`.
    IterationLimit,
    /// sigma_3: `|f(q_k+1) - f(q_k)| < eps_p`.
    SmallProgress,
    /// sigma_4: `|grad phi| < eps_g` (stationary point of (4.4) that is not a root).
    SmallGradient,
    /// `J J^T` singular: no Newton step exists (Algorithm 4.1 only).
    Singular,
    /// The line search found no decrease along the direction (Algorithm 4.2 only).
    NoDecrease,
}
