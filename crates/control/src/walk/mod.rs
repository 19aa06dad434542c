//! `biped walk`: the full IK stack of Lola over a walking pattern (thesis 4.5, 5.2, 7.3-7.5).
//!
//! - [`method`]: the arm methods compared in ch. 7 (`none`, `reference` 7.3.1,
//!   `compensation` 7.3.2, `minimization` 7.5) and the tuning [`WalkParams`].
//! - [`controller`]: [`WalkController`], one 1 kHz IK cycle (preallocated).
//! - [`evaluate`]: per-cycle metrics: `L_z`, `dL_z/dt`, stance-foot torque `tau_z` by RNEA,
//!   smallest SSV distance, joint-limit margin.
//! - [`run`]: [`run_walk`], a whole walk with time series and a [`WalkSummary`].
//!
//! Resolved choices: the arm tasks of Table 4.2 are off for `none`, `compensation` and
//! `minimization` (the arms are redundant); `none` keeps the arms still with a large RMRC
//! weight on the arm joints instead of tasks. The reference method swings the arm CoG
//! fore-aft only (x of the planning frame) with the opposite foot's position relative to the
//! CoG times `arm_swing_scale`. Compensation uses the exact law (7.7) on all six arm joints,
//! with the producing momentum from the previous cycle's velocities, and `L_ref,z` of (7.10)
//! restarted at every step. The IK runs `settle_time` on the first sample before the walk so
//! that the initial task errors (standing pose vs. pattern) have decayed.

pub mod controller;
mod error;
pub mod evaluate;
pub mod method;
pub mod run;
mod targets;

pub use controller::{
    walk_pattern_params, walk_start_configuration, CycleInfo, WalkController, WALK_KNEE,
};
pub use error::WalkError;
pub use evaluate::{CycleMetrics, Evaluator};
pub use method::{Method, WalkParams};
pub use run::{run_walk, WalkRun, WalkSeries, WalkSummary};
