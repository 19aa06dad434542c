//! Python bindings of the biped libraries, built by maturin into the native module
//! `biped._native` (re-exported by the pure-Python package `biped`): `Model` (dynamics,
//! kinematics, centroidal quantities, batched over states in parallel), SSV distances and
//! collision models, and `BipedError`. Every library error becomes a Python exception and no
//! panic crosses into the interpreter.

mod batch;
mod error;
mod ik;
mod kernels;
mod model;
mod run;
mod ssv;

use pyo3::prelude::*;

/// The native module `biped._native`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("BipedError", m.py().get_type::<error::BipedError>())?;
    m.add_class::<model::PyModel>()?;
    m.add_class::<ik::PyIk>()?;
    ssv::register(m)?;
    run::register(m)?;
    Ok(())
}
