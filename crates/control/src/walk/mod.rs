//! `biped walk`: the full IK stack of Lola over a walking pattern (thesis 4.5, 5.2, 7.3-7.5),
//! written against the robot-neutral [`WalkRobot`] (Lola, or any robot of a description file).
//!
//! - [`robot`]: [`WalkRobot`], what the walk needs to know of a robot (frames, joints, arm
//!   and momentum DoFs, collision model, posture, pattern geometry from its legs).
//!
//! - [`method`]: the arm methods compared in ch. 7 (`none`, `reference` 7.3.1,
//!   `compensation` 7.3.2, `minimization` 7.5) and the tuning [`WalkParams`].
//! - [`controller`]: [`WalkController`], one 1 kHz IK cycle (preallocated).
//! - [`evaluate`]: per-cycle metrics: `L_z`, `dL_z/dt`, stance-foot torque `tau_z` by RNEA,
//!   smallest SSV distance, joint-limit margin, ground wrench.
//! - [`friction`]: whether the ground can supply that wrench (friction cone and free moment).
//! - [`trajectory`]: [`Trajectory`], the full planned motion for replay.
//! - [`contact`]: [`SupportCheck`], how far the planned motion lifts a supporting foot.
//! - [`verdict`]: [`WalkVerdicts`], where and when a walk came closest to each limit.
//! - [`run`]: [`run_walk`], a whole walk with time series and a [`WalkSummary`].
//! - [`dynamic`]: [`run_dynamic_walk`], the walk tracked by joint controllers in the contact
//!   simulation of `biped_sim` (`biped walk --dynamic`).
//!
//! Resolved choices and known limits:
//! - The arm CoG tasks of Table 4.2 are off for `none`, `compensation` and `minimization`
//!   (the arms are redundant); `none` keeps the arms still with a large RMRC weight on the
//!   arm joints instead of tasks.
//! - Reference (7.3.1): the opposite foot's fore-aft position relative to the CoG times
//!   `arm_swing_scale` moves the arm CoG on a circle about the current shoulder (a target
//!   fixed relative to the CoG would stretch the elbow into the 3-D task's singularity).
//! - Compensation (7.3.2): instead of the previous cycle's producing momentum, the response of
//!   RMRC to the reducing direction `J_{L,r,z}^T` is solved with the same factorisation and
//!   superposed (RMRC is linear), so `L_z -> k L_ref + (1 - k) L_z` within the cycle. With
//!   the one-cycle-delayed estimate gains near 1 oscillated at 1 kHz (|dL_z/dt| x5).
//!   `L_ref,z` (7.10) restarts at every step with the turn per step of the pattern.
//! - Minimisation (7.5): `W = delta E + J_Lz^T J_Lz` with `delta = 0.003` (the arms' entries
//!   of `J_Lz` are small, so a larger delta leaves most of `L_z`); the null-space steps are
//!   scaled by delta so that `W^-1 grad H` keeps its size.
//! - Posture (Lola; a described robot walks in its comfort pose, [`robot`]): knees bent
//!   [`WALK_KNEE`] = 0.55 rad (hip height between the stance ankle's
//!   dorsiflexion limit, which a lower hip reaches at the end of single support, and the
//!   reach of the legs at touch-down, which a higher hip loses); elbows at -0.8 rad. The
//!   pattern rolls the feet (toe-off, heel strike, [`crate::pattern::roll`]): while a heel is
//!   lifted the foot tasks track the toe segment ([`crate::tasks::FootFrame::Toe`]) and the
//!   toe joint tasks follow the pattern's toe angles.
//! - Joint limits are hard: the RMRC solution is kept inside the velocity box of the joint
//!   ranges (margin, velocity, deceleration: [`WalkParams::limits`]) by saturation in the null
//!   space ([`crate::ik::saturation`]); a task that would need a joint beyond its range
//!   yields instead (the summary's `max_task_error` and `limited_cycles` say how much and
//!   how often). The compensation term is shortened to stay in the box.
//! - The IK runs `settle_time` on the first sample before the walk.

pub mod contact;
pub mod controller;
pub mod dynamic;
mod error;
pub mod evaluate;
pub mod friction;
pub mod method;
mod posture;
pub mod robot;
pub mod run;
mod targets;
pub mod trajectory;
pub mod verdict;

pub use contact::{FootLift, SupportCheck};
pub use controller::{CycleInfo, WalkController};
pub use dynamic::{
    run_dynamic_walk, run_dynamic_walk_robot, DynamicRobot, DynamicWalkParams, DynamicWalkRun,
    DynamicWalkSeries, DynamicWalkSummary,
};
pub use error::WalkError;
pub use evaluate::{CycleMetrics, Evaluator};
pub use method::{Method, WalkParams};
pub use robot::lola_posture::{
    walk_pattern_params, walk_start_configuration, WALK_ELBOW, WALK_KNEE,
};
pub use robot::{WalkJoint, WalkRobot};
pub use run::{run_walk, run_walk_robot, WalkRun, WalkSeries, WalkSummary};
pub use trajectory::Trajectory;
pub use verdict::{Verdict, Violation, WalkVerdicts};
