//! Task identifiers and targets of Lola's task description (Table 4.2).
//!
//! Frames (our resolution of "torso planning frame", which the thesis does not define): the
//! planning frame is the inertial frame rotated about the vertical by the planned upper-body
//! yaw `planning_yaw` (an input from the walking pattern, not a function of q), so feet and
//! arm CoG positions relative to the CoG are expressed in a heading-aligned frame. Foot
//! orientations are relative to the upper body (torso) and expressed in torso coordinates;
//! the upper body orientation and the CoG are inertial.

use nalgebra::{DVector, Matrix3, Vector3};

/// One task of Table 4.2 (plus joint tasks holding the head and vergence joints).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TaskId {
    /// Right foot TCP (sole or toe frame origin, [`FootFrame`]) relative to the CoG, planning
    /// frame (3).
    RightFootPosition,
    /// Left foot TCP relative to the CoG, planning frame (3).
    LeftFootPosition,
    /// Right foot orientation relative to the upper body (3).
    RightFootOrientation,
    /// Left foot orientation relative to the upper body (3).
    LeftFootOrientation,
    /// Robot CoG in the inertial frame (3).
    CoG,
    /// Upper body (torso) orientation in the inertial frame (3).
    UpperBodyOrientation,
    /// Right arm CoG relative to the robot CoG, planning frame (3).
    RightArmCoG,
    /// Left arm CoG relative to the robot CoG, planning frame (3).
    LeftArmCoG,
    /// Pelvis rotation joint (1).
    PelvisRotation,
    /// Pelvis adduction joint (the `torso` joint) (1).
    PelvisAdduction,
    /// Right toe flexion joint (1).
    RightToe,
    /// Left toe flexion joint (1).
    LeftToe,
    /// Head pan joint (1).
    HeadPan,
    /// Head tilt joint (1).
    HeadTilt,
    /// Camera vergence joint (1).
    Vergence,
}

impl TaskId {
    /// All tasks in stacking order.
    pub const ALL: [TaskId; 15] = [
        TaskId::RightFootPosition,
        TaskId::LeftFootPosition,
        TaskId::RightFootOrientation,
        TaskId::LeftFootOrientation,
        TaskId::CoG,
        TaskId::UpperBodyOrientation,
        TaskId::RightArmCoG,
        TaskId::LeftArmCoG,
        TaskId::PelvisRotation,
        TaskId::PelvisAdduction,
        TaskId::RightToe,
        TaskId::LeftToe,
        TaskId::HeadPan,
        TaskId::HeadTilt,
        TaskId::Vergence,
    ];

    /// Total rows with every task active.
    pub const TOTAL_ROWS: usize = 31;

    /// Position of the task in [`Self::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// Number of rows of the task.
    pub fn dim(self) -> usize {
        if self.index() < 8 {
            3
        } else {
            1
        }
    }

    /// First row of the task in the full (all-active) layout.
    pub fn full_offset(self) -> usize {
        Self::ALL[..self.index()].iter().map(|t| t.dim()).sum()
    }

    /// Joint-task index (0..7) for the 1-D tasks.
    pub(crate) fn joint_slot(self) -> Option<usize> {
        self.index().checked_sub(8)
    }
}

/// Frame of a foot task (the foot's TCP).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum FootFrame {
    /// The sole frame (`*_sole`, below the ankle): foot flat, on its heel, or swinging.
    #[default]
    Sole,
    /// The toe segment frame (`*_toe`, on the toe joint axis): while the heel is lifted and
    /// the toe stands on the ground (toe-off); the toe joint task then sets the heel lift.
    Toe,
}

/// Desired task values `x_d` (and feed-forward velocities) of all tasks (Table 4.2).
#[derive(Debug, Clone, PartialEq)]
pub struct LolaTargets {
    /// Planned upper-body yaw defining the planning frame \[rad].
    pub planning_yaw: f64,
    /// Frame tracked by the right, left foot tasks.
    pub foot_frame: [FootFrame; 2],
    /// Right, left foot TCP relative to the CoG (planning frame).
    pub foot_position: [Vector3<f64>; 2],
    /// Right, left foot frame orientation relative to the torso (columns = frame axes in torso
    /// axes).
    pub foot_orientation: [Matrix3<f64>; 2],
    /// CoG in the inertial frame.
    pub cog: Vector3<f64>,
    /// Torso orientation in the inertial frame.
    pub upper_body: Matrix3<f64>,
    /// Right, left arm CoG relative to the robot CoG (planning frame).
    pub arm_cog: [Vector3<f64>; 2],
    /// Joint targets in the order of the 1-D tasks of [`TaskId::ALL`].
    pub joints: [f64; 7],
    /// Feed-forward task velocities in the full layout (31 rows; orientation rows are angular
    /// velocities in the frame of the orientation error).
    pub velocity: DVector<f64>,
}

impl Default for LolaTargets {
    fn default() -> Self {
        Self {
            planning_yaw: 0.0,
            foot_frame: [FootFrame::Sole; 2],
            foot_position: [Vector3::zeros(); 2],
            foot_orientation: [Matrix3::identity(); 2],
            cog: Vector3::zeros(),
            upper_body: Matrix3::identity(),
            arm_cog: [Vector3::zeros(); 2],
            joints: [0.0; 7],
            velocity: DVector::zeros(TaskId::TOTAL_ROWS),
        }
    }
}
