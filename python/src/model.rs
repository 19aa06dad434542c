//! `biped.Model`: a multibody model (URDF, Lola-like biped, Dill(n)) and its dynamics,
//! kinematics and centroidal quantities for one state or a batch of states.

use crate::batch::{compute, to_array, Arg, Inputs};
use crate::error::{biped_err, os_err};
use crate::kernels::{KernelResult, Work};
use biped_dynamics::urdf::UrdfError;
use biped_dynamics::{Algorithm, JacobianFrame};
use nalgebra::Vector3;
use pyo3::exceptions::{PyFileNotFoundError, PyPermissionError};
use pyo3::prelude::*;
use std::sync::Mutex;

/// A multibody model with a cached workspace for single-state calls.
#[pyclass(module = "biped._native", name = "Model", frozen)]
pub struct PyModel {
    pub(crate) model: biped_dynamics::Model,
    label: String,
    warnings: Vec<String>,
    work: Mutex<Work>,
    source: Source,
}

impl PyModel {
    fn new(
        model: biped_dynamics::Model,
        label: String,
        warnings: Vec<String>,
        source: Source,
    ) -> Self {
        let work = Mutex::new(Work::new(&model));
        Self {
            model,
            label,
            warnings,
            work,
            source,
        }
    }

    /// Index of the body named `name`, or an error listing the bodies.
    pub(crate) fn body(&self, name: &str) -> PyResult<usize> {
        self.model.body_id(name).ok_or_else(|| {
            let names = self.model.body_names();
            let shown = names.iter().take(8).copied().collect::<Vec<_>>().join(", ");
            let more = if names.len() > 8 { ", ..." } else { "" };
            biped_err(format!("unknown body \"{name}\" (bodies: {shown}{more})"))
        })
    }

    /// Checks `args`, runs `kernel` on every state and returns `shape`-shaped results.
    fn run<'py>(
        &self,
        py: Python<'py>,
        args: &[Arg<'_, 'py>],
        shape: &[usize],
        threads: Option<usize>,
        kernel: impl Fn(&biped_dynamics::Model, &mut Work, &mut [f64]) -> KernelResult + Sync,
    ) -> PyResult<Bound<'py, PyAny>> {
        let inputs = Inputs::gather(args)?;
        let model = &self.model;
        let out_len = shape.iter().product();
        let mut work = self.work.lock().unwrap_or_else(|p| p.into_inner());
        let result = compute(
            py,
            &inputs,
            out_len,
            threads,
            &mut *work,
            || Work::new(model),
            |w, i, out| {
                w.load(inputs.state(i));
                kernel(model, w, out)
            },
        );
        if result.is_err() {
            // a failed call may leave partial kinematics behind: start the next one afresh
            *work = Work::new(model);
        }
        to_array(py, &inputs, result?, shape)
    }

    fn arg<'a, 'py>(name: &'a str, value: &'a Bound<'py, PyAny>, shape: &[usize]) -> Arg<'a, 'py> {
        Arg {
            name,
            value,
            shape: shape.to_vec(),
        }
    }

    /// `q` plus optional further arguments.
    fn q_arg<'a, 'py>(&self, q: &'a Bound<'py, PyAny>) -> Arg<'a, 'py> {
        Self::arg("q", q, &[self.model.nq()])
    }

    /// Arguments `(q, v, x[, fext])` of the dynamics functions.
    fn dyn_args<'a, 'py>(
        &self,
        (q, v): (&'a Bound<'py, PyAny>, &'a Bound<'py, PyAny>),
        (name, x): (&'a str, &'a Bound<'py, PyAny>),
        fext: Option<&'a Bound<'py, PyAny>>,
    ) -> Vec<Arg<'a, 'py>> {
        let nv = self.model.nv();
        let mut args = vec![
            self.q_arg(q),
            Self::arg("v", v, &[nv]),
            Self::arg(name, x, &[nv]),
        ];
        if let Some(f) = fext {
            args.push(Self::arg("fext", f, &[self.model.nbodies(), 6]));
        }
        args
    }
}

/// The URDF error as a Python exception: `OSError` (subclass) if the file cannot be read.
pub(crate) fn urdf_error(e: UrdfError) -> PyErr {
    match &e {
        UrdfError::Io { source, .. } => match source.kind() {
            std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(e.to_string()),
            std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(e.to_string()),
            _ => os_err(e.to_string()),
        },
        _ => biped_err(e.to_string()),
    }
}

/// A 3-vector argument (e.g. a point in body coordinates), zero if not given.
fn point_arg(point: Option<[f64; 3]>) -> PyResult<Vector3<f64>> {
    let p = Vector3::from(point.unwrap_or_default());
    match p.iter().all(|x| x.is_finite()) {
        true => Ok(p),
        false => Err(biped_err("\"point\" is not finite")),
    }
}

/// `"on"`, `"crba"` or `"sparse"`.
fn algorithm(name: &str) -> PyResult<Algorithm> {
    match name {
        "on" => Ok(Algorithm::On),
        "crba" => Ok(Algorithm::Crba),
        "sparse" => Ok(Algorithm::Sparse),
        _ => Err(biped_err(format!(
            "algorithm: unknown \"{name}\" (on, crba or sparse)"
        ))),
    }
}

/// `"local"`, `"local_world_aligned"` or `"world"` (Pinocchio's reference-frame names).
fn reference(name: &str) -> PyResult<JacobianFrame> {
    match name {
        "local" => Ok(JacobianFrame::Body),
        "local_world_aligned" => Ok(JacobianFrame::WorldAligned),
        "world" => Ok(JacobianFrame::World),
        _ => Err(biped_err(format!(
            "reference: unknown \"{name}\" (local, local_world_aligned or world)"
        ))),
    }
}

mod methods;
mod source;

use source::Source;
