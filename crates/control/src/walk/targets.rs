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
use crate::pattern::{Contact, Foot, FootGeometry, PatternSample};
use crate::tasks::{FootFrame, LolaTargets, TaskId};
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

/// Joint-task slots of the toe joints in [`LolaTargets::joints`], per [`SLOT_FOOT`] slot.
const TOE_TASK: [TaskId; 2] = [TaskId::RightToe, TaskId::LeftToe];

/// Writes all targets and feed-forward velocities of `s` into `t`: foot tasks on the sole, or
/// on the toe segment while the heel is lifted (toe-off) if the feet have toes (`foot.1`),
/// toe joint tasks from the pattern's toe angles; the arm CoG targets only if `arms` is
/// given, the other joint targets are left as they are.
pub(crate) fn set_targets(
    s: &PatternSample,
    com_offset: &Vector3<f64>,
    (foot, toes): (&FootGeometry, bool),
    arms: Option<&ArmTargets>,
    t: &mut LolaTargets,
) {
    let upper = s.torso.to_rotation_matrix().into_inner();
    t.planning_yaw = yaw_of(&upper);
    t.cog = s.com + com_offset;
    t.upper_body = upper;
    let at = upper.transpose();
    let rpt = Rotation3::from_axis_angle(&Vector3::z_axis(), t.planning_yaw)
        .into_inner()
        .transpose();
    let v = &mut t.velocity;
    for (slot, side) in SLOT_FOOT.iter().enumerate() {
        let f = s.foot(*side);
        let (frame, (pose, linear, angular)) = match f.contact {
            Contact::Toe if toes => (FootFrame::Toe, f.toe_frame(foot)),
            _ => (FootFrame::Sole, (f.pose, f.linear, f.angular)),
        };
        t.foot_frame[slot] = frame;
        let c = s.com + com_offset;
        t.foot_position[slot] = rpt * (pose.translation.vector - c);
        t.foot_orientation[slot] = at * pose.rotation.to_rotation_matrix().into_inner();
        let pos_id = [TaskId::RightFootPosition, TaskId::LeftFootPosition][slot];
        let rot_id = [TaskId::RightFootOrientation, TaskId::LeftFootOrientation][slot];
        let lin = rpt * (linear - s.com_vel);
        let w = at * (angular - s.torso_angular);
        for i in 0..3 {
            v[pos_id.full_offset() + i] = lin[i];
            v[rot_id.full_offset() + i] = w[i];
        }
        if toes {
            let toe = TOE_TASK[slot];
            t.joints[toe.joint_slot().unwrap_or(0)] = f.toe_angle;
            v[toe.full_offset()] = f.toe_rate;
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
