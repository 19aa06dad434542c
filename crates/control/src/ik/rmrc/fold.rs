//! The unit-row fast case of [`super::Rmrc`]: soft trailing rows `a_r e_v^T` (a posture or
//! joint task: one nonzero entry per row) folded into the joint weight instead of stacked.
//!
//! With `s_r = damping + c_r > 0` such a row adds `(xd_r - a_r qd_v)^2 / (2 s_r)` to the cost
//! of [`super`] (the penalty form of its softness), i.e. `a_r^2 / s_r` to `W_vv` and
//! `-a_r xd_r / s_r` to the gradient `alpha_N grad_H` at v. The remaining rows are solved with
//! that weight and gradient: the same optimum as the stacked system, with `B` of the remaining
//! rows only. The folded rows' multipliers follow as `lambda_r = (xd_r - a_r qd_v) / s_r`
//! (their stacked values, the stacked KKT conditions for `s_r > 0`).

use super::RmrcProblem;
use crate::error::IkError;
use crate::ik::linalg::{check_dim, check_finite};
use crate::ik::weight::Weight;
use nalgebra::DVector;

/// Columns of the trailing unit rows and the folded weight and gradient buffers.
#[derive(Debug, Clone)]
pub(super) struct Fold {
    /// Column v of each trailing unit row, in row order.
    pub(super) columns: Vec<usize>,
    /// Folded `W` when the problem's weight has no rank-one part.
    diagonal: Weight,
    /// Folded `W` when it has one.
    rank_one: Weight,
    /// Folded `alpha_N grad_H`.
    grad: DVector<f64>,
    /// Rows of the problem of the last folded solve (None: the last solve was stacked).
    pub(super) last: Option<usize>,
}

impl Fold {
    /// Buffers for up to `m_max` unit rows on `n` joint velocities.
    pub(super) fn new(m_max: usize, n: usize) -> Self {
        Self {
            columns: Vec::with_capacity(m_max),
            diagonal: Weight::Diagonal(DVector::zeros(n)),
            rank_one: Weight::DiagonalRankOne {
                diag: DVector::zeros(n),
                u: DVector::zeros(n),
            },
            grad: DVector::zeros(n),
            last: None,
        }
    }

    /// Folds the unit rows of checked problem `p` into the buffers; false (nothing done) when
    /// the fast case does not apply: no unit rows, more than `p.rows`, or one of them hard.
    pub(super) fn prepare(&mut self, p: &RmrcProblem<'_>) -> Result<bool, IkError> {
        let (k, n) = (self.columns.len(), self.grad.len());
        let Some(soft) = p.softness.filter(|_| k > 0 && k <= p.rows) else {
            return Ok(false);
        };
        let first = p.rows - k;
        if !soft[first..p.rows].iter().all(|c| p.damping + c > 0.0) {
            return Ok(false);
        }
        p.weight.validate(n)?;
        match p.null_space {
            Some((g, alpha)) => {
                check_dim("null-space gradient", n, g.len())?;
                check_finite("alpha_N", &[alpha])?;
                self.grad.copy_from(g);
                self.grad *= alpha;
            }
            None => self.grad.fill(0.0),
        }
        let d = copy_weight(p.weight, &mut self.diagonal, &mut self.rank_one);
        let nr = p.jacobian.nrows();
        let j = p.jacobian.as_slice();
        for (i, &v) in self.columns.iter().enumerate() {
            let r = first + i;
            let (a, s) = (j[v * nr + r], p.damping + soft[r]);
            debug_assert!(
                (0..n).all(|c| c == v || j[c * nr + r] == 0.0),
                "row {r} not unit"
            );
            d[v] += a * a / s;
            self.grad[v] -= a * p.xdot[r] / s;
        }
        Ok(true)
    }

    /// The problem of the remaining rows with the folded weight and gradient (after a
    /// successful [`Self::prepare`] of `p`).
    pub(super) fn problem<'c>(&'c self, p: &RmrcProblem<'c>) -> RmrcProblem<'c> {
        let weight = match p.weight {
            Weight::DiagonalRankOne { .. } => &self.rank_one,
            _ => &self.diagonal,
        };
        RmrcProblem {
            rows: p.rows - self.columns.len(),
            weight,
            null_space: Some((&self.grad, 1.0)),
            ..*p
        }
    }

    /// The folded rows' multipliers `(xd_r - a_r qd_v) / s_r` into `lambda` (see the module
    /// docs) for the solution `qdot` of the folded problem of `p`.
    pub(super) fn multipliers(
        &self,
        p: &RmrcProblem<'_>,
        qdot: &DVector<f64>,
        lambda: &mut DVector<f64>,
    ) {
        let (first, nr) = (p.rows - self.columns.len(), p.jacobian.nrows());
        let (j, soft) = (p.jacobian.as_slice(), p.softness.unwrap_or(&[]));
        for (i, &v) in self.columns.iter().enumerate() {
            let r = first + i;
            let s = p.damping + soft[r];
            lambda[r] = (p.xdot[r] - j[v * nr + r] * qdot[v]) / s;
        }
    }
}

/// Copies `w` into the buffer of its shape (`diagonal` or `rank_one`); returns that buffer's
/// diagonal.
fn copy_weight<'b>(
    w: &Weight,
    diagonal: &'b mut Weight,
    rank_one: &'b mut Weight,
) -> &'b mut [f64] {
    match (w, diagonal, rank_one) {
        (Weight::Identity, Weight::Diagonal(d), _) => {
            d.fill(1.0);
            d.as_mut_slice()
        }
        (Weight::Diagonal(src), Weight::Diagonal(d), _) => {
            d.copy_from(src);
            d.as_mut_slice()
        }
        (Weight::DiagonalRankOne { diag, u }, _, Weight::DiagonalRankOne { diag: d, u: v }) => {
            d.copy_from(diag);
            v.copy_from(u);
            d.as_mut_slice()
        }
        _ => unreachable!("the fold buffers keep their shapes"),
    }
}
