//! [`WalkController`]: one 1 kHz IK cycle of a [`WalkRobot`] (Lola, or a described robot)
//! over a walking-pattern sample (thesis 4.5,
//! 5.2, 7.3-7.5): targets, closed-loop task velocities (4.13)-(4.16), Klein-Huang RMRC
//! (Alg. 4.3) with null-space gradient `grad H_J + grad H_C` (+ compensation) and the
//! method's weight, and the SE(3) integration of q. Everything is preallocated in
//! [`WalkController::for_robot`].

use super::error::WalkError;
use super::method::{Method, WalkParams};
use super::posture::{swing_on_circle, ArmPivot};
use super::robot::WalkRobot;
use super::targets::{legs, set_targets};
use crate::avoidance::{AvoidanceSummary, CollisionAvoidance};
use crate::ik::joint_cost::JointCost;
use crate::ik::{RmrcProblem, SaturatedRmrc, SaturationReport, TaskBuffers, TaskMap, Weight};
use crate::momentum::{
    ArmSwing, ArmTargets, InCycleCompensation, MomentumMinimisation, MomentumReference,
    VerticalMomentum,
};
use crate::pattern::{FootGeometry, PatternSample, WalkingPattern};
use crate::tasks::LolaTasks;
use biped_robots::lola::LolaModel;
use nalgebra::{DVector, Vector3};

mod access;
mod build;
mod compensate;
mod joints;

/// What one cycle did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleInfo {
    /// Active task rows m.
    pub rows: usize,
    /// Norm of the task error before the step.
    pub error_norm: f64,
    /// Collision avoidance summary (`None` with avoidance off).
    pub avoidance: Option<AvoidanceSummary>,
    /// Joints the solve held at their limit box (SNS).
    pub limits: SaturationReport,
}

/// The walking IK of a [`WalkRobot`] (Lola by [`Self::new`]) with one arm method (see
/// [`Method`]).
///
/// # Example
///
/// A walk of three 0.2 m steps, one [`Self::cycle`] per pattern sample. By the footstep plan
/// (the first step is a half step, the last one closes the feet side by side) both feet end
/// up `(3 - 1) * 0.2 = 0.4 m` ahead of where they started, which the kinematics of the final
/// configuration confirms.
///
/// ```
/// use biped_control::pattern::{PatternParams, WalkingPattern};
/// use biped_control::walk::{walk_pattern_params, Method, WalkController, WalkParams};
/// use biped_dynamics::{update_placements, Data};
/// use biped_robots::lola::{build, LolaType};
///
/// let lola = build(LolaType::Type2)?;
/// let params = PatternParams {
///     start_time: 0.4,
///     end_time: 0.4,
///     ..walk_pattern_params(&lola, 3, 0.2, 0.6)?
/// };
/// let pattern = WalkingPattern::generate(&params)?;
/// let mut walk = WalkController::new(&lola, Method::None, WalkParams::default(), &pattern)?;
///
/// let model = &lola.model;
/// let mut data = Data::new(model);
/// let soles = ["l_sole", "r_sole"].map(|n| model.body_id(n).unwrap());
/// update_placements(model, &mut data, walk.q())?;
/// let start = soles.map(|b| data.world_pos[b]);
/// for sample in pattern.iter() {
///     walk.cycle(sample, params.dt)?;
/// }
/// update_placements(model, &mut data, walk.q())?;
/// for (k, &b) in soles.iter().enumerate() {
///     let moved = data.world_pos[b] - start[k];
///     assert!((moved.x - 0.4).abs() < 2e-3 && moved.y.abs() < 2e-3 && moved.z.abs() < 2e-3);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct WalkController {
    method: Method,
    params: WalkParams,
    tasks: LolaTasks,
    buf: TaskBuffers,
    sns: SaturatedRmrc,
    foot: FootGeometry,
    toes: bool,
    xcmd: DVector<f64>,
    grad: DVector<f64>,
    grad_c: DVector<f64>,
    weight: Weight,
    cost: JointCost,
    avoid: Option<CollisionAvoidance>,
    vm: VerticalMomentum,
    comp: InCycleCompensation,
    minim: MomentumMinimisation,
    reference: MomentumReference,
    swing: ArmSwing,
    com_offset: Vector3<f64>,
    arm_pivot: [ArmPivot; 2],
    shoulders: [usize; 2],
    step: usize,
    step_turn: (f64, f64),
    q: DVector<f64>,
    q_eval: DVector<f64>,
    q_next: DVector<f64>,
    qdot: DVector<f64>,
}

