//! The Python methods of `biped.Model` (one `#[pymethods]` block); each array method takes
//! one state (1-D arrays) or a batch (2-D arrays, one row per state) and an optional
//! `threads` count for batches.

use super::source::{Pickled, Source};
use super::{point_arg, urdf_error, PyModel};
use crate::kernels::{self, CentroidalMatrix};
use biped_dynamics::urdf::read_file;
use numpy::PyArray1;
use pyo3::prelude::*;
use std::path::PathBuf;

#[pymethods]
impl PyModel {
    /// Loads a URDF file; `floating` adds a free-flyer root joint named "root".
    #[staticmethod]
    #[pyo3(signature = (path, floating = false, reject_mimic = false))]
    fn from_urdf(
        py: Python<'_>,
        path: PathBuf,
        floating: bool,
        reject_mimic: bool,
    ) -> PyResult<Self> {
        let text = read_file(&path).map_err(urdf_error)?;
        let file = path.display().to_string();
        let source = Source::Urdf {
            text,
            file,
            floating,
            reject_mimic,
        };
        source.build(py)
    }

    /// The Lola-like biped: `"type2"` (rigid drives) or `"type3"` (elastic gears).
    #[staticmethod]
    fn lola(py: Python<'_>, kind: &str) -> PyResult<Self> {
        Source::Lola(kind.to_string()).build(py)
    }

    /// Featherstone's Dill(n) benchmark tree (2^n revolute bodies).
    #[staticmethod]
    fn dill(py: Python<'_>, n: i64) -> PyResult<Self> {
        Source::Dill(n).build(py)
    }

    /// Rebuilds a pickled model (see `__reduce__`).
    #[staticmethod]
    fn _restore(py: Python<'_>, pickled: Pickled) -> PyResult<Self> {
        Source::unpickled(pickled)?.build(py)
    }

