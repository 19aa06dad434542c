//! Read access to a [`WalkController`]'s state after a cycle.

use super::WalkController;
use crate::ik::SaturatedRmrc;
use crate::tasks::LolaTasks;
use crate::walk::method::Method;
use biped_dynamics::{Data, Jacobians};
use nalgebra::DVector;

impl WalkController {
    /// The method.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Configuration for the next cycle.
    pub fn q(&self) -> &DVector<f64> {
        &self.q
    }

    /// Configuration at which the last cycle evaluated tasks and momentum.
    pub fn q_eval(&self) -> &DVector<f64> {
        &self.q_eval
    }

    /// Joint velocities of the last cycle (at [`Self::q_eval`]).
    pub fn qdot(&self) -> &DVector<f64> {
        &self.qdot
    }

    /// `J_Lz^T` at [`Self::q_eval`] (7.2).
    pub fn jlz(&self) -> &DVector<f64> {
        self.vm.jacobian_z()
    }

    /// The limit-keeping solver (its box and fixed joints of the last cycle).
    pub fn limiter(&self) -> &SaturatedRmrc {
        &self.sns
    }

    /// The task set (targets, activations, model).
    pub fn tasks(&self) -> &LolaTasks {
        &self.tasks
    }

    /// Kinematics at [`Self::q_eval`].
    pub fn kinematics(&self) -> (&Data, &Jacobians) {
        self.tasks.kinematics()
    }
}
