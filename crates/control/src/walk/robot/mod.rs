//! [`WalkRobot`]: everything the kinematic walk needs to know about a robot, robot-neutral:
//! the model, the sole and toe frames, the body of the upper-body task, the joints with their
//! ranges, the arm roots and joints of the arm methods, the momentum-reducing DoFs, the SSV
//! collision model, the walking posture and the pattern parameters that follow from the
//! robot's geometry (step width, CoM height, sole rectangle, reach of the legs).
//!
//! Built from the Lola-like model ([`WalkRobot::lola`], the thesis's robot: its numbers are
//! those of the thesis chapters) or from a robot description file
//! ([`WalkRobot::from_description`], any URDF humanoid; see `docs/robot_description.md`).

mod describe;
mod geometry;
pub mod lola_posture;

pub(crate) use geometry::frame_position;
pub use geometry::{REACH_FRACTION, STEP_FRACTION};

use super::error::{model_err, WalkError};
use crate::momentum::LOLA_ARMS;
use crate::pattern::fit::standing_com_height;
use crate::pattern::{FootGeometry, FootRoll, PatternParams};
use crate::tasks::WalkTaskFrames;
use biped_dynamics::Model;
use biped_robots::lola::{lola_collision_model, LolaModel};
use biped_ssv::CollisionModel;
use lola_posture::{walk_start_configuration, WALK_KNEE};
use nalgebra::DVector;

/// One actuated joint with its position range.
#[derive(Debug, Clone, PartialEq)]
pub struct WalkJoint {
    /// Joint name.
    pub name: String,
    /// Index into `q`.
    pub q_index: usize,
    /// Index into `v`.
    pub v_index: usize,
    /// Lower bound \[rad or m].
    pub lower: f64,
    /// Upper bound \[rad or m].
    pub upper: f64,
}

/// Slots of [`WalkTaskFrames::joints`] that hold trunk and head joints (the others are the
/// right and left toe).
pub const HELD_SLOTS: [usize; 5] = [0, 1, 4, 5, 6];

/// A robot as the kinematic walk sees it (see the module docs). Slot order of the pairs:
/// `[right, left]`.
#[derive(Debug, Clone)]
pub struct WalkRobot {
    /// Robot name (for reports).
    pub name: String,
    /// The multibody model (quaternion floating base).
    pub model: Model,
    /// Actuated joints with a finite range: the joint limits, the joint cost `H_J` and the
    /// joint-limit margin of the verdicts.
    pub joints: Vec<WalkJoint>,
    /// Bodies, frames and joints of the walking task set (upper body, soles, toes, arm
    /// roots, joint-task joints).
    pub frames: WalkTaskFrames,
    /// Arm joints (held still by the `none` method).
    pub arm_joints: Vec<String>,
    /// Joints set from [`super::WalkParams::arm_pose`]: `(q index, component, sign)`; empty
    /// for robots whose walking posture fixes the arms.
    pub arm_pose_joints: Vec<(usize, usize, f64)>,
    /// Momentum-reducing joints of the compensation method (7.3.2).
    pub reducing: Vec<String>,
    /// Joints recorded in the per-method time series (`METHOD.csv`).
    pub recorded: Vec<String>,
    /// SSV collision model (segments and pairs).
    pub collision: CollisionModel,
    /// Walking posture with the base at the origin (arms of `arm_pose_joints` at 0).
    pub posture: DVector<f64>,
    /// Sole rectangle (and toe axis) in the sole frame.
    pub foot: FootGeometry,
    /// Toe-off and heel strike (flat feet without toes).
    pub roll: FootRoll,
    /// Lateral distance of the sole frames in the walking posture \[m].
    pub step_width: f64,
    /// CoM height above the soles in the walking posture \[m].
    pub com_height: f64,
    /// Largest distance between consecutive footprints the legs reach \[m].
    pub reach: f64,
    /// Step length `biped walk` takes by default \[m].
    pub natural_step_length: f64,
}

/// Lola's recorded joints: the arm joints, pelvis rotation and torso.
const LOLA_RECORDED: [&str; 2] = ["pelvis_rotation", "torso"];

impl WalkRobot {
    /// The Lola-like model (Type 2) in the walking posture of [`WALK_KNEE`] with the default
    /// pattern geometry fitted to it (0.4 m steps).
    pub fn lola(lola: &LolaModel) -> Result<Self, WalkError> {
        let model = lola.model.clone();
        let joints: Vec<WalkJoint> = lola
            .limits
            .iter()
            .map(|l| WalkJoint {
                name: l.name.clone(),
                q_index: l.q_index,
                v_index: l.v_index,
                lower: l.lower,
                upper: l.upper,
            })
            .collect();
        let arm_pose_joints = LOLA_ARMS
            .iter()
            .enumerate()
            .map(|(k, name)| {
                let sign = if k == 4 { -1.0 } else { 1.0 };
                Ok((joints[joint_index(&joints, name)?].q_index, k % 3, sign))
            })
            .collect::<Result<Vec<_>, WalkError>>()?;
        let defaults = PatternParams::default();
        let names = |n: &[&str]| n.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let mut recorded = names(&LOLA_ARMS);
        recorded.extend(names(&LOLA_RECORDED));
        Ok(Self {
            name: "lola".into(),
            frames: WalkTaskFrames::lola(lola)?,
            arm_joints: names(&LOLA_ARMS),
            arm_pose_joints,
            reducing: names(&LOLA_ARMS),
            recorded,
            collision: lola_collision_model(lola).map_err(model_err)?.model,
            posture: walk_start_configuration(lola, [0.0; 3])?,
            foot: defaults.foot,
            roll: defaults.roll,
            step_width: defaults.step_width,
            com_height: standing_com_height(lola, WALK_KNEE)?,
            reach: defaults.reach,
            natural_step_length: defaults.step_length,
            joints,
            model,
        })
    }

    /// Start configuration with the arm pose `arm_pose` (for the joints of
    /// [`Self::arm_pose_joints`]); base at the origin.
    pub fn start_configuration(&self, arm_pose: [f64; 3]) -> DVector<f64> {
        let mut q = self.posture.clone();
        for &(i, k, sign) in &self.arm_pose_joints {
            q[i] = sign * arm_pose[k];
        }
        q
    }

    /// Pattern parameters for this robot: the default pattern with `n_steps`, `step_length`,
    /// `step_time` and the robot's step width, CoM height, feet and reach.
    pub fn pattern_params(
        &self,
        n_steps: usize,
        step_length: f64,
        step_time: f64,
    ) -> PatternParams {
        PatternParams {
            n_steps,
            step_length,
            step_time,
            step_width: self.step_width,
            com_height: self.com_height,
            foot: self.foot,
            roll: self.roll,
            reach: self.reach,
            ..PatternParams::default()
        }
    }

    /// The joint of `name` in [`Self::joints`].
    pub fn joint(&self, name: &str) -> Option<&WalkJoint> {
        self.joints.iter().find(|j| j.name == name)
    }
}

/// Index of joint `name` in `joints`.
fn joint_index(joints: &[WalkJoint], name: &str) -> Result<usize, WalkError> {
    joints
        .iter()
        .position(|j| j.name == name)
        .ok_or_else(|| model_err(format!("no joint {name}")))
}
