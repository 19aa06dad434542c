//! Rows of the offset task of a [`TaskStack`]: the positions and Jacobians of its points (a
//! frame origin, the CoM, the CoM of a subtree) from the last pass.

use super::{kin, TaskStack};
use crate::error::IkError;
use crate::tasks::rows::put_rows;
use crate::tasks::task::Point;
use biped_dynamics::{Data, Jacobians, Model};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

/// The bodies with mass of the subtree of `root`: `(body, CoM in the body frame, mass)`, and
/// their total mass.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Subtree {
    /// The subtree's first body.
    pub root: usize,
    /// Every body with mass of the subtree.
    pub parts: Vec<(usize, Vector3<f64>, f64)>,
    /// Their total mass \[kg].
    pub mass: f64,
}

impl Subtree {
    /// The subtree of `root` in `model`; errors if it has no mass.
    pub(crate) fn new(model: &Model, root: usize) -> Result<Self, IkError> {
        let in_subtree = |mut b: usize| loop {
            if b == root {
                return true;
            }
            match model.bodies()[b].parent() {
                Some(p) => b = p,
                None => return false,
            }
        };
        let parts: Vec<_> = (0..model.nbodies())
            .filter(|&b| in_subtree(b))
            .map(|b| {
                let i = model.bodies()[b].inertia();
                (b, i.com(), i.mass())
            })
            .filter(|a| a.2 > 0.0)
            .collect();
        let mass: f64 = parts.iter().map(|a| a.2).sum();
        if !(mass > 0.0 && mass.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "subtree CoM task",
                reason: "the subtree has no mass",
            });
        }
        Ok(Self { root, parts, mass })
    }

    /// CoM `sum m_b c_b / m` (world) and its Jacobian `sum m_b J_p(b, c_b) / m` into `out`
    /// (`tmp`: a 3 x nv buffer).
    fn rows(
        &self,
        data: &Data,
        jac: &Jacobians,
        out: &mut DMatrix<f64>,
        tmp: &mut DMatrix<f64>,
    ) -> Result<Vector3<f64>, IkError> {
        out.fill(0.0);
        let mut c = Vector3::zeros();
        for &(b, com, m) in &self.parts {
            c += (data.world_pos[b] + data.world_rot[b] * com) * m;
            jac.point_jacobian(b, &com, tmp).map_err(kin)?;
            let f = m / self.mass;
            for (a, b) in out.iter_mut().zip(tmp.iter()) {
                *a += f * b;
            }
        }
        Ok(c / self.mass)
    }
}

impl TaskStack {
    /// Caches the subtree of every [`Point::SubtreeCom`] of `points` not cached yet.
    pub(super) fn cache_subtrees(&mut self, points: &[Point]) -> Result<(), IkError> {
        for p in points {
            if let Point::SubtreeCom(root) = *p {
                if !self.subtrees.iter().any(|s| s.root == root) {
                    self.subtrees.push(Subtree::new(&self.model, root)?);
                }
            }
        }
        Ok(())
    }

    /// World position of `p` with its Jacobian into `j3` (`from`: into `j3r`).
    fn point_rows(&mut self, p: &Point, from: bool) -> Result<Vector3<f64>, IkError> {
        let out = if from { &mut self.j3r } else { &mut self.j3 };
        match p {
            Point::Frame(f) => {
                let t = f.offset.translation.vector;
                self.jac.point_jacobian(f.body, &t, out).map_err(kin)?;
                Ok(self.data.world_pos[f.body] + self.data.world_rot[f.body] * t)
            }
            Point::Com => {
                out.copy_from(&self.jc);
                Ok(self.cen.com())
            }
            Point::SubtreeCom(root) => {
                let s = self.subtrees.iter().find(|s| s.root == *root);
                let s = s.ok_or(IkError::InvalidParameter {
                    name: "subtree CoM task",
                    reason: "the subtree was not added with the task",
                })?;
                s.rows(&self.data, &self.jac, out, &mut self.jt)
            }
        }
    }

    /// Rows of an offset task at row `r`: `x = A^T (p - p_from)`, `J = A^T (J_p - J_from)`.
    pub(super) fn write_offset(
        &mut self,
        (point, from): (&Point, &Point),
        axes: &Matrix3<f64>,
        target: &Vector3<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let p = self.point_rows(point, false)?;
        let pf = self.point_rows(from, true)?;
        let at = axes.transpose();
        put_rows(out, r, &at, &self.j3, 0, Some(&self.j3r), 0);
        err.fixed_rows_mut::<3>(r)
            .copy_from(&(target - at * (p - pf)));
        Ok(())
    }
}
