//! Step timing, support phases and the ZMP reference.
//!
//! Timeline: standing double support of `start_time` (the ZMP reference holds the feet
//! midpoint for the first half and moves to the first stance foot in the second half), then
//! per step a single support of `ss_time` and a double support of `ds_time` in which the ZMP
//! reference moves to the foot just placed (after the last step: to the midpoint of the
//! feet), then standing double support of `end_time`. Every transfer is the minimum-jerk
//! blend (`swing::min_jerk`), so the reference is C2 in time. The ZMP reference point of a
//! foot is its sole frame origin (below the ankle).

use super::blend::min_jerk;
use super::footsteps::{Foot, FootstepPlan, Pose2};
use super::PatternParams;
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

/// Support phase of a sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Phase {
    /// Both feet on the ground.
    Double,
    /// Single support on the left foot (right foot swinging).
    LeftStance,
    /// Single support on the right foot (left foot swinging).
    RightStance,
}

impl Phase {
    /// The stance foot in single support, `None` in double support.
    pub fn stance_foot(self) -> Option<Foot> {
        match self {
            Phase::Double => None,
            Phase::LeftStance => Some(Foot::Left),
            Phase::RightStance => Some(Foot::Right),
        }
    }
}

/// Where a time instant falls in the walk.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Moment {
    /// Initial standing; `tau` in \[0, 1] over `start_time`.
    Start { tau: f64 },
    /// Single support of step `k` (0-based); `tau` in \[0, 1).
    Single { k: usize, tau: f64 },
    /// Double support after step `k`; `tau` in \[0, 1).
    Double { k: usize, tau: f64 },
    /// Final standing.
    End,
}

/// Footstep plan with its timing.
#[derive(Debug, Clone)]
pub struct Schedule {
    /// The footsteps.
    pub plan: FootstepPlan,
    stances: Vec<[Pose2; 2]>,
    start: f64,
    ss: f64,
    ds: f64,
}

impl Schedule {
    /// Timing of `plan` with the durations of `params` (assumed validated).
    pub fn new(plan: FootstepPlan, params: &PatternParams) -> Self {
        let stances = (0..=plan.steps.len())
            .map(|k| plan.stance_after(k))
            .collect();
        Self {
            plan,
            stances,
            start: params.start_time,
            ss: params.ss_time(),
            ds: params.ds_time(),
        }
    }

    /// Sole poses `[left, right]` after `k` steps (clamped to the last stance).
    pub fn stance(&self, k: usize) -> &[Pose2; 2] {
        &self.stances[k.min(self.stances.len() - 1)]
    }

    /// Single-support duration \[s].
    pub fn ss_time(&self) -> f64 {
        self.ss
    }

    /// Lift-off time of step `k` (0-based) \[s].
    pub fn lift_off(&self, k: usize) -> f64 {
        self.start + k as f64 * (self.ss + self.ds)
    }

    /// Phase position at time `t`.
    pub fn locate(&self, t: f64) -> Moment {
        if t < self.start {
            return Moment::Start {
                tau: t / self.start,
            };
        }
        let period = self.ss + self.ds;
        let rel = t - self.start;
        let k = (rel / period).floor() as usize;
        if k >= self.plan.steps.len() {
            return Moment::End;
        }
        let within = rel - k as f64 * period;
        if within < self.ss {
            Moment::Single {
                k,
                tau: within / self.ss,
            }
        } else {
            Moment::Double {
                k,
                tau: ((within - self.ss) / self.ds).min(1.0),
            }
        }
    }

    /// Support phase at time `t`.
    pub fn phase(&self, t: f64) -> Phase {
        match self.locate(t) {
            Moment::Single { k, .. } => match self.plan.steps[k].foot.other() {
                Foot::Left => Phase::LeftStance,
                Foot::Right => Phase::RightStance,
            },
            _ => Phase::Double,
        }
    }

    /// ZMP reference `p_ref(t)` (x, y) \[m].
    pub fn zmp_reference(&self, t: f64) -> Vector2<f64> {
        let steps = &self.plan.steps;
        let stance = |k: usize| self.stance(k)[steps[k].foot.other().index()];
        match self.locate(t) {
            Moment::Start { tau } => {
                let mid = midpoint(&self.plan.initial);
                let s = min_jerk((2.0 * tau - 1.0).max(0.0))[0];
                mid + s * (stance(0).position() - mid)
            }
            Moment::Single { k, .. } => stance(k).position(),
            Moment::Double { k, tau } => {
                let from = stance(k).position();
                let to = if k + 1 < steps.len() {
                    steps[k].to.position()
                } else {
                    midpoint(self.stance(steps.len()))
                };
                from + min_jerk(tau)[0] * (to - from)
            }
            Moment::End => midpoint(self.stance(steps.len())),
        }
    }
}

/// Midpoint of the two sole origins.
pub fn midpoint(feet: &[Pose2; 2]) -> Vector2<f64> {
    0.5 * (feet[0].position() + feet[1].position())
}
