//! The sampled walking pattern: CoM from ZMP preview control, feet and torso.

use super::feet::{Feet, RollPlan};
use super::footsteps::{Foot, FootstepPlan};
use super::preview::PreviewController;
use super::roll::Contact;
use super::swing::SoleMotion;
use super::timeline::{midpoint, Phase, Schedule};
use super::{FootGeometry, PatternError, PatternParams};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector2, Vector3};

/// Pose and spatial velocity of one sole frame (world coordinates), toe joint and contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FootState {
    /// Sole frame pose (origin on the ground below the ankle when standing).
    pub pose: Isometry3<f64>,
    /// Linear velocity of the sole origin \[m/s].
    pub linear: Vector3<f64>,
    /// Angular velocity \[rad/s].
    pub angular: Vector3<f64>,
    /// Toe joint angle (toe segment relative to the foot, about the lateral axis) \[rad].
    pub toe_angle: f64,
    /// Toe joint rate \[rad/s].
    pub toe_rate: f64,
    /// Contact state (toe-off, heel strike, flat, swing).
    pub contact: Contact,
}

impl From<&SoleMotion> for FootState {
    fn from(m: &SoleMotion) -> Self {
        Self {
            pose: Isometry3::from_parts(Translation3::new(m.pose.x, m.pose.y, m.z), m.rotation()),
            linear: m.velocity,
            angular: m.angular(),
            toe_angle: m.toe,
            toe_rate: m.toe_rate,
            contact: m.contact,
        }
    }
}

impl FootState {
    /// Pose and spatial velocity (linear, angular) of the toe segment frame: origin on the toe
    /// joint axis (`front`, `toe_height` in the sole frame), rotated by the toe angle.
    pub fn toe_frame(&self, foot: &FootGeometry) -> (Isometry3<f64>, Vector3<f64>, Vector3<f64>) {
        let offset = self.pose.rotation * Vector3::new(foot.front, 0.0, foot.toe_height);
        let rot = self.pose.rotation
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), self.toe_angle);
        let pose = Isometry3::from_parts((self.pose.translation.vector + offset).into(), rot);
        let lateral = self.pose.rotation * Vector3::y();
        let linear = self.linear + self.angular.cross(&offset);
        (pose, linear, self.angular + lateral * self.toe_rate)
    }
}

/// One sample of the walking pattern at time `t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatternSample {
    /// Time since the start \[s].
    pub t: f64,
    /// CoM position \[m] (height constant).
    pub com: Vector3<f64>,
    /// CoM velocity \[m/s].
    pub com_vel: Vector3<f64>,
    /// CoM acceleration \[m/s^2].
    pub com_acc: Vector3<f64>,
    /// ZMP of the LIPM, `p = c - h/g c_ddot` \[m].
    pub zmp: Vector2<f64>,
    /// ZMP reference \[m].
    pub zmp_ref: Vector2<f64>,
    /// Sole frames `[left, right]`.
    pub feet: [FootState; 2],
    /// Torso orientation: yaw = mean of the feet yaws, roll = pitch = 0.
    pub torso: UnitQuaternion<f64>,
    /// Torso angular velocity \[rad/s].
    pub torso_angular: Vector3<f64>,
    /// Support phase.
    pub phase: Phase,
    /// Index of the step under way or next (0-based; `n_steps` after the last).
    pub step: usize,
}

impl PatternSample {
    /// State of one foot.
    pub fn foot(&self, foot: Foot) -> &FootState {
        &self.feet[foot.index()]
    }
}

/// A precomputed walking pattern sampled every `dt`.
#[derive(Debug, Clone)]
pub struct WalkingPattern {
    params: PatternParams,
    schedule: Schedule,
    controller: PreviewController,
    roll: RollPlan,
    samples: Vec<PatternSample>,
}

