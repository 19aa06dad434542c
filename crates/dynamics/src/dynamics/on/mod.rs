//! The O(n) forward-dynamics algorithm of section 2.7-2.8 (Algorithms 2.1-2.4) with sub-systems.
//!
//! Propagation quantities in the thesis' notation, per body `i` with joint Jacobian `J_i`:
//! - backward (2.67)-(2.72): `M-bar_i = M_i + sum_j C_j^T K_j`, `f-bar_i = f_i - sum_j C_j^T k_j`,
//!   `P_i = -(J^T M-bar J)^-1 J^T M-bar C_i`, `p_i = (J^T M-bar J)^-1 (Q_i - J^T (M-bar b_i - f-bar_i))`,
//!   `K_i = M-bar_i (C_i + J_i P_i)`, `k_i = M-bar_i (J_i p_i + b_i) - f-bar_i`;
//! - second forward (2.66), (2.34): `qddot_i = P_i a_p(i) + p_i`, `a_i = C_i a_p(i) + J_i qddot_i + b_i`.
//!
//! Zero pruning: for one-DoF joints `U = M-bar J` is a 6-vector and `D = J^T U` a scalar, so
//! `P_i a = -D^-1 U^T (C_i a)` and `C_i^T K_i = C_i^T (M-bar - U D^-1 U^T) C_i` are evaluated
//! without forming `P_i` or `K_i`. The passes run over the rewired body list (2.9): bodies are
//! dispatched by joint type with one `match` per body, sub-systems (2.6-2.8) by
//! [`crate::subsystem`]'s branches, so geared rotors and coupled parts are supported.
//! Spin-invariant Harmonic Drive rotors enter in their parent's frame without kinematics
//! (`subsystem::axial`), and one-DoF sub-systems of one link plus such rotors take the
//! one-DoF body step with constant rotor terms (`subsystem::link`).
//!
//! Files: `first` (body forces, rotor bias), `backward` (Algorithm 2.3), `forward`
//! (Algorithm 2.4), `six_dof` (the 6-DoF joint steps of both passes).

mod backward;
mod first;
mod forward;
mod six_dof;

pub use backward::backward_pass;
pub use first::forward_pass_1;
pub use forward::forward_pass_2;

use crate::spatial::{Force, Motion, Wrench};
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// What the backward pass leaves for the second forward pass of a one-DoF step (a body or a
/// link-with-rotors sub-system): one record per body, so each step indexes one array.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct OneDofStep {
    /// `U = M-bar J` (for a link with rotors `B_S`, parent frame).
    pub(crate) u: Force,
    /// `D^-1 = (J^T M-bar J)^-1`.
    pub(crate) dinv: f64,
    /// `p` of (2.68).
    pub(crate) p: f64,
}

impl OneDofStep {
    /// `qddot = p - D^-1 U^T a` for the parent acceleration `a` ((2.66) with `P = -D^-1 U^T C`).
    #[inline(always)]
    pub(crate) fn qdd(&self, a: &Motion) -> f64 {
        self.p - self.dinv * self.u.dot(a)
    }
}

/// Body forces and the backward and second forward passes (Algorithms 2.1-2.4 after the
/// kinematics of [`super::forward_dynamics_kinematics`]); inputs are checked by the caller.
pub(crate) fn solve<'d>(
    model: &Model,
    data: &'d mut Data,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<&'d DVector<f64>, DynamicsError> {
    first::dynamic_first_pass(model, data, fext)?;
    backward::backward_unchecked(model, data, tau)?;
    Ok(forward::forward_pass_2(model, data))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    /// Non-finite `tau` is rejected once by the two-phase entry point (the solve itself does
    /// not scan it again) and by the public backward pass.
    #[test]
    fn non_finite_tau_is_rejected() {
        use crate::model::{BodySpec, JointModel, ModelBuilder};
        use crate::spatial::RigidInertia;
        use nalgebra::{Isometry3, Matrix3};
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let mut b = ModelBuilder::new();
        b.add_body(BodySpec {
            name: "link".into(),
            joint_name: "link".into(),
            parent: None,
            joint: JointModel::Revolute {
                axis: Vector3::y_axis(),
            },
            placement: Isometry3::identity(),
            inertia,
        })
        .expect("body");
        let model = b.build().expect("model");
        let mut data = Data::new(&model);
        let (q, v) = (
            DVector::from_element(1, 0.3),
            DVector::from_element(1, -0.2),
        );
        let tau = DVector::from_element(1, f64::NAN);
        crate::forward_dynamics_kinematics(&model, &mut data, &q, &v).expect("kinematics");
        let err =
            crate::forward_dynamics_solve(&model, &mut data, &tau, None, crate::Algorithm::On);
        assert!(matches!(
            err,
            Err(DynamicsError::NonFinite {
                argument: "tau",
                ..
            })
        ));
        let err = backward_pass(&model, &mut data, &tau);
        assert!(matches!(
            err,
            Err(DynamicsError::NonFinite {
                argument: "tau",
                ..
            })
        ));
        let ok = DVector::from_element(1, 0.5);
        assert!(
            crate::forward_dynamics_solve(&model, &mut data, &ok, None, crate::Algorithm::On)
                .is_ok()
        );
    }
}
