//! Compensation (7.3)-(7.9) of [`WalkController`] solved within the cycle and inside the
//! joint limits ([`crate::momentum::InCycleCompensation`]).

use super::WalkController;
use crate::ik::RmrcProblem;
use crate::ik::TaskMap;
use crate::walk::error::WalkError;

impl WalkController {
    /// Adds the in-cycle compensating term towards `l_desired` to the cycle's `qdot`.
    pub(super) fn compensate(&mut self, l_desired: f64) -> Result<(), WalkError> {
        let p = RmrcProblem {
            jacobian: &self.buf.jac,
            rows: self.buf.rows,
            xdot: &self.xcmd,
            weight: &self.weight,
            null_space: Some((&self.grad, 1.0)),
            damping: 0.0,
            softness: self.tasks.softness(),
        };
        let jlz = self.vm.jacobian_z();
        self.comp
            .apply(&mut self.sns, &p, jlz, l_desired, &mut self.qdot)?;
        Ok(())
    }
}
