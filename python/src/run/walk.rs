//! `biped.walk` and `biped.walk_batch`: `biped walk` from its options (as command-line words),
//! without the GIL, the batch in parallel.

use super::output::RunOutput;
use super::pool::run_all;
use crate::batch::thread_count;
use crate::error::{biped_err, guard, BipedError};
use biped::cli::walk::{execute, parse_args};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// A finished walk on the Rust side: summary JSON text and the tables by file stem.
type WalkOutput = (String, Vec<(String, RunOutput)>);

/// One `biped walk` with `words`: its summary and tables, or its error line (a fall, or a
/// violated verdict unless `allow_violations`).
fn run(words: &[String]) -> Result<WalkOutput, String> {
    guard(|| {
        let args = parse_args(words)?;
        let walk = execute(&args, false)?;
        let allow = args.allow_violations();
        if let Some(line) = walk.failure().or_else(|| walk.violation(allow)) {
            return Err(line);
        }
        let mut tables = Vec::new();
        for (stem, rec) in &walk.tables {
            tables.push((stem.clone(), RunOutput::new(&serde_json::Value::Null, rec)?));
        }
        Ok((walk.summary.to_string(), tables))
    })
}

/// `(summary: dict, tables: dict[stem, dict[column, array]])` of a finished walk.
fn into_py(py: Python<'_>, (summary, tables): WalkOutput) -> PyResult<Py<PyAny>> {
    let summary = py.import("json")?.call_method1("loads", (summary,))?;
    let out = PyDict::new(py);
    for (stem, table) in tables {
        out.set_item(stem, table.signals_dict(py)?)?;
    }
    Ok((summary, out).into_pyobject(py)?.into_any().unbind())
}

/// Runs `biped walk` with the options `words` (command-line words, see `biped.walk`);
/// returns `(summary, tables)`, the tables by file stem (`"none"`, `"none_trajectory"`,
/// `"none_recording"`, ..., `"dynamic"`, `"dynamic_recording"`), each a dict of column name to array. A fall or a violated verdict raises
/// `BipedError` with the line the command line exits with (unless `allow_violations`).
#[pyfunction]
pub fn walk(py: Python<'_>, words: Vec<String>) -> PyResult<Py<PyAny>> {
    let result = py.detach(|| run(&words));
    into_py(py, result.map_err(biped_err)?)
}

/// Runs every walk of `batch` (each a list of command-line words) on `threads` threads;
/// returns a list in input order of `(summary, tables)` tuples, or of `BipedError` instances
/// for the walks that failed or fell.
#[pyfunction]
#[pyo3(signature = (batch, threads=None))]
pub fn walk_batch<'py>(
    py: Python<'py>,
    batch: Vec<Vec<String>>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyList>> {
    let threads = thread_count(threads, batch.len())?;
    let results = py.detach(|| run_all(batch.len(), threads, |i| run(&batch[i])));
    let out = PyList::empty(py);
    for result in results {
        match result {
            Ok(done) => out.append(into_py(py, done)?)?,
            Err(line) => out.append(BipedError::new_err(line).value(py))?,
        }
    }
    Ok(out)
}
