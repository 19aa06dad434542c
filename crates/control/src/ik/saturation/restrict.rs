//! The problem without the fixed joints (see [`super`]): zeroed Jacobian columns, the
//! restricted rank-one weight, the coupled gradient and the damping of the restricted solve.

use super::SaturatedRmrc;
use crate::error::IkError;
use crate::ik::rmrc::RmrcProblem;
use crate::ik::weight::Weight;
use nalgebra::{DMatrix, DVector};

impl SaturatedRmrc {
    /// Solves the problem without the fixed joints (module docs) and sets their velocities.
    pub(super) fn solve_restricted(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        let m = p.rows;
        let nr = p.jacobian.nrows();
        let src = p.jacobian.as_slice();
        let mm = self.jac.nrows();
        let dst = self.jac.as_mut_slice();
        self.xdot.rows_mut(0, m).copy_from(&p.xdot.rows(0, m));
        for (c, fixed) in self.fixed.iter().enumerate() {
            let (a, b) = (&src[c * nr..c * nr + m], &mut dst[c * mm..c * mm + m]);
            if *fixed {
                b.fill(0.0);
                let s = self.value[c];
                for (x, j) in self.xdot.iter_mut().zip(a) {
                    *x -= j * s;
                }
            } else {
                b.copy_from_slice(a);
            }
        }
        self.restrict_weight(p.weight);
        self.restrict_gradient(p, true);
        self.run_restricted(p, qdot, true)
    }

    /// Solves the restricted problem held in `jac`, `xdot`, `weight` and `grad` (`fresh`:
    /// factorised anew; else with the last factorisation, [`crate::ik::rmrc::Rmrc::resolve`])
    /// and sets the fixed joints' velocities (their held value; 0 for a re-solve, whose
    /// right-hand side is a response).
    pub(super) fn run_restricted(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
        fresh: bool,
    ) -> Result<(), IkError> {
        let q = RmrcProblem {
            jacobian: &self.jac,
            rows: p.rows,
            xdot: &self.xdot,
            weight: restricted(p.weight, &self.weight),
            null_space: Some((&self.grad, 1.0)),
            damping: p.damping + self.damping,
            softness: p.softness,
        };
        match fresh {
            true => self.rmrc.solve(&q, qdot)?,
            false => self.rmrc.resolve(&q, qdot)?,
        }
        for (i, f) in self.fixed.iter().enumerate() {
            if *f {
                qdot[i] = if fresh { self.value[i] } else { 0.0 };
            }
        }
        Ok(())
    }

    /// `lambda^2 = (rho + 1e-12) mean(diag(J W^-1 J^T))` over the first `m` rows of the full
    /// Jacobian `j`, with `diag W^-1 = D^-1 - (D^-1 u)^2 / c` (7.14); the floor keeps `B`
    /// positive definite when the fixed joints take all rank (`rho = 0`: practically exact).
    pub(super) fn regularisation(&mut self, j: &DMatrix<f64>, w: &Weight, m: usize) -> f64 {
        let n = self.fixed.len();
        let (dinv, du) = self.parts.as_mut_slice().split_at_mut(n);
        let c = w.inverse_parts(dinv, du);
        let columns = j.as_slice().chunks_exact(j.nrows().max(1));
        let mut trace = 0.0;
        for (col, (d, e)) in columns.zip(dinv.iter().zip(du.iter())) {
            let winv = if c > 0.0 { d - e * e / c } else { *d };
            trace += winv * col[..m].iter().map(|x| x * x).sum::<f64>();
        }
        (self.limits.settings().regularisation + 1e-12) * trace / m.max(1) as f64
    }

    /// `grad = alpha_N grad_H` zeroed at the fixed joints, plus `W_fs qd_s` if `coupled`.
    pub(super) fn restrict_gradient(&mut self, p: &RmrcProblem<'_>, coupled: bool) {
        match p.null_space {
            Some((g, alpha)) => {
                self.grad.copy_from(g);
                self.grad *= alpha;
            }
            None => self.grad.fill(0.0),
        }
        let cross = match p.weight {
            Weight::DiagonalRankOne { u, .. } if coupled => {
                let us: f64 = (0..u.len())
                    .filter(|&i| self.fixed[i])
                    .map(|i| u[i] * self.value[i])
                    .sum();
                Some((u, us))
            }
            _ => None,
        };
        for i in 0..self.grad.len() {
            if self.fixed[i] {
                self.grad[i] = 0.0;
            } else if let Some((u, us)) = cross {
                self.grad[i] += u[i] * us;
            }
        }
    }

    /// Copies a rank-one weight with the fixed joints' entries of `u` zeroed into the buffer.
    fn restrict_weight(&mut self, w: &Weight) {
        if let Weight::DiagonalRankOne { diag, u } = w {
            match &mut self.weight {
                Weight::DiagonalRankOne { diag: d, u: v } if v.len() == u.len() => {
                    d.copy_from(diag);
                    v.copy_from(u);
                }
                buf => *buf = w.clone(),
            }
            if let Weight::DiagonalRankOne { u: v, .. } = &mut self.weight {
                for (x, f) in v.iter_mut().zip(&self.fixed) {
                    if *f {
                        *x = 0.0;
                    }
                }
            }
        }
    }
}

/// The weight of a restricted solve: the buffer for a rank-one weight, else the weight itself
/// (a diagonal weight needs no change once the fixed columns and gradient entries are 0).
fn restricted<'a>(w: &'a Weight, buf: &'a Weight) -> &'a Weight {
    match w {
        Weight::DiagonalRankOne { .. } => buf,
        _ => w,
    }
}
