//! The release test of the active set (see [`super`]): the multipliers of the held joints.

use super::SaturatedRmrc;
use crate::ik::rmrc::RmrcProblem;
use crate::ik::weight::Weight;
use nalgebra::DVector;

impl SaturatedRmrc {
    /// Held joint with the largest multiplier of the wrong sign, if any: with
    /// `r = W qd + alpha_N grad_H - J^T lambda` (zero for the free joints, the force that
    /// holds a fixed one), a joint held at its upper edge is released for `r_i > 0`, at its
    /// lower edge for `r_i < 0` (KKT conditions of the box constraints).
    pub(super) fn releasable(&self, p: &RmrcProblem<'_>, qdot: &DVector<f64>) -> Option<usize> {
        let lambda = &self.rmrc.multipliers().as_slice()[..p.rows];
        let uq = match p.weight {
            Weight::DiagonalRankOne { u, .. } => u.dot(qdot),
            _ => 0.0,
        };
        let nr = p.jacobian.nrows();
        let mut best = (None, 1e-9);
        for i in (0..self.fixed.len()).filter(|&i| self.fixed[i] && !self.pinned[i]) {
            let wq = match p.weight {
                Weight::Identity => qdot[i],
                Weight::Diagonal(d) => d[i] * qdot[i],
                Weight::DiagonalRankOne { diag, u } => diag[i] * qdot[i] + u[i] * uq,
            };
            let g = p.null_space.map_or(0.0, |(g, a)| a * g[i]);
            let col = &p.jacobian.as_slice()[i * nr..i * nr + p.rows];
            let jl: f64 = col.iter().zip(lambda).map(|(j, l)| j * l).sum();
            let r = wq + g - jl;
            let wrong = if self.upper[i] { r } else { -r };
            if wrong > best.1 {
                best = (Some(i), wrong);
            }
        }
        best.0
    }
}
