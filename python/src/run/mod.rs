//! `biped.simulate`, `biped.simulate_batch` and `biped.walk`: the command line's runs with
//! its options as keywords (turned into its words by `biped/_options.py`, parsed by the same
//! parser), returning the summary of `summary.json` and the recorded signals as numpy arrays.

mod controller;
mod output;
mod pool;
mod simulate;
mod walk;

use pyo3::prelude::*;

/// Adds the run functions to the native module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::simulate_batch, m)?)?;
    m.add_function(wrap_pyfunction!(walk::walk, m)?)?;
    m.add_function(wrap_pyfunction!(walk::walk_batch, m)?)?;
    m.add_function(wrap_pyfunction!(output::option_spec, m)?)?;
    Ok(())
}
