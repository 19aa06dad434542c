//! Relative kinematics of coupled parts of closed-form mechanisms (thesis ch. 3, see
//! [`crate::mechanism`]): pose, Jacobian columns and joint bias from the mechanism.

use super::rotor::rotor_kinematics;
use crate::mechanism::{Coupling, MechanismError, RelativeMotion, MAX_COUPLED};
use crate::model::coupling::Mechanism;
use crate::model::{Body, JointModel};
use crate::spatial::{Motion, SpatialTransform};
use crate::Data;
use nalgebra::DVector;

/// Relative kinematics of a coupled part from its mechanism (see [`crate::mechanism`]): the
/// Jacobian columns go to `jacobian6[i]`; the joint bias adds `omega_rel x v_rel` to the
/// mechanism's component-wise `Jdot qd` (the frame rotates while `v_rel` is expressed in it).
/// A mechanism error leaves the placement and records the body in `mechanism_fault`.
pub(super) fn coupled_kinematics(
    body: &Body,
    data: &mut Data,
    i: usize,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
) -> (SpatialTransform, Motion, Motion) {
    let JointModel::Coupled { mechanism, .. } = &body.joint_model else {
        return (body.placement_x, Motion::zero(), Motion::zero());
    };
    if let Mechanism::HarmonicDrive(rotor) = mechanism {
        return rotor_kinematics(rotor, body, data, i, q, v);
    }
    let n = body.v_set.len();
    let (mut qin, mut qdin) = ([0.0; MAX_COUPLED], [0.0; MAX_COUPLED]);
    for k in 0..n {
        qin[k] = q[body.q_set.as_slice()[k]];
        qdin[k] = v.map_or(0.0, |v| v[body.v_set.as_slice()[k]]);
    }
    let motion = match mechanism {
        Mechanism::Ankle(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.ankle_loop),
        Mechanism::Knee(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.knee_loop),
        _ => mechanism
            .motion(&qin[..n], &qdin[..n])
            .map(|m| RelativeMotion::from_coupled(&m)),
    };
    let fault = match motion {
        Ok(m) if m.pos.iter().all(|x| x.is_finite()) => Ok(m),
        Ok(_) => Err(MechanismError::BadInput {
            mechanism: "coupled part",
            reason: "non-finite pose".into(),
        }),
        Err(e) => Err(e),
    };
    let m = match fault {
        Ok(m) => m,
        Err(e) => {
            data.mechanism_fault = Some((i, e));
            return (body.placement_x, Motion::zero(), Motion::zero());
        }
    };
    // Pose `placement * (A_pk, r)`: `A_kp = A_pk^T A_placement^T`, origin shifted by the placement.
    let pl = &body.placement_x;
    let x = SpatialTransform::new(m.rot.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(&m.pos));
    let mut rel = Motion::zero();
    for (c, (col, qd)) in m.jacobian.iter().zip(&qdin).take(n).enumerate() {
        data.jacobian6[i].set_column(c, col);
        rel += Motion::from_vector(col) * *qd;
    }
    let mut cj = Motion::from_vector(&m.bias);
    cj.lin += rel.ang.cross(&rel.lin);
    (x, rel, cj)
}
