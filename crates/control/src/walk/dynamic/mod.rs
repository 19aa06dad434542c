//! `biped walk --dynamic`: the kinematic walk tracked by joint controllers in the full contact
//! simulation of `biped_sim` (thesis 2.1 Fig. 2.1 for the loop, 4.5 / 7.3 for the walk).
//!
//! - [`mod@reference`]: the kinematic walk of one arm method sampled at 1 kHz: actuated joints'
//!   `q`, `qdot`, feedforward torques, planned base position, support phase.
//! - [`feedforward`]: RNEA of the planned motion with the ground wrench distributed over the
//!   support feet (single support: stance foot; double support: split by the motion's ZMP).
//! - [`tracking`]: [`TrackingController`], PD per joint + feedforward, joint-torque mode.
//! - [`run`]: [`run_dynamic_walk`] on the Lola Type 2 plant (RK4, h = 1 ms), time series and
//!   the verdict; [`run_dynamic_walk_robot`] on the plant of any [`DynamicRobot`] ([`robot`]:
//!   the Lola-like model or a robot description, e.g. the G1).
//! - [`margins`]: the joint-limit margin and SSV distance of the simulated poses (the
//!   limits and self-collision verdicts of the simulation).
//! - [`slip`]: the sides' contact per cycle (load, toe load, heel lift, friction use, slip).
//!
//! Resolved choices and limits:
//! - The IK model and the plant share the `q`/`v` layout (Lola: both `lola::build(Type2)`; a
//!   described robot: the URDF model, the plant adding rotor bodies without coordinates); the
//!   reference holds one column per plant actuator, in the plant's order; the start pose is the
//!   first reference sample lowered so that the soles rest at the contact law's static
//!   penetration.
//! - Described robots: the defaults of [`DynamicWalkParams`] were tuned on the Lola-like
//!   model; [`DynamicWalkParams::for_robot`] scales the foot force control and the fall
//!   criterion to the robot's weight and CoM height, and [`robot`] derives the ground's
//!   contact law from the robot's weight, CoM height and soles (a narrow sole on a soft ground
//!   rolls under the robot: the G1 falls sideways on the light-feet contact law). Feet without
//!   toe joints stay flat (the kinematic walk's flat-foot pattern).
//! - Tracking the LIPM pattern as planned (PD + feedforward only) falls forward after 2-4
//!   steps: the multibody ZMP of the IK motion leaves the 0.13 m front edge of the sole. So
//!   the pattern's CoM is corrected for the multibody ZMP ([`mod@reference`], 2 iterations by
//!   default), and the trunk inclination is fed back through the support ankles
//!   ([`stabiliser`]); each of the two alone is not enough for the default walk, and without
//!   the RNEA feedforward the PD alone falls too. The feet's heights follow the error of their
//!   vertical loads ([`force`]): without that, the stiff legs share a double support by
//!   sub-millimetre length differences, and the walk hops at every step change.
//! - The reference keeps every joint inside its range (toe-off and heel strike in the
//!   pattern, hard limits in the IK, see [`crate::walk`]): the summary's `limit_excess` is 0
//!   for the default walk, so `end_stops = true` (the plant's stops at the joint ranges,
//!   [`biped_sim::passive`]) and `clamp_margin = Some(m)` (the reference clamped into the
//!   limits shrunk by `m`, reported per sample) do not change the reference itself.
//! - Contact: the plant's toe segments have contact points of their own
//!   ([`biped_sim::plant::PlantConfig::toe_contacts`]): while the heel is lifted the rear foot
//!   stands on its flat toe, and the feedforward puts that foot's share of the ground wrench
//!   on the toe ([`feedforward`]). The series and summary use each side's wrench (foot and
//!   toe summed, [`biped_sim::contact::ContactOutput::sides`]).
//! - Verdict: walked = no fall (base height never below its start minus `fall_drop`, trunk
//!   tilt never above `max_tilt`) and forward progress `>= min_progress` of the planned
//!   base travel. Apart from it, the friction verdict ([`slip`]: friction use, slip speed,
//!   slip = a side sliding [`SLIP_DISTANCE`] within one contact), the contact verdict (no
//!   hop), the limits verdict (no joint past its range) and the self-collision verdict (no
//!   interpenetrating segments, [`margins`]). A simulation that diverges
//!   numerically ([`biped_sim::SimError::is_divergence`]) is a fall at its last finite sample
//!   (`diverged` in the summary), not an error.

pub mod feedforward;
pub mod flight;
pub mod force;
pub mod margins;
pub mod reference;
pub mod robot;
mod robot_legs;
pub mod run;
pub mod slip;
pub mod stabiliser;
mod summary;
pub mod tracking;

pub use feedforward::Feedforward;
pub use force::{ForceControl, ForceGains};
pub use reference::{build_reference, build_robot_reference, JointReference, ReferenceOptions};
pub use robot::{DynamicRobot, PlantSource, RobotScale, FOOT_DAMPING_RATIO, SOLE_ROLL_MARGIN};
pub use robot_legs::{DynamicLeg, LEG_JOINTS};
pub use run::{
    robot_plant, run_dynamic_walk, run_dynamic_walk_robot, start_on_ground, DynamicWalkRun,
};
pub use slip::{SideContact, SideSample, SlipTracker, SLIP_DISTANCE, SLIP_POINTS};
pub use stabiliser::{Stabiliser, StabiliserGains};
pub use summary::{DynamicWalkSeries, DynamicWalkSummary};
pub use tracking::TrackingController;

