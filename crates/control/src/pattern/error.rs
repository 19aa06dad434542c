//! Typed errors of the walking pattern generator.

use thiserror::Error;

/// Why a walking pattern could not be generated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PatternError {
    /// A parameter is non-finite or outside its admissible range.
    #[error("parameter `{name}` = {value} is invalid: {reason}")]
    InvalidParameter {
        /// Field name in [`PatternParams`](super::PatternParams).
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// The admissible range or rule.
        reason: &'static str,
    },
    /// A parameter is outside the range in which the legs can walk the pattern.
    #[error("parameter `{name}` = {value} is out of range [{}, {}]: {why}", inward(*min, f64::ceil), inward(*max, f64::floor))]
    OutOfRange {
        /// Field name in [`PatternParams`](super::PatternParams).
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Smallest valid value for the other parameters.
        min: f64,
        /// Largest valid value for the other parameters.
        max: f64,
        /// What limits the range.
        why: &'static str,
    },
    /// Two foot rectangles of a double-support stance overlap.
    #[error("the feet overlap in the double support after step {step} (increase step_width)")]
    FeetOverlap {
        /// Step index (0 = initial stance).
        step: usize,
    },
    /// The doubling iteration for the discrete Riccati equation did not converge.
    #[error("discrete Riccati equation: no convergence (residual {residual:e} after {iterations} doublings)")]
    Riccati {
        /// Relative residual of the last iterate.
        residual: f64,
        /// Doublings performed.
        iterations: usize,
    },
    /// The closed loop of the preview controller is not asymptotically stable.
    #[error("preview controller closed loop unstable (spectral radius {spectral_radius})")]
    Unstable {
        /// Largest eigenvalue modulus of the closed-loop matrix (from the DARE check: the norm
        /// of its 2^40-th power, infinite when unstable).
        spectral_radius: f64,
    },
    /// The robot model needed for a fitted default failed.
    #[error("robot model: {0}")]
    Model(String),
}

/// `x` rounded to 3 decimals towards the inside of its range (`round` = ceil for a lower
/// bound, floor for an upper one), so that the printed bounds are themselves valid.
fn inward(x: f64, round: fn(f64) -> f64) -> String {
    format!("{:.3}", round(x * 1e3) / 1e3)
}
