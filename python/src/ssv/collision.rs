//! `biped.ssv.CollisionModel`: a collision model read from a TOML file (`biped_ssv::format`),
//! moved to body poses, giving the distances of its segment pairs.

use super::closest;
use crate::error::{biped_err, os_err};
use biped_ssv::format::{self, FormatErrorKind};
use biped_ssv::{CollisionModel, PairDistance, PairQuery};
use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray3};
use pyo3::exceptions::PyFileNotFoundError;
use pyo3::prelude::*;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// One pair's result: names of both segments, then distance and closest points (`None` when
/// the pair is beyond the activation distance and was not computed).
type PairRow = (
    String,
    String,
    Option<f64>,
    Option<[f64; 3]>,
    Option<[f64; 3]>,
);

/// The closest pair: names of both segments, distance and closest points.
type ClosestRow = (String, String, f64, [f64; 3], [f64; 3]);

/// A collision model and the named postures of its file.
#[pyclass(module = "biped._native", name = "CollisionModel")]
pub struct PyCollisionModel {
    model: CollisionModel,
    poses: BTreeMap<String, Vec<Isometry3<f64>>>,
}

/// A 4x4 homogeneous transform as an isometry; errors unless it is a rigid transform.
fn isometry(m: &[f64], body: usize) -> Result<Isometry3<f64>, String> {
    let bad = |what: &str| format!("poses[{body}]: {what}");
    if m.iter().any(|x| !x.is_finite()) {
        return Err(bad("not finite"));
    }
    if m[12..16] != [0.0, 0.0, 0.0, 1.0] {
        return Err(bad("last row is not [0, 0, 0, 1]"));
    }
    let rot = Matrix3::from_fn(|r, c| m[4 * r + c]);
    let err = (rot.transpose() * rot - Matrix3::identity()).amax();
    if err > 1e-6 || rot.determinant() <= 0.0 {
        return Err(bad("rotation part is not a rotation matrix"));
    }
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(rot));
    Ok(Isometry3::from_parts(
        Translation3::new(m[3], m[7], m[11]),
        q,
    ))
}

/// An isometry as a row-major 4x4 transform.
fn homogeneous(iso: &Isometry3<f64>) -> [f64; 16] {
    let h = iso.to_homogeneous();
    std::array::from_fn(|k| h[(k / 4, k % 4)])
}

#[pymethods]
impl PyCollisionModel {
    /// Loads a collision-model file; `within_activation` computes only pairs closer than d_a.
    #[new]
    #[pyo3(signature = (path, within_activation = false))]
    fn new(path: PathBuf, within_activation: bool) -> PyResult<Self> {
        let loaded = format::load(&path).map_err(|e| match (&e.kind, path.exists()) {
            (FormatErrorKind::Io(_), false) => PyFileNotFoundError::new_err(e.to_string()),
            (FormatErrorKind::Io(_), true) => os_err(e.to_string()),
            _ => biped_err(e.to_string()),
        })?;
        let mut model = loaded.model;
        if within_activation {
            model.set_pair_query(PairQuery::WithinActivation);
        }
        Ok(Self {
            model,
            poses: loaded.poses,
        })
    }

    /// Body names; `update` takes one pose per body in this order.
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.model.bodies().to_vec()
    }

    /// Segment names.
    #[getter]
    fn segments(&self) -> Vec<String> {
        self.model
            .segments()
            .iter()
            .map(|s| s.name().to_string())
            .collect()
    }

    /// Segment pairs as `(name_a, name_b)`.
    #[getter]
    fn pairs(&self) -> Vec<(String, String)> {
        let name = |i: usize| self.model.segments()[i].name().to_string();
        self.model
            .pairs()
            .iter()
            .map(|p| (name(p.a), name(p.b)))
            .collect()
    }

    /// Activation distance d_a in metres.
    #[getter]
    fn activation_distance(&self) -> f64 {
        self.model.activation_distance()
    }

    /// The file's named postures: name -> array (nbodies, 4, 4) of body poses.
    #[getter]
    fn poses<'py>(&self, py: Python<'py>) -> PyResult<BTreeMap<String, Bound<'py, PyAny>>> {
        let mut out = BTreeMap::new();
        for (name, poses) in &self.poses {
            let flat: Vec<f64> = poses.iter().flat_map(homogeneous).collect();
            let array = PyArray1::from_vec(py, flat).reshape([poses.len(), 4, 4])?;
            out.insert(name.clone(), array.into_any());
        }
        Ok(out)
    }

    /// Moves the segments to body poses (array (nbodies, 4, 4) in `bodies` order) or to the
    /// file's posture of that name, and evaluates every pair.
    fn update(&mut self, poses: &Bound<'_, PyAny>) -> PyResult<()> {
        if let Ok(name) = poses.extract::<String>() {
            let set = self
                .poses
                .get(&name)
                .ok_or_else(|| biped_err(format!("no pose named \"{name}\"")))?;
            return self.model.update(set).map_err(|e| biped_err(e.to_string()));
        }
        let array: PyReadonlyArray3<f64> = poses.extract().map_err(|_| {
            biped_err("poses: expected a pose name or a float array of shape (nbodies, 4, 4)")
        })?;
        let view = array.as_array();
        let n = self.model.bodies().len();
        if view.shape() != [n, 4, 4] {
            return Err(biped_err(format!(
                "poses: shape {:?}, expected [{n}, 4, 4]",
                view.shape()
            )));
        }
        let flat: Vec<f64> = view.iter().copied().collect();
        let isos = flat
            .chunks_exact(16)
            .enumerate()
            .map(|(i, m)| isometry(m, i));
        let isos = isos.collect::<Result<Vec<_>, _>>().map_err(biped_err)?;
        self.model
            .update(&isos)
            .map_err(|e| biped_err(e.to_string()))
    }

    /// Every pair's result at the last update: `(a, b, distance, point_a, point_b)`.
    fn distances(&self) -> Vec<PairRow> {
        let name = |i: usize| self.model.segments()[i].name().to_string();
        let rows = self.model.distances().map(|(pair, result)| {
            let c = match result {
                PairDistance::Computed(c) => Some(closest(&c.result)),
                PairDistance::Beyond => None,
            };
            (
                name(pair.a),
                name(pair.b),
                c.map(|c| c.0),
                c.map(|c| c.1),
                c.map(|c| c.2),
            )
        });
        rows.collect()
    }

    /// The closest computed pair `(a, b, distance, point_a, point_b)`, or `None`.
    fn min_distance(&self) -> Option<ClosestRow> {
        let (k, c) = self.model.min_distance()?;
        let p = self.model.pairs()[k];
        let name = |i: usize| self.model.segments()[i].name().to_string();
        let (d, pa, pb, _) = closest(&c.result);
        Some((name(p.a), name(p.b), d, pa, pb))
    }
}
