//! Relative kinematics of coupled parts of closed-form mechanisms (thesis ch. 3, see
//! [`crate::mechanism`]): pose, Jacobian columns and joint bias from the mechanism.

use super::rotor::rotor_kinematics;
use crate::mechanism::{Coupling, MechanismError, RelativeMotion, MAX_COUPLED};
use crate::model::coupling::Mechanism;
use crate::model::{Body, JointModel};
use crate::spatial::{Motion, SpatialTransform};
use crate::{Data, Model};
use nalgebra::{Matrix3, Vector3};

/// Relative kinematics of a coupled part from its mechanism (see [`crate::mechanism`]): the
/// Jacobian columns go to `jacobian6[i]`; the joint bias adds `omega_rel x v_rel` to the
/// mechanism's component-wise `Jdot qd` (the frame rotates while `v_rel` is expressed in it).
/// A mechanism error leaves the placement and records the body in `mechanism_fault`.
pub(super) fn coupled_kinematics(
    body: &Body,
    data: &mut Data,
    i: usize,
    q: &[f64],
    v: Option<&[f64]>,
) -> (SpatialTransform, Motion, Motion) {
    let JointModel::Coupled { mechanism, .. } = &body.joint_model else {
        return (body.placement_x, Motion::zero(), Motion::zero());
    };
    if let Mechanism::HarmonicDrive(rotor) = mechanism {
        return rotor_kinematics(rotor, body, data, i, q, v);
    }
    let (qin, qdin, n) = inputs(body, q, v);
    let motion = match mechanism {
        Mechanism::Ankle(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.ankle_loop),
        Mechanism::Knee(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.knee_loop),
        _ => mechanism
            .motion(&qin[..n], &qdin[..n])
            .map(|m| RelativeMotion::from_coupled(&m)),
    };
    let fault = match motion {
        // Non-short-circuit `&`: no branch per component.
        Ok(m) if m.pos.x.is_finite() & m.pos.y.is_finite() & m.pos.z.is_finite() => Ok(m),
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
    let x = part_transform(&body.placement_x, data.unplaced[i], &m.rot, &m.pos);
    let jacobian = &mut data.jacobian6[i];
    let mut rel = Motion::zero();
    #[allow(clippy::needless_range_loop)]
    for c in 0..MAX_COUPLED {
        if c < n {
            let col = &m.jacobian[c];
            jacobian.set_column(c, col);
            rel += Motion::from_vector(col) * qdin[c];
        }
    }
    let mut cj = Motion::from_vector(&m.bias);
    cj.lin += rel.ang.cross(&rel.lin);
    (x, rel, cj)
}

/// `C` of a coupled part at pose `(A_pk, r)` relative to its joint frame: `placement * (A_pk, r)`,
/// i.e. `A_kp = A_pk^T A_placement^T` with the origin shifted by the placement; `unplaced`
/// (identity placement, as for all of Lola's parts) skips the products.
#[inline(always)]
pub(crate) fn part_transform(
    pl: &SpatialTransform,
    unplaced: bool,
    rot: &Matrix3<f64>,
    pos: &Vector3<f64>,
) -> SpatialTransform {
    if unplaced {
        SpatialTransform::new(rot.transpose(), *pos)
    } else {
        SpatialTransform::new(rot.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(pos))
    }
}

/// `C` of coupled part `body` at the configuration `q` (its mechanism evaluated at zero input
/// rates), `None` if the mechanism fails there.
pub(crate) fn coupled_transform(
    body: &Body,
    unplaced: bool,
    q: &[f64],
) -> Option<SpatialTransform> {
    let JointModel::Coupled { mechanism, .. } = &body.joint_model else {
        return None;
    };
    let (qin, qdin, n) = inputs(body, q, None);
    let m = mechanism.motion(&qin[..n], &qdin[..n]).ok()?;
    let m = RelativeMotion::from_coupled(&m);
    Some(part_transform(&body.placement_x, unplaced, &m.rot, &m.pos))
}

/// Spin or travel of axial member `i` (a roller-screw rotor or nut, whose pose the
/// forward-dynamics kinematics skips, [`crate::subsystem::axial`]) into `data.axial_motion[i]`
/// from the loop its mechanism shares with the other parts of the drive; a mechanism error is
/// recorded in `mechanism_fault` as by [`coupled_kinematics`].
pub(crate) fn axial_motion(body: &Body, data: &mut Data, i: usize, q: &[f64], v: &[f64]) {
    let (qin, qdin, n) = inputs(body, q, Some(v));
    let rate = match &body.joint_model {
        JointModel::Coupled {
            mechanism: Mechanism::Ankle(part),
            ..
        } => part.axial_motion_cached(&qin[..n], &qdin[..n], &mut data.ankle_loop),
        JointModel::Coupled {
            mechanism: Mechanism::Knee(part),
            ..
        } => part.axial_motion_cached(&qin[..n], &qdin[..n], &mut data.knee_loop),
        _ => Ok(None),
    };
    match rate {
        Ok(Some(r)) => data.axial_motion[i] = r,
        Ok(None) => {
            let reason = "not a roller-screw rotor or nut".into();
            let e = MechanismError::BadInput {
                mechanism: "coupled part",
                reason,
            };
            data.mechanism_fault = Some((i, e));
        }
        Err(e) => data.mechanism_fault = Some((i, e)),
    }
}

/// The input coordinates and rates of coupled part `body` (unused entries zero) and their
/// count; without `v` the rates are zero.
#[inline(always)]
fn inputs(
    body: &Body,
    q: &[f64],
    v: Option<&[f64]>,
) -> ([f64; MAX_COUPLED], [f64; MAX_COUPLED], usize) {
    let n = body.v_set.len();
    let (mut qin, mut qdin) = ([0.0; MAX_COUPLED], [0.0; MAX_COUPLED]);
    // Constant trip counts (unrolled) guarded by `n <= MAX_COUPLED` (checked by the builder):
    // cheaper than loops over `0..n` or iterator chains (measured).
    for k in 0..MAX_COUPLED {
        if k < n {
            qin[k] = q[body.q_set.as_slice()[k]];
            qdin[k] = v.map_or(0.0, |v| v[body.v_set.as_slice()[k]]);
        }
    }
    (qin, qdin, n)
}

/// Per body: whether its joint placement is the identity (`C` of the joint is the relative
/// pose alone), for [`crate::Data`]'s `unplaced`.
pub(crate) fn identity_placements(model: &Model) -> Vec<bool> {
    let unplaced = |b: &Body| b.placement_x == SpatialTransform::identity();
    model.bodies.iter().map(unplaced).collect()
}

#[cfg(test)]
mod tests {
    use crate::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
    use crate::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
    use crate::model::coupling::Mechanism;
    use crate::model::{BodySpec, JointModel, ModelBuilder};
    use crate::spatial::RigidInertia;
    use crate::{forward_kinematics, Data, Model};
    use nalgebra::{DVector, Isometry3, Matrix3, Vector3};

    /// Thigh, knee (y) with its three knee parts, ankle flexion (y) and adduction (x) with the
    /// six slider-crank parts; every part attached at its parent's frame (identity placement).
    fn leg() -> Model {
        let knee = KneeDrive::new(KneeDriveParams::default()).expect("knee");
        let ankle = AnkleDrive::new(AnkleDriveParams::default()).expect("ankle");
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let mut b = ModelBuilder::new();
        let mut add = |parent, joint, placement| {
            let n = format!("b{parent:?}{placement:?}{joint:?}");
            b.add_body(BodySpec {
                name: n.clone(),
                joint_name: n,
                parent,
                joint,
                placement,
                inertia,
            })
            .expect("body")
        };
        let shift = Isometry3::new(Vector3::new(0.1, -0.2, 0.3), Vector3::new(0.2, 0.1, -0.3));
        let rev = |axis| JointModel::Revolute { axis };
        let thigh = add(None, rev(Vector3::y_axis()), shift);
        let shank = add(Some(thigh), rev(Vector3::y_axis()), shift);
        for part in [KneePart::Housing, KneePart::Nut, KneePart::Rotor] {
            let mechanism = Mechanism::Knee(knee.part(part));
            let joint = JointModel::Coupled {
                mechanism,
                inputs: vec![shank],
            };
            add(Some(thigh), joint, Isometry3::identity());
        }
        let flx = add(Some(shank), rev(Vector3::y_axis()), shift);
        let abd = add(Some(flx), rev(Vector3::x_axis()), shift);
        for act in 0..2 {
            for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
                let mechanism = Mechanism::Ankle(ankle.part(act, part).expect("part"));
                let joint = JointModel::Coupled {
                    mechanism,
                    inputs: vec![flx, abd],
                };
                add(Some(shank), joint, Isometry3::identity());
            }
        }
        ModelBuilder::build(b).expect("model")
    }

    /// The identity-placement shortcut gives the same kinematics as the placement products
    /// (`unplaced` forced off), for every body and output, at several states.
    #[test]
    fn unplaced_parts_equal_the_placement_products() {
        let model = leg();
        let mut fast = Data::new(&model);
        let mut general = fast.clone();
        assert_eq!(fast.unplaced.iter().filter(|&&u| u).count(), 9);
        general.unplaced.fill(false);
        let a = DVector::zeros(model.nv());
        for (q, v) in [
            ([0.3, 0.5, 0.1, -0.05], [0.7, -1.2, 0.4, 0.9]),
            ([-0.4, 1.1, -0.2, 0.1], [-2.0, 0.3, -0.6, 1.5]),
        ] {
            let (q, v) = (DVector::from_row_slice(&q), DVector::from_row_slice(&v));
            forward_kinematics(&model, &mut fast, &q, &v, &a).expect("fast");
            forward_kinematics(&model, &mut general, &q, &v, &a).expect("general");
            for i in 0..model.nbodies() {
                assert_eq!(fast.x[i], general.x[i]);
                assert_eq!(fast.world_rot[i], general.world_rot[i]);
                assert_eq!(fast.world_pos[i], general.world_pos[i]);
                assert_eq!(fast.vel[i], general.vel[i]);
                assert_eq!(fast.bias_acc[i], general.bias_acc[i]);
                assert_eq!(fast.acc[i], general.acc[i]);
            }
        }
    }
}
