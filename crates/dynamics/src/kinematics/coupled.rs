//! Relative kinematics of coupled parts of closed-form mechanisms (thesis ch. 3, see
//! [`crate::mechanism`]): pose, Jacobian columns and joint bias from the mechanism.

use super::rotor::rotor_kinematics;
use crate::mechanism::{Coupling, MechanismError, RelativeMotion, MAX_COUPLED};
use crate::model::coupling::Mechanism;
use crate::model::{Body, JointModel};
use crate::spatial::{Motion, SpatialTransform};
use crate::{Data, Model};

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
    // Pose `placement * (A_pk, r)`: `A_kp = A_pk^T A_placement^T`, origin shifted by the placement
    // (the identity for parts attached at the parent's frame, as all of Lola's).
    let pl = &body.placement_x;
    let x = if data.unplaced[i] {
        SpatialTransform::new(m.rot.transpose(), m.pos)
    } else {
        SpatialTransform::new(m.rot.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(&m.pos))
    };
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
