//! Task targets of Table 4.2 from one walking-pattern sample (pattern frame -> model frame).
//!
//! The pattern's world frame is the model's world frame (the robot is placed on the pattern's
//! initial footprints); only the CoM is shifted by a constant `com_offset` (model CoM minus
//! pattern CoM at the start), because the pattern's LIPM CoM is a point over the feet
//! midpoint, while the model's CoM in the chosen standing pose sits slightly elsewhere.
//! Feed-forward velocities neglect the planning frame's own rotation rate (its yaw rate
//! times a lever of the foot/arm relative position): zero for straight and sideways walks,
//! and corrected by the feedback gain otherwise.

use crate::momentum::{ArmTargets, PointTarget};
use crate::pattern::{Foot, PatternSample};
use crate::tasks::{LolaTargets, TaskId};
use nalgebra::{Matrix3, Rotation3, Vector3};

/// Pattern foot feeding [`LolaTargets`] slot `s` (0 = right, 1 = left).
pub(crate) const SLOT_FOOT: [Foot; 2] = [Foot::Right, Foot::Left];

/// Yaw of a rotation matrix about the vertical.
fn yaw_of(r: &Matrix3<f64>) -> f64 {
    r[(1, 0)].atan2(r[(0, 0)])
}

/// Legs (foot sole points) relative to the target CoG in the planning frame, with velocities:
/// `[right, left]`.
pub(crate) fn legs(s: &PatternSample, com_offset: &Vector3<f64>) -> [PointTarget; 2] {
    let upper = s.torso.to_rotation_matrix().into_inner();
    let rpt = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw_of(&upper))
        .into_inner()
        .transpose();
    let c = s.com + com_offset;
    SLOT_FOOT.map(|f| {
        let foot = s.foot(f);
        PointTarget {
            position: rpt * (foot.pose.translation.vector - c),
            velocity: rpt * (foot.linear - s.com_vel),
        }
    })
}

/// Writes all targets and feed-forward velocities of `s` into `t`; the arm CoG targets only if
/// `arms` is given, the joint targets are left as they are.
pub(crate) fn set_targets(
    s: &PatternSample,
    com_offset: &Vector3<f64>,
    arms: Option<&ArmTargets>,
    t: &mut LolaTargets,
) {
    let upper = s.torso.to_rotation_matrix().into_inner();
    t.planning_yaw = yaw_of(&upper);
    t.cog = s.com + com_offset;
    t.upper_body = upper;
    let at = upper.transpose();
    let legs = legs(s, com_offset);
    let v = &mut t.velocity;
    for (slot, foot) in SLOT_FOOT.iter().enumerate() {
        let f = s.foot(*foot);
        t.foot_position[slot] = legs[slot].position;
        t.foot_orientation[slot] = at * f.pose.rotation.to_rotation_matrix().into_inner();
        let pos_id = [TaskId::RightFootPosition, TaskId::LeftFootPosition][slot];
        let rot_id = [TaskId::RightFootOrientation, TaskId::LeftFootOrientation][slot];
        let w = at * (f.angular - s.torso_angular);
        for i in 0..3 {
            v[pos_id.full_offset() + i] = legs[slot].velocity[i];
            v[rot_id.full_offset() + i] = w[i];
        }
    }
    for i in 0..3 {
        v[TaskId::CoG.full_offset() + i] = s.com_vel[i];
        v[TaskId::UpperBodyOrientation.full_offset() + i] = s.torso_angular[i];
    }
    if let Some(a) = arms {
        for (slot, p) in [a.right, a.left].iter().enumerate() {
            t.arm_cog[slot] = p.position;
            let id = [TaskId::RightArmCoG, TaskId::LeftArmCoG][slot];
            for i in 0..3 {
                v[id.full_offset() + i] = p.velocity[i];
            }
        }
    }
}
