//! `biped walk`: the full IK stack of Lola over a walking pattern (thesis 4.5, 5.2, 7.3-7.5).
//!
//! - [`method`]: the arm methods compared in ch. 7 (`none`, `reference` 7.3.1,
//!   `compensation` 7.3.2, `minimization` 7.5) and the tuning [`WalkParams`].
//! - [`controller`]: [`WalkController`], one 1 kHz IK cycle (preallocated).
//! - [`evaluate`]: per-cycle metrics: `L_z`, `dL_z/dt`, stance-foot torque `tau_z` by RNEA,
//!   smallest SSV distance, joint-limit margin.
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
//! - Posture: knees bent 0.9 rad so that the 0.4 m steps (0.8 m stride) of the flat-footed
//!   pattern keep the knees out of their singularity; elbows at -0.8 rad. The flat-footed
//!   pattern still takes the rear ankle about 0.36 rad beyond its dorsiflexion limit at the
//!   end of double support (Lola uses toe-off, which the pattern does not model): the IK does
//!   not enforce limits on task-determined joints; `min_joint_margin` reports it. In the
//!   default walk the ankle flexion is beyond its -0.45 rad limit (the bent-knee posture
//!   starts on it) in ~30-40 % of the samples, by up to 0.34 rad, and the upper-arm
//!   abduction by up to 0.1 rad; [`dynamic`] tracks it as planned (on a plant without end
//!   stops unless asked).
//! - The IK runs `settle_time` on the first sample before the walk.

pub mod controller;
pub mod dynamic;
mod error;
pub mod evaluate;
pub mod method;
mod posture;
pub mod run;
mod targets;

pub use controller::{CycleInfo, WalkController};
pub use dynamic::{run_dynamic_walk, DynamicWalkParams, DynamicWalkRun, DynamicWalkSummary};
pub use error::WalkError;
pub use evaluate::{CycleMetrics, Evaluator};
pub use method::{Method, WalkParams};
pub use posture::{walk_pattern_params, walk_start_configuration, WALK_ELBOW, WALK_KNEE};
pub use run::{run_walk, WalkRun, WalkSeries, WalkSummary};