    /// Pickling: the model is rebuilt from its URDF text, Lola variant or Dill level.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Pickled,))> {
        let restore = py.get_type::<PyModel>().getattr("_restore")?;
        Ok((restore, (self.source.pickled(),)))
    }

    /// Number of position coordinates.
    #[getter]
    fn nq(&self) -> usize {
        self.model.nq()
    }

    /// Number of velocity coordinates.
    #[getter]
    fn nv(&self) -> usize {
        self.model.nv()
    }

    /// Number of bodies.
    #[getter]
    fn nbodies(&self) -> usize {
        self.model.nbodies()
    }

    /// Joints in coordinate order: `(name, idx_q, nq, idx_v, nv)`.
    #[getter]
    fn joints(&self) -> Vec<(String, usize, usize, usize, usize)> {
        let joints = self.model.joints().iter();
        joints
            .map(|j| (j.name.clone(), j.q_index, j.nq, j.v_index, j.nv))
            .collect()
    }

    /// Body names in body-index order (the frames of `frame_pose` and `frame_jacobian`).
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.model
            .body_names()
            .into_iter()
            .map(String::from)
            .collect()
    }

    /// Names of the position coordinates, in `q` order.
    #[getter]
    fn q_names(&self) -> Vec<String> {
        self.model.q_names()
    }

    /// Names of the velocity coordinates, in `v` order.
    #[getter]
    fn v_names(&self) -> Vec<String> {
        self.model.v_names()
    }

    /// Import warnings (e.g. ignored URDF `<mimic>` joints).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// Total mass in kg.
    #[getter]
    fn mass(&self) -> f64 {
        self.model.mass()
    }

    /// The neutral configuration (zero joint angles, identity quaternions).
    fn neutral<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.model.neutral().as_slice().to_vec())
    }

    fn __repr__(&self) -> String {
        let m = &self.model;
        format!(
            "Model({}: nq={}, nv={}, {} bodies)",
            self.label,
            m.nq(),
            m.nv(),
            m.nbodies()
        )
    }

    /// Joint accelerations `qdd` for `(q, v, tau)`, optional body wrenches `fext`.
    #[pyo3(signature = (q, v, tau, algorithm = "on", fext = None, threads = None))]
    #[allow(clippy::too_many_arguments)] // the Python signature: state, options, keywords
    fn forward_dynamics<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
        algorithm: &str,
        fext: Option<&Bound<'py, PyAny>>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let algo = super::algorithm(algorithm)?;
        let args = self.dyn_args((q, v), ("tau", tau), fext);
        self.run(py, &args, &[self.model.nv()], threads, |m, w, o| {
            kernels::forward(m, w, algo, o)
        })
    }

    /// Joint forces `tau` for `(q, v, a)` (RNEA), optional body wrenches `fext`.
    #[pyo3(signature = (q, v, a, fext = None, threads = None))]
    fn inverse_dynamics<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        a: &Bound<'py, PyAny>,
        fext: Option<&Bound<'py, PyAny>>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let args = self.dyn_args((q, v), ("a", a), fext);
        self.run(py, &args, &[self.model.nv()], threads, kernels::inverse)
    }

    /// Joint-space mass matrix `M(q)` (nv x nv, CRBA).
    #[pyo3(signature = (q, threads = None))]
    fn mass_matrix<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let nv = self.model.nv();
        self.run(py, &[self.q_arg(q)], &[nv, nv], threads, kernels::mass)
    }

    /// World pose (4x4 homogeneous) of body `name`'s frame, origin moved to `point`.
    #[pyo3(signature = (q, name, point = None, threads = None))]
    fn frame_pose<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        name: &str,
        point: Option<[f64; 3]>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (body, p) = (self.body(name)?, point_arg(point)?);
        self.run(py, &[self.q_arg(q)], &[4, 4], threads, |m, w, o| {
            kernels::pose(m, w, body, &p, o)
        })
    }

    /// World poses (nbodies x 4 x 4) of all bodies, in `bodies` order.
    #[pyo3(signature = (q, threads = None))]
    fn body_poses<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let shape = [self.model.nbodies(), 4, 4];
        self.run(py, &[self.q_arg(q)], &shape, threads, kernels::all_poses)
    }

    /// Jacobian (6 x nv, rows `[angular; linear]`) of body `name`'s frame at `point`.
    #[pyo3(signature = (q, name, reference = "local_world_aligned", point = None, threads = None))]
    fn frame_jacobian<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        name: &str,
        reference: &str,
        point: Option<[f64; 3]>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (body, p, frame) = (
            self.body(name)?,
            point_arg(point)?,
            super::reference(reference)?,
        );
        let shape = [6, self.model.nv()];
        self.run(py, &[self.q_arg(q)], &shape, threads, |m, w, o| {
            kernels::jacobian(m, w, (body, &p, frame), o)
        })
    }

    /// Centre of mass (world, 3).
    #[pyo3(signature = (q, threads = None))]
    fn com<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.run(py, &[self.q_arg(q)], &[3], threads, kernels::com)
    }

    /// CoM Jacobian `J_C` (3 x nv).
    #[pyo3(signature = (q, threads = None))]
    fn com_jacobian<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let shape = [3, self.model.nv()];
        self.run(py, &[self.q_arg(q)], &shape, threads, |m, w, o| {
            kernels::centroidal(m, w, CentroidalMatrix::Com, o)
        })
    }

    /// Centroidal momentum `h_G = [L_G; p]` (6, world axes, about the CoM).
    #[pyo3(signature = (q, v, threads = None))]
    fn centroidal_momentum<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let args = [self.q_arg(q), Self::arg("v", v, &[self.model.nv()])];
        self.run(py, &args, &[6], threads, kernels::momentum)
    }

    /// Centroidal momentum matrix `A_G` (6 x nv, `h_G = A_G v`).
    #[pyo3(signature = (q, threads = None))]
    fn centroidal_matrix<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let shape = [6, self.model.nv()];
        self.run(py, &[self.q_arg(q)], &shape, threads, |m, w, o| {
            kernels::centroidal(m, w, CentroidalMatrix::Full, o)
        })
    }

    /// Angular-momentum Jacobian `J_L` (3 x nv, `L_G = J_L v`): the top rows of `A_G`.
    #[pyo3(signature = (q, threads = None))]
    fn centroidal_jacobian<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let shape = [3, self.model.nv()];
        self.run(py, &[self.q_arg(q)], &shape, threads, |m, w, o| {
            kernels::centroidal(m, w, CentroidalMatrix::Angular, o)
        })
    }
}