impl WalkingPattern {
    /// Plans footsteps, runs the preview servo along the ZMP reference and samples feet and torso.
    pub fn generate(params: &PatternParams) -> Result<WalkingPattern, PatternError> {
        let plan = FootstepPlan::new(params)?;
        let schedule = Schedule::new(plan, params);
        let horizon = (params.preview_time / params.dt).round() as usize;
        let weights = (params.zmp_weight, params.state_weight, params.input_weight);
        let h = params.com_height;
        let controller = PreviewController::new(h, params.gravity, params.dt, weights, horizon)?;
        let n = (params.duration() / params.dt).floor() as usize + 1;
        let times: Vec<f64> = (0..n).map(|k| k as f64 * params.dt).collect();
        let refs: Vec<Vector2<f64>> = times.iter().map(|&t| schedule.zmp_reference(t)).collect();
        let start = midpoint(schedule.stance(0));
        let mut axes = [Vec::new(), Vec::new()];
        for (i, out) in axes.iter_mut().enumerate() {
            let r: Vec<f64> = refs.iter().map(|p| p[i]).collect();
            controller.track(&r, &Vector3::new(start[i], 0.0, 0.0), out);
        }
        let com = |t: f64| {
            let k = ((t / params.dt).round() as usize).min(n - 1);
            Vector2::new(axes[0][k][0], axes[1][k][0])
        };
        let roll = RollPlan::new(&schedule, params, com);
        let feet = Feet {
            schedule: &schedule,
            params,
            roll: &roll,
        };
        let samples = (0..n)
            .map(|k| {
                let (x, y) = (&axes[0][k], &axes[1][k]);
                let mut s = feet_and_torso(&feet, &schedule, times[k]);
                s.com = Vector3::new(x[0], y[0], h);
                s.com_vel = Vector3::new(x[1], y[1], 0.0);
                s.com_acc = Vector3::new(x[2], y[2], 0.0);
                s.zmp = Vector2::new((controller.c * x)[0], (controller.c * y)[0]);
                s.zmp_ref = refs[k];
                s
            })
            .collect();
        Ok(WalkingPattern {
            params: params.clone(),
            schedule,
            controller,
            roll,
            samples,
        })
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// Whether there are no samples (never after a successful `generate`).
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// Sample `k` (time `k dt`), `None` past the end.
    pub fn sample(&self, k: usize) -> Option<&PatternSample> {
        self.samples.get(k)
    }

    /// All samples in time order.
    pub fn samples(&self) -> &[PatternSample] {
        &self.samples
    }

    /// Iterator over the samples.
    pub fn iter(&self) -> std::slice::Iter<'_, PatternSample> {
        self.samples.iter()
    }

    /// Adds a CoM offset per sample, `[x, y]` each as `(position, velocity, acceleration)`,
    /// and the matching LIPM ZMP change `c * offset` to `zmp` (e.g. the multibody ZMP
    /// correction of a second preview pass); `zmp_ref` is left as planned.
    pub fn offset_com(&mut self, offset: &[[Vector3<f64>; 2]]) -> Result<(), PatternError> {
        let finite = offset
            .iter()
            .flatten()
            .all(|v| v.iter().all(|x| x.is_finite()));
        if offset.len() != self.samples.len() || !finite {
            return Err(PatternError::InvalidParameter {
                name: "com offset",
                value: offset.len() as f64,
                reason: "needs one finite offset per sample",
            });
        }
        for (s, o) in self.samples.iter_mut().zip(offset) {
            for (i, d) in o.iter().enumerate() {
                s.com[i] += d[0];
                s.com_vel[i] += d[1];
                s.com_acc[i] += d[2];
                s.zmp[i] += (self.controller.c * d)[0];
            }
        }
        Ok(())
    }

    /// The parameters the pattern was generated with.
    pub fn params(&self) -> &PatternParams {
        &self.params
    }

    /// The footstep plan.
    pub fn footsteps(&self) -> &FootstepPlan {
        &self.schedule.plan
    }

    /// Heel-lift and toe-up angles of the steps (toe-off, heel strike).
    pub fn roll(&self) -> &RollPlan {
        &self.roll
    }

    /// The step timing and ZMP reference.
    pub fn schedule(&self) -> &Schedule {
        &self.schedule
    }

    /// The preview servo used for the CoM (gains, DARE solution).
    pub fn controller(&self) -> &PreviewController {
        &self.controller
    }
}

/// Feet, torso, phase and step index at `t` (CoM and ZMP left zero).
fn feet_and_torso(feet: &Feet<'_>, schedule: &Schedule, t: f64) -> PatternSample {
    let (feet, step): ([SoleMotion; 2], usize) = feet.at(t);
    let yaw = 0.5 * (feet[0].pose.yaw + feet[1].pose.yaw);
    let yaw_rate = 0.5 * (feet[0].yaw_rate + feet[1].yaw_rate);
    PatternSample {
        t,
        com: Vector3::zeros(),
        com_vel: Vector3::zeros(),
        com_acc: Vector3::zeros(),
        zmp: Vector2::zeros(),
        zmp_ref: Vector2::zeros(),
        feet: [FootState::from(&feet[0]), FootState::from(&feet[1])],
        torso: UnitQuaternion::from_euler_angles(0.0, 0.0, yaw),
        torso_angular: Vector3::new(0.0, 0.0, yaw_rate),
        phase: schedule.phase(t),
        step,
    }
}
