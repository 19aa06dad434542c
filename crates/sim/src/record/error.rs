//! Errors of the [`super::Recorder`].

use std::path::PathBuf;

/// Failure of a recorder operation.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    /// No signal (or column) of that name.
    #[error("unknown signal {0:?}")]
    UnknownSignal(String),
    /// A name is empty, contains `,`, `"`, a line break, or collides with an existing column.
    #[error("invalid or duplicate signal name {0:?}")]
    InvalidName(String),
    /// A vector signal was pushed with a different length than registered.
    #[error("signal {name:?} has {expected} entries, got {got}")]
    LengthMismatch {
        /// Signal name.
        name: String,
        /// Registered length.
        expected: usize,
        /// Pushed length.
        got: usize,
    },
    /// Sample time not finite or earlier than the previous sample.
    #[error("sample time {t} not finite or before the previous sample {prev}")]
    InvalidTime {
        /// Offending time.
        t: f64,
        /// Previous sample time.
        prev: f64,
    },
    /// A value was set, or output requested, before any sample was started.
    #[error("recorder has no samples")]
    Empty,
    /// A table that cannot be turned into a recording for replay.
    #[error("recording: {0}")]
    Replay(String),
    /// No signal names given to plot.
    #[error("no signals to plot")]
    NoSignals,
    /// File system error, with the path.
    #[error("I/O error on {path}: {source}")]
    Io {
        /// File concerned.
        path: PathBuf,
        /// Underlying error.
        #[source]
        source: std::io::Error,
    },
    /// Plot backend error, with the path.
    #[error("plotting {path} failed: {message}")]
    Plot {
        /// File concerned.
        path: PathBuf,
        /// Backend message.
        message: String,
    },
}
