//! `biped.Ik`: the generic whole-body IK (`biped_control::whole_body::Ik`) on a URDF, with the URDF's
//! joint position and velocity limits kept by default: frame, CoM, posture and joint tasks
//! by name, moving targets, and one differential step at a time.

use crate::error::{biped_err, guard};
use crate::model::urdf_error;
use biped_control::tasks::{TaskHandle, TaskKind};
use biped_control::whole_body::Ik;
use biped_dynamics::urdf::{load_file, UrdfOptions};
use nalgebra::{DVector, Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use numpy::{AllowTypeChange, PyArray1, PyArrayLikeDyn};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// Differential IK on a URDF (see `biped_control::whole_body::Ik`).
#[pyclass(name = "Ik", module = "biped._native")]
pub struct PyIk {
    ik: Ik,
    nq: usize,
}

/// The finite numbers of `value`, of `shape` (`name` labels errors).
fn numbers(value: &Bound<'_, PyAny>, name: &str, shape: &[usize]) -> PyResult<Vec<f64>> {
    let array: PyArrayLikeDyn<f64, AllowTypeChange> = value
        .extract()
        .map_err(|_| biped_err(format!("\"{name}\": expected an array of numbers")))?;
    let view = array.as_array();
    if view.shape() != shape {
        return Err(biped_err(format!(
            "\"{name}\" has shape {:?}, expected {shape:?}",
            view.shape()
        )));
    }
    let values: Vec<f64> = view.iter().copied().collect();
    match values.iter().position(|x| !x.is_finite()) {
        Some(i) => Err(biped_err(format!("\"{name}\"[{i}] is not finite"))),
        None => Ok(values),
    }
}

/// A 4x4 homogeneous transform with an orthonormal rotation.
fn pose(value: &Bound<'_, PyAny>) -> PyResult<Isometry3<f64>> {
    let m = numbers(value, "pose", &[4, 4])?;
    if m[12..] != [0.0, 0.0, 0.0, 1.0] {
        return Err(biped_err("\"pose\": the last row must be [0, 0, 0, 1]"));
    }
    let rot = rotation(
        &[m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]],
        "pose",
    )?;
    let t = Translation3::new(m[3], m[7], m[11]);
    Ok(Isometry3::from_parts(
        t,
        UnitQuaternion::from_rotation_matrix(&rot),
    ))
}

/// A row-major 3x3 rotation matrix, checked orthonormal.
fn rotation(rows: &[f64], name: &str) -> PyResult<Rotation3<f64>> {
    let m = Matrix3::from_row_slice(rows);
    if (m.transpose() * m - Matrix3::identity()).amax() > 1e-6 || m.determinant() < 0.0 {
        return Err(biped_err(format!(
            "\"{name}\": the rotation is not orthonormal"
        )));
    }
    Ok(Rotation3::from_matrix_unchecked(m))
}

