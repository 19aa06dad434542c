//! Per-cycle evaluation of a walk (thesis 7.6, Fig. 7.1/7.4): vertical angular momentum about
//! the CoM `L_z = J_Lz qd` (7.2), its rate (backward difference over the cycle), the vertical
//! torque `tau_z` the stance foot must transmit, the smallest SSV segment distance and the
//! smallest joint-limit margin.
//!
//! `tau_z`: inverse dynamics of the floating-base model at `(q, qd, qdd)` with `qdd` the
//! backward difference of the IK velocities gives, in the free joint's entries, the wrench
//! (body axes, about the base origin) the environment must apply to the base for this motion
//! (the free joint transmits it from the world). Only the ground can supply it, so it is
//! shifted to the stance sole point `p`: `M_p = R m + (o - p) x R f`, `tau_z = M_p,z`. In
//! double support the total wrench is reported about the midpoint of the two soles (how it
//! splits between the feet is not determined by the kinematics). The same wrench gives the
//! friction load of [`super::friction`].

use super::controller::WalkController;
use super::error::{model_err, WalkError};
use super::friction::{FrictionLoad, Support};
use super::robot::{frame_position, WalkRobot};
use crate::avoidance::{AvoidanceParams, CollisionAvoidance};
use crate::momentum::LzRate;
use crate::pattern::{Foot, FootGeometry, PatternSample};
use crate::tasks::Frame;
use biped_dynamics::{inverse_dynamics, Data, JointModel, Model};
use biped_robots::lola::LolaModel;
use nalgebra::{DVector, Vector3};

/// Metrics of one cycle (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleMetrics {
    /// Vertical angular momentum about the CoM \[N m s].
    pub lz: f64,
    /// Its rate (backward difference) \[N m].
    pub dlz: f64,
    /// Vertical torque at the stance sole (double support: sole midpoint) \[N m].
    pub tau_z: f64,
    /// Smallest SSV distance over all segment pairs \[m].
    pub min_distance: f64,
    /// Smallest distance of a joint to its nearer limit \[rad or m].
    pub joint_margin: f64,
    /// Index (into [`Evaluator::joint_name`]) of the joint with that margin.
    pub worst_joint: usize,
    /// Index (into [`Evaluator::pair_name`]) of the closest segment pair, if any.
    pub closest_pair: Option<usize>,
    /// Ground wrench at the stance sole point (double support: sole midpoint): force \[N].
    pub force: Vector3<f64>,
    /// ... and moment about that point \[N m] (world axes).
    pub moment: Vector3<f64>,
    /// Friction load of that wrench on the planned support.
    pub friction: FrictionLoad,
}

/// Preallocated evaluator (own dynamics workspace and collision model).
#[derive(Debug, Clone)]
pub struct Evaluator {
    data: Data,
    distances: CollisionAvoidance,
    rate: LzRate,
    dt: f64,
    qdot_prev: DVector<f64>,
    qdd: DVector<f64>,
    started: bool,
    root: usize,
    soles: [Frame; 2],
    limits: Vec<(usize, f64, f64)>,
    names: Vec<String>,
    support: Support,
    geometry: FootGeometry,
    mu: f64,
}

impl Evaluator {
    /// Evaluator for `lola` with control period `dt`, the default sole geometry and the
    /// friction coefficient of the contact simulation's default ground.
    pub fn new(lola: &LolaModel, dt: f64) -> Result<Self, WalkError> {
        Self::for_robot(&WalkRobot::lola(lola)?, dt)
    }

    /// Evaluator for `robot` with control period `dt`, the robot's sole geometry and the
    /// friction coefficient of the contact simulation's default ground.
    pub fn for_robot(robot: &WalkRobot, dt: f64) -> Result<Self, WalkError> {
        let model = &robot.model;
        let root = floating_root(model)?;
        let [right, left] = robot.frames.soles;
        let segments = robot.collision.clone();
        Ok(Self {
            data: Data::new(model),
            distances: CollisionAvoidance::new(model, segments, AvoidanceParams::default())?,
            rate: LzRate::new(dt)?,
            dt,
            qdot_prev: DVector::zeros(model.nv()),
            qdd: DVector::zeros(model.nv()),
            started: false,
            root,
            soles: [left, right],
            limits: robot
                .joints
                .iter()
                .map(|l| (l.q_index, l.lower, l.upper))
                .collect(),
            names: robot.joints.iter().map(|l| l.name.clone()).collect(),
            support: Support::new(),
            geometry: robot.foot,
            mu: biped_sim::contact::ContactParams::default().friction,
        })
    }

    /// The same with the sole geometry `geometry` and the ground's Coulomb coefficient `mu`
    /// for the friction load.
    pub fn with_ground(self, geometry: FootGeometry, mu: f64) -> Result<Self, WalkError> {
        if !(mu.is_finite() && mu > 0.0) {
            return Err(WalkError::InvalidParameter {
                name: "friction",
                reason: format!("{mu} must be finite and > 0"),
            });
        }
        Ok(Self {
            geometry,
            mu,
            ..self
        })
    }

