//! Construction of a [`WalkController`]: its tasks placed on the pattern's first footprints,
//! the null-space and momentum parts of its method, and the settling cycles.

use super::joints::{joint_cost, joint_limits};
use super::WalkController;
use crate::avoidance::{AvoidanceParams, CollisionAvoidance};
use crate::ik::{SaturatedRmrc, TaskBuffers, Weight};
use crate::momentum::{
    vertical_inertia, ArmSwing, ArmSwingNominal, Compensation, InCycleCompensation,
    MomentumMinimisation, MomentumReference, VerticalMomentum,
};
use crate::pattern::{PatternSample, WalkingPattern};
use crate::tasks::{LolaTasks, TaskId};
use crate::walk::error::WalkError;
use crate::walk::method::{Method, WalkParams};
use crate::walk::posture::{arm_lock_weight, arm_pivots, place_on_footprints};
use crate::walk::robot::WalkRobot;
use crate::walk::targets::legs;
use biped_dynamics::Data;
use nalgebra::{DVector, Vector3};

impl WalkController {
    /// Controller for `robot` standing on the first footprints of `pattern`, after
    /// `params.settle_time` of IK cycles on its first sample.
    pub fn for_robot(
        robot: &WalkRobot,
        method: Method,
        params: WalkParams,
        pattern: &WalkingPattern,
    ) -> Result<Self, WalkError> {
        let dt = pattern.params().dt;
        params.validate(dt)?;
        let first = pattern.sample(0).ok_or(WalkError::InvalidParameter {
            name: "pattern",
            reason: "has no samples".into(),
        })?;
        let (model, nv) = (&robot.model, robot.model.nv());
        let mut tasks = LolaTasks::with_frames(model, &robot.frames, 0.2)?;
        let q = place_on_footprints(robot, &mut tasks, first, params.arm_pose)?;
        tasks.set_targets_from(&q)?;
        let com_offset = tasks.targets.cog - first.com;
        let arm_on = method.arm_tasks();
        tasks.set_active_now(TaskId::RightArmCoG, arm_on);
        tasks.set_active_now(TaskId::LeftArmCoG, arm_on);
        let swing = arm_swing(&tasks, first, &com_offset, &params)?;
        let cost = joint_cost(
            robot,
            &q,
            params.comfort_weight,
            params.limit_weight,
            params.limit_margin,
        )?;
        let minim = MomentumMinimisation::new(params.minimization_delta)?;
        let izz = vertical_inertia(model, &mut Data::new(model), &q)?;
        let shoulders = robot.frames.arm_roots;
        let mut ctrl = Self {
            arm_pivot: arm_pivots(&tasks, &shoulders),
            shoulders,
            method,
            params,
            buf: TaskBuffers::new(&tasks),
            sns: SaturatedRmrc::new(TaskId::TOTAL_ROWS, nv, joint_limits(robot, &params)?)?,
            foot: pattern.params().foot,
            toes: robot.frames.toes.is_some(),
            xcmd: DVector::zeros(TaskId::TOTAL_ROWS),
            grad: DVector::zeros(nv),
            grad_c: DVector::zeros(nv),
            weight: method_weight(robot, method, &minim, &params)?,
            cost,
            avoid: avoidance(robot, &params)?,
            vm: VerticalMomentum::new(model),
            comp: compensation(robot, &params)?,
            minim,
            reference: MomentumReference::new(izz)?,
            swing,
            com_offset,
            step: first.step,
            step_turn: (pattern.params().step_time, pattern.params().turn_angle),
            q_eval: q.clone(),
            q_next: q.clone(),
            qdot: DVector::zeros(nv),
            q,
            tasks,
        };
        ctrl.settle(first, dt)?;
        Ok(ctrl)
    }

    /// `params.settle_time` of IK cycles on the first sample, then at rest.
    fn settle(&mut self, first: &PatternSample, dt: f64) -> Result<(), WalkError> {
        let settle = (self.params.settle_time / dt).round() as usize;
        for _ in 0..settle {
            self.cycle(first, dt)?;
        }
        self.qdot.fill(0.0);
        Ok(())
    }
}

/// The reference method's arm swing about the arm CoG targets of `tasks` (7.3.1).
fn arm_swing(
    tasks: &LolaTasks,
    first: &PatternSample,
    com_offset: &Vector3<f64>,
    params: &WalkParams,
) -> Result<ArmSwing, WalkError> {
    let [right_leg, left_leg] = legs(first, com_offset).map(|l| l.position);
    let nominal = ArmSwingNominal {
        left_arm: tasks.targets.arm_cog[1],
        right_arm: tasks.targets.arm_cog[0],
        left_leg,
        right_leg,
    };
    Ok(ArmSwing::with_mask(
        params.arm_swing_scale,
        Vector3::x(),
        nominal,
    )?)
}

/// The self-collision avoidance of `robot`, if on.
fn avoidance(
    robot: &WalkRobot,
    params: &WalkParams,
) -> Result<Option<CollisionAvoidance>, WalkError> {
    if !params.avoidance {
        return Ok(None);
    }
    let collision = robot.collision.clone();
    let avoid = CollisionAvoidance::new(&robot.model, collision, AvoidanceParams::default())?;
    Ok(Some(avoid))
}

/// The joint weight of `method`: (7.13) for minimisation, the arm lock for `none`.
fn method_weight(
    robot: &WalkRobot,
    method: Method,
    minim: &MomentumMinimisation,
    params: &WalkParams,
) -> Result<Weight, WalkError> {
    Ok(match method {
        Method::Minimization => minim.weight(robot.model.nv())?,
        Method::None => arm_lock_weight(robot, params.arm_lock_weight)?,
        _ => Weight::Identity,
    })
}

/// The in-cycle compensation by `robot`'s reducing joints (7.3.2).
fn compensation(robot: &WalkRobot, params: &WalkParams) -> Result<InCycleCompensation, WalkError> {
    let reducing: Vec<&str> = robot.reducing.iter().map(String::as_str).collect();
    let comp = Compensation::new(&robot.model, &reducing)?.with_gain(params.compensation_gain)?;
    let max_speed = params.compensation_max_speed;
    Ok(InCycleCompensation::new(
        comp,
        TaskId::TOTAL_ROWS,
        max_speed,
    )?)
}
