//! Both feet at any instant of the timeline: standing, toe-off, swing and heel strike
//! ([`super::roll`]); the stance foot of a single support is flat.

use super::footsteps::Pose2;
use super::roll::{min_jerk_inverse, window_blend, Contact};
use super::swing::SoleMotion;
use super::timeline::{Moment, Schedule};
use super::PatternParams;
use nalgebra::Vector2;

/// Roll angles of every step: heel lift at lift-off and toes up at touch-down \[rad].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RollPlan {
    /// Heel-lift angle of each step's swing foot at lift-off.
    pub toe_off: Vec<f64>,
    /// Toe-up angle of each step's swing foot at touch-down.
    pub heel_strike: Vec<f64>,
}

impl RollPlan {
    /// Angles from the CoM path `com(t)` (x, y): the reach of the leg at each contact switch,
    /// the fore-aft distance of the CoM ahead of the lifting foot at lift-off, resp. of the
    /// landing foot ahead of the CoM at touch-down, in the foot's frame (see [`super::roll`]).
    /// The first step lifts from the standing start, without a double support to lift the
    /// heel in: no toe-off.
    pub fn new(
        schedule: &Schedule,
        params: &PatternParams,
        com: impl Fn(f64) -> Vector2<f64>,
    ) -> Self {
        let steps = &schedule.plan.steps;
        let ahead = |pose: &Pose2, p: Vector2<f64>| pose.to_local(&p).x;
        let toe_off = (0..steps.len())
            .map(|k| match k {
                0 => 0.0,
                _ => params
                    .roll
                    .toe_off(ahead(&steps[k].from, com(schedule.lift_off(k)))),
            })
            .collect();
        let heel_strike = (0..steps.len())
            .map(|k| {
                let c = com(schedule.lift_off(k) + schedule.ss_time());
                params.roll.heel_strike(-ahead(&steps[k].to, c))
            })
            .collect();
        Self {
            toe_off,
            heel_strike,
        }
    }
}

/// Both feet of a walk: the schedule, the parameters and the roll angles of its steps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Feet<'a> {
    pub schedule: &'a Schedule,
    pub params: &'a PatternParams,
    pub roll: &'a RollPlan,
}

impl Feet<'_> {
    /// Sole motions `[left, right]` at `t` and the index of the step under way or next.
    pub fn at(&self, t: f64) -> ([SoleMotion; 2], usize) {
        let schedule = self.schedule;
        match schedule.locate(t) {
            Moment::Start { .. } => (standing(schedule.stance(0)), 0),
            Moment::Single { k, tau } => {
                let mut feet = standing(schedule.stance(k));
                let (a, b) = (self.lift_off(k), self.touch_down(k));
                let foot = schedule.plan.steps[k].foot.index();
                let (h, hold) = (self.params.step_height, self.params.roll.swing_hold);
                feet[foot] = SoleMotion::swing(&a, &b, tau, schedule.ss_time(), h, hold);
                (feet, k)
            }
            Moment::Double { k, tau } => (self.double_support(k, tau), k + 1),
            Moment::End => {
                let n = schedule.plan.steps.len();
                (standing(schedule.stance(n)), n)
            }
        }
    }

    /// Double support after step `k` at phase `tau`: the landed foot rolls flat from its
    /// heel, the rear foot (lifting in step `k + 1`) lifts its heel.
    fn double_support(&self, k: usize, tau: f64) -> [SoleMotion; 2] {
        let mut feet = standing(self.schedule.stance(k + 1));
        let ds = self.params.ds_time();
        let steps = &self.schedule.plan.steps;
        let landed = &steps[k];
        let theta = self.roll.heel_strike[k];
        let end = self.heel_roll_end(k);
        if theta > 0.0 && tau < end {
            let p = window_blend(-theta, 0.0, tau, 0.0, end, ds);
            feet[landed.foot.index()] = self.heel_pivot(landed.to, p);
        }
        if k + 1 < steps.len() {
            let rear = &steps[k + 1];
            let theta = self.roll.toe_off[k + 1];
            let start = self.toe_off_start(k);
            if theta > 0.0 && tau > start {
                let p = window_blend(0.0, theta, tau, start, 1.0 - start, ds);
                feet[rear.foot.index()] = self.toe_pivot(rear.from, p);
            }
        }
        feet
    }

    /// Phase of the double support after step `k` at which the rear heel starts to lift:
    /// when the ZMP reference (moving from the rear to the front sole origin) passes the
    /// rear toe axis, but no earlier than `1 - toe_off_fraction` and no later than 0.9.
    fn toe_off_start(&self, k: usize) -> f64 {
        let pass = min_jerk_inverse(self.params.foot.front / self.span(k));
        pass.max(1.0 - self.params.roll.toe_off_fraction).min(0.9)
    }

    /// Phase of the double support after step `k` at which the landed foot is flat: before
    /// the ZMP reference passes its heel edge, at most `heel_roll_fraction`, at least 0.1.
    fn heel_roll_end(&self, k: usize) -> f64 {
        let pass = min_jerk_inverse(1.0 - self.params.foot.back / self.span(k));
        pass.min(self.params.roll.heel_roll_fraction).max(0.1)
    }

    /// Distance the ZMP reference travels in the double support after step `k` (rear to
    /// front sole origin; infinite for the last step, whose ZMP stops between the feet).
    fn span(&self, k: usize) -> f64 {
        let steps = &self.schedule.plan.steps;
        match steps.get(k + 1) {
            Some(rear) => (steps[k].to.position() - rear.from.position()).norm(),
            None => f64::INFINITY,
        }
    }

    /// Step `k`'s swing foot at lift-off: heel lifted about the toe axis, at rest.
    fn lift_off(&self, k: usize) -> SoleMotion {
        let theta = self.roll.toe_off[k];
        self.toe_pivot(self.schedule.plan.steps[k].from, [theta, 0.0])
    }

    /// Step `k`'s swing foot at touch-down: on its heel edge, toes up, at rest.
    fn touch_down(&self, k: usize) -> SoleMotion {
        let theta = self.roll.heel_strike[k];
        self.heel_pivot(self.schedule.plan.steps[k].to, [-theta, 0.0])
    }

    /// Foot on `print` rotated about its toe joint axis (toe segment flat on the ground).
    fn toe_pivot(&self, print: Pose2, p: [f64; 2]) -> SoleMotion {
        let axis = (self.params.foot.front, self.params.foot.toe_height);
        SoleMotion::pivot(print, axis, p, Contact::Toe)
    }

    /// Foot on `print` rotated about its heel edge.
    fn heel_pivot(&self, print: Pose2, p: [f64; 2]) -> SoleMotion {
        SoleMotion::pivot(print, (-self.params.foot.back, 0.0), p, Contact::Heel)
    }
}

fn standing(feet: &[Pose2; 2]) -> [SoleMotion; 2] {
    [SoleMotion::standing(feet[0]), SoleMotion::standing(feet[1])]
}
