//! Harmonic Drive rotors (3.1)-(3.2) in the kinematics: constant rotor frames, the rotor
//! transform at angle `N q + offset` and the rotor's relative kinematics without evaluating
//! the mechanism.

use super::coupled::part_transform;
use crate::mechanism::harmonic_drive::HarmonicDriveRotor;
use crate::mechanism::MechanismError;
use crate::model::coupling::Mechanism;
use crate::model::{Body, JointModel};
use crate::spatial::{sin_cos, Axis, Motion, SpatialTransform};
use crate::{Data, Model};
use nalgebra::{Isometry3, Translation3, Vector3};

/// Harmonic Drive rotor (3.1)-(3.2) without evaluating the mechanism: the rotor turns by
/// `N q + offset` about the z axis of the constant frame `data.rotor_frame[i]` (placement times
/// the rotor's initial pose, precomputed by [`rotor_frames`]); its Jacobian column
/// `[0, 0, N, 0, 0, 0]` is constant (set in [`crate::Data::new`]) and its bias is zero.
#[inline]
pub(super) fn rotor_kinematics(
    rotor: &HarmonicDriveRotor,
    body: &Body,
    data: &mut Data,
    i: usize,
    q: &[f64],
    v: Option<&[f64]>,
) -> (SpatialTransform, Motion, Motion) {
    let Some(x) = rotor_transform(rotor, &data.rotor_frame[i], q[body.q_set.as_slice()[0]]) else {
        data.mechanism_fault = Some((
            i,
            MechanismError::BadInput {
                mechanism: "harmonic drive rotor",
                reason: "non-finite input".into(),
            },
        ));
        return (body.placement_x, Motion::zero(), Motion::zero());
    };
    let qd = v.map_or(0.0, |v| v[body.v_set.as_slice()[0]]);
    let rel = Motion::new(
        Vector3::new(0.0, 0.0, rotor.params().ratio * qd),
        Vector3::zeros(),
    );
    (x, rel, Motion::zero())
}

/// Per body: the constant frame of a part moving about or along a fixed axis, as a transform
/// from the parent, identity for other bodies: for a Harmonic Drive rotor the placement times
/// its initial pose (`A_pk'`, `r_0` of (3.2)), for an ankle roller-screw rotor or nut the
/// placement times its frame at spin angle and travel zero (3.22), (3.29). The part spins about
/// or moves along this frame's z axis.
pub(crate) fn rotor_frames(model: &Model) -> Vec<SpatialTransform> {
    let frame = |b: &Body| match &b.joint_model {
        JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            ..
        } => {
            let p = rotor.params();
            let initial = Isometry3::from_parts(Translation3::from(p.position), p.orientation);
            SpatialTransform::from_pose(&(b.placement * initial))
        }
        JointModel::Coupled {
            mechanism: Mechanism::Ankle(part),
            ..
        } => match part.axis_frame() {
            Some((rot, pos, _)) => part_transform(&b.placement_x, false, &rot, &pos),
            None => SpatialTransform::identity(),
        },
        _ => SpatialTransform::identity(),
    };
    model.bodies.iter().map(frame).collect()
}

/// Transform `C` of a Harmonic Drive rotor at angle `N q + offset` about the z axis of its
/// constant frame `frame` (3.1)-(3.2); `None` for a non-finite angle.
#[inline]
pub(crate) fn rotor_transform(
    rotor: &HarmonicDriveRotor,
    frame: &SpatialTransform,
    q: f64,
) -> Option<SpatialTransform> {
    let angle = rotor.rotor_angle(q);
    if !angle.is_finite() {
        return None;
    }
    let (s, c) = sin_cos(angle);
    Some(SpatialTransform::new(
        Axis::Z.rot_tr_mul(s, c, &frame.rot),
        frame.trans,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{forward_kinematics, joint_column, update_placements};
    use crate::mechanism::harmonic_drive::HarmonicDriveParams;
    use crate::mechanism::Coupling;
    use crate::model::{BodySpec, ModelBuilder};
    use crate::spatial::RigidInertia;
    use nalgebra::UnitQuaternion;
    use nalgebra::{DVector, Matrix3};

    /// Base on a revolute joint carrying a link and its Harmonic Drive rotor.
    fn rotor_model() -> (Model, HarmonicDriveRotor) {
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let rotor = HarmonicDriveRotor::new(HarmonicDriveParams {
            ratio: -80.0,
            orientation: UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1),
            position: Vector3::new(0.01, -0.02, 0.3),
            offset: 0.4,
        })
        .expect("valid rotor");
        let mut b = ModelBuilder::new();
        let spec = |name: &str, parent, joint, placement| {
            BodySpec::named(name, parent, joint, placement, inertia)
        };
        let place = Isometry3::new(Vector3::new(0.2, 0.1, -0.3), Vector3::new(0.4, 0.5, -0.6));
        let axis = Vector3::y_axis();
        let base = b
            .add_body(spec("base", None, JointModel::Revolute { axis }, place))
            .expect("base");
        let link = b
            .add_body(spec(
                "link",
                Some(base),
                JointModel::Revolute { axis },
                place,
            ))
            .expect("link");
        let joint = JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            inputs: vec![link],
        };
        b.add_body(spec("rotor", Some(base), joint, place))
            .expect("rotor");
        (b.build().expect("model"), rotor)
    }

    /// The rotor fast path against the generic mechanism evaluation: pose `placement * pose`,
    /// velocity `C v_p + J qd`, bias `b = w x (J qd)`-type terms through a zero-bias mechanism.
    #[test]
    fn rotor_fast_path_matches_the_mechanism() {
        let (model, rotor) = rotor_model();
        let mut data = Data::new(&model);
        let q = DVector::from_vec(vec![0.7, -1.3]);
        let v = DVector::from_vec(vec![2.0, -0.5]);
        let a = DVector::zeros(2);
        forward_kinematics(&model, &mut data, &q, &v, &a).expect("kinematics");
        let body = &model.bodies[2];
        let m = rotor.motion(&[q[1]], &[v[1]]).expect("motion");
        let x = SpatialTransform::from_pose(&(body.placement * m.pose));
        assert!((data.x[2].rot - x.rot).amax() < 1e-12);
        assert!((data.x[2].trans - x.trans).amax() < 1e-12);
        let rel = Motion::from_vector(&(m.jacobian[0] * v[1]));
        let vel = x.apply_motion(&data.vel[0]) + rel;
        assert!((data.vel[2].ang - vel.ang).amax() < 1e-12);
        assert!((data.vel[2].lin - vel.lin).amax() < 1e-12);
        let col = joint_column(&data, 2, &body.joint, 0);
        assert_eq!(col.ang, Vector3::new(0.0, 0.0, rotor.params().ratio));
        let mut qn = q.clone();
        qn[1] = f64::NAN;
        assert!(update_placements(&model, &mut data, &qn).is_err());
    }
}
