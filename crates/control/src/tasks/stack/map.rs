//! [`TaskMap`] of a [`TaskStack`]: one kinematics pass (and one centroidal pass when a task
//! needs it), then the active tasks' rows, soft joint-space tasks last.

use super::unit::{is_unit, push_columns};
use super::{kin, TaskStack};
use crate::error::IkError;
use crate::ik::TaskMap;
use crate::tasks::rows::com_jacobian_from_ag;
use nalgebra::{DMatrix, DVector};

impl TaskMap for TaskStack {
    fn nq(&self) -> usize {
        self.model.nq()
    }

    fn nv(&self) -> usize {
        self.model.nv()
    }

    fn max_rows(&self) -> usize {
        self.rows
    }

    /// Stacks the active tasks in insertion order (soft joint-space tasks last).
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        let (rows, nv) = (self.rows, self.model.nv());
        if err.len() < rows || jac.nrows() < rows || jac.ncols() != nv {
            return Err(IkError::Dimension {
                what: "task buffers (rows)",
                expected: rows,
                got: err.len().min(jac.nrows()),
            });
        }
        self.jac
            .compute(&self.model, &mut self.data, q)
            .map_err(kin)?;
        if self.tasks.iter().any(|t| t.kind.needs_centroidal()) {
            self.cen
                .compute_matrix_with(&self.model, &self.data, &self.jac)
                .map_err(kin)?;
            let ag = self.cen.ag().map_err(kin)?;
            com_jacobian_from_ag(ag, self.cen.mass(), &mut self.jc);
            self.cen
                .angular_momentum_jacobian(&mut self.jl)
                .map_err(kin)?;
        }
        let mut r = 0;
        self.unit.clear();
        for unit in [false, true] {
            for k in 0..self.tasks.len() {
                if !self.tasks[k].active || is_unit(&self.tasks[k]) != unit {
                    continue;
                }
                self.write_task(k, q, r, err, jac)?;
                self.write_velocity(k, r);
                r += self.tasks[k].kind.dim();
                if unit {
                    push_columns(&self.tasks[k].kind, &mut self.unit);
                }
            }
        }
        Ok(r)
    }

    fn feedforward(&self, out: &mut DVector<f64>) {
        out.rows_mut(0, self.rows).copy_from(&self.ff);
    }

    fn softness(&self) -> Option<&[f64]> {
        Some(&self.soft)
    }

    fn unit_rows(&self) -> &[usize] {
        &self.unit
    }

    fn retract(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        step: f64,
        out: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        crate::tasks::retract::retract_configuration(&self.model, q, v, step, out)
    }
}
