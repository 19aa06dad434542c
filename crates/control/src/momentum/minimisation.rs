//! Angular momentum minimisation through the RMRC weight (thesis 7.5, (7.13)-(7.15)).
//!
//! RMRC (4.11) minimises `1/2 qdot^T W qdot` (+ the null-space cost) subject to the tasks.
//! With `W = D + J_Lz^T J_Lz` the objective becomes `1/2 qdot^T D qdot + 1/2 L_z^2`
//! (`L_z = J_Lz qdot`, (7.2)): among all velocities that track `xdot`, the solver now trades
//! joint speed against vertical momentum, so the redundant DoFs (arms, pelvis, ...) move to
//! cancel `L_z`. `D = delta E` in the thesis (`delta = 0.5` on Lola); `D = delta diag(d)` is
//! offered for a per-joint base weight. `J_Lz^T J_Lz` has rank one, hence `D > 0` keeps `W`
//! invertible, and `W^-1` is the Sherman-Morrison formula (7.14)-(7.15), applied by
//! [`Weight::solve_into`] without forming `W`.
//!
//! Guarantee (why it minimises): let `qdot_D` minimise `qdot^T D qdot` and `qdot_W` minimise
//! `qdot^T W qdot` under the same task constraint. Optimality of each gives
//! `qdot_W^T D qdot_W + L_z(qdot_W)^2 <= qdot_D^T D qdot_D + L_z(qdot_D)^2` and
//! `qdot_D^T D qdot_D <= qdot_W^T D qdot_W`, so `|L_z(qdot_W)| <= |L_z(qdot_D)|`
//! (checked on random Lola states in `tests/momentum_minimisation.rs`).

use super::error::{check_finite, check_len, positive, MomentumError};
use crate::ik::Weight;
use nalgebra::DVector;

/// The weight `W = delta D + J_Lz^T J_Lz` of (7.13), refreshed in place every cycle.
#[derive(Clone, Debug)]
pub struct MomentumMinimisation {
    delta: f64,
    base: Option<DVector<f64>>,
}

impl MomentumMinimisation {
    /// `W = delta E + J_Lz^T J_Lz` (7.13), `delta > 0`.
    pub fn new(delta: f64) -> Result<Self, MomentumError> {
        Ok(Self {
            delta: positive("delta", delta)?,
            base: None,
        })
    }

    /// `W = delta diag(d) + J_Lz^T J_Lz` with per-joint base weights `d_i > 0`.
    pub fn with_base(delta: f64, d: DVector<f64>) -> Result<Self, MomentumError> {
        let delta = positive("delta", delta)?;
        for &di in d.iter() {
            positive("base weight", di)?;
        }
        Ok(Self {
            delta,
            base: Some(d),
        })
    }

    /// The regularisation `delta`.
    pub fn delta(&self) -> f64 {
        self.delta
    }

    /// A fresh `Weight::DiagonalRankOne` of size `nv` (allocates; call once, then [`Self::update`]).
    pub fn weight(&self, nv: usize) -> Result<Weight, MomentumError> {
        let mut w = Weight::DiagonalRankOne {
            diag: DVector::zeros(nv),
            u: DVector::zeros(nv),
        };
        self.fill_diag(&mut w, nv)?;
        Ok(w)
    }

    /// Writes `W = delta D + J_Lz^T J_Lz` into `w` in place (`jlz` = `J_Lz^T`, length nv). `w`
    /// must be a `DiagonalRankOne` of that size (from [`Self::weight`]); no allocation.
    pub fn update(&self, jlz: &DVector<f64>, w: &mut Weight) -> Result<(), MomentumError> {
        check_finite("jlz", jlz.iter())?;
        self.fill_diag(w, jlz.len())?;
        if let Weight::DiagonalRankOne { u, .. } = w {
            u.copy_from(jlz);
        }
        Ok(())
    }

    /// Sets the diagonal `delta D` of a `DiagonalRankOne` weight of size `n`.
    fn fill_diag(&self, w: &mut Weight, n: usize) -> Result<(), MomentumError> {
        let Weight::DiagonalRankOne { diag, u } = w else {
            return Err(MomentumError::InvalidParameter {
                name: "weight",
                value: f64::NAN,
                reason: "must be Weight::DiagonalRankOne (use MomentumMinimisation::weight)",
            });
        };
        check_len("weight diagonal", diag.len(), n)?;
        check_len("weight rank-one vector", u.len(), n)?;
        match &self.base {
            None => diag.fill(self.delta),
            Some(d) => {
                check_len("base weight", d.len(), n)?;
                diag.zip_apply(d, |o, di| *o = self.delta * di);
            }
        }
        Ok(())
    }
}
