//! How [`super::LolaTasks`] configures its stack: the generic task of every [`TaskId`] and
//! the copy of the walking targets into it.

use crate::tasks::frames::{WalkTaskFrames, JOINT_TASKS};
use crate::tasks::targets::{FootFrame, LolaTargets, TaskId};
use crate::tasks::task::{Frame, Point, TaskKind};
use nalgebra::{Matrix3, Rotation3, Vector3};

/// TCP frame of foot slot `s` (0 = right, 1 = left) for its target frame (the sole frame on
/// feet without toes).
pub(super) fn foot_frame(
    frames: (&[Frame; 2], &Option<[Frame; 2]>),
    s: usize,
    which: FootFrame,
) -> Frame {
    match (which, frames.1) {
        (FootFrame::Toe, Some(toes)) => toes[s],
        _ => frames.0[s],
    }
}

/// The stack task of `id` on `frames` (targets set before each evaluation); `None` for an
/// unused joint slot.
pub(super) fn initial_kind(id: TaskId, frames: &WalkTaskFrames) -> Option<TaskKind> {
    let (zero, id3) = (Vector3::zeros(), Matrix3::identity());
    let torso = Frame::body(frames.torso);
    let side = |right: TaskId| (id != right) as usize;
    Some(match id {
        TaskId::RightFootPosition | TaskId::LeftFootPosition => TaskKind::Offset {
            point: Point::Frame(frames.soles[side(TaskId::RightFootPosition)]),
            from: Point::Com,
            axes: id3,
            target: zero,
        },
        TaskId::RightFootOrientation | TaskId::LeftFootOrientation => {
            TaskKind::RelativeOrientation {
                frame: frames.soles[side(TaskId::RightFootOrientation)],
                reference: torso,
                target: id3,
            }
        }
        TaskId::CoG => TaskKind::Com { target: zero },
        TaskId::UpperBodyOrientation => TaskKind::Orientation {
            frame: torso,
            target: id3,
        },
        TaskId::RightArmCoG | TaskId::LeftArmCoG => TaskKind::Offset {
            point: Point::SubtreeCom(frames.arm_roots[side(TaskId::RightArmCoG)]),
            from: Point::Com,
            axes: id3,
            target: zero,
        },
        _ => {
            let k = JOINT_TASKS.iter().position(|&t| t == id)?;
            let (q_index, v_index) = frames.joints[k]?;
            TaskKind::Joint {
                q_index,
                v_index,
                target: 0.0,
            }
        }
    })
}

/// Writes the target (and the foot frame, the planning axes) of task `id` into `kind`.
pub(super) fn set_target(
    id: TaskId,
    kind: &mut TaskKind,
    t: &LolaTargets,
    frames: (&[Frame; 2], &Option<[Frame; 2]>),
    planning: &Matrix3<f64>,
) {
    let foot = |s: usize| foot_frame(frames, s, t.foot_frame[s]);
    let left = matches!(
        id,
        TaskId::LeftFootPosition | TaskId::LeftFootOrientation | TaskId::LeftArmCoG
    ) as usize;
    match kind {
        TaskKind::Offset {
            point,
            axes,
            target,
            ..
        } => {
            *axes = *planning;
            if let Point::Frame(f) = point {
                *f = foot(left);
                *target = t.foot_position[left];
            } else {
                *target = t.arm_cog[left];
            }
        }
        TaskKind::RelativeOrientation { frame, target, .. } => {
            *frame = foot(left);
            *target = t.foot_orientation[left];
        }
        TaskKind::Com { target } => *target = t.cog,
        TaskKind::Orientation { target, .. } => *target = t.upper_body,
        TaskKind::Joint { target, .. } => *target = t.joints[id.joint_slot().unwrap_or(0)],
        _ => {}
    }
}

/// Rotation of the planning frame: yaw about the inertial vertical.
pub(super) fn planning_rotation(yaw: f64) -> Matrix3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), yaw).into_inner()
}
