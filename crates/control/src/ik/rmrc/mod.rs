//! Resolved motion rate control (4.11)-(4.12) solved the Klein-Huang way (Algorithm 4.3),
//! with optional damping (damped least squares, 4.4) and per-row softness (task blending).
//!
//! Signs, derived from (4.11): minimise `1/2 qd^T W qd + alpha_N grad_H^T qd` subject to
//! `J qd = xd`. The Lagrange conditions give `qd = W^-1 J^T lambda + z` with
//! `z = -alpha_N W^-1 grad_H` and `(J W^-1 J^T) lambda = xd - J z`, i.e. (4.12):
//! `qd = J#_W xd - alpha_N N W^-1 grad_H` with `N = E - J#_W J` (Alg. 4.3 lines 1-5).
//! Neither `J#`, `N` nor `W^-1` is formed; only the m x m matrix `B` is factorised in place.
//!
//! Extensions (both keep the same structure): `damping` adds `lambda_d^2 E` to `B` (the
//! weighted damped least squares solution `W^-1 J^T (J W^-1 J^T + lambda_d^2 E)^-1 xd`), and
//! `softness` adds `c_i >= 0` to `B_ii`, the KKT system of the penalty problem
//! `1/2 qd^T W qd + sum_i (xd_i - J_i qd)^2 / (2 c_i)`. As `c_i -> infinity` row `i` drops out
//! continuously; this is how tasks are blended in and out (see [`crate::ik::blend`]).
//!
//! Assembly: the rows are stacked into `B` (`kernel`), except in the named fast case of
//! trailing soft unit rows (a posture or joint task, [`Rmrc::set_unit_rows`]), which are folded
//! into the joint weight and gradient instead (`fold`): the same solution with a smaller `B`.

mod dense;
mod fold;
mod kernel;
#[cfg(test)]
mod tests;

use super::weight::Weight;
use crate::error::IkError;
use fold::Fold;
use kernel::Kernel;
use nalgebra::{DMatrix, DVector};

/// One RMRC problem: the first `rows` rows of `jacobian` and `xdot` form `J` and `xd` (4.12).
#[derive(Debug, Clone, Copy)]
pub struct RmrcProblem<'a> {
    /// Task Jacobian buffer (at least `rows` x n).
    pub jacobian: &'a DMatrix<f64>,
    /// Number of active task rows m.
    pub rows: usize,
    /// Task velocity buffer (at least `rows` entries).
    pub xdot: &'a DVector<f64>,
    /// Joint-space weight W (4.7).
    pub weight: &'a Weight,
    /// Null-space term: gradient of H (length n) and `alpha_N = beta dt` (4.12).
    pub null_space: Option<(&'a DVector<f64>, f64)>,
    /// Damping `lambda_d^2 >= 0` added to `J W^-1 J^T` (damped least squares, section 4.4).
    pub damping: f64,
    /// Per-row softness `c_i >= 0` added to `B_ii` (task blending; 0 = hard constraint).
    pub softness: Option<&'a [f64]>,
}

impl<'a> RmrcProblem<'a> {
    /// Hard problem `J qd = xd` with weight `W` and no null-space term (4.9).
    pub fn new(
        jacobian: &'a DMatrix<f64>,
        rows: usize,
        xdot: &'a DVector<f64>,
        weight: &'a Weight,
    ) -> Self {
        Self {
            jacobian,
            rows,
            xdot,
            weight,
            null_space: None,
            damping: 0.0,
            softness: None,
        }
    }
}

/// Preallocated Klein-Huang RMRC solver (Algorithm 4.3) for up to `m_max` rows and n DoF.
#[derive(Debug, Clone)]
pub struct Rmrc {
    kernel: Kernel,
    fold: Fold,
}

impl Rmrc {
    /// Solver for at most `m_max` task rows and `n` joint velocities.
    pub fn new(m_max: usize, n: usize) -> Self {
        Self {
            kernel: Kernel::new(m_max, n),
            fold: Fold::new(m_max, n),
        }
    }

    /// Number of joint velocities n.
    pub fn nv(&self) -> usize {
        self.kernel.n
    }

    /// Lagrange multipliers `lambda` of the last solve (first m entries are valid).
    pub fn multipliers(&self) -> &DVector<f64> {
        &self.kernel.lambda
    }

    /// Declares that the last `columns.len()` rows of the following problems are unit rows:
    /// row `m - k + i` of `J` is zero except in column `columns[i]` (the rows of a posture or
    /// joint task). Where all of them are soft (`damping + c_r > 0`) they are folded into the
    /// weight (module docs); an empty slice (the default) stacks every row.
    pub fn set_unit_rows(&mut self, columns: &[usize]) -> Result<(), IkError> {
        if columns.len() > self.kernel.capacity() || columns.iter().any(|&c| c >= self.nv()) {
            return Err(IkError::InvalidParameter {
                name: "unit rows",
                reason: "at most m_max rows, each column below n",
            });
        }
        self.fold.columns.clear();
        self.fold.columns.extend_from_slice(columns);
        Ok(())
    }

    /// `qdot = J#_W xd - alpha_N N W^-1 grad_H` (4.12) by Algorithm 4.3, without allocation.
    pub fn solve(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        self.kernel.check(p, qdot)?;
        self.fold.last = None;
        if !self.fold.prepare(p)? {
            return self.kernel.solve(p, qdot);
        }
        self.kernel.solve(&self.fold.problem(p), qdot)?;
        self.fold.last = Some(p.rows);
        self.fold.multipliers(p, qdot, &mut self.kernel.lambda);
        Ok(())
    }

    /// Same as [`Self::solve`] for a problem with the Jacobian, weight, damping and softness
    /// of the last successful `solve` (only `xdot` and the null-space term may differ):
    /// reuses the factorisation, O(m n) instead of O(m^2 n). RMRC is linear in
    /// `(xdot, grad_H)`, so responses to separate inputs can be superposed.
    pub fn resolve(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        self.kernel.check(p, qdot)?;
        if self.fold.last != Some(p.rows) {
            return self.kernel.resolve(p, qdot);
        }
        if !self.fold.prepare(p)? {
            return Err(IkError::InvalidParameter {
                name: "resolve",
                reason: "needs a preceding solve with the same rows",
            });
        }
        self.kernel.resolve(&self.fold.problem(p), qdot)?;
        self.fold.multipliers(p, qdot, &mut self.kernel.lambda);
        Ok(())
    }

    /// Yoshikawa manipulability `w = sqrt(det(J J^T))` (4.22) of the first `rows` rows, from
    /// the Cholesky factor (`prod L_ii`); 0 if `J J^T` is numerically singular.
    pub fn manipulability(&mut self, jacobian: &DMatrix<f64>, rows: usize) -> Result<f64, IkError> {
        self.fold.last = None;
        self.kernel.manipulability(jacobian, rows)
    }
}
