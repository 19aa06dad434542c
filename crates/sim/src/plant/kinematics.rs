//! `qdot` from `v` for every joint (the position rate of (2.3)), quaternion free joints by
//! `qdot_quat = q (x) (0, omega) / 2` with the body-frame angular velocity.

use biped_dynamics::{JointModel, Model};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Index map from `v` to `qdot`, built once.
#[derive(Debug, Clone, Default)]
pub struct QdotMap {
    /// `(q start, v start, length)` of runs of consecutive scalar coordinates (`qdot = v`),
    /// copied as slices.
    scalar: Vec<(usize, usize, usize)>,
    /// `(q index, v index)` of quaternion free joints.
    free: Vec<(usize, usize)>,
}

impl QdotMap {
    /// Map for `model`.
    pub fn new(model: &Model) -> Self {
        let mut m = Self::default();
        for b in model.bodies().iter().filter(|b| b.owns_coordinates()) {
            let (qi, vi) = (b.q_index(), b.v_index());
            match b.joint() {
                JointModel::FreeQuaternion => m.free.push((qi, vi)),
                j => (0..j.nv()).for_each(|c| m.push_scalar(qi + c, vi + c)),
            }
        }
        m
    }

    /// Adds scalar coordinate `(qi, vi)`, extending the last run if it continues it.
    fn push_scalar(&mut self, qi: usize, vi: usize) {
        match self.scalar.last_mut() {
            Some((q0, v0, n)) if *q0 + *n == qi && *v0 + *n == vi => *n += 1,
            _ => self.scalar.push((qi, vi, 1)),
        }
    }

    /// Writes `qdot(q, v)` into `qdot` (length `nq`).
    pub fn qdot(&self, q: &[f64], v: &[f64], qdot: &mut [f64]) {
        for &(qi, vi, n) in &self.scalar {
            qdot[qi..qi + n].copy_from_slice(&v[vi..vi + n]);
        }
        for &(qi, vi) in &self.free {
            let quat = Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]);
            let rot = UnitQuaternion::new_normalize(quat);
            let lin = rot * Vector3::new(v[vi], v[vi + 1], v[vi + 2]);
            let w = Quaternion::new(0.0, v[vi + 3], v[vi + 4], v[vi + 5]);
            let dq = quat * w * 0.5;
            qdot[qi..qi + 3].copy_from_slice(lin.as_slice());
            qdot[qi + 3] = dq.i;
            qdot[qi + 4] = dq.j;
            qdot[qi + 5] = dq.k;
            qdot[qi + 6] = dq.w;
        }
    }

    /// Renormalises the quaternions of `q` (the manifold projection).
    pub fn normalize(&self, q: &mut [f64]) {
        for &(qi, _) in &self.free {
            let n = q[qi + 3..qi + 7].iter().map(|x| x * x).sum::<f64>().sqrt();
            if n > 1e-12 && n.is_finite() {
                q[qi + 3..qi + 7].iter_mut().for_each(|x| *x /= n);
            }
        }
    }

    /// The first quaternion free joint `(q index, v index)`, if any (the floating base).
    pub fn floating_base(&self) -> Option<(usize, usize)> {
        self.free.first().copied()
    }
}