use super::error::WalkError;
use super::method::{Method, WalkParams};

/// Parameters of [`run_dynamic_walk`] (defaults: the `biped walk` walk, minimisation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicWalkParams {
    /// Number of steps.
    pub steps: usize,
    /// Step length \[m].
    pub step_length: f64,
    /// Step time \[s].
    pub step_time: f64,
    /// Arm method of the kinematic walk.
    pub method: Method,
    /// IK tuning of the kinematic walk.
    pub walk: WalkParams,
    /// PD bandwidth \[rad/s] of the gains of `JointPd::scaled`.
    pub bandwidth: f64,
    /// PD damping ratio.
    pub damping: f64,
    /// Factor on both PD gains (1 = as scaled; 0 = feedforward only).
    pub gain_scale: f64,
    /// Whether the RNEA feedforward is applied.
    pub feedforward: bool,
    /// Ankle stabiliser gains (`None`: off).
    pub stabiliser: Option<StabiliserGains>,
    /// Foot force control gains (`None`: off).
    pub force: Option<ForceGains>,
    /// Clamp the reference into the joint limits shrunk by this margin \[rad] (`None`: no).
    pub clamp_margin: Option<f64>,
    /// Give the plant its end stops at the joint ranges (on by default; the reference stays
    /// inside the ranges, see the module docs).
    pub end_stops: bool,
    /// Multibody ZMP correction iterations of the pattern (see [`mod@reference`]).
    pub zmp_iterations: usize,
    /// Coulomb friction coefficient `mu` of the ground (default: the contact law's, 0.8).
    pub friction: f64,
    /// Standing time simulated after the walk \[s].
    pub hold_time: f64,
    /// Fall: base lower than its start height minus this \[m].
    pub fall_drop: f64,
    /// Fall: trunk tilt above this \[rad].
    pub max_tilt: f64,
    /// Required forward progress as a fraction of the planned base travel.
    pub min_progress: f64,
    /// Longest phase with both feet off the ground that still counts as walking \[s]: a
    /// longer one is a hop, the contact verdict's violation (contact chatter at a step change
    /// lasts a few ms).
    pub max_flight: f64,
}

impl Default for DynamicWalkParams {
    fn default() -> Self {
        Self {
            steps: 10,
            step_length: 0.4,
            step_time: 0.8,
            method: Method::Minimization,
            walk: WalkParams::default(),
            bandwidth: 40.0,
            damping: 1.0,
            gain_scale: 1.0,
            feedforward: true,
            stabiliser: Some(StabiliserGains::default()),
            force: Some(ForceGains::default()),
            clamp_margin: None,
            end_stops: true,
            zmp_iterations: 2,
            friction: biped_sim::contact::ContactParams::default().friction,
            hold_time: 1.0,
            fall_drop: 0.25,
            max_tilt: 0.3,
            min_progress: 0.8,
            max_flight: 0.02,
        }
    }
}

impl DynamicWalkParams {
    /// The defaults for `robot`: [`Self::default`] for the Lola-like model, whose numbers they
    /// are; for other robots the gains and criteria that depend on the robot's size follow
    /// from its weight and CoM height against the Lola-like model's ([`RobotScale`]).
    pub fn for_robot(robot: &DynamicRobot) -> Result<Self, WalkError> {
        let d = Self::default();
        if matches!(robot.source, PlantSource::Lola(_)) {
            return Ok(d);
        }
        let lola = DynamicRobot::lola(biped_robots::lola::LolaType::Type2)?;
        Ok(RobotScale::between(robot, &lola).apply(d))
    }

    /// Options of the reference built from these parameters.
    pub fn reference_options(&self) -> ReferenceOptions {
        ReferenceOptions {
            method: self.method,
            walk: self.walk,
            zmp_iterations: self.zmp_iterations,
            clamp_margin: self.clamp_margin,
        }
    }

    /// Checks ranges (the walk's own parameters are checked by the pattern and the IK).
    pub fn validate(&self) -> Result<(), WalkError> {
        let bad = |name: &'static str, reason: &str| {
            Err(WalkError::InvalidParameter {
                name,
                reason: reason.into(),
            })
        };
        let pos = |x: f64| x.is_finite() && x > 0.0;
        let nonneg = |x: f64| x.is_finite() && x >= 0.0;
        if self.steps == 0 {
            return bad("steps", "must be at least 1");
        }
        if !pos(self.bandwidth) || !nonneg(self.damping) || !nonneg(self.gain_scale) {
            return bad(
                "gains",
                "bandwidth > 0, damping and gain_scale >= 0, finite",
            );
        }
        if self.clamp_margin.is_some_and(|m| !nonneg(m)) {
            return bad("clamp_margin", "must be finite and >= 0");
        }
        if !nonneg(self.hold_time) || !pos(self.fall_drop) || !pos(self.max_tilt) {
            return bad(
                "criteria",
                "hold_time >= 0, fall_drop and max_tilt > 0, finite",
            );
        }
        if !nonneg(self.max_flight) {
            return bad("max_flight", "must be finite and >= 0");
        }
        if !nonneg(self.min_progress) {
            return bad("min_progress", "must be finite and >= 0");
        }
        if !pos(self.friction) {
            return bad("friction", "must be finite and > 0");
        }
        Ok(())
    }
}
