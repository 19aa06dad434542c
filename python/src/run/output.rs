//! What a run returns to Python: its summary (the JSON of `summary.json` as a dict) and its
//! signals (a dict of column name to 1-D float array, time first as `"t"`), and the option
//! table that `biped/_options.py` turns keywords into command-line words with.

use biped_sim::record::Recorder;
use clap::{Args, Command};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// A finished run on the Rust side: summary JSON text and signal columns.
pub struct RunOutput {
    /// `summary.json`'s content.
    pub summary: String,
    /// `(name, values)` columns, time first.
    pub signals: Vec<(String, Vec<f64>)>,
}

impl RunOutput {
    /// The summary and every column of `rec` (time as `"t"`).
    pub fn new(summary: &serde_json::Value, rec: &Recorder) -> Result<Self, String> {
        let mut signals = vec![("t".to_string(), rec.time().to_vec())];
        for name in rec.column_names() {
            let column = rec.column(name).map_err(|e| e.to_string())?;
            signals.push((name.clone(), column));
        }
        Ok(Self {
            summary: summary.to_string(),
            signals,
        })
    }

    /// `(summary: dict, signals: dict[str, numpy.ndarray])`.
    pub fn into_py(self, py: Python<'_>) -> PyResult<Py<PyTuple>> {
        let summary = py.import("json")?.call_method1("loads", (&self.summary,))?;
        let signals = self.signals_dict(py)?;
        Ok(PyTuple::new(py, [summary, signals.into_any()])?.unbind())
    }

    /// The signals as a dict of column name to array.
    pub fn signals_dict(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let signals = PyDict::new(py);
        for (name, values) in self.signals {
            signals.set_item(name, PyArray1::from_vec(py, values))?;
        }
        Ok(signals)
    }
}

/// The options of `biped <command>` (`simulate` or `walk`): `{name: (takes_value,
/// repeatable)}` with names as Python keywords (`sole_size` for `--sole-size`).
#[pyfunction]
pub fn option_spec<'py>(py: Python<'py>, command: &str) -> PyResult<Bound<'py, PyDict>> {
    let cmd = match command {
        "simulate" => biped::cli::simulate::SimulateArgs::augment_args(Command::new("simulate")),
        "walk" => biped::cli::walk::WalkArgs::augment_args(Command::new("walk")),
        other => return Err(crate::error::biped_err(format!("no command `{other}`"))),
    };
    let spec = PyDict::new(py);
    for arg in cmd.get_arguments() {
        let Some(long) = arg.get_long() else { continue };
        let action = arg.get_action();
        let repeatable = matches!(action, clap::ArgAction::Append);
        spec.set_item(long.replace('-', "_"), (action.takes_values(), repeatable))?;
    }
    Ok(spec)
}