fn vec3(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Vector3<f64>> {
    Ok(Vector3::from_column_slice(&numbers(value, name, &[3])?))
}

impl PyIk {
    fn config(&self, value: &Bound<'_, PyAny>, name: &str) -> PyResult<DVector<f64>> {
        Ok(DVector::from_vec(numbers(value, name, &[self.nq])?))
    }
}

#[pymethods]
impl PyIk {
    /// IK on the URDF at `path` (`floating`: a free-flyer root, the default).
    #[new]
    #[pyo3(signature = (path, floating=true))]
    fn new(path: PathBuf, floating: bool) -> PyResult<Self> {
        let options = UrdfOptions {
            floating,
            ..Default::default()
        };
        let urdf = load_file(&path, &options).map_err(urdf_error)?;
        let nq = urdf.model.nq();
        let ik = Ik::new(&urdf).map_err(|e| biped_err(e.to_string()))?;
        Ok(Self { ik, nq })
    }

    /// Number of position coordinates of `q`.
    #[getter]
    fn nq(&self) -> usize {
        self.nq
    }

    /// A hard task: link `link`'s frame to the world pose `pose` (4x4); returns its handle.
    fn frame_pose(&mut self, link: &str, pose_: &Bound<'_, PyAny>) -> PyResult<usize> {
        let target = pose(pose_)?;
        self.ik.frame_pose(link, target).map(|h| h.0).map_err(err)
    }

    /// A hard task: link `link`'s origin to the world point `position`.
    fn frame_position(&mut self, link: &str, position: &Bound<'_, PyAny>) -> PyResult<usize> {
        let target = vec3(position, "position")?;
        self.ik
            .frame_position(link, target)
            .map(|h| h.0)
            .map_err(err)
    }

    /// A hard task: link `link`'s orientation to the world rotation `rotation` (3x3).
    fn frame_orientation(&mut self, link: &str, rotation_: &Bound<'_, PyAny>) -> PyResult<usize> {
        let rows = numbers(rotation_, "rotation", &[3, 3])?;
        let target = rotation(&rows, "rotation")?.into_inner();
        self.ik
            .frame_orientation(link, target)
            .map(|h| h.0)
            .map_err(err)
    }

    /// A hard task: the offset `axes^T (p - p_from)` of point `point` from point `from_` at
    /// `target`. Points: `"com"`, `"subtree:LINK"` (the CoM of LINK and every link beyond
    /// it) or a link's origin; `axes` (3x3, columns: the axes in world) defaults to the
    /// world axes.
    #[pyo3(signature = (point, from_, target, axes=None))]
    fn offset(
        &mut self,
        point: &str,
        from_: &str,
        target: &Bound<'_, PyAny>,
        axes: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<usize> {
        let axes = match axes {
            Some(a) => rotation(&numbers(a, "axes", &[3, 3])?, "axes")?.into_inner(),
            None => Matrix3::identity(),
        };
        let target = vec3(target, "target")?;
        self.ik
            .offset(point, from_, axes, target)
            .map(|h| h.0)
            .map_err(err)
    }

    /// A hard task: the centre of mass to the world point `position`.
    fn com(&mut self, position: &Bound<'_, PyAny>) -> PyResult<usize> {
        let target = vec3(position, "position")?;
        self.ik.com(target).map(|h| h.0).map_err(err)
    }

    /// A soft task (weight `weight`): every limited joint towards configuration `q`.
    fn posture(&mut self, q: &Bound<'_, PyAny>, weight: f64) -> PyResult<usize> {
        let q = self.config(q, "q")?;
        self.ik.posture(&q, weight).map(|h| h.0).map_err(err)
    }

    /// A hard task: joint `name` to `target` (rad or m).
    fn joint(&mut self, name: &str, target: f64) -> PyResult<usize> {
        self.ik.joint(name, target).map(|h| h.0).map_err(err)
    }

    /// Moves the target of task `task`: a pose (4x4), point (3), rotation (3x3),
    /// configuration (nq) or joint value, as the task was made.
    fn set_target(&mut self, task: usize, target: &Bound<'_, PyAny>) -> PyResult<()> {
        let nq = self.nq;
        let kind = &mut self.ik.task_mut(TaskHandle(task)).map_err(err)?.kind;
        match kind {
            TaskKind::Pose { target: t, .. } => *t = pose(target)?,
            TaskKind::Position { target: t, .. }
            | TaskKind::Com { target: t }
            | TaskKind::Offset { target: t, .. } => *t = vec3(target, "target")?,
            TaskKind::Orientation { target: t, .. } => {
                let rows = numbers(target, "target", &[3, 3])?;
                *t = rotation(&rows, "target")?.into_inner();
            }
            TaskKind::Posture { target: t, .. } => {
                *t = DVector::from_vec(numbers(target, "target", &[nq])?)
            }
            TaskKind::Joint { target: t, .. } => *t = numbers(target, "target", &[])?[0],
            _ => {
                return Err(biped_err(
                    "set_target: this task's target is not settable here",
                ))
            }
        }
        Ok(())
    }

    /// One step of `dt` seconds from configuration `q`: the new configuration and a dict with
    /// the task error norm before the step, the joints held at their limits and the smallest
    /// distance of a joint to its limit after the step.
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        dt: f64,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyDict>)> {
        let mut q = self.config(q, "q")?;
        let ik = &mut self.ik;
        let report = guard(|| ik.step(&mut q, dt).map_err(|e| e.to_string())).map_err(biped_err)?;
        let info = PyDict::new(py);
        info.set_item("error_norm", report.error_norm)?;
        info.set_item("joints_at_limits", report.saturation.fixed)?;
        info.set_item("min_limit_margin", ik.limits().min_margin(&q))?;
        Ok((PyArray1::from_slice(py, q.as_slice()), info))
    }
}

/// An IK error as `BipedError`.
fn err(e: biped_control::error::IkError) -> PyErr {
    biped_err(e.to_string())
}
