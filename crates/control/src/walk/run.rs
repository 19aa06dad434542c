//! A whole walk with one method: time series of the metrics and their summary (Fig. 7.1/7.4).

use super::contact::SupportCheck;
use super::controller::WalkController;
use super::error::{model_err, WalkError};
use super::evaluate::{CycleMetrics, Evaluator};
use super::method::{Method, WalkParams};
use super::robot::WalkRobot;
use super::trajectory::Trajectory;
use super::verdict::WalkVerdicts;
use crate::momentum::LOLA_ARMS;
use crate::pattern::{Foot, PatternSample, WalkingPattern};
use biped_robots::lola::LolaModel;
use serde::Serialize;
use std::time::Instant;

/// Joints recorded in the time series: the arm joints of [`LOLA_ARMS`], pelvis rotation and torso.
pub const RECORDED_JOINTS: [&str; 8] = {
    let mut out = ["pelvis_rotation"; 8];
    let mut k = 0;
    while k < LOLA_ARMS.len() {
        out[k] = LOLA_ARMS[k];
        k += 1;
    }
    out[7] = "torso";
    out
};

/// Per-cycle signals of one walk (index = pattern sample).
#[derive(Debug, Clone, Default)]
pub struct WalkSeries {
    /// Time \[s].
    pub t: Vec<f64>,
    /// `L_z` \[N m s].
    pub lz: Vec<f64>,
    /// `dL_z/dt` \[N m].
    pub dlz: Vec<f64>,
    /// Stance-foot vertical torque \[N m].
    pub tau_z: Vec<f64>,
    /// Smallest SSV distance \[m].
    pub min_distance: Vec<f64>,
    /// Smallest joint-limit margin.
    pub joint_margin: Vec<f64>,
    /// IK cycle wall time \[us].
    pub ik_us: Vec<f64>,
    /// Task error norm before each step.
    pub task_error: Vec<f64>,
    /// Friction usage of the ground wrench ([`super::friction`]).
    pub friction_usage: Vec<f64>,
    /// Centre of pressure (ZMP) of the ground wrench \[m].
    pub zmp: Vec<[f64; 2]>,
    /// Height of the highest planned contact point of a supporting foot above the ground
    /// ([`super::contact`]; 0 without support) \[m].
    pub foot_lift: Vec<f64>,
    /// Joints the IK held at their limit box in each cycle.
    pub limited: Vec<usize>,
    /// Names of the recorded joints ([`WalkRobot::recorded`]; Lola: [`RECORDED_JOINTS`]).
    pub joint_names: Vec<String>,
    /// Angles of the recorded joints (one row per cycle, order of `joint_names`).
    pub joints: Vec<Vec<f64>>,
}

/// Summary of one walk (keys of `summary.json`; SI units, distances in m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WalkSummary {
    /// `max |L_z|` \[N m s].
    #[serde(rename = "peak_abs_Lz")]
    pub peak_abs_lz: f64,
    /// `max |dL_z/dt|` \[N m].
    #[serde(rename = "peak_abs_dLz")]
    pub peak_abs_dlz: f64,
    /// `max |tau_z|` \[N m].
    pub peak_abs_tau_z: f64,
    /// Smallest SSV distance over the walk \[m].
    pub min_distance: f64,
    /// Median IK cycle time \[us].
    pub ik_us_median: f64,
    /// 99th percentile IK cycle time \[us].
    pub ik_us_p99: f64,
    /// Smallest joint-limit margin over the walk.
    pub min_joint_margin: f64,
    /// Largest task error norm over the walk.
    pub max_task_error: f64,
    /// Largest height of a planned contact point of a supporting foot above the ground \[m].
    pub max_foot_lift: f64,
    /// Cycles in which the IK held at least one joint at its limit box.
    pub limited_cycles: usize,
    /// Largest friction usage of the ground wrench (kept: `<= 1`).
    pub peak_friction_usage: f64,
    /// Number of cycles.
    pub cycles: usize,
    /// Joint limits, self-collision and friction: kept or not, where and when.
    pub verdicts: WalkVerdicts,
}

/// Result of [`run_walk`].
#[derive(Debug, Clone)]
pub struct WalkRun {
    /// The method.
    pub method: Method,
    /// Time series.
    pub series: WalkSeries,
    /// Summary.
    pub summary: WalkSummary,
    /// The full motion (every coordinate, CoM, ZMP, soles, ground wrench).
    pub trajectory: Trajectory,
}

/// Runs the IK over every sample of `pattern` with `method` and evaluates each cycle.
///
/// # Example
///
/// A short walk with the arms held still and one with momentum minimisation (7.5): one
/// evaluated cycle per pattern sample, no self-collision, and the free arms reduce the peak
/// vertical angular momentum `L_z`.
///
/// ```
/// use biped_control::pattern::{PatternParams, WalkingPattern};
/// use biped_control::walk::{run_walk, walk_pattern_params, Method, WalkParams};
/// use biped_robots::lola::{build, LolaType};
///
/// let lola = build(LolaType::Type2)?;
/// let params = PatternParams {
///     start_time: 0.3,
///     end_time: 0.3,
///     ..walk_pattern_params(&lola, 3, 0.3, 0.6)?
/// };
/// let pattern = WalkingPattern::generate(&params)?;
/// let still = run_walk(&lola, &pattern, Method::None, WalkParams::default())?.summary;
/// let free = run_walk(&lola, &pattern, Method::Minimization, WalkParams::default())?.summary;
/// assert_eq!(still.cycles, pattern.len());
/// assert!(still.min_distance > 0.0 && free.min_distance > 0.0);
/// assert!(free.peak_abs_lz < still.peak_abs_lz);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn run_walk(
    lola: &LolaModel,
    pattern: &WalkingPattern,
    method: Method,
    params: WalkParams,
) -> Result<WalkRun, WalkError> {
    run_walk_robot(&WalkRobot::lola(lola)?, pattern, method, params)
}

