//! `biped.walk`: `biped walk` from its options (as command-line words), without the GIL.

use super::output::RunOutput;
use crate::error::{biped_err, guard};
use biped::cli::walk::{execute, parse_args};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Runs `biped walk` with the options `words` (command-line words, see `biped.walk`);
/// returns `(summary, tables)`, the tables by file stem (`"none"`, `"none_trajectory"`, ...,
/// `"dynamic"`), each a dict of column name to array. A fall or a violated verdict raises
/// `BipedError` with the line the command line exits with (unless `allow_violations`).
#[pyfunction]
pub fn walk(py: Python<'_>, words: Vec<String>) -> PyResult<Py<PyAny>> {
    let result = py.detach(|| {
        guard(|| {
            let args = parse_args(&words)?;
            let walk = execute(&args, false)?;
            if let Some(line) = walk
                .failure()
                .or_else(|| walk.violation(args.allow_violations()))
            {
                return Err(line);
            }
            let tables = walk
                .tables
                .iter()
                .map(|(stem, rec)| {
                    Ok((stem.clone(), RunOutput::new(&serde_json::Value::Null, rec)?))
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok((walk.summary.to_string(), tables))
        })
    });
    let (summary, tables) = result.map_err(biped_err)?;
    let summary = py.import("json")?.call_method1("loads", (summary,))?;
    let out = PyDict::new(py);
    for (stem, table) in tables {
        out.set_item(stem, table.signals_dict(py)?)?;
    }
    Ok((summary, out).into_pyobject(py)?.into_any().unbind())
}
