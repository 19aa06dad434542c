//! Typed errors of the SSV library.

use thiserror::Error;

/// What can be wrong with SSV input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SsvError {
    /// A coordinate or radius is NaN or infinite.
    #[error("{what} is not finite ({value})")]
    NonFinite {
        /// Which quantity, e.g. `"vertex 1 x"` or `"radius"`.
        what: String,
        /// The offending value.
        value: f64,
    },
    /// A coordinate or radius beyond [`crate::primitives::MAX_MAGNITUDE`] in magnitude.
    #[error("{what} = {value:e} exceeds the supported magnitude 1e50")]
    OutOfRange {
        /// Which quantity, e.g. `"vertex 1 x"` or `"radius"`.
        what: String,
        /// The offending value.
        value: f64,
    },
    /// A radius below zero.
    #[error("radius must be >= 0, got {0}")]
    NegativeRadius(f64),
}
