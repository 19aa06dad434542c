//! `biped.BipedError` and the conversions of library errors and panics into Python exceptions.

use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::PyErr;
use std::panic::{catch_unwind, AssertUnwindSafe};

pyo3::create_exception!(
    biped,
    BipedError,
    PyValueError,
    "Invalid input to a biped function (model file, array, name or option); the message \
     names what is wrong and where, as the command line does."
);

/// A `BipedError` with `message`.
pub fn biped_err(message: impl Into<String>) -> PyErr {
    BipedError::new_err(message.into())
}

/// An `OSError` with `message` (a file that cannot be read).
pub fn os_err(message: impl Into<String>) -> PyErr {
    PyOSError::new_err(message.into())
}

/// Runs `f`, turning a panic into an error message instead of unwinding into Python.
pub fn guard<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(format!("internal error (please report): {what}"))
        }
    }
}
