//! Errors of the integrators: configuration errors at construction, integration errors per call.

use super::Method;

/// Which quantity became non-finite (NaN or infinite) during integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// The state `z` (initial value or result of a step).
    State,
    /// The derivative `f(t, z)` returned by [`super::OdeSystem::rhs`].
    Derivative,
    /// The position rate returned by [`super::SplitSystem::position_rate`].
    PositionRate,
    /// The embedded error estimate of Dormand-Prince.
    ErrorEstimate,
}

impl std::fmt::Display for Quantity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Quantity::State => "state",
            Quantity::Derivative => "derivative",
            Quantity::PositionRate => "position rate",
            Quantity::ErrorEstimate => "error estimate",
        })
    }
}

/// Invalid integrator settings, reported by [`super::Integrator::new`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ConfigError {
    /// A setting is out of its valid range.
    #[error("invalid integrator setting {name} = {value}: {reason}")]
    Setting {
        /// Field name in [`super::Settings`].
        name: &'static str,
        /// Offending value.
        value: f64,
        /// What the valid range is.
        reason: &'static str,
    },
}

/// Failure of one [`super::Integrator`] call; the state is left at the last accepted step.
#[derive(Debug, thiserror::Error)]
pub enum IntegrateError<E: std::error::Error + 'static> {
    /// The system dimension or the state length differs from the integrator's dimension.
    #[error("dimension mismatch: integrator has {expected}, got {got} ({what})")]
    DimensionMismatch {
        /// Dimension the integrator was built for.
        expected: usize,
        /// Dimension found.
        got: usize,
        /// Which length was wrong.
        what: &'static str,
    },
    /// `t0`/`t1` not finite or `t1 < t0`.
    #[error("invalid interval [{t0}, {t1}]: need finite t0 <= t1")]
    InvalidInterval {
        /// Start time.
        t0: f64,
        /// End time.
        t1: f64,
    },
    /// Requested output times not sorted or outside `[t0, t1]`.
    #[error("output time {t} not finite, not sorted or outside [{t0}, {t1}]")]
    InvalidOutputTime {
        /// Offending output time.
        t: f64,
        /// Start time.
        t0: f64,
        /// End time.
        t1: f64,
    },
    /// A state, derivative or error estimate became NaN or infinite.
    #[error("non-finite {what} at t = {t}")]
    NonFinite {
        /// Time of the evaluation.
        t: f64,
        /// Which quantity.
        what: Quantity,
    },
    /// The adaptive step size fell below the minimum step.
    #[error("step size {h:e} underflow at t = {t}")]
    StepSizeUnderflow {
        /// Time reached.
        t: f64,
        /// Proposed step size.
        h: f64,
    },
    /// More than `max_steps` steps (accepted + rejected) in one call.
    #[error("more than {max_steps} steps in one call, stopped at t = {t}")]
    TooManySteps {
        /// The limit from [`super::Settings::max_steps`].
        max_steps: usize,
        /// Time reached.
        t: f64,
    },
    /// The method needs a [`super::SplitSystem`]; call the `*_split` entry points.
    #[error("method {0} needs a SplitSystem: use Integrator::advance_split")]
    SplitRequired(Method),
    /// The split position block is longer than the state.
    #[error("position block of length {position_len} exceeds state dimension {dim}")]
    InvalidSplit {
        /// [`super::SplitSystem::position_len`].
        position_len: usize,
        /// State dimension.
        dim: usize,
    },
    /// The system's right-hand side failed.
    #[error("right-hand side failed: {0}")]
    System(#[source] E),
}
