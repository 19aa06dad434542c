//! `biped.simulate` and `biped.simulate_batch`: `biped simulate` runs from its options (as
//! command-line words), without the GIL, the batch in parallel; one run's failure is that
//! run's error, the others complete.

use super::controller::{hook, Stash};
use super::output::RunOutput;
use super::pool::run_all;
use crate::batch::thread_count;
use crate::error::{biped_err, guard, BipedError};
use biped::cli::simulate::{execute, parse_args, MakeHook};
use biped_sim::SimError;
use pyo3::prelude::*;
use pyo3::types::PyList;

/// Control periods between two checks for Ctrl-C in the interpreter.
const SIGNAL_CHECK_EVERY: u32 = 100;

/// One run of `biped simulate` with `words`: its summary and signals, or its error line.
fn run(words: &[String], make: Option<MakeHook<'_>>, stash: &Stash) -> Result<RunOutput, String> {
    guard(|| {
        let args = parse_args(words)?;
        let mut cycles = 0u32;
        let mut stop = |_t: f64, _duration: f64| -> Result<(), SimError> {
            cycles += 1;
            if !cycles.is_multiple_of(SIGNAL_CHECK_EVERY) {
                return Ok(());
            }
            match Python::attach(|py| py.check_signals()) {
                Ok(()) => Ok(()),
                Err(e) => {
                    stash.put(e);
                    Err(SimError::Stopped("interrupted from Python".into()))
                }
            }
        };
        let done = execute(&args, make, &mut stop, false).map_err(|e| e.to_string())?;
        let summary = done
            .done
            .summary_json(&done.files)
            .map_err(|e| e.to_string())?;
        RunOutput::new(&summary, &done.done.rec)
    })
}

/// Runs `biped simulate` with the options `words` (command-line words, see
/// `biped.simulate`) and the optional Python `controller`; returns `(summary, signals)`.
#[pyfunction]
#[pyo3(signature = (words, controller=None))]
pub fn simulate(
    py: Python<'_>,
    words: Vec<String>,
    controller: Option<Py<PyAny>>,
) -> PyResult<Py<PyAny>> {
    let stash = Stash::default();
    let make: Option<MakeHook<'_>> = controller.map(|c| {
        let stash = stash.clone();
        Box::new(move |plant: &_| hook(c, stash, plant)) as MakeHook<'_>
    });
    let result = py.detach(|| run(&words, make, &stash));
    if let Some(err) = stash.take() {
        return Err(err);
    }
    Ok(result.map_err(biped_err)?.into_py(py)?.into_any())
}

/// Runs every entry of `batch` (each a list of command-line words) on `threads` threads
/// (default: the cores); returns a list in input order of `(summary, signals)` tuples, or
/// of `BipedError` instances for the runs that failed.
#[pyfunction]
#[pyo3(signature = (batch, threads=None))]
pub fn simulate_batch<'py>(
    py: Python<'py>,
    batch: Vec<Vec<String>>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyList>> {
    let threads = thread_count(threads, batch.len())?;
    let stash = Stash::default();
    let results = py.detach(|| run_all(batch.len(), threads, |i| run(&batch[i], None, &stash)));
    if let Some(err) = stash.take() {
        return Err(err);
    }
    let out = PyList::empty(py);
    for result in results {
        match result {
            Ok(done) => out.append(done.into_py(py)?)?,
            Err(line) => out.append(BipedError::new_err(line).value(py))?,
        }
    }
    Ok(out)
}
