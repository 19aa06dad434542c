//! The reference of the dynamic walk: the kinematic walk ([`WalkController`]) sampled at the
//! pattern period, with the actuated joints' `q`, `qdot` and the feedforward torques of
//! [`super::feedforward`] per sample, plus the planned base position and the support phase.
//!
//! Multibody ZMP correction (a second preview pass in the manner of Kajita's two-stage
//! preview control, not in the thesis): the pattern's CoM comes from the LIPM, but the
//! multibody ZMP of the IK motion (from the RNEA ground wrench) deviates from it by up to
//! ~0.17 m at the start of single support with 0.4 m / 0.8 s steps (heavy swing leg, rotor
//! inertias), beyond the 0.13 m front edge of the sole. Each iteration runs the kinematic
//! walk, takes the error `e = p_mb - p_lipm` of every sample, runs the pattern's preview servo
//! on the reference `-e` from rest and adds the resulting CoM offset to the pattern
//! ([`WalkingPattern::offset_com`]); the IK then tracks the corrected CoM.
//!
//! Accelerations are central differences of the IK velocities (one-sided at the ends).

use super::feedforward::Feedforward;
use super::stabiliser::roll_pitch;
use crate::pattern::{Phase, WalkingPattern};
use crate::walk::error::WalkError;
use crate::walk::{Method, WalkController, WalkJoint, WalkParams, WalkRobot};
use biped_robots::lola::LolaModel;
use nalgebra::{DVector, Quaternion, UnitQuaternion, Vector2, Vector3};

/// Joint reference of the actuated joints, sampled every `dt` (row-major: sample x joint).
#[derive(Debug, Clone)]
pub struct JointReference {
    /// Sample period \[s].
    pub dt: f64,
    /// Number of actuated joints per sample (the order of the plant's actuators).
    pub joints: usize,
    /// Joint angles \[rad].
    pub q: Vec<f64>,
    /// Joint velocities \[rad/s].
    pub qd: Vec<f64>,
    /// Feedforward joint torques \[N m].
    pub tau: Vec<f64>,
    /// Planned base (floating-joint origin) position per sample \[m].
    pub base: Vec<Vector3<f64>>,
    /// ZMP of the planned motion (multibody, from the RNEA ground wrench) per sample \[m].
    pub zmp: Vec<Vector2<f64>>,
    /// ZMP of the uncorrected pattern (LIPM) per sample \[m].
    pub pattern_zmp: Vec<Vector2<f64>>,
    /// Reference base inclination `[roll, pitch]` per sample \[rad].
    pub tilt: Vec<[f64; 2]>,
    /// Support phase per sample.
    pub phase: Vec<Phase>,
    /// Planned vertical load of the `[left, right]` side per sample (the feedforward's share
    /// of the ground force) \[N].
    pub fz: Vec<[f64; 2]>,
    /// Full configuration of the first sample (the start pose).
    pub q0: DVector<f64>,
    /// Largest `|p_mb - p_lipm|` before each correction and after the last \[m].
    pub zmp_error: Vec<f64>,
    /// Reference samples whose joint angle was clamped into its limits.
    pub clamped_samples: usize,
    /// Largest amount by which a reference angle was clamped \[rad].
    pub max_clamp: f64,
    /// Largest amount by which a reference angle lies beyond its joint range before any
    /// clamping (what the plant's end stops resist) \[rad].
    pub max_excess: f64,
}

impl JointReference {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.phase.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.phase.is_empty()
    }

    /// Row of sample `k` (clamped to the last sample) of one of the per-joint series.
    pub fn row<'a>(&self, series: &'a [f64], k: usize) -> &'a [f64] {
        let k = k.min(self.len().saturating_sub(1));
        &series[k * self.joints..(k + 1) * self.joints]
    }

    /// Sample index of time `t` (nearest sample, clamped to the walk).
    pub fn index(&self, t: f64) -> usize {
        let k = (t / self.dt).round().max(0.0) as usize;
        k.min(self.len().saturating_sub(1))
    }
}

/// How the reference is built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceOptions {
    /// Arm method of the kinematic walk.
    pub method: Method,
    /// IK tuning.
    pub walk: WalkParams,
    /// Multibody ZMP correction iterations (0 = the LIPM pattern as is).
    pub zmp_iterations: usize,
    /// Clamp joint angles into the limits shrunk by this margin \[rad] (`None`: no clamping;
    /// the velocity of a clamped sample is set to zero).
    pub clamp_margin: Option<f64>,
}

/// The kinematic walk's `(q, qdot)` of every sample.
type Motion = (Vec<DVector<f64>>, Vec<DVector<f64>>);

/// Runs the IK over every sample of `pattern`.
fn kinematic_walk(
    robot: &WalkRobot,
    pattern: &WalkingPattern,
    o: &ReferenceOptions,
) -> Result<Motion, WalkError> {
    let dt = pattern.params().dt;
    let mut ctrl = WalkController::for_robot(robot, o.method, o.walk, pattern)?;
    let n = pattern.len();
    let (mut qs, mut vs) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for sample in pattern.iter() {
        ctrl.cycle(sample, dt)?;
        qs.push(ctrl.q_eval().clone());
        vs.push(ctrl.qdot().clone());
    }
    Ok((qs, vs))
}

/// Central-difference acceleration of sample `k` into `a`.
fn acceleration(vs: &[DVector<f64>], dt: f64, k: usize, a: &mut DVector<f64>) {
    let n = vs.len();
    let (prev, next) = (k.saturating_sub(1), (k + 1).min(n - 1));
    a.copy_from(&vs[next]);
    *a -= &vs[prev];
    *a /= dt * (next - prev).max(1) as f64;
}

