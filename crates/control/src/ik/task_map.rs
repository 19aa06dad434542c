//! The task map interface shared by all IK solvers: a task set with `x(q)` and `J(q)` (4.1),
//! (4.6), evaluated into caller-provided buffers.
//!
//! Tasks report the *error* `Delta x = x_d - x(q)` (4.13) rather than `x(q)`, because for
//! orientation tasks only the angle-axis error (C.1) is meaningful, and the Jacobian whose
//! rows map joint velocities `v` to task velocities (geometric Jacobian (C.9) for
//! orientations). Configurations may live on a manifold (quaternion base: nq = nv + 1), so
//! the solver moves `q` only through [`TaskMap::retract`].

use super::linalg::check_dim;
use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// A task set `x(q)` with its targets `x_d`: the residual and Jacobian of (4.1)/(4.6).
pub trait TaskMap {
    /// Number of position coordinates of `q`.
    fn nq(&self) -> usize;
    /// Number of velocity coordinates (columns of J).
    fn nv(&self) -> usize;
    /// Capacity of the row buffers (largest m).
    fn max_rows(&self) -> usize;
    /// Writes `Delta x = x_d - x(q)` into the first m entries of `err` and `J(q)` into the
    /// first m rows of `jac` (buffers of `max_rows` rows); returns m.
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError>;
    /// Feed-forward task velocity `xdot_d` (first m entries); the default is zero.
    fn feedforward(&self, out: &mut DVector<f64>) {
        out.fill(0.0);
    }
    /// Per-row softness `c_i >= 0` of blended tasks (see [`crate::ik::rmrc`]); default none.
    fn softness(&self) -> Option<&[f64]> {
        None
    }
    /// Columns of the trailing unit rows of the last evaluation: its last `k` rows are zero
    /// except in these columns, one per row (soft joint-space tasks; the solver folds them into
    /// the joint weight, [`crate::ik::Rmrc::set_unit_rows`]). The default is none.
    fn unit_rows(&self) -> &[usize] {
        &[]
    }
    /// `out = q (+) v step`; the default is the vector sum (nq = nv).
    fn retract(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        step: f64,
        out: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        vector_retract(q, v, step, out)
    }
}

/// `out = q + step v` for configurations in a vector space.
pub fn vector_retract(
    q: &DVector<f64>,
    v: &DVector<f64>,
    step: f64,
    out: &mut DVector<f64>,
) -> Result<(), IkError> {
    check_dim("v", q.len(), v.len())?;
    check_dim("retract output", q.len(), out.len())?;
    out.copy_from(q);
    out.axpy(step, v, 1.0);
    Ok(())
}

/// Preallocated buffers for evaluating a [`TaskMap`]: error, Jacobian and its row count.
#[derive(Debug, Clone)]
pub struct TaskBuffers {
    /// Task error `Delta x` (first `rows` entries valid).
    pub err: DVector<f64>,
    /// Task Jacobian (first `rows` rows valid).
    pub jac: DMatrix<f64>,
    /// Active rows m of the last evaluation.
    pub rows: usize,
}

impl TaskBuffers {
    /// Buffers sized for `task`.
    pub fn new(task: &impl TaskMap) -> Self {
        Self {
            err: DVector::zeros(task.max_rows()),
            jac: DMatrix::zeros(task.max_rows(), task.nv()),
            rows: 0,
        }
    }

    /// Evaluates `task` at `q` into the buffers.
    pub fn evaluate(&mut self, task: &mut impl TaskMap, q: &DVector<f64>) -> Result<(), IkError> {
        self.rows = task.error_and_jacobian(q, &mut self.err, &mut self.jac)?;
        Ok(())
    }

    /// Euclidean norm of the active error rows.
    pub fn error_norm(&self) -> f64 {
        self.err.rows(0, self.rows).norm()
    }

    /// `out = J^T err` over the active rows (the negative gradient of `1/2 |Delta x|^2`).
    pub fn jt_err(&self, out: &mut DVector<f64>) {
        for (c, o) in out.iter_mut().enumerate() {
            *o = (0..self.rows).map(|i| self.jac[(i, c)] * self.err[i]).sum();
        }
    }
}
