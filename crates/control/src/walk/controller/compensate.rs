//! Compensation (7.3)-(7.9) of [`WalkController`] solved within the cycle and inside the
//! joint limits.

use super::WalkController;
use crate::ik::RmrcProblem;
use crate::ik::TaskMap;
use crate::walk::error::WalkError;

/// Joints the compensating term may still hold at their limit box before it is shortened.
const MAX_HOLDS: usize = 4;

impl WalkController {
    /// Compensation (7.3)-(7.9) solved within the cycle: RMRC is linear in the null-space
    /// input, so the response `qd_r` to the reducing direction `y_r = J_{L,r,z}^T` (arms
    /// only, zero task velocity) is computed with the same factorisation, and
    /// `qd += k s qd_r` with `s = (L_d - J_Lz qd) / (J_Lz qd_r)` sets `L_z` to
    /// `k L_d + (1 - k) L_z` exactly, including the tasks' reaction to the arm motion (the
    /// thesis estimates the producing momentum from the previous cycle instead, which at
    /// 1 kHz with gain 1 oscillates). The arm speed of the term is capped at
    /// `compensation_max_speed`. Inside the joint limits: a joint the sum would take out of
    /// its box is held at the box edge, the cycle's solve repeated without it and the term
    /// computed again (saturation in the null space, [`crate::ik::saturation`]); after
    /// [`MAX_HOLDS`] such joints the term is shortened to stay in the box.
    pub(super) fn compensate(&mut self, l_desired: f64) -> Result<(), WalkError> {
        for _ in 0..=MAX_HOLDS {
            let f = self.compensation_step(l_desired)?;
            match self.sns.worst_outside(&self.qdot, &self.qdot_r, f) {
                None => {
                    self.qdot.axpy(f, &self.qdot_r, 1.0);
                    return Ok(());
                }
                Some((i, v)) => {
                    self.sns.hold(i, v);
                    self.resolve_main()?;
                }
            }
        }
        let f = self.compensation_step(l_desired)?;
        let f = self.sns.box_fraction(&self.qdot, &self.qdot_r, f);
        self.qdot.axpy(f, &self.qdot_r, 1.0);
        Ok(())
    }

    /// `qd_r` for the reducing direction and the factor `f` of the compensating term `f qd_r`.
    fn compensation_step(&mut self, l_desired: f64) -> Result<f64, WalkError> {
        let jlz = self.vm.jacobian_z();
        self.dir.fill(0.0);
        for &i in self.comp.reducing() {
            self.dir[i] = jlz[i];
        }
        self.zero_x.fill(0.0);
        let p = RmrcProblem {
            jacobian: &self.buf.jac,
            rows: self.buf.rows,
            xdot: &self.zero_x,
            weight: &self.weight,
            null_space: Some((&self.dir, 1.0)),
            damping: 0.0,
            softness: self.tasks.softness(),
        };
        self.sns.resolve(&p, &mut self.qdot_r)?;
        let effect = jlz.dot(&self.qdot_r);
        if effect.abs() < 1e-12 {
            return Ok(0.0);
        }
        let mut f = self.params.compensation_gain * (l_desired - jlz.dot(&self.qdot)) / effect;
        let peak = self.qdot_r.amax() * f.abs();
        if peak > self.params.compensation_max_speed {
            f *= self.params.compensation_max_speed / peak;
        }
        Ok(f)
    }

    /// The cycle's solve again with the joints held so far (SNS).
    fn resolve_main(&mut self) -> Result<(), WalkError> {
        let p = RmrcProblem {
            jacobian: &self.buf.jac,
            rows: self.buf.rows,
            xdot: &self.xcmd,
            weight: &self.weight,
            null_space: Some((&self.grad, 1.0)),
            damping: 0.0,
            softness: self.tasks.softness(),
        };
        self.sns.saturate(&p, &mut self.qdot)?;
        Ok(())
    }
}