/// [`run_walk`] for any [`WalkRobot`] (e.g. one of a robot description file).
pub fn run_walk_robot(
    robot: &WalkRobot,
    pattern: &WalkingPattern,
    method: Method,
    params: WalkParams,
) -> Result<WalkRun, WalkError> {
    let dt = pattern.params().dt;
    let mut ctrl = WalkController::for_robot(robot, method, params, pattern)?;
    let mut eval =
        Evaluator::for_robot(robot, dt)?.with_ground(pattern.params().foot, params.friction)?;
    let mut verdicts = WalkVerdicts::new(eval.mu());
    let idx = robot
        .recorded
        .iter()
        .map(|n| robot.joint(n).map(|j| j.q_index))
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| model_err("recorded joint missing"))?;
    let n = pattern.len();
    let mut s = WalkSeries {
        joint_names: robot.recorded.clone(),
        ..WalkSeries::default()
    };
    let mut trajectory = Trajectory::with_capacity(robot.model.q_names(), n);
    let soles = eval.soles();
    let support = SupportCheck::new(robot, pattern.params().foot);
    for sample in pattern.iter() {
        let start = Instant::now();
        let info = ctrl.cycle(sample, dt)?;
        s.ik_us.push(start.elapsed().as_secs_f64() * 1e6);
        let m = eval.evaluate(&ctrl, sample)?;
        record_verdicts(&mut verdicts, &eval, sample, &m);
        verdicts.tracking(sample.t, info.error_norm, params.task_tolerance, || {
            held_joints(robot, &ctrl)
        });
        let lift = record_contact(&mut verdicts, &support, &ctrl, sample, &params);
        s.foot_lift.push(lift);
        s.t.push(sample.t);
        s.lz.push(m.lz);
        s.dlz.push(m.dlz);
        s.tau_z.push(m.tau_z);
        s.min_distance.push(m.min_distance);
        s.joint_margin.push(m.joint_margin);
        s.friction_usage.push(m.friction.usage);
        s.zmp.push([m.friction.cop.x, m.friction.cop.y]);
        s.task_error.push(info.error_norm);
        s.limited.push(info.limits.fixed + info.limits.clamped);
        s.joints
            .push(idx.iter().map(|&i| ctrl.q_eval()[i]).collect());
        trajectory.push(sample.t, &ctrl, &m, soles);
    }
    let summary = summarize(&s, n, verdicts);
    Ok(WalkRun {
        method,
        series: s,
        summary,
        trajectory,
    })
}

/// Adds one evaluated cycle to the verdicts.
fn record_verdicts(
    v: &mut WalkVerdicts,
    eval: &Evaluator,
    sample: &PatternSample,
    m: &CycleMetrics,
) {
    let t = sample.t;
    v.joint(t, m.joint_margin, || {
        eval.joint_name(m.worst_joint).to_string()
    });
    if let Some(pair) = m.closest_pair {
        v.distance(t, m.min_distance, || eval.pair_name(pair));
    }
    v.friction(t, m.friction.usage, || {
        match sample.phase.stance_foot() {
            Some(Foot::Left) => "left foot",
            Some(Foot::Right) => "right foot",
            None => "double support",
        }
        .to_string()
    });
}

/// Records the lift of the supporting feet of the cycle `ctrl` has just run and returns it
/// \[m] (0 without support in the pattern).
fn record_contact(
    v: &mut WalkVerdicts,
    support: &SupportCheck,
    ctrl: &WalkController,
    sample: &PatternSample,
    params: &WalkParams,
) -> f64 {
    let lift = support.lift(ctrl.kinematics().0, sample);
    if let Some(l) = lift {
        v.contact(sample.t, l.height, params.contact_tolerance, || {
            l.describe()
        });
    }
    lift.map_or(0.0, |l| l.height)
}

/// The joints the IK held at their limit box in the last cycle, for the tracking verdict.
fn held_joints(robot: &WalkRobot, ctrl: &WalkController) -> String {
    let fixed = ctrl.limiter().fixed();
    let names: Vec<&str> = robot
        .joints
        .iter()
        .filter(|l| fixed.get(l.v_index).copied().unwrap_or(false))
        .map(|l| l.name.as_str())
        .collect();
    match names.is_empty() {
        true => "no joint at its limit box".to_string(),
        false => format!("held at the limit box: {}", names.join(", ")),
    }
}

/// Peaks, minima and timing percentiles of a series.
fn summarize(s: &WalkSeries, cycles: usize, verdicts: WalkVerdicts) -> WalkSummary {
    let peak = |v: &[f64]| v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let mut us = s.ik_us.clone();
    us.sort_by(f64::total_cmp);
    let pct = |p: f64| {
        if us.is_empty() {
            0.0
        } else {
            us[((us.len() - 1) as f64 * p).round() as usize]
        }
    };
    WalkSummary {
        peak_abs_lz: peak(&s.lz),
        peak_abs_dlz: peak(&s.dlz),
        peak_abs_tau_z: peak(&s.tau_z),
        min_distance: min(&s.min_distance),
        ik_us_median: pct(0.5),
        ik_us_p99: pct(0.99),
        min_joint_margin: min(&s.joint_margin),
        max_task_error: peak(&s.task_error),
        max_foot_lift: s.foot_lift.iter().copied().fold(0.0, f64::max),
        limited_cycles: s.limited.iter().filter(|&&n| n > 0).count(),
        peak_friction_usage: s.friction_usage.iter().copied().fold(0.0, f64::max),
        cycles,
        verdicts,
    }
}