impl WalkController {
    /// Controller for `lola` standing on the first footprints of `pattern`, after
    /// `params.settle_time` of IK cycles on its first sample.
    pub fn new(
        lola: &LolaModel,
        method: Method,
        params: WalkParams,
        pattern: &WalkingPattern,
    ) -> Result<Self, WalkError> {
        Self::for_robot(&WalkRobot::lola(lola)?, method, params, pattern)
    }

    /// One IK cycle over pattern sample `s` with period `dt`: q moves to the next cycle.
    pub fn cycle(&mut self, s: &PatternSample, dt: f64) -> Result<CycleInfo, WalkError> {
        self.set_sample_targets(s)?;
        self.tasks.advance(dt);
        self.q_eval.copy_from(&self.q);
        self.buf.evaluate(&mut self.tasks, &self.q)?;
        self.sns.set_unit_rows(self.tasks.unit_rows())?;
        self.cost.gradient_into(&self.q, &mut self.grad)?;
        let scale = match self.method {
            Method::Minimization => self.params.minimization_delta,
            _ => 1.0,
        };
        self.grad *= self.params.alpha_n * scale;
        let avoidance = match &mut self.avoid {
            Some(a) => {
                let (data, jac) = self.tasks.kinematics();
                self.grad_c.fill(0.0);
                let sum = a.gradient(self.tasks.model(), data, jac, &mut self.grad_c)?;
                self.grad
                    .axpy(self.params.avoidance_gain * scale, &self.grad_c, 1.0);
                Some(sum)
            }
            None => None,
        };
        self.vm.update(self.tasks.centroidal())?;
        if self.method == Method::Minimization {
            self.minim.update(self.vm.jacobian_z(), &mut self.weight)?;
        }
        let limits = self.solve(dt)?;
        if self.method == Method::Compensation {
            self.compensate(self.reference.sample(s.t).0)?;
        }
        self.tasks
            .retract(&self.q, &self.qdot, dt, &mut self.q_next)?;
        std::mem::swap(&mut self.q, &mut self.q_next);
        Ok(CycleInfo {
            rows: self.buf.rows,
            error_norm: self.buf.error_norm(),
            avoidance,
            limits,
        })
    }

    /// Targets of sample `s` (arm CoG targets for the reference method, `L_ref` per step).
    fn set_sample_targets(&mut self, s: &PatternSample) -> Result<(), WalkError> {
        let arms: Option<ArmTargets> = if self.method.arm_tasks() {
            let [right, left] = legs(s, &self.com_offset);
            let mut a = self.swing.targets(&left, &right)?;
            let shoulders = self.shoulders_now()?;
            for (slot, arm) in [&mut a.right, &mut a.left].into_iter().enumerate() {
                swing_on_circle(arm, &self.arm_pivot[slot], &shoulders[slot]);
            }
            Some(a)
        } else {
            None
        };
        if s.step != self.step {
            self.step = s.step;
            let (t_step, turn) = self.step_turn;
            self.reference.start_step(s.t, t_step, turn)?;
        }
        let t = &mut self.tasks.targets;
        set_targets(
            s,
            &self.com_offset,
            (&self.foot, self.toes),
            arms.as_ref(),
            t,
        );
        Ok(())
    }

    /// Shoulder positions (right, left) relative to the CoG in the planning frame, from the
    /// last evaluation.
    fn shoulders_now(&self) -> Result<[Vector3<f64>; 2], WalkError> {
        let (data, _) = self.tasks.kinematics();
        let c = self.tasks.centroidal().com();
        let yaw = self.tasks.targets.planning_yaw;
        let rpt = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), -yaw);
        Ok(self.shoulders.map(|b| rpt * (data.world_pos[b] - c)))
    }

    /// `xd_cmd = xd_d + K_x dx` (4.14b), then (4.12) by Alg. 4.3 into `qdot`, inside the
    /// joint limits (SNS) for a step `dt`.
    fn solve(&mut self, dt: f64) -> Result<SaturationReport, WalkError> {
        let m = self.buf.rows;
        self.tasks.feedforward(&mut self.xcmd);
        for i in 0..m {
            self.xcmd[i] += self.params.gain * self.buf.err[i];
        }
        let p = RmrcProblem {
            jacobian: &self.buf.jac,
            rows: m,
            xdot: &self.xcmd,
            weight: &self.weight,
            null_space: Some((&self.grad, 1.0)),
            damping: 0.0,
            softness: self.tasks.softness(),
        };
        Ok(self.sns.solve(&p, &self.q, dt, &mut self.qdot)?)
    }
}