/// Runs the kinematic walk of `lola` on `pattern` corrected `o.zmp_iterations` times for the
/// multibody ZMP (see the module docs) and builds the reference of its actuated joints (the
/// order of `lola.limits`) from the last walk.
pub fn build_reference(
    lola: &LolaModel,
    pattern: &WalkingPattern,
    o: &ReferenceOptions,
) -> Result<JointReference, WalkError> {
    let robot = WalkRobot::lola(lola)?;
    let joints = robot.joints.clone();
    build_robot_reference(&robot, &joints, Feedforward::new(lola)?, pattern, o)
}

/// [`build_reference`] for any robot: the kinematic walk of `robot`, the reference of the
/// joints `joints` (the plant's actuators, in their order; ranges for the clamping and the
/// excess), the feedforward of `ff`.
pub fn build_robot_reference(
    robot: &WalkRobot,
    joints: &[WalkJoint],
    mut ff: Feedforward,
    pattern: &WalkingPattern,
    o: &ReferenceOptions,
) -> Result<JointReference, WalkError> {
    let dt = pattern.params().dt;
    let n = pattern.len();
    let mut a = DVector::zeros(robot.model.nv());
    let mut offset = vec![[Vector3::zeros(); 2]; n];
    let mut corrected = pattern.clone();
    let mut zmp_error = Vec::new();
    let mut iteration = 0;
    loop {
        let (qs, vs) = kinematic_walk(robot, &corrected, o)?;
        let mut r = empty_reference(n, joints.len(), dt, &qs)?;
        let mut err = [Vec::with_capacity(n), Vec::with_capacity(n)];
        for (k, sample) in corrected.iter().enumerate() {
            acceleration(&vs, dt, k, &mut a);
            let tau = ff.compute(&qs[k], &vs[k], &a, sample)?;
            r.push_sample(joints, (&qs[k], &vs[k], tau), o.clamp_margin);
            let p0 = pattern.samples()[k].zmp;
            let p = ff.zmp().unwrap_or(p0);
            err[0].push(p0.x - p.x);
            err[1].push(p0.y - p.y);
            r.zmp.push(p);
            r.pattern_zmp.push(p0);
            r.phase.push(sample.phase);
            r.fz.push(ff.planned_loads());
        }
        let worst = err[0]
            .iter()
            .chain(&err[1])
            .fold(0.0_f64, |m, e| m.max(e.abs()));
        zmp_error.push(worst);
        if iteration == o.zmp_iterations {
            r.zmp_error = zmp_error;
            return Ok(r);
        }
        let mut out = Vec::with_capacity(n);
        for (axis, e) in err.iter().enumerate() {
            pattern.controller().track(e, &Vector3::zeros(), &mut out);
            for (slot, d) in offset.iter_mut().zip(&out) {
                slot[axis] += d;
            }
        }
        corrected = pattern.clone();
        corrected.offset_com(&offset)?;
        iteration += 1;
    }
}

/// A reference with no samples yet (capacity for `n`), starting at `qs[0]`.
fn empty_reference(
    n: usize,
    nj: usize,
    dt: f64,
    qs: &[DVector<f64>],
) -> Result<JointReference, WalkError> {
    let q0 = qs.first().cloned().ok_or(WalkError::InvalidParameter {
        name: "pattern",
        reason: "has no samples".into(),
    })?;
    Ok(JointReference {
        dt,
        joints: nj,
        q: Vec::with_capacity(n * nj),
        qd: Vec::with_capacity(n * nj),
        tau: Vec::with_capacity(n * nj),
        base: Vec::with_capacity(n),
        zmp: Vec::with_capacity(n),
        pattern_zmp: Vec::with_capacity(n),
        tilt: Vec::with_capacity(n),
        phase: Vec::with_capacity(n),
        fz: Vec::with_capacity(n),
        q0,
        zmp_error: Vec::new(),
        clamped_samples: 0,
        max_clamp: 0.0,
        max_excess: 0.0,
    })
}

impl JointReference {
    /// Appends the actuated joints' angle (clamped if asked), velocity and torque of one
    /// sample, and the base position.
    fn push_sample(
        &mut self,
        joints: &[WalkJoint],
        (q, v, tau): (&DVector<f64>, &DVector<f64>, &DVector<f64>),
        clamp: Option<f64>,
    ) {
        let mut clamped = false;
        for l in joints {
            let excess = (q[l.q_index] - l.upper).max(l.lower - q[l.q_index]);
            self.max_excess = self.max_excess.max(excess);
            let (qc, c) = clamp_angle(q[l.q_index], l, clamp);
            clamped |= c > 0.0;
            self.max_clamp = self.max_clamp.max(c);
            self.q.push(qc);
            self.qd.push(if c > 0.0 { 0.0 } else { v[l.v_index] });
            self.tau.push(tau[l.v_index]);
        }
        self.clamped_samples += usize::from(clamped);
        self.base.push(Vector3::new(q[0], q[1], q[2]));
        let rot = UnitQuaternion::new_normalize(Quaternion::new(q[6], q[3], q[4], q[5]));
        self.tilt.push(roll_pitch(&rot));
    }
}

/// `q` clamped into the limits shrunk by `margin` (if any), and the amount moved.
fn clamp_angle(q: f64, l: &WalkJoint, clamp: Option<f64>) -> (f64, f64) {
    match clamp {
        Some(m) if l.upper - l.lower > 2.0 * m => {
            let c = q.clamp(l.lower + m, l.upper - m);
            (c, (c - q).abs())
        }
        _ => (q, 0.0),
    }
}