    /// The sole frames `[left, right]`.
    pub fn soles(&self) -> [Frame; 2] {
        self.soles
    }

    /// Coulomb coefficient of the friction load.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// Name of the joint `i` of [`CycleMetrics::worst_joint`].
    pub fn joint_name(&self, i: usize) -> &str {
        self.names.get(i).map_or("?", String::as_str)
    }

    /// Names of the segments of pair `i` of [`CycleMetrics::closest_pair`], "a and b".
    pub fn pair_name(&self, i: usize) -> String {
        let model = self.distances.collision_model();
        let segments = model.segments();
        match model.pairs().get(i) {
            Some(p) => format!("{} and {}", segments[p.a].name(), segments[p.b].name()),
            None => "?".to_string(),
        }
    }

    /// Metrics of the cycle `ctrl` has just run for pattern sample `sample`.
    pub fn evaluate(
        &mut self,
        ctrl: &WalkController,
        sample: &PatternSample,
    ) -> Result<CycleMetrics, WalkError> {
        let (q, qdot) = (ctrl.q_eval(), ctrl.qdot());
        let lz = ctrl.jlz().dot(qdot);
        let dlz = self.rate.update(lz)?;
        if self.started {
            self.qdd.copy_from(qdot);
            self.qdd -= &self.qdot_prev;
            self.qdd /= self.dt;
        }
        self.started = true;
        self.qdot_prev.copy_from(qdot);
        let (kin, _) = ctrl.kinematics();
        let [left, right] = self.soles.map(|f| frame_position(kin, &f));
        let point = match sample.phase.stance_foot() {
            Some(Foot::Left) => left,
            Some(Foot::Right) => right,
            None => 0.5 * (left + right),
        };
        let model = ctrl.tasks().model();
        let state = (q, qdot, &self.qdd);
        let (force, moment) = wrench(model, &mut self.data, self.root, state, &point)?;
        self.support.update(&sample.feet, &self.geometry);
        let friction = self.support.load(&force, &moment, &point, self.mu);
        self.distances.update(kin)?;
        let closest = self.distances.global_minimum();
        let (joint_margin, worst_joint) = self.margin(q);
        Ok(CycleMetrics {
            lz,
            dlz,
            tau_z: moment.z,
            min_distance: closest
                .as_ref()
                .map_or(f64::INFINITY, |(_, c)| c.result.distance),
            joint_margin,
            worst_joint,
            closest_pair: closest.map(|(i, _)| i),
            force,
            moment,
            friction,
        })
    }

    /// Smallest joint-limit margin at `q` and the index of its joint.
    fn margin(&self, q: &DVector<f64>) -> (f64, usize) {
        self.limits
            .iter()
            .map(|&(i, lo, hi)| (q[i] - lo).min(hi - q[i]))
            .enumerate()
            .fold((f64::INFINITY, 0), |best, (k, m)| match m < best.0 {
                true => (m, k),
                false => best,
            })
    }

    /// Total external wrench at `(q, v, a)` as (force, moment about `point`) in world axes:
    /// the free-joint entries of the inverse dynamics (exposed for tests of the convention).
    pub fn ground_wrench(
        &mut self,
        ctrl: &WalkController,
        a: &DVector<f64>,
        point: &Vector3<f64>,
    ) -> Result<(Vector3<f64>, Vector3<f64>), WalkError> {
        let model = ctrl.tasks().model();
        let state = (ctrl.q_eval(), ctrl.qdot(), a);
        wrench(model, &mut self.data, self.root, state, point)
    }
}

/// Index of the quaternion floating base of `model`.
pub(crate) fn floating_root(model: &Model) -> Result<usize, WalkError> {
    model
        .bodies()
        .iter()
        .position(|b| matches!(b.joint(), JointModel::FreeQuaternion))
        .ok_or_else(|| model_err("no quaternion floating base"))
}

/// Id of the body named `name`, or a model error naming it.
pub(crate) fn body(model: &Model, name: &str) -> Result<usize, WalkError> {
    model
        .body_id(name)
        .ok_or_else(|| model_err(format!("no body {name}")))
}

/// Free-joint entries of the inverse dynamics at `(q, v, a)` as world-axes force and moment
/// about `point` (see the module docs).
pub(crate) fn wrench(
    model: &Model,
    data: &mut Data,
    root: usize,
    (q, v, a): (&DVector<f64>, &DVector<f64>, &DVector<f64>),
    point: &Vector3<f64>,
) -> Result<(Vector3<f64>, Vector3<f64>), WalkError> {
    let tau = inverse_dynamics(model, data, q, v, a, None).map_err(model_err)?;
    let f_body = Vector3::new(tau[0], tau[1], tau[2]);
    let m_body = Vector3::new(tau[3], tau[4], tau[5]);
    let (rot, origin) = (data.world_rot[root], data.world_pos[root]);
    let f = rot * f_body;
    Ok((f, rot * m_body + (origin - point).cross(&f)))
}
